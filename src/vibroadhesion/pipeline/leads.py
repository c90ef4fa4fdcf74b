"""What each report page found, in two or three sentences read from its artefacts: the first lines of the page.

Each function takes the page's artefacts (the papermill parameters of its notebook) and returns Markdown; nothing
in a lead is typed in. A lead says where an artefact has nothing to say (no simulated pull-off, no compared level)
instead of a number. How the numbers were computed follows on the page, below its figure.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from pathlib import Path

import numpy as np
import pandas as pd

from vibroadhesion.core import groups, levels
from vibroadhesion.pipeline.data import read_canonical_setup
from vibroadhesion.pipeline.tables import significant

Path_ = str | Path


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def number(x: float, digits: int = 3, power: bool = False) -> str:
    """``x`` to ``digits`` significant figures as a reader writes it.

    Plain from 1e-3 to 1e5 (unless ``power``), else ``1.8 × 10⁴`` (``10⁹`` for a power of ten).
    """
    if not power and (x == 0 or 1e-3 <= abs(x) < 1e5):
        return significant(x, digits)
    mantissa, exponent = f"{x:.{digits - 1}e}".split("e")
    mantissa = mantissa.rstrip("0").rstrip(".")
    ten = "10" + str(int(exponent)).translate(_SUPERSCRIPT)
    return ten if mantissa == "1" else f"{mantissa} × {ten}"


def _span(values: Iterable[float], digits: int = 3) -> str:
    """``lo–hi`` of the finite ``values`` to ``digits`` significant figures (one number where they agree).

    Both ends in one notation (:func:`number`).
    """
    finite = [float(v) for v in values if v is not None and math.isfinite(float(v))]
    if not finite:
        return "—"
    lo, hi = min(finite), max(finite)
    power = any(x != 0 and not 1e-3 <= abs(x) < 1e5 for x in (lo, hi))
    lo_text, hi_text = number(lo, digits, power), number(hi, digits, power)
    return lo_text if lo_text == hi_text else f"{lo_text} – {hi_text}" if power else f"{lo_text}–{hi_text}"


def _percent_span(values: Iterable[float]) -> str:
    """``lo–hi %`` of relative values (0.27 -> 27 %), two significant figures."""
    return _span([100 * v for v in values], 2) + " %"


#: Curves closer than this share of the plot's height lie under one another at the page's size (a line's width).
COINCIDE = 0.01


def coinciding_frequencies(table: pd.DataFrame) -> list[float]:
    """The test frequencies whose refined curve of Fig. 4 (Eq. 106) is hidden under the leading order (Eqs. 71-72).

    Hidden: within :data:`COINCIDE` of the plot's height from the leading-order curve at every h1.
    """
    lead = table[table["model"] == "leading"].drop_duplicates("h1_um").set_index("h1_um")["pulloff_ratio"]
    height = float(table["pulloff_ratio"].max())
    out = []
    for f, rows in table[table["model"] == "refined"].groupby("frequency_hz", sort=True):
        gap = (rows["pulloff_ratio"].to_numpy() - lead.reindex(rows["h1_um"]).to_numpy())
        gap = pd.Series(np.abs(gap))
        if gap.notna().all() and float(gap.max()) <= COINCIDE * height:
            out.append(float(f))
    return out


def fig3(fig_csv: Path_, setup_json: Path_) -> str:
    """Fig. 3: how far J0 rises over the Abar range at the published n and at the other exponents (Eqs. 28, 29)."""
    n = read_canonical_setup(setup_json).n
    table = pd.read_csv(fig_csv)
    top = table.loc[table.groupby("n")["Abar"].idxmax()].set_index("n")
    at = top.loc[top.index[np.isclose(top.index, n)][0]]
    others = ", ".join(f"{number(row.J0)} at n = {k:g}" for k, row in top.iterrows() if not np.isclose(k, n))
    return (f"The J-integral J0, whose square is the pull-off amplification (Eq. 71), grows from 1 at small Ā to "
            f"{number(at['J0'])} at Ā = {number(at['Abar'])} for n = {n:g}. The exponent n sets the growth: J0 "
            f"at the largest Ā is {others}.")


def fig4(fig_csv: Path_, virtual_csv: Path_, setup_json: Path_) -> str:
    """Fig. 4: the leading order, the refined curves and the SIMULATED pull-off at the test amplitudes."""
    table = pd.read_csv(fig_csv)
    tests = table[table["h1_um"].isin(list(read_canonical_setup(setup_json).amplitudes_um))]
    lead = tests[tests["model"] == "leading"].drop_duplicates("h1_um").set_index("h1_um")["pulloff_ratio"]
    refined = tests[tests["model"] == "refined"]
    gap = (refined["pulloff_ratio"].to_numpy() / lead.reindex(refined["h1_um"]).to_numpy() - 1)
    virtual = pd.read_csv(virtual_csv)
    sim = virtual[(virtual["fixation"] == "rigid") & (virtual["model"] == "simulation")
                  & (virtual["status"] == "pulloff")]
    under = coinciding_frequencies(table)
    hidden = f", so at {'/'.join(f'{f:g}' for f in under)} Hz they lie under it in the figure" if under else ""
    text = (f"At the test amplitudes h1 = {_span(lead.index, 3)} µm the leading order predicts a pull-off "
            f"{_span(lead)} times the static JKR force; the refined curves at the test frequencies differ from it by "
            f"at most {significant(100 * float(np.nanmax(np.abs(gap))), 2)} %{hidden}.")
    if sim.empty:
        return text + " The SIMULATED pull-off experiment found no pull-off at these conditions."
    ratio = sim.set_index("h1_um")["pulloff_ratio"] / lead.reindex(sim["h1_um"]).to_numpy() - 1
    return (text + f" The SIMULATED pull-off of the full model is {_span(sim['pulloff_ratio'])} times the JKR force, "
            f"{_percent_span(ratio)} above the leading order at the same amplitude.")


def fig5(markers_csv: Path_) -> str:
    """Fig. 5: where the compliant fixation's response folds, and A/a_m at the test frequencies."""
    markers = pd.read_csv(markers_csv)
    folds = markers[markers["kind"] == "fold"]
    tests = markers[markers["kind"] == "experiment"]
    fold = ("No assumed fixation folds." if folds.empty else " ".join(
        f"At κ = {kappa:g} the response curve folds between ω̄ = {_span(rows['omega_bar'])}: the amplitude jumps "
        "there as the frequency passes." for kappa, rows in folds.groupby("kappa")))
    inside = " (inside the model's range A ≤ 0.1 a_m)" if (tests["A_over_am"] <= 0.1).all() else ""
    return (f"With a compliant fixation the contact amplitude A/a_m peaks near the natural frequency (ω̄ = 1). {fold} "
            f"At the rig's test frequencies A/a_m is {_span(tests['A_over_am'], 2)}{inside}.")


def fig6(fig_csv: Path_) -> str:
    """Fig. 6: w_eff/w0 at the highest frequency ratio, and where A/a_m falls below 0.1 at each amplitude."""
    table = pd.read_csv(fig_csv)
    top = table.loc[table.groupby("h1_um")["omega_check"].idxmax()]
    applies = table[table["A_over_am"] <= 0.1].groupby("h1_um")["omega_check"].min()
    return (f"The effective work of adhesion w_eff rises with the frequency ratio ω̌ and levels off at "
            f"{_span(top['w_eff_ratio'])} w0 for h1 = {_span(top['h1_um'])} µm. The contact amplitude A/a_m falls "
            f"below 0.1, where the model applies, above ω̌ = {_span(applies, 2)}, depending on the amplitude.")


def fig7(fig_csv: Path_) -> str:
    """Fig. 7: from which omega_check the refined pull-off (Eq. 106) is within 1 % of its high-frequency value."""
    table = pd.read_csv(fig_csv)
    top = table.loc[table.groupby("h1_um")["omega_check"].idxmax()].set_index("h1_um")["pulloff_ratio"]
    close = table[(table["pulloff_ratio"] / top.reindex(table["h1_um"]).to_numpy() - 1).abs() <= 0.01]
    reach = close.groupby("h1_um")["omega_check"].min()
    return (f"The refined pull-off estimate rises with the frequency ratio ω̌ and comes within 1 % of its "
            f"high-frequency value above ω̌ = {_span(reach, 2)}, depending on the amplitude. There it is "
            f"{_span(top)} times the static JKR force for h1 = {_span(top.index)} µm, the frequency-independent "
            "leading order (dashed).")


def fig8(fig_csv: Path_) -> str:
    """Fig. 8: the storage stiffness at both ends of the omega_check range, and the peak of the loss stiffness."""
    table = pd.read_csv(fig_csv)
    low = table.loc[table.groupby("h1_um")["omega_check"].idxmin()]
    high = table.loc[table.groupby("h1_um")["omega_check"].idxmax()]
    peak = table.loc[table["S_loss_rel"].idxmax()]
    return (f"The storage stiffness S'/(2E\\*a_m) runs from {_span(low['S_storage_rel'])} at ω̌ = "
            f"{number(low['omega_check'].min())} to {_span(high['S_storage_rel'])} at ω̌ = "
            f"{number(high['omega_check'].max())}, between the limits 1/3 and 1 (the flat punch). The loss "
            f"stiffness peaks at {significant(peak['S_loss_rel'], 3)} near ω̌ = {number(peak['omega_check'], 2)}.")


def validation(errors_csv: Path_, summary_csv: Path_, setup_json: Path_) -> str:
    """Validation: each level's error in w_eff/w0 at the test frequencies; the most accurate level overall.

    The validation runs at the published parameters: the test frequencies' omega_check (Eq. 105) at the published v0.
    """
    rig = read_canonical_setup(setup_json)
    test_omega = [float(groups.omega_check(f, rig.v0, rig.radius)) for f in rig.frequencies_hz]
    errors = pd.read_csv(errors_csv)
    at = errors[errors["omega_check"].isin(test_omega) & (errors["quantity"] == "w_eff_ratio")]
    if at.empty:
        return "No level could be compared with the simulation at the test frequencies: it found no steady state."
    by = at.groupby("model")["relative_error"]
    summary = pd.read_csv(summary_csv).set_index("model")
    best = summary["max_error_experiments_applicable"].idxmin()
    return (f"At the paper's test conditions the paper's formulas (leading order and refined) miss the simulated "
            f"effective work of adhesion w_eff by {_percent_span([by.min()['refined'], by.max()['refined']])}; exact "
            f"harmonic balance misses it as much ({_percent_span([by.max()['exact_hb']])} at most). The most accurate "
            f"level there, {_errs_by(best, summary.loc[best, 'max_error_experiments_applicable'])} in any quantity.")


def _errs_by(model: object, relative_error: float) -> str:
    """``<level label>, errs by up to <x> %``: the most accurate level of a lead and its largest relative error."""
    return f"{levels.level(str(model)).label}, errs by up to {significant(100 * float(relative_error), 2)} %"


def rigs(equivalence_csv: Path_) -> str:
    """Two rigs: the largest difference between the equal-amplitude force rig and the base rig."""
    table = pd.read_csv(equivalence_csv)
    sim = table[table["level"] == "simulation"].drop(columns=["zeta", "omega_bar", "level"])
    worst = float(np.nanmax(sim.to_numpy())) if sim.notna().any().any() else math.nan
    return ("At equal contact-displacement amplitude the force rig and the base rig give the same effective work of "
            "adhesion and the same pull-off: the SIMULATED rigs differ by at most "
            f"{number(worst, 2) if math.isfinite(worst) else '— (not simulated)'} (relative). They differ in "
            "the drive they need, which vanishes for the force rig at the base rig's anti-resonance.")


def benchmarks(speed_csv: Path_) -> str:
    """Benchmarks: the time per point and largest error of the cheapest and the most accurate level."""
    table = pd.read_csv(speed_csv).set_index("model")
    sim = table.loc["simulation"] if "simulation" in table.index else None
    levels_only = table.drop(index="simulation", errors="ignore")
    if levels_only["max_relative_error_vs_simulation"].isna().all() or sim is None:
        return "No level was compared with the simulation at the test conditions: it found no steady state there."
    best = levels_only["max_relative_error_vs_simulation"].idxmin()
    row = levels_only.loc[best]
    return (f"Every asymptotic level solves a test point in {_span(1e3 * levels_only['seconds_per_point_median'], 2)}"
            f" ms, the direct simulation in {significant(1e3 * sim['seconds_per_point_median'], 2)} ms. The most "
            f"accurate level, {_errs_by(best, row['max_relative_error_vs_simulation'])} at the test conditions, the "
            f"others by "
            f"up to {_percent_span([levels_only['max_relative_error_vs_simulation'].max()])}.")


def withdrawal(limits_csv: Path_) -> str:
    """Withdrawal: below which speeds the period-mean pull-off is within 1 % and 5 % of the quasi-static value."""
    limits = pd.read_csv(limits_csv)
    parts = []
    for fixation, rows in limits.groupby("fixation", sort=False):
        never = int(rows["V_over_v0_within_1pct"].isna().sum())
        parts.append(f"with {fixation} fixation below V = {_span(rows['V_over_v0_within_5pct'], 2)} v0 "
                     f"(1 %: {_span(rows['V_over_v0_within_1pct'], 2)} v0"
                     + (f"; {never} of {len(rows)} tests not within 1 % at any simulated speed)" if never else ")"))
    rising = all(rows.sort_values("h1_um")["V_over_v0_within_5pct"].dropna().is_monotonic_increasing
                 for _, rows in limits.groupby(["fixation", "frequency_hz"]))
    return ("A pull-off test must withdraw slowly enough for the quasi-static pull-off to hold: the SIMULATED "
            "period-mean pull-off stays within 5 % of its quasi-static value " + "; ".join(parts) + ", depending on "
            "frequency and amplitude." + (" Larger amplitudes tolerate faster withdrawal." if rising else ""))
