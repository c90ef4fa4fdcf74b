"""Refined asymptotic model (Sec. 3.6): frequency-dependent pull-off estimate.

The refined harmonic coefficients, Eqs. (93)–(94), keep the quasi-static term of Eq. (46)
that the leading order drops. With a_m = a_cr, i.e. abar_m^(3/2) = (3/4) J0 (Eq. 61 over the
scale a_o of Eq. 86), they become Eq. (104), and the high-frequency displacement condition
(103) gives

    chi0^4/9 J0^(2/3) Jc1^2 + chi0^2/w^2 Abar^2 J0^(4/3) (1 - J1/(3 J0))^2 = eta1^2,   Eq. (106)

with w = omega_check = omega R / v0 (Eq. 105). As omega_check -> infinity the second term
vanishes and Eq. (106) is the square of Eq. (72): the leading-order estimate.

Uniqueness (Gent–Schultz law). The first term is the square of the leading-order left-hand
side, strictly increasing (:mod:`vibroadhesion.leading_order`). In the second term write
Abar J0^(2/3) (1 - J1/(3J0)) = Abar J0^(-1/3) (J0 - J1/3). J0 - J1/3 = 1/pi int S(u)
(1 - 2/3 cos^2 t) dt has a positive weight and an increasing S, so it increases. And
d ln J0 / d ln Abar = n <u S'(u)> / <S(u)> < n/2 because u S'(u)/S(u) = u^2/(2(1+u)(2+u)) < 1/2,
so Abar J0^(-1/3) increases whenever n < 6. The left-hand side thus rises strictly from 0 to
infinity and Eq. (106) has exactly one root for every eta1 > 0, omega_check > 0, n < 6.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.integrals import j_integrals_for_law
from vibroadhesion.leading_order import PulloffEstimate, critical_abar_leading
from vibroadhesion.ratelaw import RateLaw
from vibroadhesion.roots import solve_log_increasing


def pulloff_lhs_refined(abar: ArrayLike, law: RateLaw, chi0: float, omega_check: float) -> NDArray[np.float64]:
    """Left-hand side of Eq. (106); ``omega_check = inf`` drops the frequency term."""
    abar = np.asarray(abar, dtype=float)
    j0, jc1, j1 = j_integrals_for_law(abar, law)
    static = chi0**4 / 9.0 * np.cbrt(j0) ** 2 * jc1**2
    if math.isinf(omega_check):
        return static
    dynamic = (chi0 * abar / omega_check) ** 2 * np.cbrt(j0) ** 4 * (1.0 - j1 / (3.0 * j0)) ** 2
    return static + dynamic


def critical_abar_refined(eta1: float, chi0: float, omega_check: float, law: RateLaw) -> float:
    """Root Abar_cr of Eq. (106) for one (eta1, omega_check); eta1 = 0 gives 0."""
    if not omega_check > 0:
        raise ValueError(f"omega_check must be positive, got {omega_check}")
    if math.isinf(omega_check):
        return critical_abar_leading(eta1, chi0, law)
    if eta1 < 0 or not np.isfinite(eta1):
        raise ValueError(f"eta1 must be finite and non-negative, got {eta1}")
    if eta1 == 0:
        return 0.0
    log_target = 2.0 * math.log(eta1)
    return solve_log_increasing(
        lambda z: float(np.log(pulloff_lhs_refined(math.exp(z), law, chi0, omega_check))) - log_target,
        what=f"Eq. (106) at eta1 = {eta1:.6g}, omega_check = {omega_check:.6g}",
    )


def pulloff_refined(eta1: ArrayLike, chi0: float, omega_check: ArrayLike, law: RateLaw) -> PulloffEstimate:
    """Refined pull-off estimate (Eqs. 71, 106), vectorised and broadcast over eta1 and omega_check."""
    abar = np.vectorize(lambda e, w: critical_abar_refined(e, chi0, w, law), otypes=[float])(
        np.asarray(eta1, dtype=float), np.asarray(omega_check, dtype=float)
    )
    return PulloffEstimate.from_abar(abar, law)
