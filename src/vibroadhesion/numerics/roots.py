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


#: The grid in z = ln Abar on which :func:`solve_log_increasing_many` brackets its roots (spacing _Z_STEP).
_BRACKET_GRID = np.arange(-80.0, 80.0 + _Z_STEP / 2, _Z_STEP)
#: At most this many Illinois steps (each at least halves the bracket every second step; 8 in ln spans 2^-60
#: within 120).
_MAX_ILLINOIS = 200


def solve_log_increasing_many(log_lhs: Callable[[NDArray[np.float64]], NDArray[np.float64]],
                              log_targets: NDArray[np.float64], *, what: str) -> NDArray[np.float64]:
    """Abar with ln lhs(Abar) = each of ``log_targets`` for one increasing lhs, vectorised over the targets.

    ``log_lhs(z)`` is ln lhs(e^z), vectorised over a 1-d z. The roots are bracketed on :data:`_BRACKET_GRID`
    (one evaluation of the grid for all targets) and polished together by the Illinois variant of regula falsi
    (superlinear, the bracket kept) to the tolerance of :func:`solve_log_increasing`; a target outside the grid's
    range is solved by :func:`solve_log_increasing` (which widens its bracket to ``Z_MIN``, ``Z_MAX``).
    """
    shape = np.shape(log_targets)
    targets = np.asarray(log_targets, dtype=float).ravel()
    grid_values = log_lhs(_BRACKET_GRID)
    k = np.searchsorted(grid_values, targets, side="left")
    inside = (k > 0) & (k < _BRACKET_GRID.size)
    z = np.empty(targets.size)
    for i in np.flatnonzero(~inside):
        z[i] = math.log(solve_log_increasing(_Shifted(log_lhs, float(targets[i])), what=what))
    idx = np.flatnonzero(inside)
    lo, hi = _BRACKET_GRID[k[idx] - 1], _BRACKET_GRID[k[idx]]
    f_lo, f_hi = grid_values[k[idx] - 1] - targets[idx], grid_values[k[idx]] - targets[idx]
    z[idx] = _illinois_many(log_lhs, targets[idx], (lo, f_lo), (hi, f_hi), what)
    return np.exp(z).reshape(shape)


class _Shifted:
    """ln lhs(e^z) - target as a scalar function of z (for :func:`solve_log_increasing`)."""

    def __init__(self, log_lhs: Callable[[NDArray[np.float64]], NDArray[np.float64]], target: float) -> None:
        """The vectorised ``log_lhs`` and one ``target``."""
        self.log_lhs, self.target = log_lhs, target

    def __call__(self, z: float) -> float:
        """ln lhs(e^z) - target."""
        return float(self.log_lhs(np.array([z]))[0]) - self.target


def _illinois_many(log_lhs: Callable[[NDArray[np.float64]], NDArray[np.float64]], targets: NDArray[np.float64],
                   low: tuple[NDArray[np.float64], NDArray[np.float64]],
                   high: tuple[NDArray[np.float64], NDArray[np.float64]], what: str) -> NDArray[np.float64]:
    """The roots of ln lhs(e^z) - target in the brackets [lo, hi] (values f_lo < 0 <= f_hi), together.

    Illinois steps (Dowell & Jarratt, BIT 11, 1971) until the bracket is narrower than the tolerance of
    :func:`solve_log_increasing` or the residual vanishes; :class:`NoRootError` naming ``what`` after
    :data:`_MAX_ILLINOIS` steps.
    """
    (lo, f_lo), (hi, f_hi) = (np.array(a, dtype=float) for a in low), (np.array(a, dtype=float) for a in high)
    z = np.where(f_hi == 0, hi, lo)
    side = np.zeros(lo.size)
    active = np.flatnonzero(f_hi != 0)
    for _ in range(_MAX_ILLINOIS):
        if active.size == 0:
            return z
        a, b, fa, fb = lo[active], hi[active], f_lo[active], f_hi[active]
        c = np.clip(b - fb * (b - a) / (fb - fa), a, b)
        fc = log_lhs(c) - targets[active]
        z[active] = c
        left = fc < 0
        lo[active] = np.where(left, c, a)
        f_lo[active] = np.where(left, fc, np.where(side[active] == 1, fa / 2, fa))
        hi[active] = np.where(left, b, c)
        f_hi[active] = np.where(left, np.where(side[active] == -1, fb / 2, fb), fc)
        side[active] = np.where(left, -1, 1)
        done = (fc == 0) | (hi[active] - lo[active] <= _Z_TOL + 4 * np.finfo(float).eps * np.abs(c))
        active = active[~done]
    raise NoRootError(f"{what}: the Illinois iteration did not converge in {_MAX_ILLINOIS} steps")
