"""The pages of the rendered report (results/report/) and their index.

With the standard library only, so the Snakefile can read the list of pages without importing the numerics stack.

Each page is a notebook of notebooks/ executed by papermill and exported to HTML by nbconvert
(:mod:`vibroadhesion.pipeline.steps.report`); its tables come from :mod:`vibroadhesion.pipeline.report`.
"""

from __future__ import annotations

import html
from pathlib import Path

from vibroadhesion.pipeline.atomic import atomic_path

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
    ("identifiability", "Identifiability — what simulated pull-off data determine, and with which model"),
    ("benchmarks", "Speed against error: every model level, J-integrals, simulation, rule timings"),
]

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
        """<p>Figs. 3, 5, 6 and 8 reproduce the paper at the published Gent–Schultz parameters of
  <code>data/setup.yaml</code>. Figs. 4 and 7 and the fit page show the measured rows of
  <code>data/pulloff.csv</code> with the fit the figures use (<code>fit.figures_use</code>); no measured pull-off
  forces are published in text form, so without your rows that fit is the published set. Series marked
  SIMULATED come from the direct simulation of the full model (a virtual experiment), never from measurements.</p>
  <p>The checks of every model level against the direct simulation, the identifiability of the
  parameters and the speed-against-error benchmarks are built by <code>snakemake -c2 validation</code>:
  <a href="validation_index.html">validation pages</a>.</p>"""),
    "validation_index": (
        "validation against the direct simulation",
        """<p>Built by <code>snakemake -c2 validation</code>.
  Every number on these pages that is not a model prediction is SIMULATED (periodic steady states of the
  full nonlinear model, <code>vibroadhesion.simulation</code>); none is a measurement.
  <a href="index.html">Figure pages</a>.</p>"""),
}



def write_index(out: str | Path) -> None:
    """results/report/index.html (figure pages) or validation_index.html (validation pages), by the file name."""
    stem = Path(out).stem
    if stem not in _INDEX_TEXT:
        raise ValueError(f"unknown index {out}: expected index.html or validation_index.html")
    subtitle, preamble = _INDEX_TEXT[stem]
    pages = PAGES if stem == "index" else VALIDATION_PAGES
    items = "\n".join(f'    <li><a href="{html.escape(name)}.html">{html.escape(title)}</a></li>'
                      for name, title in pages)
    text = f"""<!DOCTYPE html>
<html lang="en">
<head><meta charset="utf-8"><title>Vibroadhesion: {subtitle}</title>
<style>body {{ font-family: sans-serif; max-width: 48em; margin: 2em auto; line-height: 1.5; }}</style></head>
<body>
  <h1>An asymptotic model of vibroadhesion — {subtitle}</h1>
  <p>Argatov, Papangelo &amp; Ciavarella, <em>An asymptotic model of vibroadhesion</em>. Every page is a
  notebook executed by papermill on the artefacts of the pipeline;
  the numbers behind each figure are in <code>results/figN/figN.csv</code>.</p>
  {preamble}
  <ul>
{items}
  </ul>
</body>
</html>
"""
    with atomic_path(out) as tmp:
        tmp.write_text(text)
