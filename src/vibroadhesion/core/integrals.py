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
over in a boundary layer t ~ 1/A. One fixed rule serves every A: t = (pi/2) tau^4 turns the
kink into tau^(4n) times the Jacobian tau^3 (dt = 2 pi tau^3 dtau), and Gauss–Jacobi
quadrature with the weight tau^3 (72 nodes, tau = (1 + x)/2, weight (1 + x)^3 on (-1, 1))
integrates the rest: tau^(4n) is smooth enough (Gauss error on x^b is O(N^(-2b-2))) and the
layer, spread over tau ~ A^(-1/4), is resolved. The weight tau^3 is carried by the weights, so
they sum to pi/2 within 2e-16 (Gauss–Legendre times tau^3 misses by 4e-15 through its end
weights); what is left of the rule's rounding is below 3e-15 (J1(0+) = 1 - 2.6e-15: a node's
rounding, 2e-16 in x, moves t by up to pi times that). The hardest case is the largest n, where the layer is
sharpest (the pole of 1/sqrt(1+u) at u = -1 lies ~ 1/(nA) off the real t axis); the error
falls geometrically with the number of nodes (n = 4: 3.9e-13 with 64 nodes, 5.4e-14 with 72).
Where A is large the layer carries a share ~ A^(-1-n/2) of the integral and its error is
irrelevant.

Error bound, as established (measured, not proved): the largest relative error of (J0, Jc1,
J1) against a 3600-node reference rule (composite Gauss–Legendre, 30 nodes on each panel of
width 1/2 in -ln(2t/pi) up to 60; it agrees with the 30-digit mpmath reference to 4e-16) over
n in [0.05, 4] (step 0.05, and 3.9, 3.95, 3.98) and 4001 log-spaced A per n from 1e-12 to the
overflow limit (n ln A <= 690, A <= 1e300) is 5.3e-14, at n = 4, A = 114 (5.5e-14 against
mpmath at A = 150); elsewhere it is rounding, 4e-15. The stated bound is 1e-13 relative
(absolute for Jc1 where A^n underflows, A^n < 1e-308, and for Jc1(0) = 0, returned exactly);
below A = 1e-12 the integrand tends to its small-A form, which the rule integrates as well.
The tests check it on a coarser scan (9 values of n, 1201 of A) and 1e-12 against mpmath at
the hard cases (n = 0.05 and 4, A from 1e-300 to 1e100, and A = 50–250 at n = 4).

Because A enters only through A^n times the node value (sin t_k)^n, u = (A sin t_k)^n is one
product per node after one power per A: no exp, which cost time and carried the rounding of
n ln A (relative error up to 690 x 1.1e-16 = 8e-14 in u at the overflow limit).
The rule is several thousand times faster than adaptive quadrature (see ``benchmarks/``).
"""

from __future__ import annotations

import math
from functools import cache, partial

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import beta, gammaln, roots_jacobi

from vibroadhesion.core.ratelaw import GentSchultz, RateLaw
from vibroadhesion.numerics.roots import solve_increasing_bounded_slope

#: Three arrays of one shape: (J0, Jc1, J1), or nodes, sin t and weights of the rule.
Triple = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]

#: Gauss–Jacobi nodes in tau, t = (pi/2) tau^_POWER (module docstring: error bound).
_NODES = 72
_POWER = 4
_BLOCK = 512  # rows per block: keeps the (block x nodes) work arrays in cache

#: Largest Abar^n the rule accepts (n ln Abar <= 690), far from overflow.
_MAX_ABAR_POWER = math.exp(690.0)


@cache
def folded_rule() -> Triple:
    """Nodes t_k in (0, pi/2), sin t_k, and the (nodes x 3) weight matrix of (J0, Jc1, J1).

    t = (pi/2) tau^4, tau = (1 + x)/2: int_0^(pi/2) g dt = (pi/8) int_(-1)^1 g (1 + x)^3 dx, by
    Gauss–Jacobi with the weight (1 + x)^3 (module docstring). Columns: weights of S for J0, of
    D for Jc1, of S for J1 (the last two folded with sin t and cos^2 t).
    """
    x, w_jacobi = roots_jacobi(_NODES, 0.0, _POWER - 1.0)
    t = 0.5 * np.pi * (0.5 * (1.0 + x)) ** _POWER
    w = 0.5 * np.pi * _POWER / 2.0**_POWER * w_jacobi  # dt = (pi/2) 4 tau^3 dtau, tau^3 dtau = (1 + x)^3 dx / 16
    sin_t = np.sin(t)
    weights = np.stack([w / np.pi, 2.0 / np.pi * w * sin_t, 2.0 / np.pi * w * np.cos(t) ** 2], axis=1)
    return t, sin_t, weights


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


def gent_schultz_u(Abar: NDArray[np.float64], n: float) -> NDArray[np.float64]:
    """u = (Abar sin t_k)^n of Eq. (75) at the rule's nodes: rows the 1-d ``Abar``, columns t_k.

    Abar^n (sin t_k)^n: one power per Abar and per node and a product, no exp (module
    docstring). ValueError where n ln Abar > 690 (Abar^n would come near overflow).
    """
    with np.errstate(over="ignore"):
        a_n = Abar**n
    if np.any(a_n > _MAX_ABAR_POWER):
        raise ValueError("Abar^n overflows: Abar must satisfy n*ln(Abar) <= 690")
    return np.multiply.outer(a_n, folded_rule()[1] ** n)


def j_integrals(Abar: ArrayLike, n: float) -> Triple:
    """J0, Jc1 and J1 of the Gent–Schultz law (Eqs. 28, 29, 36 with Eqs. 73–75).

    Vectorised over ``Abar`` (any shape; each output has that shape). ``n`` is the
    Gent–Schultz exponent. Relative error below 1e-13 for Abar from 0 to the overflow limit
    n ln Abar <= 690 and n in [0.05, 4] (module docstring; absolute for Jc1 where Abar^n
    underflows and for Jc1(0) = 0, which is returned exactly).
    """
    GentSchultz(n)  # validates n
    a = _as_internal_variable(Abar)
    flat = a.ravel()
    w_r, w_ur = _gent_schultz_weights()
    out = np.empty((flat.size, 3))
    for start in range(0, flat.size, _BLOCK):
        u = gent_schultz_u(flat[start : start + _BLOCK], n)
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
    _, sin_t, weights = folded_rule()
    out = np.empty((a.size, 3))
    flat = a.ravel()
    for start in range(0, flat.size, _BLOCK):
        v = np.multiply.outer(flat[start : start + _BLOCK], sin_t)
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


def jc1_log_slope(Abar: NDArray[np.float64], n: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """ln|Jc1| and s = d ln|Jc1| / d ln Abar of the Gent–Schultz law, on the rule of :func:`j_integrals` (Eq. 29).

    With u_k = (Abar sin t_k)^n, |Jc1| = sum_k w_k D(u_k), D(u) = u/sqrt(1+u) and w_k > 0 the Jc1 weights;
    d D(u_k)/d ln Abar = n D(u_k) q(u_k), q(u) = (2+u)/(2(1+u)) in (1/2, 1]. So s is n times the mean of q
    weighted by w_k D(u_k): s lies in (n/2, n]. It falls as Abar grows (every u_k rises, q falls, and the
    weight moves to the nodes of larger u_k, where q is smaller), so ln|Jc1| is concave in ln Abar. 1-d
    ``Abar``, positive, with Abar^n far from underflow (ln|Jc1| is -inf where it underflows).
    """
    u = gent_schultz_u(Abar, n)
    w = folded_rule()[2][:, 1]
    d = u / np.sqrt(1.0 + u)
    jc1 = d @ w
    return np.log(jc1), n * ((d * ((1.0 + 0.5 * u) / (1.0 + u))) @ w) / jc1


#: Where c1 Abar^n is below this, every u_k <= Abar^n < 3e-17 (c1 > 1/3 for n <= 4) and D(u) = u (1 - u/2 + ...) is
#: u to rounding: |Jc1| = c1 Abar^n, c1 = sum_k w_k (sin t_k)^n (:func:`abar_for_abs_jc1`).
_LINEAR_U = 1e-17


def abar_for_abs_jc1(log_target: ArrayLike, n: float, what: str) -> NDArray[np.float64]:
    """Abar with ln|Jc1(Abar)| = log_target elementwise: the amplitude equations' inversion (Eqs. 29, 43, 73–75).

    |Jc1| rises from 0 to infinity with Abar, its log concave in ln Abar with slope in (n/2, n]
    (:func:`jc1_log_slope`). It lies below both c1 Abar^n (D(u) <= u; c1 = sum_k w_k (sin t_k)^n on the
    rule, (2/pi) int cos^(n+1) exactly) and c2 Abar^(n/2) (:func:`j_integrals_large_Abar`, whose remainder is
    positive), so the larger of the two roots of those bounds lies at or below the root: the start of
    Newton's method (:func:`vibroadhesion.numerics.roots.solve_increasing_bounded_slope`, to 1e-14 in
    ln Abar). Where c1 Abar^n < _LINEAR_U the first bound is |Jc1| to rounding and its root is returned.
    :class:`vibroadhesion.numerics.roots.NoRootError` naming ``what`` where the root may lie beyond the
    rule's range (n ln Abar > 690).
    """
    log_target = np.atleast_1d(np.asarray(log_target, dtype=float))
    c1, c2 = _jc1_bound_constants(n)
    z = np.maximum((log_target - math.log(c1)) / n, (log_target - math.log(c2)) / (0.5 * n))
    newton = np.flatnonzero(n * z + math.log(c1) >= math.log(_LINEAR_U))
    if newton.size:
        z[newton] = solve_increasing_bounded_slope(
            partial(_jc1_log_excess, log_target=log_target[newton], n=n), z[newton], 0.5 * n, n,
            z_max=math.log(_MAX_ABAR_POWER) / n, what=what)
    return np.exp(z)


@cache
def _jc1_bound_constants(n: float) -> tuple[float, float]:
    """c1 = sum_k w_k (sin t_k)^n on the rule and c2 = (2/pi) int cos^(n/2+1): |Jc1| <= c1 Abar^n, c2 Abar^(n/2).

    The bounds of :func:`abar_for_abs_jc1` (small- and large-Abar forms, :func:`j_integrals_small_Abar`,
    :func:`j_integrals_large_Abar`), once per n: the scan's scalar residuals call it thousands of times.
    """
    _, sin_t, weights = folded_rule()
    return float(sin_t**n @ weights[:, 1]), 2.0 * _cos_power_integral(0.5 * n + 1.0) / math.pi


def _jc1_log_excess(
    z: NDArray[np.float64], index: NDArray[np.intp], log_target: NDArray[np.float64], n: float
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """ln|Jc1(e^z)| - log_target[index] and its slope in z (:func:`jc1_log_slope`; Eq. 29)."""
    log_jc1, slope = jc1_log_slope(np.exp(z), n)
    return log_jc1 - log_target[index], slope
