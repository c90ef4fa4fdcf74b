"""Benchmark: the fit's cost against the number of rows and of distinct (frequency, amplitude) pairs.

Usage: python benchmarks/fit_scaling.py [LEVEL ...]   (default: every level of role ``fit``)

Two synthetic row sets (labelled synthetic, never measurements; from the exact-averaging level at the published
parameters with 1 % scatter, numpy default_rng seeds fixed): 10,000 rows on the rig's 15 pairs (200/300/400 Hz x
20..100 um), and 200 rows with continuous amplitudes (uniform 10-100 um, 3 frequencies: 200 pairs). Prints, per
level and set, the status, the wall time of ``fit_gent_schultz`` (one run: a fit is minutes at most) and the machine.
"""

import os
import sys
import time

import numpy as np
import pandas as pd

from vibroadhesion.core.levels import names
from vibroadhesion.experiments.benchmarking import machine_description
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters, predict_pulloff, pulloff_mN

RADIUS = 51.5e-3
REDUCED_MODULUS = 2 * 2.8e6 / (1 - 0.5**2)  # data/setup.yaml: E* = f_storage E/(1 - nu^2)
PUBLISHED = GentSchultzParameters(0.236, 0.531, 44.5e-6)


def synthetic_rows(frequency_hz: np.ndarray, h1_um: np.ndarray, rng: np.random.Generator) -> pd.DataFrame:
    """Rows of the exact-averaging pull-off at the published parameters times (1 + 0.01 z)."""
    record = predict_pulloff("exact_averaging", PUBLISHED, np.nan, h1_um, radius=RADIUS,
                             reduced_modulus=REDUCED_MODULUS)
    force = pulloff_mN(record, PUBLISHED.w0, RADIUS) * (1 + 0.01 * rng.standard_normal(len(h1_um)))
    return pd.DataFrame({"frequency_hz": frequency_hz, "h1_um": h1_um, "pulloff_mN": force,
                         "source": "synthetic", "line": np.arange(len(h1_um))})


def row_sets() -> dict[str, pd.DataFrame]:
    """The two sets of the module docstring."""
    pairs = np.array([(f, h) for f in (200.0, 300.0, 400.0) for h in (20.0, 40.0, 60.0, 80.0, 100.0)])
    many = pairs[np.random.default_rng(2).integers(0, len(pairs), 10_000)]
    rng = np.random.default_rng(1)
    continuous = (rng.choice([200.0, 300.0, 400.0], 200), np.round(rng.uniform(10.0, 100.0, 200), 3))
    return {"10,000 rows, 15 pairs": synthetic_rows(many[:, 0], many[:, 1], np.random.default_rng(0)),
            "200 rows, 200 pairs": synthetic_rows(*continuous, np.random.default_rng(0))}


def main(levels: list[str]) -> None:
    print(f"machine: {machine_description()}; load average {os.getloadavg()[0]:.1f} at start")
    print(f"{'rows':<22}  {'level':<30}  {'status':<16}  {'wall_s':>7}")
    for label, rows in row_sets().items():
        for level in levels:
            start = time.perf_counter()
            summary = fit_gent_schultz(rows, level, PUBLISHED, radius=RADIUS, reduced_modulus=REDUCED_MODULUS)
            print(f"{label:<22}  {level:<30}  {summary['status']:<16}  {time.perf_counter() - start:7.1f}", flush=True)
    print(f"load average {os.getloadavg()[0]:.1f} at the end")


if __name__ == "__main__":
    main(sys.argv[1:] or names("fit"))
