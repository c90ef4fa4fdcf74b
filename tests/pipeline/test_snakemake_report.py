"""Snakemake's own report (`snakemake --report results/report.zip all validation`, the README's command) as a
deliverable: built from a finished `all validation` run, it holds the workflow description, every figure with its
table, the fit, the validation, rigs, withdrawal, identifiability and benchmark results and the rendered pages, under
their categories, each with a caption that is valid reStructuredText; and inside the zip every link and image of
every HTML file resolves to a file of the zip."""

from __future__ import annotations

import json
import posixpath
import re
import subprocess
import sys
import zipfile
from html.parser import HTMLParser
from pathlib import Path
from typing import Any
from urllib.parse import unquote, urlsplit

import pytest

from vibroadhesion.pipeline.pages import PAGES, VALIDATION_PAGES
from vibroadhesion.pipeline.steps.site import report_site

FIGURES = ["fig3", "fig4", "fig5", "fig6", "fig7", "fig8"]
CATEGORIES = {"Figures", "Fit", "Validation", "Rigs", "Withdrawal", "Identifiability", "Benchmarks", "Report pages"}


class _Links(HTMLParser):
    """The ``href`` and ``src`` values of an HTML text, in order."""

    def __init__(self) -> None:
        super().__init__()
        self.links: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.links += [value for name, value in attrs if name in ("href", "src") and value]


def relative_links(text: str) -> list[str]:
    """The links of HTML ``text`` to other files by relative path: no scheme (data:, http:, javascript:), no
    in-page anchor; query and fragment removed."""
    parser = _Links()
    parser.feed(text)
    parts = [urlsplit(link) for link in parser.links]
    return [unquote(p.path) for p in parts if not p.scheme and not p.netloc and p.path]


def test_relative_links_are_found_and_others_left() -> None:
    text = ('<a href="fig3.html#top">x</a><img src="../fig3/fig3.png"><img src="data:image/png;base64,AA">'
            '<a href="https://example.org/a">y</a><a href="#local">z</a><script src="javascript:void(0)"></script>')
    assert relative_links(text) == ["fig3.html", "../fig3/fig3.png"]


def _assigned_json(text: str, name: str) -> Any:
    """The JSON value of Snakemake's report.html in its ``<script id="name">var name = {...}`` element."""
    start = re.search(rf'<script id="{name}">\s*var {name} = ', text)
    assert start is not None, name
    return json.JSONDecoder().raw_decode(text, start.end())[0]


@pytest.fixture(scope="module")
def report_zip(pipeline_results: Path, tmp_path_factory: pytest.TempPathFactory) -> zipfile.ZipFile:
    """The zip of the README's report command, run in the repository copy of the shared pipeline build."""
    work = pipeline_results.parent
    if not (work / "Snakefile").exists():
        pytest.skip("VIBROADHESION_RESULTS names finished results without their repository")
    out = tmp_path_factory.mktemp("snakemake-report") / "report.zip"
    run = subprocess.run([str(Path(sys.prefix) / "bin" / "snakemake"), "--report", str(out), "all", "validation"],
                         cwd=work, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-3000:]
    assert "ERROR/" not in run.stderr and "WARNING/" not in run.stderr, run.stderr[-3000:]  # docutils on captions
    return zipfile.ZipFile(out)


def test_snakemake_report_packs_every_category_with_its_artefacts(report_zip: zipfile.ZipFile) -> None:
    names = {Path(name).name for name in report_zip.namelist()}
    expected = ({f"{fig}.{ext}" for fig in FIGURES for ext in ("png", "csv")}
                | {"gent_schultz.json", "rigid_error_maps.png", "compliant_sweep.png", "rig_comparison.png",
                   "speed_sweep.png", "speed_vs_error.png", "fits.csv", "design.csv", "information.csv"}
                | {f"{stem}.html" for stem, _ in PAGES + VALIDATION_PAGES} | {"index.html", "validation_index.html"})
    assert expected <= names, sorted(expected - names)
    report = report_zip.read("report/report.html").decode("utf-8")
    assert "Reproduction of Argatov, Papangelo" in report  # the workflow description (Snakefile `report:`)
    assert set(_assigned_json(report, "categories")) == CATEGORIES
    results = _assigned_json(report, "results")
    uncaptioned = [path for path, result in results.items() if not result["caption"].strip()]
    assert not uncaptioned, uncaptioned
    missing = [path for path, result in results.items() if f"report/{result['data_uri']}" not in report_zip.namelist()]
    assert not missing, missing


def test_every_link_and_image_inside_the_report_zip_resolves_there(report_zip: zipfile.ZipFile) -> None:
    """Every relative href and src of every HTML file of the zip names a file of the zip (the index's thumbnails,
    the links between the pages and the indexes)."""
    entries = set(report_zip.namelist())
    pages = [name for name in entries if name.endswith(".html")]
    assert len(pages) == len(PAGES + VALIDATION_PAGES) + 3  # the pages, the two indexes, Snakemake's report.html
    broken = [(page, link) for page in pages
              for link in relative_links(report_zip.read(page).decode("utf-8"))
              if posixpath.normpath(posixpath.join(posixpath.dirname(page), link)) not in entries]
    assert not broken, broken
    index = next(name for name in pages if name.endswith("/index.html"))
    linked = set(relative_links(report_zip.read(index).decode("utf-8")))
    assert {f"{stem}.html" for stem, _ in PAGES} | {"validation_index.html"} <= linked
    assert {f"../{fig}/{fig}.png" for fig in FIGURES} <= linked  # the thumbnails, resolved above


def test_the_report_zip_shows_the_indexes_results_report_shows(pipeline_results: Path,
                                                                report_zip: zipfile.ZipFile) -> None:
    """The indexes in the zip are those of results/report/ after the run (whose figure index was written before the
    validation it links, and read again at the end of the run), and a second `all validation` has nothing to do."""
    for stem in ("index", "validation_index"):
        (packed,) = [name for name in report_zip.namelist() if name.endswith(f"/{stem}.html")]
        assert report_zip.read(packed) == (pipeline_results / "report" / f"{stem}.html").read_bytes(), stem
    run = subprocess.run([str(Path(sys.prefix) / "bin" / "snakemake"), "-n", "all", "validation"],
                         cwd=pipeline_results.parent, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0 and "Nothing to be done" in run.stdout + run.stderr, run.stdout[-3000:]


def test_the_report_site_holds_each_file_at_its_path_under_results(tmp_path: Path) -> None:
    """The folder Snakemake packs (rule report_site): the pages and figures at their paths under results/, so the
    index's links (``fig3.html``, ``../fig3/fig3.png``) resolve in it; a file outside results/ is refused before
    anything is written."""
    results = tmp_path / "results"
    files = {results / "report" / "index.html": b"<a href='fig3.html'>", results / "report" / "fig3.html": b"<p>",
             results / "fig3" / "fig3.png": b"\x89PNG"}
    for path, content in files.items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(content)
    report_site(files, tmp_path / "site", {}, results)
    copied = {p.relative_to(tmp_path / "site").as_posix(): p.read_bytes() for p in (tmp_path / "site").rglob("*")
              if p.is_file()}
    assert copied == {"report/index.html": b"<a href='fig3.html'>", "report/fig3.html": b"<p>",
                      "fig3/fig3.png": b"\x89PNG"}
    (tmp_path / "elsewhere.png").write_bytes(b"x")
    with pytest.raises(ValueError, match="elsewhere.png"):
        report_site([*files, tmp_path / "elsewhere.png"], tmp_path / "other", {}, results)
    assert not (tmp_path / "other").exists()
