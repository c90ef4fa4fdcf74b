"""Every figure the pipeline saves gives its plot area the room: no legend squeezes the panels.

Each figure is drawn again from the run's artefacts by the step that saved it (:mod:`vibroadhesion.pipeline.steps.plots`
and the benchmark's :func:`vibroadhesion.pipeline.page_figures.plot_speed_vs_error`); where it is saved, the
panels are measured in the saved PNG's frame (the tight bounding box ``bbox_inches="tight"`` crops to, whose size
the PNG has): in each row of panels, every panel is at least :data:`SHARE` of the figure's width divided by the
panels in that row, and at least :data:`HEIGHT_SHARE` of its height divided by the rows (a legend below must not
flatten them either). Colour bars are not panels.
"""

from __future__ import annotations

import io
from functools import partial
from pathlib import Path

import matplotlib.image
import pandas as pd
import pytest
import yaml
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.transforms import Bbox

from vibroadhesion.pipeline import figures, page_figures
from vibroadhesion.pipeline.steps import plots

ROOT = Path(__file__).resolve().parents[2]

#: The least share of the saved figure's width that the panels of one row take together (issue 27: 55 %).
SHARE = 0.55
#: The least share of the saved figure's height that the rows of panels take together.
HEIGHT_SHARE = 0.4


def _panels(fig: Figure) -> list[Axes]:
    """The figure's panels: its axes less colour bars (insets are children of a panel, not in ``fig.axes``)."""
    return [ax for ax in fig.axes if ax.get_label() != "<colorbar>" and ax.get_visible()]


def _rows(boxes: list[Bbox]) -> list[list[Bbox]]:
    """``boxes`` grouped into rows: boxes whose vertical extents overlap by more than half share a row."""
    rows: list[list[Bbox]] = []
    for box in sorted(boxes, key=lambda b: -b.y1):
        for row in rows:
            overlap = min(row[0].y1, box.y1) - max(row[0].y0, box.y0)
            if overlap > 0.5 * min(row[0].height, box.height):
                row.append(box)
                break
        else:
            rows.append([box])
    return rows


def squeezed(fig: Figure) -> list[str]:
    """The panels of ``fig``, as saved with a tight bounding box, narrower or flatter than their share.

    Saved first (to memory) so that the layout engine has placed them as in the saved PNG; the PNG's size is
    checked against the tight box the panels are measured in.
    """
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", bbox_inches="tight", dpi=100, pad_inches=0)
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]
    frame = fig.get_tightbbox(renderer).transformed(fig.dpi_scale_trans)
    height, width = matplotlib.image.imread(io.BytesIO(buffer.getvalue())).shape[:2]
    assert abs(width - frame.width) <= 2 and abs(height - frame.height) <= 2
    rows = _rows([ax.get_window_extent(renderer) for ax in _panels(fig)])
    out = []
    for row in rows:
        for box in row:
            w, h = box.width / frame.width, box.height / frame.height
            if w < SHARE / len(row) or h < HEIGHT_SHARE / len(rows):
                out.append(f"panel {w:.2f} of the width (least {SHARE / len(row):.2f}), {h:.2f} of the height "
                           f"(least {HEIGHT_SHARE / len(rows):.2f})")
    return out


def _measure_saves(monkeypatch: pytest.MonkeyPatch) -> dict[str, list[str]]:
    """Patch :func:`figures.save_figure` to measure each figure (:func:`squeezed`) before saving it; by PNG name."""
    seen: dict[str, list[str]] = {}
    original = figures.save_figure

    def measuring(fig: Figure, pdf: str | Path, png: str | Path) -> None:
        seen[Path(png).name] = squeezed(fig)
        original(fig, pdf, png)

    monkeypatch.setattr(figures, "save_figure", measuring)
    return seen


def _save_speed_vs_error(csv: Path, pdf: Path, png: Path) -> None:
    """The benchmark's figure (benchmarks/speed_vs_error.py) from its table; the benchmark solves each point 5 times."""
    figures.save_figure(page_figures.plot_speed_vs_error(pd.read_csv(csv), 5), pdf, png)


def _figure_steps(run: Path, out: Path) -> dict[str, partial[None]]:
    """Each figure the pipeline saves, as the call of its step on the run's artefacts, writing into ``out``."""
    setup, fit = run / "data/setup.json", run / "fit/gent_schultz.json"
    inputs = {**{f"fig{k}": run / f"fig{k}/fig{k}.csv" for k in range(3, 9)},
              "fig5_markers": run / "fig5/fig5_markers.csv", "setup": setup, "fit": fit,
              "pulloff": run / "data/pulloff.csv", "grid": run / "simulation/rigid_grid.csv",
              "virtual": run / "simulation/published/virtual_pulloff_rigid.csv"}
    panel_n = yaml.safe_load((ROOT / "workflow/config.yaml").read_text(encoding="utf-8"))["fig3"]["panel_n"]
    steps = {f"fig{k}": partial(plots.all_figures, inputs, {f"fig{k}_pdf": out / f"fig{k}.pdf",
                                                            f"fig{k}_png": out / f"fig{k}.png"}, panel_n)
             for k in range(3, 9)}
    steps["validation"] = partial(plots.validation_plot, setup, fit, run / "simulation/rigid_grid.csv",
                                  run / "validation/rigid_errors.csv", out / "maps.pdf", out / "maps.png")
    steps["compliant_sweep"] = partial(plots.compliant_sweep_plot, run / "validation/compliant_sweep.csv",
                                       run / "validation/compliant_sweep_refined.csv", out / "sweep.pdf",
                                       out / "sweep.png")
    steps["withdrawal"] = partial(plots.withdrawal_plot, run / "withdrawal/speed_sweep.csv", out / "speed.pdf",
                                  out / "speed.png")
    steps["rigs"] = partial(plots.rigs_plot, run / "validation/rig_comparison.csv", out / "rigs.pdf",
                            out / "rigs.png")
    steps["speed_vs_error"] = partial(_save_speed_vs_error, run / "benchmarks/speed_vs_error.csv",
                                      out / "speed_vs_error.pdf", out / "speed_vs_error.png")
    return steps


FIGURES = ["fig3", "fig4", "fig5", "fig6", "fig7", "fig8", "validation", "compliant_sweep", "withdrawal", "rigs",
           "speed_vs_error"]


@pytest.mark.parametrize("name", FIGURES)
def test_no_legend_squeezes_the_panels(pipeline_results: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                       name: str) -> None:
    seen = _measure_saves(monkeypatch)
    _figure_steps(pipeline_results, tmp_path)[name]()
    assert len(seen) == 1
    assert next(iter(seen.values())) == []


def test_the_measure_sees_a_squeezed_panel() -> None:
    """Negative control: a panel beside a legend of long labels, in a figure 5 inches wide, is reported."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.0, 3.5), layout="constrained")
    for k in range(6):
        ax.plot([1, 2], [k, k + 1], label=f"a long label of a curve that no reader could miss, number {k}")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0))
    assert squeezed(fig) != []
    plt.close(fig)
    fig, ax = plt.subplots(figsize=(5.0, 3.5), layout="constrained")
    ax.plot([1, 2], [1, 2], label="one curve")
    ax.legend()
    assert squeezed(fig) == []
    plt.close(fig)
