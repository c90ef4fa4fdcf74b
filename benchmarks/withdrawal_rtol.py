"""Benchmark: the integration tolerances of the withdrawal sweep (speed_sweep.SWEEP_RTOL, slow_flow.SLOW_FLOW_RTOL).

Usage: python benchmarks/withdrawal_rtol.py [RESULTS_DIR]   (default results; needs a finished `validation` there)

Every withdrawal the sweep ran (status other than skipped_within_tolerance in RESULTS_DIR/withdrawal/) of the
compliant fixation at 200 and 400 Hz and the rigid one at 400 Hz, every amplitude, from the sweep's start state, at
rtol 1e-9, 1e-8 and 1e-7 against rtol 1e-12: the process CPU time of all of them per rtol and the largest relative
difference of the pull-off (peak and period-mean force over |P_JKR|), and whether every status is the reference's.
Then the same for the averaged slow flow (rigid, every amplitude and every V/v0 of config
withdrawal.slow_flow_speed_ratios) at rtol 1e-8, 3e-8 and 1e-7 against rtol 1e-10.
"""

import sys
import time

import pandas as pd

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.experiments import speed_sweep
from vibroadhesion.models.slow_flow import withdraw_slowly
from vibroadhesion.pipeline.steps.inputs import experiment_omega_check, rig, setup_fixations
from vibroadhesion.simulation import steady_state
from vibroadhesion.simulation.withdrawal import withdraw

RTOLS = (1e-9, 1e-8, 1e-7)
REFERENCE = 1e-12
TESTS = (("compliant", 200.0), ("compliant", 400.0), ("rigid", 400.0))
SLOW_RTOLS = (1e-8, 3e-8, 1e-7)
SLOW_REFERENCE = 1e-10
SLOW_SPEEDS = (0.001, 0.01, 0.1, 0.3, 1.0)  # workflow/config.yaml withdrawal.slow_flow_speed_ratios


def runs(results):
    """(start problem, start state, V/v0) of every withdrawal of TESTS that the sweep in ``results`` ran."""
    setup, params, chi0 = rig(f"{results}/data/setup.json")
    sweep = pd.read_csv(f"{results}/withdrawal/speed_sweep.csv")
    for fixation, frequency in TESTS:
        (case,) = setup_fixations(setup, params["v0"], fixation)
        omega_check = experiment_omega_check(setup, params["v0"])[frequency]
        ran = sweep[(sweep["fixation"] == fixation) & (sweep["frequency_hz"] == frequency)
                    & (sweep["method"] == "time_domain") & (sweep["status"] != speed_sweep.SKIPPED)]
        for h1, problem in speed_sweep.rig_problems(chi0, params["n"], omega_check, setup.radius,
                                                    setup.amplitudes_um, case):
            start = speed_sweep.start_problem(problem)
            state = steady_state(start).orbit.start_state
            for ratio in ran.loc[ran["h1_um"] == h1, "V_over_v0"]:
                yield start, state, float(ratio)


def slow_runs(results):
    """(start problem, V/v0) of every slow flow of the rig (rigid, the frequency does not enter: module docstring)."""
    setup, params, chi0 = rig(f"{results}/data/setup.json")
    omega_check = experiment_omega_check(setup, params["v0"])[setup.frequencies_hz[0]]
    for _, problem in speed_sweep.rig_problems(chi0, params["n"], omega_check, setup.radius, setup.amplitudes_um,
                                               Fixation.rigid()):
        for ratio in SLOW_SPEEDS:
            yield speed_sweep.start_problem(problem), ratio


def compare(label, cases, run, reference, rtols):
    """Print CPU seconds per rtol over ``cases`` and the largest relative difference of the pull-off from ``reference``."""
    cpu = dict.fromkeys((reference, *rtols), 0.0)
    error, same_status, count = dict.fromkeys(rtols, 0.0), dict.fromkeys(rtols, True), 0
    for case in cases:
        out = {}
        for rtol in (reference, *rtols):
            begin = time.process_time()
            out[rtol] = run(*case, rtol)
            cpu[rtol] += time.process_time() - begin
        ref, count = out[reference], count + 1
        for rtol in rtols:
            error[rtol] = max(error[rtol], abs(out[rtol].force / ref.force - 1),
                              abs(out[rtol].mean_force / ref.mean_force - 1))
            same_status[rtol] &= out[rtol].status == ref.status
    print(f"{label}: {count} runs, against rtol {reference:g}")
    print(f"{'rtol':>8}{'CPU s':>9}{'max rel. diff.':>16}{'statuses':>10}")
    print(f"{reference:>8.0e}{cpu[reference]:>9.2f}")
    for rtol in rtols:
        print(f"{rtol:>8.0e}{cpu[rtol]:>9.2f}{error[rtol]:>16.2e}{'same' if same_status[rtol] else 'differ':>10}")
    print()


def _withdraw(start, state, ratio, rtol):
    return withdraw(start, ratio, initial_state=state, rtol=rtol)


def _withdraw_slowly(start, ratio, rtol):
    return withdraw_slowly(start, ratio, rtol=rtol)


def main(results):
    compare(f"time domain ({', '.join(f'{f} {h:g} Hz' for f, h in TESTS)})", runs(results), _withdraw, REFERENCE,
            RTOLS)
    compare("slow flow (rigid)", slow_runs(results), _withdraw_slowly, SLOW_REFERENCE, SLOW_RTOLS)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "results")
