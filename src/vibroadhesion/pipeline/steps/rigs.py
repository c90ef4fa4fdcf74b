"""Steps of the rig-comparison rules: the base- and the force-excitation rigs (Figs. 1, 2; Eq. 13; Appendix B).

The cases are the test frequencies of data/setup.yaml and the fixation's anti-resonance omega0 (with the configured
damping and undamped), simulation_jobs.rig_cases_per_job of them per job (workflow/config.yaml: all four in one job
with -c2, where a job's start-up costs about a case; profiles/slurm: one each), for the simulated compliant fixation
(kappa, zeta) and every amplitude h1; the table is :func:`vibroadhesion.experiments.rigs.rig_comparison`'s with the
dimensional columns added.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path

import pandas as pd

from vibroadhesion.core import groups
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.experiments import rigs
from vibroadhesion.experiments.virtual_pulloff import published_pulloffs
from vibroadhesion.numerics.progress import ProgressBar
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.data import Setup
from vibroadhesion.pipeline.steps.inputs import rig, setup_fixations, setup_number

#: The wildcard value of the job at the fixation's anti-resonance omega = omega0 (Appendix B).
ANTI_RESONANCE = "antiresonance"


def rigs_part(setup_json: str | Path, virtual_csvs: Sequence[str | Path], out: str | Path, cases: str) -> None:
    """The comparison at the cases of one job: ``cases`` joined by "_", each a test frequency in Hz or ANTI_RESONANCE.

    Published parameters (the validation's); the rows of :func:`case_table` of each case (Figs. 1, 2; Eqs. 11, 13),
    in the order given. ``virtual_csvs``: the virtual pull-off jobs' parts of the compliant fixation at the published
    parameters (results/simulation/published/virtual_pulloff/compliant_*Hz.csv), whose simulated rows are the base
    rig's pull-offs at the test frequencies (the same families: equal to 6e-14, the rounding of omega_check; not
    traced again).
    """
    virtual = pd.concat([pd.read_csv(p) for p in virtual_csvs], ignore_index=True)
    setup, params, chi0 = rig(setup_json)
    (fixation,) = setup_fixations(setup, params["v0"], "compliant")
    omega0 = setup_number(setup, "fixation.natural_frequency")
    names = cases.split("_")
    progress = ProgressBar(sum(2 if c == ANTI_RESONANCE else 1 for c in names) * len(setup.amplitudes_um)
                           * len(rigs.RIGS), "rig points")
    write_csv(pd.concat([case_table(case, setup, fixation, omega0, chi0, params["n"], progress, virtual)
                         for case in names], ignore_index=True), out)


def case_table(case: str, setup: Setup, fixation: Fixation, omega0: float, chi0: float, n: float,
               progress: ProgressBar, virtual: pd.DataFrame) -> pd.DataFrame:
    """The comparison at one test frequency (``case`` in Hz) or at the anti-resonance (``case`` = ANTI_RESONANCE).

    Columns of :func:`vibroadhesion.experiments.rigs.rig_comparison` plus frequency_hz, h1_um, F1_N = force E* R^2
    (Eq. 13) and delta_amplitude_um = delta_amplitude a_o^2/R (Eq. 86); the anti-resonance omega = omega0 with the
    configured damping and undamped (Appendix B). At a test frequency the base rig's pull-offs are ``virtual``'s
    (its simulated rows, :func:`vibroadhesion.experiments.virtual_pulloff.published_pulloffs`).
    """
    frequency_hz = omega0 / (2.0 * math.pi) if case == ANTI_RESONANCE else float(case)
    eta1 = [float(groups.eta1(h * 1e-6, setup.radius)) for h in setup.amplitudes_um]
    known: dict[tuple[float, float], tuple[str, float]] = {}
    if case == ANTI_RESONANCE:
        cases = [(fixation, [1.0]), (replace(fixation, zeta=0.0), [1.0])]
    else:
        omega_bar = 2.0 * math.pi * frequency_hz / omega0
        cases = [(fixation, [omega_bar])]
        published = published_pulloffs(virtual, frequency_hz)
        known = {(omega_bar, e): published[float(h)] for e, h in zip(eta1, setup.amplitudes_um, strict=True)}
    table = rigs.rig_comparison(cases, eta1, chi0, n, progress, known)
    c_o, radius = groups.contact_radius_ratio(chi0), setup.radius
    table.insert(0, "frequency_hz", frequency_hz)  # the configured frequency, not omega_bar omega0/2pi's rounding
    table.insert(4, "h1_um", table["eta1"] * radius * 1e6)
    table["F1_N"] = table["force"] * setup.reduced_modulus * radius**2
    table["delta_amplitude_um"] = table["delta_amplitude"] * c_o**2 * radius * 1e6
    return table


def rigs_gather(parts: Sequence[str | Path], out: str | Path, summary_out: str | Path) -> None:
    """results/validation/rig_comparison.csv (every job's rows by frequency) and the equivalence summary."""
    table = pd.concat([pd.read_csv(p) for p in parts], ignore_index=True)
    table = table.sort_values(["frequency_hz", "zeta"], kind="stable").reset_index(drop=True)
    summary = rigs.equivalence_summary(table)
    write_csv(table, out)
    write_csv(summary, summary_out)
    print(summary.to_string(index=False))

