"""Numbers behind each figure (tables) and their drawings (plots), kept apart.

A ``figN_table`` function computes the numbers of Fig. N from model parameters and returns
the DataFrame that the pipeline writes as ``results/figN/figN.csv``; a ``plot_figN`` function
draws that table (and nothing it would have to recompute with a solver), so restyling a plot
never reruns a solve.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from vibroadhesion.integrals import j_integrals, j_integrals_large_abar
from vibroadhesion.pulloff import GentSchultzParameters, Model, predict_pulloff

FIG3_COLUMNS = ["n", "Abar", "J0", "Jc1", "J1"]
FIG4_COLUMNS = ["model", "frequency_hz", "h1_um", "Abar_cr", "J0", "ratio", "pulloff_mN"]


# --- Fig. 3: the J-integrals -------------------------------------------------------------


def fig3_table(exponents: Sequence[float], abar: np.ndarray) -> pd.DataFrame:
    """J0, Jc1, J1 (Eqs. 28, 29, 36 for the Gent–Schultz law, Eq. 77) on ``abar`` for each n."""
    frames = []
    for n in sorted(set(float(n) for n in exponents)):
        j0, jc1, j1 = j_integrals(abar, n)
        frames.append(pd.DataFrame({"n": n, "Abar": abar, "J0": j0, "Jc1": jc1, "J1": j1}))
    return pd.concat(frames, ignore_index=True)[FIG3_COLUMNS]


def plot_fig3(table: pd.DataFrame, n_fitted: float, panel_exponents: Sequence[float]) -> plt.Figure:
    """(a) J0, -Jc1, J1 for the fitted n with their large-Abar asymptotes; (b) J0, -Jc1 for several n."""
    fig, (ax_a, ax_b) = plt.subplots(1, 2, figsize=(9.0, 3.6), constrained_layout=True)
    rows = table[np.isclose(table["n"], n_fitted)]
    abar = rows["Abar"].to_numpy()
    asym = j_integrals_large_abar(abar, n_fitted)
    for (label, column, sign), a, color in zip(
        [(r"$\mathcal{J}_0$", "J0", 1), (r"$-\mathcal{J}_{c1}$", "Jc1", -1), (r"$\mathcal{J}_1$", "J1", 1)],
        asym,
        ["C0", "C1", "C2"],
    ):
        ax_a.loglog(abar, sign * rows[column], color=color, label=label)
        ax_a.loglog(abar, sign * a, "--", color=color, lw=0.9, label=f"{label}, large-$\\bar A$ asymptote")
    ax_a.set_ylim(1e-4, None)
    ax_a.set(xlabel=r"$\bar A$", title=f"(a) fitted n = {n_fitted:.4g}")
    ax_a.legend(ncol=2)
    for k, n in enumerate(panel_exponents):
        rows = table[np.isclose(table["n"], n)]
        ax_b.loglog(rows["Abar"], rows["J0"], color=f"C{k}", label=rf"$\mathcal{{J}}_0$, n = {n:g}")
        ax_b.loglog(rows["Abar"], -rows["Jc1"], ":", color=f"C{k}", label=rf"$-\mathcal{{J}}_{{c1}}$, n = {n:g}")
    ax_b.set_ylim(1e-4, None)
    ax_b.set(xlabel=r"$\bar A$", title="(b) effect of the exponent n")
    ax_b.legend(ncol=2)
    return fig


# --- Fig. 4: pull-off amplification -------------------------------------------------------


def fig4_table(
    params: Mapping[Model, GentSchultzParameters],
    frequencies_hz: Sequence[float],
    h1_um: np.ndarray,
    *,
    radius: float,
    reduced_modulus: float,
) -> pd.DataFrame:
    """Leading-order curve (Eqs. 71–72, no frequency) and refined curves (Eq. 106) per frequency."""
    geometry = {"radius": radius, "reduced_modulus": reduced_modulus}
    frames = []
    lead = predict_pulloff("leading", params["leading"], np.nan, h1_um, **geometry)
    frames.append(_fig4_frame("leading", np.nan, h1_um, lead))
    for f in frequencies_hz:
        frames.append(_fig4_frame("refined", f, h1_um, predict_pulloff("refined", params["refined"], f, h1_um, **geometry)))
    return pd.concat(frames, ignore_index=True)[FIG4_COLUMNS]


def _fig4_frame(model: str, frequency: float, h1_um: np.ndarray, pred) -> pd.DataFrame:
    return pd.DataFrame(
        {"model": model, "frequency_hz": frequency, "h1_um": h1_um, "Abar_cr": pred.abar_cr,
         "J0": pred.j0, "ratio": pred.ratio, "pulloff_mN": pred.pulloff_mN}
    )


def plot_fig4(table: pd.DataFrame, measurements: pd.DataFrame, jkr_pulloff_mN: float) -> plt.Figure:
    """P_cr/P_JKR against h1: leading-order and refined curves, and measured rows by source."""
    fig, ax = plt.subplots(figsize=(5.4, 3.9), constrained_layout=True)
    lead = table[table["model"] == "leading"]
    ax.plot(lead["h1_um"], lead["ratio"], "k-", lw=1.6, label="leading order, Eqs. (71)–(72)")
    refined = table[table["model"] == "refined"]
    for k, (f, rows) in enumerate(refined.groupby("frequency_hz", sort=True)):
        ax.plot(rows["h1_um"], rows["ratio"], "--", color=f"C{k}", lw=1.0, label=f"refined, Eq. (106), {f:g} Hz")
    markers = "osD^v<>p"
    for k, (source, rows) in enumerate(measurements.groupby("source", sort=True)):
        ax.plot(rows["h1_um"], rows["pulloff_mN"] / jkr_pulloff_mN, markers[k % len(markers)], mfc="none",
                color=f"C{k + 3}", label=str(source))
    if measurements.empty:
        ax.text(0.03, 0.97, "no measured rows in data/pulloff.csv\n(published fit shown)", transform=ax.transAxes,
                va="top", fontsize=7.5, color="0.35")
    ax.set(xlabel=r"base amplitude $h_1$ (µm)", ylabel=r"$P_{cr}/P^{JKR}_{cr}$", xlim=(0, None), ylim=(0, None))
    ax.legend(loc="lower right")
    return fig
