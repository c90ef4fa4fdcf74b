"""Drawings of the figures (plots).

Each ``plot_figN`` draws the table that :mod:`vibroadhesion.experiments.figure_tables` computed (and nothing it
would have to recompute with a solver), so restyling a plot never reruns a solve. :func:`save_figure` writes PDF and
PNG without time stamps. With :mod:`vibroadhesion.pipeline.error_maps` (the validation's error maps, in this
style), :mod:`vibroadhesion.pipeline.dynamics_figures` (the withdrawal speed and the two rigs) and
:mod:`vibroadhesion.pipeline.page_figures` (the compliant sweep, measured against predicted, speed against error),
the only modules of the package that import matplotlib.
"""

from __future__ import annotations

import io
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from matplotlib.axes import Axes  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.ticker import LogFormatterSciNotation  # noqa: E402

from vibroadhesion.core.integrals import j_integrals_large_Abar  # noqa: E402
from vibroadhesion.experiments.figure_tables import APPLICABILITY_LIMIT  # noqa: E402
from vibroadhesion.pipeline.atomic import atomic_path  # noqa: E402
from vibroadhesion.pipeline.data import SPEED_COLUMN  # noqa: E402
from vibroadhesion.pipeline.leads import coinciding_frequencies  # noqa: E402

if TYPE_CHECKING:
    from matplotlib.typing import RcKeyType
    from numpy.typing import ArrayLike

STYLE: dict[RcKeyType, Any] = {
    "font.size": 9,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "legend.fontsize": 7.5,
    "figure.dpi": 100,
    "savefig.dpi": 200,
    "path.simplify": False,
    "svg.hashsalt": "vibroadhesion",
}
plt.rcParams.update(STYLE)

_PDF_METADATA = {"CreationDate": None, "Creator": None, "Producer": None}
_PNG_METADATA = {"Software": None}


#: ω̌ = ωR/v0 (Eq. 105) as text: omega with a combining caron. Matplotlib's mathtext sets the accent of
#: ``\check{\omega}`` beside the letter, not on it, in every math font it ships.
OMEGA_CHECK = "\u03c9\u030c"
OMEGA_CHECK_AXIS = f"{OMEGA_CHECK} = " + r"$\omega R / v_0$"
OMEGA_CHECK_LABEL_INF_EXACT = f"exact averaging ({OMEGA_CHECK} " + r"$\to \infty$), $a_m = a_{cr}$"

def name_parameter_set(fig: Figure, label: str) -> Figure:
    """Name the Gent–Schultz parameter set that every curve of ``fig`` uses, above its panels."""
    fig.suptitle(label, fontsize=7.5)
    return fig


#: Opacity of a model curve where the asymptotic model does not apply (A/a_m > APPLICABILITY_LIMIT, Sec. 3.5.3).
OUTSIDE_ALPHA = 0.3


def plot_applicable(ax: Axes, x: ArrayLike, y: ArrayLike, A_over_am: ArrayLike, fmt: str, **style: Any) -> None:
    """Plot a refined-model curve, faded where A/a_m > APPLICABILITY_LIMIT (outside the asymptotic model).

    The faded part starts at the last applicable point, so the curve stays connected; ``style`` applies to both
    parts and its ``label`` to the applicable one (or to the faded one when no point applies).
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    outside = np.asarray(A_over_am, dtype=float) > APPLICABILITY_LIMIT
    joined = outside | np.r_[outside[1:], False] | np.r_[False, outside[:-1]]
    label = style.pop("label", None)
    ax.plot(x, np.where(outside, np.nan, y), fmt, label=None if outside.all() else label, **style)
    if outside.any():
        ax.plot(x, np.where(joined, y, np.nan), fmt, alpha=OUTSIDE_ALPHA,
                label=label if outside.all() else None, **style)


def _legend_outside_applicability(ax: Axes, A_over_am: pd.Series) -> None:
    """A legend entry for the faded curves of :func:`plot_applicable`, when a curve has such a part."""
    if (A_over_am > APPLICABILITY_LIMIT).any():
        ax.plot([], [], "k-", alpha=OUTSIDE_ALPHA, label=f"faded: $A/a_m > {APPLICABILITY_LIMIT:g}$ at detachment, "
                "outside the asymptotic model (Sec. 3.5.3)")


class PlainLogFormatter(LogFormatterSciNotation):
    """Tick labels of a log axis as plain numbers (``30``, ``0.001``) where the axis lies within 1e-4 to 1e5.

    An axis reaching beyond reads in powers of ten throughout (``10⁹``, not ``10000`` beside ``10⁵``). Which ticks are
    labelled is matplotlib's choice for log axes (minor ticks only where the axis spans few decades).
    """

    def __call__(self, x: float, pos: int | None = None) -> str:
        """The label of the tick at ``x``: empty where matplotlib leaves it out."""
        label = str(super().__call__(x, pos))
        low, high = sorted(abs(v) for v in self.axis.get_view_interval()) if self.axis else (x, x)
        if label and 1e-4 <= low and high < 1e5:
            return self.fix_minus(f"{x:g}")
        return label


def plain_log_labels(fig: Figure) -> Figure:
    """Label every log axis of ``fig`` (panels and insets) with :class:`PlainLogFormatter`."""
    for ax in [*fig.axes, *(child for panel in fig.axes for child in panel.child_axes)]:
        for axis in (ax.xaxis, ax.yaxis):
            if axis.get_scale() == "log":
                axis.set_major_formatter(PlainLogFormatter())
                axis.set_minor_formatter(PlainLogFormatter(labelOnlyBase=False))
    return fig


def save_figure(fig: Figure, pdf: str | Path, png: str | Path) -> None:
    """Save ``fig`` as PNG and PDF without time stamps (log axes in plain numbers: :func:`plain_log_labels`), close it.

    The layout engine (constrained layout) places the axes for the PNG, the page's figure; the PDF keeps that
    layout (engine off for its draw) instead of solving it again: the two files show the same placement, and the
    second solve was a third of a figure's save time (Fig. 6: 80 tick labels per log axis measured each time).
    """
    plain_log_labels(fig)
    with atomic_path(png) as tmp:
        fig.savefig(tmp, format="png", metadata=_PNG_METADATA, bbox_inches="tight")
    fig.set_layout_engine("none")
    with atomic_path(pdf) as tmp:
        fig.savefig(tmp, format="pdf", metadata=_PDF_METADATA, bbox_inches="tight")
    plt.close(fig)


# --- Fig. 3: the J-integrals -------------------------------------------------------------


def plot_fig3(table: pd.DataFrame, n: float, panel_exponents: Sequence[float]) -> Figure:
    """(a) J0, -Jc1, J1 for the figure's n with their large-Abar asymptotes; (b) J0, -Jc1 for several n."""
    fig, (ax_a, ax_b) = plt.subplots(1, 2, figsize=(9.0, 3.6), constrained_layout=True)
    rows = table[np.isclose(table["n"], n)]
    Abar = rows["Abar"].to_numpy()
    asym = j_integrals_large_Abar(Abar, n)
    for (label, column, sign), a, color, width in zip(
        [(r"$\mathcal{J}_0$", "J0", 1), (r"$-\mathcal{J}_{c1}$", "Jc1", -1), (r"$\mathcal{J}_1$", "J1", 1)],
        asym,
        ["C0", "C1", "C2"],
        [3.0, 1.8, 1.0],  # J0 and J1 coincide for Abar < 1 (both -> 1): the wider line stays visible beneath
        strict=True,
    ):
        ax_a.loglog(Abar, sign * rows[column], color=color, lw=width, label=label)
        ax_a.loglog(Abar, sign * a, "--", color=color, lw=0.9, label=f"{label}, large-$\\bar A$ asymptote")
    ax_a.set_ylim(1e-4, None)
    ax_a.set(xlabel=r"$\bar A$", ylabel="J-integral (Eqs. 28, 29, 36)", title=f"(a) n = {n:.4g}")
    ax_a.legend(ncol=2)
    for k, exponent in enumerate(panel_exponents):
        rows = table[np.isclose(table["n"], exponent)]
        ax_b.loglog(rows["Abar"], rows["J0"], color=f"C{k}", label=rf"$\mathcal{{J}}_0$, n = {exponent:g}")
        ax_b.loglog(rows["Abar"], -rows["Jc1"], ":", color=f"C{k}", label=rf"$-\mathcal{{J}}_{{c1}}$, n = {exponent:g}")
    ax_b.set_ylim(1e-4, None)
    ax_b.set(xlabel=r"$\bar A$", ylabel=r"$\mathcal{J}_0$ and $-\mathcal{J}_{c1}$",
             title="(b) effect of the exponent n")
    ax_b.legend(ncol=2)
    return fig


# --- Fig. 4: pull-off amplification -------------------------------------------------------


def _simulated_rigid_pulloff(virtual: pd.DataFrame) -> pd.DataFrame:
    """The rows of virtual_pulloff.csv that Figs. 4 and 7 draw.

    The simulated pull-off of the RIGID fixation (the figures' model); the compliant rows are a different experiment
    (report page only).
    """
    keep = (virtual["fixation"] == "rigid") & (virtual["model"] == "simulation") & (virtual["status"] == "pulloff")
    return virtual[keep]


def plot_fig4(table: pd.DataFrame, measurements: pd.DataFrame, jkr_pulloff_mN: float,
              virtual: pd.DataFrame | None = None) -> Figure:
    """Fig. 4: P_cr/P_JKR against h1, every curve and the measured rows at one parameter set.

    Leading-order, refined and exact-averaging curves, the simulated pull-off of the rigidly fixed virtual
    experiment (its own, labelled series: not measurements), and the measured rows scaled by the same
    ``jkr_pulloff_mN``: coloured by frequency as the refined curve of that frequency, marked by source.
    """
    fig, ax = plt.subplots(figsize=(7.8, 5.6), constrained_layout=True)
    lead = table[table["model"] == "leading"]
    ax.plot(lead["h1_um"], lead["pulloff_ratio"], "k-", lw=1.6, label="leading order, Eqs. (71)–(72)")
    refined = table[table["model"] == "refined"]
    hidden = coinciding_frequencies(table)
    for k, (f, rows) in enumerate(refined.groupby("frequency_hz", sort=True)):
        plot_applicable(ax, rows["h1_um"], rows["pulloff_ratio"], rows["A_over_am"], "--", color=f"C{k}", lw=1.0,
                        label=f"refined, Eq. (106), {f:g} Hz" + (" (coincides with the leading order: hidden under "
                                                                   "it)" if f in hidden else ""))
    exact = table[table["model"] == "exact_averaging"]
    ax.plot(exact["h1_um"], exact["pulloff_ratio"], "k:", lw=1.4,
            label=OMEGA_CHECK_LABEL_INF_EXACT)
    if virtual is not None:
        sim = _simulated_rigid_pulloff(virtual)
        for k, (f, rows) in enumerate(sim.groupby("frequency_hz", sort=True)):
            ax.plot(rows["h1_um"], rows["pulloff_ratio"], "x+*"[k % 3], color=f"C{k}", ms=7,
                    label=f"SIMULATED pull-off, rigid fixation, {f:g} Hz")
        _note_missing_simulation(ax, virtual, len(sim))
    _plot_measured(ax, measurements, jkr_pulloff_mN, "h1_um", "frequency_hz", sorted(refined["frequency_hz"].unique()))
    if measurements.empty:
        ax.text(0.03, 0.97, "no measured rows in data/pulloff.csv\n(published fit shown)", transform=ax.transAxes,
                va="top", fontsize=7.5, color="0.35")
    ax.set(xlabel=r"base amplitude $h_1$ (µm)", ylabel=r"$P_{cr}/P^{JKR}_{cr}$", xlim=(0, None), ylim=(0, None))
    _legend_outside_applicability(ax, refined["A_over_am"])
    legend_below(fig, [ax], ncol=2, fontsize=7)
    return fig


def _note_missing_simulation(ax: Axes, virtual: pd.DataFrame, drawn: int) -> None:
    """Say in the legend of ``ax`` (beside the data) how many rigid test conditions have no simulated pull-off.

    With why: the statuses of their families.
    """
    rigid = virtual[(virtual["fixation"] == "rigid") & (virtual["model"] == "simulation")]
    if drawn == len(rigid):
        return
    missing = rigid[rigid["status"] != "pulloff"]["status"].value_counts(sort=False)
    why = ", ".join(f"{status} at {count}" for status, count in missing.items())
    ax.plot([], [], " ", label=f"SIMULATED pull-off: none at {len(rigid) - drawn} of {len(rigid)} test conditions\n"
                               f"({why})")


def _plot_measured(ax: Axes, measurements: pd.DataFrame, jkr_pulloff_mN: float, x: str, by: str,
                   curves: Sequence[float]) -> None:
    """Measured rows over P_JKR against column ``x``: one marker per source, labelled by it.

    Coloured as the curve of their ``by`` value among ``curves`` (Fig. 4: against h1, by frequency; Fig. 7: against
    omega_check, by h1); grey for a value without a curve or for a static test (h1 = 0). Rows measured at a
    withdrawal speed (``withdrawal_speed_um_s`` > 0) are filled and labelled so: the quasi-static curves are not their
    model.
    """
    markers = "osD^v<>p"
    moving = measurements[SPEED_COLUMN] > 0 if SPEED_COLUMN in measurements else False
    for k, (source, by_source) in enumerate(measurements.assign(moving=moving).groupby("source", sort=True)):
        for (value, at_speed), rows in by_source.groupby([by, "moving"], sort=True):
            known = [j for j, curve in enumerate(curves) if np.isclose(curve, value)]
            where = _measured_where(by, value) + (", withdrawn at V > 0" if at_speed else "")
            color = f"C{known[0]}" if known else "0.4"
            ax.plot(rows[x], rows["pulloff_mN"] / jkr_pulloff_mN, markers[k % len(markers)],
                    mfc=color if at_speed else "none", color=color, label=f"{source}, {where}")


def _measured_where(by: str, value: float) -> str:
    """The legend's name of a group of measured rows: its amplitude (``by`` = ``h1_um``) or its frequency."""
    if by == "h1_um":
        return rf"$h_1$ = {value:g} µm"
    return "static, $h_1$ = 0" if value == 0 else f"{value:g} Hz"


# --- Figs. 6–8: rigidly fixed indenter, refined model ----------------------------------------

def _by_amplitude(table: pd.DataFrame) -> Any:
    return table.groupby("h1_um", sort=True)


def _mark_frequencies(ax: Axes, experiment_omega_check: Mapping[float, float]) -> None:
    """A dotted vertical line at the omega_check of each test frequency of the rig, labelled once with all of them."""
    label = "test frequencies " + "/".join(f"{f:g}" for f in sorted(experiment_omega_check)) + " Hz"
    for k, (_f, w) in enumerate(sorted(experiment_omega_check.items())):
        ax.axvline(w, color="0.5", lw=0.7, ls=(0, (1, 2)), label=label if k == 0 else None)


def shade_amplitude_regions(ax: Axes) -> None:
    """Shade A > a_m (geometrically impossible) and A <= 0.1 a_m (the model applies) on an A/a_m axis.

    The axis keeps the data's lower limit and reaches at least 2, so that the impossible region shows.
    """
    lo, hi = ax.get_ylim()
    ax.axhspan(1.0, max(hi, 2.0), color="C3", alpha=0.15, label=r"$A > a_m$: impossible")
    ax.axhspan(lo, APPLICABILITY_LIMIT, color="C2", alpha=0.12, label=r"$A \leq 0.1\,a_m$: model applies")
    ax.set_ylim(lo, max(hi, 2.0))


def legend_below(fig: Figure, axes: Sequence[Axes], **style: Any) -> None:
    """One legend for ``axes`` below the panels (each label once, from the first panel that has it): off the data."""
    entries: dict[str, Any] = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            entries.setdefault(label, handle)
    fig.legend(list(entries.values()), list(entries), loc="outside lower center", **style)


def plot_fig6(table: pd.DataFrame, experiment_omega_check: Mapping[float, float],
              validation: pd.DataFrame | None = None) -> Figure:
    """(a) Abar, (b) abar_m, (c) w_eff/w0, (d) A/a_m against omega_check, regions of (d) shaded.

    With the validation grid: the simulated steady states of the full model (filled markers) and the
    exact high-frequency averaging (dotted) over the paper's refined model (solid).
    """
    fig, axes = plt.subplots(2, 2, figsize=(9.0, 6.4), constrained_layout=True, sharex=True)
    panels = [("Abar", r"$\bar A$", "log"), ("abar_m", r"$\bar a_m = a_m/a_o$", "linear"),
              ("w_eff_ratio", r"$w_{eff}/w_0$", "linear"), ("A_over_am", r"$A/a_m$", "log")]
    for ax, (column, label, yscale), letter in zip(axes.flat, panels, "abcd", strict=True):
        for k, (h1, rows) in enumerate(_by_amplitude(table)):
            ax.plot(rows["omega_check"], rows[column], color=f"C{k}", label=rf"$h_1$ = {h1:g} µm")
            if validation is not None:
                here = validation[np.isclose(validation["h1_um"], h1) & (validation["status"] == "ok")]
                sim, exact = here[here["model"] == "simulation"], here[here["model"] == "exact_averaging"]
                ax.plot(exact["omega_check"], exact[column], ":", color=f"C{k}", lw=1.2,
                        label="exact averaging" if k == 0 else None)
                ax.plot(sim["omega_check"], sim[column], "o", color=f"C{k}", ms=3.5,
                        label="simulation of the full model" if k == 0 else None)
        ax.set(xscale="log", yscale=yscale, ylabel=label, title=f"({letter})")
        _mark_frequencies(ax, experiment_omega_check)
    ax_d = axes.flat[3]
    shade_amplitude_regions(ax_d)
    for ax in axes[1]:
        ax.set_xlabel(OMEGA_CHECK_AXIS)
    legend_below(fig, [axes.flat[0], ax_d], ncol=4)
    return fig


def plot_fig7(table: pd.DataFrame, leading: pd.DataFrame, experiment_omega_check: Mapping[float, float],
              exact: pd.DataFrame | None = None, virtual: pd.DataFrame | None = None,
              measurements: pd.DataFrame | None = None, jkr_pulloff_mN: float = 1.0) -> Figure:
    """(a) Abar_cr and (b) P_cr/P_JKR against omega_check.

    Dashed: the leading-order values (Eq. 72); dotted: the exact high-frequency averaging with the same criterion
    a_m = a_cr (Fig. 4's rows). In (b) the measured rows (with their ``omega_check``, Eq. 105) over
    ``jkr_pulloff_mN``, as in Fig. 4 (:func:`_plot_measured`), coloured by amplitude; a static test (no frequency)
    has no place on this axis: it is in Fig. 4 only.
    """
    fig, (ax_a, ax_b) = plt.subplots(1, 2, figsize=(9.0, 5.0), constrained_layout=True)
    for k, (h1, rows) in enumerate(_by_amplitude(table)):
        lead = leading[np.isclose(leading["h1_um"], h1)].iloc[0]
        for ax, column in ((ax_a, "Abar_cr"), (ax_b, "pulloff_ratio")):
            plot_applicable(ax, rows["omega_check"], rows[column], rows["A_over_am"], "-", color=f"C{k}",
                            label=rf"$h_1$ = {h1:g} µm")
            ax.axhline(lead[column], color=f"C{k}", ls="--", lw=0.8)
        if exact is not None:
            row = exact[np.isclose(exact["h1_um"], h1)].iloc[0]
            for ax, column in ((ax_a, "Abar_cr"), (ax_b, "pulloff_ratio")):
                ax.axhline(row[column], color=f"C{k}", ls=":", lw=1.0)
        if virtual is not None:
            sim = _simulated_rigid_pulloff(virtual)
            sim = sim[np.isclose(sim["h1_um"], h1)]
            sim_omega_check = [experiment_omega_check[f] for f in sim["frequency_hz"]]
            ax_b.plot(sim_omega_check, sim["pulloff_ratio"], "o", color=f"C{k}",
                      ms=4, label="simulated pull-off (virtual experiment)" if k == 0 else None)
    if measurements is not None:
        _plot_measured(ax_b, measurements[measurements["frequency_hz"] > 0], jkr_pulloff_mN, "omega_check", "h1_um",
                       sorted(table["h1_um"].unique()))
    for ax, label, letter in ((ax_a, r"$\bar A_{cr}$", "a"), (ax_b, r"$P_{cr}/P^{JKR}_{cr}$", "b")):
        _mark_frequencies(ax, experiment_omega_check)
        ax.set(xscale="log", xlabel=OMEGA_CHECK_AXIS, ylabel=label, title=f"({letter})")
    ax_a.set_yscale("log")
    ax_b.plot([], [], "k--", lw=0.8, label=f"Eq. (72) ({OMEGA_CHECK} " + r"$\to \infty$)")
    ax_b.plot([], [], "k:", lw=1.0, label="exact averaging, $a_m = a_{cr}$")
    _legend_outside_applicability(ax_b, table["A_over_am"])
    legend_below(fig, [ax_b, ax_a], ncol=3, fontsize=7)
    return fig


def plot_fig8(table: pd.DataFrame, experiment_omega_check: Mapping[float, float]) -> Figure:
    """Storage and loss contact stiffness relative to 2E*a_m, and the phase, against omega_check."""
    fig, axes = plt.subplots(1, 3, figsize=(11.0, 3.5), constrained_layout=True)
    panels = [("S_storage_rel", r"$\tilde S'/(2E^*a_m)$"), ("S_loss_rel", r"$\tilde S''/(2E^*a_m)$"),
              ("phase_rad", "phase (rad)")]
    for ax, (column, label), letter in zip(axes, panels, "abc", strict=True):
        for k, (h1, rows) in enumerate(_by_amplitude(table)):
            ax.plot(rows["omega_check"], rows[column], color=f"C{k}", label=rf"$h_1$ = {h1:g} µm")
        _mark_frequencies(ax, experiment_omega_check)
        ax.set(xscale="log", xlabel=OMEGA_CHECK_AXIS, ylabel=label, title=f"({letter})")
    axes[0].axhline(1.0, color="k", lw=0.6, ls="--")
    axes[0].axhline(1.0 / 3.0, color="k", lw=0.6, ls=":")
    legend_below(fig, [axes[0]], ncol=6)
    return fig


# --- Fig. 5: compliant fixation, passage through resonance ---------------------------------

def plot_fig5(curves: pd.DataFrame, markers: pd.DataFrame, highlight_hz: float) -> Figure:
    """A/a_m against omega_bar, one panel per kappa, one colour per zeta; folds and test frequencies marked."""
    kappas = sorted(curves["kappa"].unique())
    fig, axes = plt.subplots(1, len(kappas), figsize=(4.6 * len(kappas), 4.6), layout="constrained", squeeze=False)
    for ax, kappa in zip(axes[0], kappas, strict=True):
        _plot_fig5_curves(ax, curves[curves["kappa"] == kappa])
        here = markers[markers["kappa"] == kappa]
        folds = here[here["kind"] == "fold"]
        ax.plot(folds["omega_bar"], folds["A_over_am"], "kx", ms=6, label="fold" if len(folds) else None)
        tests = here[here["kind"] == "experiment"]
        ax.plot(tests["omega_bar"], tests["A_over_am"], "o", mfc="none", color="0.3", ms=5, label="200/300/400 Hz")
        ended = here[~here["kind"].isin(["fold", "experiment"])]  # pieces that cannot be continued
        ax.plot(ended["omega_bar"], ended["A_over_am"].clip(upper=10.0), "r^", ms=6,
                label="branch ended (" + ", ".join(sorted(ended["kind"].unique())) + ")" if len(ended) else None)
        top = tests[tests["frequency_hz"] == highlight_hz]
        ax.plot(top["omega_bar"], top["A_over_am"], "o", color="k", ms=7, label=f"{highlight_hz:g} Hz (paper's dot)")
        ax.axvline(1.0, color="0.6", lw=0.6, ls=":")
        ax.set(xscale="log", yscale="log", xlabel=r"$\bar\omega = \omega/\omega_0$", ylabel=r"$A/a_m$",
               title=rf"$\kappa$ = {kappa:g}")
        ax.set_ylim(1e-10, 10.0)
        shade_amplitude_regions(ax)
        if len(folds):
            fold_inset(ax, curves[curves["kappa"] == kappa], folds)
    legend_below(fig, axes[0], ncol=4, fontsize=8)  # a branch ended in one panel only is listed too
    return fig


def _plot_fig5_curves(ax: Axes, curves: pd.DataFrame) -> None:
    """A/a_m against omega_bar (Eqs. 87, 90), one colour per zeta; the unstable middle branch dashed."""
    for k, (zeta, rows) in enumerate(curves.groupby("zeta", sort=True)):
        for j, (branch, seg) in enumerate(rows[rows["A_over_am"] > 0].groupby("branch", sort=False)):
            middle = branch.endswith("-1")  # between two folds: the unstable middle branch of a saddle-node pair
            ax.plot(seg["omega_bar"], seg["A_over_am"], color=f"C{k}", ls="--" if middle else "-",
                    label=rf"$\zeta$ = {zeta:g}" if j == 0 else None)


#: Where the zoom on the folds of Fig. 5 sits in its panel (axes fraction: left, bottom, width, height): the lower
#: right, below the curves' high-frequency tail (A/a_m < 1e-5 there, the curves lie above 1e-4).
FOLD_INSET = (0.55, 0.05, 0.42, 0.36)


def fold_inset(ax: Axes, curves: pd.DataFrame, folds: pd.DataFrame) -> Axes:
    """An inset of ``ax`` zooming on the folds (saddle-node points of Eqs. 87, 90) on a linear omega_bar axis.

    At decade scale the two folds of a panel are a few per cent apart in omega_bar and the S between them is a
    vertical stroke; the inset spans the folds plus their distance on each side (at least 2 % of omega_bar) and the
    A/a_m the curves take there, so the three branches and the folds separate.
    """
    lo, hi = float(folds["omega_bar"].min()), float(folds["omega_bar"].max())
    pad = max(hi - lo, 0.02 * hi)
    near = curves[curves["omega_bar"].between(lo - pad, hi + pad) & (curves["A_over_am"] > 0)]["A_over_am"]
    inset = ax.inset_axes(FOLD_INSET)
    _plot_fig5_curves(inset, curves)
    inset.plot(folds["omega_bar"], folds["A_over_am"], "kx", ms=5)
    inset.set(xlim=(lo - pad, hi + pad), yscale="log", ylim=(near.min() / 1.5, near.max() * 1.5))
    inset.tick_params(labelsize=6)
    inset.set_title("zoom on the folds (linear " + r"$\bar\omega$)", fontsize=6.5, pad=2)
    ax.indicate_inset_zoom(inset, edgecolor="0.3")
    return inset


def figure_png(fig: Figure) -> bytes:
    """``fig`` as PNG bytes without a time stamp (for a page that draws it inline), then close it."""
    buffer = io.BytesIO()
    plain_log_labels(fig).savefig(buffer, format="png", metadata=_PNG_METADATA, bbox_inches="tight")
    plt.close(fig)
    return buffer.getvalue()
