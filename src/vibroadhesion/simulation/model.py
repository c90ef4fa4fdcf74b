"""The full nonlinear model (Eqs. 1–11, Appendix A) in nondimensional form: parameters, contact kernel, static state.

The asymptotic models of the paper replace the contact dynamics by averages (Bogoliubov,
Eqs. 14–19) and first harmonics (Eqs. 25–36). The sub-package :mod:`vibroadhesion.simulation`
integrates the model itself and finds its periodic steady state by shooting, so that every
asymptotic formula can be checked against it. This module holds the model: the constants
of a :class:`vibroadhesion.core.problem.Problem` (:class:`Model`), the contact kernel of Eqs. (4')–(6')
(:func:`contact_kernel`), the constants of the right-hand side (:class:`Model`) and the static
state (:func:`static_state`).

Nondimensional model
--------------------
Scales: a_o = (2 pi w0 R^2/E*)^(1/3) (Eq. 86), c_o = a_o/R = 2^(1/3) 3^(-2/3) chi0, tau = omega t,

    abar = a/a_o,   deltabar = delta R/a_o^2,   Phat = P R/(E* a_o^3),   xbar = x_s R/a_o^2,

with the identities 2 pi w0/E* = a_o^3/R^2 and pi w0 R^2/(E* a_o^3) = 1/2. Dividing Eq. (5) by
a_o^2/R, sqrt(2 pi w a/E*) R/a_o^2 = sqrt(w/w0) sqrt(abar), so

    deltabar = abar^2 - sqrt(w/w0) sqrt(abar)   =>   sqrt(w/w0) = (abar^2 - deltabar)/sqrt(abar).   (5')

Dividing Eq. (4) by E* a_o^3/R, sqrt(8 pi w E* a^3) R/(E* a_o^3) = 2 sqrt(w/w0) abar^(3/2), and
with (5'),

    Phat = (4/3) abar^3 - 2 sqrt(w/w0) abar^(3/2) = 2 abar deltabar - (2/3) abar^3.       (4')

(So Phat_JKR = -(3/2) pi w0 R · R/(E* a_o^3) = -3/4, and the static nominal point contact
abar = 1, deltabar = 0 carries Phat = -2/3.) Since w > 0, Eq. (5') needs abar^2 > deltabar, and
then the rate law (6) is solved for the contact-front speed: with

    Phi(abar, deltabar) = w/w0 = (abar^2 - deltabar)^2 / abar,

    x = adot/v0 = f^{-1}(Phi)  (GentSchultz.speed: -(Phi-1)^(1/n) opening, (1/Phi-1)^(1/n) closing),
    d abar/d tau = x / (omega_check c_o),          omega_check c_o = omega a_o / v0.            (6')

The state therefore needs no algebraic constraint: Eqs. (4)–(6) become one explicit ODE for a.

Rigid fixation (x_s = 0). Eq. (7) with h = h0 + h1 sin tau (Eq. 11) gives delta = hhat - h0 - h1 sin tau:

    deltabar(tau) = base_offset - etahat sin tau,   base_offset = (hhat - h0) R/a_o^2,   etahat = eta1/c_o^2,

(h1 R/a_o^2 = eta1 R^2/a_o^2), base_offset = 0 for the nominal point contact h0 = hhat (Eq. 78), and
(6') is a scalar non-autonomous ODE for abar.

Compliant fixation. Eq. (3) with (2), m xs'' + c xs' + k xs = m g - P, divided by k a_o^2/R, with
m omega^2/k = omega_bar^2, c omega/k = 2 zeta omega_bar (Eq. 65), m g R/(k a_o^2) = mu/(kappa c_o^2)
and P R/(k a_o^2) = (c_o/kappa) Phat (Eqs. 66, 81):

    omega_bar^2 xbar'' + 2 zeta omega_bar xbar' + xbar = mu/(kappa c_o^2) - (c_o/kappa) Phat,       (3')
    deltabar = xbar + base_offset - etahat sin tau      (Eq. 7 divided by a_o^2/R),

with omega_check = omega_bar/nu0 (Eqs. 97, 105). The state is (xbar, xbar', abar).

Force rig (Fig. 2, Eq. 13). The base stays at h0 and the force F1 sin(omega t) acts on the indenter:
m xs'' + c xs' + k xs = m g - P + F1 sin(omega t), i.e. Eq. (3') with one more term,

    omega_bar^2 xbar'' + 2 zeta omega_bar xbar' + xbar = mu/(kappa c_o^2) - (c_o/kappa) Phat + fhat sin tau,
    fhat = F1 R/(k a_o^2) = force_amplitude/(kappa c_o^2)   (force_amplitude = F1/(E* R^2)),

with etahat = 0 in Eq. (7). With y = xbar - etahat sin tau the base rig's Eq. (3') has the forcing
-etahat [(1 - omega_bar^2) sin tau + 2 zeta omega_bar cos tau] instead: the two rigs are the same
dynamical system for deltabar when fhat = etahat |1 - omega_bar^2 + 2 i zeta omega_bar|, i.e.
F1 = h1 |k - m omega^2 + i c omega| (Eqs. 9, 13, 21–22), up to a shift of the phase of tau.

Static state (Eqs. 10, A.4–A.7). With w = w0 the static contact obeys deltabar_0s = s(abar),
s(a) = a^2 - sqrt(a), Phat_0 = p(a), p(a) = (4/3) a^3 - 2 a^(3/2), and xbar_0 = deltabar_0s -
base_offset = mu/(kappa c_o^2) - (c_o/kappa) p(abar). Multiplied by kappa c_o^2:

    g(a) = kappa c_o^2 (s(a) - base_offset) + c_o^3 p(a) - mu = 0,

which is Eq. (80) (Eq. 82 with a_0/R = c_o abar, since c_o^(3/2) = sqrt(2) chi0^(3/2)/3) for
base_offset = 0. g(0) = -kappa c_o^2 base_offset - mu and g -> infinity; the contact that a
displacement-controlled spring holds stably is the largest root (g' > 0 there). For the rigid
fixation (kappa -> infinity) it is s(a) = base_offset on the stable branch a > 4^(-2/3); abar = 1 for
the nominal point contact (Sec. 3.5.4). These reductions agree with the paper's Eqs. (3), (7),
(8), (80), (82) and (A.7); no discrepancy was found.

Contact loss and speed saturation
---------------------------------
The contact is lost when a reaches 0. Near a = 0 with deltabar < 0, Phi ~ deltabar^2/abar -> infinity
and the opening speed diverges, so a reaches 0 in finite time; the event "abar < contact_loss_abar"
(default 1e-3, checked at every accepted step) stops the integration and is reported. The boundary
abar^2 = deltabar (Phi -> 0, w -> 0) is not a loss of contact: the closing speed diverges there and
drives abar away from it. To keep the integrators finite in these blow-ups (for n = 0.05, x =
(Phi - 1)^20 overflows a double at Phi ~ 1e15) the speed is saturated smoothly at
|d abar/dtau| = SPEED_CAP (1e6, i.e. the radius would change by 1e6 a_o per radian):
ln|x| -> ln|x| - ln(1 + e^(8 (ln|x| - ln x_cap)))/8, which changes speeds of 1e-3 x_cap by a
relative 1e-25; a periodic orbit whose speed comes within 1e-3 of the cap is reported with status
``speed_unresolved`` instead of being trusted. The threshold is not critical: below it the
collapse is a finite-time blow-up (tested: 1e-3 and 1e-4 give the same loss time to 1e-3).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from vibroadhesion.core.problem import Problem

Array = NDArray[np.float64]

TWO_PI = 2.0 * math.pi
#: Saturation of the front speed, in |d abar / d tau| (module docstring).
SPEED_CAP = 1e6
_SATURATION_SHARPNESS = 8.0
#: Smallest excess |Phi - 1| (or |1/Phi - 1|) passed to the logarithm: x ~ 0 below it.
_TINY_EXCESS = 1e-300
#: For n > 1, dx/dPhi is evaluated no closer to Phi = 1 than this excess (it diverges there).
_SINGULAR_EXCESS = 1e-12


class NoStaticContactError(ValueError):
    """The static problem (Eqs. A.4–A.7) has no contact: there is nothing to excite."""


class StaticState(NamedTuple):
    """Static equilibrium (Eqs. 10, A.4–A.7, 80, 82) in the units of this module."""

    abar_0: float  # a_0 / a_o
    xbar: float  # x_s R / a_o^2 (0 for rigid fixation)
    phat: float  # P_0 R / (E* a_o^3)


# --- The model's right-hand side ----------------------------------------------------------------


def contact_kernel(
    abar: float, deltabar: float, inv_n: float, log_cap: float
) -> tuple[float, float, float, float, float]:
    """(x, dx/dabar, dx/ddeltabar, Phat, sqrt(w/w0)): Eqs. (6'), (4'), (5') at one state.

    x = adot/v0 is the front speed of Eq. (6') with the saturation of the module docstring.
    Written with :mod:`math` on Python floats (the ODE right-hand side is called ~1e4 times per
    steady state; numpy on scalars would be ~20 times slower) and in log space, so that no
    power overflows; it agrees with :meth:`GentSchultz.speed` below the cap (tested).
    """
    if abar <= 0.0:  # only at rejected trial stages: beyond a -> 0, where the opening speed -> cap
        return -math.exp(log_cap), 0.0, 0.0, 0.0, 0.0
    gap = abar * abar - deltabar  # = sqrt(w/w0) sqrt(abar) > 0
    phat = 2.0 * abar * deltabar - (2.0 / 3.0) * abar * abar * abar
    gap2 = gap * gap
    phi = gap2 / abar
    if gap <= 0.0 or phi < 1e-290:  # w -> 0 (or a trial stage beyond): the closing speed -> cap
        return math.exp(log_cap), 0.0, 0.0, phat, max(gap, 0.0) / math.sqrt(abar)
    if phi >= 1.0:  # opening: x = -(Phi - 1)^(1/n)
        excess = max((gap2 - abar) / abar, _TINY_EXCESS)
        sign, dlog_dphi = -1.0, 1.0 / excess
    else:  # closing: x = (1/Phi - 1)^(1/n)
        excess = max((abar - gap2) / gap2, _TINY_EXCESS)
        sign, dlog_dphi = 1.0, -1.0 / (excess * phi * phi)  # (excess phi) phi = (1 - Phi) Phi: no underflow
    log_speed = inv_n * math.log(excess)
    z = _SATURATION_SHARPNESS * (log_speed - log_cap)
    if z < -36.0:
        damping = 1.0
    elif z > 36.0:
        log_speed, damping = log_cap, 0.0
    else:
        ez = math.exp(z)
        log_speed -= math.log1p(ez) / _SATURATION_SHARPNESS
        damping = 1.0 / (1.0 + ez)
    speed = sign * math.exp(log_speed)
    dspeed_dphi = speed * inv_n * dlog_dphi * damping
    if inv_n < 1.0 and excess < _SINGULAR_EXCESS:
        # n > 1: dx/dPhi ~ |Phi - 1|^(1/n - 1) is unbounded at the turning points; only the implicit
        # integrators' Newton iterations use it then (Psi comes from differences, see the shooting
        # module), so it is bounded there.
        dspeed_dphi *= (excess / _SINGULAR_EXCESS) ** (1.0 - inv_n)
    return (
        speed,
        dspeed_dphi * gap * (3.0 * abar * abar + deltabar) / (abar * abar),
        dspeed_dphi * (-2.0 * gap / abar),
        phat,
        gap / math.sqrt(abar),
    )


class Model:
    """Constants of the nondimensional model (module docstring) for one parameter point."""

    def __init__(self, problem: Problem, contact_loss_abar: float):
        """The constants of Eqs. (3'), (6') and (7) for a rigid or compliant fixation (a free one is a ValueError).

        ``contact_loss_abar``: the abar below which the contact counts as lost (module docstring).
        """
        if not (0 < contact_loss_abar < 1):
            raise ValueError(f"contact_loss_abar must lie in (0, 1), got {contact_loss_abar}")
        fixation = problem.fixation
        if fixation.kind == "free":
            raise ValueError("fixation: the simulation implements the rigid and the compliant kinds, not free")
        self.problem = problem
        self.inv_n = 1.0 / problem.law.n
        self.speed_scale = problem.speed_scale
        self.etahat = problem.etahat
        self.base_offset = problem.base_offset
        self.log_cap = math.log(SPEED_CAP * self.speed_scale)
        self.contact_loss_abar = contact_loss_abar
        self.compliant = not fixation.is_rigid
        self.force_drive = 0.0  # fhat = F1 R/(k a_o^2) of the force rig (module docstring, Eq. 13)
        self.dim = 3 if self.compliant else 1
        # For n > 1 the variational equations have an unbounded (integrable) coefficient at the
        # turning points that no error-controlled integrator resolves: Psi by differences instead.
        self.variational = problem.law.n <= 1.0
        if self.compliant:
            c_o = problem.c_o
            self.force_offset = fixation.mu / (fixation.kappa * c_o**2)
            self.compliance = c_o / fixation.kappa
            self.omega_bar = fixation.omega_bar(problem.omega_check)
            self.zeta = fixation.zeta
            self.force_drive = problem.force_amplitude / (fixation.kappa * c_o**2)

    def force_response(self, abar: float) -> float:
        """Amplitude of deltabar under the force rig's drive with the contact radius frozen at ``abar`` (Eqs. 3', 13).

        With abar fixed, Phat = 2 abar deltabar - (2/3) abar^3 is linear, so Eq. (3') is a linear oscillator of
        stiffness 1 + 2 abar c_o/kappa: fhat/|1 + 2 abar c_o/kappa - omega_bar^2 + 2 i zeta omega_bar|, the modulus
        kept above 1e-2 of the stiffness (an undamped resonance; a scale, not a result). 0 without a force.
        """
        if self.force_drive == 0.0:
            return 0.0
        stiffness = 1.0 + 2.0 * abar * self.compliance
        return self.force_drive / max(abs(complex(stiffness - self.omega_bar**2, 2.0 * self.zeta * self.omega_bar)),
                                      1e-2 * stiffness)


# --- Static state -------------------------------------------------------------------------------


def _jkr_displacement(abar: float) -> float:
    """s(a) = a^2 - sqrt(a): static deltabar of Eq. (5') with w = w0."""
    return abar * abar - math.sqrt(abar)


def _jkr_force(abar: float) -> float:
    """p(a) = (4/3) a^3 - 2 a^(3/2): static Phat of Eq. (4') with w = w0."""
    return (4.0 / 3.0) * abar**3 - 2.0 * abar**1.5


def _rigid_static_excess(abar: float, d0: float) -> float:
    """g(a) of the rigid fixation: s(a) - base_offset (Eq. A.7 with kappa -> infinity)."""
    return _jkr_displacement(abar) - d0


def _spring_static_excess(abar: float, d0: float, stiffness: float, cube: float, mu: float) -> float:
    """g(a) = kappa c_o^2 (s(a) - base_offset) + c_o^3 p(a) - mu (Eqs. 80, 82, A.7).

    ``stiffness`` = kappa c_o^2, ``cube`` = c_o^3 (model docstring, "Static state").
    """
    return stiffness * (_jkr_displacement(abar) - d0) + cube * _jkr_force(abar) - mu


def static_state(problem: Problem) -> StaticState:
    """Static equilibrium (Eqs. A.4–A.7): the largest root of g(a) = 0 (module docstring).

    Raises :class:`NoStaticContactError` when there is no static contact (a tensile preset
    beyond the JKR pull-off of the displacement-controlled assembly).
    """
    d0, fixation = problem.base_offset, problem.fixation
    excess: Callable[..., float]
    args: tuple[float, ...]
    if fixation.is_rigid:
        excess, args = _rigid_static_excess, (d0,)
    else:
        c_o = problem.c_o
        excess, args = _spring_static_excess, (d0, fixation.kappa * c_o**2, c_o**3, fixation.mu)
    hi = 2.0
    while excess(hi, *args) <= 0:
        hi *= 2.0
    lo = hi
    while excess(lo, *args) > 0:
        lo *= 0.9
        if lo < 1e-9:
            raise NoStaticContactError(f"no static contact for base_offset = {d0} (Eqs. A.4–A.7)")
    abar = brentq(excess, lo, lo / 0.9, args=args, xtol=1e-15, rtol=4 * np.finfo(float).eps)
    if fixation.is_rigid:
        # The stable branch of displacement control is a > 4^(-2/3) where s is increasing.
        if abar < 4.0 ** (-2.0 / 3.0):
            raise NoStaticContactError(f"base_offset = {d0} is beyond the JKR fixed-grip pull-off (-0.4725)")
        return StaticState(abar, 0.0, _jkr_force(abar))
    return StaticState(abar, _jkr_displacement(abar) - d0, _jkr_force(abar))


def absolute_start(model: Model, state: ArrayLike | None) -> Array:
    """Absolute start state (abar,) or (xbar, xbar', abar): ``state`` checked, or the static state (Eq. 10).

    Raises :class:`ValueError` unless ``state`` holds ``model.dim`` finite numbers with abar > 0.
    """
    if state is None:
        st = static_state(model.problem)
        return np.array([st.xbar, 0.0, st.abar_0] if model.compliant else [st.abar_0])
    start = np.asarray(state, dtype=float).ravel()
    if start.size != model.dim or not np.all(np.isfinite(start)) or not start[-1] > 0:
        raise ValueError(f"initial state must be {model.dim} finite numbers with abar > 0, got {state}")
    return start

