"""Pull-off at a finite withdrawal speed: the full model integrated in time with the base offset ramped (issue 15).

The paper's Discussion: "in real experiments, during detachment, the indenter has some pull-off
velocity that compromises the quasi-static approximation". Here the base of Eq. (11) is withdrawn at
a constant speed V, h0(t) = h0_start + V t, so with tau = omega t the base offset of the model
(:mod:`vibroadhesion.simulation.model`) falls linearly,

    base_offset(tau) = base_offset_start - ramp tau,      ramp = V R/(a_o^2 omega),            (11')

and deltabar(tau) = base_offset(tau) - etahat sin tau (+ xbar, compliant; Eq. 7). With V/v0 the speed
in units of the Gent–Schultz v0 (Eq. 73), ramp = (V/v0) / (omega_check c_o^2) since omega_check =
omega R/v0 (Eq. 105) and c_o = a_o/R. The compiled DOP853 of :mod:`vibroadhesion.simulation.kernel`
integrates Eqs. (3'), (6') with this ramp, period by period (each period re-based, as
:func:`vibroadhesion.simulation.transient` does, so that abar keeps full precision), from the
vibrating steady state at a compressive start offset to the loss of contact (abar below the
model's contact-loss threshold).

What the instrument records: the load-cell force, in units of E* a_o^3/R (Eq. 4'),

* rigid fixation: the contact force Phat (Eq. 4');
* compliant fixation: the spring force, mu/c_o^3 - (kappa/c_o) xbar = (mu/(kappa c_o^2) - xbar)/(c_o/kappa)
  (Eq. 3' without its inertia and damping terms: m g - k x_s in units of E* a_o^3/R), equal to Phat statically.

The pull-off is the most tensile load-cell force over the whole withdrawal: every interval of accepted
steps where its rate dF/dtau turns from negative to positive holds a local minimum, estimated by the
cubic Hermite interpolant through the interval's ends; the _CANDIDATES lowest estimates are refined by
Brent's method on dF/dtau = 0 at re-integrated states (to 1e-12 in tau), with its tau and base offset.
Along with it, the most tensile one-period mean of the load-cell force (the reading of a load cell that
averages over a period), from the quadratures of the compiled state over each period [2 pi k, 2 pi (k+1)]
and a parabola through the three periods around the smallest: as V -> 0 it tends to the quasi-static
pull-off of :mod:`vibroadhesion.experiments.virtual_pulloff` (the most tensile mean force of the family
of steady states).

Status (:data:`vibroadhesion.core.records.WithdrawalStatus`): ``pulloff`` when the period-mean force passed a
tensile minimum before the contact was lost; ``detached_before_mean_extremum`` when the contact was lost first (e.g.
in the tensile half-period of a fast or large stroke): the numbers are then the instantaneous ones an
instrument records, and there is no quasi-static counterpart; ``not_detached`` when the contact is
still there after ``max_periods``; ``integration_failure`` when the integrator gives up (step budget
or step underflow). A failure is a status, never an exception.
"""

from __future__ import annotations

import math
from operator import attrgetter
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from vibroadhesion.core.problem import Problem
from vibroadhesion.core.records import WithdrawalStatus
from vibroadhesion.simulation import kernel
from vibroadhesion.simulation.excitation import CONSTANT_SCHEDULE, ExcitationSchedule
from vibroadhesion.simulation.integrators import Period
from vibroadhesion.simulation.model import TWO_PI, Array, Model, absolute_start
from vibroadhesion.simulation.scales import v_scale_estimate, x_scale

#: Index of the withdrawal ramp and of the variational switch in the kernel's constants.
_RAMP = kernel.CONSTANTS.index("ramp")
_OFFSET = kernel.CONSTANTS.index("base_offset")
_ETAHAT = kernel.CONSTANTS.index("etahat")
_VARIATIONAL = kernel.CONSTANTS.index("variational")
_EXCITATION = slice(kernel.CONSTANTS.index("excitation_s0"), kernel.CONSTANTS.index("excitation_tau_b") + 1)
#: Index of the quadrature of Phat (rigid) and of xi (compliant) in the full compiled state.
_PHAT_QUADRATURE = 6
_XI_QUADRATURE = 19
#: Steps allowed per period (a period of the steady state takes ~100-300).
_STEPS_PER_PERIOD = 20_000
#: Candidate minima refined: successive periods have nearly equal force minima (they differ by ~ramp 2 pi
#: dF/dbase_offset), which the cubic Hermite estimates rank to O(step^4) only.
_CANDIDATES = 4


class Withdrawal(NamedTuple):
    """One withdrawal at constant speed (module docstring); forces in units of E* a_o^3/R (Eq. 4')."""

    status: WithdrawalStatus
    force: float  # most tensile load-cell force (NaN if none recorded)
    tau: float  # its time omega t from the start of the withdrawal
    base_offset: float  # base_offset there (Eq. 11')
    mean_force: float  # most tensile one-period mean of the load-cell force
    mean_base_offset: float  # base_offset at the middle of that period
    tau_detached: float  # tau at which abar fell below the contact-loss threshold (NaN if not)
    periods: int  # periods integrated (the last one partial if detached)
    steps: int  # accepted integration steps


def ramp_rate(problem: Problem, speed_ratio: float) -> float:
    """ramp = V R/(a_o^2 omega) = (V/v0)/(omega_check c_o^2) (Eq. 11', with omega_check of Eq. 105)."""
    return speed_ratio / (problem.omega_check * problem.c_o**2)


class _Best(NamedTuple):
    """A candidate of the most tensile load-cell force: an interval of accepted steps of one period."""

    force: float  # its estimate (cubic Hermite through the interval's ends), or the sampled value
    period: Period
    constants: Array
    tau0: float  # tau at the start of that period
    taus: Array
    cores: Array
    step: int  # the interval [taus[step], taus[step + 1]] where dF/dtau changes sign, or the sampled step
    bracketed: bool  # whether dF/dtau changes sign from - to + in that interval


def _contact_state(period: Period, constants: Array, taus: Array, cores: Array) -> tuple[Array, Array]:
    """(abar, deltabar) of the rigid fixation at local times ``taus``: the scaled core's abar and Eq. (11')."""
    abar = (period.b0 + period.v_scale * cores[:, -1]) / period.m.speed_scale
    level = kernel.excitation_factors(taus, constants)[0]  # s(tau) of the excitation schedule
    return abar, constants[_OFFSET] - constants[_RAMP] * taus - constants[_ETAHAT] * level * np.sin(taus)


def cell_forces(period: Period, constants: Array, taus: Array, cores: Array) -> Array:
    """Load-cell force at local times ``taus`` of a period from its scaled cores (module docstring, Eqs. 3', 4').

    ``constants`` are the period's kernel constants with its base offset and ramp (Eq. 11').
    """
    m = period.m
    if m.compliant:
        return np.asarray((m.force_offset - cores[:, 0] * period.x_scale) / m.compliance, dtype=float)
    abar, d = _contact_state(period, constants, taus, cores)
    return np.asarray(2.0 * abar * d - (2.0 / 3.0) * abar**3, dtype=float)


def cell_force_rates(period: Period, constants: Array, taus: Array, cores: Array) -> Array:
    """dF/dtau of the load-cell force of :func:`cell_forces` (Eqs. 3', 4', 6', 11').

    Compliant: -xbar'/(c_o/kappa). Rigid: dPhat/dtau = 2 abar' deltabar + 2 abar deltabar' - 2 abar^2 abar' with
    abar' = x/speed_scale (Eq. 6') and deltabar' = -ramp - etahat (s cos tau + s' sin tau) (s of the excitation).
    """
    m = period.m
    if m.compliant:
        return np.asarray(-cores[:, 1] * period.x_scale / m.compliance, dtype=float)
    abar, d = _contact_state(period, constants, taus, cores)
    a_rate = kernel.speeds(abar, d, m.inv_n, m.log_cap) / m.speed_scale
    level, level_rate = kernel.excitation_factors(taus, constants)
    d_rate = -constants[_RAMP] - constants[_ETAHAT] * (level * np.cos(taus) + level_rate * np.sin(taus))
    return np.asarray(2.0 * a_rate * (d - abar * abar) + 2.0 * abar * d_rate, dtype=float)


def _period_mean(period: Period, y: Array) -> float:
    """One-period mean of the load-cell force from the quadratures of the full state (Eqs. 3', 4')."""
    m = period.m
    if m.compliant:
        return float((m.force_offset - period.x_scale * y[_XI_QUADRATURE] / TWO_PI) / m.compliance)
    return float(y[_PHAT_QUADRATURE] / TWO_PI)


#: Points per interval at which the cubic Hermite estimate of a force minimum is evaluated (a ranking only).
_HERMITE = np.linspace(0.0, 1.0, 17)


def _interval_minima(taus: Array, forces: Array, rates: Array) -> tuple[NDArray[np.intp], Array]:
    """(intervals where dF/dtau goes from - to +, cubic Hermite estimate of the minimum in each)."""
    j = np.flatnonzero((rates[:-1] < 0.0) & (rates[1:] >= 0.0))
    h, s = (taus[j + 1] - taus[j])[:, None], _HERMITE[None, :]
    f0, f1, g0, g1 = forces[j, None], forces[j + 1, None], rates[j, None] * h, rates[j + 1, None] * h
    cubic = (f0 * (1 + 2 * s) * (1 - s) ** 2 + g0 * s * (1 - s) ** 2 + f1 * s * s * (3 - 2 * s)
             + g1 * s * s * (s - 1))
    return j, np.asarray(cubic.min(axis=1), dtype=float)


def _rate_at(tau: float, best: _Best, rtol: float) -> float:
    """dF/dtau at ``tau`` integrated from the start of the candidate's interval (Eqs. 3', 6', 4')."""
    lo, state = float(best.taus[best.step]), best.cores[best.step]
    if tau > lo:
        state = kernel.integrate(best.constants, state, lo, tau, rtol, _STEPS_PER_PERIOD, -math.inf).y
    return float(cell_force_rates(best.period, best.constants, np.array([tau]), state[None, :])[0])


def _refine(best: _Best, rtol: float) -> tuple[float, float]:
    """(force, local tau) of the candidate: the root of dF/dtau in its interval (Brent on re-integrated states)."""
    lo, start = float(best.taus[best.step]), best.cores[best.step]
    if not best.bracketed:
        return best.force, lo
    root = float(brentq(_rate_at, lo, float(best.taus[best.step + 1]), args=(best, rtol), xtol=1e-12))
    state = kernel.integrate(best.constants, start, lo, root, rtol, _STEPS_PER_PERIOD, -math.inf).y
    return float(cell_forces(best.period, best.constants, np.array([root]), state[None, :])[0]), root


def _parabola_minimum(values: list[float], k: int) -> tuple[float, float]:
    """(minimum, abscissa in periods) of the parabola through values[k-1..k+1]; values[k] at an edge."""
    if k == 0 or k == len(values) - 1:
        return values[k], float(k)
    f0, f1, f2 = values[k - 1], values[k], values[k + 1]
    curvature = f0 - 2.0 * f1 + f2
    if curvature <= 0.0:
        return f1, float(k)
    shift = 0.5 * (f0 - f2) / curvature
    return f1 - 0.25 * (f0 - f2) * shift, k + shift


class _Trace:
    """What a withdrawal keeps while it runs: the best steps of the _CANDIDATES best periods, the period means."""

    def __init__(self) -> None:
        self.best: list[_Best] = []
        self.means: list[float] = []
        self.steps = 0

    def record(self, period: Period, constants: Array, tau0: float, run: kernel.KernelRun) -> None:
        """Note the accepted steps of one period (and its mean if it completed)."""
        self.steps += len(run.taus) - 1
        forces = cell_forces(period, constants, run.taus, run.cores)
        steps, estimates = _interval_minima(run.taus, forces, cell_force_rates(period, constants, run.taus, run.cores))
        candidates = [_Best(float(f), period, constants, tau0, run.taus, run.cores, int(j), True)
                      for j, f in zip(steps, estimates, strict=True)]
        if not candidates:
            i = int(np.argmin(forces))
            candidates = [_Best(float(forces[i]), period, constants, tau0, run.taus, run.cores, i, False)]
        self.best = sorted([*self.best, *candidates], key=attrgetter("force"))[:_CANDIDATES]
        if run.code == kernel.REACHED:
            self.means.append(_period_mean(period, run.y))

    def pulloff(self, rtol: float) -> tuple[float, float]:
        """(force, tau from the start) of the most tensile load-cell force: each candidate refined (:func:`_refine`)."""
        refined = [(*_refine(best, rtol), best.tau0) for best in self.best]
        force, tau_local, tau0 = min(refined)
        return force, tau0 + tau_local


def withdraw(problem: Problem, speed_ratio: float, *, initial_state: ArrayLike | None = None,
             max_periods: int = 100_000, rtol: float = 1e-11, contact_loss_abar: float = 1e-3,
             excitation: ExcitationSchedule = CONSTANT_SCHEDULE) -> Withdrawal:
    """Withdraw the base of ``problem`` at V = ``speed_ratio`` v0 from its base offset to detachment (module docstring).

    Starts from ``initial_state`` (abar,) or (xbar, xbar', abar) at tau = 0 (the periodic steady state at
    ``problem.base_offset``, :func:`vibroadhesion.simulation.steady_state`), or from the static state.
    ``excitation``: the excitation amplitude etahat s(tau) switched on or off or ramped (Eq. 11), the Discussion's
    suggestion of a time-dependent excitation (:mod:`vibroadhesion.simulation.excitation`; default: constant).
    """
    if not (math.isfinite(speed_ratio) and speed_ratio > 0):
        raise ValueError(f"speed_ratio must be positive, got {speed_ratio}")
    model = Model(problem, contact_loss_abar)
    state = absolute_start(model, initial_state)
    ramp = ramp_rate(problem, speed_ratio)
    trace, v_scale, lost, code = _Trace(), v_scale_estimate(model, float(state[-1])), math.nan, kernel.REACHED
    k = 0
    while k < max_periods:
        period = Period(model, state, v_scale, x_scale(model, state))
        constants = period.kernel_constants.copy()
        offset = problem.base_offset - ramp * TWO_PI * k  # Eq. (11') at the start of period k
        constants[_OFFSET], constants[_RAMP], constants[_VARIATIONAL] = offset, ramp, 0.0
        constants[_EXCITATION] = excitation.kernel_constants(TWO_PI * k)
        run = kernel.integrate(constants, np.array(period.full_start()), 0.0, TWO_PI, rtol, _STEPS_PER_PERIOD,
                               contact_loss_abar)
        code = run.code
        if code < 0:
            break
        trace.record(period, constants, TWO_PI * k, run)
        k += 1
        if code == kernel.CONTACT_LOST:
            lost = TWO_PI * (k - 1) + run.tau
            break
        u = run.cores[:, -1]
        v_scale = max(0.5 * float(u.max() - u.min()) * v_scale, 1e-14 * model.speed_scale * float(state[-1]))
        state = period.absolute(run.y[: model.dim].tolist())
    return _result(problem, ramp, trace, code, lost, k, rtol)


def _result(problem: Problem, ramp: float, trace: _Trace, code: int, lost: float, periods: int,
            rtol: float) -> Withdrawal:
    """The :class:`Withdrawal` record of a finished run (module docstring, "Status")."""
    nan = math.nan
    if code < 0 or not trace.best:
        return Withdrawal("integration_failure", nan, nan, nan, nan, nan, nan, periods, trace.steps)
    force, tau = trace.pulloff(rtol)
    means = trace.means
    k = int(np.argmin(means)) if means else -1
    mean_force, at = _parabola_minimum(means, k) if means else (nan, nan)
    mean_offset = problem.base_offset - ramp * TWO_PI * (at + 0.5)
    status: WithdrawalStatus
    if math.isnan(lost):
        status = "not_detached"
    elif 0 < k < len(means) - 1 and means[k] < 0.0:
        status = "pulloff"
    else:
        status = "detached_before_mean_extremum"
    return Withdrawal(status, force, tau, problem.base_offset - ramp * tau, mean_force, mean_offset, lost, periods,
                      trace.steps)
