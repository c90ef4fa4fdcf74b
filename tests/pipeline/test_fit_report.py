"""The fit page: per level estimates ± SE, misfit, status; measured against predicted; renders with and without rows.

The fit summaries are written here by hand in the format of ``experiments.fitting`` (residual = model - measured
in mN, ``row_status`` of the simulation with ``model_mN`` null where a family lost contact), so every expected
number follows from the fixture by arithmetic, not from the code under test.
"""

import json
import math
from pathlib import Path

import nbformat
import pandas as pd
import pytest

from vibroadhesion.core import levels
from vibroadhesion.pipeline import data, fit_report
from vibroadhesion.pipeline.steps.report import Page, render_page, reset_namespace, shared_kernel

ROOT = Path(__file__).resolve().parents[2]
PUBLISHED = {"w0": 0.236, "n": 0.531, "v0": 4.45e-05}
UNITS = {"w0": "J/m^2", "n": "1", "v0": "m/s"}


def _parameters(values: dict[str, float], errors: dict[str, float | None], sources: dict[str, str]) -> dict:
    return {name: {"estimate": values[name], "std_error": errors.get(name), "unit": UNITS[name],
                   "source": sources.get(name, "published (Fig. 4 caption)")} for name in ("w0", "n", "v0")}


def _fit(rows: int) -> dict:
    """A fit of 3 rows (lines 2-4: 200 Hz/20 um 170 mN, 300 Hz/60 um 700 mN, 400 Hz/100 um 1400 mN)."""
    simulation = {
        "model": "simulation", "rows": rows, "status": "fitted", "note": "", "free_parameters": ["w0", "n", "v0"],
        "at_bound": [], "v0_identifiable": True, "v0_note": "v0 identifiable: relative standard error 0.117",
        "parameters": _parameters({"w0": 0.2361234, "n": 0.531, "v0": 4.503121e-05},
                                  {"w0": 0.001234, "n": 0.25, "v0": 1.87152e-07}, dict.fromkeys(PUBLISHED, "fitted")),
        "residuals_mN": [{"line": 2, "residual": 1.7}, {"line": 3, "residual": -7.0}, {"line": 4, "residual": -1400.0}],
        "rms_relative_residual": 0.5774,
        "row_status": [{"line": 2, "frequency_hz": 200.0, "h1_um": 20.0, "status": "pulloff", "model_mN": 171.7},
                       {"line": 3, "frequency_hz": 300.0, "h1_um": 60.0, "status": "pulloff", "model_mN": 693.0},
                       {"line": 4, "frequency_hz": 400.0, "h1_um": 100.0, "status": "contact_loss_before_extremum",
                        "model_mN": None}],
    }
    leading = {
        "model": "leading", "rows": rows, "status": "at_bound", "free_parameters": ["w0", "n"], "at_bound": ["n"],
        "note": "n ends on its bound 0.05 1", "v0_identifiable": False, "v0_note": "v0 not identifiable: no v0",
        "parameters": _parameters({"w0": 0.49, "n": 0.05000000000000003, "v0": 4.45e-05}, {"w0": 0.12},
                                  {"w0": "fitted", "n": "fitted, on its bound (0.05, 4.0)"}),
        "residuals_mN": [{"line": 2, "residual": 17.0}, {"line": 3, "residual": -140.0},
                         {"line": 4, "residual": -280.0}],
        "rms_relative_residual": 0.17,
    }
    refined = {"model": "refined", "rows": rows, "status": "failed", "note": "no root at a trial point",
               "v0_identifiable": False, "v0_note": "no fit", "parameters": _parameters(PUBLISHED, {}, {})}
    fits = {"refined": refined, "simulation": simulation, "leading": leading}  # not in the registry's order
    if rows == 0:
        fits = {name: {"model": name, "rows": 0, "status": "published", "note": "no rows: published values kept",
                       "v0_identifiable": False, "v0_note": "", "parameters": _parameters(PUBLISHED, {}, {})}
                for name in ("simulation", "leading")}
    return {"data_rows": rows, "figures_use": "simulation", "fits": fits, "status": "",
            "published": {**PUBLISHED, "source": "Fig. 4 caption"}}


def _rows(tmp_path: Path) -> pd.DataFrame:
    csv = tmp_path / "pulloff.csv"
    csv.write_text("frequency_hz,h1_um,pulloff_mN,source\n200.0,20.0,170.0,lab A\n300.0,60.0,700.0,lab A\n"
                   "400.0,100.0,1400.0,lab B\n")
    return data.read_canonical_pulloff(csv)


def test_levels_in_the_registry_order_with_the_converged_simulation_as_headline() -> None:
    fit = _fit(3)
    assert fit_report.ordered_levels(fit) == ["simulation", "leading", "refined"]
    assert fit_report.headline(fit) == "simulation"
    fit["fits"]["simulation"]["status"] = "failed"
    assert fit_report.headline(fit) is None
    assert "did not converge (**failed**" in fit_report.summary_sentence(fit)


def test_estimates_give_value_plus_minus_se_or_why_there_is_none() -> None:
    table = fit_report.estimates(_fit(3)).set_index("status")
    assert table.loc["fitted", "w0"] == "0.2361\u00a0±\u00a00.0012"
    assert table.loc["fitted", "v0"] == "(4.503\u00a0±\u00a00.019)e-05"
    assert table.loc["at_bound", "n"] == "0.0500 (at bound)"  # 0.05000000000000003 to 3 figures
    assert table.loc["at_bound", "v0"] == "4.45e-05 (fixed: published)"  # as published, no padding zero
    assert table.loc["failed", "w0"] == "0.236 (fixed: published)" and "no root" in table.loc["failed", "reason"]
    assert table.loc["fitted", "rms_relative_residual"] == 0.5774
    assert math.isnan(table.loc["failed", "rms_relative_residual"])
    assert table.loc["fitted", "level"] == levels.level("simulation").label


def test_figure_pages_show_the_fit_the_figures_use_and_the_headline() -> None:
    fit = _fit(3)
    assert fit_report.figures_fit(fit)["level"].tolist() == [levels.level("simulation").label]
    fit["figures_use"] = "leading"
    assert fit_report.figures_fit(fit)["level"].tolist() == [levels.level(n).label for n in ("simulation", "leading")]


def test_measured_against_predicted_per_row_with_the_contact_loss_row_unpredicted(tmp_path: Path) -> None:
    table = fit_report.measured_vs_predicted(_fit(3), _rows(tmp_path))
    assert table["predicted_mN:leading"].tolist() == pytest.approx([187.0, 560.0, 1120.0], rel=1e-15)
    simulated = table["predicted_mN:simulation"]
    assert simulated.iloc[:2].tolist() == pytest.approx([171.7, 693.0], rel=1e-15) and math.isnan(simulated.iloc[2])
    assert table["relative_residual:simulation"].iloc[:2].tolist() == pytest.approx([1.7 / 170, -0.01], rel=1e-12)
    assert table["status:simulation"].tolist() == ["pulloff", "pulloff", "contact_loss_before_extremum"]
    assert "predicted_mN:refined" not in table  # a failed level predicts nothing
    plotted = fit_report.long_predictions(table)
    assert len(plotted) == 5 and set(plotted["level"]) == {levels.level("simulation").label,
                                                           levels.level("leading").label}
    headers = fit_report.measured_vs_predicted_columns(table)
    assert headers["predicted_mN:leading"].header == "predicted, leading (mN)"


@pytest.mark.parametrize("rows", [0, 3])
def test_fit_page_renders_with_and_without_measured_rows(tmp_path: Path, rows: int) -> None:
    setup_json, pulloff_csv = tmp_path / "setup.json", tmp_path / "pulloff.csv"
    data.ingest(ROOT / "data/setup.yaml", ROOT / "data/pulloff.csv", setup_json, pulloff_csv)
    if rows:
        _rows(tmp_path)  # overwrites pulloff.csv with the 3 rows of the fixture
    fit_json = tmp_path / "fit.json"
    fit_json.write_text(json.dumps(_fit(rows)))
    page = Page(ROOT / "notebooks/fit.ipynb", tmp_path / "fit.ipynb", tmp_path / "fit.html",
                {"fit_json": str(fit_json), "setup_json": str(setup_json), "pulloff_csv": str(pulloff_csv)})
    with shared_kernel() as manager:
        reset_namespace(manager)
        render_page(page, manager)
    html = page.html.read_text(encoding="utf-8")
    if rows:
        assert "0.2361\u00a0±\u00a00.0012" in html and "contact_loss_before_extremum" in html and "image/png" in html
    else:
        assert "holds no measured rows" in html and "Estimates per model level" not in html
    assert "0.236" in html
    assert nbformat.read(page.executed, as_version=4).cells[0].metadata["tags"] == ["parameters"]
