"""Steps of the simulation rules.

The direct simulation of the full model (ground truth) on the rigid validation grid and in the virtual pull-off
experiment, written under results/simulation/ for the figures and the validation to read.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from vibroadhesion.experiments import validation, virtual_pulloff
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.numerics.progress import ProgressBar
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.inputs import FixationCase, experiment_omega_check, rig, setup_fixations


def rigid_part(setup_json: str | Path, fit_json: str | Path | None, out: str | Path, h1_um: Sequence[float],
               log10_omega_check_min: int, log10_omega_check_max: int) -> None:
    """Every model level and the simulation at the amplitudes ``h1_um`` (one job's share) on the rigid grid.

    The levels are leading, refined, exact harmonic balance and exact averaging (rigid nominal point
    contact, Eqs. 49, 98, 122-123 against the simulation of Eqs. 64-66); the grid is the whole decades of
    omega_check and the test frequencies. Rows by amplitude in the order given, then by omega_check.
    """
    setup, params, chi0 = rig(setup_json, fit_json)
    omega = validation.validation_frequencies((log10_omega_check_min, log10_omega_check_max),
                                              list(experiment_omega_check(setup, params["v0"]).values()))
    rows, progress = [], ProgressBar(len(omega) * len(h1_um), "frequencies")
    for h1, w in itertools.product(h1_um, omega):
        point = validation.rigid_point(h1, float(w), chi0=chi0, radius=setup.radius, n=params["n"])
        rows.extend(point)
        simulated = next(r["status"] for r in point if r["model"] == "simulation")
        progress.advance(1, f"h1 = {h1:g} um, omega_check = {w:.6g}: simulation {simulated}")
    write_csv(pd.DataFrame(rows)[validation.RIGID_GRID_COLUMNS], out)


def virtual_pulloff_part(setup_json: str | Path, fit_json: str | Path | None, out: str | Path, fixation: FixationCase,
                         frequencies_hz: Sequence[float]) -> None:
    """The simulated pull-off (Sec. 3.4, Eqs. 70-72) at the test frequencies of one job, with the predictions.

    Every amplitude of the rig, for the rigid fixation or the simulated compliant case of
    data/setup.yaml (kappa, zeta; mu, omega0); rows by frequency in the order given.
    """
    setup, params, _ = rig(setup_json, fit_json)
    (case,) = setup_fixations(setup, params["v0"], fixation)
    h1 = np.asarray(setup.amplitudes_um, dtype=float)
    progress = ProgressBar(len(h1) * len(frequencies_hz), "amplitudes")
    tables = [virtual_pulloff.pulloff_table(GentSchultzParameters(**params), f, h1, radius=setup.radius,
                                            reduced_modulus=setup.reduced_modulus, fixation=case, progress=progress)
              for f in frequencies_hz]
    write_csv(pd.concat(tables, ignore_index=True), out)
