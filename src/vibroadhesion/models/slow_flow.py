"""The averaged slow flow of a withdrawal at a finite speed: exact averaging with the base offset slow, rigid fixation.

The time-domain withdrawal (:mod:`vibroadhesion.simulation.withdrawal`) integrates every period; this is its
high-frequency average, for the rigidly fixed indenter only (the exact averaging is a model of the rigid
contact, :mod:`vibroadhesion.core.levels`; the compliant fixation has no exact-averaging level to average).

Derivation (notation of :mod:`vibroadhesion.models.frozen_radius`). The base is withdrawn at V (Eq. 11 with
h0 = h0_start + V t), so base_offset = (hhat - h0) R/a_o^2 falls as d base_offset/dt = -V R/a_o^2. With the
slow time T = v0 t/a_o (tau = omega t = omega_check c_o T, Eqs. 86, 105), Eq. (5) solved for the front speed,
d abar/dt = (v0/a_o) X(s), reads d abar/dT = X(s), s = (abar^2 - deltabar)/sqrt(abar) (Eqs. 4-6, 73-74), and
deltabar = base_offset(T) - etahat sin tau (Eq. 11, rigid: x_s = 0 in Eq. 7). As omega_check -> infinity a
period is an instant of T: the radius is frozen at abar_m over it and first-order averaging gives

    d abar_m/dT = G(alpha, beta),   alpha = (abar_m^2 - base_offset)/sqrt(abar_m),   beta = etahat/sqrt(abar_m),
    d base_offset/dT = -(V/v0)/c_o,                                                                     (SF)

with G the period-mean front speed of the frozen-radius cycle s = alpha + beta sin tau
(:func:`vibroadhesion.models.frozen_radius.mean_front_speed`), zero exactly on the quasi-static family
alpha = alpha*(beta) of :func:`vibroadhesion.models.exact_averaging.mean_state`. The period-mean force is
Eq. (4) averaged with the radius frozen (mean sin tau = 0):

    Phat_m = (4/3) abar_m^3 - 2 alpha abar_m^(3/2) = 2 abar_m base_offset - (2/3) abar_m^3,

and the most tensile instantaneous force of the frozen cycle is at sin tau = 1, Phat_m - 2 etahat abar_m (the
reading of an instrument sampling faster than the excitation). (SF) depends on the frequency only through
omega_check -> infinity: at given etahat and V/v0 every frequency has the same slow flow, and the pull-off is
that of the exact averaging with the speed added. As V -> 0 the flow follows the family and its most tensile
mean force tends to the family's force minimum
(:func:`vibroadhesion.models.exact_averaging.pulloff_at_force_minimum`): under displacement control the mean
state passes the force minimum before the fold of base_offset (there d Phat_m/d abar_m = -2 alpha sqrt(abar_m)
< 0). Beyond the fold G < 0 for every abar_m and abar_m reaches 0 in finite T (detachment).

(SF) is integrated from the family's state at the start offset by scipy's LSODA (the flow is stiff near the
family: its relaxation rate is up to ~1e5 per unit T at 100 um) with dense output, in q = ln(abar_m^2 -
base_offset - etahat) = ln(sqrt(abar_m) (alpha - beta)), which keeps trial steps off alpha = beta. The most
tensile mean and peak forces are found at the accepted steps and refined on the dense output (d Phat_m/dT =
-2 G alpha sqrt(abar_m) - 2 abar_m (V/v0)/c_o); the flow ends at abar_m = ``contact_loss_abar`` or where the
front runs away (:func:`_front_runs_away`), whichever comes first. Statuses as the time-domain
withdrawal's (:data:`vibroadhesion.core.records.WithdrawalStatus`): ``pulloff`` when the mean force passed a
tensile minimum before the contact was lost, ``detached_before_mean_extremum`` when not (the numbers are then
the smallest along the flow), ``not_detached`` when the contact is still there after the slow-time budget,
``integration_failure`` when the integrator gives up or leaves the flow's domain (alpha <= beta: s would
reach 0 within a period). A failure is a status, never an exception.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import solve_ivp
from scipy.optimize import OptimizeResult, brentq, minimize_scalar

from vibroadhesion.core.problem import Problem
from vibroadhesion.core.records import WithdrawalStatus
from vibroadhesion.models.exact_averaging import mean_state, pulloff_at_force_minimum
from vibroadhesion.models.frozen_radius import mean_front_speed

Array = NDArray[np.float64]

#: Relative (and, the state being a logarithm, absolute) tolerance of the slow flow's integrator: against rtol 1e-10
#: the pull-off forces (mean and peak) agree within 1.4e-7 relative in the pipeline's 25 flows (20-100 um, V = 1e-3
#: to 1 v0; the largest at 20 um, V = v0, 8e-9 elsewhere), with the same statuses, at 0.66 of the CPU time of rtol
#: 1e-8 (1.3e-8) and 0.23 of 1e-10's (benchmarks/withdrawal_rtol.py). The flow's numbers are read to 1e-4
#: (deviations from the quasi-static value, the difference from the time domain). tests/models/test_slow_flow.py
#: bounds it by 3e-7.
SLOW_FLOW_RTOL = 1e-7
#: Slow-time budget, in units of the time the base offset takes to fall by (1 + etahat): the fold of the family
#: lies above base_offset = -(1 + etahat) (alpha* < 1 + beta), and detachment follows it within O(1) in T.
_BUDGET = 20.0


class SlowWithdrawal(NamedTuple):
    """One withdrawal by the slow flow (module docstring); forces in units of E* a_o^3/R (Eq. 4').

    The fields of :class:`vibroadhesion.simulation.withdrawal.Withdrawal` in the slow time T = v0 t/a_o (tau = omega t
    = omega_check c_o T, Eqs. 86, 105: the flow itself does not depend on the frequency), with the frozen-radius peak
    force.
    """

    status: WithdrawalStatus
    force: float  # most tensile instantaneous force of the frozen cycle, Phat_m - 2 etahat abar_m
    slow_time: float  # its slow time T from the start of the withdrawal
    base_offset: float  # base_offset there
    mean_force: float  # most tensile period-mean force Phat_m
    mean_base_offset: float  # base_offset there
    slow_time_detached: float  # T of detachment (abar_m below contact_loss_abar, or the front running away; NaN if not)
    steps: int  # accepted steps of the slow-flow integrator


class _Flow(NamedTuple):
    """The constants of (SF) and of its ends: etahat, offsets, fall rate (V/v0)/c_o, problem, contact loss, the fold."""

    etahat: float
    start_offset: float
    fall: float
    problem: Problem
    contact_loss_abar: float
    fold_offset: float


def _offset(flow: _Flow, t: float) -> float:
    """base_offset(T) = start - ((V/v0)/c_o) T (Eq. 11 with h0 = h0_start + V t, slow time T = v0 t/a_o)."""
    return float(flow.start_offset - flow.fall * t)


def _radius(t: float, q: float, flow: _Flow) -> float:
    """abar_m from the integrated state q = ln(abar_m^2 - base_offset - etahat) = ln(sqrt(abar_m) (alpha - beta)).

    NaN where exp(q) + base_offset + etahat <= 0 (no contact).
    """
    square = math.exp(q) + _offset(flow, t) + flow.etahat
    return math.sqrt(square) if square > 0.0 else math.nan


def _front_speed(t: float, q: float, flow: _Flow) -> tuple[float, float]:
    """(abar_m, G(alpha, beta)) at the state q and base_offset(T): the drift of (SF), Eq. (5) averaged.

    alpha - beta = exp(q)/sqrt(abar_m) > 0 for every finite q: the integrated variable keeps the flow off the
    border alpha = beta, where the closing speed diverges (n <= 4, :mod:`vibroadhesion.models.frozen_radius`).
    """
    abar_m = _radius(t, q, flow)
    root = math.sqrt(abar_m)
    alpha, beta = (abar_m * abar_m - _offset(flow, t)) / root, flow.etahat / root
    return abar_m, float(mean_front_speed(alpha, beta, flow.problem.law))


def _rhs(t: float, y: Array, flow: _Flow) -> Array:
    """(SF) in q: dq/dT = (2 abar_m G + (V/v0)/c_o) exp(-q), from d abar_m/dT = G and d base_offset/dT = -(V/v0)/c_o."""
    abar_m, speed = _front_speed(t, float(y[0]), flow)
    return np.array([(2.0 * abar_m * speed + flow.fall) * math.exp(-float(y[0]))])


def _contact_left(t: float, y: Array, flow: _Flow) -> float:
    """abar_m - contact_loss_abar: zero at detachment (negative where no radius exists)."""
    abar_m = _radius(t, float(y[0]), flow)
    return abar_m - flow.contact_loss_abar if math.isfinite(abar_m) else -1.0


def _front_runs_away(t: float, y: Array, flow: _Flow) -> float:
    """Negative once the base offset is below the family's fold and both forces passed their minima.

    max(base_offset - fold, -d Phat_m/dT, -d(Phat_m - 2 etahat abar_m)/dT): below the fold G < 0 at every
    abar_m (no mean state exists), so abar_m falls to 0 in finite T (detachment: the front runs away). That the
    forces, rising there, do not turn more tensile again before abar_m = 1e-3 is measured, not proven: integrating
    on to abar_m = 1e-3 changed no pull-off beyond the integration tolerance (20 and 100 um, V = 1e-3 to 1 v0).
    Above the fold only the first term is returned: the sign, which is all the event detection and its root (after
    the fold, the base offset falling monotonically) depend on, is the same.
    """
    offset = _offset(flow, t)
    if offset > flow.fold_offset:  # the max is positive whatever G is: G (a quadrature, 30 % of the flow) not needed
        return offset - flow.fold_offset
    abar_m, speed = _front_speed(t, float(y[0]), flow)
    mean_rate = 2.0 * speed * (offset - abar_m * abar_m) - 2.0 * abar_m * flow.fall
    return max(offset - flow.fold_offset, -mean_rate, 2.0 * flow.etahat * speed - mean_rate)


for _event in (_contact_left, _front_runs_away):
    _event.terminal = True  # type: ignore[attr-defined]
    _event.direction = -1.0  # type: ignore[attr-defined]


def fold_offset(problem: Problem) -> float:
    """The smallest base offset of the quasi-static family (Eqs. 16-18 exact): its fold under displacement control.

    Bounded Brent on ln abar_m between the contact-loss radius 1e-3 and the family's force minimum (the fold lies
    below the minimum's radius, module docstring); the value at 1e-3 if the offset still falls there.
    """
    low = float(pulloff_at_force_minimum(problem.eta1, problem.chi0, problem.law).abar_m)
    best = minimize_scalar(_family_offset, bounds=(math.log(1e-3), math.log(low)), args=(problem,),
                           method="bounded", options={"xatol": 1e-10})
    return float(best.fun)


def _family_offset(log_abar_m: float, problem: Problem) -> float:
    """base_offset of the family at abar_m = exp(log_abar_m) (Eqs. 16-18 exact, rigid)."""
    return float(mean_state(math.exp(log_abar_m), problem.eta1, problem.chi0, problem.law).base_offset)


def start_radius(problem: Problem) -> float:
    """abar_m of the quasi-static family (Eqs. 16-18 exact) at ``problem.base_offset``, above the force minimum.

    base_offset(abar_m) = abar_m^2 - alpha*(etahat/sqrt(abar_m)) sqrt(abar_m) rises with abar_m above the
    family's force minimum (the fold of base_offset lies below it, module docstring) and exceeds the offset at
    abar_m = 2 sqrt(|offset| + etahat) + 2 (alpha* < 1 + beta); NaN if the offset is below the minimum's.
    """
    low = float(pulloff_at_force_minimum(problem.eta1, problem.chi0, problem.law).abar_m)
    high = 2.0 * math.sqrt(abs(problem.base_offset) + problem.etahat) + 2.0
    excess = _offset_excess(low, problem)
    if not math.isfinite(excess) or excess > 0.0:
        return math.nan
    return float(brentq(_offset_excess, low, high, args=(problem,), xtol=1e-15, rtol=1e-15))


def _offset_excess(abar_m: float, problem: Problem) -> float:
    """base_offset of the family at abar_m minus the problem's (Eqs. 16-18 exact, rigid)."""
    return float(mean_state(abar_m, problem.eta1, problem.chi0, problem.law).base_offset) - problem.base_offset


def withdraw_slowly(problem: Problem, speed_ratio: float, *, rtol: float = SLOW_FLOW_RTOL,
                    contact_loss_abar: float = 1e-3) -> SlowWithdrawal:
    """Withdraw the base of the rigid ``problem`` at V = ``speed_ratio`` v0 by the slow flow (SF), from its offset.

    Starts on the quasi-static family at ``problem.base_offset`` (:func:`start_radius`); the pull-off is the most
    tensile mean force along the slow trajectory (module docstring). Ends at detachment: abar_m below
    ``contact_loss_abar``, or the front running away (:func:`_front_runs_away`), whichever comes first.
    """
    if not problem.fixation.is_rigid:
        raise ValueError("the slow flow averages the rigid fixation only (the exact averaging's fixation)")
    if not (math.isfinite(speed_ratio) and speed_ratio > 0):
        raise ValueError(f"speed_ratio must be positive, got {speed_ratio}")
    flow = _Flow(problem.etahat, problem.base_offset, speed_ratio / problem.c_o, problem, contact_loss_abar,
                 fold_offset(problem))
    start = start_radius(problem)
    if math.isnan(start):
        return _result(flow, None)
    span = _BUDGET * (1.0 + problem.etahat + max(problem.base_offset, 0.0)) / flow.fall
    q0 = math.log(start * start - problem.base_offset - problem.etahat)
    try:
        sol = solve_ivp(_rhs, (0.0, span), [q0], method="LSODA", rtol=rtol, atol=rtol,
                        events=(_contact_left, _front_runs_away), args=(flow,), dense_output=True)
    except (ValueError, ArithmeticError):  # a trial state without contact (NaN radius) met by the event search
        return _result(flow, None)
    return _result(flow, sol)


def _forces(flow: _Flow, times: Array, q: Array, peak: bool) -> Array:
    """Phat_m = 2 abar_m base_offset - (2/3) abar_m^3, minus 2 etahat abar_m if ``peak`` (module docstring).

    At the states q: abar_m^2 = exp(q) + base_offset + etahat.
    """
    offsets = flow.start_offset - flow.fall * times
    radii = np.sqrt(np.exp(q) + offsets + flow.etahat)
    return np.asarray(2.0 * radii * offsets - (2.0 / 3.0) * radii**3 - 2.0 * flow.etahat * radii * peak, dtype=float)


def _force_on_dense_output(t: float, sol: OptimizeResult, flow: _Flow, peak: bool) -> float:
    """The force of :func:`_forces` on the integrator's dense output at slow time ``t``."""
    return float(_forces(flow, np.array([t]), sol.sol(t)[0:1], peak)[0])


def _smallest(flow: _Flow, sol: OptimizeResult, peak: bool) -> tuple[float, float, bool]:
    """(force, T, interior) of the most tensile force along the flow (:func:`_forces`).

    The smallest at the accepted steps, refined between its neighbours on the dense output (bounded Brent, to
    1e-12 relative in T); ``interior`` when the force rises again after it (an extremum passed, not an end).
    """
    force = _forces(flow, sol.t, sol.y[0], peak)
    k = int(np.argmin(force))
    if k == 0 or k == len(force) - 1:
        return float(force[k]), float(sol.t[k]), False
    lo, hi = float(sol.t[k - 1]), float(sol.t[k + 1])
    best = minimize_scalar(_force_on_dense_output, bounds=(lo, hi), args=(sol, flow, peak), method="bounded",
                           options={"xatol": 1e-12 * hi})
    return (float(best.fun), float(best.x), True) if best.fun < force[k] else (float(force[k]), float(sol.t[k]), True)


def _result(flow: _Flow, sol: OptimizeResult | None) -> SlowWithdrawal:
    """The :class:`SlowWithdrawal` record of a finished (or failed) integration of (SF) (module docstring)."""
    nan = math.nan
    if sol is None or sol.status < 0 or not np.all(np.isfinite(sol.y)):
        return SlowWithdrawal("integration_failure", nan, nan, nan, nan, nan, nan, 0 if sol is None else len(sol.t) - 1)
    mean_force, mean_t, passed = _smallest(flow, sol, False)
    force, t, _ = _smallest(flow, sol, True)
    detached = sol.status == 1
    passed = passed or bool(np.size(sol.t_events[1]))  # the front ran away: both minima passed (its event)
    status: WithdrawalStatus = ("pulloff" if detached and passed and mean_force < 0.0
                                else "detached_before_mean_extremum" if detached else "not_detached")
    return SlowWithdrawal(status, force, t, _offset(flow, t), mean_force, _offset(flow, mean_t),
                          float(sol.t[-1]) if detached else nan, len(sol.t) - 1)
