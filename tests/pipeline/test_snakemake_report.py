"""Snakemake's own report (`snakemake --report`) as a deliverable: built from a finished `all validation` run,
it holds the workflow description, every figure with its table, the fit, the validation and benchmark figures and
the rendered pages, under their categories, and its captions are valid reStructuredText."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from vibroadhesion.pipeline.pages import PAGES, VALIDATION_PAGES

FIGURES = ["fig3", "fig4", "fig5", "fig6", "fig7", "fig8"]
CATEGORIES = ["Figures", "Tables", "Fit", "Validation", "Benchmarks", "Report pages"]


def test_snakemake_report_packs_every_category_with_its_artefacts(pipeline_results: Path, tmp_path: Path) -> None:
    work = pipeline_results.parent
    if not (work / "Snakefile").exists():
        pytest.skip("VIBROADHESION_RESULTS names finished results without their repository")
    out = tmp_path / "report.zip"
    run = subprocess.run([str(Path(sys.prefix) / "bin" / "snakemake"), "--report", str(out), "all", "validation"],
                         cwd=work, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-3000:]
    assert "ERROR/" not in run.stderr and "WARNING/" not in run.stderr, run.stderr[-3000:]  # docutils on captions
    archive = zipfile.ZipFile(out)
    names = {Path(name).name for name in archive.namelist()}
    expected = ({f"{fig}.{ext}" for fig in FIGURES for ext in ("png", "csv")}
                | {"gent_schultz.json", "rigid_error_maps.png", "compliant_sweep.png", "speed_vs_error.png"}
                | {f"{stem}.html" for stem, _ in PAGES + VALIDATION_PAGES} | {"index.html", "validation_index.html"})
    assert expected <= names, sorted(expected - names)
    report = archive.read("report/report.html").decode("utf-8")
    assert "Reproduction of Argatov, Papangelo" in report  # the workflow description (Snakefile `report:`)
    missing = [category for category in CATEGORIES if f'"{category}"' not in report]
    assert not missing, missing
