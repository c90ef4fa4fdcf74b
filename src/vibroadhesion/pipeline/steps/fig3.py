"""Fig. 3's table: the J-integrals (Eqs. 28, 29, 36) for the figure's n and the panel exponents.

Run by rule ``fig3_fig6_fig8_data`` (:mod:`vibroadhesion.pipeline.steps.fig3_fig6_fig8`).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from vibroadhesion.experiments.figure_tables.fig3 import fig3_table
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.inputs import rig


def fig3_data(setup_json: str | Path, fit_json: str | Path | None, out: str | Path, panel_n: Sequence[float],
              log10_Abar_min: float, log10_Abar_max: float, points: int) -> None:
    """results/fig3/fig3.csv on ``points`` log-spaced Abar in [10^min, 10^max] (Eq. 77).

    n of the parameter set of :func:`~vibroadhesion.pipeline.steps.inputs.rig` (published unless ``fit_json``).
    """
    _, params, _ = rig(setup_json, fit_json)
    Abar = np.logspace(log10_Abar_min, log10_Abar_max, points)
    write_csv(fig3_table([params["n"], *panel_n], Abar), out)
