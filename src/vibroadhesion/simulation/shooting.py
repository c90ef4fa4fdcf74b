"""Periodic steady state of the full model by shooting on the one-period map: :func:`steady_state`.

Shooting
--------
The one-period map (:mod:`vibroadhesion.simulation.integrators`) in the coordinates
(xbar, xbar', b = omega_check c_o abar) has the residual
r = (xbar(2pi) - xbar(0), xbar'(2pi) - xbar'(0), v(2pi)), and its Jacobian minus the identity,
Psi = M - I (M the monodromy matrix), obeys

    Psi' = J(tau) (I + Psi),   Psi(0) = 0,

integrated directly (not M) so that the multipliers 1 + eig(Psi), which tend to 1 as
omega_check -> infinity, keep their distance from 1 to full precision (rigid: lambda = ln M,
lambda' = J, exact for multipliers near 0 and near 1). J is the Jacobian of the right-hand side:
with dPhi/dabar = (abar^2 - deltabar)(3 abar^2 + deltabar)/abar^2, dPhi/ddeltabar =
-2 (abar^2 - deltabar)/abar, dPhat/dabar = 2 deltabar - 2 abar^2, dPhat/ddeltabar = 2 abar and
dx/dPhi from the inverse law. For n > 1, dx/dPhi ~ |Phi - 1|^(1/n - 1) is unbounded where the
front reverses; no error-controlled integrator resolves that coefficient, so Psi is then taken
from central differences of the map (step 1e-5 of the scaled state, accuracy ~1e-5).

Iteration. The Newton correction g = Psi^{-1} r is ~ z - z* near a simple fixed point and
~ (z - z*)/p near one of order p (r ~ |z - z*|^p: a contact that barely moves has x ~ |Phi - 1|^(1/n)),
where plain Newton would crawl (p > 1) or oscillate (p < 1); steps therefore solve B dz = -g with B
a secant (Broyden) estimate of dg/dz started at the identity (plain Newton). The orbit is accepted
when the step is below 1e-11 of the state, or below the uncertainty of the fixed point that an
integration error of 10 rtol in r causes (|Psi^{-1}| e, e_i = 10 rtol max(1, range_i)), or when r itself is
at rounding level (10 rtol max(1, range_i), or a drift of abar below its resolution). Both tolerances go
component by component with the scaled range of that component over the period (absolute, 10 rtol, for the
O(1) components the fitted scales give; relative to the component's own size where it is larger): a tolerance
that scaled with the largest component let an unconverged orbit through whenever one component was huge (a
scale far off, as the force rig's first v scale before it included the drive), and now does not (tested).

First period and starting guess. The experiment starts from the static state (Eq. 10). Its first
period is integrated (core only, with LSODA, which switches to BDF: while the base compresses the
contact faster than a^2 = deltabar allows, the front slides along Phi ~ 0 at a huge closing speed,
a stiff phase; for the rigid fixation with n <= 1 the compiled DOP853 instead, whose ~100-2000
explicit steps cost less than LSODA's Python right-hand side; at rtol 1e-9 unless a decision is in
doubt, :func:`_first_period`) and decides ``contact_loss``. The
iteration then starts from the limit omega_check -> infinity of the orbit (abar frozen over a
period: the root of the mean front speed; for the compliant fixation with the linear response of
the spring to the frozen contact, whose stiffness is 2 abar;
:func:`vibroadhesion.simulation.orbits.frozen_start`), unless the static state is already periodic
to rounding.

Rigid fixation: the scalar flow is order preserving (solutions of a scalar ODE do not cross),
so the map abar(0) -> abar(2 pi) is increasing and the iterates from any start move
monotonically to the nearest fixed point on the side given by the sign of r. The search keeps a
bracket of that fixed point (the static state is one end), bisecting when a step leaves it: the
periodic state found is the one the transient from the static state reaches (if there is one
fixed point in between), or ``contact_loss`` when that transient loses the contact. Its Floquet
multiplier d abar(2pi)/d abar(0) = exp(int_0^2pi dF/dabar dtau) is positive.

Compliant fixation: damped (halving) Newton–Broyden on the 3-D map (from the static state, or from
a given state for continuation); all three Floquet multipliers are returned, so the stability of
the orbit found is known (it need not be the one the transient reaches).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import cast

import numpy as np
from numpy.typing import ArrayLike

from vibroadhesion.core.problem import Problem
from vibroadhesion.core.records import SteadyState
from vibroadhesion.simulation.integrators import (
    IntegrationError,
    Integrator,
    Integrators,
    Period,
    Run,
    run_period,
)
from vibroadhesion.simulation.model import Array, Model, absolute_start
from vibroadhesion.simulation.orbits import MAX_ABAR, failure_record, frozen_start, summarise
from vibroadhesion.simulation.scales import (
    observed_v_scale,
    periodic_to_rounding,
    scaled_core_ranges,
    v_scale_estimate,
    x_scale,
)

#: Central-difference step of the one-period map in the scaled coordinates (n > 1).
_FD_STEP = 1e-5
#: Newton: relative size of the last correction at which the orbit is accepted.
_NEWTON_XTOL = 1e-11
#: Global integration error of a period in units of rtol times each component's scaled range: a
#: Newton correction below the uncertainty it causes in the fixed point also ends the iteration.
_GLOBAL_ERROR_FACTOR = 10.0


#: Tolerance of the first period from the static state, which only decides contact loss, the side of the
#: fixed point and the scale of v (:func:`_first_period`).
_FIRST_PERIOD_RTOL = 1e-9
#: The first period is repeated at rtol when its residual is within this many of its tolerances of
#: periodic in a component, or its contact radius comes within this factor of the loss threshold.
_FIRST_PERIOD_MARGIN, _LOSS_MARGIN = 1e4, 2.0


# --- Shooting ------------------------------------------------------------------------------------


def _first_period(model: Model, start: Array, v_scale: float, integrators: Integrators) -> Run:
    """The physical first period from the static state ``start`` (core only, the transient's integrator).

    It decides only whether the contact is lost (then that is the answer), on which side of the
    start the fixed point lies (the sign of the residual) and the scale of v, so it runs at the
    looser :data:`_FIRST_PERIOD_RTOL`, and again at ``integrators.rtol`` where that leaves a decision
    in doubt: the looser integration gave up, lost the contact or came within :data:`_LOSS_MARGIN` of
    the loss threshold, or ended with a residual within :data:`_FIRST_PERIOD_MARGIN` looser
    tolerances (1e-5 of the scale) of 0 in a component (a start periodic to rounding, or a sign the
    looser run cannot tell). Measured at the cases of ``benchmarks/simulate.py`` (rigid n = 0.531,
    h1 = 20-100 um, omega_check 1e4-1e9; n = 0.05 and 4; compliant), the looser end state differs from
    the one at rtol 1e-12 by at most 8.7e-8 of the scale where the contact is kept: 1/100 of the margin.
    Only a period that runs with the compiled DOP853 (rigid, n <= 1) runs looser first: elsewhere the first
    period is LSODA's, and the looser run followed by a doubtful decision cost more than it saved (rigid n = 4,
    omega_check = 1e8, h1 = 20 um: 3.8 s against 0.59 s per steady state).
    """
    period = Period(model, start, v_scale, x_scale(model, start))
    if not integrators.compiles(period, transient=True):
        return run_period(period, integrators, full=False, transient=True)
    looser = integrators.with_rtol(max(integrators.rtol, _FIRST_PERIOD_RTOL))
    try:
        run = run_period(period, looser, full=False, transient=True)
    except IntegrationError:
        return run_period(period, integrators, full=False, transient=True)
    residual = np.abs(run.y_end[: period.dim] - np.array(period.core_start()))
    doubtful = (not math.isnan(run.lost_at) or period.abar(run.u_range[0]) < _LOSS_MARGIN * model.contact_loss_abar
                or bool(np.any(residual <= _FIRST_PERIOD_MARGIN * looser.rtol * scaled_core_ranges(run))))
    return run_period(period, integrators, full=False, transient=True) if doubtful else run


def _evaluate(model: Model, start: Array, v_scale: float, integrators: Integrators) -> Run:
    """One period from ``start`` with the variational equations and the quadratures."""
    period = Period(model, start, v_scale, x_scale(model, start))
    return run_period(period, integrators, full=True)


def _psi(run: Run, integrators: Integrators) -> Array:
    """Psi(2pi) = M - I at the run's start, in its scaled coordinates.

    From the variational equations (n <= 1), or by central differences of the one-period map
    with the step _FD_STEP in the scaled coordinates (n > 1; absolute error ~1e-5 from the
    ~1e-10 integration error of the residual, which limits the multipliers to that accuracy).
    """
    period, dim = run.period, run.period.dim
    if period.m.variational:
        return run.y_end[dim : dim + dim * dim].reshape(dim, dim)
    unscale = [period.x_scale, period.x_scale, period.v_scale / period.m.speed_scale][-dim:]
    psi = np.empty((dim, dim))
    for j in range(dim):
        residuals = []
        for sign in (1.0, -1.0):
            shifted = period.start.copy()
            shifted[j] += sign * _FD_STEP * unscale[j]
            neighbour = Period(period.m, shifted, period.v_scale, period.x_scale)
            neighbour_run = run_period(neighbour, integrators, full=False)
            if not math.isnan(neighbour_run.lost_at):
                raise IntegrationError("contact lost next to the orbit: no finite-difference monodromy")
            residuals.append(neighbour_run.y_end[:dim] - np.array(neighbour.core_start()))
        psi[:, j] = (residuals[0] - residuals[1]) / (2.0 * _FD_STEP)
    return psi


# --- Rigid fixation: bracketed Newton–secant on the scalar map -----------------------------------


@dataclass
class _Bracket:
    """Bracket of the fixed point of the rigid one-period map that the iterates approach.

    ``lower`` is the largest a0 known to have r > 0 or to lose contact (the fixed point lies
    above it; ``lower_is_loss`` says which), ``upper`` the smallest a0 known to have r < 0.
    """

    lower: float = 0.0
    lower_is_loss: bool = True
    upper: float = math.inf

    def record(self, a: float, drift: float) -> None:
        """A period from ``a`` ended with r = ``drift`` (any quantity with the sign of r)."""
        if drift > 0:
            self.lower, self.lower_is_loss = a, False
        elif drift < 0:
            self.upper = a

    def record_loss(self, a: float) -> None:
        """A period from ``a`` lost the contact."""
        self.lower, self.lower_is_loss = a, True

    def contains(self, a: float) -> bool:
        """Whether ``a`` lies strictly inside the bracket (False for NaN)."""
        return self.lower < a < self.upper

    def fallback(self, a: float, a_next: float) -> float:
        """``a_next`` if inside; else the midpoint, or (no upper end yet) a doubling of the step from ``lower``."""
        if self.contains(a_next):
            return a_next
        if math.isfinite(self.upper):
            return 0.5 * (self.lower + self.upper)
        if self.lower_is_loss or a <= self.lower:
            return 2.0 * max(a, self.lower)
        return a + 2.0 * max(a - self.lower, 1e-3 * a)

    def collapsed(self) -> bool:
        """Whether the bracket has shrunk to rounding level."""
        return math.isfinite(self.upper) and self.upper - self.lower <= 4e-16 * self.upper


def _rigid_drift_and_slope(model: Model, run: Run, integrators: Integrators) -> tuple[float, float, float]:
    """(r, r'(a0), ln multiplier) of a rigid period: r = abar(2pi) - abar(0), r' = multiplier - 1.

    From the variational equation lambda = ln(d abar/d a0) (n <= 1: r' = expm1(lambda)), or from
    the finite-difference Psi (n > 1).
    """
    u_end = float(run.y_end[0])
    drift = run.period.v_scale * u_end / model.speed_scale  # r = abar(2pi) - abar(0)
    if model.variational:
        log_multiplier = float(run.y_end[1])
        slope = math.expm1(log_multiplier)  # r'(a0) = multiplier - 1
    else:
        slope = float(_psi(run, integrators)[0, 0])
        log_multiplier = math.log1p(slope) if slope > -1 else -math.inf
    return drift, slope, log_multiplier


def _secant_step(model: Model, run: Run, integrators: Integrators, a: float, drift: float, slope: float,
                 previous: tuple[float, float] | None) -> tuple[float, float, tuple[float, float]]:
    """(step, noise, (a0, g)): secant step on the Newton correction g = r/r' (slope 1 to start).

    ``noise`` is the uncertainty of the fixed point caused by the integration error of v(2pi);
    ``previous`` is the (a0, g) of the last evaluation with r' < 0.
    """
    g = drift / slope
    g_slope = 1.0
    if previous is not None and previous[0] != a:
        secant = (g - previous[1]) / (a - previous[0])
        g_slope = secant if secant > 0 else 1.0
    step = -g / g_slope
    noise = (_GLOBAL_ERROR_FACTOR * integrators.rtol * float(scaled_core_ranges(run)[0]) * run.period.v_scale
             / (model.speed_scale * abs(slope) * g_slope))
    return step, noise, (a, g)


def _shoot_rigid(model: Model, start: Array, integrators: Integrators, max_iterations: int,
                 speed_range: tuple[float, float] | None, guess: float | None) -> SteadyState:
    """Bracketed Newton–secant iteration on r(a0) = abar(2pi) - a0 (module docstring).

    When ``guess`` is given, ``start`` is the static state: the first period is integrated from
    it (the physical transient), and the iteration begins at ``guess`` if that lies on the side
    of the start that r(start) points to. The scalar variational equation is integrated as
    lambda = ln(d abar(tau)/d a0), lambda' = dF/dabar, so that the multiplier e^lambda and
    r'(a0) = expm1(lambda) keep full precision however close to 0 or to 1 the multiplier is.
    Steps follow the Newton correction g = r/r', which near a root of any order p (r ~ |a0 - a*|^p,
    as when the contact barely moves and x ~ |Phi - 1|^(1/n)) is ~ (a0 - a*)/p: secant steps on
    g (starting from its ideal slope 1) converge superlinearly where plain Newton would crawl
    (p > 1) or oscillate (p < 1); a step leaving the bracket is replaced by bisection.
    """
    a = float(start[0])
    v_scale = v_scale_estimate(model, a)
    bracket = _Bracket()
    if guess is not None:
        # The physical first period from the static state (core only, stiff integrator): contact
        # loss there is the answer; otherwise it tells on which side of the start the state lies.
        first = _first_period(model, start, v_scale, integrators)
        if not math.isnan(first.lost_at):
            return failure_record("contact_loss", f"contact lost at tau = {first.lost_at:.6g} in the first period "
                                  f"from the static state abar = {a:.6g}", model, start, 1, integrators, first.lost_at)
        v_scale = observed_v_scale(first)
        bracket.record(a, float(first.y_end[0]))
        # A static state that is already periodic to rounding (a contact that does not move) is
        # the state reached; otherwise the iteration starts from the guess.
        if bracket.contains(guess) and not periodic_to_rounding(first, integrators):
            a = guess
    periods = 0 if guess is None else 1
    previous: tuple[float, float] | None = None  # (a0, g) of the last evaluation with r' < 0
    while periods < max_iterations:
        run = _evaluate(model, np.array([a]), v_scale, integrators)
        periods += 1
        a_next = math.nan
        if not math.isnan(run.lost_at):
            bracket.record_loss(a)
        else:
            v_scale = observed_v_scale(run)
            drift, slope, log_multiplier = _rigid_drift_and_slope(model, run, integrators)
            bracket.record(a, drift)
            if slope < 0:
                step, noise, previous = _secant_step(model, run, integrators, a, drift, slope, previous)
                if periodic_to_rounding(run, integrators) or abs(step) <= max(_NEWTON_XTOL * a, noise):
                    multiplier = np.array([math.exp(log_multiplier)], dtype=complex)
                    return summarise(model, run, integrators, multiplier, abs(drift) / a, periods, speed_range)
                a_next = a + step
        a_next = bracket.fallback(a, a_next)
        if bracket.collapsed():
            if bracket.lower_is_loss:
                return failure_record("contact_loss", "the transient from the start state drifts to contact loss: "
                                      "no periodic state between the start and the loss boundary", model,
                                      np.array([a]), periods, integrators)
            break
        if a_next > MAX_ABAR:
            break
        a = a_next
    return failure_record("not_converged", f"shooting did not converge in {periods} periods",
                          model, np.array([a]), periods, integrators)


# --- Compliant fixation: damped Newton–Broyden on the 3-D map ------------------------------------

#: (g and the residual in absolute units, noise of each component of g in scaled units, residual at rounding level).
_Correction = tuple[Array, Array, Array, bool]


def _correction(model: Model, run: Run, integrators: Integrators) -> _Correction | None:
    """The Newton correction g = Psi^{-1} r of a compliant period (None where Psi is singular).

    Returns g and the residual r in absolute units, the noise of each component of g in scaled units (the
    uncertainty |Psi^{-1}| e that an integration error e_i = 10 rtol max(1, range_i) of each component of r
    causes, :func:`vibroadhesion.simulation.scales.scaled_core_ranges`) and whether r is at rounding level.
    """
    period = run.period
    residual = run.y_end[:3] - np.array(period.core_start())
    psi = _psi(run, integrators)
    try:
        g_scaled = np.linalg.solve(psi, residual)
        noise = _GLOBAL_ERROR_FACTOR * integrators.rtol * (np.abs(np.linalg.inv(psi)) @ scaled_core_ranges(run))
    except np.linalg.LinAlgError:
        return None
    unscale = np.array([period.x_scale, period.x_scale, period.v_scale / model.speed_scale])
    return g_scaled * unscale, residual * unscale, noise, periodic_to_rounding(run, integrators)


def _broyden_step(broyden: Array, z: Array, g: Array, previous: tuple[Array, Array] | None,
                  scales: Array) -> tuple[Array, Array]:
    """(B, dz): the Broyden update of B (dg/dz, in the metric of ``scales``) and the step B dz = -g.

    ``previous`` is the (z, g) of the last iterate; a singular B is reset to the identity.
    """
    weight = 1.0 / scales**2
    if previous is not None:
        s_k, y_k = z - previous[0], g - previous[1]
        denominator = float(s_k @ (weight * s_k))
        if denominator > 0:
            broyden = broyden + np.outer(y_k - broyden @ s_k, weight * s_k) / denominator
    try:
        # numpy's stubs type solve() of any real operands as floating[Any]; float64 ones give float64.
        step = -cast(Array, np.linalg.solve(broyden, g))
    except np.linalg.LinAlgError:
        broyden = np.eye(3)
        step = -g
    return broyden, step


def _damped_step(model: Model, z: Array, step: Array, v_scale: float, scales: Array, merit: float,
                 integrators: Integrators, periods: int, max_iterations: int,
                 ) -> tuple[tuple[Array, Run, _Correction] | None, int, bool]:
    """Halve the step (at most 5 times) while the trial orbit loses the contact or its |g| grows.

    Returns (the accepted (z, run, correction) or None, periods used so far, whether every
    halving failed); None without exhaustion means the period budget ran out.
    """
    for halving in range(6):
        trial = z + 0.5**halving * step
        if trial[2] <= 0:
            continue
        periods += 1
        try:
            trial_run = _evaluate(model, trial, v_scale, integrators)
        except IntegrationError:
            continue
        trial_correction = _correction(model, trial_run, integrators) if math.isnan(trial_run.lost_at) else None
        if trial_correction is not None and (
                float(np.max(np.abs(trial_correction[0]) / scales)) < merit or halving == 5):
            return (trial, trial_run, trial_correction), periods, False
        if periods >= max_iterations:
            return None, periods, False
    return None, periods, True


def _shoot_compliant(model: Model, start: Array, integrators: Integrators, max_iterations: int,
                     speed_range: tuple[float, float] | None, guess: Array | None) -> SteadyState:
    """Damped Newton–Broyden iteration on the 3-D one-period map.

    The Newton correction g = Psi^{-1} r (Psi = M - I from the variational equations) is, as in
    the scalar case, ~ z - z* in the well-conditioned directions and ~ (z - z*)/p along a direction
    in which the root is of order p (the contact barely moving); steps solve B dz = -g with B a
    Broyden secant estimate of dg/dz that starts at the identity (plain Newton). A step is halved
    (at most 5 times) while the trial orbit loses the contact or its |g| grows. All vectors are
    compared in the scales (S, S, A_ref) of xbar, xbar' and abar. When ``guess`` is given,
    ``start`` is the static state: the first period is integrated from it (the physical
    transient; contact loss there is the answer) and the iteration begins at ``guess``.
    """
    z = start.copy()
    v_scale = v_scale_estimate(model, float(z[2]))
    periods = 0
    if guess is not None:
        first = _first_period(model, z, v_scale, integrators)
        periods += 1
        if not math.isnan(first.lost_at):
            return failure_record("contact_loss", f"contact lost at tau = {first.lost_at:.6g} in the first period "
                                  f"from the static state {z.tolist()}", model, z, 1, integrators, first.lost_at)
        if not periodic_to_rounding(first, integrators):
            z = guess.copy()
    run = _evaluate(model, z, v_scale, integrators)
    periods += 1
    if not math.isnan(run.lost_at):
        return failure_record("contact_loss", f"contact lost at tau = {run.lost_at:.6g} in the first period from "
                              f"{z.tolist()}", model, z, periods, integrators, run.lost_at)
    broyden = np.eye(3)
    previous: tuple[Array, Array] | None = None
    current = _correction(model, run, integrators)
    while current is not None and periods < max_iterations:
        v_scale = observed_v_scale(run)
        g, residual, noise, at_rounding = current
        scales = np.array([run.period.x_scale, run.period.x_scale, max(v_scale / model.speed_scale, 1e-14 * z[2])])
        broyden, step = _broyden_step(broyden, z, g, previous, scales)
        converged = np.all(np.abs(step) <= _NEWTON_XTOL * np.array([scales[0], scales[1], z[2]]))
        if converged or at_rounding or bool(np.all(np.abs(step) / scales <= noise)):
            relative = np.abs(residual) / np.array([scales[0], scales[1], z[2]])
            multipliers = 1.0 + np.linalg.eigvals(_psi(run, integrators))
            return summarise(model, run, integrators, multipliers, float(np.max(relative)), periods, speed_range)
        merit = float(np.max(np.abs(g) / scales))
        previous = (z.copy(), g)
        accepted, periods, exhausted = _damped_step(model, z, step, v_scale, scales, merit, integrators, periods,
                                                    max_iterations)
        if exhausted:
            return failure_record("not_converged", "every damped step lost the contact or had a singular Jacobian",
                                  model, z, periods, integrators)
        if accepted is not None:
            z, run, current = accepted
    if current is None:
        return failure_record("not_converged", "singular monodromy matrix minus identity", model, z, periods,
                              integrators)
    return failure_record("not_converged", f"shooting did not converge in {periods} periods", model, z, periods,
                          integrators)


def steady_state(
    problem: Problem,
    *,
    initial_state: ArrayLike | None = None,
    speed_range: tuple[float, float] | None = None,
    rtol: float = 1e-12,
    integrator: Integrator = "auto",
    contact_loss_abar: float = 1e-3,
    max_iterations: int = 40,
) -> SteadyState:
    """Periodic steady state of the full model for ``problem`` by shooting on the one-period map.

    The fixation (rigid or compliant) is ``problem.fixation``. ``initial_state`` (layout of
    ``OrbitDiagnostics.start_state``) defaults to the static state (Eq. 10); a continuation passes the
    previous orbit's ``orbit.start_state``. ``speed_range`` = (lo, hi) is the range of |adot|/v0 in which
    the rate law was characterised. ``integrator``: "auto" (see :class:`Integrators`),
    "fortran-dop853" (:class:`scipy.integrate.ode`, also for the rigid periods that "auto" compiles), or a
    :func:`scipy.integrate.solve_ivp` method name for everything. Numerical failure and contact loss are returned as the
    ``status`` of the record, never as numbers.
    """
    model = Model(problem, contact_loss_abar)
    start = absolute_start(model, initial_state)
    integrators = Integrators(integrator, rtol)
    try:
        guess = frozen_start(model) if initial_state is None else None
        if model.compliant:
            return _shoot_compliant(model, start, integrators, max_iterations, speed_range, guess)
        return _shoot_rigid(model, start, integrators, max_iterations, speed_range,
                            None if guess is None else float(guess[0]))
    except IntegrationError as error:
        return failure_record("integration_failure", str(error), model, start, 0, integrators)


