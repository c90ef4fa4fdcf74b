"""Benchmarks (vibroadhesion.experiments.benchmarking): timings repeated in turn, the load stated, J-integral rules."""

from __future__ import annotations

import os
import time
from functools import partial

import numpy as np
import pytest
from mpmath_reference import j_integrals_mp

from vibroadhesion.core.integrals import Triple, j_integrals
from vibroadhesion.experiments.benchmarking import (
    benchmark_j_integrals,
    compare_j_integrals,
    format_comparison,
    format_table,
    load_average,
    load_note,
    timed_in_turn,
)


def _biased(Abar: np.ndarray, n: float) -> Triple:
    """j_integrals times (1 + 1e-6): a rule whose error is 1e-6 relative to within j_integrals' 1e-13 (2e-13)."""
    j0, jc1, j1 = j_integrals(Abar, n)
    return j0 * (1 + 1e-6), jc1 * (1 + 1e-6), j1 * (1 + 1e-6)


def test_compare_reports_each_rule_with_its_error_and_ratios_to_the_first() -> None:
    """Reference: 30-digit mpmath; j_integrals is within its stated 1e-13, the biased rule at 1e-6 to
    within that; the first rule's speed-ups are 1 by definition, every rate is positive and finite.
    """
    table = compare_j_integrals({"rule": j_integrals, "biased": _biased}, j_integrals_mp, exponents=(0.531,),
                                error_Abar=(0.3, 30.0), size=2000, repeats=3)
    assert list(table["rule"]) == ["rule", "biased"]
    first, biased = table.iloc[0], table.iloc[1]
    assert first["speedup_min"] == 1.0 and first["speedup_median"] == 1.0
    assert first["max_relative_error"] < 1e-13
    assert abs(biased["max_relative_error"] - 1e-6) < 2e-13
    rates = table[["evaluations_per_s_min_time", "evaluations_per_s_median_time"]].to_numpy()
    assert np.all(np.isfinite(rates)) and np.all(rates > 0)
    assert np.all(table["evaluations_per_s_min_time"] >= table["evaluations_per_s_median_time"])
    assert "biased" in format_comparison(table, 3)


def test_calls_are_timed_in_turn_repeat_after_repeat() -> None:
    """The order of the runs is a, b, a, b, a, b; each time is at least the call's sleep (a lower bound)."""
    order: list[str] = []
    calls = {label: partial(_sleep_and_note, order, label, pause) for label, pause in (("a", 0.002), ("b", 0.004))}
    seconds = timed_in_turn(calls, 3)
    assert order == ["a", "b"] * 3
    assert [len(seconds["a"]), len(seconds["b"])] == [3, 3]
    assert min(seconds["a"]) >= 0.002 and min(seconds["b"]) >= 0.004


def _sleep_and_note(order: list[str], label: str, pause: float) -> None:
    order.append(label)
    time.sleep(pause)


def test_load_is_stated_with_the_three_averages_and_the_cores(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(os, "getloadavg", lambda: (6.884, 3.99, 2.2))
    monkeypatch.setattr(os, "cpu_count", lambda: 2)
    stated = "load average 6.88 (1 min), 3.99 (5 min), 2.20 (15 min) on 2 logical cores"
    assert load_average() == stated
    assert load_note("before") == f"machine load before the timings: before\nmachine load after the timings:  {stated}"


def test_j_integral_benchmark_gives_min_and_median_throughput_and_the_error_against_mpmath() -> None:
    """Reference: 30-digit mpmath. The fixed rule within its stated 1e-13, quad within its epsrel 1e-12 (x10 for
    the sum of three integrals' roundings); quad's speed-ups over itself are 1; the minimum time gives the higher rate."""
    table = benchmark_j_integrals(j_integrals_mp, exponents=(0.531,), error_Abar=(0.3, 30.0), throughput_size=2000,
                                  quad_size=3, repeats=3)
    assert list(table["method"].str.split().str[0]) == ["fixed", "scipy"]
    fixed, quad = table.iloc[0], table.iloc[1]
    assert fixed["max_relative_error"] < 1e-13 and quad["max_relative_error"] < 1e-11
    assert quad["speedup_vs_quad_min"] == 1.0 and quad["speedup_vs_quad_median"] == 1.0
    assert np.all(table["evaluations_per_s_min_time"] >= table["evaluations_per_s_median_time"])
    assert "repeats in turn" in format_table(table, 3, load_note("x"))
