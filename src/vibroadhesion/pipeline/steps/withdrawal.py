"""Steps of the withdrawal rules (workflow/rules/withdrawal.smk): the simulated pull-off against withdrawal speed.

One job per (fixation, test frequency) runs every amplitude of data/setup.yaml at the speeds of
workflow/config.yaml (:mod:`vibroadhesion.experiments.speed_sweep`, time-domain withdrawal of the full model,
Eqs. 3'-11'); the gather step concatenates them and writes the speeds below which the quasi-static
pull-off is within 1 % and 5 % (the figure: :func:`vibroadhesion.pipeline.steps.plots.withdrawal_plot`).
Every number here is simulated.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import pandas as pd

from vibroadhesion.experiments import speed_sweep
from vibroadhesion.numerics.progress import ProgressBar
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.inputs import FixationCase, experiment_omega_check, rig, setup_fixations

Path_ = str | Path


def withdrawal_part(setup_json: Path_, out: Path_, fixation: FixationCase, frequency_hz: float,
                    speed_ratios: Sequence[float]) -> None:
    """results/withdrawal/{fixation}_{frequency}Hz.csv: every amplitude of the rig at each V/v0 (Eq. 11')."""
    setup, params, chi0 = rig(setup_json)
    (case,) = setup_fixations(setup, params["v0"], fixation)
    omega_check = experiment_omega_check(setup, params["v0"])[frequency_hz]
    problems = speed_sweep.rig_problems(chi0, params["n"], omega_check, setup.radius, setup.amplitudes_um, case)
    progress = ProgressBar(len(problems), "amplitudes")
    parts = []
    for h1, problem in problems:
        parts.append(speed_sweep.sweep_table([(h1, problem)], speed_ratios, fixation_name=fixation,
                                             frequency_hz=frequency_hz, v0_um_s=params["v0"] * 1e6))
        progress.advance(1, f"{fixation}, {frequency_hz:g} Hz, h1 = {h1:g} um")
    write_csv(pd.concat(parts, ignore_index=True), out)


def withdrawal_gather(parts: Sequence[Path_], out: Path_, limits_out: Path_) -> None:
    """results/withdrawal/speed_sweep.csv and quasi_static_limits.csv (1 % and 5 %, simulated)."""
    table = pd.concat([pd.read_csv(p) for p in parts], ignore_index=True)
    write_csv(table, out)
    write_csv(speed_sweep.quasi_static_limits(table), limits_out)

