"""Every root of a scalar function F(z) on a scanned line: next to poles, hidden pairs, a monotone tail.

Physics-free. The caller scans F on nodes (z, F) of pole-free segments, ascending. This module

* refines the nodes geometrically towards a pole where F -> -infinity (:func:`approach_pole`);
* finds the roots on the nodes of one segment: each sign change polished by Brent's method, and each
  discrete minimum of |F| without a sign change driven towards zero by a bounded minimisation, to catch
  two roots inside one cell (:func:`roots_on_nodes`);
* brackets the one root of an increasing tail by doubling the step (:func:`bracket_increasing_root`).

Roots are reported as (e^z0, increasing): the unknowns are logarithms (z = ln abar_m for the mean
balance of the leading order, :func:`vibroadhesion.models.leading_order.steady_states`, Eqs. 43, 54),
and ``increasing`` (F rising through the root) is the caller's stability criterion.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.optimize import minimize_scalar

from vibroadhesion.numerics.roots import NoRootError, solve_log_increasing

Residual = Callable[[float], float]
Node = tuple[float, float]


def approach_pole(
    residual: Residual, z_pole: float, side: float, step: float, max_halvings: int, what: str
) -> list[Node]:
    """Nodes (z, F) at z = z_pole + side step 2^-j, j = 1, 2, ..., until F < 0 and decreasing towards z_pole.

    ``side`` is -1 (from below) or +1 (from above); F(z_pole + side step) is the reference for the first
    node. Raises :class:`NoRootError` when F has not fallen after ``max_halvings`` halvings.
    """
    nodes: list[Node] = []
    previous = residual(z_pole + side * step)
    for j in range(1, max_halvings + 1):
        z = z_pole + side * step * 2.0**-j
        nodes.append((z, residual(z)))
        if nodes[-1][1] < min(previous, 0.0):
            return nodes
        previous = nodes[-1][1]
    raise NoRootError(f"{what}: residual does not fall towards the pole at e^z = {math.exp(z_pole):.6g}")


def bracket_increasing_root(residual: Residual, z: float, f: float, step: float, what: str) -> Node | None:
    """(lo, hi) with F(lo) < 0 <= F(hi), hi - lo doubling from ``step``, or ``None`` when f = F(z) >= 0.

    F increases strictly beyond z (the caller's proof): one root beyond z if f < 0, none otherwise.
    Raises :class:`NoRootError` when lo passes ln(largest double)/3 with F still negative.
    """
    if not f < 0:
        return None
    lo = z
    while residual(lo + step) < 0:
        lo, step = lo + step, 2.0 * step
        if lo > math.log(np.finfo(float).max) / 3:
            raise NoRootError(f"{what}: no sign change for any representable e^z")
    return lo, lo + step


def polish_sign_change(residual: Residual, lo: float, hi: float, increasing: bool, what: str) -> tuple[float, bool]:
    """(e^z0, increasing) of the root z0 of F in (lo, hi], F changing sign there.

    Brent's method (:func:`vibroadhesion.numerics.roots.solve_log_increasing`, to 1e-14 in z).
    """
    sign = 1.0 if increasing else -1.0
    return solve_log_increasing(lambda t: sign * residual(t), what=what, z_start=lo, z_min=lo, z_max=hi), increasing


def roots_on_nodes(residual: Residual, nodes: list[Node], what: str) -> list[tuple[float, bool]]:
    """(e^z0, increasing) of the roots of F found on the nodes (z, F) of one pole-free segment, ascending.

    Each sign change is polished (:func:`polish_sign_change`); at each discrete minimum of |F| without a
    sign change F is driven towards zero by a bounded minimisation (to 1e-10 in z), and if it crosses
    zero the two roots inside the two cells are polished as well.
    """
    zs = [node[0] for node in nodes]
    fs = [node[1] for node in nodes]
    roots: list[tuple[float, bool]] = []
    for i in range(len(nodes) - 1):
        if (fs[i] >= 0) != (fs[i + 1] >= 0):
            roots.append(polish_sign_change(residual, zs[i], zs[i + 1], fs[i] < 0, what))
        elif 0 < i and (fs[i - 1] >= 0) == (fs[i] >= 0) and abs(fs[i]) < min(abs(fs[i - 1]), abs(fs[i + 1])):
            sign = 1.0 if fs[i] >= 0 else -1.0
            extremum = minimize_scalar(_signed, bounds=(zs[i - 1], zs[i + 1]), args=(residual, sign),
                                       method="bounded", options={"xatol": 1e-10})
            if extremum.fun < 0:
                roots.append(polish_sign_change(residual, zs[i - 1], extremum.x, fs[i] < 0, what))
                roots.append(polish_sign_change(residual, extremum.x, zs[i + 1], fs[i] >= 0, what))
    return roots


def _signed(z: float, residual: Residual, sign: float) -> float:
    """sign F(z): F or its negative, minimised towards zero by :func:`roots_on_nodes`."""
    return sign * residual(z)
