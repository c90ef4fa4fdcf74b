"""Benchmark: the full model as a fit level (vibroadhesion.experiments.simulation_fit).

Usage: python benchmarks/simulation_fit.py [--fit] [OUT_TXT]

1. Derivatives of the simulated pull-off, d ln P_cr / d ln theta for w0, n, v0 at the published parameters:
   the envelope theorem (two warm orbits per parameter at the fixed pull-off offset) against central
   differences of re-traced families (the sensitivity rule's way), step 1e-3 in ln theta. Per (f, h1):
   the time of each (min and median of 5 repeats, wall), their ratio, and the largest difference.
2. With ``--fit``: the issue-13 target, the fit of the 15 simulated rigid rows (200/300/400 Hz x 20..100 um,
   published parameters, noise-free) from w0 +50 %, n -40 %: wall time, families traced, recovered errors.
"""

import math
import statistics
import sys
import time
from dataclasses import replace

import numpy as np
import pandas as pd

from vibroadhesion.experiments.benchmarking import machine_description
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.experiments.simulation_fit import envelope_log_derivatives, jkr_mN, pulloff_problem
from vibroadhesion.experiments.virtual_pulloff import simulated_pulloff, traced_pulloff

RADIUS = 51.5e-3
REDUCED_MODULUS = 2 * 2.8e6 / (1 - 0.5**2)  # data/setup.yaml: E* = f_storage E/(1 - nu^2)
GEOMETRY = {"radius": RADIUS, "reduced_modulus": REDUCED_MODULUS}
PUBLISHED = GentSchultzParameters(0.236, 0.531, 44.5e-6)
NAMES = ("w0", "n", "v0")
STEP = 1e-3
REPEATS = 5


def simulated_mN(params, frequency_hz, h1_um):
    """|P_cr| in mN of the virtual pull-off (rigid fixation)."""
    record = simulated_pulloff(pulloff_problem(params, frequency_hz, h1_um, **GEOMETRY))
    return float(record.pulloff_ratio) * jkr_mN(params.w0, RADIUS)


def family_derivatives(frequency_hz, h1_um):
    """d ln P_cr / d ln theta by central differences of re-traced families."""
    values = []
    for name in NAMES:
        plus, minus = (simulated_mN(replace(PUBLISHED, **{name: getattr(PUBLISHED, name) * math.exp(s * STEP)}),
                                    frequency_hz, h1_um) for s in (1, -1))
        values.append(math.log(plus / minus) / (2 * STEP))
    return np.array(values)


def timed(function):
    """Result, min and median wall time of REPEATS calls."""
    times, result = [], None
    for _ in range(REPEATS):
        began = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - began)
    return result, min(times), statistics.median(times)


def derivative_table():
    """Part 1 of the module docstring."""
    rows = []
    for frequency_hz, h1_um in ((200.0, 20.0), (200.0, 100.0), (400.0, 100.0)):
        at = traced_pulloff(pulloff_problem(PUBLISHED, frequency_hz, h1_um, **GEOMETRY))[1]
        envelope, env_min, env_med = timed(lambda f=frequency_hz, h=h1_um, a=at: envelope_log_derivatives(
            PUBLISHED, f, h, a, NAMES, **GEOMETRY, step=STEP))
        families, fam_min, fam_med = timed(lambda f=frequency_hz, h=h1_um: family_derivatives(f, h))
        rows.append({"frequency_hz": frequency_hz, "h1_um": h1_um, "envelope_s_min": env_min,
                     "envelope_s_median": env_med, "families_s_min": fam_min, "families_s_median": fam_med,
                     "speedup_min": fam_min / env_min, "speedup_median": fam_med / env_med,
                     "max_abs_difference": float(np.max(np.abs(envelope - families)))})
    return pd.DataFrame(rows)


def target_fit():
    """Part 2 of the module docstring."""
    pairs = [(f, h) for f in (200.0, 300.0, 400.0) for h in (20.0, 40.0, 60.0, 80.0, 100.0)]
    rows = pd.DataFrame({"frequency_hz": [f for f, _ in pairs], "h1_um": [h for _, h in pairs],
                         "pulloff_mN": [simulated_mN(PUBLISHED, f, h) for f, h in pairs], "source": "simulated",
                         "line": np.arange(2, 17)})
    start = replace(PUBLISHED, w0=1.5 * PUBLISHED.w0, n=0.6 * PUBLISHED.n)
    began = time.perf_counter()
    summary = fit_gent_schultz(rows, "simulation", start, **GEOMETRY)
    wall = time.perf_counter() - began
    estimate = {name: summary["parameters"][name]["estimate"] for name in NAMES}
    return pd.DataFrame([{"status": summary["status"], "wall_s": wall, "families": summary["families_traced"],
                          "free": ",".join(summary["free_parameters"]),
                          **{f"{name}_relative_error": estimate[name] / getattr(PUBLISHED, name) - 1
                             for name in NAMES}}])


def main(argv):
    """Print (and with OUT_TXT write) the tables."""
    out = [a for a in argv if not a.startswith("--")]
    text = [machine_description(), "", "d ln P_cr / d ln theta: envelope theorem against re-traced families "
            f"(step {STEP}, {REPEATS} repeats, wall s)", derivative_table().to_string(index=False)]
    if "--fit" in argv:
        text += ["", "full-model fit of the 15 simulated rigid rows from w0 +50 %, n -40 %",
                 target_fit().to_string(index=False)]
    report = "\n".join(text)
    print(report)
    if out:
        with open(out[0], "w") as handle:
            handle.write(report + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
