"""Step of rule ``fig3_fig6_fig8_data``: the tables of Figs. 3, 6 and 8 in one process.

Each costs less to compute than a process costs to start and import the numerics (about 0.7 CPU-s), so the three
tables at the published parameters share one job. Fig. 8 reads Fig. 6's table as written, as its own rule did.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from vibroadhesion.pipeline.steps.fig3 import fig3_data
from vibroadhesion.pipeline.steps.fig8 import fig8_data
from vibroadhesion.pipeline.steps.rigid import fig6_data


def fig3_fig6_fig8_data(setup_json: str | Path, fit_json: str | Path | None, outputs: Mapping[str, str | Path],
                        fig3: Mapping[str, Any], fig6: Mapping[str, Any]) -> None:
    """results/fig3/fig3.csv, results/fig6/fig6.csv, then results/fig8/fig8.csv from Fig. 6's rows.

    ``outputs`` by figure (``fig3``, ``fig6``, ``fig8``); ``fig3`` and ``fig6`` are the sections of
    workflow/config.yaml with the grids of :func:`~vibroadhesion.pipeline.steps.fig3.fig3_data` and
    :func:`~vibroadhesion.pipeline.steps.rigid.fig6_data`.
    """
    fig3_data(setup_json, fit_json, outputs["fig3"], fig3["panel_n"], fig3["log10_Abar_min"], fig3["log10_Abar_max"],
              fig3["points"])
    fig6_data(setup_json, fit_json, outputs["fig6"], fig6["log10_omega_check_min"], fig6["log10_omega_check_max"],
              fig6["points"])
    fig8_data(setup_json, fit_json, outputs["fig6"], outputs["fig8"])
