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


def _table(speeds: np.ndarray, deviation: np.ndarray, method: str = "time_domain") -> pd.DataFrame:
    return pd.DataFrame({"fixation": "rigid", "frequency_hz": 200.0, "h1_um": 20.0, "V_over_v0": speeds,
                         "relative_deviation": deviation, "method": method,
                         "source": "simulated" if method == "time_domain" else "averaged"})


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


def test_limits_take_the_time_domain_where_both_ran_and_name_the_methods() -> None:
    c = 0.2
    slow = _table(np.array([0.001, 0.01, 0.1]), c * np.array([0.001, 0.01, 0.1]), "slow_flow")
    # the time domain at 0.1 differs (0.03 instead of 0.02): where both ran, its row is the one used
    timed = _table(np.array([0.1, 1.0]), np.array([0.03, 0.3]))
    limits = speed_sweep.quasi_static_limits(pd.concat([slow, timed], ignore_index=True)).iloc[0]
    # 1 %: between 0.01 (slow flow, 2e-3) and 0.1 (time domain, 0.03), log-log interpolated
    assert limits["method_1pct"] == "slow_flow/time_domain"
    crossing = 0.01 * 10 ** (math.log(0.01 / 2e-3) / math.log(0.03 / 2e-3))
    assert limits["V_over_v0_within_1pct"] == pytest.approx(crossing, rel=1e-12)
    assert limits["method_5pct"] == "time_domain"  # between 0.1 (0.03) and 1 (0.3): both time domain
    assert limits["V_over_v0_within_5pct"] == pytest.approx(0.1 * 10 ** (math.log(0.05 / 0.03) / math.log(10)),
                                                            rel=1e-12)
    assert limits["source"] == "averaged/simulated"


def test_slow_flow_placed_at_a_frequency() -> None:
    slow = pd.DataFrame({"h1_um": [20.0, 20.0], "V_over_v0": [0.1, 1.0], "slow_time_pulloff": [0.25, 0.03],
                         "slow_time_detached": [0.5, math.nan]})
    placed = speed_sweep.at_frequency(slow, 1e6, 0.02, fixation_name="rigid", frequency_hz=200.0)
    assert list(placed.columns) == speed_sweep.COLUMNS
    assert (placed["method"] == "slow_flow").all() and (placed["source"] == "averaged").all()
    # tau = omega_check c_o T (Eqs. 86, 105); periods up to detachment (else to the pull-off), rounded up
    assert placed["tau_pulloff"].tolist() == pytest.approx([0.25 * 2e4, 0.03 * 2e4], rel=1e-15)
    assert placed["periods"].tolist() == [math.ceil(0.5 * 2e4 / (2 * math.pi)), math.ceil(0.03 * 2e4 / (2 * math.pi))]


def test_quasi_static_ratios_read_the_simulated_family() -> None:
    table = pd.DataFrame({"model": ["simulation", "simulation", "exact_averaging", "simulation"],
                          "frequency_hz": [200.0, 200.0, 200.0, 300.0], "h1_um": [20.0, 40.0, 20.0, 20.0],
                          "status": ["pulloff", "contact_loss_before_extremum", "ok", "pulloff"],
                          "pulloff_ratio": [3.0, math.nan, 2.0, 3.5]})
    ratios = speed_sweep.quasi_static_ratios(table, 200.0)
    assert ratios[20.0] == 3.0 and math.isnan(ratios[40.0]) and len(ratios) == 2


def test_rows_of_the_200hz_test() -> None:
    from vibroadhesion.experiments.virtual_pulloff import simulated_pulloff

    omega = float(omega_check(200.0, V0, RADIUS))
    problems = speed_sweep.rig_problems(CHI0, N_PUBLISHED, omega, RADIUS, [20.0], Fixation.rigid())
    family = float(simulated_pulloff(problems[0][1]).pulloff_ratio)
    table = speed_sweep.sweep_table(problems, [0.3, 100.0], fixation_name="rigid", frequency_hz=200.0,
                                    v0_um_s=V0 * 1e6, quasi_static={20.0: family})
    assert list(table.columns) == speed_sweep.COLUMNS and (table["source"] == "simulated").all()
    slow, fast = table.iloc[0], table.iloc[1]
    assert slow["status"] == "pulloff" and fast["status"] == "detached_before_mean_extremum"
    assert slow["V_um_s"] == pytest.approx(0.3 * V0 * 1e6, rel=1e-15)
    assert slow["relative_deviation"] == pytest.approx(slow["mean_pulloff_ratio"] / slow["quasi_static_ratio"] - 1)
    # measured with the withdrawal's O(V) approach (test_withdrawal.py): 3.7 % at V = 0.3 v0, pulling harder
    assert 0.0 < slow["relative_deviation"] < 0.05
    assert slow["peak_pulloff_ratio"] > slow["mean_pulloff_ratio"] > 0.0


def test_stopping_rule_skips_only_speeds_below_the_first_within_tolerance_and_keeps_the_limits() -> None:
    """200 Hz, 40 um, rigid at 3, 1, 0.3 v0: deviations 1.9 %, 0.57 %, 0.17 % (the full sweep): stopping within 1 %
    the sweep ends at 1 v0, 0.3 v0 is skipped, the rows run are the full sweep's bit for bit (the same integration),
    and the 1 % and 5 % limits are those of the full sweep."""
    from vibroadhesion.experiments.virtual_pulloff import simulated_pulloff

    omega = float(omega_check(200.0, V0, RADIUS))
    problems = speed_sweep.rig_problems(CHI0, N_PUBLISHED, omega, RADIUS, [40.0], Fixation.rigid())
    family = {40.0: float(simulated_pulloff(problems[0][1]).pulloff_ratio)}
    speeds = [0.3, 1.0, 3.0]
    kwargs = {"fixation_name": "rigid", "frequency_hz": 200.0, "v0_um_s": V0 * 1e6, "quasi_static": family}
    full = speed_sweep.sweep_table(problems, speeds, **kwargs)
    stopped = speed_sweep.sweep_table(problems, speeds, stop=speed_sweep.StopRule(0.01), **kwargs)
    assert full["V_over_v0"].tolist() == stopped["V_over_v0"].tolist() == speeds
    assert (full["status"] == "pulloff").all()
    assert 0.01 < full["relative_deviation"].iloc[2] < 0.05 and abs(full["relative_deviation"].iloc[1]) <= 0.01
    assert stopped["status"].tolist() == [speed_sweep.SKIPPED, "pulloff", "pulloff"]
    assert stopped.iloc[0][["mean_pulloff_ratio", "peak_pulloff_ratio", "periods"]].isna().all()
    pd.testing.assert_frame_equal(stopped.iloc[1:], full.iloc[1:])
    pd.testing.assert_frame_equal(speed_sweep.quasi_static_limits(stopped), speed_sweep.quasi_static_limits(full))


def test_stop_rule_from_the_config_and_its_not_above_limit() -> None:
    """config withdrawal.stop: within null runs every speed, not_above null sets no limit. At 200 Hz, 40 um, rigid,
    3 v0 (1.9 %) and 1 v0 (0.57 %): with not_above = 0.5 the rule cannot stop at 1 v0, so 0.3 v0 runs too."""
    assert speed_sweep.StopRule.from_config({"within": None, "not_above": 1.0}) is None
    assert speed_sweep.StopRule.from_config({"within": 0.01, "not_above": None}) == speed_sweep.StopRule(0.01, math.inf)
    assert speed_sweep.StopRule.from_config({"within": 0.01, "not_above": 1}) == speed_sweep.StopRule(0.01, 1.0)
    omega = float(omega_check(200.0, V0, RADIUS))
    problems = speed_sweep.rig_problems(CHI0, N_PUBLISHED, omega, RADIUS, [40.0], Fixation.rigid())
    table = speed_sweep.sweep_table(problems, [0.3, 1.0, 3.0], fixation_name="rigid", frequency_hz=200.0,
                                    v0_um_s=V0 * 1e6, quasi_static={40.0: 7.435},
                                    stop=speed_sweep.StopRule(0.01, not_above=0.5))
    assert (table["status"] == "pulloff").all()
