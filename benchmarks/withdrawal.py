"""Benchmark: one dynamic pull-off at a finite withdrawal speed (vibroadhesion.simulation.withdrawal).

Usage: python benchmarks/withdrawal.py

For the issue's target case (200 Hz, h1 = 20 um, rigid, V = v0, published parameters) and two heavier ones
(400 Hz, 100 um, rigid; 200 Hz, 20 um, the simulated compliant fixation), it prints the wall time of the
steady state at the start (``simulation.steady_state``) and of the withdrawal (min and median of 5 repeats),
the periods and steps integrated, the pull-off (peak and period-mean load-cell force over |P_JKR|) and the
relative change of both when rtol goes from the default 1e-11 to 1e-13. The compiled kernel is warmed up
first (numba's on-disk cache; a cold process pays the compilation once).

Then the averaged slow flow (vibroadhesion.models.slow_flow, rigid only) against the time domain at the same V
(200 Hz, h1 = 20 um, rigid, V = 0.1, 0.3, 1 v0): time per pull-off (min and median of REPEATS; the time domain's
from its start state, which the slow flow does not need), periods (integrated, or spanned by the slow flow), the
period-mean pull-off over |P_JKR| and the slow flow's relative difference from the time domain.
"""

import math
import statistics
import time

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.benchmarking import machine_description
from vibroadhesion.experiments.speed_sweep import start_problem
from vibroadhesion.models.slow_flow import withdraw_slowly
from vibroadhesion.simulation import steady_state
from vibroadhesion.simulation.withdrawal import withdraw

CHI0, RADIUS, NU0, N = 2.589e-2, 51.5e-3, 1.227e-5, 0.531
OMEGA_200HZ = 1454310.3070550503  # omega_check of 200 Hz for v0 = 44.5 um/s, R = 51.5 mm (groups.omega_check)
REPEATS = 5
CASES = [("200 Hz, 20 um, rigid", 1.0, 20.0, Fixation.rigid()),
         ("400 Hz, 100 um, rigid", 2.0, 100.0, Fixation.rigid()),
         ("200 Hz, 20 um, compliant", 1.0, 20.0, Fixation.compliant(0.001, 0.01, NU0))]


def _timed(function, *args, **kwargs):
    """(min, median) wall seconds of REPEATS calls and the last result."""
    times = []
    for _ in range(REPEATS):
        start = time.perf_counter()
        result = function(*args, **kwargs)
        times.append(time.perf_counter() - start)
    return min(times), statistics.median(times), result


def main() -> None:
    print(machine_description())
    print(f"{'case (V = v0)':26} {'steady s min/med':>18} {'withdraw s min/med':>20} {'periods':>8} {'steps':>8} "
          f"{'peak P/PJKR':>12} {'mean P/PJKR':>12} {'rel. change 1e-13':>18}")
    for name, frequency_factor, h1, fixation in CASES:
        problem = start_problem(Problem(GentSchultz(N), CHI0, h1 * 1e-6 / RADIUS, OMEGA_200HZ * frequency_factor,
                                        fixation))
        steady_state(problem)  # warm-up (compilation cache)
        s_min, s_med, steady = _timed(steady_state, problem)
        start = steady.orbit.start_state
        w_min, w_med, run = _timed(withdraw, problem, 1.0, initial_state=start)
        tight = withdraw(problem, 1.0, initial_state=start, rtol=1e-13)
        change = max(abs(run.force / tight.force - 1), abs(run.mean_force / tight.mean_force - 1))
        print(f"{name:26} {s_min:8.3f}/{s_med:<9.3f} {w_min:9.3f}/{w_med:<10.3f} {run.periods:8d} {run.steps:8d} "
              f"{-run.force / 0.75:12.6g} {-run.mean_force / 0.75:12.6g} {change:18.2e}")
    slow_flow_against_time_domain()


SLOW_SPEEDS = (0.1, 0.3, 1.0)


def slow_flow_against_time_domain() -> None:
    """The table of the module docstring's second part."""
    problem = start_problem(Problem(GentSchultz(N), CHI0, 20e-6 / RADIUS, OMEGA_200HZ))
    start = steady_state(problem).orbit.start_state
    print("\nslow flow against time domain, 200 Hz, 20 um, rigid")
    print(f"{'V/v0':>6} {'method':>12} {'time s min/med':>18} {'periods':>8} {'mean P/PJKR':>12} {'difference':>11}")
    for speed in SLOW_SPEEDS:
        t_min, t_med, run = _timed(withdraw, problem, speed, initial_state=start, rtol=1e-9)
        s_min, s_med, slow = _timed(withdraw_slowly, problem, speed)
        spanned = math.ceil(slow.slow_time_detached * problem.omega_check * problem.c_o / (2 * math.pi))
        print(f"{speed:6g} {'time_domain':>12} {t_min:8.3f}/{t_med:<9.3f} {run.periods:8d} "
              f"{-run.mean_force / 0.75:12.6g} {'':>11}")
        print(f"{speed:6g} {'slow_flow':>12} {s_min:8.3f}/{s_med:<9.3f} {spanned:8d} "
              f"{-slow.mean_force / 0.75:12.6g} {slow.mean_force / run.mean_force - 1:11.2e}")


if __name__ == "__main__":
    main()
