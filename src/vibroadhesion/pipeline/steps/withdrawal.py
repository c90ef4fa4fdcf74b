"""Steps of the withdrawal rules (workflow/rules/withdrawal.smk): the simulated pull-off against withdrawal speed.

One job per fixation and chunk of test frequencies (config simulation_jobs.frequencies_per_job) runs every
amplitude of data/setup.yaml at the speeds of workflow/config.yaml (:mod:`vibroadhesion.experiments.speed_sweep`,
time-domain withdrawal of the full model, Eqs. 3'-11'), its V -> 0 values read from the published virtual
pull-off; one job runs the averaged slow flow (rigid, frequency-free: :mod:`vibroadhesion.models.slow_flow`) of
every amplitude; the gather step places the slow flow at each rigid test frequency, concatenates them and writes
the speeds below which the quasi-static pull-off is within 1 % and 5 % (the figure:
:func:`vibroadhesion.pipeline.steps.plots.withdrawal_plot`).
Time-domain rows are simulated, slow-flow rows averaged (``method``, ``source``).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import pandas as pd

from vibroadhesion.core import groups
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.experiments import speed_sweep
from vibroadhesion.numerics.progress import ProgressBar
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.inputs import FixationCase, experiment_omega_check, rig, setup_fixations

Path_ = str | Path


def withdrawal_part(setup_json: Path_, virtual_pulloff_csv: Path_, out: Path_, fixation: FixationCase,
                    frequencies_hz: Sequence[float], speed_ratios: Sequence[float],
                    stop: Mapping[str, float | None]) -> None:
    """results/withdrawal/{fixation}_{frequencies}Hz.csv: every amplitude at each frequency and V/v0 (Eq. 11').

    The rows come in the order of ``frequencies_hz``, then of the amplitudes of data/setup.yaml.

    ``stop``: config withdrawal.stop of the fixation
    (:meth:`vibroadhesion.experiments.speed_sweep.StopRule.from_config`).

    The V -> 0 value of each test is read from ``virtual_pulloff_csv`` (the published virtual pull-off of the
    fixation, the same family of steady states).
    """
    setup, params, chi0 = rig(setup_json)
    (case,) = setup_fixations(setup, params["v0"], fixation)
    omega_checks = experiment_omega_check(setup, params["v0"])
    virtual, rule = pd.read_csv(virtual_pulloff_csv), speed_sweep.StopRule.from_config(stop)
    progress = ProgressBar(len(frequencies_hz) * len(setup.amplitudes_um), "amplitudes")
    parts = []
    for frequency_hz in frequencies_hz:
        problems = speed_sweep.rig_problems(chi0, params["n"], omega_checks[frequency_hz], setup.radius,
                                            setup.amplitudes_um, case)
        quasi_static = speed_sweep.quasi_static_ratios(virtual, frequency_hz)
        for h1, problem in problems:
            parts.append(speed_sweep.sweep_table([(h1, problem)], speed_ratios, fixation_name=fixation,
                                                 frequency_hz=frequency_hz, v0_um_s=params["v0"] * 1e6,
                                                 quasi_static=quasi_static, stop=rule))
            progress.advance(1, f"{fixation}, {frequency_hz:g} Hz, h1 = {h1:g} um")
    write_csv(pd.concat(parts, ignore_index=True), out)


def withdrawal_slow_flow(setup_json: Path_, out: Path_, speed_ratios: Sequence[float]) -> None:
    """results/withdrawal/slow_flow.csv: the slow flow (rigid) of every amplitude at each V/v0, slow times."""
    setup, params, chi0 = rig(setup_json)
    omega_check = experiment_omega_check(setup, params["v0"])[setup.frequencies_hz[0]]  # the flow does not use it
    problems = speed_sweep.rig_problems(chi0, params["n"], omega_check, setup.radius, setup.amplitudes_um,
                                        Fixation.rigid())
    write_csv(speed_sweep.slow_flow_rows(problems, speed_ratios, params["v0"] * 1e6), out)


def withdrawal_gather(setup_json: Path_, parts: Sequence[Path_], slow_flow_csv: Path_, out: Path_,
                      limits_out: Path_) -> None:
    """results/withdrawal/speed_sweep.csv (the slow flow at each rigid frequency) and quasi_static_limits.csv."""
    setup, params, chi0 = rig(setup_json)
    slow, c_o = pd.read_csv(slow_flow_csv), float(groups.contact_radius_ratio(chi0))
    placed = [speed_sweep.at_frequency(slow, omega_check, c_o, fixation_name="rigid", frequency_hz=frequency)
              for frequency, omega_check in experiment_omega_check(setup, params["v0"]).items()]
    table = pd.concat([pd.read_csv(p) for p in parts], ignore_index=True)
    table = pd.concat([table, *placed], ignore_index=True).sort_values(
        ["fixation", "frequency_hz", "h1_um", "V_over_v0", "method"], kind="stable", ascending=[False, True, True,
                                                                                              True, True])
    write_csv(table.reset_index(drop=True), out)
    write_csv(speed_sweep.quasi_static_limits(table), limits_out)

