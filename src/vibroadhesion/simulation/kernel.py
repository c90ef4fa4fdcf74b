"""One period of the full model compiled with numba: the right-hand sides of Eqs. (3'), (6') and DOP853.

The rigid one-period problem (:mod:`vibroadhesion.simulation.integrators`) is a scalar ODE for the
scaled front displacement u = v/V (Eq. 6'), carried with the log-multiplier lambda of its
variational equation and seven quadratures; the compliant one adds the spring (Eq. 3') in the
scaled xi = xbar/S, eta = xbar'/S, with Psi = M - I (9 components) and ten quadratures. Called from
scipy's integrators, a right-hand side costs ~1.5-3 us a call in Python and a period at rtol 1e-12
~1500 calls; here the right-hand sides (:func:`state_rates`, the same
:func:`vibroadhesion.simulation.model.contact_kernel` compiled) and the whole Dormand–Prince 8(5,3)
loop (:func:`integrate`) run compiled, ~20 times faster per period.

The integrator is the explicit Runge–Kutta method of order 8 of Hairer, Nørsett & Wanner
(Solving ODEs I, Sec. II.10) with the coefficients and the step-size control of
:class:`scipy.integrate.DOP853` (the error norm that combines the 5th- and 3rd-order estimates,
safety 0.9, factors in [0.2, 10], initial step of Sec. II.4), one tolerance rtol = atol for the
scaled state. It records every accepted step (tau, u) and stops at the first accepted step with
abar below the contact-loss threshold (model docstring). Compiled code is cached on disk
(numba ``cache=True``): a process pays the compilation only when the cache is missing or stale.

Constants of a period (:data:`CONSTANTS`, in this order): b0 = speed_scale abar(0), V, 1/speed_scale,
1/V, base_offset, etahat, 1/n, ln(speed cap), 1.0 if the variational equation is integrated
(n <= 1) else 0.0, 1.0 if compliant else 0.0; then, compliant (else 0): S, mu/(kappa c_o^2)/S,
(c_o/kappa)/S, 1/omega_bar^2, 2 zeta omega_bar, c_o/kappa (integrators module, Eq. 3'), fhat/S (the force
rig's drive, Eq. 13, model docstring); last the withdrawal ramp, d base_offset/d tau = -ramp (Eq. 11 with
h0 = h0_start + V t: ramp = V R/(a_o^2 omega); 0 for a periodic steady state,
:mod:`vibroadhesion.simulation.withdrawal`): deltabar = base_offset - ramp tau - etahat s(tau) sin tau (+ xbar);
then the excitation schedule s(tau) (:mod:`vibroadhesion.simulation.excitation`) as s0, s1, tau_a, tau_b in the
period's time: s = s0 before tau_a, s1 from tau_b on, linear in between; it scales the base amplitude etahat
(Eq. 11) and the force rig's drive fhat (Eq. 13). The constant excitation s = 1 (:data:`CONSTANT_EXCITATION`)
leaves every product etahat s, fhat s equal to etahat, fhat to the bit. :func:`integrate` splits its interval at
tau_a and tau_b and gives each piece the level of its own side (s1 := s0 before tau_a, s0 := s1 from tau_b on), so
that no step straddles a switch and the stages of a step that ends at one see their own side's level.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit
from scipy.integrate._ivp import dop853_coefficients as _dop853

from vibroadhesion.simulation.model import Array, contact_kernel

#: Names of the entries of the constants array of a period (module docstring).
CONSTANTS = ("b0", "v_scale", "inv_speed_scale", "inv_v_scale", "base_offset", "etahat", "inv_n", "log_cap",
             "variational", "compliant", "x_scale", "scaled_force_offset", "scaled_compliance", "inv_omega_bar2",
             "damping", "compliance", "scaled_force_drive", "ramp", "excitation_s0", "excitation_s1",
             "excitation_tau_a", "excitation_tau_b")
#: Indices of the excitation schedule s0, s1, tau_a, tau_b (module docstring) in the constants.
_S0, _S1, _TAU_A, _TAU_B = (CONSTANTS.index(name) for name in
                            ("excitation_s0", "excitation_s1", "excitation_tau_a", "excitation_tau_b"))
#: The schedule of a constant excitation, s = 1 (a periodic steady state): s0, s1, tau_a, tau_b.
CONSTANT_EXCITATION = (1.0, 1.0, math.inf, math.inf)
#: Components of the full rigid state: u, lambda and the quadratures u, u cos, u sin, sqrt(w/w0), Phat,
#: Phat cos, Phat sin (integrators module).
FULL_SIZE = 9
#: Components of the full compliant state: xi, eta, u, Psi (9, row-major) and the quadratures u, u cos,
#: u sin, sqrt(w/w0), Phat, Phat cos, Phat sin, xi, xi cos, xi sin.
COMPLIANT_FULL_SIZE = 22
#: Return codes of :func:`integrate`.
REACHED, CONTACT_LOST, STEP_BUDGET, STEP_UNDERFLOW = 0, 1, -1, -2
#: Kinds of :func:`point_values`: abar (Phi - 1) (extremes of a) and dPhi/dtau (extremes of Phi).
TURNING, PHI_RATE = 0, 1

_STAGES = _dop853.N_STAGES  # 12 stages, the 13th is the first of the next step
_A = np.ascontiguousarray(_dop853.A[:_STAGES, :_STAGES])
_B = np.ascontiguousarray(_dop853.B)
_C = np.ascontiguousarray(_dop853.C[:_STAGES])
_E3 = np.ascontiguousarray(_dop853.E3)
_E5 = np.ascontiguousarray(_dop853.E5)
_SAFETY, _MIN_FACTOR, _MAX_FACTOR, _ERROR_EXPONENT = 0.9, 0.2, 10.0, -1.0 / 8.0

compiled_contact_kernel = njit(cache=True)(contact_kernel)


def _excitation_factor(tau: float, k: Array) -> float:
    """s(tau) of the excitation schedule in the constants ``k`` (Eq. 11 with etahat s(tau); module docstring).

    s0 before tau_a, s1 from tau_b on (right-continuous at a switch, tau_a = tau_b), linear in between.
    """
    if tau < k[_TAU_A]:
        return float(k[_S0])
    if tau >= k[_TAU_B]:
        return float(k[_S1])
    return float(k[_S0] + (k[_S1] - k[_S0]) * (tau - k[_TAU_A]) / (k[_TAU_B] - k[_TAU_A]))


_compiled_excitation_factor = njit(cache=True)(_excitation_factor)


def _excitation_factors(taus: Array, k: Array) -> Array:
    """(s, ds/dtau) of the excitation schedule at each of ``taus`` (rows 0 and 1; Eq. 11 with etahat s(tau)).

    ds/dtau = (s1 - s0)/(tau_b - tau_a) on [tau_a, tau_b), 0 elsewhere (a switch is a jump of s, not a rate).
    """
    out = np.zeros((2, taus.shape[0]))
    for i in range(taus.shape[0]):
        out[0, i] = _compiled_excitation_factor(taus[i], k)
        if k[_TAU_A] <= taus[i] < k[_TAU_B]:
            out[1, i] = (k[_S1] - k[_S0]) / (k[_TAU_B] - k[_TAU_A])
    return out


excitation_factors = njit(cache=True)(_excitation_factors)


def _rigid_rates(tau: float, y: Array, out: Array, k: Array) -> None:
    """Rates of the scaled rigid state into ``out``: Eq. (6') for u; with 9 components lambda and the quadratures too.

    u' = x/V with x = f^{-1}(Phi(abar, deltabar)) (Eq. 6'), abar = (b0 + V u)/speed_scale and deltabar =
    base_offset - ramp tau - etahat s(tau) sin tau (Eqs. 7, 11'); lambda' = (dx/dabar)/speed_scale (the
    variational equation of the shooting module, 0 for n > 1); then u, u cos, u sin, sqrt(w/w0) (Eq. 5'), Phat (Eq. 4'),
    Phat cos, Phat sin.
    """
    u = y[0]
    abar = (k[0] + k[1] * u) * k[2]
    s = math.sin(tau)
    d = k[4] - k[17] * tau - k[5] * _compiled_excitation_factor(tau, k) * s
    x, x_a, _, p, w = compiled_contact_kernel(abar, d, k[6], k[7])
    out[0] = x * k[3]
    if out.shape[0] > 1:
        c = math.cos(tau)
        out[1] = x_a * k[2] if k[8] > 0.0 else 0.0
        out[2], out[3], out[4] = u, u * c, u * s
        out[5], out[6], out[7], out[8] = w, p, p * c, p * s


_compiled_rigid_rates = njit(cache=True)(_rigid_rates)


def _compliant_rates(tau: float, y: Array, out: Array, k: Array) -> None:
    """Rates of the scaled compliant state into ``out``: Eqs. (3'), (6'); with 22 components Psi and the quadratures.

    xi' = eta, eta' = (mu/(kappa c_o^2) - (c_o/kappa) Phat - S xi - 2 zeta omega_bar S eta + fhat s(tau) sin tau)
    / (omega_bar^2 S) (Eqs. 3', 13), u' = x/V (Eq. 6') with deltabar = S xi + base_offset - ramp tau
    - etahat s(tau) sin tau (Eqs. 7, 11'); then
    Psi' = J (I + Psi) with J = [[0, 1, 0], [j10, j11, j12], [j20, 0, j22]] (0 for n > 1, shooting
    module) and u, u cos, u sin, sqrt(w/w0), Phat, Phat cos, Phat sin, xi, xi cos, xi sin.
    """
    xi, eta, u = y[0], y[1], y[2]
    abar = (k[0] + k[1] * u) * k[2]
    s = math.sin(tau)
    level = _compiled_excitation_factor(tau, k)
    d = k[10] * xi + k[4] - k[17] * tau - k[5] * level * s
    x, x_a, x_d, p, w = compiled_contact_kernel(abar, d, k[6], k[7])
    out[0], out[1], out[2] = eta, (k[11] - k[12] * p - xi - k[14] * eta + k[16] * level * s) * k[13], x * k[3]
    if out.shape[0] == 3:
        return
    out[3:12] = 0.0
    if k[8] > 0.0:
        j10, j11 = (-1.0 - 2.0 * k[15] * abar) * k[13], -k[14] * k[13]
        j12 = -k[12] * (2.0 * d - 2.0 * abar * abar) * k[13] * k[1] * k[2]
        j20, j22 = x_d * k[10] * k[3], x_a * k[2]
        for col in range(3):  # column col of M = I + Psi (row-major Psi in y[3:12])
            m0 = y[3 + col] + (1.0 if col == 0 else 0.0)
            m1 = y[6 + col] + (1.0 if col == 1 else 0.0)
            m2 = y[9 + col] + (1.0 if col == 2 else 0.0)
            out[3 + col] = m1
            out[6 + col] = j10 * m0 + j11 * m1 + j12 * m2
            out[9 + col] = j20 * m0 + j22 * m2
    c = math.cos(tau)
    out[12], out[13], out[14], out[15], out[16] = u, u * c, u * s, w, p
    out[17], out[18], out[19], out[20], out[21] = p * c, p * s, xi, xi * c, xi * s


_compiled_compliant_rates = njit(cache=True)(_compliant_rates)


def _rates(tau: float, y: Array, out: Array, k: Array) -> None:
    """The rates of the period's state (rigid or compliant, k[9]) into ``out``: Eqs. (3'), (6')."""
    if k[9] > 0.0:
        _compiled_compliant_rates(tau, y, out, k)
    else:
        _compiled_rigid_rates(tau, y, out, k)


state_rates = njit(cache=True)(_rates)


def _rms(values: Array, y: Array, tol: float) -> float:
    """Root mean square of values / (tol + tol |y|): the norm of scipy's Runge–Kutta error control."""
    total = 0.0
    for i in range(values.shape[0]):
        total += (values[i] / (tol + tol * abs(y[i]))) ** 2
    return math.sqrt(total / values.shape[0])


_compiled_rms = njit(cache=True)(_rms)


def _initial_step(k: Array, tau0: float, tau1: float, y: Array, f: Array, tol: float, work: Array,
                  rates: Array) -> float:
    """First step of an order-8 method (Hairer, Nørsett & Wanner, Solving ODEs I, Sec. II.4).

    As scipy's select_initial_step: h0 from the norms of y and f, h1 from the second-derivative estimate.
    """
    d0, d1 = _compiled_rms(y, y, tol), _compiled_rms(f, y, tol)
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    h0 = min(h0, tau1 - tau0)
    for i in range(y.shape[0]):
        work[i] = y[i] + h0 * f[i]
    state_rates(tau0 + h0, work, rates, k)
    for i in range(y.shape[0]):
        work[i] = rates[i] - f[i]
    d2 = _compiled_rms(work, y, tol) / h0
    h1 = max(1e-6, h0 * 1e-3) if d1 <= 1e-15 and d2 <= 1e-15 else (0.01 / max(d1, d2)) ** (1.0 / 8.0)
    return min(100.0 * h0, h1, tau1 - tau0)


_compiled_initial_step = njit(cache=True)(_initial_step)


def _rk_step(k: Array, tau: float, y: Array, h: float, tol: float, stages: Array, y_new: Array,
             work: Array, rates: Array) -> float:
    """One DOP853 step of size h from (tau, y) with stages[0] = f(tau, y): y_new, stages[12] = f(tau + h, y_new).

    Returns the error norm of scipy's DOP853 (|h| |e5|^2 / sqrt((|e5|^2 + 0.01 |e3|^2) n), each
    estimate scaled by tol (1 + max(|y|, |y_new|))): the step is accepted when it is below 1.
    """
    n = y.shape[0]
    for s in range(1, _STAGES):
        for i in range(n):
            acc = 0.0
            for j in range(s):
                acc += stages[j, i] * _A[s, j]
            work[i] = y[i] + acc * h
        state_rates(tau + _C[s] * h, work, rates, k)
        stages[s, :] = rates
    for i in range(n):
        acc = 0.0
        for j in range(_STAGES):
            acc += stages[j, i] * _B[j]
        y_new[i] = y[i] + h * acc
    state_rates(tau + h, y_new, rates, k)
    stages[_STAGES, :] = rates
    e5, e3 = 0.0, 0.0
    for i in range(n):
        scale = tol + tol * max(abs(y[i]), abs(y_new[i]))
        a5, a3 = 0.0, 0.0
        for j in range(_STAGES + 1):
            a5 += stages[j, i] * _E5[j]
            a3 += stages[j, i] * _E3[j]
        e5 += (a5 / scale) ** 2
        e3 += (a3 / scale) ** 2
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(h) * e5 / math.sqrt((e5 + 0.01 * e3) * n)


_compiled_rk_step = njit(cache=True)(_rk_step)


def _dop853_loop(k: Array, y: Array, tau0: float, tau1: float, tol: float, max_steps: int, loss_abar: float,
                 taus: Array, cores: Array) -> tuple[int, float, int]:
    """DOP853 from (tau0, y) to tau1 (``y`` overwritten with the last accepted state).

    Records the accepted steps in ``taus`` and the core (the first ``cores.shape[1]`` components:
    u, or xi, eta, u) in ``cores`` (index 0 the start) and returns (code, tau
    reached, steps): code REACHED, CONTACT_LOST (abar < ``loss_abar`` after a step), STEP_BUDGET
    (more than ``max_steps`` steps) or STEP_UNDERFLOW (the step fell below 10 ulp of tau).
    """
    n, u_at = y.shape[0], cores.shape[1] - 1
    stages, y_new = np.empty((_STAGES + 1, n)), np.empty(n)
    work, rates = np.empty(n), np.empty(n)
    state_rates(tau0, y, rates, k)
    stages[0, :] = rates
    h_abs = _compiled_initial_step(k, tau0, tau1, y, stages[0], tol, work, rates)
    tau, steps = tau0, 0
    taus[0], cores[0, :] = tau0, y[: u_at + 1]
    while tau < tau1:
        if steps >= max_steps:
            return STEP_BUDGET, tau, steps
        min_step = 10.0 * (np.nextafter(tau, np.inf) - tau)
        h_abs = max(h_abs, min_step)
        rejected = False
        while True:
            if h_abs < min_step:
                return STEP_UNDERFLOW, tau, steps
            tau_new = min(tau + h_abs, tau1)
            h = tau_new - tau
            error = _compiled_rk_step(k, tau, y, h, tol, stages, y_new, work, rates)
            if error < 1.0:
                factor = _MAX_FACTOR if error == 0.0 else min(_MAX_FACTOR, _SAFETY * error**_ERROR_EXPONENT)
                h_abs = h * (min(1.0, factor) if rejected else factor)
                break
            h_abs = h * max(_MIN_FACTOR, _SAFETY * error**_ERROR_EXPONENT)
            rejected = True
        tau = tau_new
        y[:] = y_new
        stages[0, :] = stages[_STAGES]
        steps += 1
        taus[steps], cores[steps, :] = tau, y[: u_at + 1]
        if (k[0] + k[1] * y[u_at]) * k[2] < loss_abar:
            return CONTACT_LOST, tau, steps
    return REACHED, tau, steps


_compiled_dop853_loop = njit(cache=True)(_dop853_loop)


def _speeds(abar: Array, deltabar: Array, inv_n: float, log_cap: float) -> Array:
    """x = adot/v0 of Eq. (6') (:func:`vibroadhesion.simulation.model.contact_kernel`) at each (abar, deltabar)."""
    out = np.empty(abar.shape[0])
    for i in range(abar.shape[0]):
        out[i] = compiled_contact_kernel(abar[i], deltabar[i], inv_n, log_cap)[0]
    return out


speeds = njit(cache=True)(_speeds)


def _frozen_mean_speed(abar: float, d_mean: float, amplitude: float, sines: Array, inv_n: float, cap: float) -> float:
    """Mean of x = f^{-1}(Phi) (Eq. 6', Gent–Schultz, clipped to +-cap) over deltabar = d_mean - amplitude sin tau.

    abar is frozen; ``sines`` holds sin tau at the points of the periodic trapezoid rule. Where
    abar^2 <= deltabar (w -> 0) the contact closes at the cap. The root in abar is the frozen-contact
    limit omega_check -> infinity of the orbit (:func:`vibroadhesion.simulation.orbits.frozen_start`).
    """
    total = 0.0
    for i in range(sines.shape[0]):
        gap = abar * abar - (d_mean - amplitude * sines[i])
        x = cap
        if gap > 0.0:
            phi = max(gap * gap / abar, 1e-300)
            x = -((phi - 1.0) ** inv_n) if phi > 1.0 else ((1.0 - phi) / phi) ** inv_n
            x = min(max(x, -cap), cap)
        total += x
    return total / sines.shape[0]


frozen_mean_speed = njit(cache=True)(_frozen_mean_speed)


def _point_value(kind: int, tau: float, core: Array, k: Array) -> float:
    """A function of a point of the period whose sign changes locate the orbit's extremes (Eqs. 5', 6', 7).

    kind :data:`TURNING`: abar (Phi - 1) = gap^2 - abar (gap = abar^2 - deltabar), zero where x = 0, at
    the extremes of a; :data:`PHI_RATE`: dPhi/dtau = Phi_a abar' + Phi_d deltabar' with Phi_a =
    gap (3 abar^2 + deltabar)/abar^2, Phi_d = -2 gap/abar, zero at the extremes of Phi and of the speed.
    ``core`` is the scaled core (u, or xi, eta, u), ``k`` the period's constants.
    """
    u = core[core.shape[0] - 1]
    abar = (k[0] + k[1] * u) * k[2]
    d = k[4] - k[5] * math.sin(tau)
    rate = -k[5] * math.cos(tau)
    if k[9] > 0.0:
        d += k[10] * core[0]
        rate += k[10] * core[1]
    gap = abar * abar - d
    if kind == TURNING:
        return gap * gap - abar
    x = compiled_contact_kernel(abar, d, k[6], k[7])[0]
    return gap * (3.0 * abar * abar + d) / (abar * abar) * x * k[2] - 2.0 * gap / abar * rate


_compiled_point_value = njit(cache=True)(_point_value)


def _point_values(kind: int, taus: Array, cores: Array, k: Array) -> Array:
    """:func:`_point_value` at each accepted step (``cores`` (steps, core dimension))."""
    out = np.empty(taus.shape[0])
    for i in range(taus.shape[0]):
        out[i] = _compiled_point_value(kind, taus[i], cores[i], k)
    return out


point_values = njit(cache=True)(_point_values)


def _point_in_step(kind: int, k: Array, tau_k: float, core_k: Array, tau: float, tol: float, max_steps: int,
                   core: Array) -> tuple[int, float]:
    """(code, g): the core at ``tau`` into ``core``, integrated from (tau_k, core_k), and :func:`_point_value` there.

    The DOP853 of :func:`_dop853_loop` at ``tol`` without a contact-loss stop; a code below 0 (the
    integration gave up) comes with g = NaN.
    """
    core[:] = core_k
    if tau != tau_k:
        taus, cores = np.empty(max_steps + 1), np.empty((max_steps + 1, core.shape[0]))
        code = _compiled_dop853_loop(k, core, tau_k, tau, tol, max_steps, -math.inf, taus, cores)[0]
        if code < 0:
            return code, math.nan
    return REACHED, _compiled_point_value(kind, tau, core, k)


point_in_step = njit(cache=True)(_point_in_step)


class KernelRun(NamedTuple):
    """What :func:`integrate` returns: the code, the tau reached, the state there, the accepted steps."""

    code: int
    tau: float
    y: Array
    taus: Array  # accepted steps, the start first
    cores: Array  # (steps, core dimension): the core (u, or xi, eta, u) at those steps


def _pieces(k: Array, tau0: float, tau1: float) -> list[tuple[float, float, Array]]:
    """[tau0, tau1] split at the schedule's tau_a, tau_b, each piece with its side's constants (module docstring).

    A constant schedule (s0 = s1) is one piece with the constants unchanged (Eq. 11 with etahat s(tau)).
    """
    if k[_S0] == k[_S1]:
        return [(tau0, tau1, k)]
    bounds = [tau0, *sorted({float(t) for t in (k[_TAU_A], k[_TAU_B]) if tau0 < t < tau1}), tau1]
    pieces = []
    for lo, hi in zip(bounds[:-1], bounds[1:], strict=True):
        piece, middle = k.copy(), 0.5 * (lo + hi)
        if middle < k[_TAU_A]:
            piece[_S1] = k[_S0]
        elif middle >= k[_TAU_B]:
            piece[_S0] = k[_S1]
        pieces.append((lo, hi, piece))
    return pieces


def integrate(constants: Array, y0: Array, tau0: float, tau1: float, rtol: float, max_steps: int,
              loss_abar: float) -> KernelRun:
    """Compiled DOP853 of a period (Eqs. 3', 6', with the full y0 the variational equations and quadratures).

    From (tau0, y0) to tau1 with the period's ``constants`` (module docstring), piece by piece between the
    excitation schedule's switches (:func:`_pieces`; one piece for a constant excitation), within ``max_steps``
    accepted steps in all. ``y0`` is the core
    (1 or 3 components) or the full state (:data:`FULL_SIZE`, :data:`COMPLIANT_FULL_SIZE`); rtol is
    also the absolute tolerance (the state is scaled to O(1)). Integration failures are return
    codes, never exceptions.
    """
    k = np.asarray(constants, dtype=np.float64)
    y = np.array(y0, dtype=np.float64)
    taus, cores = np.empty(max_steps + 1), np.empty((max_steps + 1, 3 if k[9] > 0.0 else 1))
    code, tau, steps = REACHED, float(tau0), 0
    for lo, hi, piece in _pieces(k, float(tau0), float(tau1)):
        code, tau, taken = _compiled_dop853_loop(piece, y, lo, hi, float(rtol), int(max_steps) - steps,
                                                 float(loss_abar), taus[steps:], cores[steps:])
        steps += taken
        if code != REACHED:
            break
    return KernelRun(int(code), float(tau), y, taus[: steps + 1], cores[: steps + 1])
