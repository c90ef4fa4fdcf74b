"""Refined asymptotic model (Secs. 3.5.4, 3.6, 3.7): rigid fixation, frequency dependent.

The refined harmonic coefficients of the indentation, Eqs. (93)–(94), keep the quasi-static
term of Eq. (46) that the leading order drops. Divided by R, and with nu0/omega_bar =
1/omega_check (Eqs. 97, 105):

    delta_check_c = -(2^(2/3) / 3^(4/3)) chi0^2 abar_m^(1/2) Jc1                          Eq. (93)
    delta_check_s = (2^(4/3) / 3^(2/3)) chi0 (Abar / omega_check) abar_m (1 - J1/(4 abar_m^(3/2)))   Eq. (94)

For a rigidly fixed indenter the displacement amplitude equals the base amplitude,
delta_check_c^2 + delta_check_s^2 = eta1^2 (Eqs. 100, 103). Two closures fix abar_m:

* pull-off (Sec. 3.6): a_m = a_cr, abar_m = (9/16)^(1/3) J0^(2/3) (Eqs. 61, 86), which turns
  Eq. (103) into Eq. (106);
* nominal point contact (Secs. 3.5.4, 3.7): abar_m = J0^(2/3) (Eqs. 99, 123), which turns it
  into Eq. (122) (the printed Eq. 101 is wrong: docs/errata.md, E2).

As omega_check -> infinity delta_check_s vanishes and both reduce to the leading order (Eqs. 72, 55).

Uniqueness (Gent–Schultz law). With abar_m = c J0^(2/3) (c > 0), delta_check_c^2 = const J0^(2/3) Jc1^2
is strictly increasing (J0 and |Jc1| are, :mod:`vibroadhesion.models.leading_order`). delta_check_s is
proportional to Abar J0^(2/3) (1 - J1/(4 c^(3/2) J0)) = Abar J0^(-1/3) (J0 - J1/(4 c^(3/2))).
For both closures 4 c^(3/2) >= 3, so J0 - J1/(4c^(3/2)) = 1/pi int S(u) (1 - 2 cos^2 t/(4 c^(3/2))) dt
has a positive weight and an increasing S: it increases. And d ln J0 / d ln Abar
= n <u S'(u)> / <S(u)> < n/2 because u S'/S = u^2/(2(1+u)(2+u)) < 1/2, so Abar J0^(-1/3)
increases whenever n < 6. The left-hand side rises strictly from 0 to infinity: one root for
every eta1 > 0, omega_check > 0 and n < 6.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.core import groups
from vibroadhesion.core.integrals import j_integrals_for_law
from vibroadhesion.core.ratelaw import RateLaw
from vibroadhesion.core.records import Pulloff, SteadyState
from vibroadhesion.models.leading_order import pm_over_abs_pjkr
from vibroadhesion.models.leading_pulloff import pulloff_closure, pulloff_from_internal_variable
from vibroadhesion.numerics.roots import solve_log_increasing

#: The asymptotic model needs A << a_m; the paper takes A <= 0.1 a_m as its region of applicability (Sec. 3.5.3).
APPLICABILITY_LIMIT = 0.1

#: omega_check = omega R/v0 (Eq. 105) over which the asymptotic levels are validated against the simulation: the
#: validation's grid (workflow/config.yaml, validation.log10_omega_check_min/max = 3, 8; a test keeps them equal).
#: Outside it their error is unknown (0.1 Hz on the paper's rig is omega_check = 727; its tests are ~1.5e6).
VALIDATED_OMEGA_CHECK = (1e3, 1e8)

Array = NDArray[np.float64]


def nominal_point_contact_closure(j0: Array) -> Array:
    """abar_m = J0^(2/3): rigidly fixed nominal point contact (Eqs. 99, 123)."""
    return np.cbrt(j0) ** 2


def displacement_harmonics(
    Abar: ArrayLike, abar_m: ArrayLike, jc1: ArrayLike, j1: ArrayLike, chi0: float, omega_check: ArrayLike
) -> tuple[Array, Array]:
    """(delta_check_c, delta_check_s) of Eqs. (93)–(94), broadcast; ``omega_check = inf`` gives delta_check_s = 0."""
    Abar, abar_m = np.asarray(Abar, dtype=float), np.asarray(abar_m, dtype=float)
    delta_check_c = -(2.0 ** (2 / 3) / 3.0 ** (4 / 3)) * chi0**2 * np.sqrt(abar_m) * np.asarray(jc1)
    delta_check_s = (
        (2.0 ** (4 / 3) / 3.0 ** (2 / 3)) * chi0 * (Abar / np.asarray(omega_check, dtype=float)) * abar_m
        * (1.0 - np.asarray(j1) / (4.0 * abar_m**1.5))
    )
    return delta_check_c, delta_check_s


def rigid_amplitude_squared(
    Abar: ArrayLike, law: RateLaw, chi0: float, omega_check: float, closure: Callable[[Array], Array]
) -> Array:
    """delta_check_c^2 + delta_check_s^2 (left-hand side of Eq. 103) along a closure abar_m(J0)."""
    j0, jc1, j1 = j_integrals_for_law(Abar, law)
    delta_check_c, delta_check_s = displacement_harmonics(Abar, closure(j0), jc1, j1, chi0, omega_check)
    return delta_check_c**2 + delta_check_s**2


def solve_rigid_internal_variable(
    eta1: float, chi0: float, omega_check: float, law: RateLaw, closure: Callable[[Array], Array], what: str
) -> float:
    """The unique root Abar of delta_check_c^2 + delta_check_s^2 = eta1^2 along ``closure``; eta1 = 0 gives 0."""
    if not omega_check > 0:
        raise ValueError(f"omega_check must be positive, got {omega_check}")
    if eta1 < 0 or not np.isfinite(eta1):
        raise ValueError(f"eta1 must be finite and non-negative, got {eta1}")
    if eta1 == 0:
        return 0.0
    log_target = 2.0 * math.log(eta1)
    return solve_log_increasing(
        lambda z: float(np.log(rigid_amplitude_squared(math.exp(z), law, chi0, omega_check, closure))) - log_target,
        what=f"{what} at eta1 = {eta1:.6g}, omega_check = {omega_check:.6g}",
    )


# --- Pull-off, Eq. (106) ------------------------------------------------------------------


def pulloff_lhs_refined(Abar: ArrayLike, law: RateLaw, chi0: float, omega_check: float) -> Array:
    """Left-hand side of Eq. (106); ``omega_check = inf`` drops the frequency term."""
    return rigid_amplitude_squared(Abar, law, chi0, omega_check, pulloff_closure)


def critical_internal_variable_refined(eta1: float, chi0: float, omega_check: float, law: RateLaw) -> float:
    """Root Abar_cr of Eq. (106) for one (eta1, omega_check); eta1 = 0 gives 0."""
    return solve_rigid_internal_variable(eta1, chi0, omega_check, law, pulloff_closure, "Eq. (106)")


def pulloff_refined(eta1: ArrayLike, chi0: float, omega_check: ArrayLike, law: RateLaw) -> Pulloff:
    """Refined pull-off (Eqs. 71, 106), vectorised and broadcast over eta1 and omega_check: level ``refined``.

    With A/a_m at detachment, where a_m = a_cr = a_o (9/16)^(1/3) J0^(2/3) (Eqs. 60-61, 86) and
    A/a_m = Abar/(c_o abar_m omega_check) (Eq. 98 corrected): the asymptotic model applies while it is small
    (A/a_m <= 0.1, Sec. 3.5.3), so a caller can flag the test conditions where it does not.
    """
    eta1, omega_check = np.broadcast_arrays(np.asarray(eta1, dtype=float), np.asarray(omega_check, dtype=float))
    Abar = np.vectorize(lambda e, w: critical_internal_variable_refined(e, chi0, w, law), otypes=[float])(
        eta1, omega_check
    )
    record = pulloff_from_internal_variable("refined", Abar, law)
    abar_cr = pulloff_closure(record.sqrt_w_eff_ratio)
    return replace(record, A_over_am=groups.A_over_am(Abar, abar_cr, chi0, omega_check))


# --- Nominal point contact of a rigidly fixed indenter, Eqs. (122)–(123) -------------------


def nominal_point_contact(eta1: ArrayLike, omega_check: ArrayLike, chi0: float, law: RateLaw) -> SteadyState:
    """Solve Eqs. (122)–(123) for Abar, broadcast over eta1 and omega_check: the record of level ``refined``.

    abar_m = J0^(2/3) (Eq. 123), w_eff/w0 = J0^2 (Eq. 49), A/a_m (Eq. 98 corrected), P_m/|P_JKR| from
    Eq. (52) with sqrt(w_eff/w0) for J0, and deltabar_m = abar_m^2 - J0 abar_m^(1/2) = 0 (Eq. 53 with
    Eq. 123). Points with A/a_m > 1 are geometrically impossible and A/a_m > 0.1 lies outside the
    asymptotic model's applicability (Sec. 3.5.3); they are returned, not hidden, so the caller can
    report them.
    """
    eta1, omega_check = np.broadcast_arrays(np.asarray(eta1, dtype=float), np.asarray(omega_check, dtype=float))
    Abar = np.vectorize(
        lambda e, w: solve_rigid_internal_variable(e, chi0, w, law, nominal_point_contact_closure, "Eq. (122)"),
        otypes=[float],
    )(eta1, omega_check)
    j0 = j_integrals_for_law(Abar, law)[0]
    abar_m = nominal_point_contact_closure(j0)
    w_eff_ratio = j0**2
    return SteadyState(
        "refined", np.full(Abar.shape, "ok"), Abar, abar_m, w_eff_ratio,
        groups.A_over_am(Abar, abar_m, chi0, omega_check),
        pm_over_abs_pjkr(abar_m, np.sqrt(w_eff_ratio)), np.zeros(Abar.shape),
    )


def leading_nominal_point_contact(eta1: ArrayLike, omega_check: ArrayLike, chi0: float, law: RateLaw) -> SteadyState:
    """Leading order of the rigidly fixed nominal point contact (Eqs. 55, 99, 123): the record of level ``leading``.

    The refined solution at omega_check = infinity (frequency independent), with A/a_m (Eq. 98
    corrected) at the actual ``omega_check``.
    """
    eta1 = np.broadcast_arrays(np.asarray(eta1, dtype=float), np.asarray(omega_check, dtype=float))[0]
    limit = nominal_point_contact(eta1, math.inf, chi0, law)
    A_over_am = groups.A_over_am(limit.Abar, limit.abar_m, chi0, omega_check)
    return replace(limit, level="leading", A_over_am=A_over_am)
