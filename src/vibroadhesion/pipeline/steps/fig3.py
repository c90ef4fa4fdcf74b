"""Step of rule ``fig3_data``: the J-integrals (Eqs. 28, 29, 36) for the fitted n and the panel exponents."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from vibroadhesion.experiments.figure_tables.fig3 import fig3_table
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.inputs import fitted


def fig3_data(fit_json: str | Path, out: str | Path, panel_n: Sequence[float], log10_Abar_min: float,
              log10_Abar_max: float, points: int) -> None:
    """results/fig3/fig3.csv on ``points`` log-spaced Abar in [10^min, 10^max] (Eq. 77)."""
    Abar = np.logspace(log10_Abar_min, log10_Abar_max, points)
    write_csv(fig3_table([fitted(fit_json)["n"], *panel_n], Abar), out)
