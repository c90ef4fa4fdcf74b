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
import yaml

from vibroadhesion.core import levels
from vibroadhesion.experiments.pulloff import GentSchultzParameters, predict_pulloff
from vibroadhesion.models.refined import APPLICABILITY_LIMIT, VALIDATED_OMEGA_CHECK
from vibroadhesion.pipeline import data, fit_report, page_figures, tables
from vibroadhesion.pipeline.input_checks import schema_validator
from vibroadhesion.pipeline.steps.report import Page, render_page, reset_namespace, shared_kernel

ROOT = Path(__file__).resolve().parents[2]
PUBLISHED = {"w0": 0.236, "n": 0.531, "v0": 4.45e-05}
UNITS = {"w0": "J/m^2", "n": "1", "v0": "m/s"}


def _parameters(values: dict[str, float], errors: dict[str, float | None], statuses: dict[str, str],
                intervals: dict[str, list[float]] | None = None) -> dict:
    """Parameter entries of the fit JSON (pipeline/schemas/fit.schema.json), ``published`` where no status is given."""
    return {name: {"estimate": values[name], "std_error": errors.get(name), "unit": UNITS[name],
                   "status": statuses.get(name, "published"), "reason": "",
                   "interval": (intervals or {}).get(name)} for name in ("w0", "n", "v0")}


def _fit(rows: int) -> dict:
    """A fit of 3 rows (lines 2-4: 200 Hz/20 um 170 mN, 300 Hz/60 um 700 mN, 400 Hz/100 um 1400 mN)."""
    simulation = {
        "model": "simulation", "rows": rows, "status": "fitted", "note": "", "free_parameters": ["w0", "n", "v0"],
        "at_bound": [], "v0_identifiable": True, "v0_note": "v0 identifiable: relative standard error 0.117",
        "determined": ["w0", "n", "v0"],
        "parameters": _parameters({"w0": 0.2361234, "n": 0.531, "v0": 4.503121e-05},
                                  {"w0": 0.001234, "n": 0.25, "v0": 1.87152e-07}, dict.fromkeys(PUBLISHED, "fitted"),
                                  {"w0": [0.2337, 0.2386], "n": [0.31, 1.42], "v0": [4.46e-05, 4.541e-05]}),
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
        "determined": [],
        "parameters": _parameters({"w0": 0.49, "n": 0.05000000000000003, "v0": 4.45e-05}, {"w0": 0.12},
                                  {"w0": "not_identifiable", "n": "at_bound"}),
        "residuals_mN": [{"line": 2, "residual": 17.0}, {"line": 3, "residual": -140.0},
                         {"line": 4, "residual": -280.0}],
        "rms_relative_residual": 0.17,
    }
    refined = {"model": "refined", "rows": rows, "status": "failed", "note": "no root at a trial point",
               "determined": [], "v0_identifiable": False, "v0_note": "no fit",
               "parameters": _parameters(PUBLISHED, {}, {})}
    fits = {"refined": refined, "simulation": simulation, "leading": leading}  # not in the registry's order
    if rows == 0:
        fits = {name: {"model": name, "rows": 0, "status": "published", "note": "no rows: published values kept",
                       "determined": [], "v0_identifiable": False, "v0_note": "",
                       "parameters": _parameters(PUBLISHED, {}, {})}
                for name in ("simulation", "leading")}
    fit = {"data_rows": rows, "figures_preferred": "simulation", "figures_use": "simulation" if rows else "published",
           "figures_reason": "the simulation fit determines every parameter it fits" if rows else "no measured rows",
           "fits": fits, "status": "", "published": {**PUBLISHED, "source": "Fig. 4 caption"},
           "settings": {"confidence": 0.95, "relative_scatter": 0.05, "alpha": 0.05, "max_relative_se": 0.5}}
    schema_validator("fit").validate(fit)
    return fit


def _rows(tmp_path: Path) -> pd.DataFrame:
    csv = tmp_path / "pulloff.csv"
    csv.write_text("line,frequency_hz,h1_um,pulloff_mN,source\n2,200.0,20.0,170.0,lab A\n3,300.0,60.0,700.0,lab A\n"
                   "4,400.0,100.0,1400.0,lab B\n")
    return data.read_canonical_pulloff(csv)


def _setup_json(tmp_path: Path) -> Path:
    """The canonical setup of data/setup.yaml (R = 51.5 mm, E* = 2 x 2.8 MPa/(1 - 0.5^2))."""
    setup_json = tmp_path / "setup.json"
    data.ingest(ROOT / "data/setup.yaml", ROOT / "data/pulloff.csv", setup_json, tmp_path / "ingested.csv")
    return setup_json


def test_levels_in_the_registry_order_with_the_converged_simulation_as_headline() -> None:
    fit = _fit(3)
    assert fit_report.ordered_levels(fit) == ["simulation", "leading", "refined"]
    assert fit_report.headline(fit) == "simulation"
    fit["fits"]["simulation"]["status"] = "failed"
    assert fit_report.headline(fit) is None
    assert "reached no estimate (**failed**" in fit_report.summary_sentence(fit)


def test_estimates_give_value_and_interval_or_say_not_determined() -> None:
    """A fitted parameter: its value and its interval to 3 figures; a parameter on a bound or not determined: "not
    determined by these rows", never a bare number; a parameter not fitted: its published value as typed."""
    table = fit_report.estimates(_fit(3)).set_index("level")
    simulation, leading, refined = (levels.level(name).label for name in ("simulation", "leading", "refined"))
    assert table.loc[simulation, "w0"] == "0.236 [0.234, 0.239]"
    assert table.loc[simulation, "v0"] == "4.50e-05 [4.46e-05, 4.54e-05]"
    assert table.loc[leading, "n"] == "not determined by these rows (on its bound 0.0500)"
    assert table.loc[leading, "w0"] == "not determined by these rows"
    assert table.loc[leading, "v0"] == "4.45e-05 (fixed: published)"  # as published, no padding zero
    assert table.loc[refined, "w0"] == "0.236 (fixed: published)" and "no root" in table.loc[refined, "reason"]
    assert table.loc[simulation, "status"] == "fitted" and table.loc[leading, "status"] == "at a bound"
    assert table.loc[simulation, "rms_relative_residual"] == 0.5774
    assert math.isnan(table.loc[refined, "rms_relative_residual"])


def test_figure_pages_show_the_fit_the_figures_use_and_the_headline() -> None:
    fit = _fit(3)
    assert fit_report.figures_fit(fit)["level"].tolist() == [levels.level("simulation").label]
    fit["figures_use"] = "leading"
    assert fit_report.figures_fit(fit)["level"].tolist() == [levels.level(n).label for n in ("simulation", "leading")]


def test_measured_against_predicted_per_row_with_the_contact_loss_row_unpredicted(tmp_path: Path) -> None:
    table = fit_report.measured_vs_predicted(_fit(3), _rows(tmp_path), _setup_json(tmp_path))
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


def test_speed_column_shown_where_a_row_has_one_and_the_static_frequency_is_missing_not_zero(tmp_path: Path) -> None:
    """The withdrawal speed (um/s) appears as a column only where a row has one (quasi-static rows "—", NaN), with a
    sentence on how the levels treat it; a static JKR test's frequency is "—" (NaN), not 0."""
    csv = tmp_path / "pulloff.csv"
    csv.write_text("line,frequency_hz,h1_um,pulloff_mN,source,withdrawal_speed_um_s\n2,200.0,20.0,170.0,lab A,44.5\n"
                   "3,300.0,60.0,700.0,lab A,\n4,400.0,100.0,1400.0,lab B,0\n5,,0.0,57.0,lab C,\n")
    rows = data.read_canonical_pulloff(csv)
    setup_json = _setup_json(tmp_path)
    table = fit_report.measured_vs_predicted(_fit(3), rows, setup_json)
    assert table.columns[:5].tolist() == ["frequency_hz", "h1_um", "withdrawal_speed_um_s", "source", "pulloff_mN"]
    assert table["withdrawal_speed_um_s"].iloc[0] == 44.5 and table["withdrawal_speed_um_s"].iloc[1:].isna().all()
    assert table["frequency_hz"].iloc[:3].tolist() == [200.0, 300.0, 400.0] and math.isnan(table["frequency_hz"].iloc[3])
    shown = tables.formatted(table, fit_report.measured_vs_predicted_columns(table))
    assert shown["f (Hz)"].tolist() == ["200", "300", "400", tables.MISSING]
    assert shown["V, withdrawal speed (µm/s)"].tolist() == ["44.5"] + [tables.MISSING] * 3
    sentence = fit_report.speed_sentence(table)
    assert sentence.startswith("1 of 4 rows were measured at a withdrawal speed V") and "as if V → 0" in sentence
    quasi_static = fit_report.measured_vs_predicted(_fit(3), _rows(tmp_path), setup_json)
    assert "withdrawal_speed_um_s" not in quasi_static and fit_report.speed_sentence(quasi_static) == ""


def test_figure_pages_show_the_measured_rows_as_the_fit_page_does(tmp_path: Path) -> None:
    """Fig. 4's page shows the measured rows by measured_table: a static JKR test's frequency "—" (the canonical file
    stores 0), a quasi-static row's speed "—" (stored 0), the speed column read "V, withdrawal speed (µm/s)" and the
    force "measured |P_cr| (mN)" -- the first columns of the fit page's table, the same cells."""
    csv = tmp_path / "pulloff.csv"
    csv.write_text("line,frequency_hz,h1_um,pulloff_mN,source,withdrawal_speed_um_s\n2,200.0,20.0,170.0,lab A,44.5\n"
                   "3,,0.0,57.0,lab C,\n")
    rows = fit_report.measured_rows(csv)
    shown = tables.formatted(fit_report.measured_table(rows), fit_report.MEASURED_COLUMNS)
    assert shown["f (Hz)"].tolist() == ["200", tables.MISSING]
    assert shown["V, withdrawal speed (µm/s)"].tolist() == ["44.5", tables.MISSING]
    assert shown["measured |P_cr| (mN)"].tolist() == ["170", "57"]
    fit_page = tables.formatted(fit_report.measured_vs_predicted(_fit(3), rows, _setup_json(tmp_path)),
                                fit_report.measured_vs_predicted_columns(fit_report.measured_table(rows)))
    assert shown.equals(fit_page[shown.columns])


@pytest.mark.parametrize("omega_check, a_over_am, expected", [
    (1.437e6, 0.0019, "inside"),
    (1.437e6, 0.1, "inside"),  # the paper's A <= 0.1 a_m
    (7186.0, 0.33, "outside the asymptotic levels' range: A/a_m = 0.33 > 0.1"),
    (718.6, 0.0155, "outside the asymptotic levels' range: ωR/v0 = 719 outside 10^3–10^8"),
    (2.0e8, 0.23, "outside the asymptotic levels' range: A/a_m = 0.23 > 0.1, ωR/v0 = 2e+08 outside 10^3–10^8"),
    (7186.0, math.nan, "outside the asymptotic levels' range: A/a_m unknown (the refined model has no pull-off)"),
    (math.nan, 0.0, "inside"),  # a static JKR test: no frequency, Eq. (70) at every level
])
def test_outside_text_on_both_sides_of_the_limits(omega_check: float, a_over_am: float, expected: str) -> None:
    assert fit_report.outside_text(omega_check, a_over_am) == expected


def test_the_validated_range_is_the_validation_grid() -> None:
    """VALIDATED_OMEGA_CHECK is the omega_check range the validation compares the levels over (workflow config)."""
    config = yaml.safe_load((ROOT / "workflow/config.yaml").read_text())["validation"]
    assert VALIDATED_OMEGA_CHECK == (10.0 ** config["log10_omega_check_min"], 10.0 ** config["log10_omega_check_max"])


def test_rows_outside_the_asymptotic_levels_range_are_flagged_in_table_plot_and_sentence(tmp_path: Path) -> None:
    """Rows on both sides of A/a_m = 0.1 and of the validated omega_check range, in the table, plot and sentence.

    The 3 rows of the fixture (A/a_m 0.002-0.05 at 200-400 Hz) and three more: 1 Hz, 20 um (omega_check 7.2e3,
    inside the validated range, refined A/a_m 0.33 > 0.1), 0.1 Hz, 2 um (omega_check 719 < 1e3, A/a_m 0.016) and a
    static JKR test. omega_check = 2 pi f R/v0 (Eq. 105) with the simulation fit's v0 (the headline) is checked by
    hand; A/a_m is the refined model's (Eq. 106, tested in tests/models) at that fit, R and E* of the setup.
    """
    csv = tmp_path / "pulloff.csv"
    csv.write_text("line,frequency_hz,h1_um,pulloff_mN,source\n2,200.0,20.0,170.0,lab A\n3,300.0,60.0,700.0,lab A\n"
                   "4,400.0,100.0,1400.0,lab B\n5,1.0,20.0,150.0,lab C\n6,0.1,2.0,60.0,lab C\n7,,0.0,57.0,lab C\n")
    rows = data.read_canonical_pulloff(csv)
    setup_json = _setup_json(tmp_path)
    fit = _fit(3)
    table = fit_report.measured_vs_predicted(fit, rows, setup_json)
    v0 = 4.503121e-05
    assert table["omega_check"].iloc[:5].tolist() == pytest.approx(
        [2 * math.pi * f * 51.5e-3 / v0 for f in (200.0, 300.0, 400.0, 1.0, 0.1)], rel=1e-14)
    assert math.isnan(table["omega_check"].iloc[5]) and table["A_over_am:refined"].iloc[5] == 0.0
    setup = data.read_canonical_setup(setup_json)
    params = GentSchultzParameters(0.2361234, 0.531, v0)
    refined = predict_pulloff("refined", params, [200.0, 300.0, 400.0, 1.0, 0.1], [20.0, 60.0, 100.0, 20.0, 2.0],
                              radius=setup.radius, reduced_modulus=setup.reduced_modulus).A_over_am
    assert table["A_over_am:refined"].iloc[:5].tolist() == pytest.approx(list(refined), rel=1e-12)
    assert max(refined[:3]) < APPLICABILITY_LIMIT < refined[3] and refined[4] < APPLICABILITY_LIMIT
    assert table["range"].tolist() == ["inside"] * 3 + [
        f"outside the asymptotic levels' range: A/a_m = {refined[3]:.2g} > 0.1",
        "outside the asymptotic levels' range: ωR/v0 = 719 outside 10^3–10^8", "inside"]
    assert fit_report.range_sentence(table).startswith("2 of 6 rows lie outside the asymptotic levels' range")
    plotted = fit_report.long_predictions(table)
    assert set(plotted.loc[plotted["range"] != "inside", "measured_mN"]) <= {150.0, 60.0}
    headers = fit_report.measured_vs_predicted_columns(table)
    assert headers["range"].header == "asymptotic levels' range" and headers["range"].format == "text"
    fig = page_figures.plot_measured_vs_predicted(pd.DataFrame({
        "level": ["a", "a"], "measured_mN": [170.0, 150.0], "predicted_mN": [171.0, 140.0],
        "range": ["inside", table["range"].iloc[3]]}))
    assert [t.get_text() for t in fig.axes[0].texts] == [f"A/a_m = {refined[3]:.2g} > 0.1"]
    assert "outside the asymptotic levels' range" in [t.get_text() for t in fig.legends[0].get_texts()]


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
        assert "0.236 [0.234, 0.239]" in html and "contact loss before extremum" in html and "image/png" in html
        assert "All 3 rows lie inside the asymptotic levels" in html
    else:
        assert "holds no measured rows" in html and "Estimates per model level" not in html
    assert "0.236" in html
    assert nbformat.read(page.executed, as_version=4).cells[0].metadata["tags"] == ["parameters"]
