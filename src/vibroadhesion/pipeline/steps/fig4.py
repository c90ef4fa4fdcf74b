"""Fig. 4's table: pull-off amplification, leading order (Eqs. 71-72) and refined (Eq. 106).

Run by rule ``fig4_fig7_data`` (:mod:`vibroadhesion.pipeline.steps.fig4_fig7`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from vibroadhesion.experiments.figure_tables.fig4 import fig4_table
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.data import read_canonical_setup
from vibroadhesion.pipeline.steps.inputs import fitted


def fig4_data(setup_json: str | Path, fit_json: str | Path, out: str | Path, h1_max_um: float, points: int) -> None:
    """results/fig4/fig4.csv at the rig's test frequencies, on ``points`` amplitudes in [0, h1_max_um].

    The rig's own amplitudes (data/setup.yaml) are added to the grid, so that Fig. 7 finds the leading-order and
    exact-averaging values at each of them whatever they are (25.5 um, or beyond h1_max_um).
    """
    setup = read_canonical_setup(setup_json)
    params = GentSchultzParameters(**fitted(fit_json))  # the fit the figures use, for every curve
    h1 = np.union1d(np.linspace(0.0, h1_max_um, points), setup.amplitudes_um)
    table = fig4_table(params, setup.frequencies_hz, h1, radius=setup.radius, reduced_modulus=setup.reduced_modulus)
    write_csv(table, out)
