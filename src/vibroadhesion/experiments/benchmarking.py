"""Speed against error of the J-integral evaluation (issue: "every method reports its speed against its error").

Two methods are measured on the same machine in one run:

* ``fixed rule``: :func:`vibroadhesion.core.integrals.j_integrals`, vectorised;
* ``scipy quad``: :func:`scipy.integrate.quad` on Eqs. (28), (29), (36) over (0, pi) with
  ``points=[pi/2]`` and ``epsrel=1e-12``, one Abar at a time (three integrals per Abar).

Throughput is the number of Abar values for which all three integrals are returned per
second; the error is the largest relative error (absolute where the reference is 0) of any of
the three against a high-precision reference passed in by the caller.
"""

from __future__ import annotations

import math
import os
import platform
import time
import warnings
from collections.abc import Callable, Sequence

import numpy as np
import pandas as pd
from scipy.integrate import IntegrationWarning, quad

from vibroadhesion.core.integrals import j_integrals
from vibroadhesion.core.ratelaw import GentSchultz

Reference = Callable[[float, float], Sequence[float]]


def j_integrals_quad(Abar: float, n: float) -> tuple[float, float, float]:
    """Adaptive-quadrature baseline for one Abar (QUADPACK, split at pi/2, epsrel = 1e-12)."""
    law = GentSchultz(n)

    def sqrt_f(x: float) -> float:
        return math.sqrt(float(law.f(Abar * math.cos(x))))

    options = {"points": [0.5 * math.pi], "epsrel": 1e-12, "epsabs": 0.0, "limit": 200}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", IntegrationWarning)
        j0 = quad(sqrt_f, 0.0, math.pi, **options)[0] / math.pi
        jc1 = 2.0 / math.pi * quad(lambda x: sqrt_f(x) * math.cos(x), 0.0, math.pi, **options)[0]
        j1 = 2.0 / math.pi * quad(lambda x: sqrt_f(x) * math.sin(x) ** 2, 0.0, math.pi, **options)[0]
    return j0, jc1, j1


def _max_error(values: np.ndarray, reference: np.ndarray) -> float:
    scale = np.where(reference == 0.0, 1.0, np.abs(reference))
    return float(np.max(np.abs(values - reference) / scale))


def machine_description() -> str:
    """One line naming the CPU, the core count and the Python and numpy versions (for benchmark tables)."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            cpu = next(line.split(":", 1)[1].strip() for line in fh if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return f"{cpu}, {os.cpu_count()} logical cores, Python {platform.python_version()}, numpy {np.__version__}"


def benchmark_j_integrals(
    reference: Reference,
    exponents: Sequence[float] = (0.05, 0.531, 4.0),
    error_Abar: Sequence[float] = (0.0, 1e-12, 1e-3, 0.3, 1.0, 3.0, 30.0, 1e3, 1e5, 1e7, 1e10),
    throughput_size: int = 200_000,
    quad_size: int = 60,
) -> pd.DataFrame:
    """Table of throughput and maximal error of both methods (one row per method and n)."""
    rows = []
    error_points = np.asarray(error_Abar, dtype=float)
    timing_abar = np.logspace(-3, 10, throughput_size)
    quad_abar = np.logspace(-3, 10, quad_size)
    for n in exponents:
        ref = np.array([[float(v) for v in reference(float(a), n)] for a in error_points])
        fast = np.stack(j_integrals(error_points, n), axis=1)
        slow = np.array([j_integrals_quad(float(a), n) for a in error_points])
        start = time.perf_counter()
        j_integrals(timing_abar, n)
        fast_rate = throughput_size / (time.perf_counter() - start)
        start = time.perf_counter()
        for a in quad_abar:
            j_integrals_quad(float(a), n)
        quad_rate = quad_size / (time.perf_counter() - start)
        rows.append({"method": "fixed rule (198 nodes)", "n": n, "evaluations_per_s": fast_rate,
                     "max_relative_error": _max_error(fast, ref), "speedup_vs_quad": fast_rate / quad_rate})
        rows.append({"method": "scipy quad (epsrel 1e-12)", "n": n, "evaluations_per_s": quad_rate,
                     "max_relative_error": _max_error(slow, ref), "speedup_vs_quad": 1.0})
    return pd.DataFrame(rows)


def format_table(table: pd.DataFrame) -> str:
    """Plain-text table for the terminal and the log."""
    lines = [f"J-integral benchmark on {machine_description()}", "",
             f"{'method':<28}{'n':>7}{'evals/s':>14}{'max rel err':>14}{'speed-up':>11}"]
    for row in table.itertuples():
        lines.append(f"{row.method:<28}{row.n:>7g}{row.evaluations_per_s:>14.4g}{row.max_relative_error:>14.2e}{row.speedup_vs_quad:>11.0f}")
    return "\n".join(lines) + "\n"
