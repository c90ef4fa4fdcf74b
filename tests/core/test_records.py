"""The two result records of every model level (vibroadhesion.core.records): the status/NaN invariant.

A status that says "no solution" never comes with a number, a status that says "solved" always
comes with the defining numbers, and every field has the status's shape. The checks are exact
(NaN or not, finite or not): no tolerance is involved.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from vibroadhesion.core.records import OrbitDiagnostics, Pulloff, SteadyState, stacked


def _steady(status, value=1.0, **changes) -> SteadyState:
    """A SteadyState of ``status``'s shape with every number ``value`` (``changes`` replace fields)."""
    status = np.asarray(status)
    numbers = {name: np.full(status.shape, value) for name in
               ("Abar", "abar_m", "w_eff_ratio", "A_over_am", "pm_over_abs_pjkr", "deltabar_m")}
    return SteadyState("refined", status, **{**numbers, **changes})


def _pulloff(status, value=1.0, **changes) -> Pulloff:
    """A Pulloff of ``status``'s shape with every number ``value`` (``changes`` replace fields)."""
    status = np.asarray(status)
    numbers = {name: np.full(status.shape, value) for name in
               ("pulloff_ratio", "Abar_cr", "sqrt_w_eff_ratio", "w_eff_ratio", "abar_cr", "abar_m", "A_over_am",
                "base_offset")}
    return Pulloff("leading", status, **{**numbers, **changes})


def test_a_solved_steady_state_keeps_its_numbers_as_float_arrays() -> None:
    state = _steady(["ok", "ok"], 2.0, Abar=[1, 3])
    assert state.Abar.dtype == np.float64 and state.Abar.tolist() == [1.0, 3.0]
    assert state.ok.tolist() == [True, True] and state.status.dtype.kind == "U"


def test_a_scalar_steady_state_has_shape_0d() -> None:
    state = _steady("ok", 2.0)
    assert state.status.shape == state.abar_m.shape == () and bool(state.ok)


@pytest.mark.parametrize("status", ["no_solution", "contact_loss", "not_converged", "integration_failure"])
def test_a_number_without_a_solution_is_refused(status: str) -> None:
    with pytest.raises(ValueError, match="status says there is no solution"):
        _steady(status, 1.0)
    assert math.isnan(_steady(status, math.nan).Abar)


def test_every_number_is_checked_not_only_the_first() -> None:
    """One field with a number among NaNs is enough to refuse the record."""
    with pytest.raises(ValueError, match="deltabar_m"):
        _steady(["ok", "no_solution"], [1.0, math.nan], deltabar_m=[0.0, 0.0])


def test_a_solution_without_its_defining_numbers_is_refused() -> None:
    """Abar, abar_m and w_eff/w0 define a steady state; deltabar_m may be NaN (a level that does not give it)."""
    with pytest.raises(ValueError, match="abar_m is not finite"):
        _steady("ok", 1.0, abar_m=math.nan)
    assert math.isnan(_steady("ok", 1.0, deltabar_m=math.nan).deltabar_m)


def test_speed_unresolved_keeps_its_numbers_but_is_not_ok() -> None:
    state = _steady("speed_unresolved", 1.5)
    assert state.Abar == 1.5 and not state.ok


def test_shapes_must_agree_with_the_status() -> None:
    with pytest.raises(ValueError, match="shape"):
        _steady(["ok", "ok"], 1.0, Abar=[1.0, 2.0, 3.0])


def test_unsolved_steady_state_is_nan_with_its_status_and_message() -> None:
    orbit = OrbitDiagnostics(np.array([1.0]), *(math.nan,) * 9, None, np.full(1, math.nan, dtype=complex), math.nan,
                             3, "dop853", 1.5)
    state = SteadyState.unsolved("simulation", "contact_loss", "lost", orbit)
    assert state.status == "contact_loss" and state.message == "lost" and state.orbit is orbit
    assert all(math.isnan(getattr(state, f)) for f in ("Abar", "abar_m", "w_eff_ratio", "A_over_am",
                                                        "pm_over_abs_pjkr", "deltabar_m"))
    assert state.stable is not None and not state.stable
    shaped = SteadyState.unsolved("exact_averaging", "no_solution", shape=(2, 3))
    assert shaped.status.shape == shaped.Abar.shape == (2, 3) and shaped.stable is None


def test_pulloff_found_covers_ok_and_the_simulated_pulloff() -> None:
    found = _pulloff(["ok", "pulloff"], 1.2).found
    assert found.tolist() == [True, True]


@pytest.mark.parametrize("status", ["no_solution", "contact_loss_before_extremum", "no_steady_state_before_extremum"])
def test_a_pulloff_number_without_a_pulloff_is_refused(status: str) -> None:
    with pytest.raises(ValueError, match="status says there is no solution"):
        _pulloff(status, math.nan, base_offset=-3.0)
    assert not _pulloff(status, math.nan).found


def test_a_pulloff_without_its_ratio_is_refused() -> None:
    with pytest.raises(ValueError, match="pulloff_ratio is not finite"):
        _pulloff("ok", math.nan)


def test_from_ratio_leaves_what_a_prediction_does_not_compute_nan() -> None:
    """A prediction has no simulated criterion a_cr, mean state or base offset: NaN, broadcast to the ratio."""
    pulloff = Pulloff.from_ratio("refined", "ok", [1.5, 2.0], Abar_cr=[3.0, 4.0], sqrt_w_eff_ratio=[1.1, 1.2])
    assert pulloff.status.tolist() == ["ok", "ok"] and pulloff.Abar_cr.tolist() == [3.0, 4.0]
    assert np.all(np.isnan(pulloff.abar_cr)) and np.all(np.isnan(pulloff.abar_m))
    assert np.all(np.isnan(pulloff.base_offset)) and np.all(np.isnan(pulloff.w_eff_ratio))


def test_taken_indexes_every_array_field_alike() -> None:
    pulloff = Pulloff.from_ratio("leading", ["ok", "no_solution"], [1.5, math.nan], Abar_cr=[3.0, math.nan])
    back = pulloff.taken(np.array([[1, 0], [0, 0]]))
    assert back.status.tolist() == [["no_solution", "ok"], ["ok", "ok"]]
    assert back.pulloff_ratio[0, 1] == 1.5 and math.isnan(back.pulloff_ratio[0, 0])
    assert back.Abar_cr.shape == back.base_offset.shape == (2, 2) and back.level == "leading"


def test_unsolved_pulloff_is_nan_with_its_status_and_message() -> None:
    pulloff = Pulloff.unsolved("exact_averaging", "no_solution", "no root", shape=(2,))
    assert pulloff.status.tolist() == ["no_solution"] * 2 and not pulloff.found.any() and pulloff.message == "no root"
    assert all(np.isnan(getattr(pulloff, name)).all() for name in ("pulloff_ratio", "Abar_cr", "abar_m", "base_offset"))


def test_stacked_records_are_the_elements_in_their_order_with_the_messages_joined() -> None:
    """Several solutions of one level at one point are the elements of one record (shape (k,))."""
    first, second = _steady("ok", 1.0, stable=True), _steady("ok", 2.0, stable=False)
    both = stacked([first, SteadyState.unsolved("refined", "not_converged", "Newton"), second][::2])
    assert both.status.tolist() == ["ok", "ok"] and both.Abar.tolist() == [1.0, 2.0]
    assert both.stable is not None and both.stable.tolist() == [True, False]
    mixed = stacked([_steady("ok", 1.0), SteadyState.unsolved("refined", "not_converged", "Newton")])
    assert mixed.status.tolist() == ["ok", "not_converged"] and math.isnan(mixed.abar_m[1])
    assert mixed.message == "Newton" and mixed.stable is None
    roots = stacked([_pulloff("ok", 2.0), _pulloff("ok", 3.0)])
    assert roots.pulloff_ratio.tolist() == [2.0, 3.0] and roots.taken(np.asarray(0)).pulloff_ratio == 2.0


def test_stacking_refuses_records_that_are_not_elements_of_one_level() -> None:
    with pytest.raises(ValueError, match="different levels"):
        stacked([_steady("ok"), replace(_steady("ok"), level="leading")])
    with pytest.raises(ValueError, match="stable"):
        stacked([_steady("ok", stable=True), _steady("ok")])
    with pytest.raises(ValueError, match="simulated"):
        stacked([replace(_pulloff("pulloff"), steady_states=3)])
