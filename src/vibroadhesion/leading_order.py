"""Leading-order asymptotic model (Sec. 3.1–3.2): quasi-static pull-off estimate.

Detachment is assumed when the mean contact radius reaches the JKR critical value for the
effective work of adhesion, a_m = a_cr (Eqs. 60–61). For rigid fixation Eq. (55) then reads

    J0(Abar)^(1/3) |Jc1(Abar)| = 3 eta1 / chi0^2,                                  Eq. (72)

which fixes Abar_cr independently of the frequency, and

    P_cr / P_cr^JKR = J0(Abar_cr)^2,                                               Eq. (71)

Uniqueness (Gent–Schultz law). With u = (Abar sin t)^n the integrands of J0 and -Jc1 are
S(u) = (2+u)/sqrt(1+u) and u/sqrt(1+u) (see :mod:`vibroadhesion.integrals`), whose
u-derivatives u/(2(1+u)^{3/2}) and (2+u)/(2(1+u)^{3/2}) are positive; u increases with Abar,
so J0 and |Jc1| are strictly increasing, the left-hand side of Eq. (72) rises strictly from 0
(Abar = 0) to infinity, and Eq. (72) has exactly one root for every eta1 > 0. The tests check
the monotonicity on a dense grid for n in [0.05, 4].
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.integrals import j_integrals_for_law
from vibroadhesion.ratelaw import RateLaw
from vibroadhesion.roots import solve_log_increasing


class PulloffEstimate(NamedTuple):
    """Critical internal variable, J0 there, and the amplification P_cr / P_cr^JKR = J0^2 (Eq. 71)."""

    abar_cr: NDArray[np.float64]
    j0: NDArray[np.float64]
    ratio: NDArray[np.float64]

    @classmethod
    def from_abar(cls, abar_cr: NDArray[np.float64], law: RateLaw) -> "PulloffEstimate":
        j0 = j_integrals_for_law(abar_cr, law)[0]
        return cls(abar_cr, j0, j0**2)


def pulloff_lhs_leading(abar: ArrayLike, law: RateLaw) -> NDArray[np.float64]:
    """Left-hand side of Eq. (72), J0^(1/3) |Jc1|."""
    j0, jc1, _ = j_integrals_for_law(abar, law)
    return np.cbrt(j0) * np.abs(jc1)


def critical_abar_leading(eta1: float, chi0: float, law: RateLaw) -> float:
    """Root Abar_cr of Eq. (72) for one amplitude ratio eta1 = h1/R >= 0 (0 gives 0)."""
    if eta1 < 0 or not np.isfinite(eta1):
        raise ValueError(f"eta1 must be finite and non-negative, got {eta1}")
    if eta1 == 0:
        return 0.0
    log_target = np.log(3.0 * eta1 / chi0**2)
    return solve_log_increasing(
        lambda z: float(np.log(pulloff_lhs_leading(np.exp(z), law))) - log_target,
        what=f"Eq. (72) at eta1 = {eta1:.6g}",
    )


def pulloff_leading(eta1: ArrayLike, chi0: float, law: RateLaw) -> PulloffEstimate:
    """Leading-order pull-off estimate (Eqs. 71–72), vectorised over eta1."""
    eta1 = np.asarray(eta1, dtype=float)
    abar = np.vectorize(lambda e: critical_abar_leading(e, chi0, law), otypes=[float])(eta1)
    return PulloffEstimate.from_abar(abar, law)
