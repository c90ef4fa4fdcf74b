"""What a periodic orbit of the full model is reported as, where the shooting starts it, and the transient.

:class:`~vibroadhesion.core.records.SteadyState` (level ``simulation``, with the orbit's
:class:`~vibroadhesion.core.records.OrbitDiagnostics`) is the record of a converged period
(:func:`summarise`) or of a failure (:func:`failure_record`); :func:`frozen_start` is the limit
omega_check -> infinity of the orbit (abar frozen over a period) that starts the shooting;
:func:`transient` integrates period after period from the static state, the brute-force reference
of the shooting.

Outputs
-------
Means and first harmonics are integrals over the converged period carried along as extra ODE
components (so they share the integrator's error control), in the base-motion time tau = omega t
with h - h0 = h1 sin tau (Eq. 11):

    y(tau) ~ y_m + y_c cos tau + y_s sin tau,  y_c = (1/pi) int y cos tau,  y_s = (1/pi) int y sin tau.

The paper's harmonics (Eqs. 30, 31, 107, 108) refer to the shifted time t' = t + phi/omega of
Eq. (25), i.e. to a phase chosen so that a - a_m ~ A sin(omega t'); they follow from these by the
rotation by phi. A is half the peak-to-peak range of a over the period, its extremes (where x = 0,
Phi = 1) located by root finding between accepted steps; Abar = omega A/v0 = omega_check c_o A/a_o
(Eq. 45); w_eff/w0 = (mean sqrt(w/w0))^2 (Eq. 18); the peak front speed max |x| is taken at the
extremes of Phi, located the same way.
"""

from __future__ import annotations

import math
from typing import Any, Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from vibroadhesion.core.groups import PHAT_JKR
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.records import OrbitDiagnostics, SteadyState, SteadyStatus
from vibroadhesion.simulation import kernel
from vibroadhesion.simulation.integrators import (
    IntegrationError,
    Integrator,
    Integrators,
    Period,
    Run,
    integrate_core,
    run_period,
)
from vibroadhesion.simulation.model import (
    SPEED_CAP,
    TWO_PI,
    Array,
    Model,
    absolute_start,
)
from vibroadhesion.simulation.scales import observed_v_scale, v_scale_estimate, x_scale

#: Floquet multipliers: complex, except that :func:`numpy.linalg.eigvals` returns them as real
#: numbers when all of them are real (compliant fixation).
Multipliers = NDArray[np.inexact[Any]]

#: A periodic orbit is trusted only if its peak speed stays below this fraction of the cap.
_RESOLVED_SPEED_FRACTION = 1e-3
#: Largest contact radius abar a search tries (the frozen start, the rigid shooting).
MAX_ABAR = 1e4
#: Step budget of a re-integration inside one accepted step (as the integrators' budget per call).
_REINTEGRATION_STEPS = 10_000
#: sin tau at the points of the periodic trapezoid rule of the frozen drift (:func:`_frozen_drift`).
_FROZEN_SINES = np.sin(np.linspace(0.0, TWO_PI, 512, endpoint=False))



# --- Records ---------------------------------------------------------------------------------------


class Transient(NamedTuple):
    """Brute-force integration period after period (the states at tau = 2 pi k)."""

    status: Literal["completed", "contact_loss"]
    states: Array  # (periods completed + 1, state dimension), same layout as OrbitDiagnostics.start_state
    tau_contact_loss: float


# --- Analysis of a converged period --------------------------------------------------------------


def _speeds_at_steps(run: Run) -> Array:
    """x = adot/v0 (Eq. 6') at the run's accepted steps, with abar and deltabar of :meth:`Period.contact_at`."""
    period, m = run.period, run.period.m
    abar = (period.b0 + period.v_scale * run.cores[:, -1]) / m.speed_scale
    d = m.base_offset - m.etahat * np.sin(run.taus)
    if m.compliant:
        d = d + run.cores[:, 0] * period.x_scale
    return kernel.speeds(abar, d, m.inv_n, m.log_cap)


def _refine_roots(run: Run, integrators: Integrators, kind: int) -> list[tuple[float, Array]]:
    """Points (tau, scaled core) where :func:`kernel.point_values` of ``kind`` changes sign between accepted steps.

    Located by Brent's method on re-integrated states: the state inside a step is obtained by
    integrating from the step's start, so the root is located to ~1e-14 in tau on the integrated
    solution itself. A sign change that re-integration does not reproduce (g at rounding level, as
    for a contact that does not move) is dropped.
    """
    period = run.period
    values = kernel.point_values(kind, run.taus, run.cores, period.kernel_constants)
    roots = []
    for k in np.flatnonzero((values[:-1] == 0.0) | (values[:-1] * values[1:] < 0.0)).tolist():
        tau_k, core_k = float(run.taus[k]), run.cores[k]
        if values[k] == 0.0:
            roots.append((tau_k, core_k))
            continue
        in_step = (kind, period, integrators, tau_k, core_k)
        tau_end = float(run.taus[k + 1])
        if values[k] * _g_in_step(tau_end, *in_step) >= 0.0:
            continue
        tau_root = brentq(_g_in_step, tau_k, tau_end, args=in_step, xtol=1e-14, rtol=1e-15)
        roots.append((tau_root, _state_in_step(tau_root, *in_step)[0]))
    return roots


def _state_in_step(tau: float, kind: int, period: Period, integrators: Integrators, tau_k: float,
                   core_k: Array) -> tuple[Array, float]:
    """(scaled core, g of ``kind``) at ``tau`` inside the accepted step that starts at (tau_k, core_k), re-integrated.

    Compiled (:func:`kernel.point_in_step`) where the period is; otherwise, or where that gives up,
    with :func:`integrate_core` (the integrators' methods, their failure an :class:`IntegrationError`).
    """
    k = period.kernel_constants
    if integrators.compiles(period):
        core = np.empty(core_k.shape[0])
        code, value = kernel.point_in_step(kind, k, tau_k, core_k, tau, integrators.rtol, _REINTEGRATION_STEPS, core)
        if code >= 0:
            return core, value
    core = core_k if tau == tau_k else np.array(integrate_core(period, integrators, tau_k, core_k.tolist(), tau))
    return core, float(kernel.point_values(kind, np.array([tau]), core[None, :], k)[0])


def _g_in_step(tau: float, kind: int, period: Period, integrators: Integrators, tau_k: float, core_k: Array) -> float:
    """g of ``kind`` at ``tau`` on the re-integrated solution inside a step (:func:`_state_in_step`)."""
    return _state_in_step(tau, kind, period, integrators, tau_k, core_k)[1]


def summarise(
    model: Model, run: Run, integrators: Integrators, multipliers: Multipliers,
    residual: float, iterations: int, speed_range: tuple[float, float] | None,
) -> SteadyState:
    """The record of a converged period: quadratures, refined extremes of a and of Phi."""
    period = run.period
    dim, speed_scale, v_scale = model.dim, model.speed_scale, period.v_scale
    quad = run.y_end[dim + period.n_var :]
    a0 = float(period.start[-1])
    # Extremes of a (x = 0) and of Phi (of the speed, which decreases with Phi).
    u_values = [0.0, *(float(core[-1]) for _, core in _refine_roots(run, integrators, kernel.TURNING))]
    u_values.append(float(run.y_end[dim - 1]))
    half_range = 0.5 * (max(u_values) - min(u_values)) * v_scale  # in v units: = Abar
    peak_speed = max([float(np.max(np.abs(_speeds_at_steps(run)))),
                      *(abs(period.contact_at(t, core.tolist())[2][0]) for t, core in
                        _refine_roots(run, integrators, kernel.PHI_RATE))])

    abar_m = a0 + quad[0] * v_scale / (TWO_PI * speed_scale)
    a_c, a_s = quad[1] * v_scale / (math.pi * speed_scale), quad[2] * v_scale / (math.pi * speed_scale)
    phat_m, phat_c, phat_s = quad[4] / TWO_PI, quad[5] / math.pi, quad[6] / math.pi
    d_m, d_c, d_s = model.base_offset, 0.0, -model.etahat
    if model.compliant:
        d_m += quad[7] * period.x_scale / TWO_PI
        d_c += quad[8] * period.x_scale / math.pi
        d_s += quad[9] * period.x_scale / math.pi
    in_range = None if speed_range is None else bool(speed_range[0] <= peak_speed <= speed_range[1])
    status: SteadyStatus = "ok"
    message = "periodic steady state"
    if peak_speed > _RESOLVED_SPEED_FRACTION * SPEED_CAP * speed_scale:
        status = "speed_unresolved"
        message = f"peak |d abar/d tau| = {peak_speed / speed_scale:.3g} is within 1e-3 of the numerical speed cap"
    orbit = OrbitDiagnostics(
        start_state=period.start.copy(), A1_over_am=math.hypot(a_c, a_s) / abar_m, abar_c=a_c, abar_s=a_s,
        phat_m=phat_m, phat_c=phat_c, phat_s=phat_s, deltabar_c=d_c, deltabar_s=d_s, peak_speed=peak_speed,
        peak_speed_in_range=in_range, floquet_multipliers=multipliers, periodicity_residual=residual,
        iterations=iterations, integrator=integrators.description(), tau_contact_loss=math.nan,
    )
    return SteadyState(
        level="simulation", status=np.asarray(status), Abar=np.asarray(half_range), abar_m=np.asarray(abar_m),
        w_eff_ratio=np.asarray((quad[3] / TWO_PI) ** 2), A_over_am=np.asarray(half_range / (speed_scale * abar_m)),
        pm_over_abs_pjkr=np.asarray(phat_m / -PHAT_JKR), deltabar_m=np.asarray(d_m),
        stable=np.asarray(np.all(np.abs(multipliers) < 1.0)),
        orbit=orbit, message=message,
    )


def failure_record(status: SteadyStatus, message: str, model: Model, start: Array, iterations: int,
                   integrators: Integrators, tau_loss: float = math.nan) -> SteadyState:
    """The record of a failure: ``status`` and ``message``, the last state tried, every number NaN.

    ``tau_loss`` is the tau of contact loss (``contact_loss`` only); the multipliers are NaN too
    and ``stable`` is False.
    """
    nan = math.nan
    orbit = OrbitDiagnostics(
        np.asarray(start, dtype=float).copy(), nan, nan, nan, nan, nan, nan, nan, nan, nan, None,
        np.full(model.dim, nan, dtype=complex), nan, iterations, integrators.description(), tau_loss,
    )
    return SteadyState.unsolved("simulation", status, message, orbit)



# --- The frozen-contact limit: where the shooting starts -----------------------------------------


def _frozen_drift(model: Model, abar: float, deltabar_mean: float, amplitude: float) -> float:
    """Mean front speed <x(Phi(abar, deltabar(tau)))> over a period, abar frozen.

    deltabar(tau) = deltabar_mean - amplitude sin tau (the phase does not change the mean).
    Its root is the limit omega_check -> infinity of the steady contact radius: the contact cannot
    drift over a period. Periodic trapezoid rule on 512 points (:func:`kernel.frozen_mean_speed`,
    compiled); where abar^2 <= deltabar the contact closes at the capped speed.
    """
    return float(kernel.frozen_mean_speed(abar, deltabar_mean, amplitude, _FROZEN_SINES, model.inv_n,
                                          SPEED_CAP * model.speed_scale))


def _frozen_excitation(model: Model, abar: float) -> tuple[float, complex]:
    """(mean deltabar, complex amplitude of xbar) with the contact radius frozen at ``abar``.

    Rigid: (base_offset, 0). Compliant: with abar fixed, Phat = 2 abar deltabar - (2/3) abar^3 is
    linear in deltabar = xbar + base_offset - etahat sin tau, so Eq. (3') is a linear oscillator with
    the contact stiffness 2 abar (units of E* a_o): with sigma = c_o/kappa,
    mean xbar = (mu/(kappa c_o^2) - sigma (2 abar base_offset - (2/3) abar^3))/(1 + 2 abar sigma), and
    xbar - mean = Im(X e^{i tau}), X = (2 abar sigma etahat + fhat)/(1 + 2 abar sigma - omega_bar^2 + 2i zeta omega_bar)
    with the force rig's drive fhat (Eq. 13; model docstring) (the denominator is kept away from 0 at an
    undamped resonance: a guess, not a result).
    """
    if not model.compliant:
        return model.base_offset, 0j
    sigma = model.compliance
    stiffness = 1.0 + 2.0 * abar * sigma
    x_mean = (model.force_offset - sigma * (2.0 * abar * model.base_offset - (2.0 / 3.0) * abar**3)) / stiffness
    denominator = complex(stiffness - model.omega_bar**2, 2.0 * model.zeta * model.omega_bar)
    if abs(denominator) < 1e-2 * stiffness:
        denominator = 1e-2 * stiffness * (denominator / abs(denominator) if denominator != 0 else 1.0)
    return x_mean + model.base_offset, (2.0 * abar * sigma * model.etahat + model.force_drive) / denominator


def _frozen_orbit_drift(abar: float, model: Model) -> float:
    """Mean front speed of the frozen contact ``abar`` under its frozen excitation (rigid or spring).

    :func:`_frozen_drift` with the contact displacement deltabar = mean + Im((X - etahat) e^{i tau})
    of :func:`_frozen_excitation` (limit omega_check -> infinity of Eqs. 3', 6').
    """
    d_mean, x_hat = _frozen_excitation(model, abar)
    return _frozen_drift(model, abar, d_mean, abs(x_hat - model.etahat))


def frozen_start(model: Model) -> Array | None:
    """Start of the periodic orbit in the limit omega_check -> infinity (a guess for the shooting).

    The contact radius is the largest root of the frozen drift (:func:`_frozen_drift`) with the
    contact displacement deltabar = mean + Im((X - etahat) e^{i tau}) of :func:`_frozen_excitation`;
    None when no root is bracketed.
    """
    hi = 1.0
    while _frozen_orbit_drift(hi, model) > 0:
        hi *= 2.0
        if hi > MAX_ABAR:
            return None
    lo = 0.5 * hi
    while _frozen_orbit_drift(lo, model) <= 0:
        lo, hi = 0.5 * lo, lo
        if lo < 1e-3:
            return None
    abar = brentq(_frozen_orbit_drift, lo, hi, args=(model,), xtol=1e-12)
    if not model.compliant:
        return np.array([abar])
    d_mean, x_hat = _frozen_excitation(model, abar)
    return np.array([d_mean - model.base_offset + x_hat.imag, x_hat.real, abar])



# --- Brute-force transient -----------------------------------------------------------------------


def transient(
    problem: Problem,
    *,
    periods: int,
    initial_state: ArrayLike | None = None,
    rtol: float = 1e-12,
    integrator: Integrator = "auto",
    contact_loss_abar: float = 1e-3,
) -> Transient:
    """Brute-force integration of ``problem`` from the static state (or ``initial_state``) over ``periods`` periods.

    The reference the shooting is checked against; each period is integrated from the state the
    previous one ended in (the front displacement v is re-based every period, so abar keeps
    full precision). Raises :class:`RuntimeError` if the integrator fails.
    """
    if periods < 1:
        raise ValueError("periods must be at least 1")
    model = Model(problem, contact_loss_abar)
    state = absolute_start(model, initial_state)
    integrators = Integrators(integrator, rtol)
    states = [state]
    v_scale = v_scale_estimate(model, float(state[-1]))
    for k in range(periods):
        period = Period(model, state, v_scale, x_scale(model, state))
        try:
            run = run_period(period, integrators, full=False, transient=True)
        except IntegrationError as error:
            raise RuntimeError(f"transient integration failed in period {k + 1}: {error}") from error
        if not math.isnan(run.lost_at):
            return Transient("contact_loss", np.array(states), TWO_PI * k + run.lost_at)
        v_scale = observed_v_scale(run)
        state = period.absolute(run.y_end.tolist())
        states.append(state)
    return Transient("completed", np.array(states), math.nan)
