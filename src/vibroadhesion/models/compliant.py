"""Compliantly fixed indenter, refined model of Sec. 3.5.3: passage through resonance (Fig. 5).

Unknowns abar_m = a_m/a_o and the internal variable Abar = omega A/v0 (Eq. 45) at the
excitation frequency omega_bar = omega/omega0 (Eq. 65). Two equations:

Mean balance, Eq. (87) (nominal point contact h0 = hhat, Eq. 78; derived from Eq. 85 with
a_m/R = c_o abar_m, c_o = a_o/R = 2^(1/3) 3^(-2/3) chi0, dividing by c_o^2 and using
(sqrt(2)/3) chi0^(3/2) c_o^(-3/2) = 1; agrees with the printed equation, docs/errata.md):

    (2^(7/3) chi0 / 3^(5/3)) abar_m^3 + kappa abar_m^2
        - J0(Abar) ((2^(4/3) chi0 / 3^(2/3)) abar_m^(3/2) + kappa abar_m^(1/2)) = 3^(4/3) mu / (2^(2/3) chi0^2).

Harmonic balance, Eq. (90) with Eqs. (91)–(92):

    xi_c^2 + xi_s^2 = eta1^2 [(1 - omega_bar^2)^2 + 4 zeta^2 omega_bar^2],
    xi_c = (1 - omega_bar^2) delta_check_c + 2 zeta omega_bar delta_check_s + p_check_c,
    xi_s = (1 - omega_bar^2) delta_check_s - 2 zeta omega_bar delta_check_c + p_check_s,

with the refined coefficients divided by R (delta) and by kR (P), Eqs. (93)–(96); omega_check =
omega_bar/nu0 (Eq. 105), so nu0/omega_bar = 1/omega_check:

    delta_check_c = -(2^(2/3)/3^(4/3)) chi0^2 abar_m^(1/2) Jc1                                   (93)
    delta_check_s = (2^(4/3)/3^(2/3)) chi0 (nu0/omega_bar) Abar abar_m (1 - J1/(4 abar_m^(3/2)))  (94)
    p_check_c     = -(4 chi0^3/(9 kappa)) abar_m^(3/2) Jc1                                       (95)
    p_check_s     = (2^(8/3)/3^(4/3)) chi0^2 (nu0/(kappa omega_bar)) Abar abar_m^2 (1 - 3 J1/(4 abar_m^(3/2)))  (96)

(re-derived from Eqs. 32–35 in docs/errata.md; Eq. 96 prints sigma_bar for abar_m). The
contact-radius amplitude is A/a_m = 3^(2/3) nu0 Abar / (2^(1/3) chi0 abar_m omega_bar), the
corrected Eq. (98) (errata E1).

Numerical form. Both equations are solved in logarithmic variables x = (ln omega_bar,
ln abar_m, ln Abar), which spans the decades of Fig. 5 with uniform conditioning: Eq. (87) as
the ratio of its positive and negative parts minus one, Eq. (90) as the difference of the
logarithms of the two amplitudes. The anti-resonance of the base-excited system (Appendix B):
at omega_bar = 1 with zeta = 0 the right-hand side of Eq. (90) vanishes, so xi = 0 forces
Jc1 = 0, i.e. Abar = 0 exactly and abar_m equals its static value (Eq. 82). In x that point is at
ln Abar = -infinity: the solution curve splits into a branch below and a branch above
omega_bar = 1 (traced in :mod:`vibroadhesion.models.response_curve`, Fig. 5).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import partial

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from vibroadhesion.core import groups
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.integrals import j_integrals_for_law
from vibroadhesion.core.ratelaw import RateLaw
from vibroadhesion.core.records import Pulloff, SteadyState, stacked
from vibroadhesion.models.leading_order import mean_indentation, pm_over_abs_pjkr
from vibroadhesion.models.leading_pulloff import pulloff_closure, pulloff_from_internal_variable
from vibroadhesion.models.refined import displacement_harmonics
from vibroadhesion.numerics.continuation import ContinuationSettings, jacobian
from vibroadhesion.numerics.roots import NoRootError

Array = NDArray[np.float64]

def mean_balance_parts(abar_m: ArrayLike, j0: ArrayLike, fixation: Fixation, chi0: float) -> tuple[Array, Array]:
    """Eq. (87) as (positive part, J0 part): the equation is ``positive == negative``."""
    abar_m = np.asarray(abar_m, dtype=float)
    positive = (2.0 ** (7 / 3) * chi0 / 3.0 ** (5 / 3)) * abar_m**3 + fixation.kappa * abar_m**2 - (
        3.0 ** (4 / 3) * fixation.mu / (2.0 ** (2 / 3) * chi0**2)
    )
    negative = np.asarray(j0) * (
        (2.0 ** (4 / 3) * chi0 / 3.0 ** (2 / 3)) * abar_m**1.5 + fixation.kappa * np.sqrt(abar_m)
    )
    return positive, negative


def mean_balance_excess(log_abar_m: ArrayLike, j0: ArrayLike, fixation: Fixation, chi0: float) -> Array:
    """positive/negative - 1 of Eq. (87) (:func:`mean_balance_parts`) at abar_m = exp(``log_abar_m``).

    Zero on the mean balance, increasing with abar_m (see :func:`static_abar_0`).
    """
    positive, negative = mean_balance_parts(np.exp(log_abar_m), j0, fixation, chi0)
    return positive / negative - 1.0


def static_abar_0(fixation: Fixation, chi0: float) -> float:
    """Static contact radius a_0/a_o: Eq. (87) with J0 = 1, i.e. Eq. (82) (unique root, see below).

    Dividing both parts by abar^(3/2): positive/negative = (c1 abar^(3/2) + kappa abar^(1/2) - M abar^(-3/2))
    / (c2 + kappa/abar), with c1, c2, M the coefficients of Eq. (87). The numerator increases and the
    positive denominator decreases with abar, so the ratio increases strictly, from below 1 (it tends
    to -inf for M > 0 and to 0 for M = 0) to infinity: exactly one root.
    """
    return float(abar_m_from_mean_balance(np.array([1.0]), fixation, chi0)[0])


def harmonic_coefficients(
    omega_bar: ArrayLike, abar_m: ArrayLike, Abar: ArrayLike, fixation: Fixation, chi0: float, law: RateLaw
) -> tuple[Array, Array, Array, Array, Array]:
    """(J0, delta_check_c, delta_check_s, p_check_c, p_check_s) of Eqs. (93)–(96), broadcast over the inputs."""
    omega_bar, abar_m, Abar = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (omega_bar, abar_m, Abar)))
    j0, jc1, j1 = j_integrals_for_law(Abar.ravel(), law)
    j0, jc1, j1 = (v.reshape(Abar.shape) for v in (j0, jc1, j1))
    delta_check_c, delta_check_s = displacement_harmonics(Abar, abar_m, jc1, j1, chi0, omega_bar / fixation.nu0)
    p_check_c = -(4.0 * chi0**3 / (9.0 * fixation.kappa)) * abar_m**1.5 * jc1
    kappa, nu0 = fixation.kappa, fixation.nu0
    p_check_s = (2.0 ** (8 / 3) / 3.0 ** (4 / 3)) * chi0**2 * (nu0 / (kappa * omega_bar)) * Abar * abar_m**2 * (
        1.0 - 3.0 * j1 / (4.0 * abar_m**1.5)
    )
    return j0, delta_check_c, delta_check_s, p_check_c, p_check_s


def forcing_modulus(log_omega_bar: ArrayLike, zeta: float) -> Array:
    """|1 - omega_bar^2 + 2 i zeta omega_bar|: the right-hand side of Eq. (90) is eta1^2 times its square.

    Taken from ln omega_bar with 1 - omega_bar^2 = -expm1(2 ln omega_bar): no cancellation near
    the anti-resonance omega_bar = 1, where the solution depends on this difference alone; the
    modulus by hypot, without overflow.
    """
    s = np.asarray(log_omega_bar, dtype=float)
    return np.hypot(np.expm1(2.0 * s), 2.0 * zeta * np.exp(s))


def amplitude_log_residual(log_omega_bar: Array, delta_check_c: Array, delta_check_s: Array, p_check_c: Array,
                           p_check_s: Array, zeta: float, eta1: float) -> Array:
    """Eq. (90) in logarithms, ln|xi| - ln(eta1 |1 - omega_bar^2 + 2i zeta omega_bar|).

    From the harmonic coefficients of any model level (Eqs. 93-96 here, Eqs. 125-126 in
    exact_harmonic_balance).
    """
    xi_c, xi_s = xi_coefficients(log_omega_bar, delta_check_c, delta_check_s, p_check_c, p_check_s, zeta)
    return np.log(np.hypot(xi_c, xi_s)) - math.log(eta1) - np.log(forcing_modulus(log_omega_bar, zeta))


def residual(x: ArrayLike, fixation: Fixation, chi0: float, eta1: float, law: RateLaw) -> Array:
    """Eqs. (87) and (90) at x = (ln omega_bar, ln abar_m, ln Abar), rows of an (m, 3) array -> (m, 2).

    Column 0: positive/negative - 1 of Eq. (87); column 1: ln|xi| - ln(eta1 |1 - omega_bar^2 + 2i zeta omega_bar|).
    """
    x = np.atleast_2d(np.asarray(x, dtype=float))
    omega_bar, abar_m, Abar = np.exp(x[:, 0]), np.exp(x[:, 1]), np.exp(x[:, 2])
    j0, delta_check_c, delta_check_s, p_check_c, p_check_s = harmonic_coefficients(omega_bar, abar_m, Abar, fixation,
                                                                                   chi0, law)
    amplitude = amplitude_log_residual(x[:, 0], delta_check_c, delta_check_s, p_check_c, p_check_s, fixation.zeta, eta1)
    return np.stack([mean_balance_excess(x[:, 1], j0, fixation, chi0), amplitude], axis=1)


def xi_coefficients(log_omega_bar: ArrayLike, delta_check_c: Array, delta_check_s: Array, p_check_c: Array,
                    p_check_s: Array, zeta: float) -> tuple[Array, Array]:
    """xi_c, xi_s of Eqs. (91)-(92) from the harmonic coefficients (any model level that provides them)."""
    log_omega_bar = np.asarray(log_omega_bar, dtype=float)
    omega_bar, stiffness = np.exp(log_omega_bar), -np.expm1(2.0 * log_omega_bar)  # stiffness = 1 - omega_bar^2
    return (stiffness * delta_check_c + 2.0 * zeta * omega_bar * delta_check_s + p_check_c,
            stiffness * delta_check_s - 2.0 * zeta * omega_bar * delta_check_c + p_check_s)


def residual_linear(
    omega_bar: float, abar_m: float, Abar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw
) -> tuple[float, float]:
    """Eqs. (87) and (90) in their printed (polynomial) form, relative: for checking a solution.

    Returns ((positive - negative)/negative, (xi_c^2 + xi_s^2 - rhs)/rhs) of Eqs. (87) and (90).
    """
    j0, delta_check_c, delta_check_s, p_check_c, p_check_s = harmonic_coefficients(omega_bar, abar_m, Abar, fixation,
                                                                                   chi0, law)
    positive, negative = mean_balance_parts(abar_m, j0, fixation, chi0)
    xi_c, xi_s = xi_coefficients(math.log(omega_bar), delta_check_c, delta_check_s, p_check_c, p_check_s, fixation.zeta)
    rhs = (eta1 * forcing_modulus(math.log(omega_bar), fixation.zeta)) ** 2
    return float((positive - negative) / negative), float((xi_c**2 + xi_s**2 - rhs) / rhs)


def abar_m_from_mean_balance(j0: ArrayLike, fixation: Fixation, chi0: float) -> Array:
    """abar_m solving Eq. (87) for given J0(Abar), vectorised (unique root, see :func:`static_abar_0`).

    Bisection in ln abar_m on [ln J0^(2/3) - 1, ln J0^(2/3) + 1] (widened upwards while needed): at
    abar_m = lambda J0^(2/3) the ratio of the parts of Eq. (87) lies between (2/3) lambda^(3/2) and
    lambda^(3/2) when mu = 0, below 1 at lambda = 1/e and above 1 at lambda = e. 80 halvings of a
    width-2 bracket reach the spacing of doubles.
    """
    j0 = np.asarray(j0, dtype=float)
    excess = partial(mean_balance_excess, j0=j0, fixation=fixation, chi0=chi0)
    centre = (2.0 / 3.0) * np.log(j0)
    lo, hi = centre - 1.0, centre + 1.0
    for _ in range(200):
        if np.all(excess(hi) > 0):
            break
        hi = np.where(excess(hi) > 0, hi, hi + 2.0)
    else:
        raise NoRootError("Eq. (87): no mean contact radius found (load group mu too large?)")
    while np.any(excess(lo) > 0):
        lo = np.where(excess(lo) > 0, lo - 2.0, lo)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        above = excess(mid) > 0
        lo, hi = np.where(above, lo, mid), np.where(above, mid, hi)
    return np.exp(0.5 * (lo + hi))


def refined_steady_state(omega_bar: float, abar_m: ArrayLike, Abar: ArrayLike, fixation: Fixation, chi0: float,
                         law: RateLaw) -> SteadyState:
    """The record of level ``refined`` at solutions (abar_m, Abar) of Eqs. (87), (90) at ``omega_bar`` (any shape).

    w_eff/w0 = J0^2 (Eq. 49), A/a_m at omega_check = omega_bar/nu0 (corrected Eq. 98), P_m/|P_JKR|
    (Eqs. 52, 71) and deltabar_m (Eqs. 53, 86); the averaged model gives no stability (``stable`` None).
    """
    abar_m, Abar = np.asarray(abar_m, dtype=float), np.asarray(Abar, dtype=float)
    j0 = j_integrals_for_law(Abar, law)[0]
    return SteadyState("refined", np.full(Abar.shape, "ok"), Abar, abar_m, j0**2,
                       groups.A_over_am(Abar, abar_m, chi0, omega_bar / fixation.nu0),
                       pm_over_abs_pjkr(abar_m, j0), mean_indentation(abar_m, j0))


def newton_at_frequency(
    omega_bar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw, guess: tuple[float, float]
) -> SteadyState:
    """The solution of Eqs. (87), (90) at ``omega_bar`` reached by Newton from ``guess`` = (abar_m, Abar).

    A record of level ``refined`` of shape () (:func:`refined_steady_state`); where Newton does not
    converge (:func:`_newton`), the status ``not_converged`` with NaN numbers and the reason in ``message``.
    """
    try:
        abar_m, Abar = _newton(omega_bar, fixation, chi0, eta1, law, guess)
    except NoRootError as error:
        return SteadyState.unsolved("refined", "not_converged", str(error))
    return refined_steady_state(omega_bar, abar_m, Abar, fixation, chi0, law)


def _newton(
    omega_bar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw, guess: tuple[float, float]
) -> tuple[float, float]:
    """Newton in (ln abar_m, ln Abar) at fixed omega_bar from ``guess`` = (abar_m, Abar), to 1e-13 in Eqs. (87), (90).

    Returns (abar_m, Abar); raises NoRootError when Newton does not converge.
    """
    at_frequency = partial(residual_at_frequency, log_omega_bar=math.log(omega_bar), fixation=fixation, chi0=chi0,
                           eta1=eta1, law=law)
    z = np.log(np.asarray(guess, dtype=float))
    for _ in range(40):
        f = at_frequency(z[None, :])[0]
        dz = np.linalg.solve(jacobian(at_frequency, z, ContinuationSettings().fd_step), -f)
        z = z + np.clip(dz, -2.0, 2.0)
        if np.max(np.abs(f)) < 1e-13 and np.max(np.abs(dz)) < 1e-10:
            return float(np.exp(z[0])), float(np.exp(z[1]))
    raise NoRootError(f"Eqs. (87), (90): Newton did not converge at omega_bar = {omega_bar:.6g} from {guess}")


def residual_at_frequency(
    z: Array, log_omega_bar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw
) -> Array:
    """:func:`residual` (Eqs. 87, 90) at fixed ln omega_bar for rows z = (ln abar_m, ln Abar) of an (m, 2) array."""
    return residual(np.column_stack([np.full(len(z), log_omega_bar), z]), fixation, chi0, eta1, law)


def amplitude_residual_on_closure(
    log_Abar: Array, log_omega_bar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw,
    abar_m_of_j0: Callable[[Array], Array]
) -> Array:
    """Eq. (90) in logarithms (column 1 of :func:`residual`) along abar_m = abar_m_of_j0(J0(Abar)).

    Vectorised over ln Abar; the closure is Eq. (87) (:func:`abar_m_from_mean_balance`) or a_m = a_cr (Eq. 61).
    """
    abar_m = abar_m_of_j0(j_integrals_for_law(np.exp(log_Abar), law)[0])
    x = np.column_stack([np.full(len(log_Abar), log_omega_bar), np.log(abar_m), log_Abar])
    return residual(x, fixation, chi0, eta1, law)[:, 1]


def _roots_by_scan(
    omega_bar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw, log_Abar: Array,
    abar_m_of_j0: Callable[[Array], Array]
) -> list[tuple[float, float]]:
    """Roots (abar_m, Abar) of Eq. (90) along abar_m = abar_m_of_j0(J0(Abar)).

    Sign changes on the grid ``log_Abar`` polished by Brent's method. Roots closer than the grid
    spacing can be missed.
    """
    g = partial(amplitude_residual_on_closure, log_omega_bar=math.log(omega_bar), fixation=fixation, chi0=chi0,
                eta1=eta1, law=law, abar_m_of_j0=abar_m_of_j0)
    values = g(log_Abar)
    roots = []
    for k in np.flatnonzero(np.sign(values[:-1]) * np.sign(values[1:]) < 0):
        z = brentq(lambda y: float(g(np.array([y]))[0]), log_Abar[k], log_Abar[k + 1], xtol=1e-14, rtol=1e-15)
        roots.append((float(abar_m_of_j0(j_integrals_for_law(np.array([math.exp(z)]), law)[0])[0]), math.exp(z)))
    return roots


def solutions_by_scan(
    omega_bar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw, log_Abar: Array
) -> SteadyState:
    """All solutions of Eqs. (87), (90) at one omega_bar with Abar in the scanned range: one record.

    Independent of the continuation: Eq. (87) gives abar_m(Abar) uniquely, so Eq. (90) becomes a
    scalar equation in ln Abar. The record of level ``refined`` (:func:`refined_steady_state`) has one
    element per solution, by increasing Abar; without any, one element of status ``no_solution``.
    """
    closure = partial(abar_m_from_mean_balance, fixation=fixation, chi0=chi0)
    roots = _roots_by_scan(omega_bar, fixation, chi0, eta1, law, log_Abar, closure)
    if not roots:
        return SteadyState.unsolved("refined", "no_solution", _no_root(omega_bar, "Eqs. (87), (90)", log_Abar),
                                    shape=(1,))
    return refined_steady_state(omega_bar, [abar_m for abar_m, _ in roots], [Abar for _, Abar in roots], fixation,
                                chi0, law)


def pulloff_by_scan(
    omega_bar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw, log_Abar: Array
) -> Pulloff:
    """Refined pull-off of the compliantly fixed indenter: Eq. (90) at a_m = a_cr (Eq. 61), all roots.

    The compliant counterpart of Eq. (106) (which it becomes as kappa -> infinity) and the refined
    counterpart of Eqs. (67)-(69). The record of level ``refined`` has one element per root, by
    increasing Abar_cr, with P_cr/P_cr^JKR = J0(Abar_cr)^2 (Eq. 71) each (a_m = a_cr: ``abar_m`` is not
    solved for, NaN); without any root, one element of status ``no_solution``.
    """
    roots = _roots_by_scan(omega_bar, fixation, chi0, eta1, law, log_Abar, pulloff_closure)
    if not roots:
        return Pulloff.unsolved("refined", "no_solution", _no_root(omega_bar, "Eq. (90) at a_m = a_cr", log_Abar),
                                shape=(1,))
    return stacked([pulloff_from_internal_variable("refined", np.asarray(Abar), law) for _, Abar in roots])


def _no_root(omega_bar: float, equations: str, log_Abar: Array) -> str:
    """The message of a scan without a sign change (the grid ``log_Abar`` in ln Abar, Eqs. 87, 90)."""
    return (f"{equations}: no root at omega_bar = {omega_bar:.6g} for Abar in "
            f"[{math.exp(log_Abar[0]):.3g}, {math.exp(log_Abar[-1]):.3g}]")
