"""Fig. 8's table: dynamic contact stiffness (Eqs. 117-121) along the Fig. 6 solution.

Run by rule ``fig3_fig6_fig8_data`` (:mod:`vibroadhesion.pipeline.steps.fig3_fig6_fig8`).
"""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from vibroadhesion.experiments.figure_tables.fig8 import fig8_table
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.inputs import rig


def fig8_data(setup_json: str | Path, fit_json: str | Path | None, fig6_csv: str | Path, out: str | Path) -> None:
    """results/fig8/fig8.csv from the rows of results/fig6/fig6.csv (no new solve)."""
    _, params, chi0 = rig(setup_json, fit_json)
    write_csv(fig8_table(pd.read_csv(fig6_csv), chi0=chi0, n=params["n"]), out)
