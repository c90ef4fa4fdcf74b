"""Step of rule ``simulation_kernels``: compile the simulation's numba kernels once, before the jobs that use them.

The compiled code of :mod:`vibroadhesion.simulation.kernel` is cached on disk by numba; a process that finds the
cache loads it (~0.2-0.4 s) instead of compiling (~4-5 s). Two jobs that start together on a missing cache would
each compile, so this rule does it once and the simulation rules take its output as an input. It imports only
the simulation and what it stands on, so that editing another module does not rerun it.
"""

from __future__ import annotations

import time
from pathlib import Path

import numba

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.pipeline.atomic import atomic_path
from vibroadhesion.simulation import steady_state


def compile_kernels(out: str | Path) -> None:
    """Run one rigid and one compliant steady state (every compiled function), then record what was compiled.

    Any contact that keeps contact exercises every compiled function, so the states are fixed representative
    ones, not inputs (data/setup.yaml is not read: the rule reruns only when the simulation's code changes):
    chi0 = 2.589e-2, eta1 = 3.9e-4, omega_check = 1.1e6, rigid and on a spring kappa = 0.1, zeta = 0.2
    (Eqs. 64-66, 97, 105). ``out`` names the numba version and the two statuses (the same bytes on every run);
    the time taken goes to the log.
    """
    start = time.perf_counter()
    law, chi0, eta1 = GentSchultz(0.531), 2.589e-2, 20e-6 / 51.5e-3
    rigid = steady_state(Problem(law, chi0, eta1, 1.1e6))
    spring = Fixation.compliant(kappa=0.1, zeta=0.2, nu0=1.227e-5)
    compliant = steady_state(Problem(law, chi0, eta1, 17.85 / 1.227e-5, fixation=spring))
    print(f"compiled or loaded the simulation kernels in {time.perf_counter() - start:.1f} s")
    with atomic_path(out) as tmp:
        tmp.write_text(f"numba {numba.__version__}: simulation kernels compiled and cached (rigid steady state "
                       f"{rigid.status}, compliant {compliant.status})\n", encoding="utf-8")
