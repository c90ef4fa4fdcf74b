"""Fourier-coefficient integrals J0, Jc1 and J1 of sqrt(f), Eqs. (28), (29) and (36).

    J0(A)  = 1/pi int_0^pi sqrt(f(A cos x))          dx      Eq. (28)
    Jc1(A) = 2/pi int_0^pi sqrt(f(A cos x)) cos x    dx      Eq. (29), n = 1
    J1(A)  = 2/pi int_0^pi sqrt(f(A cos x)) sin^2 x  dx      Eq. (36)

Folding x -> pi - x and writing t = pi/2 - x (the distance from the point where the contact
front reverses) gives integrals over t in (0, pi/2) of the even and odd parts of sqrt(f):

    S(v) = sqrt(f(v)) + sqrt(f(-v)),  D(v) = sqrt(f(v)) - sqrt(f(-v)),  v = A sin t,
    J0 = 1/pi int S dt,   Jc1 = 2/pi int D sin t dt,   J1 = 2/pi int S cos^2 t dt.

For the Gent–Schultz law (Eqs. 73–75), with u = v^n,

    S = (2 + u)/sqrt(1 + u),  D = -u/sqrt(1 + u)                       (Eq. 77 and its twins)

both free of cancellation, so Jc1 keeps full relative accuracy down to A = 1e-300.

Quadrature. The integrand is not smooth at t = 0 (it goes like t^n) and, for large A, turns
over in a boundary layer t ~ 1/A. In y = -ln(2t/pi) both become harmless: the integrand is
(pi/2) e^{-y} S(A (pi/2) e^{-y} ...), analytic in the strip |Im y| < pi/n, and the layer is a
smooth step of width ~1/n located at y ~ ln A. One fixed rule therefore serves every A:
composite Gauss–Legendre on panels of width 2 over y in [0, 36] (t down to 3.6e-16; what lies
below contributes < 1e-15 relatively), with 18 nodes on the first panel and fewer further out,
where the weight e^{-y} makes each panel matter less. 198 nodes in all. Because A enters only
as A^n times the node value sin^n t, evaluating the rule is one exp per node, which makes it
several thousand times faster than adaptive quadrature (see ``benchmarks/``). The measured
error against a 30-digit mpmath reference (``tests/test_integrals.py``) is below 1e-12
relative for A in [0, 1e12] and n in [0.05, 4].
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import beta, gammaln

from vibroadhesion.core.ratelaw import GentSchultz, RateLaw

#: Panels of the fixed rule in y = -ln(2t/pi): (start, end, number of Gauss–Legendre nodes).
#: Three arrays of one shape: (J0, Jc1, J1), or nodes, ln(sin t) and weights of the rule.
Triple = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]

_PANEL_WIDTH = 2.0
_Y_MAX = 36.0
_BLOCK = 512  # rows per block: keeps the (block x nodes) work arrays in cache

#: Largest n ln(A) the rule accepts: exp of it must not overflow.
_MAX_N_LOG_A = 690.0


def _nodes_on_panel(y_mid: float) -> int:
    return max(6, round(18 - 0.4 * y_mid))


@cache
def folded_rule() -> Triple:
    """Nodes t_k in (0, pi/2), ln(sin t_k), and the (nodes x 3) weight matrix of (J0, Jc1, J1).

    Columns: weights of S for J0, of D for Jc1, of S for J1 (the last two folded with sin t and
    cos^2 t), including the Jacobian dt = t dy.
    """
    edges = np.arange(0.0, _Y_MAX + 0.5 * _PANEL_WIDTH, _PANEL_WIDTH)
    ys, ws = [], []
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        x, w = np.polynomial.legendre.leggauss(_nodes_on_panel(0.5 * (a + b)))
        ys.append(0.5 * (b - a) * x + 0.5 * (a + b))
        ws.append(0.5 * (b - a) * w)
    y, w = np.concatenate(ys), np.concatenate(ws)
    t = 0.5 * np.pi * np.exp(-y)
    w = w * t
    weights = np.stack([w / np.pi, 2.0 / np.pi * w * np.sin(t), 2.0 / np.pi * w * np.cos(t) ** 2], axis=1)
    return t, np.log(np.sin(t)), weights


@cache
def _gent_schultz_weights() -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Weights of r and u*r, r = 1/sqrt(1+u): S = 2r + ur and D = -ur (module docstring)."""
    _, _, weights = folded_rule()
    w_r = np.stack([2 * weights[:, 0], np.zeros(len(weights)), 2 * weights[:, 2]], axis=1)
    w_ur = np.stack([weights[:, 0], -weights[:, 1], weights[:, 2]], axis=1)
    return w_r, w_ur


def _as_internal_variable(Abar: ArrayLike) -> NDArray[np.float64]:
    a = np.asarray(Abar, dtype=float)
    if np.any(~np.isfinite(a)) or np.any(a < 0):
        raise ValueError("Abar must be finite and non-negative")
    return a


def j_integrals(Abar: ArrayLike, n: float) -> Triple:
    """J0, Jc1 and J1 of the Gent–Schultz law (Eqs. 28, 29, 36 with Eqs. 73–75).

    Vectorised over ``Abar`` (any shape; each output has that shape). ``n`` is the
    Gent–Schultz exponent. Relative error below 1e-12 for Abar in [0, 1e12], n in [0.05, 4]
    (absolute for Jc1(0) = 0, which is returned exactly).
    """
    GentSchultz(n)  # validates n
    a = _as_internal_variable(Abar)
    with np.errstate(divide="ignore"):
        n_log_a = n * np.log(a.ravel())
    if np.any(n_log_a > _MAX_N_LOG_A):
        raise ValueError(f"Abar^n overflows: Abar must satisfy n*ln(Abar) <= {_MAX_N_LOG_A}")
    n_log_sin_t = n * folded_rule()[1]
    w_r, w_ur = _gent_schultz_weights()
    out = np.empty((n_log_a.size, 3))
    for start in range(0, n_log_a.size, _BLOCK):
        u = np.add.outer(n_log_a[start : start + _BLOCK], n_log_sin_t)
        np.exp(u, out=u)
        r = 1.0 + u
        np.sqrt(r, out=r)
        np.reciprocal(r, out=r)
        np.multiply(u, r, out=u)
        out[start : start + _BLOCK] = r @ w_r + u @ w_ur
    # Abar = 0: f = 1 everywhere; return the exact limits (1, 0, 1) rather than the rule's weight sum.
    out[a.ravel() == 0] = (1.0, 0.0, 1.0)
    j0, jc1, j1 = (out[:, k].reshape(a.shape) for k in range(3))
    return j0, jc1, j1


def j_integrals_general(Abar: ArrayLike, law: RateLaw) -> Triple:
    """J0, Jc1 and J1 of an arbitrary rate law, Eqs. (28), (29), (36), on the same fixed rule.

    The odd part D is formed as a difference of sqrt(f) at +-v, so for small Abar Jc1 carries
    an absolute (not relative) error of ~1e-16; the rule assumes that f changes over
    |x| ~ 1 and is smooth elsewhere, as the Gent–Schultz law does.
    """
    a = _as_internal_variable(Abar)
    t, _, weights = folded_rule()
    out = np.empty((a.size, 3))
    flat = a.ravel()
    for start in range(0, flat.size, _BLOCK):
        v = np.multiply.outer(flat[start : start + _BLOCK], np.sin(t))
        closing, opening = np.sqrt(law.f(v)), np.sqrt(law.f(-v))
        s, d = closing + opening, closing - opening
        out[start : start + _BLOCK] = np.stack([s @ weights[:, 0], d @ weights[:, 1], s @ weights[:, 2]], axis=1)
    j0, jc1, j1 = (out[:, k].reshape(a.shape) for k in range(3))
    return j0, jc1, j1


def j_integrals_for_law(Abar: ArrayLike, law: RateLaw) -> Triple:
    """J0, Jc1, J1 of any rate law: the fast path for :class:`GentSchultz`, the general rule otherwise."""
    if isinstance(law, GentSchultz):
        return j_integrals(Abar, law.n)
    return j_integrals_general(Abar, law)


def _cos_power_integral(p: float) -> float:
    """int_0^{pi/2} cos^p x dx = (sqrt(pi)/2) Gamma((p+1)/2) / Gamma(p/2 + 1)."""
    return 0.5 * math.sqrt(math.pi) * math.exp(gammaln(0.5 * (p + 1)) - gammaln(0.5 * p + 1))


def _sin2_cos_power_integral(p: float) -> float:
    """int_0^{pi/2} sin^2 x cos^p x dx = B(3/2, (p+1)/2) / 2."""
    return 0.5 * float(beta(1.5, 0.5 * (p + 1)))


def j_integrals_large_Abar(Abar: ArrayLike, n: float) -> Triple:
    """Leading large-Abar asymptotes of (J0, Jc1, J1) for the Gent–Schultz law.

    Only the opening half contributes at leading order (end of Sec. 3.3), sqrt(1+u) ~ u^{1/2}:

        J0  ~  (1/pi) Abar^{n/2} int cos^{n/2}
        Jc1 ~ -(2/pi) Abar^{n/2} int cos^{n/2+1}
        J1  ~  (2/pi) Abar^{n/2} int sin^2 cos^{n/2}

    (all integrals over (0, pi/2), in Gamma functions). The remainders are bounded for every
    Abar: 0 < J0 - J0~ < 1, 0 < Jc1 - Jc1~ < 1/pi, 0 < J1 - J1~ < 1 (tested).
    """
    a = _as_internal_variable(Abar)
    p = 0.5 * n
    scale = a**p
    return (
        scale * _cos_power_integral(p) / math.pi,
        -scale * 2.0 * _cos_power_integral(p + 1) / math.pi,
        scale * 2.0 * _sin2_cos_power_integral(p) / math.pi,
    )


def j_integrals_small_Abar(Abar: ArrayLike, n: float) -> Triple:
    """Small-Abar expansions of (J0, Jc1, J1) for the Gent–Schultz law, first correction kept.

    With u = (Abar sin t)^n: S = 2 + u^2/4 + O(u^3) and D = -u + u^2/2 + O(u^3), so

        J0  = 1 + Abar^{2n} W(2n) / (4 pi)           + O(Abar^{3n})
        Jc1 = -(2/pi) Abar^n W(n+1) + Abar^{2n} W(2n+1)/pi + O(Abar^{3n})
        J1  = 1 + Abar^{2n} S2(2n) / (2 pi)          + O(Abar^{3n})

    with W(p) = int cos^p and S2(p) = int sin^2 cos^p over (0, pi/2). Hence the limits
    J0(0) = J1(0) = 1 and Jc1(0) = 0 used in Eqs. (99), (123) and Sec. 3.7.
    """
    a = _as_internal_variable(Abar)
    an, a2n = a**n, a ** (2 * n)
    return (
        1.0 + a2n * _cos_power_integral(2 * n) / (4 * math.pi),
        -2.0 / math.pi * an * _cos_power_integral(n + 1) + a2n * _cos_power_integral(2 * n + 1) / math.pi,
        1.0 + a2n * _sin2_cos_power_integral(2 * n) / (2 * math.pi),
    )
