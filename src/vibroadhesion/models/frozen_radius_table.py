"""alpha*(beta) and Abar(beta) of the drift-free cycle, tabulated per Gent–Schultz exponent n.

The direct solve of the drift condition (*) of :mod:`vibroadhesion.models.frozen_radius` (from Eqs. 5, 6
and 18) is a bracketed root search over the quadrature of the drift integrals, 3–4 ms per call; the
levels of :mod:`vibroadhesion.models.exact_averaging` call it inside a second root search (nominal point
contact, a_m = a_cr) or on nested scans (force minimum), 25–40 ms per point. For beta > 0 both alpha*
and Abar are smooth in x = ln beta (power laws at both ends, frozen_radius's docstring), so they are
tabulated once per n and evaluated in microseconds:

* the table covers x in [-9, 9] (beta from e^-9 = 1.2e-4 to e^9 = 8.1e3) in pieces [k, k + 1); on each
  piece ln alpha* and ln Abar are Chebyshev series of degree 23 in u = 2 (x - k) - 1, interpolating the
  direct solve at the 24 Chebyshev points of the first kind (one vectorised solve per piece);
* a piece is built on first use and cached per (n, k) (:func:`_piece`, a bounded functools.lru_cache):
  a fit that varies n pays, per trial n, the pieces it touches (10–25 ms each). At the paper's test
  conditions (h1 = 20–100 um) the levels use beta in [0.35, 21] (the force-minimum scan; the nominal
  point contact and a_m = a_cr use beta ~ 1–5), i.e. pieces k = -2 ... 3;
* measured against the direct solve at 3000 random points over the whole table for n = 0.05, 0.3, 0.531,
  1, 2.5 and 4: relative error below 1e-12 on alpha* and Abar (degree 19 gives 8e-11 at n = 4 near
  beta = 1, the hardest piece); tested to 1e-11 (tests/models/test_frozen_radius_table.py).

Outside the table the direct solve is used, never an extrapolation: beta below e^-9 or above e^9, and
exponents outside [0.05, 4] (the range the error was measured on; for n > 4 a steady state need not
exist, frozen_radius's docstring). beta = 0 is the static state, alpha* = 1 and Abar = 0 exactly.
"""

from __future__ import annotations

import math
from functools import cache, lru_cache
from typing import NamedTuple

import numpy as np
from numpy.polynomial import chebyshev
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.models.frozen_radius import frozen_radius_cycle

Array = NDArray[np.float64]

#: The table's range of x = ln beta: pieces [k, k + 1) for k = X_RANGE[0] ... X_RANGE[1] - 1.
X_RANGE = (-9, 9)
#: Exponents n whose table error was measured (module docstring); others use the direct solve.
N_RANGE = (0.05, 4.0)
#: Chebyshev points per piece (degree 23), chosen by the measured error (module docstring).
_NODES = 24
#: Pieces kept: 18 per exponent, so the whole table of 56 exponents (a fit's trial n).
_CACHED_PIECES = 1024


class TabulatedCycle(NamedTuple):
    """alpha*(beta), Abar(beta) of the drift-free cycle (Eq. * of frozen_radius) and d ln alpha*/d ln beta."""

    alpha: Array  # mean of sqrt(w/w0); w_eff/w0 = alpha^2 (Eq. 18)
    Abar: Array  # omega A/v0 (Eq. 45 with the exact a(t))
    slope: Array  # d ln alpha*/d ln beta (NaN where the direct solve answered)


@cache
def _chebyshev_points() -> Array:
    """The 24 Chebyshev points of the first kind on [-1, 1], cos(pi (j + 1/2)/24), nodes of every piece."""
    return np.cos(np.pi * (np.arange(_NODES) + 0.5) / _NODES)


@lru_cache(maxsize=_CACHED_PIECES)
def _piece(n: float, k: int) -> Array:
    """Chebyshev coefficients, rows ln alpha*, ln Abar, d ln alpha*/dx, on x = ln beta in [k, k + 1] (Eq. *).

    One vectorised direct solve (:func:`vibroadhesion.models.frozen_radius.frozen_radius_cycle`) at the
    24 points; the coefficients of the interpolant through values f_i at points cos(theta_i) are
    c_j = (2/24) sum_i f_i cos(j theta_i), c_0 halved (discrete orthogonality of T_j).
    """
    cycle = frozen_radius_cycle(np.exp(k + 0.5 + 0.5 * _chebyshev_points()), GentSchultz(n))
    theta = np.pi * (np.arange(_NODES) + 0.5) / _NODES
    basis = np.cos(np.outer(np.arange(_NODES), theta)) * (2.0 / _NODES)
    basis[0] *= 0.5
    values = basis @ np.stack([np.log(cycle.alpha), np.log(cycle.Abar)], axis=1)
    slope = np.zeros(_NODES)
    slope[:-1] = 2.0 * chebyshev.chebder(values[:, 0])  # du/dx = 2
    return np.stack([values[:, 0], values[:, 1], slope])


def is_tabulated(law: GentSchultz) -> bool:
    """Whether the table answers for this law: a Gent–Schultz exponent in :data:`N_RANGE` (Eqs. 73–75)."""
    return isinstance(law, GentSchultz) and N_RANGE[0] <= law.n <= N_RANGE[1]


def log_cycle_on_table(x: Array, law: GentSchultz) -> Array:
    """Rows ln alpha*, ln Abar and d ln alpha*/d ln beta at x = ln beta inside :data:`X_RANGE` (Eq. *).

    Each x is evaluated on its piece k = floor(x) (x = 9 on the last one) at u = 2 (x - k) - 1.
    """
    x = np.asarray(x, dtype=float)
    if not is_tabulated(law) or np.any(~(x >= X_RANGE[0])) or np.any(~(x <= X_RANGE[1])):
        raise ValueError(f"outside the table: n = {law.n}, ln beta in {X_RANGE} required")
    k = np.minimum(np.floor(x), X_RANGE[1] - 1)
    pieces, which = np.unique(k, return_inverse=True)
    coefficients = np.stack([_piece(law.n, int(p)) for p in pieces])[which.ravel()]
    basis = chebyshev.chebvander(2.0 * (x.ravel() - k.ravel()) - 1.0, _NODES - 1)
    return np.einsum("mj,mqj->qm", basis, coefficients).reshape((3, *x.shape))


def tabulated_cycle(beta: ArrayLike, law: GentSchultz) -> TabulatedCycle:
    """alpha*(beta) and Abar(beta) of Eq. (*) for beta >= 0 (any shape): the table, else the direct solve.

    beta = 0 gives alpha* = 1, Abar = 0 exactly; beta or n outside the table (module docstring) are solved
    directly (:func:`vibroadhesion.models.frozen_radius.frozen_radius_cycle`, which raises what it raises:
    :class:`vibroadhesion.models.frozen_radius.NoSteadyStateError` for n > 4 without a steady state).
    """
    beta = np.asarray(beta, dtype=float)
    if np.any(~np.isfinite(beta)) or np.any(beta < 0):
        raise ValueError("beta must be finite and non-negative")
    alpha, Abar, slope = np.ones(beta.shape), np.zeros(beta.shape), np.zeros(beta.shape)
    x = np.log(beta, out=np.full(beta.shape, -np.inf), where=beta > 0)
    inside = (x >= X_RANGE[0]) & (x <= X_RANGE[1]) & is_tabulated(law)
    if np.any(inside):
        log_alpha, log_Abar, slope[inside] = log_cycle_on_table(x[inside], law)
        alpha[inside], Abar[inside] = np.exp(log_alpha), np.exp(log_Abar)
    direct = (beta > 0) & ~inside
    if np.any(direct):
        cycle = frozen_radius_cycle(beta[direct], law)
        alpha[direct], Abar[direct], slope[direct] = cycle.alpha, cycle.Abar, math.nan
    return TabulatedCycle(alpha, Abar, slope)
