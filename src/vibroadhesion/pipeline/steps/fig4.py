"""Step of rule ``fig4_data``: pull-off amplification, leading order (Eqs. 71-72) and refined (Eq. 106)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from vibroadhesion.experiments.figure_tables.fig4 import fig4_table
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.data import read_canonical_setup
from vibroadhesion.pipeline.steps.inputs import fitted


def fig4_data(setup_json: str | Path, fit_json: str | Path, out: str | Path, h1_max_um: float, points: int) -> None:
    """results/fig4/fig4.csv on ``points`` amplitudes in [0, h1_max_um] at the rig's test frequencies."""
    setup = read_canonical_setup(setup_json)
    params = GentSchultzParameters(**fitted(fit_json))  # the fit the figures use, for every curve
    h1 = np.linspace(0.0, h1_max_um, points)
    table = fig4_table(params, setup.frequencies_hz, h1, radius=setup.radius, reduced_modulus=setup.reduced_modulus)
    write_csv(table, out)
