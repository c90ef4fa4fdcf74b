"""Bracketed root finding for the internal variable Abar.

Every model equation of the paper that fixes Abar (Eqs. 72, 106, 122 with 123) has the form
g(Abar) = target with g increasing from g(0) = 0 to infinity for the Gent–Schultz law (the
monotonicity proofs are in the docstrings of the callers and checked in the tests). The root
is therefore unique; it is bracketed on a logarithmic scale, z = ln Abar, and polished with
Brent's method. When a bracket cannot be found (a rate law whose g is bounded, or a root
beyond the representable range) :class:`NoRootError` is raised instead of returning a number.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.optimize import brentq

#: Bracketing range in z = ln Abar; exp(690) is close to the largest double.
Z_MIN, Z_MAX = -690.0, 690.0
_Z_STEP = 8.0
_Z_TOL = 1e-14  # absolute in ln Abar, i.e. relative in Abar


class NoRootError(ArithmeticError):
    """The model equation has no root in the admissible range; no number is returned."""


def solve_log_increasing(
    log_excess: Callable[[float], float],
    *,
    what: str,
    z_start: float = 0.0,
    z_min: float = Z_MIN,
    z_max: float = Z_MAX,
) -> float:
    """Return Abar > 0 with ``log_excess(ln Abar) == 0`` for an increasing ``log_excess``.

    ``log_excess(z)`` is ln g(e^z) - ln target (well scaled over hundreds of decades).
    ``what`` names the equation in the error message.
    """
    lo = hi = z_start
    f_lo = f_hi = log_excess(z_start)
    while f_lo > 0:
        hi, f_hi = lo, f_lo
        lo = max(lo - _Z_STEP, z_min)
        f_lo = log_excess(lo)
        if lo == z_min and f_lo > 0:
            raise NoRootError(f"{what}: left-hand side exceeds the target even at Abar = {math.exp(z_min):.3g}")
    while f_hi < 0:
        lo, f_lo = hi, f_hi
        if hi >= z_max:
            raise NoRootError(
                f"{what}: left-hand side stays below the target up to Abar = {math.exp(z_max):.3g} "
                f"(log-excess {f_hi:.3g}); the equation has no root"
            )
        hi = min(hi + _Z_STEP, z_max)
        f_hi = log_excess(hi)
    if f_lo == 0:
        return math.exp(lo)
    if f_hi == 0:
        return math.exp(hi)
    z, info = brentq(
        log_excess, lo, hi, xtol=_Z_TOL, rtol=4 * np.finfo(float).eps, maxiter=200, full_output=True, disp=False
    )
    if not info.converged:
        raise NoRootError(f"{what}: Brent iteration did not converge ({info.flag})")
    return math.exp(z)
