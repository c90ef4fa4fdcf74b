"""The validation's error maps (results/validation/rigid_error_maps.png): every model level against the simulation.

Drawn with the style of :mod:`vibroadhesion.pipeline.figures`; the labels of the cells are fitted to the cells at the
size the figure is saved, so that none spills over its neighbours.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

from vibroadhesion.pipeline.figures import OMEGA_CHECK_AXIS  # also sets the backend (Agg) and the style


def plot_validation_maps(
    grid: pd.DataFrame, errors: pd.DataFrame, experiment_omega_check: Mapping[float, float]
) -> Figure:
    """One error map per model level, two to a row.

    The largest relative error over Abar, abar_m, w_eff/w0, A/a_m and P_m/|P_JKR| against the simulation, per (h1,
    omega_check), as colour and as the cell's label in per cent (:func:`cell_label`, fitted to the cell by
    :func:`fit_labels`); cells outside the paper's applicability rule (refined A/a_m > 0.1) hatched, cells where the
    simulation loses contact left blank.
    """
    worst = errors.groupby(["model", "h1_um", "omega_check"], sort=True).agg(
        error=("relative_error", "max"), applicable=("applicable", "first")).reset_index()
    models = [m for m in dict.fromkeys(grid["model"]) if m != "simulation"]
    amplitudes = sorted(grid["h1_um"].unique())
    omegas = sorted(grid["omega_check"].unique())
    columns = min(2, len(models))
    rows_of_panels = -(-len(models) // columns)
    fig, axes = plt.subplots(rows_of_panels, columns, figsize=(4.6 * columns, 3.1 * rows_of_panels + 0.6),
                             layout="constrained", sharex=True, sharey=True, squeeze=False)
    labels: dict[Axes, list[Any]] = {}
    for ax, model in zip(axes.flat, models, strict=False):
        rows = worst[worst["model"] == model]
        cells = np.full((len(amplitudes), len(omegas)), np.nan)
        for r in rows.itertuples():
            cells[amplitudes.index(r.h1_um), omegas.index(r.omega_check)] = r.error
        image = ax.imshow(np.log10(cells), origin="lower", aspect="auto", cmap="viridis", vmin=-6, vmax=0)
        labels[ax] = []
        for r in rows.itertuples():
            i, j = amplitudes.index(r.h1_um), omegas.index(r.omega_check)
            labels[ax].append(ax.text(j, i, cell_label(r.error), ha="center", va="center", fontsize=7,
                                      color="w" if r.error < 1e-2 else "k"))
            if not r.applicable:
                ax.add_patch(Rectangle((j - 0.5, i - 0.5), 1, 1, fill=False, hatch="///", lw=0, color="C3"))
        ax.set_xticks(range(len(omegas)), [f"{w:.2g}" for w in omegas], rotation=90, fontsize=7)
        ax.set_yticks(range(len(amplitudes)), [f"{h:g}" for h in amplitudes])
        ax.set(title=model)
        ax.grid(False)  # the style's grid would cross the cells
    for ax in axes.flat[len(models):]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel(OMEGA_CHECK_AXIS)
    for ax in axes[:, 0]:
        ax.set_ylabel(r"$h_1$ (µm)")
    fig.colorbar(image, ax=axes, label="log10 max relative error vs simulation", shrink=0.9)
    fig.suptitle("Error against the direct simulation, cell labels in % (hatched: refined A/a_m > 0.1; blank: no "
                 "steady state)\ntest frequencies: " + ", ".join(f"{f:g} Hz" for f in sorted(experiment_omega_check)),
                 fontsize=8)
    fit_labels(fig, labels)
    return fig


def cell_label(error: float) -> str:
    """A relative error as an error map's cell shows it, in per cent: ``26``, ``7.6``, ``0.71``, ``0.012``, ``7e-5``.

    Two significant figures (whole per cents from 10 %); below 0.01 % one, with an exponent without padding: at
    most 5 characters for errors from 1e-99 to 9.9e3.
    """
    percent = 100.0 * error
    if percent >= 10.0 or percent == 0.0:
        return f"{percent:.0f}"
    if percent >= 0.01:
        return f"{percent:.2g}"
    mantissa, exponent = f"{percent:.0e}".split("e")
    return f"{mantissa}e{int(exponent)}"


#: The smallest font size (pt) of a cell label; a label that does not fit its cell at this size is left out.
SMALLEST_LABEL = 4.5


def fit_labels(fig: Figure, labels: Mapping[Axes, Sequence[Any]], margin: float = 0.9) -> None:
    """Shrink each cell label of an image in ``labels`` (texts per axes) until it fits ``margin`` of its cell.

    The cell is the axes' extent divided by the image's columns and rows, measured in the laid-out figure (so at any
    dpi, the sizes scaling alike); the font goes down in half points to :data:`SMALLEST_LABEL`, below which the label
    is hidden (the colour still shows the value).
    """
    fig.draw_without_rendering()
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    for ax, texts in labels.items():
        rows, columns = ax.get_images()[0].get_size()
        box = ax.get_window_extent(renderer)
        width, height = margin * box.width / columns, margin * box.height / rows
        for text in texts:
            size = text.get_fontsize()
            while size > SMALLEST_LABEL and _too_big(text, renderer, width, height):
                size -= 0.5
                text.set_fontsize(size)
            text.set_visible(not _too_big(text, renderer, width, height))


def _too_big(text: Any, renderer: Any, width: float, height: float) -> bool:
    """Whether ``text`` drawn by ``renderer`` is wider than ``width`` or taller than ``height`` (pixels)."""
    extent = text.get_window_extent(renderer)
    return bool(extent.width > width or extent.height > height)
