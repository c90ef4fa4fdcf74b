"""The pages of the rendered report (results/report/) and their index.

With the standard library only, so the Snakefile can read the list of pages, and decide whether the findings need
reading again (:func:`findings_outdated`), without importing the numerics stack.

Each page is a notebook of notebooks/ executed by papermill and exported to HTML by nbconvert
(:mod:`vibroadhesion.pipeline.steps.report`); its tables come from :mod:`vibroadhesion.pipeline.report`.
"""

from __future__ import annotations

import html
import os
import subprocess
from collections.abc import Collection, Iterable, Mapping
from pathlib import Path

from vibroadhesion.pipeline.atomic import atomic_path

#: The validation's error summary: read when present (the default target does not build it and must not wait).
VALIDATION_SUMMARY = Path("results/validation/rigid_error_summary.csv")
#: The validation index, which the figure index links only where it exists (its findings, front_page).
VALIDATION_INDEX = Path("results/report/validation_index.html")
#: How far before the findings read their artefacts an index's time is set (:func:`write_index`): more than the
#: granularity of file times (the kernel's coarse clock, a few ms), so that an artefact written while they are read
#: is newer than the index. Far less than a report job's pages take before its index, so the index stays newer
#: than the job's inputs.
FILE_TIME_MARGIN_NS = 50_000_000

#: (file stem, title) of the pages of the default target (``snakemake -c2``), in the order of its index.
PAGES: list[tuple[str, str]] = [
    ("fig3", "Fig. 3 — J-integrals of the Gent–Schultz law"),
    ("fig4", "Fig. 4 — pull-off amplification against base amplitude"),
    ("fig5", "Fig. 5 — passage through resonance of a compliantly fixed indenter"),
    ("fig6", "Fig. 6 — nominal point contact of a rigidly fixed indenter"),
    ("fig7", "Fig. 7 — refined pull-off estimate against frequency"),
    ("fig8", "Fig. 8 — dynamic contact stiffness (storage, loss, phase)"),
    ("fit", "Gent–Schultz fit and parameter provenance"),
]

#: Pages of the ``validation`` target (``snakemake -c2 validation``): the checks against the simulation.
VALIDATION_PAGES: list[tuple[str, str]] = [
    ("validation", "Validation — every model level against the direct simulation"),
    ("rigs", "Two rigs — base and force excitation (Fig. 2, Eq. 13, Appendix B)"),
    ("identifiability", "Identifiability — what simulated pull-off data determine, and with which model"),
    ("benchmarks", "Speed against error: every model level, J-integrals, simulation, rule timings"),
    ("withdrawal", "Withdrawal speed — simulated pull-off at a finite withdrawal speed"),
]

#: The figure of each page, as its thumbnail on the index: a path relative to results/report/ (the run's figure, not a
#: copy). A page without one (the fit page draws its plot only with measured rows; identifiability is tables) is
#: listed by its title alone.
THUMBNAILS: dict[str, str] = {
    **{f"fig{k}": f"../fig{k}/fig{k}.png" for k in range(3, 9)},
    "validation": "../validation/rigid_error_maps.png",
    "benchmarks": "../benchmarks/speed_vs_error.png",
}


def page_title_and_index(stem: str) -> tuple[str, str]:
    """The title of page ``stem`` and the index that lists it (``index`` or ``validation_index``).

    A notebook that no index lists (one of your own) is titled by its stem and links to ``index``.
    """
    for pages, index in ((PAGES, "index"), (VALIDATION_PAGES, "validation_index")):
        for name, title in pages:
            if name == stem:
                return title, index
    return stem, "index"


#: The report jobs: rule -> (the index it writes, or None; the pages it renders in one kernel). The default
#: target's pages in two jobs, split by parameter set: Figs. 4 and 7 and the fit page show the measured rows and
#: the fit (an edit of data/pulloff.csv reruns them; they also wait for the simulated pull-off, the longest chain
#: of the DAG), the paper's other figures are at the published parameters and render meanwhile. The index only
#: links, so the job of Figs. 4 and 7 writes it.
REPORT_JOBS: dict[str, tuple[str | None, tuple[str, ...]]] = {
    "report_index": ("index", ("fig4", "fig7", "fit")),
    "report_pages": (None, ("fig3", "fig5", "fig6", "fig8")),
    "report_validation_index": ("validation_index", tuple(stem for stem, _ in VALIDATION_PAGES)),
}

_INDEX_TEXT = {
    "index": (
        "reproduction report",
        """<p>Every page is a notebook executed by papermill on the artefacts of the pipeline; the numbers behind
  each figure are in <code>results/figN/figN.csv</code>.</p>
  <p>Figs. 3, 5, 6 and 8 reproduce the paper at the published Gent–Schultz parameters of
  <code>data/setup.yaml</code>. Figs. 4 and 7 and the fit page show the measured rows of
  <code>data/pulloff.csv</code> with the fit the figures use (<code>fit.figures_use</code>); no measured pull-off
  forces are published in text form, so without your rows that fit is the published set. Series marked
  SIMULATED come from the direct simulation of the full model (a virtual experiment), never from measurements.</p>
  <p>The checks of every model level against the direct simulation, the identifiability of the
  parameters and the speed-against-error benchmarks are built by <code>snakemake -c2 validation</code>
  (the validation pages, linked below once built).</p>"""),
    "validation_index": (
        "validation against the direct simulation",
        """<p>Built by <code>snakemake -c2 validation</code>.
  Every number on these pages that is not a model prediction is SIMULATED (periodic steady states of the
  full nonlinear model, <code>vibroadhesion.simulation</code>); none is a measurement.
  {figure_pages}</p>"""),
}



def write_index(out: str | Path, stale: Collection[str] = (), findings: str | None = None,
                as_of_ns: int | None = None) -> None:
    """results/report/index.html (figure pages) or validation_index.html (validation pages), by the file name.

    Pages named in ``stale`` (:func:`stale_pages`) are marked out of date, with a note above the list. ``findings``
    is an HTML fragment placed before the list of pages (:mod:`vibroadhesion.pipeline.front_page`); None keeps those
    of the index already there (:func:`refresh_indexes` marks stale pages without recomputing the findings).
    ``as_of_ns`` (``time.time_ns()`` taken before the findings read their artefacts) sets the index's modification
    time, less :data:`FILE_TIME_MARGIN_NS`: an artefact written after the findings started to read is newer than the
    index, and :func:`findings_outdated` says so.
    """
    if Path(out).stem not in _INDEX_TEXT:
        raise ValueError(f"unknown index {out}: expected index.html or validation_index.html")
    text = _index_html(Path(out), stale, findings_of(out) if findings is None else findings)
    with atomic_path(out) as tmp:
        tmp.write_text(text, encoding="utf-8")
    if as_of_ns is not None:
        findings_read_at(out, as_of_ns)


def findings_read_at(index: str | Path, as_of_ns: int) -> None:
    """Record that the findings of ``index`` are those of the artefacts as of ``as_of_ns``.

    ``as_of_ns`` is ``time.time_ns()`` taken before the findings read the artefacts; it becomes the index's
    modification time, less :data:`FILE_TIME_MARGIN_NS`. The index's bytes stay as they are.
    """
    os.utime(index, ns=(as_of_ns - FILE_TIME_MARGIN_NS, as_of_ns - FILE_TIME_MARGIN_NS))


def findings_outdated(index: str | Path, artefacts: Iterable[str | Path], repository: str | Path = ".") -> bool:
    """Whether the findings of the existing ``index`` must be read again (an artefact newer, another build).

    True when an artefact is newer than the index or the build the findings name is not the checkout's
    (:func:`build`). The index's time is that of its findings (:func:`write_index`'s ``as_of_ns``; a rewrite that
    only marks stale pages keeps findings that were current, since it follows their refresh), so the check needs no
    import of the numerics stack: the Snakefile's onsuccess reads the findings again, at about a second, only when
    this is true.
    """
    index = Path(index)
    if not index.exists():
        return False
    written = index.stat().st_mtime_ns
    if any(Path(a).exists() and Path(a).stat().st_mtime_ns > written for a in artefacts):
        return True
    return not findings_of(index).startswith(build_paragraph(repository))


#: The comments around the findings of an index, so that a rewrite can keep them.
_FINDINGS = ("<!-- findings -->", "<!-- /findings -->")


def findings_of(index: str | Path) -> str:
    """The findings of the index file ``index`` (empty if it does not exist or has none)."""
    text = Path(index).read_text(encoding="utf-8") if Path(index).exists() else ""
    start, end = text.find(_FINDINGS[0]), text.find(_FINDINGS[1])
    return text[start + len(_FINDINGS[0]):end] if 0 <= start < end else ""


def _index_html(out: Path, stale: Collection[str], findings: str) -> str:
    """The text of the index ``out`` (:func:`write_index`).

    Only pages that exist next to it are linked (:func:`_page_item`); the figure pages' index from the validation
    index only where it exists too.
    """
    stem = out.stem
    subtitle, preamble = _INDEX_TEXT[stem]
    pages = PAGES if stem == "index" else VALIDATION_PAGES
    figure_pages = ('<a href="index.html">Figure pages</a>.' if (out.parent / "index.html").exists() else
                    "The figure pages (<code>index.html</code>) are built by <code>snakemake -c2</code>.")
    preamble = preamble.replace("{figure_pages}", figure_pages)
    items = "\n".join(_page_item(out.parent, name, title, name in stale) for name, title in pages)
    warning = ""
    if any(name in stale for name, _ in pages):
        target = "snakemake -c2" if stem == "index" else "snakemake -c2 validation"
        warning = (f'<p class="stale"><strong>Out of date:</strong> the pages marked below are missing or were built '
                   f"before artefacts they show were rewritten (a run that stopped midway, or a run of another "
                   f"target), so they do not show one state with the rest. Run <code>{target}</code> to rebuild "
                   "them.</p>")
    return f"""<!DOCTYPE html>
<html lang="en">
<head><meta charset="utf-8"><title>Vibroadhesion: {subtitle}</title>
<style>body {{ font-family: sans-serif; max-width: 60em; margin: 2em auto; line-height: 1.5; }}
.stale {{ color: #a00; }}
table {{ border-collapse: collapse; font-size: 0.9em; }} th, td {{ padding: 0.2em 0.6em; }}
th {{ border-bottom: 1px solid #888; }}
ul.pages {{ list-style: none; padding: 0; display: grid; grid-template-columns: repeat(auto-fill, minmax(17em, 1fr));
  gap: 1em; }}
ul.pages img {{ display: block; box-sizing: border-box; width: 100%; height: 10em; object-fit: contain;
  border: 1px solid #ccc; }}
</style></head>
<body>
  <h1>An asymptotic model of vibroadhesion — {subtitle}</h1>
  <p>Argatov, Papangelo &amp; Ciavarella, <em>An asymptotic model of vibroadhesion</em>: what its reproduction
  found.</p>
  {warning}
  {_FINDINGS[0]}{findings}{_FINDINGS[1]}
  <h2>How this report was built</h2>
  {preamble}
  <h2>Pages</h2>
  <ul class="pages">
{items}
  </ul>
</body>
</html>
"""


_STALE_MARK = ' <strong class="stale">(out of date)</strong>'
#: The findings of an index written after its own report job failed (:func:`refresh_indexes`).
_JOB_FAILED = ('<p class="stale"><strong>The run stopped before the job that writes this index finished</strong> (a '
               "failed job, its log in <code>results/logs/</code>, or an interruption), so no findings are shown: the "
               "pages below are what the runs so far left.</p>")
_MISSING_MARK = ' <strong class="stale">(not built)</strong>'


def _page_item(report_dir: Path, name: str, title: str, stale: bool) -> str:
    """The list item of page ``name`` on its index: linked (with its thumbnail) where it exists in ``report_dir``.

    Else its title, marked as not built: a link to a missing page would lead nowhere.
    """
    if not (report_dir / f"{name}.html").exists():
        return f"    <li>{html.escape(title)}{_MISSING_MARK}</li>"
    return (f'    <li>{_thumbnail(name)}<a href="{html.escape(name)}.html">{html.escape(title)}</a>'
            f'{_STALE_MARK if stale else ""}</li>')


def _thumbnail(name: str) -> str:
    """The thumbnail of page ``name`` (:data:`THUMBNAILS`) linking to the page, or nothing."""
    if name not in THUMBNAILS:
        return ""
    return (f'<a href="{html.escape(name)}.html"><img src="{html.escape(THUMBNAILS[name])}" '
            f'alt="figure of the page {html.escape(name)}"></a>')


def stale_pages(page_inputs: Mapping[str, Iterable[str | Path]], report_dir: str | Path) -> list[str]:
    """The pages of ``report_dir`` that are missing or older than an artefact they show (by modification time).

    ``page_inputs`` maps each page (file stem) to the artefacts it reads; an artefact that is missing makes its page
    stale too. A page goes missing when the job that renders it fails (Snakemake removes a failed job's outputs).
    """
    stale = []
    for page, inputs in page_inputs.items():
        built = Path(report_dir) / f"{page}.html"
        when = built.stat().st_mtime_ns if built.exists() else None
        if when is None or any(not Path(p).exists() or Path(p).stat().st_mtime_ns > when for p in inputs):
            stale.append(page)
    return stale


def refresh_indexes(page_inputs: Mapping[str, Iterable[str | Path]], report_dir: str | Path,
                    asked: Collection[str] = tuple(_INDEX_TEXT)) -> list[str]:
    """After every run, finished or failed (the Snakefile's ``onsuccess`` and ``onerror``), mark stale pages.

    Only the indexes named in ``asked`` (stems: those of the run's targets) are touched: an index of a target that
    was not asked for keeps its bytes, whatever the run did. Each asked index of ``report_dir`` that exists is
    rewritten only when its text changes, so a consistent report keeps its bytes and times; one that is missing (its
    job failed, and Snakemake removed its outputs) is written with its pages marked and no findings, so that
    results/report/ still says what it holds. Returns the stale pages (:func:`stale_pages`) that an asked index lists.
    """
    stale, marked = stale_pages(page_inputs, report_dir), []
    for stem in (stem for stem in _INDEX_TEXT if stem in asked):
        index = Path(report_dir) / f"{stem}.html"
        marked += [name for name, _ in (PAGES if stem == "index" else VALIDATION_PAGES) if name in stale]
        if not index.exists() or index.read_text(encoding="utf-8") != _index_html(index, stale, findings_of(index)):
            index.parent.mkdir(parents=True, exist_ok=True)
            write_index(index, stale, None if index.exists() else _JOB_FAILED)
    return marked


def _git(repository: str | Path, *args: str) -> str:
    """The output of ``git -C repository args`` (raises OSError or CalledProcessError)."""
    return subprocess.run(["git", "-C", str(repository), *args], capture_output=True, text=True,
                          check=True).stdout.strip()


def build(repository: str | Path = ".") -> str:
    """``commit <hash> of <date>`` of the tree the report is built from (``, with uncommitted changes``)."""
    try:
        commit, date = _git(repository, "log", "-1", "--format=%H %cs").split()
        dirty = _git(repository, "status", "--porcelain", "--untracked-files=no", "--", "src", "workflow",
                     "notebooks", "data")
    except (OSError, subprocess.CalledProcessError, ValueError):
        return "an unknown commit (not a git checkout)"
    return f"commit {commit[:12]} of {date}" + (", with uncommitted changes" if dirty else "")


def build_paragraph(repository: str | Path = ".") -> str:
    """The first paragraph of an index's findings: the build they were read from (:func:`build`)."""
    return f"<p>Built from {html.escape(build(repository))}.</p>"


def findings_inputs(parameters: Mapping[str, Mapping[str, str]]) -> list[str | Path]:
    """Every file the findings of an index may read (:func:`vibroadhesion.pipeline.front_page.findings`).

    The artefacts of its pages (:func:`index_artefacts`), the validation summary, read when present, and the
    validation index, linked when present.
    """
    return [*index_artefacts(parameters).values(), VALIDATION_SUMMARY, VALIDATION_INDEX]


def index_artefacts(parameters: Mapping[str, Mapping[str, str]]) -> dict[str, str]:
    """The artefacts an index's findings read: each parameter of its pages, named by the first page that has it.

    The validation page comes first among its index's pages, so its ``virtual_csv`` (every fixation) is the one read.
    """
    artefacts: dict[str, str] = {}
    for values in parameters.values():
        for name, path in values.items():
            artefacts.setdefault(name, path)
    return artefacts
