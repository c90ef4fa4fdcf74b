"""Drawings of the validation, fit and benchmark pages: compliant sweep, measured vs predicted, speed vs error.

In the style of :mod:`vibroadhesion.pipeline.figures` (which sets matplotlib's backend and style on import), each
legend below its panel, off the data.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from vibroadhesion.core import levels
from vibroadhesion.pipeline.figures import legend_below, shade_amplitude_regions

__all__ = ["plot_compliant_sweep", "plot_measured_vs_predicted", "plot_speed_vs_error"]

#: Marker of each cost class of the level registry (:mod:`vibroadhesion.core.levels`) in the speed-against-error plot.
COST_MARKERS: dict[levels.Cost, str] = {"algebraic": "o", "quadrature": "s", "simulation": "^"}


# --- Validation: every model level against the simulation ------------------------------------


def plot_compliant_sweep(sweep: pd.DataFrame, curve: pd.DataFrame) -> Figure:
    """A/a_m against omega_bar through the folded resonance.

    The refined model's traced curve and the simulated orbits swept up and down (open markers: unstable orbit,
    |Floquet multiplier| > 1).
    """
    fig, ax = plt.subplots(figsize=(6.4, 4.8), layout="constrained")
    for j, (_, seg) in enumerate(curve.groupby("branch", sort=False)):
        ax.plot(seg["omega_bar"], seg["A_over_am"], "k-", lw=1.0,
                label="refined model, Eqs. (87), (90)" if j == 0 else None)
    sim = sweep[(sweep["model"] == "simulation") & sweep["A_over_am"].notna()]
    for direction, marker, color in (("up", "^", "C0"), ("down", "v", "C3")):
        rows = sim[sim["direction"] == direction]
        stable = rows["stable"].astype(bool)
        ax.plot(rows.loc[stable, "omega_bar"], rows.loc[stable, "A_over_am"], marker, color=color, ms=5, ls="none",
                label=f"simulation, sweep {direction}")
        ax.plot(rows.loc[~stable, "omega_bar"], rows.loc[~stable, "A_over_am"], marker, color=color, mfc="none", ms=5,
                ls="none", label=f"simulation, sweep {direction}, unstable orbit")
    ax.set(xscale="log", yscale="log", xlabel=r"$\bar\omega = \omega/\omega_0$", ylabel=r"$A/a_m$",
           xlim=(sweep["omega_bar"].min(), sweep["omega_bar"].max()))
    shade_amplitude_regions(ax)
    legend_below(fig, [ax], ncol=2, fontsize=7)
    return fig


# --- The fit page -----------------------------------------------------------------------------

def plot_measured_vs_predicted(predictions: pd.DataFrame) -> Figure:
    """Predicted against measured pull-off force (mN), one marker per model level, and the 1:1 line.

    ``predictions`` has columns level, measured_mN, predicted_mN (:func:`vibroadhesion.pipeline.fit_report.
    long_predictions`); each level's prediction is |P_cr| of its own fit (Eq. 71 or the simulated pull-off). With
    a ``range`` column, the rows outside the asymptotic levels' range (not ``inside``) are crossed in red and
    labelled once with why (e.g. ``A/a_m = 0.23 > 0.1``). Without any prediction (no level fitted the rows: one or
    two rows for three parameters) the axes say so instead.
    """
    fig, ax = plt.subplots(figsize=(6.0, 5.4), layout="constrained")
    values = pd.to_numeric(pd.concat([predictions["measured_mN"], predictions["predicted_mN"]]), errors="coerce")
    if not np.isfinite(values).any():
        ax.text(0.5, 0.5, "no model level fitted these rows:\nno prediction to compare with", ha="center",
                va="center", transform=ax.transAxes, color="0.35")
        ax.set(xticks=[], yticks=[], xlabel="measured |P_cr| (mN)", ylabel="predicted |P_cr| (mN)")
        return fig
    span = (0.0, 1.05 * float(values[np.isfinite(values)].max()))
    ax.plot(span, span, "-", color="0.6", lw=1.0, label="1:1 (predicted = measured)")
    for k, (level, rows) in enumerate(predictions.groupby("level", sort=False)):
        ax.plot(rows["measured_mN"], rows["predicted_mN"], "os^Dv<>p"[k % 8], mfc="none", color=f"C{k}", ms=6,
                ls="none", label=str(level))
    outside = predictions[predictions.get("range", pd.Series("inside", index=predictions.index)) != "inside"]
    if not outside.empty:
        ax.plot(outside["measured_mN"], outside["predicted_mN"], "x", color="red", ms=8, ls="none",
                label="outside the asymptotic levels' range")
        for row in outside.drop_duplicates(["measured_mN", "range"]).itertuples():
            ax.annotate(str(row.range).partition(": ")[2], (row.measured_mN, row.predicted_mN), fontsize=6,
                        color="red", xytext=(4, -8), textcoords="offset points")
    ax.set(xlim=span, ylim=span, aspect="equal", xlabel="measured |P_cr| (mN)",
           ylabel="predicted |P_cr| (mN)")
    legend_below(fig, [ax], ncol=2, fontsize=7)
    return fig


# --- The benchmarks page ----------------------------------------------------------------------

def plot_speed_vs_error(table: pd.DataFrame, repeats: int) -> Figure:
    """Time per solved point against the largest relative error vs the simulation, one marker per model level.

    ``table``: the rows of results/benchmarks/speed_vs_error.csv (benchmarks/speed_vs_error.py, each point solved
    ``repeats`` times): the marker at the median run, a bar from the fastest; the simulation, the reference, as a
    band of its times. Levels by their registry label, markers by the registry's cost class.
    """
    fig, ax = plt.subplots(figsize=(6.4, 4.8), layout="constrained")
    for k, r in table.iterrows():
        entry = levels.level(str(r["model"]))
        if r["model"] == "simulation":  # the reference: no error of its own to plot, only its time
            ax.axvspan(r["seconds_per_point_min"], r["seconds_per_point_median"], color=f"C{k}", alpha=0.3)
            ax.axvline(r["seconds_per_point_median"], color=f"C{k}", ls="--", lw=1.0,
                       label=f"{entry.label} [{entry.cost}]: the reference (its time)")
            continue
        ax.plot([r["seconds_per_point_min"], r["seconds_per_point_median"]],
                [r["max_relative_error_vs_simulation"]] * 2, "-", color=f"C{k}", lw=2.0)
        ax.plot(r["seconds_per_point_median"], r["max_relative_error_vs_simulation"], COST_MARKERS[entry.cost],
                color=f"C{k}", ms=8, label=f"{entry.label} [{entry.cost}]")
    errors = table.loc[table["model"] != "simulation", "max_relative_error_vs_simulation"]
    compared = bool((errors > 0).any())  # NaN where the simulation has no steady state at any test condition
    # a log axis only where the errors span a decade: over less it would carry two labelled ticks
    decades = compared and float(errors[errors > 0].max() / errors[errors > 0].min()) > 10.0
    if not compared:
        ax.text(0.5, 0.5, "no level compared: the simulation found no steady state\nat the test conditions",
                transform=ax.transAxes, ha="center", va="center", color="0.35")
    if compared and not decades:
        ax.set_ylim(0.0, 1.1 * float(errors.max()))
    ax.set(xscale="log", yscale="log" if decades else "linear",
           xlabel=f"time per solved point (s): marker median, bar from the fastest of {repeats}",
           ylabel="largest relative error vs simulation", title="Speed against error at the test conditions")
    legend_below(fig, [ax], ncol=2, fontsize=7.5)
    return fig
