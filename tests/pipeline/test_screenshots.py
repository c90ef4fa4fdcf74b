"""Every report page of a finished run as a reader sees it: headless Chromium, offline, at 1200 x 1500 pixels.

Each page (results/report/*.html: the two indexes and every page they list) is opened twice by Debian's
``chromium`` (skipped, saying so, where it is not installed; ``.ci/run`` installs it):

* as built, for a screenshot saved to :data:`SCREENSHOTS` (``results/test-output/screenshots/<page>.png`` of this
  checkout, printed) and a log of every network request (``--log-net-log``);
* as a copy with a probe script appended (and a ``<base>`` so that relative links resolve as for the page), whose
  findings the DOM carries out (``--dump-dom``): the widths of the page and of each table against their room,
  the images and whether they loaded, and any trace of code (input areas, ``In [ ]`` prompts).

What is asserted is what a reader would check: the page needs no network (no request leaves the page for another
scheme than file: or data:), shows no code, no table wider than its room (clipped or scrolled), its images load
and are not blank, and its screenshot is not blank; the fit page shows every provenance string of data/setup.yaml
in full.
"""

from __future__ import annotations

import base64
import html
import io
import json
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from urllib.parse import unquote, urlparse

import matplotlib.image
import numpy as np
import pytest

from vibroadhesion.pipeline.data import DERIVED_GROUP
from vibroadhesion.pipeline.pages import PAGES, VALIDATION_PAGES

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
#: Where the screenshots go: the test output of this checkout, whichever results directory the pages come from.
SCREENSHOTS = ROOT / "results/test-output/screenshots"
WINDOW = (1200, 1500)
#: The two indexes and every page they list.
PAGE_NAMES = ["index", *(name for name, _ in PAGES), "validation_index", *(name for name, _ in VALIDATION_PAGES)]
#: Pages that show no figure of their own: the fit page draws one only with measured rows; the identifiability page
#: and the validation index are tables and text.
WITHOUT_FIGURES = {"fit", "identifiability", "validation_index"}

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="Chromium is not installed (Debian: apt-get install -y "
                                "chromium): the screenshot test of the report pages needs a headless browser")

#: Appended to a copy of each page: once everything has loaded, the measurements, as JSON in an attribute of body.
PROBE = """<script>
window.addEventListener("load", () => {
  const page = document.documentElement;
  const narrowerBoxes = (element) => {
    const narrower = [];
    for (let box = element.parentElement; box && box !== page; box = box.parentElement) {
      if (box.scrollWidth > box.clientWidth + 1) narrower.push(box.tagName + "." + box.className);
    }
    return narrower;
  };
  const tables = [...document.querySelectorAll("table")].map((table) => (
    {head: (table.rows[0] ? table.rows[0].innerText : "").slice(0, 80),
     right: table.getBoundingClientRect().right, narrower: narrowerBoxes(table)}));
  const images = [...document.images].map((img) => ({src: img.src, complete: img.complete,
    width: img.naturalWidth, height: img.naturalHeight, right: img.getBoundingClientRect().right,
    narrower: narrowerBoxes(img)}));
  const code = document.querySelectorAll(
    ".jp-InputPrompt, .jp-OutputPrompt, .jp-InputArea-editor, .jp-CodeMirrorEditor, .input_prompt, .highlight").length;
  const prompts = (document.body.innerText.match(/(In|Out)\\s*\\[\\s*\\d*\\s*\\]\\s*:/g) || []).length;
  document.body.setAttribute("data-probe", JSON.stringify({pageWidth: page.scrollWidth, viewport: page.clientWidth,
    tables: tables, images: images, code: code, prompts: prompts, text: document.body.innerText}));
});
</script>"""

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         f"--window-size={WINDOW[0]},{WINDOW[1]}"]


@dataclass(frozen=True)
class Rendering:
    """One page as Chromium showed it: the screenshot, the requests it made and the probe's findings."""

    screenshot: Path
    requests: list[str]
    probe: dict[str, Any]


def _chromium(profile: Path, *args: str) -> subprocess.CompletedProcess[str]:
    """Chromium with the flags above, a profile of its own and ``args``; fails the test on an error exit."""
    out = subprocess.run([str(CHROMIUM), *FLAGS, f"--user-data-dir={profile}", *args], capture_output=True,
                         text=True, timeout=180)
    assert out.returncode == 0, out.stderr[-3000:]
    return out


def page_requests(net_log: Path) -> list[str]:
    """The URLs a page asked for beyond file: and data: in Chromium's net log.

    Chromium's own background traffic (its network isolation key is not the file:// page) is not the page's.
    """
    log = json.loads(net_log.read_text(encoding="utf-8"))
    start = log["constants"]["logEventTypes"]["URL_REQUEST_START_JOB"]
    urls = []
    for event in log["events"]:
        params = event.get("params", {})
        if event["type"] == start and str(params.get("network_isolation_key", "")).startswith("file://"):
            urls.append(params["url"])
    return [url for url in urls if urlparse(url).scheme not in ("file", "data")]


def _probe_copy(page: Path, dest: Path) -> Path:
    """``page`` with :data:`PROBE` before ``</body>`` and a ``<base>`` at its own directory, written to ``dest``."""
    text = page.read_text(encoding="utf-8")
    base = f'<base href="{page.parent.resolve().as_uri()}/">'
    text = text.replace("<head>", "<head>" + base, 1) if "<head>" in text else base + text
    dest.write_text(text.replace("</body>", PROBE + "</body>", 1), encoding="utf-8")
    return dest


def _probe(dom: str) -> dict[str, Any]:
    """The JSON the probe left in the ``data-probe`` attribute of the dumped DOM."""
    marker = 'data-probe="'
    start = dom.index(marker) + len(marker)
    return dict(json.loads(html.unescape(dom[start:dom.index('"', start)])))


def render(page: Path, work: Path, screenshot: Path) -> Rendering:
    """``page`` in Chromium: its screenshot to ``screenshot``, its network requests, the probe's findings."""
    net_log = work / f"{page.stem}.netlog.json"
    _chromium(work / f"profile-{page.stem}", f"--screenshot={screenshot}", f"--log-net-log={net_log}",
              "--host-resolver-rules=MAP * ~NOTFOUND", page.resolve().as_uri())
    dom = _chromium(work / f"profile-{page.stem}-probe", "--dump-dom",
                    _probe_copy(page, work / f"{page.stem}.probe.html").resolve().as_uri()).stdout
    return Rendering(screenshot, page_requests(net_log), _probe(dom))


@pytest.fixture(scope="module")
def rendered(pipeline_results: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[str, Rendering]:
    """Every page of :data:`PAGE_NAMES` of the run, screenshot and probed."""
    work = tmp_path_factory.mktemp("chromium")
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    out = {}
    for name in PAGE_NAMES:
        page = pipeline_results / "report" / f"{name}.html"
        assert page.exists(), f"{page} was not built"
        out[name] = render(page, work, SCREENSHOTS / f"{name}.png")
    return out


#: A page with every defect the checks look for: a remote image, a table three times the window's width, an
#: input prompt and a blank inline image (a white PNG).
FLAWED = """<!DOCTYPE html><html><head><title>flawed</title></head><body><p>text</p>
<img src="https://example.invalid/figure.png"><img src="data:image/png;base64,{white}">
<div class="jp-InputPrompt">In [1]:</div><table><tr>{cells}</tr></table></body></html>"""


def test_the_checks_see_each_defect_of_a_flawed_page(tmp_path: Path) -> None:
    """Negative control: the request, the wide table, the prompt and the blank image are all reported."""
    white = io.BytesIO()
    matplotlib.image.imsave(white, np.ones((20, 30, 3)), format="png")
    page = tmp_path / "flawed.html"
    page.write_text(FLAWED.format(white=base64.b64encode(white.getvalue()).decode(),
                                  cells="<td>0.123456789</td>" * 400), encoding="utf-8")
    seen = render(page, tmp_path, tmp_path / "flawed.png")
    assert seen.requests == ["https://example.invalid/figure.png"]
    assert seen.probe["code"] == 1 and seen.probe["prompts"] == 1
    assert _wide_tables(seen.probe) and seen.probe["pageWidth"] > seen.probe["viewport"]
    inline = [image for image in seen.probe["images"] if image["src"].startswith("data:")]
    assert len(inline) == 1 and _blank(_image_pixels(inline[0]["src"]))


def test_screenshots_are_saved_and_named(rendered: dict[str, Rendering], capsys: pytest.CaptureFixture[str]) -> None:
    """One PNG per page at the window's size, in the test output of this checkout (printed in the test's output)."""
    with capsys.disabled():
        print(f"\nscreenshots of the report pages: {SCREENSHOTS}/<page>.png for {', '.join(PAGE_NAMES)}")
    for name, page in rendered.items():
        assert page.screenshot == SCREENSHOTS / f"{name}.png"
        assert matplotlib.image.imread(page.screenshot).shape[:2] == (WINDOW[1], WINDOW[0])


@pytest.mark.parametrize("name", PAGE_NAMES)
def test_page_loads_offline(rendered: dict[str, Rendering], name: str) -> None:
    """No request for anything but the page's own files and inline data (no CDN: MathJax, require.js, fonts)."""
    assert rendered[name].requests == []


@pytest.mark.parametrize("name", PAGE_NAMES)
def test_page_shows_no_code(rendered: dict[str, Rendering], name: str) -> None:
    probe = rendered[name].probe
    assert probe["code"] == 0, "code input areas or prompts in the DOM"
    assert probe["prompts"] == 0, "In [ ]: / Out [ ]: prompts in the text"


@pytest.mark.parametrize("name", PAGE_NAMES)
def test_no_table_or_figure_is_wider_than_its_room(rendered: dict[str, Rendering], name: str) -> None:
    """At 1200 pixels every table and figure fits: neither clipped nor behind a scroll bar; no sideways scroll."""
    probe = rendered[name].probe
    assert _wide_tables(probe) == []
    assert _wide_tables(probe, "images") == []
    assert probe["pageWidth"] <= probe["viewport"]


def _wide_tables(probe: dict[str, Any], kind: str = "tables") -> list[dict[str, Any]]:
    """The tables (or images) that reach past the window or make a box around them scroll (clipped or behind a
    scroll bar)."""
    return [t for t in probe[kind] if t["narrower"] or t["right"] > probe["viewport"] + 1]


#: Six rows for data/pulloff.csv of a copy (never of this checkout's data/): pull-off forces of the virtual
#: experiment at 200/300/400 Hz and 20/60 µm, labelled "simulated" as every simulated row must be.
SIX_SIMULATED_ROWS = ("200.0,20.0,173.472524,simulated\n200.0,60.0,737.961579,simulated\n"
                      "300.0,20.0,173.452498,simulated\n300.0,60.0,735.731205,simulated\n"
                      "400.0,20.0,174.448593,simulated\n400.0,60.0,755.242568,simulated\n")
#: The pages that show the measured rows (the figure index, Figs. 4 and 7, the fit page): rebuilt with the rows.
PAGES_WITH_ROWS = ["index", "fig4", "fig7", "fit"]


@pytest.fixture(scope="module")
def rendered_with_rows(pipeline_results: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[str, Rendering]:
    """:data:`PAGES_WITH_ROWS` of the default target rebuilt with six simulated rows in a copy of the finished run.

    The copy keeps the run's results and Snakemake's records, so only the jobs the rows change run again (ingest,
    fit, the fitted virtual pull-off, Figs. 4 and 7 and their pages).
    """
    copy = tmp_path_factory.mktemp("with-rows") / "repository"
    shutil.copytree(pipeline_results.parent, copy, symlinks=True,
                    ignore=shutil.ignore_patterns(".venv", ".git", "test-output"))
    with (copy / "data/pulloff.csv").open("a", encoding="utf-8") as rows:
        rows.write(SIX_SIMULATED_ROWS)
    out = subprocess.run([str(Path(sys.prefix) / "bin" / "snakemake"), "-c2"], cwd=copy, capture_output=True,
                         text=True, timeout=3600)
    assert out.returncode == 0, f"snakemake failed:\n{out.stdout[-3000:]}\n{out.stderr[-5000:]}"
    work = tmp_path_factory.mktemp("chromium-with-rows")
    return {name: render(copy / "results/report" / f"{name}.html", work, SCREENSHOTS / f"{name}-six-rows.png")
            for name in PAGES_WITH_ROWS}


@pytest.mark.parametrize("name", PAGES_WITH_ROWS)
def test_pages_with_measured_rows_fit_the_window(rendered_with_rows: dict[str, Rendering], name: str) -> None:
    """With six rows the fit page's table of measured against predicted and the figures still fit 1200 pixels."""
    probe = rendered_with_rows[name].probe
    assert _wide_tables(probe) == [] and _wide_tables(probe, "images") == []
    assert probe["pageWidth"] <= probe["viewport"]
    assert rendered_with_rows[name].requests == [] and probe["code"] == 0 and probe["prompts"] == 0
    for image in probe["images"]:
        assert image["complete"] and not _blank(_image_pixels(image["src"])), image["src"][:100]
    if name in ("fig4", "fit"):
        assert "simulated" in probe["text"]  # the rows' source, shown with them


def _image_pixels(src: str) -> np.ndarray:
    """The pixels of an image the page shows: inline (data: URI) or a file next to the page."""
    if src.startswith("data:"):
        data = base64.b64decode(src.split(",", 1)[1])
    else:
        data = Path(unquote(urlparse(src).path)).read_bytes()
    return np.asarray(matplotlib.image.imread(io.BytesIO(data), format="png"))


def _blank(pixels: np.ndarray) -> bool:
    """Whether fewer than 1 % of the pixels differ from the first one (an empty canvas) by more than 5 %."""
    rgb = pixels[..., :3].astype(float)
    return bool(np.mean(np.abs(rgb - rgb[0, 0]).max(axis=-1) > 0.05) < 0.01)


@pytest.mark.parametrize("name", PAGE_NAMES)
def test_images_load_and_are_not_blank(rendered: dict[str, Rendering], name: str) -> None:
    images = rendered[name].probe["images"]
    if name not in WITHOUT_FIGURES:
        assert images, f"{name} shows no image"
    for image in images:
        assert image["complete"] and image["width"] > 0 and image["height"] > 0, f"not loaded: {image['src'][:100]}"
        assert not _blank(_image_pixels(image["src"])), f"blank image: {image['src'][:100]}"


@pytest.mark.parametrize("name", PAGE_NAMES)
def test_screenshot_is_not_blank(rendered: dict[str, Rendering], name: str) -> None:
    assert not _blank(matplotlib.image.imread(rendered[name].screenshot))


def test_fit_page_shows_every_provenance_string_in_full(rendered: dict[str, Rendering],
                                                       pipeline_results: Path) -> None:
    """Each source of data/setup.yaml (some over 500 characters), whole, as the reader's text on the fit page.

    The derived values of the canonical copy are not inputs: the fit page shows them at the fit, by their formulas.
    """
    setup = json.loads((pipeline_results / "data/setup.json").read_text(encoding="utf-8"))
    setup.pop(DERIVED_GROUP)
    sources = list(_sources(setup))
    assert max(map(len, sources)) > 200
    text = " ".join(str(rendered["fit"].probe["text"]).split())
    missing = [s for s in sources if " ".join(s.split()) not in text]
    assert missing == []


def _sources(node: object) -> list[str]:
    """Every ``source`` string of the ingested setup (nested mappings)."""
    if not isinstance(node, dict):
        return []
    found = [node["source"]] if isinstance(node.get("source"), str) else []
    return found + [s for value in node.values() for s in _sources(value)]
