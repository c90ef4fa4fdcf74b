"""Bracketed root finding for the internal variable Abar.

Every model equation of the paper that fixes Abar (Eqs. 72, 106, 122 with 123) has the form
g(Abar) = target with g increasing from g(0) = 0 to infinity for the Gent–Schultz law (the
monotonicity proofs are in the docstrings of the callers and checked in the tests). The root
is therefore unique; it is bracketed on a logarithmic scale, z = ln Abar, and polished with
Brent's method. When a bracket cannot be found (a rate law whose g is bounded, or a root
beyond the representable range) :class:`NoRootError` is raised instead of returning a number.

Where many such equations are solved at once and g's logarithmic slope is bounded and falling (|Jc1| of the
leading order, Eq. 43), :func:`solve_increasing_bounded_slope` solves them together by Newton's method kept
inside the bracket that the slope bounds give.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray
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


#: G and G' at z of the equations ``index`` (positions in the start array): :func:`solve_increasing_bounded_slope`.
ExcessAndSlope = Callable[[NDArray[np.float64], NDArray[np.intp]], tuple[NDArray[np.float64], NDArray[np.float64]]]

#: Newton steps of :func:`solve_increasing_bounded_slope` before it gives up (its docstring: about 60 would cross
#: the whole double range at the slowest rate it allows).
_MAX_NEWTON = 100


def solve_increasing_bounded_slope(
    excess_and_slope: ExcessAndSlope,
    z_start: NDArray[np.float64],
    slope_min: float,
    slope_max: float,
    *,
    z_max: float,
    what: str,
) -> NDArray[np.float64]:
    """The roots z of G(z) = 0 for an array of increasing, concave G with G' in [slope_min, slope_max], vectorised.

    ``excess_and_slope(z, index)`` returns G and G' of the equations ``index`` (positions in ``z_start``) at
    the 1-d ``z``. From the start z_s with G(z_s) = g_s the root lies between z_s - g_s/slope_max and
    z_s - g_s/slope_min (mean value theorem); Newton's steps are kept inside that bracket (widened by 1e-12
    for the rounding of g_s).
    G concave: from the left of the root the iterates rise monotonically (the tangent lies above G), each
    step covering at least slope_min/slope_max of the distance (then quadratically); from the right the
    first step lands on the left. Ends when every step is below 1e-14 + 4 eps |z| (the tolerance of
    :func:`solve_log_increasing`). :class:`NoRootError` naming ``what`` where the bracket reaches beyond
    ``z_max`` (the root may lie outside the domain of G) or after _MAX_NEWTON steps.
    """
    z = np.array(z_start, dtype=float)
    g, slope = excess_and_slope(z, np.arange(z.size))
    ends = np.stack([z - g / slope_max, z - g / slope_min])
    lo, hi = ends.min(axis=0) - 1e-12, ends.max(axis=0) + 1e-12
    if np.any(hi > z_max):
        raise NoRootError(f"{what}: the root may lie beyond z = {z_max:.6g}, outside the equation's domain")
    active = np.flatnonzero(g != 0)
    g, slope = g[active], slope[active]
    for _ in range(_MAX_NEWTON):
        if active.size == 0:
            return z
        step = np.clip(z[active] - g / slope, lo[active], hi[active]) - z[active]
        z[active] += step
        active = active[np.abs(step) > _Z_TOL + 4 * np.finfo(float).eps * np.abs(z[active])]
        if active.size:
            g, slope = excess_and_slope(z[active], active)
    raise NoRootError(f"{what}: Newton's method did not converge in {_MAX_NEWTON} steps")
