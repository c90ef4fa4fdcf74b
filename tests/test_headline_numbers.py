"""Every number docs/findings.md states about results, pinned to the pipeline's artefacts.

docs/findings.md is where the findings live as text (the report's index pages show them read from the artefacts);
the README's summary of them is pinned by :func:`check_readme` number by number, not by its wording. Each test here
quotes one phrase of docs/findings.md exactly (line breaks and runs of spaces count as one space) and marks the
numbers it pins with braces, ``{3.02}``; the test asserts that the document contains the phrase (braces removed) and
compares each marked number, in order, with values selected from the artefacts. So a number that changes in the
document or in the artefacts alone fails. The comparison follows the printed digits:

* ``{3.02}`` (rounds): the value rounded to the printed decimals, or to the printed significant
  digits in e-notation (``{1.6e-14}``), is the printed number; signed (``{+131}``, ``{−91}``) when
  the document prints a sign. A list of values must all round to it; a range ``{27}–{38} %`` is the
  min and the max over the rows the phrase names.
* ``{bound:1e-4}`` (the document's "agrees to 1e-4"): max <= 1e-4 and > 1e-5, a bound tight to its order
  (for differences the model makes: they do not move with the machine).
* ``{within:1e-9}`` (the document's "to 1e-9" for a difference that only rounding and solver tolerances make):
  max <= 1e-9. The bound follows from the numerics (the tolerance, the precision); how far below it a value
  falls depends on the CPU's rounding and the solver's path (4.4e-10 on one machine, 4e-12 on an AMD EPYC for
  the same two searches), so no lower limit is pinned.
* ``{about:8}`` (the document's "~8 %"): every value within one unit of the last printed digit.

Percentages are compared as percent. Timings (machine measurements) and Snakemake job counts are not pinned;
a test that uses the artefacts is marked ``pipeline`` (tests/conftest.py).
The artefacts come from the session fixture ``pipeline_results`` (tests/conftest.py): one
``snakemake -c2 all validation`` in a copy of the repository, or the finished results directory
named by the environment variable VIBROADHESION_RESULTS. Their paths, relative to ``results/``,
are the one dict ``ARTEFACTS`` below.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from conftest import FREQUENCIES_HZ, RADIUS, ROOT, V0

from vibroadhesion.experiments.fit_statistics import Settings
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.identifiability import IDENTIFIABLE_RELATIVE_SE

ARTEFACTS = {
    "rigid_grid": "simulation/rigid_grid.csv",
    "virtual_pulloff": "simulation/virtual_pulloff.csv",
    "compliant_sweep": "validation/compliant_sweep.csv",
    "fig5_markers": "fig5/fig5_markers.csv",
    "fits": "validation/identifiability/fits.csv",
    "information": "validation/identifiability/information.csv",
    "sensitivity": "validation/identifiability/sensitivity.csv",
    "sensitivity_runs": "validation/identifiability/sensitivity",
    "design": "validation/identifiability/design.csv",
    "candidates": "validation/identifiability/candidates.csv",
    "j_integrals": "benchmarks/j_integrals.csv",
    "simulate": "benchmarks/simulate.txt",
    "speed_vs_error": "benchmarks/speed_vs_error.csv",
    "speed_sweep": "withdrawal/speed_sweep.csv",
    "quasi_static_limits": "withdrawal/quasi_static_limits.csv",
    "rig_comparison": "validation/rig_comparison.csv",
    "rig_equivalence": "validation/rig_equivalence.csv",
}
FINDINGS = " ".join((ROOT / "docs" / "findings.md").read_text(encoding="utf-8").split())
README = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
MARK = re.compile(r"\{(?:(bound|about|within):)?([^}]*)\}")
Values = float | Sequence[float] | np.ndarray


# ----------------------------------------------------------------- the comparison


def _decimals(printed: str) -> int:
    """Digits after the point of a printed number (of its mantissa in e-notation)."""
    mantissa = printed.split("e")[0]
    return len(mantissa.split(".")[1]) if "." in mantissa else 0


def rounds_to(value: float, printed: str) -> bool:
    """Whether ``value`` rounded to the digits of ``printed`` (with its sign, if printed) is ``printed``."""
    text = printed.replace("−", "-")
    sign = "+" if text[0] in "+-" else ""
    if "e" in text:
        return float(f"{value:{sign}.{_decimals(text)}e}") == float(text)
    return f"{value:{sign}.{_decimals(text)}f}" == text


def satisfies(mode: str | None, values: np.ndarray, printed: str) -> bool:
    """The comparison of the module docstring for one marked number and the values it stands for.

    ``about`` is used with numbers in fixed notation only (its unit is that of the last printed decimal).
    """
    target = float(printed.replace("−", "-"))
    if mode == "bound":
        return bool(np.all(values <= target) and np.max(values) > target / 10)
    if mode == "within":
        return bool(np.all(values <= target))
    if mode == "about":
        unit = 10.0 ** -_decimals(printed)
        return bool(np.all(np.abs(values - target) <= unit))
    return all(rounds_to(float(v), printed) for v in values)


def check(phrase: str, values: Sequence[Values], document: str = FINDINGS) -> None:
    """Assert that docs/findings.md (or ``document``) states ``phrase`` and that its marked numbers describe ``values``."""
    text = " ".join(MARK.sub(r"\2", phrase).split())
    assert text in document, f"no longer stated: {text!r}"
    marks = MARK.findall(phrase)
    assert len(marks) == len(values), (marks, values)
    for (mode, printed), value in zip(marks, values, strict=True):
        array = np.atleast_1d(np.asarray(value, dtype=float))
        assert array.size and np.all(np.isfinite(array)), (printed, array)
        assert satisfies(mode or None, array, printed), f"stated: {printed} ({mode or 'rounds'}), artefact: {array}"


def check_readme(numbers: str, values: Sequence[Values]) -> None:
    """Assert that README.md states the marked ``numbers`` (a number or a short group of them, with their unit)."""
    check(numbers, values, README)


def test_the_comparison_follows_the_printed_digits() -> None:
    """The rules of the module docstring on hand-made cases, including the rounding edge."""
    assert rounds_to(7.4349, "7.43") and not rounds_to(7.4351, "7.43")
    assert rounds_to(-90.58, "−91") and not rounds_to(90.58, "−91") and rounds_to(131.0, "+131")
    assert rounds_to(1.62e-14, "1.6e-14") and not rounds_to(1.66e-14, "1.6e-14") and rounds_to(9.6e4, "1e5")
    assert satisfies("bound", np.array([6e-5, 1e-5]), "1e-4") and not satisfies("bound", np.array([9e-6]), "1e-4")
    assert not satisfies("bound", np.array([1.1e-4]), "1e-4")
    assert satisfies("within", np.array([4e-12, 0.0]), "1e-9") and not satisfies("within", np.array([1.1e-9]), "1e-9")
    assert satisfies("about", np.array([7.1, 8.9]), "8") and not satisfies("about", np.array([9.2]), "8")


# ----------------------------------------------------------------- artefact selections


def read(results: Path, name: str) -> pd.DataFrame:
    """One CSV artefact by its key in ARTEFACTS."""
    return pd.read_csv(results / ARTEFACTS[name])


def experimental_grid(results: Path) -> pd.DataFrame:
    """Rows of the rigid validation grid at the paper's test frequencies (omega_check = 2 pi f R/v0, Eq. 105)."""
    grid = read(results, "rigid_grid")
    wanted = [2 * math.pi * f * RADIUS / V0 for f in FREQUENCIES_HZ]
    rows = grid[[any(math.isclose(w, x, rel_tol=1e-9) for x in wanted) for w in grid["omega_check"]]]
    assert rows["omega_check"].nunique() == len(FREQUENCIES_HZ)
    return rows


def grid_quantity(results: Path, quantity: str) -> pd.DataFrame:
    """``quantity`` of experimental_grid, index (h1_um, omega_check), columns the model levels."""
    return experimental_grid(results).pivot(index=["h1_um", "omega_check"], columns="model", values=quantity)


def pulloff_ratios(results: Path, fixation: str) -> pd.DataFrame:
    """P_cr/P_JKR of the virtual pull-off experiment, index (frequency_hz, h1_um), columns the model levels."""
    table = read(results, "virtual_pulloff")
    return table[table["fixation"] == fixation].pivot(index=["frequency_hz", "h1_um"], columns="model",
                                                      values="pulloff_ratio")


def simulated_pulloffs(results: Path, fixation: str) -> pd.DataFrame:
    """The simulation rows of the virtual pull-off experiment for one fixation."""
    table = read(results, "virtual_pulloff")
    return table[(table["fixation"] == fixation) & (table["model"] == "simulation")]


def fit_row(results: Path, model: str) -> pd.Series:
    """The identifiability fit of one model level to the simulated pull-off rows."""
    fits = read(results, "fits").set_index("model")
    return fits.loc[model]


def cramer_rao(results: Path, design: str) -> pd.Series:
    """The row of information.csv for ``design`` at the smallest measurement scatter."""
    table = read(results, "information")
    rows = table[table["design"] == design]
    return rows.loc[rows["relative_noise"].idxmin()]


def sweep_simulation(results: Path) -> pd.DataFrame:
    """Simulated orbits of the compliant resonance sweep (both directions)."""
    sweep = read(results, "compliant_sweep")
    return sweep[sweep["model"] == "simulation"]


def percent_error(model: pd.Series, reference: pd.Series) -> np.ndarray:
    """100 |model/reference - 1| row by row."""
    return 100 * np.abs(model.to_numpy(float) / reference.to_numpy(float) - 1)


# ----------------------------------------------------------------- "What the validation found": rigid fixation


def test_test_frequencies_in_omega_check(pipeline_results: Path) -> None:
    omega_check = experimental_grid(pipeline_results)["omega_check"]
    check("(200–400 Hz, omega R/v0 = {1.45e6}–{2.9e6})", [omega_check.min(), omega_check.max()])


def test_every_amplitude_inside_the_applicability_rule(pipeline_results: Path) -> None:
    refined = grid_quantity(pipeline_results, "A_over_am")["refined"]
    check("every amplitude h1 = 20–100 um lies inside the paper's applicability rule (A <= {bound:0.1} a_m)", [refined])


def test_leading_and_refined_underestimate_w_eff(pipeline_results: Path) -> None:
    w = grid_quantity(pipeline_results, "w_eff_ratio")
    low = np.concatenate([100 * (1 - w[m] / w["simulation"]) for m in ("leading", "refined")])
    check("underestimate the simulated effective work of adhesion by {22}–{34} %", [low.min(), low.max()])
    check_readme("by {22}–{34} %", [low.min(), low.max()])


def test_w_eff_at_20_um(pipeline_results: Path) -> None:
    w = grid_quantity(pipeline_results, "w_eff_ratio").loc[20]
    check("(w_eff/w0 = {2.03} against {2.59} at 20 um;", [w[["leading", "refined"]].to_numpy().ravel(), w["simulation"]])


def test_w_eff_of_leading_and_refined_at_100_um(pipeline_results: Path) -> None:
    w = grid_quantity(pipeline_results, "w_eff_ratio").loc[100]
    values = w[["leading", "refined"]].to_numpy().ravel()
    check("{14.3}–{14.4} against 20.2–21.4 at 100 um)", [values.min(), values.max()])


def test_simulated_w_eff_at_100_um(pipeline_results: Path) -> None:
    simulated = grid_quantity(pipeline_results, "w_eff_ratio").loc[100, "simulation"]
    check("14.3–14.4 against {20.2}–{21.4} at 100 um)", [simulated.min(), simulated.max()])


def test_exact_averaging_against_the_simulation(pipeline_results: Path) -> None:
    """The quantity of the paragraph, w_eff/w0, at the three test frequencies."""
    w = grid_quantity(pipeline_results, "w_eff_ratio")
    error = (w["exact_averaging"] / w["simulation"] - 1).abs()
    check("agrees with the simulation to {bound:5e-5} at 20 um and to {12} % at 100 um",
          [error.loc[20].max(), 100 * error.loc[100].max()])


def test_contact_loss_below_omega_check_1e5(pipeline_results: Path) -> None:
    grid = read(pipeline_results, "rigid_grid")
    status = grid.pivot(index=["h1_um", "omega_check"], columns="model", values="status")
    lost = status[(status["simulation"] == "contact_loss") & (status["refined"] == "ok")]
    check("Below omega R/v0 ~ {1e5} the full model loses contact where the refined model still predicts a steady state",
          [lost.index.get_level_values("omega_check").max()])


# ----------------------------------------------------------------- compliant resonance sweep


def test_upper_fold_of_the_simulation_and_of_the_refined_model(pipeline_results: Path) -> None:
    """Simulation: the last omega_bar of the upward sweep before its largest drop in Abar. Refined: the upper
    fold of Fig. 5's curve for the sweep's kappa = 0.001, zeta = 0.01.
    """
    up = sweep_simulation(pipeline_results).query("direction == 'up'").sort_values("omega_bar")
    drop = np.argmin(np.diff(np.log(up["Abar"].to_numpy(float))))
    markers = read(pipeline_results, "fig5_markers")
    folds = markers[(markers["kind"] == "fold") & (markers["kappa"] == 0.001) & (markers["zeta"] == 0.01)]
    check("its upper fold lies beyond omega_bar = {11.29} where the refined model's is at {11.14}",
          [up["omega_bar"].iloc[drop], folds["omega_bar"].max()])


def test_unstable_orbits_below_omega_bar_8_4(pipeline_results: Path) -> None:
    sim = sweep_simulation(pipeline_results)
    unstable = sim[~sim["stable"].astype(bool)]
    assert unstable["omega_bar"].max() < sim.loc[sim["stable"].astype(bool), "omega_bar"].min()
    check("its orbits below omega_bar ~ {8.4} are unstable (a Floquet multiplier of modulus up to {1.15})",
          [unstable["omega_bar"].max(), sim["max_floquet_multiplier"].max()])


def test_far_above_resonance_simulation_and_refined_agree(pipeline_results: Path) -> None:
    sweep = read(pipeline_results, "compliant_sweep").query("18 <= omega_bar <= 20")
    both = sweep[sweep["model"] == "simulation"].merge(sweep[sweep["model"] == "refined"], on="omega_bar")
    check("Far above resonance (omega_bar = 18–20) the two agree to ~{about:8} % in A/a_m",
          [percent_error(both["A_over_am_y"], both["A_over_am_x"])])


# ----------------------------------------------------------------- virtual pull-off experiment


def test_simulated_rigid_pulloff_at_200_hz(pipeline_results: Path) -> None:
    ratio = pulloff_ratios(pipeline_results, "rigid").loc[200.0, "simulation"].sort_index()
    check("P_cr/P_JKR = {3.02} / {7.43} / {12.8} / {18.2} / {23.2} at 200 Hz for h1 = 20–100 um", list(ratio))


def test_eq_72_at_200_hz_and_how_low_it_is(pipeline_results: Path) -> None:
    ratio = pulloff_ratios(pipeline_results, "rigid")
    low = 100 * (1 - ratio["leading"] / ratio["simulation"])
    check("against Eq. (72)'s {2.21} / {4.75} / {8.08} / {12.0} / {16.5}: over 200–400 Hz the paper's estimate is "
          "{27}–{38} % low", [*ratio.loc[200.0, "leading"].sort_index(), low.min(), low.max()])
    check_readme("{27}–{38} % low", [low.min(), low.max()])


def test_simulated_detachment_radius(pipeline_results: Path) -> None:
    sim = simulated_pulloffs(pipeline_results, "rigid")
    radius = sim["abar_m"] / sim["abar_cr"]
    check("The simulated detachment happens at a mean radius of {0.78}–{0.83} a_cr", [radius.min(), radius.max()])


def test_force_minimum_of_the_exact_averaging(pipeline_results: Path) -> None:
    ratio = pulloff_ratios(pipeline_results, "rigid")
    high = (ratio["exact_averaging_force_minimum"] / ratio["simulation"] - 1).groupby(level="h1_um")
    check("matches the simulation to {bound:1e-4} at 20 um and is up to {0.6} % high at 40 um and {10}–{22} % high "
          "at 100 um", [high.max()[20], 100 * high.max()[40], 100 * high.min()[100], 100 * high.max()[100]])
    check_readme("to {bound:1e-4} at 20 µm", [high.max()[20]])
    check_readme("{10}–{22} % high at 100 µm", [100 * high.min()[100], 100 * high.max()[100]])


def test_compliant_fixation_of_the_virtual_experiment(pipeline_results: Path) -> None:
    sim = simulated_pulloffs(pipeline_results, "compliant")
    check("(kappa = {0.001}, zeta = {0.01}, the validation sweep's;", [sim["kappa"], sim["zeta"]])


def test_simulated_compliant_pulloff_and_its_excess_over_rigid(pipeline_results: Path) -> None:
    compliant = pulloff_ratios(pipeline_results, "compliant")["simulation"]
    above = 100 * (compliant / pulloff_ratios(pipeline_results, "rigid")["simulation"] - 1)
    check("gives {3.45} / {9.19} / {16.3} / {23.3} / {28.8} at 200 Hz, {3}–{28} % above the rigid values",
          [*compliant.loc[200.0].sort_index(), above.min(), above.max()])


def test_compliant_leading_order_and_how_low_the_estimates_are(pipeline_results: Path) -> None:
    ratio = pulloff_ratios(pipeline_results, "compliant")
    low = np.concatenate([100 * (1 - ratio[m] / ratio["simulation"]) for m in ("leading", "refined")])
    check("{2.47} / {5.82} / {10.6} / {16.7} / {24.3} from Eqs. (67)–(69): over 200–400 Hz the compliant "
          "leading-order and refined estimates are {16}–{38} % low",
          [*ratio.loc[200.0, "leading"].sort_index(), low.min(), low.max()])


# ----------------------------------------------------------------- identifiability


def test_true_parameters_of_the_table(pipeline_results: Path) -> None:
    fits = read(pipeline_results, "fits")
    check("| w0 (true {0.236} J/m²) | n (true {0.531}) | rms misfit |",
          [fits["w0"] / (1 + fits["w0_relative_bias"]), fits["n"] / (1 + fits["n_relative_bias"])])


@pytest.mark.parametrize(("model", "phrase"), [
    ("leading", "| leading, Eq. (72) | poor fit, n at its bound {0.05} | {0.545} ± {0.091} ({+131} %) | {0.05} ({−91} %) | "
                "{20.4} % |"),
    ("refined", "| refined, Eq. (106) | poor fit, v0 not identifiable | {0.606} ± {0.112} ({+157} %) | {0.375} ± {0.485} "
                "({−29} %) | {24.2} % |"),
    ("exact_averaging", "| exact averaging, a_m = a_cr | n not determined | {0.238} ± {0.094} ({+0.9} %) | {0.092} ± {0.670} "
                        "({−83} %) | {4.6} % |"),
    ("exact_averaging_force_minimum", "| exact averaging, force minimum | poor fit | {0.419} ± {0.200} ({+77} %) | {2.52} "
                                      "± {2.92} ({+375} %) | {7.4} % |"),
    ("simulation", "| simulation, Eqs. (4)–(11) | fitted, v0 identifiable | {0.236} ± {0.001} ({0.0} %) | {0.531} ± "
                   "{0.005} ({0.0} %) | {0.0} % |"),
])
def test_identifiability_table_row(pipeline_results: Path, model: str, phrase: str) -> None:
    fit = fit_row(pipeline_results, model)
    w0 = [fit["w0"], fit["w0_se"], 100 * fit["w0_relative_bias"]]
    n_bias = 100 * fit["n_relative_bias"]
    n = [fit["n"], n_bias] if model == "leading" else [fit["n"], fit["n_se"], n_bias]
    bound = [fit["n"]] if model == "leading" else []
    check(phrase, [*bound, *w0, *n, 100 * fit["rms_relative_residual"]])


def test_identifiability_table_status(pipeline_results: Path) -> None:
    """The status column: the simulation is fitted; leading (n on its bound), refined and the force minimum are poor
    fits (their model error against the chi-square test at the stated 5 % scatter); the exact averaging leaves n
    not determined; v0 identifiable by the simulation only (noise-free rows, at the 0.1 % residual floor)."""
    fits = read(pipeline_results, "fits").set_index("model")
    assert dict(fits["status"]) == {"simulation": "fitted", "leading": "poor_fit", "refined": "poor_fit",
                                    "exact_averaging": "not_identifiable", "exact_averaging_force_minimum": "poor_fit"}
    assert fits["v0_identifiable"].astype(bool).to_dict() == {"simulation": True, "leading": False, "refined": False,
                                                             "exact_averaging": False,
                                                             "exact_averaging_force_minimum": False}
    check("v0 is freed by the simulation fit on these noise-free rows (relative standard error {8} % at the {0.1} % "
          "residual floor", [100 * float(fits.loc["simulation", "note"].rsplit(" ", 1)[1]),
                             100 * Settings().noise_floor])
    check("| leading, Eq. (72) | poor fit, n at its bound 0.05 |", [])
    check("| refined, Eq. (106) | poor fit, v0 not identifiable |", [])


def test_cramer_rao_errors_of_w0_and_v0_and_the_correlation(pipeline_results: Path) -> None:
    row = cramer_rao(pipeline_results, "virtual experiment")
    check("at {1} % measurement scatter the Cramér–Rao standard errors are w0 {4.0} %, n 9.1 %, v0 {82} % "
          "(n and v0 correlated at {0.997};",
          [100 * row["relative_noise"], 100 * row["w0_relative_se"], 100 * row["v0_relative_se"], row["corr_n_v0"]])
    check_readme("w0 {4.0} %, n {9.1} % at {1} %", [100 * row["w0_relative_se"], 100 * row["n_relative_se"],
                                                        100 * row["relative_noise"]])
    check_readme("v0 ({82} %)", [100 * row["v0_relative_se"]])


def test_cramer_rao_error_of_n(pipeline_results: Path) -> None:
    row = cramer_rao(pipeline_results, "virtual experiment")
    check("the Cramér–Rao standard errors are w0 4.0 %, n {9.1} %, v0 82 %", [100 * row["n_relative_se"]])


def test_frequency_dependence_of_the_simulated_pulloff(pipeline_results: Path) -> None:
    force = simulated_pulloffs(pipeline_results, "rigid").pivot(index="h1_um", columns="frequency_hz",
                                                                  values="pulloff_mN").loc[60:]
    change = 100 * (force.max(axis=1) / force.min(axis=1) - 1)
    check("v0 enters only through the {3}–{10} % frequency dependence at h1 >= 60 um", [change.min(), change.max()])


def test_v0_sensitivity_against_the_frequency_derivative(pipeline_results: Path) -> None:
    """d ln P/d ln v0 = -d ln P/d ln omega (v0 enters only through omega R/v0, Eq. 105): the sensitivity
    column at 300 Hz against the derivative of the parabola in ln f through the simulated 200/300/400 Hz rows.
    """
    force = simulated_pulloffs(pipeline_results, "rigid").pivot(index="h1_um", columns="frequency_hz",
                                                                  values="pulloff_mN").loc[60:]
    log_f = np.log(force.columns.to_numpy(float))
    derivative = [-np.polyval(np.polyder(np.polyfit(log_f, np.log(row), 2)), math.log(300.0)) for row in force.to_numpy()]
    sensitivity = read(pipeline_results, "sensitivity").query("frequency_hz == 300.0").set_index("h1_um").loc[60:]
    check("checked against the simulated rows' own frequency derivative to {1}–{2} %",
          [100 * np.min(np.abs(sensitivity["dlnP_dlnv0"] / derivative - 1)),
           100 * np.max(np.abs(sensitivity["dlnP_dlnv0"] / derivative - 1))])


def test_recommended_level_and_the_static_test(pipeline_results: Path) -> None:
    with_static = cramer_rao(pipeline_results, "virtual experiment + static JKR pull-off")
    check("only `exact_averaging`'s w0 is close (bias {+0.9} %, inside the {4.0} % the scatter allows)",
          [100 * fit_row(pipeline_results, "exact_averaging")["w0_relative_bias"],
           100 * cramer_rao(pipeline_results, "virtual experiment")["w0_relative_se"]])
    check("One static (h1 = 0) JKR pull-off test would pin w0 to {1.0} %", [100 * with_static["w0_relative_se"]])


def test_design_table(pipeline_results: Path) -> None:
    """The table of the D-optimal added tests: its rows are design.csv's, in its order."""
    design = read(pipeline_results, "design")
    rows = [("none (the rig's 15)", "current"), ("10 Hz, h1 = 80 um", "current + 1 test"),
            ("10 Hz, 80 um; 30 Hz, 120 um", "current + 2 tests"),
            ("10 Hz, 80 um; 30 Hz, 120 um; static JKR", "current + 3 tests")]
    added = {"current + 1 test": "10 Hz, h1 = 80 um", "current + 2 tests": "10 Hz, h1 = 80 um; 30 Hz, h1 = 120 um",
             "current + 3 tests": "10 Hz, h1 = 80 um; 30 Hz, h1 = 120 um; static JKR test (h1 = 0)"}
    assert design.set_index("design")["added"].dropna().to_dict() == added
    for label, name in rows:
        se = design[design["design"] == name].set_index("relative_noise")
        printed = {"current": "{4.0} / {20} % | {9.1} / {45} % | {82} / {409} %",
                   "current + 1 test": "{2.5} / {13} % | {2.3} / {11} % | {17} / {85} %",
                   "current + 2 tests": "{2.5} / {13} % | {0.43} / {2.2} % | {6.6} / {33} %",
                   "current + 3 tests": "{0.93} / {4.6} % | {0.42} / {2.1} % | {3.7} / {19} %"}[name]
        check(f"| {label} | {printed} |", [100 * se.loc[noise, f"{p}_relative_se"]
                                            for p in ("w0", "n", "v0") for noise in (0.01, 0.05)])
    check("So v0 becomes identifiable (relative standard error below {50} %) with one added test at 10 Hz at 1 % "
          "scatter, and with two, at 10 and 30 Hz, at 5 %", [100 * IDENTIFIABLE_RELATIVE_SE])
    assert design.query("relative_noise == 0.01")["v0_identifiable"].tolist() == [False, True, True, True]
    assert design.query("relative_noise == 0.05")["v0_identifiable"].tolist() == [False, False, True, True]
    lost = read(pipeline_results, "candidates").query("status == 'contact_loss_before_extremum'")
    first = lost.groupby("frequency_hz")["h1_um"].min()
    check("(1 Hz from h1 = {40} um, 3 Hz from {60} um, 10 Hz from {100} um;", [first[1.0], first[3.0], first[10.0]])


# ----------------------------------------------------------------- Performance: the numbers that are not timings


def test_steady_states_per_amplitude(pipeline_results: Path) -> None:
    rigid = simulated_pulloffs(pipeline_results, "rigid")["steady_states"]
    compliant = simulated_pulloffs(pipeline_results, "compliant")["steady_states"]
    check("({14}–{28} steady states per amplitude)", [rigid.min(), rigid.max()])
    check("({25}–{52} steady states per amplitude, including the Brent polish", [compliant.min(), compliant.max()])


def test_simulated_orbits_and_pulloffs_per_job(pipeline_results: Path) -> None:
    runs = [pd.read_csv(run) for run in (pipeline_results / ARTEFACTS["sensitivity_runs"]).glob("*.csv")]
    rig = [set(run["frequency_hz"]) <= set(FREQUENCIES_HZ) for run in runs]
    check("({82} simulated orbits)", [len(sweep_simulation(pipeline_results))])
    check("one job for the rig's test frequencies ({18} simulated pull-offs and their envelope derivatives",
          [[len(run) for run, ours in zip(runs, rig, strict=True) if ours]])
    check("one job of {36} for the design's other candidate frequencies",
          [[len(run) for run, ours in zip(runs, rig, strict=True) if not ours]])


def test_j_integral_accuracy(pipeline_results: Path) -> None:
    table = read(pipeline_results, "j_integrals")
    fixed = table[table["method"].str.startswith("fixed rule")]
    check("at <= {1.1e-14} relative error against mpmath", [fixed["max_relative_error"].max()])


def test_shooting_self_consistency(pipeline_results: Path) -> None:
    """Column "rtol 1e-13 diff" of the converged (status ok) rigid n = 0.531 cases of benchmarks/simulate.txt.

    A row is the case (3 words), omega_check, status, periods, cpu min, cpu med, wall ms, then the difference.
    """
    lines = (pipeline_results / ARTEFACTS["simulate"]).read_text().splitlines()
    header = next(line for line in lines if line.startswith("case"))
    assert "cpu min  cpu med  wall ms rtol 1e-13 diff" in header, header
    diffs = [float(line.split()[9]) for line in lines if line.startswith("rigid n=0.531") and " ok " in line]
    assert len(diffs) == 14
    check("self-consistent to <= {2.1e-10} between rtol 1e-12 and 1e-13", [max(diffs)])


def test_speed_against_error(pipeline_results: Path) -> None:
    table = read(pipeline_results, "speed_vs_error").set_index("model")
    error = 100 * table["max_relative_error_vs_simulation"]
    check("at up to {34} % error against the simulation; exact harmonic balance", [error[["leading", "refined", "exact_hb"]]])
    check("at up to {15} % (median {0.8} %)",
          [error["exact_averaging"], 100 * table.loc["exact_averaging", "median_relative_error_vs_simulation"]])
