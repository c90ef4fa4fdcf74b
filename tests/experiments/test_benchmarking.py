"""The side-by-side comparison of J-integral rules (vibroadhesion.experiments.benchmarking)."""

from __future__ import annotations

import numpy as np
from mpmath_reference import j_integrals_mp

from vibroadhesion.core.integrals import Triple, j_integrals
from vibroadhesion.experiments.benchmarking import compare_j_integrals, format_comparison


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
