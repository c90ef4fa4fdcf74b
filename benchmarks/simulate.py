"""Benchmark: periodic steady states of the full model by shooting (vibroadhesion.simulation).

Usage: python benchmarks/simulate.py [OUT_TXT]

For each case it prints
* the time per steady state (median of 3, process CPU time and wall time),
* the periods integrated by the shooting,
* the self-consistency error: the largest relative change of a_m, Abar, w_eff/w0 and Pm when
  rtol goes from the default 1e-12 to 1e-13,
* the cost of reaching the same state by brute-force integration from the static state: the
  measured time per transient period times the number of periods the transient needs to come
  within 1e-10 of the orbit, ln(1e-10)/ln|multiplier| (the slowest Floquet multiplier), and the
  speed-up of the shooting over it.
"""

import math
import statistics
import sys
import time

import numpy as np

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.benchmarking import machine_description
from vibroadhesion.simulation import steady_state, transient

CHI0, RADIUS, NU0 = 2.589e-2, 51.5e-3, 1.227e-5
FIELDS = ("abar_m", "Abar", "w_eff_ratio", "pm_over_abs_pjkr")
TRANSIENT_PERIODS = 5


def rigid(n, h1_um, omega_check):
    return Problem(GentSchultz(n), CHI0, h1_um * 1e-6 / RADIUS, omega_check)


def cases():
    for n in (0.531,):
        for h1 in (20.0, 60.0, 100.0):
            for omega_check in (1e4, 1e5, 1e6, 1e7, 1e8, 1e9):
                yield f"rigid n={n} h1={h1:g}um", rigid(n, h1, omega_check)
    for n, h1 in ((0.05, 5.0), (4.0, 20.0)):
        for omega_check in (1e4, 1e6, 1e8):
            yield f"rigid n={n} h1={h1:g}um", rigid(n, h1, omega_check)
    for kappa, zeta in ((0.01, 0.05), (0.1, 0.2)):
        for omega_bar in (1.0, 2.0, 17.85):
            yield (f"spring k={kappa} z={zeta}",
                   Problem(GentSchultz(0.531), CHI0, 20e-6 / RADIUS, omega_bar / NU0,
                           Fixation.compliant(kappa, zeta, NU0)))


def timed(function):
    cpu, wall, result = [], [], None
    for _ in range(3):
        c0, w0 = time.process_time(), time.perf_counter()
        result = function()
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
    return result, statistics.median(cpu), statistics.median(wall)


def row(label, problem):
    result, cpu, wall = timed(lambda: steady_state(problem))
    line = {"case": label, "omega_check": problem.omega_check, "status": str(result.status),
            "periods": result.orbit.iterations, "cpu_ms": 1e3 * cpu, "wall_ms": 1e3 * wall}
    if not result.ok:
        return line
    tight = steady_state(problem, rtol=1e-13)
    line["self_consistency"] = max(abs(float(getattr(tight, f) / getattr(result, f)) - 1) for f in FIELDS)
    slowest = float(np.max(np.abs(result.orbit.floquet_multipliers)))
    needed = math.inf if slowest >= 1 else max(1.0, math.log(1e-10) / math.log(max(slowest, 1e-300)))
    start = time.process_time()
    transient(problem, periods=TRANSIENT_PERIODS, initial_state=result.orbit.start_state)
    per_period = (time.process_time() - start) / TRANSIENT_PERIODS
    line.update(multiplier=slowest, transient_periods=needed, transient_s=needed * per_period,
                speedup=needed * per_period / cpu)
    return line


def format_rows(rows):
    header = (f"{'case':<26}{'omega_check':>12}{'status':>14}{'periods':>8}{'cpu ms':>9}{'wall ms':>9}"
              f"{'rtol 1e-13 diff':>16}{'|m|max':>11}{'transient periods':>18}{'transient s':>12}{'speed-up':>10}")
    lines = [f"Shooting benchmark on {machine_description()}", "", header]
    for r in rows:
        text = (f"{r['case']:<26}{r['omega_check']:>12.0e}{r['status']:>14}{r['periods']:>8}"
                f"{r['cpu_ms']:>9.1f}{r['wall_ms']:>9.1f}")
        if "self_consistency" in r:
            text += (f"{r['self_consistency']:>16.1e}{r['multiplier']:>11.6f}{r['transient_periods']:>18.3g}"
                     f"{r['transient_s']:>12.3g}{r['speedup']:>10.3g}")
        lines.append(text)
    cpu = [r["cpu_ms"] for r in rows if r["status"] == "ok" and r["case"].startswith("rigid n=0.531")]
    lines += ["", f"rigid n = 0.531, ok: median {statistics.median(cpu):.1f} ms, max {max(cpu):.1f} ms CPU "
              f"per steady state ({len(cpu)} cases)"]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    text = format_rows([row(*case) for case in cases()])
    print(text, end="")
    if len(sys.argv) > 1:
        with open(sys.argv[1], "w", encoding="utf-8") as fh:
            fh.write(text)
