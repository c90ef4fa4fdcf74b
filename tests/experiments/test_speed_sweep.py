"""The speed sweep (vibroadhesion.experiments.speed_sweep): its rows and the 1 % / 5 % quasi-static speed limits.

References: the limits of a deviation that is a known power of V (the crossing solved in closed form), and the
rows against the withdrawal and the quasi-static family they are built from (both tested in
tests/simulation/test_withdrawal.py).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from conftest import CHI0, N_PUBLISHED, RADIUS, V0

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import omega_check
from vibroadhesion.experiments import speed_sweep


def _table(speeds: np.ndarray, deviation: np.ndarray) -> pd.DataFrame:
    return pd.DataFrame({"fixation": "rigid", "frequency_hz": 200.0, "h1_um": 20.0, "V_over_v0": speeds,
                         "relative_deviation": deviation})


def test_limits_of_a_power_law_deviation_are_its_crossings() -> None:
    speeds = np.array([0.01, 0.03, 0.1, 0.3, 1.0, 3.0])
    c = 0.2  # deviation = c V: within tol below V = tol/c, exactly, since log-log interpolation is exact for a power
    limits = speed_sweep.quasi_static_limits(_table(speeds, c * speeds)).iloc[0]
    assert limits["V_over_v0_within_1pct"] == pytest.approx(0.01 / c, rel=1e-12)
    assert limits["V_over_v0_within_5pct"] == pytest.approx(0.05 / c, rel=1e-12)


def test_limits_outside_the_simulated_speeds_are_nan_with_a_note() -> None:
    speeds = np.array([0.1, 1.0])
    too_far = speed_sweep.quasi_static_limits(_table(speeds, np.array([0.2, 0.5]))).iloc[0]
    assert math.isnan(too_far["V_over_v0_within_1pct"]) and "slowest" in too_far["note_1pct"]
    all_in = speed_sweep.quasi_static_limits(_table(speeds, np.array([1e-4, 2e-3]))).iloc[0]
    assert math.isnan(all_in["V_over_v0_within_5pct"]) and "fastest" in all_in["note_5pct"]


def test_rows_of_the_200hz_test() -> None:
    omega = float(omega_check(200.0, V0, RADIUS))
    problems = speed_sweep.rig_problems(CHI0, N_PUBLISHED, omega, RADIUS, [20.0], Fixation.rigid())
    table = speed_sweep.sweep_table(problems, [0.3, 100.0], fixation_name="rigid", frequency_hz=200.0,
                                    v0_um_s=V0 * 1e6)
    assert list(table.columns) == speed_sweep.COLUMNS and (table["source"] == "simulated").all()
    slow, fast = table.iloc[0], table.iloc[1]
    assert slow["status"] == "pulloff" and fast["status"] == "detached_before_mean_extremum"
    assert slow["V_um_s"] == pytest.approx(0.3 * V0 * 1e6, rel=1e-15)
    assert slow["relative_deviation"] == pytest.approx(slow["mean_pulloff_ratio"] / slow["quasi_static_ratio"] - 1)
    # measured with the withdrawal's O(V) approach (test_withdrawal.py): 3.7 % at V = 0.3 v0, pulling harder
    assert 0.0 < slow["relative_deviation"] < 0.05
    assert slow["peak_pulloff_ratio"] > slow["mean_pulloff_ratio"] > 0.0
