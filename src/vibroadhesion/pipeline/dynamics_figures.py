"""Drawings of the paper's open questions: the pull-off at a finite withdrawal speed and the two rigs.

The Discussion's finite withdrawal speed (:mod:`vibroadhesion.experiments.speed_sweep`) and Appendix B's base
and force rigs (:mod:`vibroadhesion.experiments.rigs`), drawn from their tables in the style of
:mod:`vibroadhesion.pipeline.figures` (which sets matplotlib's backend and style on import).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from vibroadhesion.pipeline.figures import legend_below  # also sets the backend (Agg) and the style

__all__ = ["plot_rig_comparison", "plot_speed_sweep"]


# --- Withdrawal at a finite speed (issue 15) ----------------------------------------------------

def plot_speed_sweep(sweep: pd.DataFrame) -> Figure:
    """Period-mean pull-off P/|P_JKR| (Eqs. 4', 70) against V/v0, one panel per fixation, the method of each point.

    One colour and marker per (frequency, h1) of :mod:`vibroadhesion.experiments.speed_sweep`: the time-domain
    withdrawal (SIMULATED) as a solid line with markers, the averaged slow flow (rigid only) as a dotted line with
    plus signs; the quasi-static family value (the V -> 0 asymptote) as a dashed tick at the left of each line;
    open markers: detached before the period-mean force passed its extremum (the instantaneous reading); speeds skipped
    by the stopping rule (status skipped_within_tolerance) have no point. One legend below the panels, off the data.
    """
    fixations = list(dict.fromkeys(sweep["fixation"]))
    amplitudes, frequencies = sorted(set(sweep["h1_um"])), sorted(set(sweep["frequency_hz"]))
    fig, axes = plt.subplots(1, len(fixations), figsize=(5.2 * len(fixations), 4.4), layout="constrained",
                             squeeze=False)
    for ax, fixation in zip(axes[0], fixations, strict=True):
        rows = sweep[sweep["fixation"] == fixation]
        for (frequency, h1), test in rows.groupby(["frequency_hz", "h1_um"], sort=True):
            test = test.sort_values("V_over_v0")
            color, marker = f"C{amplitudes.index(h1) % 10}", "os^Dv"[frequencies.index(frequency) % 5]
            timed, slow = test[test["method"] == "time_domain"], test[test["method"] == "slow_flow"]
            done = timed["status"] == "pulloff"
            ax.plot(timed["V_over_v0"], timed["mean_pulloff_ratio"], "-", color=color, lw=0.8, marker=marker, ms=4,
                    mfc="none", label=f"{frequency:g} Hz, {h1:g} µm")
            ax.plot(timed.loc[done, "V_over_v0"], timed.loc[done, "mean_pulloff_ratio"], marker, color=color, ms=4)
            ax.plot(slow["V_over_v0"], slow["mean_pulloff_ratio"], ":", color=color, lw=0.8, marker="+", ms=5)
            v_min = float(test.dropna(subset=["mean_pulloff_ratio"])["V_over_v0"].min())  # skipped speeds: no point
            ax.plot([v_min / 4.0, v_min], [timed["quasi_static_ratio"].iloc[0]] * 2, "--", color=color, lw=1.5)
        drawn = bool((rows["mean_pulloff_ratio"] > 0).any())  # none where every withdrawal ended without one
        if not drawn:
            ax.text(0.5, 0.5, "no simulated pull-off at any speed", transform=ax.transAxes, ha="center",
                    va="center", color="0.35")
        ax.set(xscale="log", yscale="log" if drawn else "linear", xlabel=r"withdrawal speed $V/v_0$",
               ylabel=r"pull-off $P/|P_{JKR}|$ (period mean)", title=f"{fixation} fixation")
    legend_below(fig, axes[0], fontsize=6.5, ncols=5, title="solid, o s ^: time domain (SIMULATED); dotted, +: "
                 "averaged slow flow (rigid only); dashed: quasi-static (V → 0, simulated); open: detached before "
                 "the mean extremum", title_fontsize=6.5)
    return fig


# --- The two rigs (Figs. 1, 2; Eq. 13; Appendix B) ---------------------------------------------


def plot_rig_comparison(table: pd.DataFrame) -> Figure:
    """Pull-off of the base and the force rig against h1, and the force rig's drive F1/(k h1) = |D| against omega_bar.

    Left, for the configured damping: the leading order of the base rig (lines), the SIMULATED virtual pull-off
    of the base rig (o) and of the equal-amplitude force rig, F1 = k h1 |D| (x: on the o's), and at the
    anti-resonance the force rig at F1 = k h1 (triangles; leading order dashed). Right: |1 - omega_bar^2 +
    2 i zeta omega_bar| (Eqs. 22, 65), 0 at the undamped anti-resonance, with the frequencies of the table.
    """
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.0, 5.0), layout="constrained")
    zeta = float(table["zeta"].max())
    damped = table[table["zeta"] == zeta]
    for k, (frequency, rows) in enumerate(damped.groupby("frequency_hz")):
        color, by = f"C{k}", {key: rows[(rows["rig"] == key[0]) & (rows["level"] == key[1])]
                              for key in [(r, lv) for r in ("base", "force_equivalent", "force_spring")
                                          for lv in ("leading", "simulation")]}
        left.plot(by["base", "leading"]["h1_um"], by["base", "leading"]["pulloff_ratio"], "-", color=color, lw=1,
                  label=f"{frequency:.3g} Hz, base rig, leading order")
        left.plot(by["base", "simulation"]["h1_um"], by["base", "simulation"]["pulloff_ratio"], "o", color=color,
                  mfc="none", label=f"{frequency:.3g} Hz, base rig, SIMULATED")
        equivalent = by["force_equivalent", "simulation"]
        left.plot(equivalent["h1_um"], equivalent["pulloff_ratio"], "x", color=color,
                  label=f"{frequency:.3g} Hz, force rig F1 = k h1 |D|, SIMULATED")
        if k == 0:
            spring = by["force_spring", "simulation"]
            left.plot(spring["h1_um"], spring["pulloff_ratio"], "^", color=color,
                      label=f"{frequency:.3g} Hz, force rig F1 = k h1, SIMULATED")
            left.plot(by["force_spring", "leading"]["h1_um"], by["force_spring", "leading"]["pulloff_ratio"], "--",
                      color=color, lw=1, label=f"{frequency:.3g} Hz, force rig F1 = k h1, leading order")
    left.set(xlabel=r"$h_1$ ($\mu$m)", ylabel=r"$P_{\rm pull-off}/P^{\rm JKR}$", yscale="log")
    omega_bar = np.geomspace(0.1, 2.0 * float(table["omega_bar"].max()), 400)
    for z, style in ((zeta, "k-"), (0.0, "k:")):
        right.plot(omega_bar, np.abs(1.0 - omega_bar**2 + 2j * z * omega_bar), style, lw=1, label=rf"$\zeta$ = {z:g}")
    points = table[table["rig"] == "force_equivalent"].drop_duplicates(["zeta", "omega_bar"])
    right.plot(points["omega_bar"], points["drive_ratio"].clip(lower=1e-3), "ko", mfc="none",
               label="the table's points")
    right.set(xscale="log", yscale="log", xlabel=r"$\bar\omega = \omega/\omega_0$",
              ylabel=r"$F_1/(k h_1)$ at equal contact amplitude", ylim=(1e-3, None))
    right.legend(fontsize=7)
    legend_below(fig, [left], ncol=2, fontsize=6.5)
    return fig
