"""J-integrals of Eqs. (28), (29), (36) for the Gent–Schultz law (vibroadhesion.core.integrals).

Every expected number comes from an independent reference:

* ``mpmath_reference.j_integrals_mp``: 30-digit mpmath quadrature of the definitions (stored for the points of
  :func:`stored_points`, tests/reference/j_integrals_mpmath.csv, a sample recomputed here);
* a second, 45-digit mpmath evaluation written here in a different variable (the folded form
  over t in (0, pi/2), with its own breakpoints) that checks the 30-digit reference itself;
* closed forms: the limits J(0) = (1, 0, 1), rigorous bounds on the large-Abar remainders,
  mpmath quadrature of the cos-power integrals behind the Gamma-function constants, and the
  next (u^3) Taylor coefficient of the integrands for the small-Abar remainder.
"""

from __future__ import annotations

import math
import warnings

import mpmath as mp
import numpy as np
import pytest
import mpmath_reference
from conftest import N_PUBLISHED
from mpmath_reference import j_integrals_mp

from vibroadhesion.core.integrals import (
    abar_for_abs_jc1,
    folded_rule,
    gent_schultz_u,
    j_integrals,
    j_integrals_for_law,
    j_integrals_general,
    j_integrals_large_Abar,
    j_integrals_small_Abar,
    jc1_log_slope,
)
from vibroadhesion.core.ratelaw import GentSchultz

N_VALUES = [0.05, 0.1, 0.25, N_PUBLISHED, 1.0, 1.5, 2.0, 3.0, 4.0]
FIXED_ABAR = [0.0, 1e-12, 1e-8, 1e-4, 0.01, 0.3, 1.0, 1.5708, 2.0, 7.0, 30.0, 100.0, 1e3, 1e4, 1e5, 1e6, 1e8,
              1e10, 1e12]
#: three log-uniform points in [1e-3, 1e10] from a fixed seed (a fresh generator per n keeps the grid per n fixed)
N_RANDOM = 3
RANDOM_SEED = 20240611

REL_TOL = 1e-12  # brief: 1e-12 relative (absolute where the reference is 0)


def _abar_grid(n: float) -> np.ndarray:
    rng = np.random.default_rng([RANDOM_SEED, int(round(1000 * n))])
    random_abar = 10.0 ** rng.uniform(-3.0, 10.0, size=N_RANDOM)
    return np.concatenate([np.array(FIXED_ABAR), random_abar])


def _errors(value: float, reference: mp.mpf) -> float:
    """Relative error, or absolute where the reference is exactly 0."""
    if reference == 0:
        return abs(value)
    return float(abs((mp.mpf(value) - reference) / reference))


# ----------------------------------------------------------------------------- accuracy vs mpmath


@pytest.mark.parametrize("n", N_VALUES)
def test_j_integrals_match_mpmath_30_digits_to_1e12(n: float) -> None:
    """Reference: 30-digit mpmath quadrature of Eqs. (28), (29), (36); tolerance 1e-12 relative."""
    Abar = _abar_grid(n)
    values = j_integrals(Abar, n)  # one batched call per n
    worst = {name: (0.0, None) for name in ("J0", "Jc1", "J1")}
    for i, a in enumerate(Abar):
        ref = j_integrals_mp(float(a), n)
        for k, name in enumerate(("J0", "Jc1", "J1")):
            err = _errors(float(values[k][i]), ref[k])
            if err > worst[name][0]:
                worst[name] = (err, float(a))
    print(f"n={n}: " + ", ".join(f"max err {k} = {e:.2e} at Abar={a}" for k, (e, a) in worst.items()))
    max_err = max(e for e, _ in worst.values())
    assert max_err < REL_TOL, f"n={n}: max error {max_err:.3e} > {REL_TOL:g}; per integral: {worst}"


def _j_integrals_folded_mp(Abar: float, n: float, dps: int) -> tuple[mp.mpf, mp.mpf, mp.mpf]:
    """Eqs. (28), (29), (36) folded onto t = pi/2 - x in (0, pi/2), in mpmath at ``dps`` digits.

    J0 = 1/pi int (g(v) + g(-v)) dt, Jc1 = 2/pi int (g(v) - g(-v)) sin t dt,
    J1 = 2/pi int (g(v) + g(-v)) cos^2 t dt, v = Abar sin t, g = sqrt(f) with f of Eq. (75).
    g is evaluated from f directly (not from the simplified S, D); the cancellation in
    g(v) - g(-v) is paid for with guard digits. Breakpoints at t = 10^k / Abar (boundary layer).
    """
    guard = 15 + (int(n * -math.log10(Abar)) + 1 if 0 < Abar < 1 else 0)
    with mp.workdps(dps + guard):
        a, nn = mp.mpf(Abar), mp.mpf(n)

        def f(s):
            f_op = 1 + abs(s) ** nn
            return f_op if s < 0 else 1 / f_op

        def even(t):
            v = a * mp.sin(t)
            return mp.sqrt(f(v)) + mp.sqrt(f(-v))

        def odd(t):
            v = a * mp.sin(t)
            return mp.sqrt(f(v)) - mp.sqrt(f(-v))

        points = [mp.mpf(0)]
        if a > 1:
            s = 1 / a
            while s < mp.pi / 4:
                points.append(s)
                s *= 10
        points.append(mp.pi / 2)
        j0 = mp.quad(even, points) / mp.pi
        jc1 = 2 * mp.quad(lambda t: odd(t) * mp.sin(t), points) / mp.pi
        j1 = 2 * mp.quad(lambda t: even(t) * mp.cos(t) ** 2, points) / mp.pi
        return +j0, +jc1, +j1


@pytest.mark.parametrize("Abar, n", [(1e-8, N_PUBLISHED), (1.5708, 0.05), (1e3, 4.0), (1e6, 1.0)])
def test_mpmath_reference_matches_folded_mpmath_45_digits_to_1e25(Abar: float, n: float) -> None:
    """Reference of the reference: the 30-digit values agree with an independent 45-digit evaluation."""
    ref30 = j_integrals_mp(Abar, n)
    ref45 = _j_integrals_folded_mp(Abar, n, dps=45)
    with mp.workdps(50):
        errs = [abs((r30 - r45) / r45) for r30, r45 in zip(ref30, ref45)]
    assert max(errs) < mp.mpf("1e-25"), f"relative differences {[mp.nstr(e, 3) for e in errs]}"


# ----------------------------------------------------------------------------- shapes


def _reordered_sum_bound(n_terms: int, elementwise_ulps: float) -> float:
    """Relative bound on the difference of two evaluations of a one-signed sum in different orders.

    Each evaluation of sum_k x_k (x_k all of one sign, so sum |x_k| = |sum x_k|) in any order
    has |fl(sum) - sum| <= gamma_{N-1} sum |x_k|, gamma_k = k u / (1 - k u), u = 2^-53 (Higham,
    *Accuracy and Stability of Numerical Algorithms*, 2nd ed., Eq. 4.4); the terms themselves
    may come from different element-wise kernels (SIMD or scalar exp, sqrt, ...), each within
    ``elementwise_ulps`` u relatively. Two evaluations therefore differ by at most
    2 (gamma_{N-1} + elementwise_ulps u) |sum|.
    """
    u = np.finfo(float).eps / 2
    gamma = (n_terms - 1) * u / (1 - (n_terms - 1) * u)
    return 2 * (gamma + elementwise_ulps * u)


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 4.0])
def test_shapes_scalar_0d_1d_2d_agree_with_1d_call(n: float) -> None:
    """Reference: the 1-d call. Same flat input -> bitwise equal; other batch sizes -> within the
    rounding bound of the rule's summation.

    Rows are reduced by a BLAS matrix product whose summation order (and, on some CPUs, whose
    kernel) depends on the batch size, so a scalar and the same value inside a batch may differ
    in the last digits. Every term of each sum has one sign (S > 0 with positive weights for J0
    and J1; -u r with positive weights for Jc1), so the difference is bounded relatively by
    ``_reordered_sum_bound``: N = 2 x 72 products (r @ w_r + u @ w_ur), element-wise terms
    within 7 u each (the power Abar^n <= 4 ulp in numpy's SIMD kernels, then the product with
    (sin t)^n, +1, sqrt, reciprocal, product and the weight product, each correctly rounded).
    That is 3.3e-14 relative. Reshaping the same batch changes
    nothing (the same flat array is reduced).
    """
    bound = _reordered_sum_bound(2 * len(folded_rule()[0]), elementwise_ulps=7.0)
    vec = np.array([0.0, 1e-300, 1e-3, 0.7, 3.0, 41.0, 1e5, 1e12])
    ref = j_integrals(vec, n)
    assert all(r.shape == vec.shape for r in ref)

    two_d = j_integrals(vec.reshape(2, 4), n)
    for k in range(3):
        assert two_d[k].shape == (2, 4)
        np.testing.assert_array_equal(two_d[k].ravel(), ref[k])

    for i, a in enumerate(vec):
        scalar = j_integrals(float(a), n)
        zero_d = j_integrals(np.array(a), n)
        one = j_integrals(np.array([a]), n)
        for k in range(3):
            assert np.shape(scalar[k]) == () and np.shape(zero_d[k]) == () and one[k].shape == (1,)
            assert scalar[k] == zero_d[k] == one[k][0]  # identical computation
            assert abs(scalar[k] - ref[k][i]) <= bound * abs(ref[k][i]), (a, k, scalar[k], ref[k][i], bound)


def test_abar_zero_gives_exactly_one_zero_one() -> None:
    """Closed form: at Abar = 0, f = 1 and J0 = 1/pi int_0^pi 1 = 1, Jc1 = 0, J1 = 2/pi int sin^2 = 1 (exactly).

    The limits J0(0) = J1(0) = 1 are what Eqs. (71), (99), (123) rely on (no vibration, no
    amplification: P_cr / P_cr^JKR = J0(0)^2 = 1, abar_m = 1).
    """
    got = {n: tuple(float(x) for x in j_integrals(0.0, n)) for n in (0.05, N_PUBLISHED, 1.0, 4.0)}
    wrong = {n: (j0 - 1, jc1, j1 - 1) for n, (j0, jc1, j1) in got.items() if (j0, jc1, j1) != (1.0, 0.0, 1.0)}
    assert not wrong, f"J(0) - (1, 0, 1) per n: {wrong}"


#: The probes of the rule's hardest region (n = 4, Abar ~ 2).
NEAR_2 = [1.7, 1.9, 1.95, 2.1, 2.15]


@pytest.mark.parametrize("n", [4.0])
def test_documented_1e12_accuracy_holds_near_abar_2(n: float) -> None:
    """Reference: 30-digit mpmath. The module docstring of ``integrals`` promises relative error
    below 1e-13 for Abar in [0, 1e12] and n in [0.05, 4]; probe the hardest region found (n = 4,
    Abar ~ 2, where the integrand's analyticity strip |Im y| < pi/n is narrowest).
    """
    Abar = np.array(NEAR_2)
    values = j_integrals(Abar, n)
    errs = [max(_errors(float(values[k][i]), j_integrals_mp(float(a), n)[k]) for k in range(3))
            for i, a in enumerate(Abar)]
    assert max(errs) < 1e-12, f"n={n}: max relative error {max(errs):.3e} at Abar={Abar[int(np.argmax(errs))]}"


#: Hard cases against mpmath: the ends of the validated n range, Abar from tiny to the top of the rule's
#: range, and (n = 4) the region of the rule's largest error, Abar ~ 50-250 (module docstring).
HARD_CASES = [(0.05, a) for a in (1e-300, 1e-12, 1e-3, 1.0, 1e3, 1e12, 1e100)] + [
    (4.0, a) for a in (1e-12, 1e-3, 1.0, 50.0, 75.0, 114.27, 150.0, 250.0, 1e4, 1e12, 1e70)]


@pytest.mark.parametrize("n, Abar", HARD_CASES)
def test_hard_cases_match_mpmath_to_1e12(n: float, Abar: float) -> None:
    """Reference: 30-digit mpmath; 1e-12 relative (the brief's bound; the rule's stated bound is 1e-13).

    n = 0.05: the kink t^n is sharpest; n = 4: the boundary layer is sharpest, and at Abar = 1e70
    Abar^n = e^645 is near the rule's overflow limit e^690; Abar = 1e-300 tests the small end.
    """
    values = j_integrals(Abar, n)
    ref = j_integrals_mp(Abar, n)
    errs = [_errors(float(values[k]), ref[k]) for k in range(3)]
    assert max(errs) < REL_TOL, f"n={n}, Abar={Abar}: relative errors {errs}"


def stored_points() -> list[tuple[float, float]]:
    """(n, Abar) of the stored 30-digit references (tests/reference/j_integrals_mpmath.csv): the grid of each n, the
    hard cases and the probes near Abar = 2, each once, in that order."""
    grid = [(n, float(a)) for n in N_VALUES for a in _abar_grid(n)]
    return list(dict.fromkeys([*grid, *((float(n), float(a)) for n, a in HARD_CASES), *((4.0, a) for a in NEAR_2)]))


def test_stored_reference_is_the_mpmath_quadrature() -> None:
    """The stored table holds exactly :func:`stored_points`, and a sample of its rows equals a fresh 30-digit
    quadrature to 1e-25 relative (it keeps 45 digits of it): each n at Abar = 1e-12 (Jc1's cancellation) and 30 (the
    boundary layer), and n = 4 at Abar = 1e12 (the large-Abar end; 4 s in all, the whole table 75 s)."""
    stored = mpmath_reference._stored()
    assert list(stored) == stored_points()
    sample = [(n, a) for n in N_VALUES for a in (1e-12, 30.0)] + [(4.0, 1e12)]
    for n, a in sample:
        fresh = mpmath_reference.j_integrals_mp_computed(a, n)
        with mp.workdps(40):
            assert all(abs(stored[n, a][k] - fresh[k]) <= mp.mpf("1e-25") * abs(fresh[k]) for k in range(3)), (n, a)


def _reference_rule() -> tuple[np.ndarray, np.ndarray]:
    """Nodes t and weights of int_0^(pi/2) dt: composite Gauss–Legendre, 30 nodes on each of the
    120 panels of width 1/2 in y = -ln(2t/pi) over [0, 60] (3600 nodes), written here apart from
    the package's rule (a different variable and node family).

    In y the integrand is analytic in the strip |Im y| < pi/(2n) around the layer (the zeros of
    1 + u); for n = 4 a panel of half-width 1/4 sees a Bernstein ellipse of rho >= 6, so the
    truncation error is below rho^-60 ~ 1e-46 per panel; the cut at y = 60 drops t < 1.4e-26,
    a share below 1e-26 of each integral. What remains is rounding.
    """
    x, w = np.polynomial.legendre.leggauss(30)
    edges = np.arange(0.0, 60.25, 0.5)
    y = (0.25 * x[None, :] + 0.5 * (edges[:-1] + edges[1:])[:, None]).ravel()
    t = 0.5 * np.pi * np.exp(-y)
    return t, np.tile(0.25 * w, len(edges) - 1) * t


def _j_integrals_reference_rule(Abar: np.ndarray, n: float) -> np.ndarray:
    """(J0, Jc1, J1) per row on the reference rule, from S = (2 + u)/sqrt(1 + u), D = -u/sqrt(1 + u)."""
    t, w = _reference_rule()
    u = np.multiply.outer(Abar, np.sin(t)) ** n
    s_even, d_odd = (2.0 + u) / np.sqrt(1.0 + u), -u / np.sqrt(1.0 + u)
    return np.stack([s_even @ w / np.pi, 2 / np.pi * d_odd @ (w * np.sin(t)), 2 / np.pi * s_even @ (w * np.cos(t) ** 2)],
                    axis=1)


@pytest.mark.parametrize("n, Abar", [(4.0, 114.27), (4.0, 2.0), (0.05, 1e-3), (0.05, 1e10), (N_PUBLISHED, 1e-12)])
def test_reference_rule_matches_mpmath_to_1e14(n: float, Abar: float) -> None:
    """Reference of the scan below: the 3600-node rule agrees with 30-digit mpmath to 1e-14 relative,
    a tenth of the 1e-13 it is used to check (its own error is rounding, ``_reference_rule``).
    """
    got = _j_integrals_reference_rule(np.array([Abar]), n)[0]
    ref = j_integrals_mp(Abar, n)
    errs = [_errors(float(got[k]), ref[k]) for k in range(3)]
    assert max(errs) < 1e-14, errs


@pytest.mark.parametrize("n", [0.05, 0.25, N_PUBLISHED, 1.0, 2.0, 3.0, 3.5, 3.9, 4.0])
def test_rule_within_stated_1e13_bound_on_dense_scan(n: float) -> None:
    """Reference: the 3600-node rule (checked against mpmath above). The module docstring states
    1e-13 relative for Abar up to the overflow limit n ln Abar <= 690 and n in [0.05, 4]; scan
    1201 log-spaced Abar from 1e-12 to that limit (at most 1e300).
    """
    top = min(300.0, 690.0 / n / math.log(10.0) - 0.01)
    Abar = np.logspace(-12.0, top, 1201)
    got = np.stack(j_integrals(Abar, n), axis=1)
    rel = np.max(np.abs(got / _j_integrals_reference_rule(Abar, n) - 1.0), axis=1)
    assert rel.max() < 1e-13, f"n={n}: max relative error {rel.max():.3e} at Abar={Abar[np.argmax(rel)]:.4g}"


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 4.0])
def test_node_powers_match_mpmath_to_rounding(n: float) -> None:
    """Reference: (Abar sin t_k)^n in 40-digit mpmath at the rule's (double) nodes t_k.

    Abar^n (sin t_k)^n: each power within 4 ulp (numpy's SIMD kernels), sin t_k within 1 ulp,
    which the power raises to n ulp, and the product correctly rounded: (8.5 + n) u relative.
    """
    t = folded_rule()[0]
    Abar = np.array([1e-60, 1e-3, 114.27, 1e12])  # u a normal double (> 1e-300) at every node
    got = gent_schultz_u(Abar, n)
    bound = (8.5 + n) * np.finfo(float).eps / 2
    with mp.workdps(40):
        for i, a in enumerate(Abar):
            for k in range(0, t.size, 7):
                ref = (mp.mpf(float(a)) * mp.sin(mp.mpf(float(t[k])))) ** mp.mpf(n)
                assert abs(mp.mpf(float(got[i, k])) / ref - 1) < bound, (a, k, float(got[i, k]), ref)


def test_abar_power_beyond_the_overflow_limit_raises_value_error() -> None:
    """n ln Abar <= 690 is the rule's range (module docstring): 4 ln(1e75) = 691 is refused, 1e74 (682) is not."""
    with pytest.raises(ValueError, match="overflows"):
        j_integrals(np.array([1.0, 1e75]), 4.0)
    assert np.all(np.isfinite(j_integrals(1e74, 4.0)))


# ----------------------------------------------------------------------------- general rule


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 1.0, 2.0, 4.0])
def test_general_rule_matches_gent_schultz_fast_path_to_1e12(n: float) -> None:
    """Reference: the cancellation-free fast path (itself checked against mpmath above), 1e-12 relative.

    Jc1 of the general rule is a difference of sqrt(f) at +-v, so only |Jc1| > 1e-3 is compared.
    """
    Abar = np.logspace(-6, 12, 145)
    fast = j_integrals(Abar, n)
    general = j_integrals_general(Abar, GentSchultz(n))
    dispatched = j_integrals_for_law(Abar, GentSchultz(n))
    for k in range(3):
        np.testing.assert_array_equal(dispatched[k], fast[k])
    for k in (0, 2):
        err = np.max(np.abs(general[k] / fast[k] - 1))
        assert err < 1e-12, f"k={k}: {err:.3e}"
    mask = np.abs(fast[1]) > 1e-3
    assert mask.sum() > 20
    err = np.max(np.abs(general[1][mask] / fast[1][mask] - 1))
    assert err < 1e-12, f"Jc1: {err:.3e}"


# ----------------------------------------------------------------------------- large Abar


def _cos_power_mp(p: float) -> mp.mpf:
    return mp.quad(lambda x: mp.cos(x) ** p, [0, mp.pi / 2])


def _sin2_cos_power_mp(p: float) -> mp.mpf:
    return mp.quad(lambda x: mp.sin(x) ** 2 * mp.cos(x) ** p, [0, mp.pi / 2])


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 1.0, 2.0, 4.0])
def test_large_Abar_constants_match_mpmath_quad_of_cos_powers(n: float) -> None:
    """Reference: mpmath quad of int_0^{pi/2} cos^{n/2}, cos^{n/2+1}, sin^2 cos^{n/2} (30 digits); 1e-14 relative.

    Asymptotes (only the opening half counts, sqrt(1+u) ~ u^{1/2}): J0 ~ A^{n/2}/pi int cos^{n/2},
    Jc1 ~ -2 A^{n/2}/pi int cos^{n/2+1}, J1 ~ 2 A^{n/2}/pi int sin^2 cos^{n/2}; evaluated at A = 1.
    """
    with mp.workdps(30):
        p = mp.mpf(n) / 2
        expected = (_cos_power_mp(p) / mp.pi, -2 * _cos_power_mp(p + 1) / mp.pi, 2 * _sin2_cos_power_mp(p) / mp.pi)
    got = j_integrals_large_Abar(1.0, n)
    for g, e in zip(got, expected):
        assert abs(float(g) / float(e) - 1) < 1e-14, (float(g), float(e))


def _large_Abar_asymptotes_mp(Abar: float, n: float) -> tuple[mp.mpf, mp.mpf, mp.mpf]:
    """The leading large-Abar asymptotes evaluated in mpmath (constants by quad of the cos powers)."""
    p = mp.mpf(n) / 2
    scale = mp.mpf(Abar) ** p
    return (scale * _cos_power_mp(p) / mp.pi, -2 * scale * _cos_power_mp(p + 1) / mp.pi,
            2 * scale * _sin2_cos_power_mp(p) / mp.pi)


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 1.0, 2.0, 4.0])
def test_large_Abar_remainders_within_rigorous_bounds(n: float) -> None:
    """Closed-form bounds: 0 < J0 - J0~ < 1, 0 < Jc1 - Jc1~ < 1/pi, 0 < J1 - J1~ < 1 for every Abar > 0.

    (The remainder integrands are 1/sqrt(1+u) on the closing half and sqrt(1+u) - sqrt(u) on the
    opening half, both in (0, 1]; for Jc1 their weighted difference is at most 0.3 of cos x.)
    Checked in mpmath (30-digit reference minus the asymptote evaluated in mpmath) at a few
    points in [1, 1e12], and with the package on a dense grid, where a remainder < 1 is only
    resolvable up to the accuracy of J ~ Abar^{n/2} (allowance on each side: 1e-13 |J|, the
    documented relative accuracy of ``j_integrals``, verified against mpmath above).
    """
    bounds = (1.0, 1.0 / math.pi, 1.0)
    with mp.workdps(30):
        for a in (1.0, 1e3, 1e6, 1e12):
            ref = j_integrals_mp(a, n)
            asym = _large_Abar_asymptotes_mp(a, n)
            for k in range(3):
                rem = ref[k] - asym[k]
                assert 0 < rem < bounds[k], (a, k, rem)
    Abar = np.logspace(0, 12, 241)
    exact = j_integrals(Abar, n)
    asym = j_integrals_large_Abar(Abar, n)
    for k in range(3):
        rem = exact[k] - asym[k]
        slack = 1e-13 * np.abs(exact[k])
        assert np.all(rem > -slack) and np.all(rem < bounds[k] + slack), (k, rem.min(), rem.max())


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 1.0, 2.0, 4.0])
def test_large_Abar_asymptote_relative_error_vanishes(n: float) -> None:
    """Reference: 30-digit mpmath values. Relative error of the asymptote decreases with Abar
    (it is O(Abar^{-n/2}) by the bounds above) until it reaches double rounding (1e-15), and is
    < 1e-3 at Abar = 1e12 for n >= 1.
    """
    Abar = [1e2, 1e4, 1e6, 1e8, 1e10, 1e12]
    rel = np.empty((len(Abar), 3))
    for i, a in enumerate(Abar):
        ref = j_integrals_mp(a, n)
        asym = j_integrals_large_Abar(a, n)
        rel[i] = [abs(float(asym[k]) / float(ref[k]) - 1) for k in range(3)]
    assert np.all((np.diff(rel, axis=0) < 0) | (rel[1:] < 1e-15)), rel
    bound_rel = np.array([1.0 / float(j_integrals_mp(a, n)[0]) for a in Abar])  # J0 - J0~ < 1
    assert np.all(rel[:, 0] < bound_rel + 1e-15), (rel[:, 0], bound_rel)
    if n >= 1:
        assert np.all(rel[-1] < 1e-3), rel[-1]


# ----------------------------------------------------------------------------- small Abar


def _third_order_coefficients(n: float) -> tuple[mp.mpf, mp.mpf, mp.mpf]:
    """Coefficients of Abar^{3n}: S = 2 + u^2/4 - u^3/4 + ..., D = -u + u^2/2 - 3u^3/8 + ... (u = (A sin t)^n)."""
    p = 3 * mp.mpf(n)
    w = mp.quad(lambda t: mp.sin(t) ** p, [0, mp.pi / 2])
    w1 = mp.quad(lambda t: mp.sin(t) ** (p + 1), [0, mp.pi / 2])
    s2 = mp.quad(lambda t: mp.sin(t) ** p * mp.cos(t) ** 2, [0, mp.pi / 2])
    return -w / (4 * mp.pi), -3 * w1 / (4 * mp.pi), -s2 / (2 * mp.pi)


@pytest.mark.parametrize("n, decades", [(0.5, (-5, -2)), (1.0, (-4, -1)), (2.0, (-3.5, -0.5))])
def test_small_Abar_expansion_error_is_order_abar_3n(n: float, decades: tuple[float, float]) -> None:
    """Reference: 30-digit mpmath J. error / Abar^{3n} stays bounded as Abar decreases over 3 decades.

    Bound: 2 |c3| where c3 is the exact Abar^{3n} coefficient (u^3 Taylor terms of S and D,
    integrated by mpmath), plus the double rounding of the two-term value (4 ulp of |J|).
    Where the rounding is negligible the ratio must also approach c3 (within 35 %).
    """
    c3 = _third_order_coefficients(n)
    Abar = np.logspace(decades[1], decades[0], 7)
    for k in range(3):
        ratios = []
        for a in Abar:
            ref = j_integrals_mp(float(a), n)[k]
            approx = float(j_integrals_small_Abar(float(a), n)[k])
            err = abs(ref - mp.mpf(approx))
            scale = mp.mpf(float(a)) ** (3 * n)
            rounding = 4 * np.spacing(abs(approx))
            assert err <= 2 * abs(c3[k]) * scale + rounding, (k, a, err, scale, c3[k])
            if abs(c3[k]) * scale > 1e6 * rounding:
                ratios.append(float(err / scale))
        assert len(ratios) >= 2, (k, ratios)
        assert abs(ratios[-1] / abs(float(c3[k])) - 1) < 0.35, (k, ratios, float(c3[k]))


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 4.0])
def test_small_Abar_limits_are_one_zero_one(n: float) -> None:
    """Closed-form limit J -> (1, 0, 1) as Abar -> 0 (Eqs. 99, 123): |J - limit| <= C Abar^n, checked vs mpmath."""
    for a in (1e-4, 1e-8, 1e-12):
        ref = j_integrals_mp(a, n)
        bound = 2.0 * a**n  # |Jc1| <= (2/pi) Abar^n int sin^{n+1} < Abar^n; J0 - 1, J1 - 1 are O(Abar^{2n})
        assert abs(ref[0] - 1) < bound and abs(ref[1]) < bound and abs(ref[2] - 1) < bound
        got = j_integrals(a, n)
        assert abs(float(got[0]) - 1) < bound + 1e-13
        assert abs(float(got[1])) < bound
        assert abs(float(got[2]) - 1) < bound + 1e-13


# ----------------------------------------------------------------------------- monotonicity, robustness


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 4.0])
def test_j0_and_minus_jc1_strictly_increasing_as_proved(n: float) -> None:
    """Closed-form proof (dS/du, -dD/du > 0): J0 and -Jc1 strictly increase with Abar.

    Dense grid Abar in logspace(-12, 12, 4001). -Jc1 ~ Abar^n is resolvable everywhere; J0 - 1 ~
    Abar^{2n} falls below double resolution for small Abar and large n. Each computed J0 lies
    within the summation bound of ``_reordered_sum_bound`` of the rule's exact sum, so a step
    may go down by at most that bound; J0 must increase strictly wherever the expected step
    (J0 - 1)((grid ratio)^{2n} - 1), from J0 - 1 ~ Abar^{2n}, exceeds twice the bound.
    """
    Abar = np.logspace(-12, 12, 4001)
    j0, jc1, j1 = j_integrals(Abar, n)
    bound = _reordered_sum_bound(2 * len(folded_rule()[0]), elementwise_ulps=7.0)
    assert np.all(np.diff(-jc1) > 0), np.min(np.diff(-jc1))
    assert np.all(np.diff(j0) >= -bound * j0[:-1]), np.min(np.diff(j0))
    expected_step = (j0[:-1] - 1) * ((Abar[1] / Abar[0]) ** (2 * n) - 1)
    resolvable = expected_step > 2 * bound * j0[:-1]
    assert resolvable.sum() > 1000
    assert np.all(np.diff(j0)[resolvable] > 0)
    assert float(j_integrals(0.0, n)[2]) == 1.0  # J1(0) = 2/pi int_0^pi sin^2 = 1


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 1.0, 4.0])
def test_no_nan_no_warning_at_extreme_abar(n: float) -> None:
    """Abar in {0, 1e-300, 1e12}: finite results, no warning of any kind (closed-form limit at the tiny end)."""
    Abar = np.array([0.0, 1e-300, 1e12])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        values = j_integrals(Abar, n)
        singles = [j_integrals(float(a), n) for a in Abar]
        small = j_integrals_small_Abar(Abar, n)
        large = j_integrals_large_Abar(Abar, n)
        general = j_integrals_general(Abar, GentSchultz(n))
    for arr in (*values, *small, *large, *general, *(x for s in singles for x in s)):
        assert np.all(np.isfinite(arr))
    # 1e-300: u = Abar^n sin^n t underflows harmlessly, J = (1, 0, 1) to double precision (|Jc1| ~ Abar^n)
    assert abs(values[0][1] - 1) < 1e-14 and abs(values[2][1] - 1) < 1e-14
    assert -2.0 * 1e-300**n <= values[1][1] <= 0.0


@pytest.mark.parametrize("bad", [-1.0, -1e-300, float("nan"), float("inf")])
def test_negative_or_nan_abar_raises_value_error(bad: float) -> None:
    """Eqs. (28)-(36) are defined for Abar >= 0 (Abar is an amplitude); anything else is an input error."""
    with pytest.raises(ValueError):
        j_integrals(bad, N_PUBLISHED)
    with pytest.raises(ValueError):
        j_integrals(np.array([1.0, bad]), N_PUBLISHED)
    with pytest.raises(ValueError):
        j_integrals_general(bad, GentSchultz(N_PUBLISHED))


@pytest.mark.parametrize("bad_n", [0.0, -0.5, float("nan")])
def test_nonpositive_n_raises_value_error(bad_n: float) -> None:
    """The Gent–Schultz exponent must be positive (Eq. 73)."""
    with pytest.raises(ValueError):
        j_integrals(1.0, bad_n)
    with pytest.raises(ValueError):
        GentSchultz(bad_n)


# ----------------------------------------------------------------------------- the inverse of |Jc1|


def test_inverse_of_jc1_returns_the_stored_mpmath_abar() -> None:
    """abar_for_abs_jc1 at ln|Jc1| of every stored 30-digit reference with Jc1 != 0 (9 n from 0.05 to 4, Abar from
    1e-12 to 1e12 and the hard cases to 1e-300) returns its Abar: relative error below 2e-13/n + 1e-14 |ln Abar|, the
    rule's 1e-13 bound on |Jc1| divided by the least slope n/2 of ln|Jc1| in ln Abar, plus the 1e-14 + 4 eps |z|
    stop of Newton's method in z = ln Abar. All Abar of one n in one call."""
    by_n: dict[float, list[tuple[float, float]]] = {}
    for (n, a), (_, jc1, _) in mpmath_reference._stored().items():
        if jc1 != 0 and n * math.log(a) > math.log(1e-300):  # Abar^n representable
            by_n.setdefault(n, []).append((a, float(mp.log(-jc1))))
    assert sorted(by_n) == sorted(N_VALUES)
    for n, rows in by_n.items():
        abar = np.array([a for a, _ in rows])
        got = abar_for_abs_jc1(np.array([log_jc1 for _, log_jc1 in rows]), n, "stored")
        assert np.all(np.abs(got / abar - 1) <= 2e-13 / n + 1e-14 * np.abs(np.log(abar)) + 1e-14), n


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 4.0])
def test_jc1_log_slope_is_within_n_over_2_and_n_falling_and_the_derivative(n: float) -> None:
    """The slope of ln|Jc1| in ln Abar lies in (n/2, n] (to rounding) and falls with Abar (the concavity Newton's start relies
    on, proved in the docstring), over Abar from 1e-12 to 1e130 (or the overflow limit); ln|Jc1| is that of
    j_integrals; and the slope is the derivative: a central difference with step h = 1e-3 in ln Abar agrees to 1e-6
    (its error h^2/6 times the third derivative, at most n^3 in size, plus 1e-13/h of the rule's error)."""
    z = np.linspace(math.log(1e-12), min(600.0 / n, 300.0), 3001)
    log_jc1, slope = jc1_log_slope(np.exp(z), n)
    assert np.all((slope >= n / 2 * (1 - 1e-14)) & (slope <= n * (1 + 1e-14)))  # n/2 at the large end, rounded
    assert np.all(np.diff(slope) <= 1e-14 * n)
    h = 1e-3
    difference = (jc1_log_slope(np.exp(z + h), n)[0] - jc1_log_slope(np.exp(z - h), n)[0]) / (2 * h)
    assert np.max(np.abs(difference - slope)) < 1e-6
    assert np.allclose(log_jc1, np.log(-j_integrals(np.exp(z), n)[1]), rtol=0, atol=1e-14 * np.abs(log_jc1).max())
