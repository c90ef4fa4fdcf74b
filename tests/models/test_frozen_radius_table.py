"""The table of alpha*(beta) and Abar(beta) (vibroadhesion.models.frozen_radius_table) and the levels built on it.

Independent references:

* the direct solve of the drift condition (vibroadhesion.models.frozen_radius.frozen_radius_cycle), itself
  checked against 30-digit mpmath to 1e-13 (alpha*) and 1e-12 (Abar) in tests/models/test_exact_averaging.py;
* the levels of vibroadhesion.models.exact_averaging with the table switched off (every exponent outside
  its range), i.e. the direct path the levels took before the table;
* a closed form where alpha* = beta to double precision (n = 4, large beta).

Tolerances. The table's interpolation error, measured at 3000 random points over the whole table, is below
2.2e-12 relative for alpha* and Abar at n = 0.05 ... 4 (the degree-23 Chebyshev series per unit of ln beta;
degree 19 would give 8e-11 at n = 4): tested to 1e-11, the brief's aim for alpha*. The levels inherit it
through root searches and scans whose conditioning is O(1) (F' in [1, 4/3] for the nominal point contact,
a parabola vertex for the force minimum): measured 1.3e-11 at most (2.4e-11 on base_offset, a difference),
tested to 1e-9, the requirement that every answer be unchanged to 1e-9.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import C_O, CHI0, N_PUBLISHED

from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.models import frozen_radius_table
from vibroadhesion.models.exact_averaging import (
    mean_state,
    nominal_point_contact,
    pulloff_at_critical_radius,
    pulloff_at_force_minimum,
)
from vibroadhesion.models.frozen_radius import frozen_radius_cycle
from vibroadhesion.models.frozen_radius_table import X_RANGE, log_cycle_on_table, tabulated_cycle

TABLE_N = [0.05, 0.3, N_PUBLISHED, 1.0, 4.0]


def _dense_log_beta() -> np.ndarray:
    """2001 points over the table in x = ln beta, with every piece boundary and both ends."""
    return np.union1d(np.linspace(X_RANGE[0], X_RANGE[1], 2001), np.arange(X_RANGE[0], X_RANGE[1] + 1.0))


@pytest.mark.parametrize("n", TABLE_N)
def test_table_matches_the_direct_solve_on_a_dense_grid(n: float) -> None:
    """alpha* and Abar from the table against the direct solve, 1e-11 relative (module docstring), and
    d ln alpha*/d ln beta within [0, 1] (to 1e-9), the bound the Newton search of the levels relies on.
    """
    law = GentSchultz(n)
    beta = np.exp(_dense_log_beta())
    table, direct = tabulated_cycle(beta, law), frozen_radius_cycle(beta, law)
    assert np.max(np.abs(table.alpha / direct.alpha - 1)) < 1e-11
    assert np.max(np.abs(table.Abar / direct.Abar - 1)) < 1e-11
    assert np.all(table.slope > -1e-9) and np.all(table.slope < 1 + 1e-9)


def test_slope_is_the_derivative_of_ln_alpha() -> None:
    """d ln alpha*/d ln beta against a central difference of the direct solve with step 1e-4 in ln beta
    (truncation ~1e-8 |third derivative|, rounding 1e-12): agreement to 1e-7 at n = 0.531 and 4.
    """
    x = np.array([-8.5, -3.2, -0.7, 0.0, 1.3, 4.4, 8.9])
    for n in (N_PUBLISHED, 4.0):
        law = GentSchultz(n)
        central = (np.log(frozen_radius_cycle(np.exp(x + 1e-4), law).alpha)
                   - np.log(frozen_radius_cycle(np.exp(x - 1e-4), law).alpha)) / 2e-4
        assert np.max(np.abs(log_cycle_on_table(x, law)[2] - central)) < 1e-7


def test_outside_the_table_the_direct_solve_answers_and_beta_zero_is_static() -> None:
    """beta below e^-9 or above e^9, and exponents outside [0.05, 4], are solved directly: equal to
    frozen_radius_cycle bit for bit; beta = 0 is alpha* = 1, Abar = 0 exactly; the table itself refuses
    points outside it instead of extrapolating.
    """
    beta = np.array([[0.0, 1e-5, math.exp(X_RANGE[1]) * 1.01]])
    for n in (N_PUBLISHED, 0.04, 4.5):
        law = GentSchultz(n)
        got = tabulated_cycle(beta if n <= 4 else beta[:, :2], law)
        direct = frozen_radius_cycle(beta if n <= 4 else beta[:, :2], law)
        assert got.alpha.shape == direct.alpha.shape
        assert np.array_equal(got.alpha, direct.alpha) and np.array_equal(got.Abar, direct.Abar)
        assert got.alpha[0, 0] == 1.0 and got.Abar[0, 0] == 0.0
    with pytest.raises(ValueError):
        log_cycle_on_table(np.array([X_RANGE[1] + 1e-9]), GentSchultz(N_PUBLISHED))
    with pytest.raises(ValueError):
        log_cycle_on_table(np.array([0.0]), GentSchultz(4.5))


def test_pieces_are_built_once_per_exponent_and_the_cache_is_bounded() -> None:
    """A new exponent builds the pieces a call touches, once: the same call again builds nothing."""
    law = GentSchultz(0.4321)
    beta = np.exp(np.array([-0.5, 0.2, 0.7, 2.5]))  # pieces k = -1, 0, 2
    before = frozen_radius_table._piece.cache_info()
    first = tabulated_cycle(beta, law)
    middle = frozen_radius_table._piece.cache_info()
    again = tabulated_cycle(beta, law)
    after = frozen_radius_table._piece.cache_info()
    assert middle.misses - before.misses == 3 and after.misses == middle.misses
    assert np.array_equal(first.alpha, again.alpha)
    assert after.maxsize is not None and after.maxsize >= 18 * 50  # a fit's ~50 trial exponents


def _level_outputs(eta1: np.ndarray, law: GentSchultz) -> dict[str, np.ndarray]:
    """Every number of the three records of the exact-averaging levels and of mean_state."""
    steady = nominal_point_contact(eta1, 1e3, CHI0, law)
    critical = pulloff_at_critical_radius(eta1, CHI0, law)
    minimum = pulloff_at_force_minimum(eta1, CHI0, law)
    state = mean_state(np.geomspace(0.01, 100.0, 9)[:, None], eta1[None, :], CHI0, law)
    assert all(np.all(record.status == "ok") for record in (steady, critical, minimum))
    return {"steady_" + f: np.asarray(getattr(steady, f)) for f in ("Abar", "abar_m", "w_eff_ratio", "A_over_am",
                                                                    "pm_over_abs_pjkr")} | {
        f"{name}_{f}": np.asarray(getattr(record, f)) for name, record in (("critical", critical), ("minimum", minimum))
        for f in ("pulloff_ratio", "Abar_cr", "abar_m", "w_eff_ratio")} | {
        "mean_" + f: getattr(state, f) for f in ("phat_m", "alpha", "Abar")}


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 1.0, 4.0])
def test_levels_are_unchanged_against_the_direct_path(n: float, monkeypatch: pytest.MonkeyPatch) -> None:
    """Steady state, both pull-offs and the mean state, with the table and without it, to 1e-9 relative,
    for etahat = 1e-6 (the root below the table: the direct search answers) through 30 (h1 = 20-100 um is
    etahat = 1.6-7.9).
    """
    law = GentSchultz(n)
    eta1 = np.geomspace(1e-6, 30.0, 13) * C_O**2
    fast = _level_outputs(eta1, law)
    monkeypatch.setattr(frozen_radius_table, "N_RANGE", (math.inf, -math.inf))  # no exponent tabulated
    slow = _level_outputs(eta1, law)
    for key, value in fast.items():
        assert np.max(np.abs(value / slow[key] - 1)) < 1e-9, key


def test_where_alpha_star_is_beta_in_doubles_the_radius_has_its_closed_form(monkeypatch: pytest.MonkeyPatch) -> None:
    """n = 4, etahat = 100: alpha* - beta is 1.5e-54 at the root (relative 5e-56), so alpha* = beta in doubles
    and the closures have closed forms: alpha* = abar_m^(3/2) with beta = etahat/sqrt(abar_m) gives
    abar_m = sqrt(etahat); alpha* = (4/3) abar_m^(3/2) gives abar_m = sqrt(3 etahat/4). To 1e-13 (the
    table's 1e-12 on alpha* divided by F' >= 1 and by 2 for the square root, with margin). The bracketed
    search of the direct path reports no_solution there.
    """
    law, etahat = GentSchultz(4.0), 100.0
    assert float(frozen_radius_cycle(np.array([etahat / etahat**0.25]), law).sqrt_w_min[0]) < 1e-50
    steady = nominal_point_contact(etahat * C_O**2, 1e3, CHI0, law)
    critical = pulloff_at_critical_radius(etahat * C_O**2, CHI0, law)
    assert abs(float(steady.abar_m) / math.sqrt(etahat) - 1) < 1e-13
    assert abs(float(critical.abar_m) / math.sqrt(0.75 * etahat) - 1) < 1e-13
    monkeypatch.setattr(frozen_radius_table, "N_RANGE", (math.inf, -math.inf))  # no exponent tabulated
    assert nominal_point_contact(etahat * C_O**2, 1e3, CHI0, law).status.tolist() == "no_solution"
