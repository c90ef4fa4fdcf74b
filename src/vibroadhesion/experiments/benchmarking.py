"""Speed against error of the J-integral evaluation (issue: "every method reports its speed against its error").

Two methods are measured on the same machine in one run:

* ``fixed rule``: :func:`vibroadhesion.core.integrals.j_integrals`, vectorised;
* ``scipy quad``: :func:`scipy.integrate.quad` on Eqs. (28), (29), (36) over (0, pi) with
  ``points=[pi/2]`` and ``epsrel=1e-12``, one Abar at a time (three integrals per Abar).

Throughput is the number of Abar values for which all three integrals are returned per
second, from the minimum and from the median wall time of repeated runs, the methods in turn
(:func:`timed_in_turn`); the error is the largest relative error (absolute where the reference is
0) of any of the three against a high-precision reference passed in by the caller. The machine is
shared: every benchmark states its load (:func:`load_average`) before and after its timings.

:func:`compare_j_integrals` times two or more versions of the rule (e.g. this checkout's and
the one a change starts from) in turn, repeat after repeat, so that the machine's load hits
them alike, and gives the minimum and median of each and their ratios to the first.
"""

from __future__ import annotations

import math
import os
import platform
import statistics
import time
import warnings
from collections.abc import Callable, Mapping, Sequence
from functools import partial

import numpy as np
import pandas as pd
from scipy.integrate import IntegrationWarning, quad

from vibroadhesion.core.integrals import Triple, folded_rule, j_integrals
from vibroadhesion.core.ratelaw import GentSchultz

Reference = Callable[[float, float], Sequence[float]]
#: A version of :func:`vibroadhesion.core.integrals.j_integrals`: (Abar array, n) -> (J0, Jc1, J1).
Rule = Callable[[np.ndarray, float], Triple]


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


def load_average() -> str:
    """The machine's load: its 1, 5 and 15 min load averages (runnable processes) against its logical cores."""
    one, five, fifteen = os.getloadavg()
    return (f"load average {one:.2f} (1 min), {five:.2f} (5 min), {fifteen:.2f} (15 min) on {os.cpu_count()} "
            "logical cores")


def load_note(before: str) -> str:
    """Two lines: the load before the timings (``before``, a :func:`load_average` taken then) and now, after them."""
    return f"machine load before the timings: {before}\nmachine load after the timings:  {load_average()}"


def timed_in_turn(calls: Mapping[str, Callable[[], object]], repeats: int) -> dict[str, list[float]]:
    """Wall seconds of ``repeats`` runs of each of ``calls``, the calls in turn repeat after repeat.

    On a loaded machine one timing says little: in turn, a change of load hits every call alike, and the minimum
    (the run least disturbed) and the median of the repeats say how fast and how fast typically.
    """
    seconds: dict[str, list[float]] = {label: [] for label in calls}
    for _ in range(repeats):
        for label, call in calls.items():
            start = time.perf_counter()
            call()
            seconds[label].append(time.perf_counter() - start)
    return seconds


def _quad_all(Abar: np.ndarray, n: float) -> None:
    """:func:`j_integrals_quad` at each of ``Abar`` (the baseline's throughput run)."""
    for a in Abar:
        j_integrals_quad(float(a), n)


def benchmark_j_integrals(
    reference: Reference,
    exponents: Sequence[float] = (0.05, 0.531, 4.0),
    error_Abar: Sequence[float] = (0.0, 1e-12, 1e-4, 0.3, 1.0, 2.0, 30.0, 1e3, 1e5, 1e8, 1e10),
    throughput_size: int = 50_000,
    quad_size: int = 14,
    repeats: int = 5,
) -> pd.DataFrame:
    """Throughput (minimum and median time of ``repeats``, in turn) and maximal error of both methods, per n.

    The speed-ups over quad are minimum over minimum and median over median. Both run over log-spaced Abar in
    [1e-3, 1e10]: ``quad_size`` = 14 is one point per decade, ``throughput_size`` keeps a repeat of the fixed rule
    near 30 ms, far above the timer's resolution (60 and 200,000 points took the rule benchmark_j_integrals
    16-18 CPU-s, these 10-11.5, the mpmath reference 6.8 of them; loaded machine). The error points are points of
    the tests' stored 30-digit references (tests/reference/j_integrals_mpmath.csv, for n = 0.05, 0.531, 4), so the
    reference costs a table lookup.
    """
    rows = []
    error_points = np.asarray(error_Abar, dtype=float)
    sizes = {"fixed": throughput_size, "quad": quad_size}
    for n in exponents:
        ref = np.array([[float(v) for v in reference(float(a), n)] for a in error_points])
        errors = {"fixed": _max_error(np.stack(j_integrals(error_points, n), axis=1), ref),
                  "quad": _max_error(np.array([j_integrals_quad(float(a), n) for a in error_points]), ref)}
        seconds = timed_in_turn({"fixed": partial(j_integrals, np.logspace(-3, 10, throughput_size), n),
                                 "quad": partial(_quad_all, np.logspace(-3, 10, quad_size), n)}, repeats)
        per_s = {k: (sizes[k] / min(t), sizes[k] / statistics.median(t)) for k, t in seconds.items()}
        for key, method in (("fixed", f"fixed rule ({len(folded_rule()[0])} nodes)"),
                            ("quad", "scipy quad (epsrel 1e-12)")):
            rows.append({"method": method, "n": n, "evaluations_per_s_min_time": per_s[key][0],
                         "evaluations_per_s_median_time": per_s[key][1], "max_relative_error": errors[key],
                         "speedup_vs_quad_min": per_s[key][0] / per_s["quad"][0],
                         "speedup_vs_quad_median": per_s[key][1] / per_s["quad"][1]})
    return pd.DataFrame(rows)


def compare_j_integrals(
    rules: Mapping[str, Rule],
    reference: Reference,
    exponents: Sequence[float] = (0.05, 0.531, 4.0),
    error_Abar: Sequence[float] = (1e-12, 1e-3, 0.3, 1.0, 3.0, 30.0, 114.27, 1e3, 1e5, 1e7, 1e10),
    size: int = 200_000,
    repeats: int = 7,
) -> pd.DataFrame:
    """Throughput (minimum and median time of ``repeats``) and maximal error of J-integral rules (Eqs. 28, 29, 36).

    The speed-ups are the first rule's time over each rule's (minimum over minimum, median over
    median).

    Per n and repeat every rule evaluates the same ``size`` log-spaced Abar in [1e-3, 1e10] once,
    the rules in turn (after one untimed call each); the error is taken against ``reference``
    at ``error_Abar`` (relative, absolute where the reference is 0).
    """
    timing_abar = np.logspace(-3, 10, size)
    error_points = np.asarray(error_Abar, dtype=float)
    rows = []
    for n in exponents:
        ref = np.array([[float(v) for v in reference(float(a), n)] for a in error_points])
        for rule in rules.values():
            rule(timing_abar[:1000], n)
        seconds = timed_in_turn({label: partial(rule, timing_abar, n) for label, rule in rules.items()}, repeats)
        first = next(iter(rules))
        for label, rule in rules.items():
            rows.append({"rule": label, "n": n, "evaluations_per_s_min_time": size / min(seconds[label]),
                         "evaluations_per_s_median_time": size / statistics.median(seconds[label]),
                         "max_relative_error": _max_error(np.stack(rule(error_points, n), axis=1), ref),
                         "speedup_min": min(seconds[first]) / min(seconds[label]),
                         "speedup_median": statistics.median(seconds[first]) / statistics.median(seconds[label])})
    return pd.DataFrame(rows)


def format_comparison(table: pd.DataFrame, repeats: int) -> str:
    """Plain-text table of :func:`compare_j_integrals`."""
    lines = [f"J-integral rules side by side on {machine_description()}, {repeats} repeats in turn", "",
             f"{'rule':<40}{'n':>7}{'evals/s, min t':>16}{'median t':>10}{'max rel err':>13}"
             f"{'speed-up min':>14}{'median':>8}"]
    for row in table.itertuples():
        lines.append(f"{row.rule:<40}{row.n:>7g}{row.evaluations_per_s_min_time:>16.4g}{row.evaluations_per_s_median_time:>10.4g}"
                     f"{row.max_relative_error:>13.2e}{row.speedup_min:>14.2f}{row.speedup_median:>8.2f}")
    return "\n".join(lines) + "\n"


def format_table(table: pd.DataFrame, repeats: int, load: str) -> str:
    """Plain-text table of :func:`benchmark_j_integrals` (``repeats`` per method, in turn) with the ``load`` line."""
    lines = [f"J-integral benchmark on {machine_description()}, {repeats} repeats in turn", load, "",
             f"{'method':<28}{'n':>7}{'evals/s, min t':>16}{'median t':>10}{'max rel err':>13}"
             f"{'speed-up min':>14}{'median':>8}"]
    for row in table.itertuples():
        lines.append(f"{row.method:<28}{row.n:>7g}{row.evaluations_per_s_min_time:>16.4g}"
                     f"{row.evaluations_per_s_median_time:>10.4g}{row.max_relative_error:>13.2e}"
                     f"{row.speedup_vs_quad_min:>14.0f}{row.speedup_vs_quad_median:>8.0f}")
    return "\n".join(lines) + "\n"
