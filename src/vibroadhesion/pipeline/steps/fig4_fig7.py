"""Step of rule ``fig4_fig7_data``: the tables of Figs. 4 and 7 at the fit the figures use, in one process.

Both show the measured rows (an edit of data/pulloff.csv reruns them, through the fit) and each costs less to
compute than a process costs to start and import the numerics, so they share one job.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from vibroadhesion.pipeline.steps.fig4 import fig4_data
from vibroadhesion.pipeline.steps.rigid import fig7_data


def fig4_fig7_data(setup_json: str | Path, fit_json: str | Path, outputs: Mapping[str, str | Path],
                   fig4: Mapping[str, Any], fig7: Mapping[str, Any]) -> None:
    """results/fig4/fig4.csv and results/fig7/fig7.csv.

    ``outputs`` by figure (``fig4``, ``fig7``); ``fig4`` and ``fig7`` are the sections of workflow/config.yaml
    with the grids of :func:`~vibroadhesion.pipeline.steps.fig4.fig4_data` and
    :func:`~vibroadhesion.pipeline.steps.rigid.fig7_data`.
    """
    fig4_data(setup_json, fit_json, outputs["fig4"], fig4["h1_max_um"], fig4["points"])
    fig7_data(setup_json, fit_json, outputs["fig7"], fig7["log10_omega_check_min"], fig7["log10_omega_check_max"],
              fig7["points"])
