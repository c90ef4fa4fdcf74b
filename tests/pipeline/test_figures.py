"""Figures read at the size the page shows them: the zoom on Fig. 5's folds, the labels of the error maps.

Checked on small tables written here (a fold pair, a grid of errors), and on Fig. 5 of a finished run.
"""

import io
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import pytest

from vibroadhesion.pipeline import error_maps, figures, leads

#: A fold pair as in Fig. 5 at kappa = 0.001: two saddle-node points 5 % apart in omega_bar.
FOLDS = (10.5, 11.0)


def _fold_curves() -> pd.DataFrame:
    """An S through the folds of FOLDS: lower branch up to 11.0, middle back to 10.5, upper from there on."""
    lower = np.linspace(0.1, FOLDS[1], 200)
    middle = np.linspace(FOLDS[1], FOLDS[0], 50)
    upper = np.linspace(FOLDS[0], 50.0, 200)
    parts = [("lower-0", lower, 1e-4 * lower**2), ("middle-1", middle, np.geomspace(0.12, 0.02, 50)),
             ("upper-2", upper, 0.02 * (FOLDS[0] / upper) ** 2)]
    return pd.concat([pd.DataFrame({"kappa": 0.001, "zeta": 0.0, "branch": b, "omega_bar": w, "A_over_am": a})
                      for b, w, a in parts])


def _markers(kappa: float, folds: bool) -> pd.DataFrame:
    rows = [{"kind": "experiment", "frequency_hz": f, "kappa": kappa, "omega_bar": w, "A_over_am": 1e-3}
            for f, w in ((200.0, 17.85), (300.0, 26.8))]
    if folds:
        rows += [{"kind": "fold", "frequency_hz": np.nan, "kappa": kappa, "omega_bar": w, "A_over_am": a}
                 for w, a in zip(FOLDS, (0.02, 0.12), strict=True)]
    return pd.DataFrame(rows)


def test_fig5_zooms_on_the_folds_of_the_panels_that_have_them() -> None:
    """The inset spans the folds plus their distance on each side (0.5 here: more than 2 % of 11) on a linear axis."""
    curves = pd.concat([_fold_curves(), _fold_curves().assign(kappa=0.01)])
    fig = figures.plot_fig5(curves, pd.concat([_markers(0.001, True), _markers(0.01, False)]), 200.0)
    with_folds, without = fig.axes[0], fig.axes[1]
    assert without.child_axes == []
    (inset,) = with_folds.child_axes
    assert inset.get_xlim() == pytest.approx((10.0, 11.5))
    assert inset.get_xscale() == "linear" and inset.get_yscale() == "log"
    low, high = inset.get_ylim()  # the A/a_m the curves take between 10 and 11.5, widened by 1.5 each way
    near = curves[(curves["omega_bar"] >= 10.0) & (curves["omega_bar"] <= 11.5)]["A_over_am"]
    assert (low, high) == pytest.approx((near.min() / 1.5, 1.5 * near.max()), rel=1e-12)
    assert near.min() == pytest.approx(1e-4 * 10.0**2, rel=0.02) and near.max() == pytest.approx(0.12, rel=1e-12)
    plt.close(fig)


def test_fig5_inset_covers_no_curve_of_its_panel(pipeline_results: Path) -> None:
    """On the run's Fig. 5 table: no point of a panel's curves lies under the zoom drawn on it."""
    curves = pd.read_csv(pipeline_results / "fig5/fig5.csv")
    fig = figures.plot_fig5(curves, pd.read_csv(pipeline_results / "fig5/fig5_markers.csv"), 200.0)
    fig.draw_without_rendering()
    insets = [(ax, inset) for ax in fig.axes for inset in ax.child_axes]
    assert insets, "the run's Fig. 5 has folds (kappa = 0.001): a zoom is expected"
    for ax, inset in insets:
        points = curves[curves["A_over_am"] > 0][["omega_bar", "A_over_am"]].to_numpy()
        x, y = ax.transData.transform(points).T
        box = inset.get_window_extent()
        under = (x > box.x0) & (x < box.x1) & (y > box.y0) & (y < box.y1)
        assert not under.any(), f"{under.sum()} curve points under the inset, e.g. {points[under][:3]}"
    plt.close(fig)


@pytest.mark.parametrize(("error", "label"), [(0.26, "26"), (1.5, "150"), (0.076, "7.6"), (0.0071, "0.71"),
                                              (1.2e-4, "0.012"), (9.96e-5, "1e-2"), (7.3e-7, "7e-5"),
                                              (2.0e-11, "2e-9"), (0.0, "0")])
def test_cell_labels_are_per_cents_in_at_most_five_characters(error: float, label: str) -> None:
    assert error_maps.cell_label(error) == label


def _error_grid(models: int, errors: np.ndarray) -> tuple[pd.DataFrame, pd.DataFrame]:
    """A validation grid of ``models`` levels over 5 amplitudes x 9 frequencies, each cell's error from ``errors``."""
    h1, omega = np.arange(20.0, 101.0, 20.0), np.logspace(3, 8, 9)
    cells = [(f"level{m}", h, w) for m in range(models) for h in h1 for w in omega]
    grid = pd.DataFrame(cells + [("simulation", h, w) for h in h1 for w in omega],
                        columns=["model", "h1_um", "omega_check"])
    errors_frame = pd.DataFrame(cells, columns=["model", "h1_um", "omega_check"]).assign(
        relative_error=np.resize(errors, len(cells)), applicable=True)
    return grid, errors_frame


def _spills(fig: plt.Figure) -> list[str]:
    """The visible cell labels of ``fig`` (saved at 200 dpi) whose drawn extent leaves their cell."""
    fig.set_dpi(200)
    fig.draw_without_rendering()
    out = []
    for ax in fig.axes[:-1]:  # the last axes is the colour bar
        for text in ax.texts:
            j, i = text.get_position()
            x0, y0 = ax.transData.transform((j - 0.5, i - 0.5))
            x1, y1 = ax.transData.transform((j + 0.5, i + 0.5))
            box = text.get_window_extent()
            if text.get_visible() and not (x0 <= box.x0 and box.x1 <= x1 and y0 <= box.y0 and box.y1 <= y1):
                out.append(text.get_text())
    return out


def test_error_map_labels_fit_their_cells_at_the_saved_size() -> None:
    """The widest labels (5 characters) over 4 levels: every one shown, none leaving its cell at 200 dpi."""
    grid, errors = _error_grid(4, np.array([0.26, 7.3e-7, 1.2e-4, 0.0071, 0.076]))
    fig = error_maps.plot_validation_maps(grid, errors, {200.0: 1.45e6})
    assert _spills(fig) == []
    labels = [t for ax in fig.axes for t in ax.texts]
    assert len(labels) == 4 * 45 and all(t.get_visible() for t in labels)
    assert {t.get_text() for t in labels} == {"26", "7e-5", "0.012", "0.71", "7.6"}
    plt.close(fig)


def test_a_label_too_wide_for_its_cell_at_the_smallest_font_is_left_out() -> None:
    """Squeezed to 2 inches wide, the cells are too narrow for any label: the labels are hidden, not spilled."""
    grid, errors = _error_grid(2, np.array([7.3e-7]))
    fig = error_maps.plot_validation_maps(grid, errors, {200.0: 1.45e6})
    fig.set_size_inches(2.0, 3.0)
    error_maps.fit_labels(fig, {ax: ax.texts for ax in fig.axes[:-1]})
    assert _spills(fig) == []
    assert not any(t.get_visible() for ax in fig.axes for t in ax.texts)
    assert min(t.get_fontsize() for ax in fig.axes for t in ax.texts) == error_maps.SMALLEST_LABEL
    plt.close(fig)


def _fig4_png(tmp_path: Path, measured: pd.DataFrame, name: str) -> bytes:
    """Fig. 4 of a two-curve table (h1 0-120 um at 200 and 400 Hz) with ``measured``, as PNG bytes."""
    table = pd.DataFrame([{"frequency_hz": f, "h1_um": h, "model": m, "pulloff_ratio": 1.0 + h / 100.0 + k,
                           "A_over_am": 0.01} for k, f in enumerate((200.0, 400.0)) for h in (0.0, 60.0, 120.0)
                          for m in ("leading", "refined")])
    fig = figures.plot_fig4(table, measured, 57.27)
    figures.save_figure(fig, tmp_path / f"{name}.pdf", tmp_path / f"{name}.png")
    return (tmp_path / f"{name}.png").read_bytes()


def test_fig4_fills_and_labels_rows_measured_at_a_withdrawal_speed(tmp_path: Path) -> None:
    """A row with withdrawal_speed_um_s > 0 is a filled marker labelled "withdrawn at V > 0"; an all-quasi-static
    speed column (the reader's zeros) draws the same bytes as a frame without the column."""
    rows = pd.DataFrame({"frequency_hz": [200.0, 400.0], "h1_um": [40.0, 60.0], "pulloff_mN": [250.0, 500.0],
                         "source": ["lab", "lab"]})
    without = _fig4_png(tmp_path, rows, "without")
    assert _fig4_png(tmp_path, rows.assign(withdrawal_speed_um_s=0.0), "zeros") == without
    fig = figures.plot_fig4(pd.read_csv(io.StringIO("frequency_hz,h1_um,model,pulloff_ratio,A_over_am\n"
                                                    "200.0,0.0,refined,1.0,0.01\n200.0,60.0,refined,2.0,0.01\n")),
                            rows.assign(withdrawal_speed_um_s=[44.5, 0.0]), 57.27)
    labels = {line.get_label(): line.get_markerfacecolor() for line in fig.axes[0].lines}
    assert labels["lab, 200 Hz, withdrawn at V > 0"] != "none" and labels["lab, 400 Hz"] == "none"
    plt.close(fig)


def test_fig4_names_the_refined_curves_hidden_under_the_leading_order() -> None:
    """A refined curve within 1 % of the plot's height (0.3 here) of the leading order is said to be hidden; one
    0.5 away (2.5 % of 20) is not. Hand-made curves: leading 1 to 20, refined at 200 Hz + 0.1, at 400 Hz + 0.5."""
    h1 = np.array([0.0, 50.0, 100.0])
    lead = pd.DataFrame({"model": "leading", "frequency_hz": np.nan, "h1_um": h1, "pulloff_ratio": [1.0, 8.0, 20.0]})
    refined = [pd.DataFrame({"model": "refined", "frequency_hz": f, "h1_um": h1,
                             "pulloff_ratio": [1.0 + d, 8.0 + d, 20.0 + d], "A_over_am": 0.01})
               for f, d in ((200.0, 0.1), (400.0, 0.5))]
    table = pd.concat([lead, *refined], ignore_index=True)
    assert leads.coinciding_frequencies(table) == [200.0]
    labels = [t.get_text() for t in figures.plot_fig4(table, pd.DataFrame(
        {"frequency_hz": [], "h1_um": [], "pulloff_mN": [], "source": []}), 57.27).legends[0].get_texts()]
    assert "refined, Eq. (106), 200 Hz (coincides with the leading order: hidden under it)" in labels
    assert "refined, Eq. (106), 400 Hz" in labels
    plt.close("all")
