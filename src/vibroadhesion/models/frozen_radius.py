"""The drift-free cycle of the frozen contact radius: exact averaging in the high-frequency limit, rigid fixation.

The model level built on it (mean state, nominal point contact, pull-off) is
:mod:`vibroadhesion.models.exact_averaging`.

Notation (derived from Eqs. 4–6, 11 and 86). Length and force scales a_o = (2 pi w0 R^2/E*)^(1/3)
= c_o R with c_o = 2^(1/3) 3^(-2/3) chi0 (Eq. 86), and

    abar = a/a_o,   deltabar = delta R/a_o^2,   Phat = P R/(E* a_o^3),   tau = omega t,
    s = sqrt(w/w0)  (the quantity that enters Eqs. 4, 5 and is averaged in Eq. 18).

With 2 pi w0/E* = a_o^3/R^2, Eq. (5) gives delta R/a_o^2 = abar^2 - R sqrt(2 pi w0 a/E*) s/a_o^2, i.e.

    deltabar = abar^2 - s sqrt(abar),          Phat = (4/3) abar^3 - 2 s abar^(3/2)         (Eqs. 5, 4)

(the same identity turns sqrt(8 pi w E* a^3) R/(E* a_o^3) into 2 s abar^(3/2)). The JKR pull-off
force -(3/2) pi w0 R (Eq. 70) is Phat = -3/4 because pi w0 R^2/(E* a_o^3) = 1/2. Eq. (6) reads
s^2 = f(x) with x = (da/dt)/v0 = (a_o omega/v0) d abar/d tau = omega_check c_o d abar/d tau
(omega_check = omega R/v0, Eq. 105). A rigidly fixed indenter has x_s = 0 in Eq. (7), so with
Eq. (11) delta = hhat - h = (hhat - h0) - h1 sin tau:

    deltabar(tau) = base_offset - etahat sin tau,  base_offset = (hhat - h0) R/a_o^2,  etahat = h1 R/a_o^2 = eta1/c_o^2.

The nominal point contact (Sec. 3.5.4, h0 = hhat) has base_offset = 0.

The frozen radius. The rate law is strictly decreasing, so it has an inverse X(s) = f^{-1}(s^2)
(the signed speed at which w/w0 = s^2), and Eq. (5) is the ordinary differential equation

    d abar/d tau = X(s)/(omega_check c_o),   s = (abar^2 - deltabar(tau))/sqrt(abar).

As omega_check -> infinity the right-hand side is O(1/omega_check): abar changes by O(1/omega_check)
over a period, abar = abar_m + O(1/omega_check), and (first-order averaging) the mean radius drifts
at the rate mean_tau X(s(abar_m, tau))/(omega_check c_o). Frozen at abar_m, Eq. (5) makes s *exactly*
affine in sin tau -- no linearisation and no ansatz for a(t):

    s(tau) = alpha + beta sin tau,   alpha = (abar_m^2 - base_offset)/sqrt(abar_m),   beta = etahat/sqrt(abar_m).

A steady state is a radius that does not drift:

    G(alpha, beta) = (1/2pi) int_0^2pi X(alpha + beta sin tau) d tau = 0.                     (*)

X is strictly decreasing, so G is strictly decreasing in alpha and (*) fixes alpha = alpha*(beta),
a universal function of one variable for a given law (as the J-integrals are). Signs: s > 1
(w > w0) is an opening crack, a shrinking contact, x = X < 0; this happens while sin tau is large,
when the base pulls the sample away (deltabar decreasing). By Eqs. (18) and (16)-(17) the effective
work of adhesion is the mean of s squared, exactly: w_eff/w0 = alpha*^2 (the mean state that follows is
in :mod:`vibroadhesion.models.exact_averaging`).

The contact radius oscillation follows by integrating the speed: a(t) - a_m = (v0/omega)(Xi(tau) - mean Xi)
with Xi(tau) = int_0^tau X(alpha + beta sin u) du, periodic by (*). Xi is extremal where X = 0, at
sin tau = sigma0 = (1 - alpha)/beta; its half peak-to-peak is

    Abar = omega A/v0 = int_{theta0}^{pi/2} |X(alpha + beta sin theta)| d theta,  theta0 = arcsin sigma0,

independent of omega_check, and A/a_m = Abar/(omega_check c_o abar_m) (Eqs. 45, 86; errata E1).
Integrating the unaveraged equation by brute force (tests) confirms the limit: the period mean of
abar and its half peak-to-peak approach abar_m and Abar/(omega_check c_o) with relative errors that
fall like (omega_check c_o)^-2 (1.4e-3 and 8.6e-3 at omega_check c_o = 400 for n = 0.531, etahat = 1).

Existence (s > 0, i.e. alpha > beta, is needed for w > 0). For the Gent–Schultz law (Eqs. 73–75)
X(s) = -(s^2 - 1)^p for s >= 1 and (s^-2 - 1)^p for s < 1, p = 1/n. As alpha decreases to beta the
closing speed near the minimum of s, X ~ s^(-2p) with s ~ (alpha - beta) + beta (tau + pi/2)^2/2,
has an integral that diverges when 4p >= 1, i.e. n <= 4. Hence for n <= 4 G(beta+, beta) = +infinity,
G(1 + beta, beta) < 0 (s >= 1 throughout) and (*) has exactly one root with beta < alpha* < 1 + beta
for every beta: the steady state exists and w > 0 throughout the cycle. For n > 4 the limit is finite
and can be negative (large beta): then no steady state with permanent contact exists and
:class:`NoSteadyStateError` is raised.

Asymptotes (Gent–Schultz; tested). alpha* is even in beta (tau -> tau + pi maps beta to -beta) but not
analytic at 0. Expanding X(1 + e) = -sign(e) (2|e|)^p (1 + a_sign |e| + b_sign e^2 + ...) with
a_+ = p/2, b_+ = p(p-1)/8 (opening: s^2 - 1 = 2e(1 + e/2)) and a_- = 3p/2, b_- = 2p + 9p(p-1)/8
(closing: s^-2 - 1 = 2|e|(1 + 3|e|/2 + 2e^2 + ...)), writing alpha = 1 + kappa beta and
M(q) = mean |sin tau|^q = Gamma((q+1)/2)/(sqrt(pi) Gamma(q/2 + 1)), the mean of (*) is, order by order
in beta, kappa p M(p-1) + beta [kappa p(p+1) M(p) - (p/2) M(p+1)] + beta^2 (b_+ - b_-) M(p+2)/2 + ...
(the kappa^2 term vanishes by symmetry). With M(p+1)/M(p-1) = p/(p+1):

    alpha* = 1 + k1 beta^2 + k2 beta^3 + O(beta^4),   k1 = 1/(2(1 + n)),
    k2 = -[k1 p(p+1) M(p) + (b_+ - b_-) M(p+2)/2]/(p M(p-1))    (k2 = 1/(3 pi) for n = 1),

so w_eff/w0 = 1 + beta^2/(1 + n) + O(beta^3). (Closing is faster than opening at equal |s - 1|, so
alpha must exceed 1 to cancel the drift.)
For beta -> infinity (n < 4) the opening integral is ~ beta^(2p) 2^(2p+1) W(4p) and the closing
integral is dominated by the neighbourhood of the minimum s_min = alpha - beta, ~ s_min^(1/2-2p)
sqrt(2/beta) (sqrt(pi)/2) Gamma(2p - 1/2)/Gamma(2p), with W(q) = int_0^(pi/2) cos^q; equating them,

    alpha* - beta = s_min ~ Q^(-2n/(4-n)) beta^(-(4+n)/(4-n)),
    Q = 2^(2p+1) sqrt(2/pi) W(4p) Gamma(2p)/Gamma(2p - 1/2),

so alpha*/beta -> 1 and w_eff/w0 ~ beta^2.

Quadrature. With theta = tau in (-pi/2, pi/2) (the other half period repeats it), (*) is
I_cl = I_op, where I_cl = int_{-pi/2}^{theta0} (s^-2 - 1)^p and I_op = int_{theta0}^{pi/2} (s^2 - 1)^p
(= Abar). Each is split at its midpoint and each half is integrated in a variable adapted to its
end (details in :func:`_log_drift_integrals`): at the kink theta0 the integrand behaves like
d^p (d the distance), made exponential by d = L exp(-y/(1 + p)); at the maximum of s it is smooth;
at the minimum it is a peak of width sqrt(2 s_min/beta), which s = s_min cosh^2 u maps onto a bell of
fixed shape. s - 1 and s are formed from the distance to the nearest end by product formulas (no
cancellation, so s_min down to 1e-280 keeps full relative accuracy). Composite Gauss–Legendre on
panels of width 2 with up to 24 nodes, 40 units of decay kept past the last feature (e^-40 = 4e-18);
sums are formed in logarithms (no overflow for n = 0.05, where X ~ s^40). The drift condition is
solved by Chandrupatla's bracketed method (scipy.optimize.elementwise.find_root, vectorised) in the
closing arc (beta < 1/4) or in ln(alpha - beta) (beta >= 1/4), so that both alpha* - 1 at small beta
and alpha* - beta at large beta keep their relative accuracy. Against 30-digit mpmath the measured
relative error of alpha* is below 1e-15, of Abar below 1e-14 (tests/test_exact_averaging.py).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cache
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import elementwise

from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.numerics.roots import NoRootError

Array = NDArray[np.float64]

#: y-range kept beyond the last feature of an integrand: exp(-40) = 4e-18.
_Y_TAIL = 40.0
_PANEL_WIDTH = 2.0
_NODES_PER_PANEL = 24
#: Tail decay rates 4p - 1 below which the tail next to the minimum of s is kept in full.
_MIN_TAIL_RATE = 0.05
#: Smallest minimum of s = sqrt(w/w0) the root search resolves; below it alpha* = beta in doubles.
_S_MIN_FLOOR = 1e-280
#: Smallest closing (or opening) arc in the brackets, in radians.
_ARC_FLOOR = 2.0**-20
#: beta below which the kink angle is the unknown, above which ln(alpha - beta) is.
_BETA_SPLIT = 0.25
#: Largest Gent–Schultz exponent for which the steady state is proven to exist (module docstring).
_N_EXISTENCE = 4.0
#: ln of the largest double: Abar = I_op beyond it is reported, not returned as infinity.
_LOG_MAX_DOUBLE = 709.0


class NoSteadyStateError(NoRootError):
    """No periodic state with permanent contact exists; no number is returned."""


def _panel_rule(n_panels: int, nodes: Callable[[float], int]) -> tuple[Array, Array]:
    """Composite Gauss–Legendre rule in y on panels of width 2, ``nodes(centre)`` nodes each (Eq. * quadrature)."""
    edges = np.arange(n_panels + 1) * _PANEL_WIDTH
    ys, ws = [], []
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        x, w = np.polynomial.legendre.leggauss(nodes(0.5 * (a + b)))
        ys.append(0.5 * (b - a) * x + 0.5 * (a + b))
        ws.append(0.5 * (b - a) * w)
    return np.concatenate(ys), np.concatenate(ws)


@cache
def _tail_rule() -> tuple[Array, Array]:
    """Rule in y on [0, 40] for halves whose only feature is at y = O(1): fewer nodes far out."""
    return _panel_rule(round(_Y_TAIL / _PANEL_WIDTH), lambda y: max(8, round(_NODES_PER_PANEL - 0.5 * y)))


@cache
def _uniform_rule(n_panels: int) -> tuple[Array, Array]:
    """Rule in y on [0, 2 n_panels] with 24 nodes on every panel (features anywhere)."""
    return _panel_rule(n_panels, lambda y: _NODES_PER_PANEL)


def _log_sum(log_terms: Array) -> Array:
    """ln sum_k exp(log_terms[:, k]), row-wise and overflow-free."""
    top = np.max(log_terms, axis=1)
    return top + np.log(np.sum(np.exp(log_terms - top[:, None]), axis=1))


def _log_closing_speed(one_minus_s: Array, s: Array, p: float) -> Array:
    """ln X = p ln(s^-2 - 1) for s < 1 (Eq. 74 inverted): closing crack, growing contact."""
    return p * (np.log(one_minus_s) + np.log1p(s) - 2.0 * np.log(s))


def _log_opening_speed(s_minus_1: Array, p: float) -> Array:
    """ln |X| = p ln(s^2 - 1) for s > 1 (Eq. 73 inverted): opening crack, shrinking contact."""
    return p * (np.log(s_minus_1) + np.log(2.0 + s_minus_1))


def _exponential_nodes(half: Array, rate: float) -> tuple[Array, Array]:
    """Nodes d = half exp(-y/rate) on (0, half] and ln of their weights w d/rate, (y, w) the tail rule in y.

    The distance variable of the quadrature of the drift condition (*) (module docstring) in the halves that
    end at the kink (rate 1 + p) or at the maximum of s (rate 1): sum exp(ln weight) g(d) = int_0^half g(d) dd
    for an integrand g that decays like e^-y in y.
    """
    y, w = _tail_rule()
    d = half * np.exp(-y / rate)
    return d, np.log(w * d / rate)


def _log_drift_integrals(
    beta: Array, arc_closing: Array, arc_opening: Array, s_min: Array, p: float
) -> tuple[Array, Array]:
    """(ln I_cl, ln I_op) for s = s_min + 2 beta sin^2(phi/2), phi = theta + pi/2 in (0, pi).

    ``arc_closing`` = theta0 + pi/2 is the closing arc (s < 1), ``arc_opening`` = pi - arc_closing
    the opening one (both passed, each accurate when small). Along phi, s - 1 = 2 beta
    sin((phi + l)/2) sin((phi - l)/2) with l the closing arc; each half-interval evaluates it from
    its own end so that no difference of nearby numbers is formed. Variables (module docstring):

    * halves ending at the kink: d = L exp(-y/(1 + p)), so that X d ~ d^(p+1) decays like e^-y;
    * half ending at the maximum of s: d = L exp(-y) (X is smooth there, X d ~ e^-y);
    * half ending at the minimum of s: s = s_min cosh^2 u exactly, i.e. d = 2 arcsin(c sinh u),
      c = sqrt(s_min/(2 beta)); X dd/du ~ cosh(u)^(1-4p) is a bell of width ~ (4p)^-1/2 followed by
      an exponential tail, rescaled as v = sqrt(4p) u and cut where the tail is below e^-40.
    """
    beta, arc, arc_op, s_min = beta[:, None], arc_closing[:, None], arc_opening[:, None], s_min[:, None]

    # closing half next to the kink: phi = l - d
    d, log_wd = _exponential_nodes(0.5 * arc, 1.0 + p)
    one_minus_s = 2.0 * beta * np.sin(arc - 0.5 * d) * np.sin(0.5 * d)
    closing_kink = _log_sum(_log_closing_speed(one_minus_s, 1.0 - one_minus_s, p) + log_wd)
    # opening half next to the kink: phi = l + d
    d, log_wd = _exponential_nodes(0.5 * arc_op, 1.0 + p)
    opening_kink = _log_sum(_log_opening_speed(2.0 * beta * np.sin(arc + 0.5 * d) * np.sin(0.5 * d), p) + log_wd)
    # opening half next to the maximum of s: phi = pi - d
    d, log_wd = _exponential_nodes(0.5 * arc_op, 1.0)
    top = _log_sum(_log_opening_speed(2.0 * beta * np.cos(0.5 * (arc - d)) * np.sin(0.5 * (arc_op - d)), p) + log_wd)

    # closing half next to the minimum of s: phi = d = 2 arcsin(c sinh u)
    c = np.sqrt(0.5 * s_min[:, 0] / beta[:, 0])
    u_end = np.arcsinh(np.sin(0.25 * arc[:, 0]) / c)
    tail_rate = 4.0 * p - 1.0
    if tail_rate > _MIN_TAIL_RATE:
        u_end = np.minimum(u_end, (_Y_TAIL + tail_rate * math.log(2.0)) / tail_rate)
    stretch = math.sqrt(max(1.0, 4.0 * p))
    panels = np.ceil(stretch * u_end / _PANEL_WIDTH)
    v, wv = _uniform_rule(int(panels.max()))
    du = (0.5 * u_end / panels)[:, None]  # the rule's panels have width 2; each element's own are u_end/panels
    active = v[None, :] < (panels * _PANEL_WIDTH)[:, None]
    u = np.where(active, du * v, 0.0)  # nodes past an element's own range are evaluated at u = 0 and dropped
    c = c[:, None]
    sin_half_d = np.minimum(1.0, c * np.sinh(u))
    d = 2.0 * np.arcsin(sin_half_d)
    one_minus_s = 2.0 * beta * np.sin(0.5 * (arc + d)) * np.sin(0.5 * (arc - d))
    s = s_min * np.cosh(u) ** 2
    log_jacobian = np.log(2.0 * c * np.cosh(u) / np.sqrt((1.0 - sin_half_d) * (1.0 + sin_half_d)))
    log_weight = np.log(wv * du)
    terms = _log_closing_speed(one_minus_s, s, p) + log_jacobian + log_weight
    bottom = _log_sum(np.where(active, terms, -np.inf))

    return np.logaddexp(closing_kink, bottom), np.logaddexp(opening_kink, top)


# --- The drift-free cycle ------------------------------------------------------------------


class FrozenRadiusCycle(NamedTuple):
    """The periodic state of the frozen contact radius for s = alpha + beta sin tau."""

    alpha: Array  # alpha*(beta) = mean of sqrt(w/w0); w_eff/w0 = alpha^2 (Eq. 18)
    Abar: Array  # omega A/v0: half peak-to-peak of int X d tau (Eq. 45 with the exact a(t))
    sqrt_w_min: Array  # alpha - beta: minimum of sqrt(w/w0) over the cycle (> 0: contact kept)


def _kink_arc_unknown(arc: Array, beta: Array, p: float) -> tuple[Array, Array, Array]:
    """beta < 1/4: the closing arc l in (0, pi) is the unknown; s_min = 1 - 2 beta sin^2(l/2) >= 1/2."""
    s_min = 1.0 - 2.0 * beta * np.sin(0.5 * arc) ** 2
    log_cl, log_op = _log_drift_integrals(beta, arc, np.pi - arc, s_min, p)
    return log_cl - log_op, log_op, 1.0 + beta * np.cos(arc)


def _floor_unknown(log_s_min: Array, beta: Array, p: float) -> tuple[Array, Array, Array]:
    """beta >= 1/4: v = ln(alpha - beta) is the unknown.

    The arcs follow from 2 beta sin^2(l_cl/2) = 1 - s_min and 2 beta sin^2(l_op/2) = s_max - 1 =
    (2 beta - 1) + s_min, each accurate when small.
    """
    s_min = np.exp(log_s_min)
    arc_cl = 2.0 * np.arcsin(np.sqrt(np.minimum(1.0, -np.expm1(log_s_min) / (2.0 * beta))))
    arc_op = 2.0 * np.arcsin(np.sqrt(np.minimum(1.0, ((2.0 * beta - 1.0) + s_min) / (2.0 * beta))))
    log_cl, log_op = _log_drift_integrals(beta, arc_cl, arc_op, s_min, p)
    return log_cl - log_op, log_op, beta + s_min


_Unknown = Callable[[Array, Array, float], tuple[Array, Array, Array]]


def _solve(unknown: _Unknown, lo: Array, hi: Array, beta: Array, p: float) -> tuple[Array, Array, Array]:
    """Root of ln I_cl - ln I_op (monotone in the unknown) by Chandrupatla's bracketed method.

    ``unknown(x, beta, p)`` returns (ln I_cl - ln I_op, ln I_op, alpha); returns (x, alpha, ln Abar) at the root.
    """
    res = elementwise.find_root(lambda x, b: unknown(x, b, p)[0], (lo, hi), args=(beta,))
    if not np.all(res.success):
        bad = beta[~res.success]
        raise NoRootError(
            f"drift condition: bracketed root search failed for beta = {bad[:5]} "
            f"(status {res.status[~res.success][:5]})"
        )
    _, log_op, alpha = unknown(res.x, beta, p)
    return res.x, alpha, log_op


def frozen_radius_cycle(beta: ArrayLike, law: GentSchultz) -> FrozenRadiusCycle:
    """alpha*(beta), Abar and min sqrt(w/w0) of the drift-free cycle, Eq. (*) of the module docstring.

    Vectorised over ``beta`` >= 0 (any shape). beta = 0 gives alpha = 1 and Abar = 0 exactly.
    Raises :class:`NoSteadyStateError` when no root with alpha > beta exists (possible for n > 4
    only); for n <= 4 a root below ``alpha - beta = 1e-280`` is returned as alpha = beta, which is
    that root rounded to double precision.
    """
    if not isinstance(law, GentSchultz):
        raise TypeError("the drift integrals are written for the Gent–Schultz law (Eqs. 73–75)")
    beta = np.asarray(beta, dtype=float)
    if np.any(~np.isfinite(beta)) or np.any(beta < 0):
        raise ValueError("beta must be finite and non-negative")
    p = 1.0 / law.n
    flat = beta.ravel()
    alpha, log_Abar, s_min = np.ones_like(flat), np.full_like(flat, -np.inf), np.ones_like(flat)

    small = (flat > 0) & (flat < _BETA_SPLIT)
    if np.any(small):
        b = flat[small]
        arc, alpha[small], log_Abar[small] = _solve(
            _kink_arc_unknown, np.full_like(b, _ARC_FLOOR), np.full_like(b, np.pi - _ARC_FLOOR), b, p
        )
        s_min[small] = 1.0 - 2.0 * b * np.sin(0.5 * arc) ** 2

    large = flat >= _BETA_SPLIT
    if np.any(large):
        b = flat[large]
        # upper end: closing arc _ARC_FLOOR, or 1 - s_min = 1/2 if that arc is shorter (beta > 1e12)
        hi = np.log1p(-np.minimum(0.5, 2.0 * b * np.sin(0.5 * _ARC_FLOOR) ** 2))
        lo = np.full_like(b, math.log(_S_MIN_FLOOR))
        narrow = b < 0.5  # s_min > 1 - 2 beta: start where the opening arc is _ARC_FLOOR
        lo[narrow] = np.log1p(-2.0 * b[narrow] * np.cos(0.5 * _ARC_FLOOR) ** 2)
        excess_lo, log_op_lo, _ = _floor_unknown(lo, b, p)
        below_floor = excess_lo <= 0
        if np.any(below_floor) and law.n > _N_EXISTENCE:
            raise NoSteadyStateError(
                f"Gent–Schultz n = {law.n} > 4: no drift-free cycle with sqrt(w/w0) > 0 "
                f"for beta = {b[below_floor][:5]}"
            )
        idx = np.flatnonzero(large)
        inside = ~below_floor
        if np.any(inside):
            v, alpha[idx[inside]], log_Abar[idx[inside]] = _solve(_floor_unknown, lo[inside], hi[inside], b[inside], p)
            s_min[idx[inside]] = np.exp(v)
        # n <= 4 and alpha* - beta < 1e-280: alpha* = beta to double precision; I_op at the floor
        alpha[idx[below_floor]] = b[below_floor]
        log_Abar[idx[below_floor]] = log_op_lo[below_floor]
        s_min[idx[below_floor]] = 0.0

    if np.any(log_Abar > _LOG_MAX_DOUBLE):
        too_large = flat[log_Abar > _LOG_MAX_DOUBLE][:5]
        raise OverflowError(f"Abar exceeds the double range for beta = {too_large} (n = {law.n})")
    shape = beta.shape
    return FrozenRadiusCycle(alpha.reshape(shape), np.exp(log_Abar).reshape(shape), s_min.reshape(shape))


def alpha_star(beta: ArrayLike, law: GentSchultz) -> Array:
    """alpha*(beta): the mean of sqrt(w/w0) that cancels the drift of the frozen radius, Eq. (*)."""
    return frozen_radius_cycle(beta, law).alpha


#: Gauss-Legendre nodes in phi on (0, pi) for a cycle that stays on one branch (s > 1 or s < 1 throughout).
_ONE_BRANCH_NODES = 96


@cache
def _one_branch_rule() -> tuple[Array, Array]:
    """Gauss-Legendre nodes phi on (0, pi) and weights summing to 2 (:func:`mean_front_speed`, one branch)."""
    x, w = np.polynomial.legendre.leggauss(_ONE_BRANCH_NODES)
    return 0.5 * np.pi * (x + 1.0), w


def mean_front_speed(alpha: ArrayLike, beta: ArrayLike, law: GentSchultz) -> Array:
    """G(alpha, beta) = (1/2pi) int_0^2pi X(alpha + beta sin tau) d tau: the drift of the frozen radius, Eq. (*).

    The period mean of the signed front speed x = (da/dt)/v0 (Eq. 6 inverted, Eqs. 73-74) at a radius frozen
    at abar_m, with s = alpha + beta sin tau (Eq. 5 exact); zero on the drift-free cycle alpha = alpha*(beta),
    negative (opening, a shrinking contact) above it. By the symmetry of sin about pi/2 the mean is that over
    theta in (-pi/2, pi/2): G = (I_cl - I_op)/pi with the integrals of the quadrature of (*) (module docstring),
    with the closing arc l_cl = 2 arcsin sqrt((1 - s_min)/(2 beta)) and the opening one l_op = 2 arcsin
    sqrt((s_max - 1)/(2 beta)), s_min = alpha - beta, s_max = alpha + beta (each accurate when small). A cycle
    on one branch (s_min >= 1 or s_max <= 1) is integrated by Gauss-Legendre in phi = theta + pi/2 (accurate
    while s stays away from 0). Vectorised over alpha > beta >= 0 (broadcast); alpha <= beta (s reaches 0,
    w = 0 within the period: no contact) is NaN.
    """
    alpha, beta = (np.asarray(v, dtype=float) for v in np.broadcast_arrays(alpha, beta))
    shape, alpha, beta = alpha.shape, alpha.ravel(), beta.ravel()
    p, g = 1.0 / law.n, np.full(alpha.shape, np.nan)
    s_min, s_max = alpha - beta, alpha + beta
    mixed = (s_min > 0) & (s_min < 1) & (s_max > 1)
    if np.any(mixed):
        b, lo, hi = beta[mixed], s_min[mixed], s_max[mixed]
        arc_cl = 2.0 * np.arcsin(np.sqrt(np.minimum(1.0, (1.0 - lo) / (2.0 * b))))
        arc_op = 2.0 * np.arcsin(np.sqrt(np.minimum(1.0, (hi - 1.0) / (2.0 * b))))
        log_cl, log_op = _log_drift_integrals(b, arc_cl, arc_op, lo, p)
        g[mixed] = (np.exp(log_cl) - np.exp(log_op)) / np.pi
    one_branch = (s_min > 0) & ~mixed
    if np.any(one_branch):
        phi, w = _one_branch_rule()
        s = s_min[one_branch, None] + 2.0 * beta[one_branch, None] * np.sin(0.5 * phi) ** 2
        speed = np.where(s > 1.0, -np.abs(s * s - 1.0) ** p, np.abs(1.0 / (s * s) - 1.0) ** p)
        g[one_branch] = 0.5 * speed @ w
    return g.reshape(shape)

