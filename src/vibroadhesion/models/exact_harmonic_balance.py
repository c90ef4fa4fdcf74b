"""Exact harmonic balance of the single-harmonic ansatz: the Discussion's recommendation (Eqs. 125–126).

Notation as in :mod:`vibroadhesion.models.frozen_radius`: abar = a/a_o, deltabar = delta R/a_o^2,
Phat = P R/(E* a_o^3) (JKR pull-off -3/4), c_o = a_o/R = 2^(1/3) 3^(-2/3) chi0, s = sqrt(w/w0),
etahat = eta1/c_o^2, and tau' = omega t' the phase-shifted time of Eq. (25).

Ansatz and exact coefficients. With a = a_m + A sin tau' (Eq. 25) the contact-front speed is
adot/v0 = Abar cos tau' (Abar = omega A/v0, Eq. 45) and, in units of a_o,

    abar(tau') = abar_m + A_over_ao sin tau',   A_over_ao = A/a_o = Abar/(omega_check c_o)   (Eqs. 45, 86, 105),
    s(tau') = sqrt(f(Abar cos tau'))   exactly (Eq. 26 is exact for this ansatz).

Eqs. (4)–(5) -- equivalently (125)–(126), which only subtract the means -- are kept exact, with no
linearisation in A:

    deltabar(tau') = abar^2 - s sqrt(abar),    Phat(tau') = (4/3) abar^3 - 2 s abar^(3/2).

Their means and first harmonics (Eqs. 30–31: X_c = (1/pi) int X cos tau', X_s = (1/pi) int X sin tau')
follow from the powers of abar, which contain only sin tau' (abar^2: mean abar_m^2 + A_over_ao^2/2,
sine coefficient 2 abar_m A_over_ao; abar^3: mean abar_m^3 + (3/2) abar_m A_over_ao^2, sine coefficient
3 abar_m^2 A_over_ao + (3/4) A_over_ao^3, from sin^3 = (3 sin - sin 3)/4), and from three integrals of s
against g(abar) for g = sqrt and g = (.)^(3/2):

    K0[g] = (1/2pi) int s g(abar),   Kc[g] = (1/pi) int s g(abar) cos tau',   Ks[g] = (1/pi) int s g(abar) sin tau',

    mean deltabar = abar_m^2 + A_over_ao^2/2 - K0[sqrt],       deltabar_c = -Kc[sqrt],
    deltabar_s = 2 abar_m A_over_ao - Ks[sqrt],
    mean Phat = (4/3) abar_m^3 + 2 abar_m A_over_ao^2 - 2 K0[3/2],   Phat_c = -2 Kc[3/2],
    Phat_s = 4 abar_m^2 A_over_ao + A_over_ao^3 - 2 Ks[3/2].

Folding tau' -> -tau' (s even, sin odd) and tau' -> pi - tau', and writing t = pi/2 - tau' (the distance
from the reversal of the contact front) as in :mod:`vibroadhesion.core.integrals`, with
S(v) = s(v) + s(-v), D(v) = s(v) - s(-v), v = Abar sin t and g+- = g(abar_m +- A_over_ao cos t):

    K0 = (1/2pi) int_0^(pi/2) S (g+ + g-) dt,   Kc = (1/pi) int D sin t (g+ + g-) dt,
    Ks = (1/pi) int S cos t (g+ - g-) dt,

where g+ - g- is formed without cancellation: sqrt: 2 e/(sqrt(a+) + sqrt(a-)); 3/2:
(6 a^2 e + 2 e^3)/(a+^(3/2) + a-^(3/2)), e = A_over_ao cos t. The quadrature is the fixed rule of the
J-integrals (:mod:`vibroadhesion.core.integrals`), which resolves the |sin t|^n behaviour of S and D at the
turning point and their boundary layer t ~ 1/Abar; the g factors are smooth for A_over_ao < abar_m
(A < a_m, required for abar(tau') > 0). Measured against 25-digit mpmath: relative error below 2e-13
for A_over_ao/abar_m up to 0.99, Abar up to 1e8 and n in [0.05, 4] (tests/test_exact_harmonic_balance.py;
the mean indentation, which nearly cancels at the nominal point, to 1e-13 abar_m^2 absolute). The effective
work of adhesion is w_eff/w0 = (mean s)^2 = J0^2 exactly (Eq. 18).

Linearisation (the paper's refined model). Expanding g+- in A_over_ao: g+ + g- = 2 sqrt(a) -
(A_over_ao c)^2/(4 a^(3/2)) + O(A_over_ao^4) and g+ - g- = A_over_ao c/sqrt(a) + O(A_over_ao^3) for sqrt;
2 a^(3/2) + O(A_over_ao^2) and 3 sqrt(a) A_over_ao c + O(A_over_ao^3) for 3/2. With J0 = (1/pi) int S,
Jc1 = (2/pi) int D sin t, J1 = (2/pi) int S cos^2 t and (2/pi) int D sin t cos^2 t = (Jc1 - Jc3)/4
(from cos x sin^2 x = (cos x - cos 3x)/4 in Eq. 29):

    mean deltabar = abar_m^2 - J0 sqrt(abar_m) + A_over_ao^2 (1/2 + J1/(16 abar_m^(3/2))) + O(A_over_ao^4)
    deltabar_c = -sqrt(abar_m) Jc1 + A_over_ao^2 (Jc1 - Jc3)/(32 abar_m^(3/2)) + O(A_over_ao^4)   [Eq. 93: first term]
    deltabar_s = 2 abar_m A_over_ao (1 - J1/(4 abar_m^(3/2))) + O(A_over_ao^3)                    [Eq. 94]
    mean Phat = (4/3) abar_m^3 - 2 J0 abar_m^(3/2) + O(A_over_ao^2)                               [Eq. 52]
    Phat_c = -2 abar_m^(3/2) Jc1 + O(A_over_ao^2)                                                 [Eq. 95]
    Phat_s = 4 abar_m^2 A_over_ao (1 - 3 J1/(4 abar_m^(3/2))) + O(A_over_ao^3)                    [Eq. 96]

Multiplying by c_o^2 (deltabar -> delta/R) and c_o^3/kappa (Phat -> P/(kR)) with 2 c_o = 2^(4/3)
3^(-2/3) chi0, c_o^2 = 2^(2/3) 3^(-4/3) chi0^2, c_o^3 = (2/9) chi0^3 and A_over_ao c_o = Abar/omega_check
= nu0 Abar/omega_bar gives exactly the refined coefficients (93)–(96) (tested).

Mean balance (Eq. 15). delta_m + P_m/k = hhat - h0 + mg/k; with delta_m = deltabar_m a_o^2/R,
P_m = Phat_m E* a_o^3/R, k = kappa E* R and mu = mg/(E* R^2) (Eq. 81), dividing by a_o^2/R,

    mean deltabar + (c_o/kappa) mean Phat = base_offset + mu/(kappa c_o^2),   base_offset = (hhat - h0) R/a_o^2.

For h0 = hhat (Eq. 78) and the linearised means this is Eq. (87) divided by kappa (checked:
(4/3) c_o = 2^(7/3) 3^(-5/3) chi0, mu/c_o^2 = 3^(4/3) mu/(2^(2/3) chi0^2)); kappa -> infinity gives
the rigid condition mean deltabar = base_offset (Eq. 56 generalised), and for rigid fixation the
amplitude condition of Eqs. (90)–(92), (100) is deltabar_c^2 + deltabar_s^2 = etahat^2.

High-frequency limit (rigid fixation). As omega_check -> infinity at fixed eta1, A_over_ao =
Abar/(omega_check c_o) -> 0 with Abar bounded, so the exact balance tends to the leading order
(Eq. 55 with abar_m^(3/2) = J0, Eq. 123); the first corrections are the O(A_over_ao^2) terms above (the
truncated system is solved in the tests and agrees with the exact balance to O(A_over_ao^4)). It
does *not* tend to the exact high-frequency limit of :mod:`vibroadhesion.models.exact_averaging`: the ansatz
keeps a sinusoidal contact-front speed however fast the excitation (see that module's docstring).
As eta1 -> 0 at fixed omega_check the exact balance and the refined model (Eqs. 122–123) differ by
O(A_over_ao^2), with limits that follow from the expansions above at J -> (1, 0, 1), int S cos^4/pi -> 3/8:

* abar_m(exact) - abar_m(refined) -> -(3/8) A_over_ao^2: the mean equation's A_over_ao^2 term (1/2 + 1/16)
  divided by d(abar^2 - sqrt(abar))/d abar = 3/2 at abar = 1;
* Abar(exact)/Abar(refined) - 1 -> c A_over_ao^2. For n > 1 the amplitude is deltabar_s at small Abar
  (Jc1 ~ Abar^n is smaller than A_over_ao ~ Abar): deltabar_s/A_over_ao = 2 abar_m - J1/(2 sqrt(abar_m))
  - A_over_ao^2 Js4/(8 abar_m^(5/2)) loses ((9/4)(3/8) + 3/64) A_over_ao^2 of its 3/2, so c = 19/32. For
  n < 1 it is deltabar_c: sqrt(abar_m) |Jc1| loses (3/16 + (1 - rho3)/32) A_over_ao^2 relatively, with
  rho3 = lim Jc3/Jc1 = (n - 1)/(n + 3) (from s = 1 - sign(v)|v|^n/2 + ...), and d ln|Jc1|/d ln Abar -> n,
  so c = (3/16 + 1/(8(n + 3)))/n.

Domain. The ansatz needs A < a_m, and the mean equation must keep a stable root (mean deltabar rises
with abar_m). For the nominal point contact the amplitude sqrt(deltabar_c^2 + deltabar_s^2) reached
along that branch is bounded: at low omega_check it peaks (near A/a_m = 0.75 for h1 = 20 um,
omega_check = 1e3, n = 0.531) and the branch ends (no stable mean radius) near A/a_m = 0.94. Larger base
amplitudes have no single-harmonic steady state (:class:`NoSteadyStateError`; e.g. h1 = 20 um at
omega_check = 1e3 and h1 = 100 um up to omega_check = 1e5, where the refined model returns A/a_m =
0.61 and 0.57 .. 2.8); between the end value and the peak there are two roots, and the solver returns
the smaller one, which continues the refined solution.
"""

from __future__ import annotations

import math
from typing import Generic, NamedTuple, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from vibroadhesion.core import groups
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import PHAT_JKR, contact_radius_ratio
from vibroadhesion.core.integrals import folded_rule, gent_schultz_u
from vibroadhesion.core.ratelaw import GentSchultz, RateLaw
from vibroadhesion.core.records import SteadyState
from vibroadhesion.models.compliant import amplitude_log_residual
from vibroadhesion.models.frozen_radius import NoSteadyStateError
from vibroadhesion.models.refined import nominal_point_contact as refined_nominal_point_contact
from vibroadhesion.numerics.roots import NoRootError

Array = NDArray[np.float64]
#: The coefficients' type: arrays over amplitudes (:func:`exact_harmonics`) or floats at one (``_AtAmplitude.at``).
Value = TypeVar("Value", Array, float)


class ExactHarmonics(NamedTuple, Generic[Value]):
    """Means and first harmonics (Eqs. 30–31) of deltabar and Phat for the ansatz of Eq. (25), exact."""

    deltabar_m: Value  # mean deltabar
    deltabar_c: Value  # deltabar_c
    deltabar_s: Value  # deltabar_s
    phat_m: Value  # mean Phat
    phat_c: Value  # Phat_c
    phat_s: Value  # Phat_s
    sqrt_w_eff_ratio: Value  # J0 = mean sqrt(w/w0); w_eff/w0 = J0^2 (Eq. 18)


def _even_odd_parts(Abar: Array, law: RateLaw) -> tuple[Array, Array]:
    """S = s(v) + s(-v) and D = s(v) - s(-v) at the rule's nodes, v = Abar sin t (rows: Abar values)."""
    if isinstance(law, GentSchultz):  # S = (2 + u)/sqrt(1 + u), D = -u/sqrt(1 + u), u = v^n: no cancellation
        u = gent_schultz_u(Abar, law.n)
        r = 1.0 / np.sqrt(1.0 + u)
        return (2.0 + u) * r, -u * r
    v = np.multiply.outer(Abar, folded_rule()[1])
    closing, opening = np.sqrt(law.f(v)), np.sqrt(law.f(-v))
    return closing + opening, closing - opening


def _k_integrals(
    g_sum: Array, g_diff: Array, s_even: Array, s_odd: Array, w: Array, cos_t: Array, sin_t: Array
) -> tuple[Array, Array, Array]:
    """(K0, Kc, Ks) of g folded onto t in (0, pi/2) (module docstring).

    K0 = (1/2pi) int S (g+ + g-) dt, Kc = (1/pi) int D sin t (g+ + g-) dt, Ks = (1/pi) int S cos t (g+ - g-) dt,
    with S = ``s_even``, D = ``s_odd`` and the rule's weights ``w`` for int_0^(pi/2) dt at the nodes with
    cosines ``cos_t`` and sines ``sin_t``.
    """
    return (
        (s_even * g_sum) @ w / (2.0 * np.pi),
        (s_odd * g_sum) @ (w * sin_t) / np.pi,
        (s_even * g_diff) @ (w * cos_t) / np.pi,
    )


def _coefficients(a: Array, e: Array, s_even: Array, s_odd: Array) -> ExactHarmonics[Array]:
    """The seven coefficients for rows (abar_m, A_over_ao) and the matching rows of S, D (module docstring)."""
    t, _, weights = folded_rule()
    w = np.pi * weights[:, 0]  # the rule's weights for int_0^(pi/2) dt
    cos_t, sin_t = np.cos(t), np.sin(t)
    e_c = e[:, None] * cos_t[None, :]
    a_col = a[:, None]
    plus, minus = a_col + e_c, a_col - e_c
    root_p, root_m = np.sqrt(plus), np.sqrt(minus)
    cube_p, cube_m = plus * root_p, minus * root_m
    rule = (s_even, s_odd, w, cos_t, sin_t)
    k0_half, kc_half, ks_half = _k_integrals(root_p + root_m, 2.0 * e_c / (root_p + root_m), *rule)
    diff_32 = (6.0 * a_col**2 * e_c + 2.0 * e_c**3) / (cube_p + cube_m)
    k0_32, kc_32, ks_32 = _k_integrals(cube_p + cube_m, diff_32, *rule)
    return ExactHarmonics(
        a**2 + 0.5 * e**2 - k0_half,
        -kc_half,
        2.0 * a * e - ks_half,
        (4.0 / 3.0) * a**3 + 2.0 * a * e**2 - 2.0 * k0_32,
        -2.0 * kc_32,
        4.0 * a**2 * e + e**3 - 2.0 * ks_32,
        s_even @ w / np.pi,
    )


def exact_harmonics(abar_m: ArrayLike, Abar: ArrayLike, A_over_ao: ArrayLike, law: RateLaw) -> ExactHarmonics[Array]:
    """Exact means and first harmonics of deltabar and Phat (module docstring), broadcast over the inputs.

    ``A_over_ao`` = A/a_o = Abar/(omega_check c_o) must satisfy 0 <= A_over_ao < abar_m.
    """
    abar_m, Abar, A_over_ao = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (abar_m, Abar, A_over_ao)))
    a, big_a, e = abar_m.ravel(), Abar.ravel(), A_over_ao.ravel()
    if np.any(~np.isfinite(a)) or np.any(~np.isfinite(big_a)) or np.any(~np.isfinite(e)):
        raise ValueError("abar_m, Abar and A_over_ao must be finite")
    if np.any(big_a < 0) or np.any(e < 0) or np.any(e >= a):
        raise ValueError("the ansatz needs Abar >= 0 and 0 <= A_over_ao < abar_m (A < a_m)")
    values = _coefficients(a, e, *_even_odd_parts(big_a, law))
    return ExactHarmonics(*(v.reshape(abar_m.shape) for v in values))


# --- Rigid fixation -----------------------------------------------------------------------


class _AtAmplitude:
    """Exact coefficients at one Abar and A_over_ao, as functions of abar_m (S and D computed once)."""

    def __init__(self, Abar: float, A_over_ao: float, law: RateLaw) -> None:
        self.A_over_ao = A_over_ao
        self._e = np.array([A_over_ao])
        self._parts = _even_odd_parts(np.array([Abar]), law)

    def at(self, abar_m: float) -> ExactHarmonics[float]:
        return ExactHarmonics(*(float(v[0]) for v in _coefficients(np.array([abar_m]), self._e, *self._parts)))

    def mean_indentation_slope(self, abar_m: float) -> float:
        """d(mean deltabar)/d abar_m = 2 abar_m - (1/2pi) int S (1/(2 sqrt(a+)) + 1/(2 sqrt(a-))) dt."""
        t, _, weights = folded_rule()
        e_c = self.A_over_ao * np.cos(t)
        dk0 = (self._parts[0][0] * (0.5 / np.sqrt(abar_m + e_c) + 0.5 / np.sqrt(abar_m - e_c))) @ weights[:, 0] / 2.0
        return 2.0 * abar_m - float(dk0)

    def stable_mean_radius(self, base_offset: float) -> float | None:
        """abar_m > A_over_ao with mean deltabar = base_offset on the stable branch, or None if there is none.

        F(a) = a^2 + A_over_ao^2/2 - K0[sqrt](a) - base_offset is strictly convex in a (K0[sqrt] is a positive
        combination of concave square roots), so it has at most two roots; the larger one, where
        dF/da > 0 (indentation rising with the radius), is the state a displacement-controlled
        contact holds. It is bracketed between the minimum of F (the root of the analytic dF/da,
        by Brent's method) and a radius where F > 0.
        """
        lo = self.A_over_ao + 1e-9 * max(self.A_over_ao, 1.0)
        hi = 2.0 * lo + 1.0 + math.sqrt(abs(base_offset))
        while self.mean_indentation_excess(hi, base_offset) <= 0 or self.mean_indentation_slope(hi) <= 0:
            hi *= 2.0
        turn = lo
        if self.mean_indentation_slope(lo) < 0:
            turn = brentq(self.mean_indentation_slope, lo, hi, xtol=1e-13 * hi)
        if self.mean_indentation_excess(turn, base_offset) > 0:
            return None
        return brentq(self.mean_indentation_excess, turn, hi, args=(base_offset,), xtol=4e-16 * hi, rtol=1e-15)

    def mean_indentation_excess(self, abar_m: float, base_offset: float) -> float:
        """F(abar_m) = mean deltabar - base_offset (mean of Eq. 5, module docstring).

        Zero where the base offset base_offset holds the mean radius abar_m.
        """
        return self.at(abar_m).deltabar_m - base_offset


#: Relative residual of both equations a returned rigid steady state must meet.
RESIDUAL_TOLERANCE = 1e-11
_LOG_STEP = 0.25  # bracketing step in ln Abar
_MAX_STEPS = 400
_HALVINGS = 30  # refinements of the step towards the edge A = a_m of the ansatz's domain


class _RigidBranch:
    """The stable mean radius and the amplitude excess ln(|deltabar_(c,s)|/etahat) as functions of ln Abar."""

    def __init__(self, etahat: float, omega_check: float, c_o: float, base_offset: float, law: RateLaw) -> None:
        self.etahat, self.speed_scale, self.base_offset, self.law = etahat, omega_check * c_o, base_offset, law

    def state(self, z: float) -> tuple[float, ExactHarmonics[float]] | None:
        """(abar_m, coefficients) at Abar = e^z, or None where the ansatz has no stable state (A >= a_m)."""
        amplitude = _AtAmplitude(math.exp(z), math.exp(z) / self.speed_scale, self.law)
        abar_m = amplitude.stable_mean_radius(self.base_offset)
        return None if abar_m is None else (abar_m, amplitude.at(abar_m))

    def log_excess(self, z: float) -> float | None:
        state = self.state(z)
        if state is None:
            return None
        return math.log(math.hypot(state[1].deltabar_c, state[1].deltabar_s) / self.etahat)


def _bracket_lowest_root(branch: _RigidBranch, z: float, what: str) -> tuple[float, float]:
    """(lo, hi) in ln Abar around the smallest root: log_excess(lo) < 0 < log_excess(hi), both admissible.

    From ``z`` (two units below the refined model's ln Abar) it first moves down while the point
    is inadmissible or already above the target (log_excess -> -infinity as Abar -> 0), then scans
    upwards in steps of 0.25 to the first sign change. The amplitude along the branch is not
    monotone near the edge of the ansatz's domain at low frequency (it peaks near A/a_m = 0.75 for
    h1 = 20 um, omega_check = 1e3), so a second, larger root can exist; the scan returns the smaller
    one, which continues the refined solution. A step that leaves the domain is halved up to 30
    times before the amplitude is declared unreachable.
    """
    value = branch.log_excess(z)
    for _ in range(_MAX_STEPS):
        if value is not None and value < 0:
            break
        z -= _LOG_STEP
        value = branch.log_excess(z)
    else:
        raise NoRootError(f"{what}: no admissible state below the target amplitude down to Abar = {math.exp(z):.6g}")
    step = _LOG_STEP
    for _ in range(_MAX_STEPS + _HALVINGS):
        trial = branch.log_excess(z + step)
        if trial is None:
            if step < _LOG_STEP * 2.0**-_HALVINGS:
                raise NoSteadyStateError(
                    f"{what}: the base amplitude is not reached by the single-harmonic ansatz; beyond Abar = "
                    f"{math.exp(z):.6g} the mean equation has no stable root with A < a_m"
                )
            step *= 0.5
            continue
        if trial > 0:
            return z, z + step
        z = z + step
    raise NoRootError(f"{what}: amplitude equation not bracketed")


def rigid_fixation(
    eta1: float, omega_check: float, chi0: float, law: RateLaw, base_offset: float = 0.0
) -> SteadyState:
    """Exact harmonic balance of a rigidly fixed indenter (Eqs. 56, 100/103 with exact coefficients).

    Mean deltabar = base_offset and deltabar_c^2 + deltabar_s^2 = etahat^2: the record of level
    ``exact_hb`` (scalar). Where :func:`solve_rigid_fixation` finds no steady state its status is
    ``no_solution`` (every number NaN) and its message says why.
    """
    try:
        return solve_rigid_fixation(eta1, omega_check, chi0, law, base_offset)
    except NoRootError as error:  # includes NoSteadyStateError
        return SteadyState.unsolved("exact_hb", "no_solution", str(error))


def solve_rigid_fixation(
    eta1: float, omega_check: float, chi0: float, law: RateLaw, base_offset: float = 0.0
) -> SteadyState:
    """The steady state of :func:`rigid_fixation`, raising where there is none.

    Nested bracketed solution: for each z = ln Abar the mean radius is the stable root of the mean
    equation (:meth:`_AtAmplitude.stable_mean_radius`), and ln(|deltabar_(c,s)|/etahat) along that
    branch is bracketed by an upward scan that starts below the refined model's Abar (Eqs. 122–123,
    the linearisation of this system) and stops at the first sign change
    (:func:`_bracket_lowest_root`: the smallest root, continuing the refined solution), then solved
    by Brent's method. A state needs A < a_m; when the amplitude cannot be reached inside that
    domain :class:`NoSteadyStateError` is raised. The result is checked against both equations
    (relative residuals below ``RESIDUAL_TOLERANCE``), otherwise :class:`NoRootError`. w_eff/w0 is
    J0(Abar)^2 of the exact ansatz (Eq. 18), A/a_m = A_over_ao/abar_m (Eq. 98 corrected, errata E1),
    P_m/|P_JKR| = mean Phat/(3/4) (tensile negative) and deltabar_m = base_offset.
    """
    if not (omega_check > 0 and math.isfinite(omega_check)):
        raise ValueError(f"omega_check must be positive and finite, got {omega_check}")
    what = (f"exact harmonic balance (eta1 = {eta1:.6g}, omega_check = {omega_check:.6g}, "
            f"base_offset = {base_offset:.6g})")
    etahat = float(groups.etahat(eta1, chi0))
    c_o = contact_radius_ratio(chi0)
    if etahat == 0:
        static = _AtAmplitude(0.0, 0.0, law)
        abar_m = static.stable_mean_radius(base_offset)
        if abar_m is None:
            raise NoSteadyStateError(f"{what}: no static contact holds base_offset")
        return _rigid_record(0.0, abar_m, 1.0, 0.0, static.at(abar_m).phat_m / -PHAT_JKR, base_offset)

    branch = _RigidBranch(etahat, omega_check, c_o, base_offset, law)
    start = float(refined_nominal_point_contact(eta1, omega_check, chi0, law).Abar)
    lo, hi = _bracket_lowest_root(branch, math.log(start) - 2.0, what)
    z = brentq(lambda y: branch.log_excess(y), lo, hi, xtol=1e-14, rtol=1e-15)
    Abar = math.exp(z)
    state = branch.state(z)
    if state is None:  # brentq's root lies inside the bracket, where every state exists (_bracket_lowest_root)
        raise NoRootError(f"{what}: no stable state at the root Abar = {Abar:.6g}")
    abar_m, h = state
    residuals = ((h.deltabar_m - base_offset) / max(abs(base_offset), abar_m**2),
                 math.hypot(h.deltabar_c, h.deltabar_s) / etahat - 1.0)
    if max(abs(r) for r in residuals) > RESIDUAL_TOLERANCE:
        raise NoRootError(f"{what}: not converged, relative residuals {residuals} at Abar = {Abar:.6g}")
    return _rigid_record(Abar, abar_m, h.sqrt_w_eff_ratio**2,
                         float(groups.A_over_am(Abar, abar_m, chi0, omega_check)),
                         h.phat_m / -PHAT_JKR, base_offset)


def _rigid_record(Abar: float, abar_m: float, w_eff_ratio: float, A_over_am: float, pm_over_abs_pjkr: float,
                  base_offset: float) -> SteadyState:
    """The ``exact_hb`` record of one solved state (Eqs. 18, 98 corrected, 125–126; deltabar_m = base_offset)."""
    return SteadyState("exact_hb", np.asarray("ok"), np.asarray(Abar), np.asarray(abar_m), np.asarray(w_eff_ratio),
                       np.asarray(A_over_am), np.asarray(pm_over_abs_pjkr), np.asarray(base_offset))


# --- Compliant fixation (Sec. 3.5.3): residuals for continuation ----------------------------


def compliant_residual(
    x: ArrayLike, fixation: Fixation, chi0: float, eta1: float, law: RateLaw, base_offset: float = 0.0
) -> Array:
    """Exact counterpart of :func:`vibroadhesion.models.compliant.residual`.

    Rows x = (ln omega_bar, ln abar_m, ln Abar) of an (m, 3) array -> (m, 2) residuals.

    Column 0, mean balance (Eq. 87 generalised, module docstring) as positive/negative - 1 with
    positive = kappa (abar_m^2 + A_over_ao^2/2) + c_o ((4/3) abar_m^3 + 2 abar_m A_over_ao^2) - mu/c_o^2
    - kappa base_offset
    and negative = kappa K0[sqrt] + 2 c_o K0[3/2] (the printed Eq. 87's two sides when A_over_ao -> 0).
    Column 1, Eq. (90): ln|xi| - ln(eta1 |1 - omega_bar^2 + 2i zeta omega_bar|), with Eqs. (91)–(92)
    and delta_check = c_o^2 deltabar_(c,s), P_check = (c_o^3/kappa) Phat_(c,s), A_over_ao = nu0 Abar/(omega_bar c_o).
    Rows with A_over_ao >= abar_m (A >= a_m) have no meaning and raise ValueError.
    """
    x = np.atleast_2d(np.asarray(x, dtype=float))
    omega_bar, abar_m, Abar = np.exp(x[:, 0]), np.exp(x[:, 1]), np.exp(x[:, 2])
    c_o = contact_radius_ratio(chi0)
    A_over_ao = fixation.nu0 * Abar / (omega_bar * c_o)
    h = exact_harmonics(abar_m, Abar, A_over_ao, law)
    positive = (
        fixation.kappa * (abar_m**2 + 0.5 * A_over_ao**2 - base_offset)
        + c_o * ((4.0 / 3.0) * abar_m**3 + 2.0 * abar_m * A_over_ao**2)
        - fixation.mu / c_o**2
    )
    k0_half = abar_m**2 + 0.5 * A_over_ao**2 - h.deltabar_m
    k0_three_halves = 0.5 * ((4.0 / 3.0) * abar_m**3 + 2.0 * abar_m * A_over_ao**2 - h.phat_m)
    negative = fixation.kappa * k0_half + 2.0 * c_o * k0_three_halves
    delta_scale, force_scale = c_o**2, c_o**3 / fixation.kappa
    amplitude = amplitude_log_residual(x[:, 0], delta_scale * h.deltabar_c, delta_scale * h.deltabar_s,
                                       force_scale * h.phat_c, force_scale * h.phat_s,
                                       fixation.zeta, eta1)
    return np.stack([positive / negative - 1.0, amplitude], axis=1)
