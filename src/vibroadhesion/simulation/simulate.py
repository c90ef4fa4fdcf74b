"""Direct time-domain simulation of the full nonlinear model (Eqs. 1–11, Appendix A): ground truth.

The asymptotic models of the paper replace the contact dynamics by averages (Bogoliubov,
Eqs. 14–19) and first harmonics (Eqs. 25–36). This module integrates the model itself and
finds its periodic steady state by shooting, so that every asymptotic formula can be checked
against it.

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

    deltabar(tau) = deltabar0 - eps sin tau,   deltabar0 = (hhat - h0) R/a_o^2,   eps = eta1/c_o^2,

(h1 R/a_o^2 = eta1 R^2/a_o^2), deltabar0 = 0 for the nominal point contact h0 = hhat (Eq. 78), and
(6') is a scalar non-autonomous ODE for abar.

Compliant fixation. Eq. (3) with (2), m xs'' + c xs' + k xs = m g - P, divided by k a_o^2/R, with
m omega^2/k = omega_bar^2, c omega/k = 2 zeta omega_bar (Eq. 65), m g R/(k a_o^2) = mu/(kappa c_o^2)
and P R/(k a_o^2) = (c_o/kappa) Phat (Eqs. 66, 81):

    omega_bar^2 xbar'' + 2 zeta omega_bar xbar' + xbar = mu/(kappa c_o^2) - (c_o/kappa) Phat,       (3')
    deltabar = xbar + deltabar0 - eps sin tau      (Eq. 7 divided by a_o^2/R),

with omega_check = omega_bar/nu0 (Eqs. 97, 105). The state is (xbar, xbar', abar).

Static state (Eqs. 10, A.4–A.7). With w = w0 the static contact obeys deltabar_0s = s(abar),
s(a) = a^2 - sqrt(a), Phat_0 = p(a), p(a) = (4/3) a^3 - 2 a^(3/2), and xbar_0 = deltabar_0s -
deltabar0 = mu/(kappa c_o^2) - (c_o/kappa) p(abar). Multiplied by kappa c_o^2:

    g(a) = kappa c_o^2 (s(a) - deltabar0) + c_o^3 p(a) - mu = 0,

which is Eq. (80) (Eq. 82 with a_0/R = c_o abar, since c_o^(3/2) = sqrt(2) chi0^(3/2)/3) for
deltabar0 = 0. g(0) = -kappa c_o^2 deltabar0 - mu and g -> infinity; the contact that a
displacement-controlled spring holds stably is the largest root (g' > 0 there). For the rigid
fixation (kappa -> infinity) it is s(a) = deltabar0 on the stable branch a > 4^(-2/3); abar = 1 for
the nominal point contact (Sec. 3.5.4). These reductions agree with the paper's Eqs. (3), (7),
(8), (80), (82) and (A.7); no discrepancy was found.

Shooting
--------
A period lasts 2 pi while the contact relaxes over omega_check c_o / |dx/dabar| periods, so the
steady state is found as a fixed point of the one-period map, not by waiting. abar itself changes
by only A ~ Abar/(omega_check c_o) per period (1e-7 of a_m at omega_check = 1e9), so the
integrated variable is the front displacement measured from the start of the period,

    v = omega_check c_o (abar - abar(0)),   dv/dtau = x,

which is O(Abar) and carries full relative precision whatever omega_check is (scaled internally
by its observed half range, floored at a change of abar of 1e-14 abar, and xbar by
max(eps, |xbar|, |xbar'|), so that one absolute tolerance fits all components). The one-period
map in the coordinates (xbar, xbar', b = omega_check c_o abar) has the residual
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
integration error of 10 rtol in r causes (|Psi^{-1}| 10 rtol), or when r itself is at rounding
level (10 rtol, or a drift of abar below its resolution).

First period and starting guess. The experiment starts from the static state (Eq. 10). Its first
period is integrated (core only, with LSODA, which switches to BDF: while the base compresses the
contact faster than a^2 = deltabar allows, the front slides along Phi ~ 0 at a huge closing speed,
a stiff phase) and decides ``contact_loss``. The iteration then starts from the limit
omega_check -> infinity of the orbit (abar frozen over a period: the root of the mean front speed;
for the compliant fixation with the linear response of the spring to the frozen contact, whose
stiffness is 2 abar), unless the static state is already periodic to rounding.

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

Integrators. "auto": the first period with LSODA (ODEPACK), the periods near the orbit, not stiff
for omega_check >~ 1e3, with the Fortran DOP853 of :class:`scipy.integrate.ode` (a period costs
~100 steps, ~25 us each: the Python loop of solve_ivp would cost 4 times more), a period DOP853
gives up on repeated with Radau (analytic Jacobian). The extremes of a and of Phi are located
between accepted steps by Brent's method on re-integrated states.

Known limitation: for n > 1 in the quasi-static regime (omega_check c_o << eps^(1/n - 1)) the
contact tracks Phi - 1 ~ x^n ~ 1e-9..1e-16, where the speed (Phi - 1)^(1/n) has a relative
rounding noise of 1e-16/|Phi - 1| and an unbounded derivative: no integrator meets the tolerance
and the result is ``integration_failure`` (after ~10^4 steps), not a number.

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
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal, NamedTuple

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import BDF, DOP853, LSODA, RK45, Radau, ode
from scipy.optimize import brentq

from vibroadhesion.core.groups import PHAT_JKR, contact_radius_ratio
from vibroadhesion.core.ratelaw import GentSchultz

Array = NDArray[np.float64]
Integrator = Literal["auto", "fortran-dop853", "Radau", "BDF", "LSODA", "DOP853", "RK45"]
Status = Literal["converged", "contact_loss", "not_converged", "integration_failure", "speed_unresolved"]

TWO_PI = 2.0 * math.pi
#: Saturation of the front speed, in |d abar / d tau| (module docstring).
SPEED_CAP = 1e6
_SATURATION_SHARPNESS = 8.0
#: A periodic orbit is trusted only if its peak speed stays below this fraction of the cap.
_RESOLVED_SPEED_FRACTION = 1e-3
#: Smallest excess |Phi - 1| (or |1/Phi - 1|) passed to the logarithm: x ~ 0 below it.
_TINY_EXCESS = 1e-300
#: For n > 1, dx/dPhi is evaluated no closer to Phi = 1 than this excess (it diverges there).
_SINGULAR_EXCESS = 1e-12
#: Central-difference step of the one-period map in the scaled coordinates (n > 1).
_FD_STEP = 1e-5
_FORTRAN = "fortran-dop853"
_IVP_SOLVERS = {"Radau": Radau, "BDF": BDF, "LSODA": LSODA, "DOP853": DOP853, "RK45": RK45}
_IMPLICIT = ("Radau", "BDF", "LSODA")
#: Steps allowed per call: to the Fortran DOP853 (then "auto" repeats the call with Radau) and
#: to the solve_ivp methods (then the integration has failed).
_FORTRAN_MAX_STEPS = 10_000
_IVP_MAX_STEPS = 10_000
#: Newton: relative size of the last correction at which the orbit is accepted.
_NEWTON_XTOL = 1e-11
#: Global integration error of a period in units of rtol times the (scaled, O(1)) state: a
#: Newton correction below the uncertainty it causes in the fixed point also ends the iteration.
_GLOBAL_ERROR_FACTOR = 10.0
#: A residual below this many rtol (scaled state) is periodic to the local accuracy of the
#: integration: the orbit is accepted even where the map is too ill-conditioned to pin it down
#: better (e.g. an undamped spring whose contact does not move).
_PERIODIC_RESIDUAL_FACTOR = 10.0
_MAX_ABAR = 1e4


@dataclass(frozen=True)
class BaseExcitation:
    """The contact and its rigid-base excitation h = h0 + h1 sin(omega t) (Eqs. 4–7, 11).

    ``eta1`` = h1/R (Eq. 65), ``omega_check`` = omega R/v0 (Eq. 105), ``chi0`` of Eq. (64), the
    rate law, and ``deltabar0`` = (hhat - h0) R/a_o^2 (0 for the nominal point contact, Eq. 78).
    """

    law: GentSchultz
    chi0: float
    eta1: float
    omega_check: float
    deltabar0: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.law, GentSchultz):
            raise TypeError("the simulation implements the Gent–Schultz law (Eqs. 73–75)")
        if not (math.isfinite(self.chi0) and self.chi0 > 0):
            raise ValueError(f"chi0 must be positive, got {self.chi0}")
        if not (math.isfinite(self.eta1) and self.eta1 >= 0):
            raise ValueError(f"eta1 must be finite and non-negative, got {self.eta1}")
        if not (math.isfinite(self.omega_check) and self.omega_check > 0):
            raise ValueError(f"omega_check must be positive, got {self.omega_check}")
        if not math.isfinite(self.deltabar0):
            raise ValueError(f"deltabar0 must be finite, got {self.deltabar0}")

    @property
    def contact_scale(self) -> float:
        """c_o = a_o/R."""
        return contact_radius_ratio(self.chi0)

    @property
    def displacement_amplitude(self) -> float:
        """eps = h1 R/a_o^2 = eta1/c_o^2, the base amplitude in units of a_o^2/R."""
        return self.eta1 / self.contact_scale**2

    @property
    def speed_scale(self) -> float:
        """omega_check c_o = omega a_o/v0: d abar/d tau = x / (omega_check c_o), Eq. (6')."""
        return self.omega_check * self.contact_scale


@dataclass(frozen=True)
class SpringFixation:
    """Spring–dashpot fixation of an indenter of mass m (Eqs. 2, 3, 65, 66, 81, 97).

    ``kappa`` = k/(E* R), ``zeta`` = c/(2 sqrt(k m)), ``nu0`` = v0/(omega0 R), ``mu`` = m g/(E* R^2).
    """

    kappa: float
    zeta: float
    nu0: float
    mu: float = 0.0

    def __post_init__(self) -> None:
        for name in ("kappa", "nu0"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} must be positive, got {value}")
        for name in ("zeta", "mu"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0):
                raise ValueError(f"{name} must be finite and non-negative, got {value}")


class NoStaticContactError(ValueError):
    """The static problem (Eqs. A.4–A.7) has no contact: there is nothing to excite."""


class StaticState(NamedTuple):
    """Static equilibrium (Eqs. 10, A.4–A.7, 80, 82) in the units of this module."""

    abar: float  # a_0 / a_o
    xbar: float  # x_s R / a_o^2 (0 for rigid fixation)
    phat: float  # P_0 R / (E* a_o^3)


class SteadyState(NamedTuple):
    """Periodic steady state found by shooting (module docstring for the definitions).

    Harmonic coefficients refer to tau = omega t with h - h0 = h1 sin tau. The numbers are NaN
    for ``contact_loss``, ``not_converged`` and ``integration_failure`` (``start_state`` is then
    the last state tried); ``speed_unresolved`` keeps them but flags that the orbit came within
    1e-3 of the numerical speed cap. ``tau_contact_loss`` is finite only for ``contact_loss``.
    """

    status: Status
    message: str
    start_state: Array  # state at tau = 0 mod 2pi: (abar,) rigid, (xbar, dxbar/dtau, abar) compliant
    abar_m: float  # a_m / a_o, mean over the period
    abar: float  # internal variable Abar = omega A / v0 (Eq. 45)
    a_over_am: float  # A / a_m, A = half the peak-to-peak range of a
    a1_over_am: float  # first-harmonic amplitude of a over a_m
    a_c: float  # first-harmonic cosine coefficient of a / a_o
    a_s: float  # first-harmonic sine coefficient of a / a_o
    w_eff_ratio: float  # w_eff / w0 = (mean sqrt(w/w0))^2, Eq. (18)
    pm_over_abs_pjkr: float  # mean(P) / |P_JKR| = mean(Phat)/(3/4); tensile mean force negative
    phat_m: float
    phat_c: float
    phat_s: float
    deltabar_m: float
    deltabar_c: float
    deltabar_s: float
    peak_speed: float  # max |adot| / v0 over the period
    peak_speed_in_range: bool | None  # inside ``speed_range`` (None when no range is given)
    floquet_multipliers: NDArray[np.complex128]
    stable: bool  # all |multipliers| < 1
    periodicity_residual: float  # max_i |y_i(2pi) - y_i(0)| / scale_i (abar: relative to abar(0))
    iterations: int  # one-period integrations of the shooting (finite-difference ones not counted)
    integrator: str
    tau_contact_loss: float


class Transient(NamedTuple):
    """Brute-force integration period after period (the states at tau = 2 pi k)."""

    status: Literal["completed", "contact_loss"]
    states: Array  # (periods completed + 1, state dimension), same layout as SteadyState.start_state
    tau_contact_loss: float


# --- The model's right-hand side ----------------------------------------------------------------


def _contact(abar: float, deltabar: float, inv_n: float, log_cap: float) -> tuple[float, float, float, float, float]:
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
        # integrators' Newton iterations use it then (module docstring), so it is bounded there.
        dspeed_dphi *= (excess / _SINGULAR_EXCESS) ** (1.0 - inv_n)
    return (
        speed,
        dspeed_dphi * gap * (3.0 * abar * abar + deltabar) / (abar * abar),
        dspeed_dphi * (-2.0 * gap / abar),
        phat,
        gap / math.sqrt(abar),
    )


class _Model:
    """Constants of the nondimensional model (module docstring) for one parameter point."""

    def __init__(self, excitation: BaseExcitation, fixation: SpringFixation | None, contact_loss_abar: float):
        if not (0 < contact_loss_abar < 1):
            raise ValueError(f"contact_loss_abar must lie in (0, 1), got {contact_loss_abar}")
        self.excitation, self.fixation = excitation, fixation
        self.inv_n = 1.0 / excitation.law.n
        self.rate = excitation.speed_scale
        self.eps = excitation.displacement_amplitude
        self.deltabar0 = excitation.deltabar0
        self.log_cap = math.log(SPEED_CAP * self.rate)
        self.contact_loss_abar = contact_loss_abar
        self.compliant = fixation is not None
        self.dim = 3 if self.compliant else 1
        # For n > 1 the variational equations have an unbounded (integrable) coefficient at the
        # turning points that no error-controlled integrator resolves: Psi by differences instead.
        self.variational = excitation.law.n <= 1.0
        if fixation is not None:
            c_o = excitation.contact_scale
            self.force_offset = fixation.mu / (fixation.kappa * c_o**2)
            self.compliance = c_o / fixation.kappa
            self.omega_bar = excitation.omega_check * fixation.nu0
            self.zeta = fixation.zeta


#: Quadratures carried after the core and Psi: u, u cos, u sin, sqrt(w/w0), Phat, Phat cos,
#: Phat sin and, when compliant, xi, xi cos, xi sin.
_N_QUAD_RIGID = 7
_N_QUAD_COMPLIANT = 10


class _Period:
    """The one-period problem from a start state, in scaled variables.

    Scaled core: u = v/V (rigid) or (xi, eta, u) = (xbar/S, xbar'/S, v/V) (compliant), with
    v = rate (abar - abar(0)); the map coordinate of abar is beta = rate abar / V. The
    right-hand sides are closures over the constants (speed: they run ~1e4 times per period).
    """

    def __init__(self, model: _Model, start: Array, v_scale: float, x_scale: float):
        self.m = model
        self.start = np.asarray(start, dtype=float)
        self.b0 = model.rate * float(self.start[-1])
        self.v_scale = v_scale
        self.x_scale = x_scale
        self.dim = model.dim
        self.n_var = self.dim * self.dim
        self.core_rhs, self.full_rhs = (self._compliant_rhs() if model.compliant else self._rigid_rhs())

    # -- conversions

    def abar(self, u: float) -> float:
        return (self.b0 + self.v_scale * u) / self.m.rate

    def core_start(self) -> list[float]:
        if self.m.compliant:
            return [self.start[0] / self.x_scale, self.start[1] / self.x_scale, 0.0]
        return [0.0]

    def full_start(self) -> list[float]:
        n_quad = _N_QUAD_COMPLIANT if self.m.compliant else _N_QUAD_RIGID
        return self.core_start() + [0.0] * (self.n_var + n_quad)

    def absolute(self, core: Sequence[float]) -> Array:
        """Absolute state (xbar, xbar', abar) or (abar,) from the scaled core."""
        if self.m.compliant:
            return np.array([core[0] * self.x_scale, core[1] * self.x_scale, self.abar(core[2])])
        return np.array([self.abar(core[0])])

    def contact_at(self, tau: float, core: Sequence[float]) -> tuple[float, float, tuple[float, ...]]:
        """(abar, deltabar, _contact(...)) at a point of the period."""
        m = self.m
        abar = self.abar(core[-1])
        d = m.deltabar0 - m.eps * math.sin(tau)
        if m.compliant:
            d += core[0] * self.x_scale
        return abar, d, _contact(abar, d, m.inv_n, m.log_cap)

    def deltabar_rate(self, tau: float, core: Sequence[float]) -> float:
        """d deltabar / d tau."""
        rate = -self.m.eps * math.cos(tau)
        return rate + core[1] * self.x_scale if self.m.compliant else rate

    # -- Jacobians (for the implicit integrators)

    def core_jacobian(self, tau: float, y: Array) -> Array:
        """Jacobian of the scaled core right-hand side (the J of the variational equations)."""
        abar, d, (_, x_a, x_d, _, _) = self.contact_at(tau, y.tolist()[: self.dim])
        j10, j11, j12, j20, j22 = self._jacobian_entries(abar, d, x_a, x_d)
        if not self.m.compliant:
            return np.array([[j22]])
        return np.array([[0.0, 1.0, 0.0], [j10, j11, j12], [j20, 0.0, j22]])

    def _jacobian_entries(self, abar: float, d: float, x_a: float, x_d: float) -> tuple[float, ...]:
        """Non-trivial entries (j10, j11, j12, j20, j22) of J in the scaled coordinates (xi, eta, beta).

        Unscaled, in (xbar, xbar', b): row xbar'' = [-(1 + (c_o/kappa) dPhat/ddeltabar), -2 zeta omega_bar,
        -(c_o/kappa) dPhat/dabar / rate] / omega_bar^2 and row v' = [dx/ddeltabar, 0, dx/dabar / rate]; the
        scaling multiplies entry (i, j) by scale_j / scale_i (scales S, S, V).
        """
        m = self.m
        j22 = x_a / m.rate
        if not m.compliant:
            return 0.0, 0.0, 0.0, 0.0, j22
        inv_w2 = 1.0 / m.omega_bar**2
        return (
            (-1.0 - 2.0 * m.compliance * abar) * inv_w2,
            -2.0 * m.zeta / m.omega_bar,
            -m.compliance * (2.0 * d - 2.0 * abar * abar) * inv_w2 * self.v_scale / (m.rate * self.x_scale),
            x_d * self.x_scale / self.v_scale,
            j22,
        )

    def full_jacobian(self, tau: float, y: Array) -> Array:
        """Block-diagonal part of the full Jacobian: J for the core, I (x) J for Psi.

        The one-way couplings of the core into Psi (second derivatives) and into the quadratures
        are left out: the implicit methods use the Jacobian only in the Newton iterations of
        their stages, which the driven components do not slow down.
        """
        core_j = self.core_jacobian(tau, y)
        size = len(self.full_start())
        jac = np.zeros((size, size))
        dim = self.dim
        jac[:dim, :dim] = core_j
        if self.m.compliant:
            jac[dim : dim + 9, dim : dim + 9] = np.kron(core_j, np.eye(3))
        return jac

    # -- right-hand sides

    def _rigid_rhs(self) -> tuple[Callable, Callable]:
        b0, v_scale, m = self.b0, self.v_scale, self.m
        inv_rate, inv_v, d0, eps, inv_n, log_cap = 1.0 / m.rate, 1.0 / v_scale, m.deltabar0, m.eps, m.inv_n, m.log_cap
        sin, cos, contact = math.sin, math.cos, _contact

        def core(tau: float, y: Array) -> list[float]:
            abar = (b0 + v_scale * y.item(0)) * inv_rate
            return [contact(abar, d0 - eps * sin(tau), inv_n, log_cap)[0] * inv_v]

        variational = m.variational

        def full(tau: float, y: Array) -> list[float]:
            u = y.item(0)
            abar = (b0 + v_scale * u) * inv_rate
            s, c = sin(tau), cos(tau)
            x, x_a, _, p, w = contact(abar, d0 - eps * s, inv_n, log_cap)
            return [x * inv_v, x_a * inv_rate if variational else 0.0, u, u * c, u * s, w, p, p * c, p * s]

        return core, full

    def _compliant_rhs(self) -> tuple[Callable, Callable]:
        b0, v_scale, x_scale, m = self.b0, self.v_scale, self.x_scale, self.m
        inv_rate, inv_v, d0, eps, inv_n, log_cap = 1.0 / m.rate, 1.0 / v_scale, m.deltabar0, m.eps, m.inv_n, m.log_cap
        # eta' = (offset - compliance Phat - S xi - 2 zeta omega_bar S eta) / (omega_bar^2 S), Eq. (3')
        offset, compliance = m.force_offset / x_scale, m.compliance / x_scale
        inv_w2, damp = 1.0 / m.omega_bar**2, 2.0 * m.zeta * m.omega_bar
        sin, cos, contact, entries = math.sin, math.cos, _contact, self._jacobian_entries
        variational = m.variational
        no_variation = [0.0] * 9

        def core(tau: float, y: Array) -> list[float]:
            xi, eta, u = y.item(0), y.item(1), y.item(2)
            abar = (b0 + v_scale * u) * inv_rate
            x, _, _, p, _ = contact(abar, x_scale * xi + d0 - eps * sin(tau), inv_n, log_cap)
            return [eta, (offset - compliance * p - xi - damp * eta) * inv_w2, x * inv_v]

        def full(tau: float, y: Array) -> list[float]:
            xi, eta, u = y.item(0), y.item(1), y.item(2)
            abar = (b0 + v_scale * u) * inv_rate
            s, c = sin(tau), cos(tau)
            d = x_scale * xi + d0 - eps * s
            x, x_a, x_d, p, w = contact(abar, d, inv_n, log_cap)
            quadratures = [u, u * c, u * s, w, p, p * c, p * s, xi, xi * c, xi * s]
            core_rates = [eta, (offset - compliance * p - xi - damp * eta) * inv_w2, x * inv_v]
            if not variational:
                return core_rates + no_variation + quadratures
            j10, j11, j12, j20, j22 = entries(abar, d, x_a, x_d)
            p0, p1, p2, p3, p4, p5, p6, p7, p8 = y[3:12].tolist()
            m00, m01, m02 = 1.0 + p0, p1, p2  # M = I + Psi, row-major
            m10, m11, m12 = p3, 1.0 + p4, p5
            m20, m21, m22 = p6, p7, 1.0 + p8
            return core_rates + [  # Psi' = J M with J = [[0, 1, 0], [j10, j11, j12], [j20, 0, j22]]
                m10, m11, m12,
                j10 * m00 + j11 * m10 + j12 * m20, j10 * m01 + j11 * m11 + j12 * m21, j10 * m02 + j11 * m12 + j12 * m22,
                j20 * m00 + j22 * m20, j20 * m01 + j22 * m21, j20 * m02 + j22 * m22,
            ] + quadratures

        return core, full


# --- Integration drivers --------------------------------------------------------------------------


class _IntegrationFailure(RuntimeError):
    """An integrator gave up (step size underflow, step budget, stiffness detected)."""


def _integrate(
    fun: Callable[[float, Array], list[float]],
    jac: Callable[[float, Array], Array],
    tau0: float,
    y0: Sequence[float],
    tau1: float,
    integrator: str,
    rtol: float,
    on_step: Callable[[float, Array], bool] | None = None,
) -> tuple[float, Array, bool]:
    """Integrate from tau0 to tau1; ``on_step(tau, y)`` after every accepted step may stop it.

    The state is scaled to O(1), so one absolute tolerance equal to ``rtol`` serves all
    components. ``jac`` is given to the implicit methods. Returns (tau reached, y there, stopped
    by on_step); raises :class:`_IntegrationFailure` when the integrator gives up.
    """
    if integrator == _FORTRAN:
        solver = ode(fun).set_integrator("dop853", rtol=rtol, atol=rtol, nsteps=_FORTRAN_MAX_STEPS)
        if on_step is not None:
            solver.set_solout(lambda t, y: -1 if on_step(t, y) else 0)
        solver.set_initial_value(list(y0), tau0)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # failures are read from the return code
            y = solver.integrate(tau1)
        code = solver.get_return_code()
        if code < 0:
            raise _IntegrationFailure(f"Fortran DOP853 return code {code}")
        return float(solver.t), np.array(y), code == 2
    solver_class = _IVP_SOLVERS[integrator]
    options = {"jac": jac} if integrator in _IMPLICIT else {}
    solver = solver_class(fun, tau0, np.array(y0, dtype=float), tau1, rtol=rtol, atol=rtol, **options)
    if on_step is not None and on_step(tau0, solver.y):
        return tau0, solver.y.copy(), True
    for _ in range(_IVP_MAX_STEPS):
        if solver.status != "running":
            break
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # LSODA's messages: failures are read from the status
            message = solver.step()
        if solver.status == "failed":
            raise _IntegrationFailure(f"{integrator}: {message}")
        if on_step is not None and on_step(solver.t, solver.y):
            return float(solver.t), solver.y.copy(), True
    else:
        raise _IntegrationFailure(f"{integrator}: more than {_IVP_MAX_STEPS} steps")
    return float(solver.t), solver.y.copy(), False


class _Run(NamedTuple):
    """One integrated period: accepted steps (tau, scaled core) for the refinements."""

    period: _Period
    lost_at: float  # tau of contact loss, NaN if none
    y_end: Array
    steps: list[tuple[float, list[float]]]
    u_range: tuple[float, float]


class _Integrators:
    """Which integrator runs what.

    "auto": the transient from the static state (stiff while the base stroke forces the contact
    to grow: the front then slides along Phi ~ 0 at a huge closing speed) with LSODA,
    which switches to BDF there; the periods near the orbit, which are not stiff for
    omega_check >~ 1e3, with the Fortran DOP853; a run that DOP853 gives up on is repeated with
    Radau. Any other name runs everything.
    """

    def __init__(self, integrator: Integrator, rtol: float):
        if integrator != "auto" and integrator != _FORTRAN and integrator not in _IVP_SOLVERS:
            raise ValueError(f"unknown integrator {integrator!r}")
        if not (1e-13 <= rtol <= 1e-3):
            raise ValueError(f"rtol must lie in [1e-13, 1e-3], got {rtol}")
        self.auto = integrator == "auto"
        self.orbit = _FORTRAN if self.auto else integrator
        self.transient = "LSODA" if self.auto else integrator
        self.rtol = rtol
        self.used: list[str] = []

    def run(self, fun, jac, tau0, y0, tau1, on_step=None, transient: bool = False):
        method = self.transient if transient else self.orbit
        try:
            result = _integrate(fun, jac, tau0, y0, tau1, method, self.rtol, on_step)
        except _IntegrationFailure:
            if not self.auto or method == "Radau":
                raise
            method = "Radau"
            result = _integrate(fun, jac, tau0, y0, tau1, method, self.rtol, on_step)
        if method not in self.used:
            self.used.append(method)
        return result

    def description(self) -> str:
        return "+".join(self.used)


def _run_period(period: _Period, integrators: _Integrators, full: bool, transient: bool = False) -> _Run:
    """Integrate one period, stopping at contact loss; records accepted steps and the range of u."""
    steps: list[tuple[float, list[float]]] = []
    dim, loss = period.dim, period.m.contact_loss_abar
    lost = [math.nan]

    def on_step(tau: float, y: Array) -> bool:
        core = y[:dim].tolist()
        if period.abar(core[-1]) < loss:
            lost[0] = tau
            return True
        if not steps or tau > steps[-1][0]:
            steps.append((tau, core))
        return False

    fun, jac = (period.full_rhs, period.full_jacobian) if full else (period.core_rhs, period.core_jacobian)
    y0 = period.full_start() if full else period.core_start()
    _, y_end, _ = integrators.run(fun, jac, 0.0, y0, TWO_PI, on_step, transient)
    u = [core[-1] for _, core in steps]
    return _Run(period, lost[0], y_end, steps, (min(u), max(u)))


# --- Static state -------------------------------------------------------------------------------


def _jkr_displacement(abar: float) -> float:
    """s(a) = a^2 - sqrt(a): static deltabar of Eq. (5') with w = w0."""
    return abar * abar - math.sqrt(abar)


def _jkr_force(abar: float) -> float:
    """p(a) = (4/3) a^3 - 2 a^(3/2): static Phat of Eq. (4') with w = w0."""
    return (4.0 / 3.0) * abar**3 - 2.0 * abar**1.5


def static_state(excitation: BaseExcitation, fixation: SpringFixation | None = None) -> StaticState:
    """Static equilibrium (Eqs. A.4–A.7): the largest root of g(a) = 0 (module docstring).

    Raises :class:`NoStaticContactError` when there is no static contact (a tensile preset
    beyond the JKR pull-off of the displacement-controlled assembly).
    """
    d0 = excitation.deltabar0
    if fixation is None:
        def excess(a: float) -> float:
            return _jkr_displacement(a) - d0
    else:
        c_o = excitation.contact_scale
        stiffness, cube = fixation.kappa * c_o**2, c_o**3

        def excess(a: float) -> float:
            return stiffness * (_jkr_displacement(a) - d0) + cube * _jkr_force(a) - fixation.mu

    hi = 2.0
    while excess(hi) <= 0:
        hi *= 2.0
    lo = hi
    while excess(lo) > 0:
        lo *= 0.9
        if lo < 1e-9:
            raise NoStaticContactError(f"no static contact for deltabar0 = {d0} (Eqs. A.4–A.7)")
    abar = brentq(excess, lo, lo / 0.9, xtol=1e-15, rtol=4 * np.finfo(float).eps)
    if fixation is None:
        # The stable branch of displacement control is a > 4^(-2/3) where s is increasing.
        if abar < 4.0 ** (-2.0 / 3.0):
            raise NoStaticContactError(f"deltabar0 = {d0} is beyond the JKR fixed-grip pull-off (-0.4725)")
        return StaticState(abar, 0.0, _jkr_force(abar))
    return StaticState(abar, _jkr_displacement(abar) - d0, _jkr_force(abar))


def _absolute_start(model: _Model, state: Sequence[float] | None) -> Array:
    if state is None:
        st = static_state(model.excitation, model.fixation)
        return np.array([st.xbar, 0.0, st.abar] if model.compliant else [st.abar])
    start = np.asarray(state, dtype=float).ravel()
    if start.size != model.dim or not np.all(np.isfinite(start)) or not start[-1] > 0:
        raise ValueError(f"initial state must be {model.dim} finite numbers with abar > 0, got {state}")
    return start


# --- Scales ----------------------------------------------------------------------------------------


def _v_scale_estimate(model: _Model, abar: float) -> float:
    """A guess of the half range of v = rate (abar - abar(0)) over a period.

    The smaller of the frozen-contact value (abar fixed, v' = x(Phi(abar, deltabar(tau))), the
    limit omega_check -> infinity) and the quasi-static one (v follows the JKR compliance, rate
    eps); only used to scale the first integration, later ones use the observed range.
    """
    tau = np.linspace(0.0, TWO_PI, 257)
    d = model.deltabar0 - model.eps * np.sin(tau)
    gap = np.maximum(abar * abar - d, 1e-150)
    law = model.excitation.law
    x = np.clip(law.speed(gap * gap / abar), -SPEED_CAP * model.rate, SPEED_CAP * model.rate)
    u = np.concatenate([[0.0], np.cumsum(0.5 * (x[1:] + x[:-1]) * np.diff(tau))])
    frozen = 0.5 * float(u.max() - u.min())
    return max(min(frozen, model.rate * model.eps), _v_scale_floor(model, abar))


def _v_scale_floor(model: _Model, abar: float) -> float:
    """Smallest scale of v: a change of abar below the resolution of abar itself."""
    return 1e-14 * model.rate * abar


def _x_scale(model: _Model, start: Array) -> float:
    return max(model.eps, abs(float(start[0])), abs(float(start[1])), 1e-280) if model.compliant else 1.0


def _observed_v_scale(run: _Run) -> float:
    """Half range of v over the run (the natural scale of the next run), floored."""
    lo, hi = run.u_range
    half = 0.5 * (hi - lo) * run.period.v_scale
    return max(half, _v_scale_floor(run.period.m, float(run.period.start[-1])))


def _periodic_to_rounding(run: _Run, integrators: _Integrators) -> bool:
    """Whether the run returns to its start to the accuracy of the integration.

    Each scaled core component within _PERIODIC_RESIDUAL_FACTOR rtol of the scaled range, where
    the abar component also passes when its drift is below the resolution of abar itself (a
    contact that does not move: its scaled range is then meaningless).
    """
    period = run.period
    residual = np.abs(run.y_end[: period.dim] - np.array(period.core_start()))
    tolerance = _PERIODIC_RESIDUAL_FACTOR * integrators.rtol * _scaled_core_range(run)
    abar_drift = residual[-1] * period.v_scale / period.m.rate
    abar_ok = residual[-1] <= tolerance or abar_drift <= 4.0 * np.finfo(float).eps * float(period.start[-1])
    return bool(abar_ok and np.all(residual[:-1] <= tolerance))


def _scaled_core_range(run: _Run) -> float:
    """Largest magnitude of the scaled core over the accepted steps (O(1) when the scales fit)."""
    return max(1.0, max(abs(c) for _, core in run.steps for c in core))


# --- Analysis of a converged period --------------------------------------------------------------


def _refine_roots(
    run: _Run, integrators: _Integrators, g: Callable[[float, list[float]], float]
) -> list[tuple[float, list[float]]]:
    """Points (tau, scaled core) where g changes sign between accepted steps, by Brent + re-integration.

    The state inside a step is obtained by integrating from the step's start, so the root is
    located to ~1e-14 in tau on the integrated solution itself. A sign change that re-integration
    does not reproduce (g at rounding level, as for a contact that does not move) is dropped.
    """
    period = run.period
    values = [g(t, core) for t, core in run.steps]
    roots = []
    for k in range(len(run.steps) - 1):
        if values[k] == 0.0:
            roots.append(run.steps[k])
            continue
        if values[k] * values[k + 1] >= 0.0:
            continue
        tau_k, core_k = run.steps[k]

        def state(tau: float) -> list[float]:
            if tau == tau_k:
                return core_k
            return integrators.run(period.core_rhs, period.core_jacobian, tau_k, core_k, tau)[1].tolist()

        tau_end = run.steps[k + 1][0]
        if values[k] * g(tau_end, state(tau_end)) >= 0.0:
            continue
        tau_root = brentq(lambda t: g(t, state(t)), tau_k, tau_end, xtol=1e-14, rtol=1e-15)
        roots.append((tau_root, state(tau_root)))
    return roots


def _summarise(
    model: _Model, run: _Run, integrators: _Integrators, multipliers: NDArray[np.complex128],
    residual: float, iterations: int, speed_range: tuple[float, float] | None,
) -> SteadyState:
    """The record of a converged period: quadratures, refined extremes of a and of Phi."""
    period = run.period
    dim, rate, v_scale = model.dim, model.rate, period.v_scale
    quad = run.y_end[dim + period.n_var :]
    a0 = float(period.start[-1])

    # Extremes of a: where x = 0, i.e. Phi = 1, i.e. gap^2 = abar.
    def turning(tau: float, core: list[float]) -> float:
        abar, d, _ = period.contact_at(tau, core)
        return (abar * abar - d) ** 2 - abar

    # Extremes of Phi (of the speed, which decreases with Phi): dPhi/dtau = Phi_a a' + Phi_d deltabar' = 0.
    def dphi_dtau(tau: float, core: list[float]) -> float:
        abar, d, contact = period.contact_at(tau, core)
        gap = abar * abar - d
        phi_a, phi_d = gap * (3 * abar * abar + d) / (abar * abar), -2.0 * gap / abar
        return phi_a * contact[0] / rate + phi_d * period.deltabar_rate(tau, core)

    u_values = [0.0, *(core[-1] for _, core in _refine_roots(run, integrators, turning))]
    u_values.append(float(run.y_end[dim - 1]))
    half_range = 0.5 * (max(u_values) - min(u_values)) * v_scale  # in v units: = Abar
    candidates = [*run.steps, *_refine_roots(run, integrators, dphi_dtau)]
    peak_speed = max(abs(period.contact_at(t, core)[2][0]) for t, core in candidates)

    abar_m = a0 + quad[0] * v_scale / (TWO_PI * rate)
    a_c, a_s = quad[1] * v_scale / (math.pi * rate), quad[2] * v_scale / (math.pi * rate)
    phat_m, phat_c, phat_s = quad[4] / TWO_PI, quad[5] / math.pi, quad[6] / math.pi
    d_m, d_c, d_s = model.deltabar0, 0.0, -model.eps
    if model.compliant:
        d_m += quad[7] * period.x_scale / TWO_PI
        d_c += quad[8] * period.x_scale / math.pi
        d_s += quad[9] * period.x_scale / math.pi
    in_range = None if speed_range is None else bool(speed_range[0] <= peak_speed <= speed_range[1])
    status: Status = "converged"
    message = "periodic steady state"
    if peak_speed > _RESOLVED_SPEED_FRACTION * SPEED_CAP * rate:
        status = "speed_unresolved"
        message = f"peak |d abar/d tau| = {peak_speed / rate:.3g} is within 1e-3 of the numerical speed cap"
    return SteadyState(
        status=status, message=message, start_state=period.start.copy(), abar_m=abar_m,
        abar=half_range, a_over_am=half_range / (rate * abar_m), a1_over_am=math.hypot(a_c, a_s) / abar_m,
        a_c=a_c, a_s=a_s, w_eff_ratio=(quad[3] / TWO_PI) ** 2, pm_over_abs_pjkr=phat_m / -PHAT_JKR,
        phat_m=phat_m, phat_c=phat_c, phat_s=phat_s, deltabar_m=d_m, deltabar_c=d_c, deltabar_s=d_s,
        peak_speed=peak_speed, peak_speed_in_range=in_range, floquet_multipliers=multipliers,
        stable=bool(np.all(np.abs(multipliers) < 1.0)), periodicity_residual=residual, iterations=iterations,
        integrator=integrators.description(), tau_contact_loss=math.nan,
    )


def _failure(status: Status, message: str, model: _Model, start: Array, iterations: int,
             integrators: _Integrators, tau_loss: float = math.nan) -> SteadyState:
    nan = math.nan
    return SteadyState(
        status, message, np.asarray(start, dtype=float).copy(), nan, nan, nan, nan, nan, nan, nan, nan, nan,
        nan, nan, nan, nan, nan, nan, None, np.full(model.dim, nan, dtype=complex), False, nan, iterations,
        integrators.description(), tau_loss,
    )


# --- Shooting ------------------------------------------------------------------------------------


def _evaluate(model: _Model, start: Array, v_scale: float, integrators: _Integrators, transient: bool = False) -> _Run:
    """One period from ``start`` with the variational equations and the quadratures."""
    period = _Period(model, start, v_scale, _x_scale(model, start))
    return _run_period(period, integrators, full=True, transient=transient)


def _psi(run: _Run, integrators: _Integrators) -> Array:
    """Psi(2pi) = M - I at the run's start, in its scaled coordinates.

    From the variational equations (n <= 1), or by central differences of the one-period map
    with the step _FD_STEP in the scaled coordinates (n > 1; absolute error ~1e-5 from the
    ~1e-10 integration error of the residual, which limits the multipliers to that accuracy).
    """
    period, dim = run.period, run.period.dim
    if period.m.variational:
        return run.y_end[dim : dim + dim * dim].reshape(dim, dim)
    unscale = [period.x_scale, period.x_scale, period.v_scale / period.m.rate][-dim:]
    psi = np.empty((dim, dim))
    for j in range(dim):
        residuals = []
        for sign in (1.0, -1.0):
            shifted = period.start.copy()
            shifted[j] += sign * _FD_STEP * unscale[j]
            neighbour = _Period(period.m, shifted, period.v_scale, period.x_scale)
            neighbour_run = _run_period(neighbour, integrators, full=False)
            if not math.isnan(neighbour_run.lost_at):
                raise _IntegrationFailure("contact lost next to the orbit: no finite-difference monodromy")
            residuals.append(neighbour_run.y_end[:dim] - np.array(neighbour.core_start()))
        psi[:, j] = (residuals[0] - residuals[1]) / (2.0 * _FD_STEP)
    return psi


def _frozen_drift(model: _Model, abar: float, deltabar_mean: float, amplitude: float, samples: int = 512) -> float:
    """Mean front speed <x(Phi(abar, deltabar(tau)))> over a period, abar frozen.

    deltabar(tau) = deltabar_mean - amplitude sin tau (the phase does not change the mean).
    Its root is the limit omega_check -> infinity of the steady contact radius: the contact cannot
    drift over a period. Periodic trapezoid rule on ``samples`` points; where abar^2 <= deltabar
    the contact closes at the capped speed.
    """
    tau = np.linspace(0.0, TWO_PI, samples, endpoint=False)
    gap = abar * abar - (deltabar_mean - amplitude * np.sin(tau))
    cap = SPEED_CAP * model.rate
    x = np.full_like(tau, cap)
    valid = gap > 0
    x[valid] = model.excitation.law.speed(np.maximum(gap[valid] ** 2 / abar, 1e-300))
    return float(np.mean(np.clip(x, -cap, cap)))


def _frozen_excitation(model: _Model, abar: float) -> tuple[float, complex]:
    """(mean deltabar, complex amplitude of xbar) with the contact radius frozen at ``abar``.

    Rigid: (deltabar0, 0). Compliant: with abar fixed, Phat = 2 abar deltabar - (2/3) abar^3 is
    linear in deltabar = xbar + deltabar0 - eps sin tau, so Eq. (3') is a linear oscillator with
    the contact stiffness 2 abar (units of E* a_o): with sigma = c_o/kappa,
    mean xbar = (mu/(kappa c_o^2) - sigma (2 abar deltabar0 - (2/3) abar^3))/(1 + 2 abar sigma), and
    xbar - mean = Im(X e^{i tau}), X = 2 abar sigma eps/(1 + 2 abar sigma - omega_bar^2 + 2i zeta omega_bar)
    (the denominator is kept away from 0 at an undamped resonance: a guess, not a result).
    """
    if not model.compliant:
        return model.deltabar0, 0j
    sigma = model.compliance
    stiffness = 1.0 + 2.0 * abar * sigma
    x_mean = (model.force_offset - sigma * (2.0 * abar * model.deltabar0 - (2.0 / 3.0) * abar**3)) / stiffness
    denominator = complex(stiffness - model.omega_bar**2, 2.0 * model.zeta * model.omega_bar)
    if abs(denominator) < 1e-2 * stiffness:
        denominator = 1e-2 * stiffness * (denominator / abs(denominator) if denominator != 0 else 1.0)
    return x_mean + model.deltabar0, 2.0 * abar * sigma * model.eps / denominator


def _frozen_start(model: _Model) -> Array | None:
    """Start of the periodic orbit in the limit omega_check -> infinity (a guess for the shooting).

    The contact radius is the largest root of the frozen drift (:func:`_frozen_drift`) with the
    contact displacement deltabar = mean + Im((X - eps) e^{i tau}) of :func:`_frozen_excitation`;
    None when no root is bracketed.
    """
    def drift(abar: float) -> float:
        d_mean, x_hat = _frozen_excitation(model, abar)
        return _frozen_drift(model, abar, d_mean, abs(x_hat - model.eps))

    hi = 1.0
    while drift(hi) > 0:
        hi *= 2.0
        if hi > _MAX_ABAR:
            return None
    lo = 0.5 * hi
    while drift(lo) <= 0:
        lo, hi = 0.5 * lo, lo
        if lo < 1e-3:
            return None
    abar = brentq(drift, lo, hi, xtol=1e-12)
    if not model.compliant:
        return np.array([abar])
    d_mean, x_hat = _frozen_excitation(model, abar)
    return np.array([d_mean - model.deltabar0 + x_hat.imag, x_hat.real, abar])


def _shoot_rigid(model: _Model, start: Array, integrators: _Integrators, max_iterations: int,
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
    v_scale = _v_scale_estimate(model, a)
    lower = 0.0  # largest a0 known to have r > 0 or to lose contact: the fixed point lies above
    lower_is_loss = True
    upper = math.inf  # smallest a0 known to have r < 0
    if guess is not None:
        # The physical first period from the static state (core only, stiff integrator): contact
        # loss there is the answer; otherwise it tells on which side of the start the state lies.
        first = _run_period(_Period(model, start, v_scale, 1.0), integrators, full=False, transient=True)
        if not math.isnan(first.lost_at):
            return _failure("contact_loss", f"contact lost at tau = {first.lost_at:.6g} in the first period "
                            f"from the static state abar = {a:.6g}", model, start, 1, integrators, first.lost_at)
        v_scale = _observed_v_scale(first)
        if first.y_end[0] > 0:
            lower, lower_is_loss = a, False
        elif first.y_end[0] < 0:
            upper = a
        # A static state that is already periodic to rounding (a contact that does not move) is
        # the state reached; otherwise the iteration starts from the guess.
        if lower < guess < upper and not _periodic_to_rounding(first, integrators):
            a = guess
    periods = 0 if guess is None else 1
    previous: tuple[float, float] | None = None  # (a0, g) of the last evaluation with r' < 0
    while periods < max_iterations:
        run = _evaluate(model, np.array([a]), v_scale, integrators)
        periods += 1
        a_next = math.nan
        if not math.isnan(run.lost_at):
            lower, lower_is_loss = a, True
        else:
            v_scale = _observed_v_scale(run)
            u_end = float(run.y_end[0])
            drift = run.period.v_scale * u_end / model.rate  # r = abar(2pi) - abar(0)
            if model.variational:
                log_multiplier = float(run.y_end[1])
                slope = math.expm1(log_multiplier)  # r'(a0) = multiplier - 1
            else:
                slope = float(_psi(run, integrators)[0, 0])
                log_multiplier = math.log1p(slope) if slope > -1 else -math.inf
            if drift > 0:
                lower, lower_is_loss = a, False
            elif drift < 0:
                upper = a
            if slope < 0:
                g = drift / slope
                g_slope = 1.0
                if previous is not None and previous[0] != a:
                    secant = (g - previous[1]) / (a - previous[0])
                    g_slope = secant if secant > 0 else 1.0
                previous = (a, g)
                step = -g / g_slope
                # uncertainty of the fixed point caused by the integration error of v(2pi)
                noise = (_GLOBAL_ERROR_FACTOR * integrators.rtol * _scaled_core_range(run) * run.period.v_scale
                         / (model.rate * abs(slope) * g_slope))
                if _periodic_to_rounding(run, integrators) or abs(step) <= max(_NEWTON_XTOL * a, noise):
                    multiplier = np.array([math.exp(log_multiplier)], dtype=complex)
                    return _summarise(model, run, integrators, multiplier, abs(drift) / a, periods, speed_range)
                a_next = a + step
        if not (lower < a_next < upper):  # also catches NaN
            if math.isfinite(upper):
                a_next = 0.5 * (lower + upper)
            elif lower_is_loss or a <= lower:
                a_next = 2.0 * max(a, lower)
            else:
                a_next = a + 2.0 * max(a - lower, 1e-3 * a)
        if math.isfinite(upper) and upper - lower <= 4e-16 * upper:
            if lower_is_loss:
                return _failure("contact_loss", "the transient from the start state drifts to contact loss: "
                                "no periodic state between the start and the loss boundary", model,
                                np.array([a]), periods, integrators)
            break
        if a_next > _MAX_ABAR:
            break
        a = a_next
    return _failure("not_converged", f"shooting did not converge in {periods} periods",
                    model, np.array([a]), periods, integrators)


def _shoot_compliant(model: _Model, start: Array, integrators: _Integrators, max_iterations: int,
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
    v_scale = _v_scale_estimate(model, float(z[2]))
    periods = 0
    if guess is not None:
        first = _run_period(_Period(model, z, v_scale, _x_scale(model, z)), integrators, full=False, transient=True)
        periods += 1
        if not math.isnan(first.lost_at):
            return _failure("contact_loss", f"contact lost at tau = {first.lost_at:.6g} in the first period from "
                            f"the static state {z.tolist()}", model, z, 1, integrators, first.lost_at)
        if not _periodic_to_rounding(first, integrators):
            z = guess.copy()
    run = _evaluate(model, z, v_scale, integrators)
    periods += 1
    if not math.isnan(run.lost_at):
        return _failure("contact_loss", f"contact lost at tau = {run.lost_at:.6g} in the first period from "
                        f"{z.tolist()}", model, z, periods, integrators, run.lost_at)

    def correction(run: _Run) -> tuple[Array, Array, float, bool] | None:
        """(g and the residual in absolute units, noise of g in scaled units, residual at rounding level)."""
        period = run.period
        residual = run.y_end[:3] - np.array(period.core_start())
        psi = _psi(run, integrators)
        try:
            g_scaled = np.linalg.solve(psi, residual)
            noise = (_GLOBAL_ERROR_FACTOR * integrators.rtol * _scaled_core_range(run)
                     * np.linalg.norm(np.linalg.inv(psi), np.inf))
        except np.linalg.LinAlgError:
            return None
        unscale = np.array([period.x_scale, period.x_scale, period.v_scale / model.rate])
        return g_scaled * unscale, residual * unscale, noise, _periodic_to_rounding(run, integrators)

    broyden = np.eye(3)
    previous: tuple[Array, Array] | None = None
    current = correction(run)
    while current is not None and periods < max_iterations:
        v_scale = _observed_v_scale(run)
        g, residual, noise, at_rounding = current
        scales = np.array([run.period.x_scale, run.period.x_scale, max(v_scale / model.rate, 1e-14 * z[2])])
        weight = 1.0 / scales**2
        if previous is not None:
            s_k, y_k = z - previous[0], g - previous[1]
            denominator = float(s_k @ (weight * s_k))
            if denominator > 0:
                broyden = broyden + np.outer(y_k - broyden @ s_k, weight * s_k) / denominator
        try:
            step = -np.linalg.solve(broyden, g)
        except np.linalg.LinAlgError:
            broyden = np.eye(3)
            step = -g
        converged = np.all(np.abs(step) <= _NEWTON_XTOL * np.array([scales[0], scales[1], z[2]]))
        if converged or at_rounding or float(np.max(np.abs(step) / scales)) <= noise:
            relative = np.abs(residual) / np.array([scales[0], scales[1], z[2]])
            multipliers = 1.0 + np.linalg.eigvals(_psi(run, integrators))
            return _summarise(model, run, integrators, multipliers, float(np.max(relative)), periods, speed_range)
        merit = float(np.max(np.abs(g) / scales))
        previous = (z.copy(), g)
        for halving in range(6):
            trial = z + 0.5**halving * step
            if trial[2] <= 0:
                continue
            periods += 1
            try:
                trial_run = _evaluate(model, trial, v_scale, integrators)
            except _IntegrationFailure:
                continue
            trial_correction = correction(trial_run) if math.isnan(trial_run.lost_at) else None
            if trial_correction is not None and (
                    float(np.max(np.abs(trial_correction[0]) / scales)) < merit or halving == 5):
                z, run, current = trial, trial_run, trial_correction
                break
            if periods >= max_iterations:
                break
        else:
            return _failure("not_converged", "every damped step lost the contact or had a singular Jacobian",
                            model, z, periods, integrators)
    if current is None:
        return _failure("not_converged", "singular monodromy matrix minus identity", model, z, periods,
                        integrators)
    return _failure("not_converged", f"shooting did not converge in {periods} periods", model, z, periods,
                    integrators)


def steady_state(
    excitation: BaseExcitation,
    fixation: SpringFixation | None = None,
    *,
    initial_state: Sequence[float] | None = None,
    speed_range: tuple[float, float] | None = None,
    rtol: float = 1e-12,
    integrator: Integrator = "auto",
    contact_loss_abar: float = 1e-3,
    max_iterations: int = 40,
) -> SteadyState:
    """Periodic steady state of the full model by shooting on the one-period map.

    ``fixation=None`` is the rigid fixation. ``initial_state`` (layout of
    ``SteadyState.start_state``) defaults to the static state (Eq. 10); a continuation passes the
    previous orbit's ``start_state``. ``speed_range`` = (lo, hi) is the range of |adot|/v0 in which
    the rate law was characterised. ``integrator``: "auto" (see :class:`_Integrators`),
    "fortran-dop853" (:class:`scipy.integrate.ode`), or a :func:`scipy.integrate.solve_ivp`
    method name for everything. Numerical failure and contact loss are returned as the
    ``status`` of the record, never as numbers.
    """
    model = _Model(excitation, fixation, contact_loss_abar)
    start = _absolute_start(model, initial_state)
    integrators = _Integrators(integrator, rtol)
    try:
        guess = _frozen_start(model) if initial_state is None else None
        if model.compliant:
            return _shoot_compliant(model, start, integrators, max_iterations, speed_range, guess)
        return _shoot_rigid(model, start, integrators, max_iterations, speed_range,
                            None if guess is None else float(guess[0]))
    except _IntegrationFailure as error:
        return _failure("integration_failure", str(error), model, start, 0, integrators)


def transient(
    excitation: BaseExcitation,
    fixation: SpringFixation | None = None,
    *,
    periods: int,
    initial_state: Sequence[float] | None = None,
    rtol: float = 1e-12,
    integrator: Integrator = "auto",
    contact_loss_abar: float = 1e-3,
) -> Transient:
    """Brute-force integration from the static state (or ``initial_state``) over ``periods`` periods.

    The reference the shooting is checked against; each period is integrated from the state the
    previous one ended in (the front displacement v is re-based every period, so abar keeps
    full precision). Raises :class:`RuntimeError` if the integrator fails.
    """
    if periods < 1:
        raise ValueError("periods must be at least 1")
    model = _Model(excitation, fixation, contact_loss_abar)
    state = _absolute_start(model, initial_state)
    integrators = _Integrators(integrator, rtol)
    states = [state]
    v_scale = _v_scale_estimate(model, float(state[-1]))
    for k in range(periods):
        period = _Period(model, state, v_scale, _x_scale(model, state))
        try:
            run = _run_period(period, integrators, full=False, transient=True)
        except _IntegrationFailure as error:
            raise RuntimeError(f"transient integration failed in period {k + 1}: {error}") from error
        if not math.isnan(run.lost_at):
            return Transient("contact_loss", np.array(states), TWO_PI * k + run.lost_at)
        v_scale = _observed_v_scale(run)
        state = period.absolute(run.y_end.tolist())
        states.append(state)
    return Transient("completed", np.array(states), math.nan)
