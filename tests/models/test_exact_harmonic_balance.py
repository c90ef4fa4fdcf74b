"""Exact harmonic balance of the single-harmonic ansatz (vibroadhesion.models.exact_harmonic_balance).

Independent references:

* the means and first harmonics of Eqs. (4)–(5) along a = a_m + A sin tau' integrated directly over
  the period in mpmath (tanh-sinh, breakpoints at the reversals tau' = +-pi/2 and their boundary layer);
* the paper's refined coefficients, Eqs. (93)–(96) as printed, with 30-digit J-integrals
  (tests/mpmath_reference.py) and the second-order terms derived in the module docstring, with Jc3
  and int S cos^4 by mpmath quadrature;
* the closed-form small-amplitude limits abar_m(exact) - abar_m(refined) -> -(3/8) A_over_ao^2 and
  Abar(exact)/Abar(refined) - 1 -> c A_over_ao^2 (c = 19/32 for n > 1, (3/16 + 1/(8(n+3)))/n for n < 1);
* the high-frequency expansion to O(A_over_ao^2), solved with J-integrals from scipy's adaptive
  quadrature (a second integrator) and scipy's fsolve;
* the refined-model residual of vibroadhesion.models.compliant (Eqs. 87, 90–96), which the exact residual
  must approach as O(A_over_ao^2).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from conftest import C_O, CHI0, ETA1, N_PUBLISHED, RADIUS
from mpmath_reference import j_integrals_mp
from scipy.integrate import quad
from scipy.optimize import fsolve

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.integrals import folded_rule
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.models.compliant import residual
from vibroadhesion.models.exact_harmonic_balance import (
    _k_integrals,
    compliant_residual,
    exact_harmonics,
    rigid_fixation,
    solve_rigid_fixation,
)
from vibroadhesion.models.frozen_radius import NoSteadyStateError
from vibroadhesion.models.refined import nominal_point_contact as refined_nominal_point_contact

# ----------------------------------------------------------------- mpmath reference of the coefficients


def harmonics_mp(abar_m: float, Abar: float, A_over_ao: float, n: float) -> list[mp.mpf]:
    """[mean, cos, sin of deltabar; mean, cos, sin of Phat; mean sqrt(w/w0)] at 25 digits, from
    deltabar = r^2 - s sqrt(r), Phat = (4/3) r^3 - 2 s r^(3/2), r = abar_m + A_over_ao sin x,
    s = sqrt(f(Abar cos x)) with the Gent–Schultz law f = 1 + |v|^n (v < 0), 1/(1 + v^n) (v > 0).
    """
    with mp.workdps(25):
        a, big_a, e, nn = mp.mpf(abar_m), mp.mpf(Abar), mp.mpf(A_over_ao), mp.mpf(n)

        def s(x):
            v = big_a * mp.cos(x)
            return mp.sqrt(1 + (-v) ** nn) if v < 0 else 1 / mp.sqrt(1 + v**nn)

        def indentation(x):
            r = a + e * mp.sin(x)
            return r**2 - s(x) * mp.sqrt(r)

        def force(x):
            r = a + e * mp.sin(x)
            return mp.mpf(4) / 3 * r**3 - 2 * s(x) * r ** mp.mpf(1.5)

        points = {-mp.pi, -mp.pi / 2, mp.mpf(0), mp.pi / 2, mp.pi}
        scale = 1 / big_a
        while scale < mp.pi / 4:  # the boundary layer of width 1/Abar at the reversals
            points |= {c + d for c in (-mp.pi / 2, mp.pi / 2) for d in (-scale, scale)}
            scale *= 4
        points = sorted(points)
        out = []
        for g in (indentation, force):
            out += [mp.quad(g, points) / (2 * mp.pi), mp.quad(lambda x: g(x) * mp.cos(x), points) / mp.pi,
                    mp.quad(lambda x: g(x) * mp.sin(x), points) / mp.pi]
        return out + [mp.quad(s, points) / (2 * mp.pi)]


COEFFICIENT_CASES = [  # (n, abar_m, Abar, A_over_ao): small and large Abar, A_over_ao/abar_m up to 0.99
    (0.05, 1.2, 3.0, 0.1),
    (0.05, 1.1, 1e8, 0.99 * 1.1),
    (N_PUBLISHED, 0.9, 50.0, 0.45),
    (N_PUBLISHED, 1.0, 0.01, 1e-3),
    (1.0, 2.0, 1e4, 1.8),
    (4.0, 1.5, 0.5, 0.5),
    (4.0, 1.2, 3.0, 0.1),
]


@pytest.mark.parametrize("case", COEFFICIENT_CASES)
def test_exact_coefficients_match_mpmath_over_the_period(case: tuple[float, float, float, float]) -> None:
    """Reference: 25-digit mpmath quadrature of the definitions over tau' in (-pi, pi). Tolerance 1e-12
    relative (the J-integrals' rule is accurate to 1e-12); the mean indentation, a difference of two
    O(abar_m^2) terms that nearly cancel at the nominal point, to 1e-13 abar_m^2 absolute.
    """
    n, abar_m, Abar, A_over_ao = case
    got = exact_harmonics(abar_m, Abar, A_over_ao, GentSchultz(n))
    ref = harmonics_mp(abar_m, Abar, A_over_ao, n)
    assert abs(float(got[0]) - float(ref[0])) < 1e-13 * abar_m**2, (float(got[0]), ref[0])
    for k in range(1, 7):
        assert abs(float(got[k]) / float(ref[k]) - 1) < 1e-12, (k, float(got[k]), ref[k])


def test_invalid_amplitude_is_rejected_and_static_state_is_exact() -> None:
    """A_over_ao >= abar_m (A >= a_m) has no meaning for the ansatz: ValueError. Abar = A_over_ao = 0 is the
    static JKR state: mean deltabar = abar_m^2 - sqrt(abar_m), harmonics 0, J0 = 1 (to rounding).
    """
    law = GentSchultz(N_PUBLISHED)
    with pytest.raises(ValueError):
        exact_harmonics(1.0, 3.0, 1.0, law)
    h = exact_harmonics(1.3, 0.0, 0.0, law)
    assert abs(float(h.deltabar_m) - (1.3**2 - math.sqrt(1.3))) < 4e-15
    assert abs(float(h.phat_m) - (4 / 3 * 1.3**3 - 2 * 1.3**1.5)) < 1e-14
    assert max(abs(float(v)) for v in (h.deltabar_c, h.deltabar_s, h.phat_c, h.phat_s)) < 1e-15
    assert abs(float(h.sqrt_w_eff_ratio) - 1) < 1e-15


# ----------------------------------------------------------------- linearisation: Eqs. (93)-(96)


def extra_integrals_mp(Abar: float, n: float) -> tuple[mp.mpf, mp.mpf]:
    """Jc3 = (2/pi) int_0^pi sqrt(f(Abar cos x)) cos 3x dx (Eq. 29, n = 3) and
    Js4 = (1/pi) int_0^pi sqrt(f(Abar cos x)) sin^4 x dx, 25 digits.
    """
    with mp.workdps(25):
        big_a, nn = mp.mpf(Abar), mp.mpf(n)

        def s(x):
            v = big_a * mp.cos(x)
            return mp.sqrt(1 + (-v) ** nn) if v < 0 else 1 / mp.sqrt(1 + v**nn)

        points = [0, mp.pi / 2, mp.pi]
        return (2 * mp.quad(lambda x: s(x) * mp.cos(3 * x), points) / mp.pi,
                mp.quad(lambda x: s(x) * mp.sin(x) ** 4, points) / mp.pi)


@pytest.mark.parametrize("n", [N_PUBLISHED, 4.0])
def test_linearisation_gives_the_printed_refined_coefficients_with_the_derived_corrections(n: float) -> None:
    """Eqs. (93)–(96) as printed (with chi0, nu0/omega_bar and kappa), plus the corrections of the module
    docstring (A_over_ao^2 for the means and cosine terms, A_over_ao^3 for the sine terms), must equal the
    exact coefficients rescaled by c_o^2 (deltabar -> delta/R) and c_o^3/kappa (Phat -> P/(kR)), up to
    the next order: A_over_ao^4 relative. Checked at A_over_ao = 1e-2 and 2e-2 (omega_bar fixed, nu0
    chosen), tolerance 2 A_over_ao^4; the corrections alone are larger than 1e-3 A_over_ao^2 (not vacuous).
    """
    abar_m, Abar, kappa, omega_bar = 1.2, 3.0, 1e-3, 20.0
    j0, jc1, j1 = (mp.mpf(v) for v in j_integrals_mp(Abar, n))
    jc3, js4 = extra_integrals_mp(Abar, n)
    a, c2, c3 = mp.mpf(abar_m), mp.mpf(2) ** (mp.mpf(2) / 3), mp.mpf(3) ** (mp.mpf(1) / 3)
    chi0 = mp.mpf(CHI0)
    c_o = c2 ** mp.mpf(0.5) / c3**2 * chi0  # 2^(1/3) 3^(-2/3) chi0
    law = GentSchultz(n)
    for A_over_ao in (1e-2, 2e-2):
        nu0 = mp.mpf(A_over_ao) * omega_bar * c_o / Abar  # A_over_ao = nu0 Abar/(omega_bar c_o)
        printed = [
            -(c2 / c3**4) * chi0**2 * mp.sqrt(a) * jc1,  # (93)
            (c2**2 / c3**2) * chi0 * (nu0 / omega_bar) * Abar * a * (1 - j1 / (4 * a**1.5)),  # (94)
            -(4 * chi0**3 / (9 * kappa)) * a**1.5 * jc1,  # (95)
            (c2**4 / c3**4) * chi0**2 * (nu0 / (kappa * omega_bar)) * Abar * a**2 * (1 - 3 * j1 / (4 * a**1.5)),  # (96)
        ]
        e = mp.mpf(A_over_ao)
        corrections = [
            c_o**2 * e**2 * (jc1 - jc3) / (32 * a**1.5),
            -c_o**2 * e**3 * js4 / (8 * a**2.5),
            -(c_o**3 / kappa) * 3 * e**2 * (jc1 - jc3) / (16 * mp.sqrt(a)),
            (c_o**3 / kappa) * e**3 * (1 + js4 / (4 * a**1.5)),
        ]
        h = exact_harmonics(abar_m, Abar, A_over_ao, law)
        scale_d, scale_p = float(c_o**2), float(c_o**3 / kappa)
        exact = [scale_d * float(h.deltabar_c), scale_d * float(h.deltabar_s),
                 scale_p * float(h.phat_c), scale_p * float(h.phat_s)]
        for k in range(4):
            expected = printed[k] + corrections[k]
            assert abs(exact[k] / float(expected) - 1) < 2 * A_over_ao**4, (k, A_over_ao, exact[k], expected)
            assert abs(float(corrections[k] / printed[k])) > 1e-3 * A_over_ao**2
        # means: Eqs. (53), (52) (the leading order of Eq. 87) plus the A_over_ao^2 terms
        mean_indentation = a**2 - j0 * mp.sqrt(a) + e**2 * (mp.mpf(1) / 2 + j1 / (16 * a**1.5))
        mean_force = mp.mpf(4) / 3 * a**3 - 2 * j0 * a**1.5 + e**2 * (2 * a - 3 * j1 / (8 * mp.sqrt(a)))
        assert abs(float(h.deltabar_m) - float(mean_indentation)) < 2 * A_over_ao**4
        assert abs(float(h.phat_m) / float(mean_force) - 1) < 2 * A_over_ao**4


def test_exact_compliant_residual_tends_to_the_refined_one_as_epsilon_squared() -> None:
    """Reference: vibroadhesion.models.compliant.residual (Eqs. 87, 90–96), the linearised system. At fixed
    (omega_bar, abar_m, Abar), A_over_ao = nu0 Abar/(omega_bar c_o) -> 0 with nu0: the difference of both
    columns divided by A_over_ao^2 must converge (change below 1e-3 relative from nu0 = 1e-5 to 1e-6) and
    the difference be below 1e-6 at nu0 = 1e-6.
    """
    law = GentSchultz(N_PUBLISHED)
    x = np.log(np.array([[3.0, 1.2, 20.0], [0.5, 1.0, 2.0]]))
    scaled = []
    for nu0 in (1e-5, 1e-6):
        p = Fixation.compliant(kappa=1e-3, zeta=0.05, nu0=nu0, mu=1e-7)
        A_over_ao = nu0 * np.exp(x[:, 2]) / (np.exp(x[:, 0]) * C_O)
        difference = compliant_residual(x, p, CHI0, ETA1, law) - residual(x, p, CHI0, ETA1, law)
        scaled.append(difference / A_over_ao[:, None] ** 2)
    assert np.max(np.abs(scaled[1] / scaled[0] - 1)) < 1e-3
    assert np.max(np.abs(difference)) < 1e-6


def test_compliant_mean_balance_reduces_to_the_rigid_and_static_cases() -> None:
    """kappa -> infinity: column 0 becomes the rigid mean equation (mean deltabar - base_offset)/K0[sqrt]
    (Eq. 56 generalised), up to O(c_o/kappa); checked with kappa = 1e12 against exact_harmonics, to 1e-10.
    """
    law = GentSchultz(N_PUBLISHED)
    p = Fixation.compliant(kappa=1e12, zeta=0.0, nu0=1e-5, mu=0.0)
    x = np.log(np.array([[3.0, 1.2, 20.0]]))
    A_over_ao = 1e-5 * 20.0 / (3.0 * C_O)
    h = exact_harmonics(1.2, 20.0, A_over_ao, law)
    k0_sqrt = 1.2**2 + 0.5 * A_over_ao**2 - float(h.deltabar_m)
    for base_offset in (0.0, 0.3):
        col = float(compliant_residual(x, p, CHI0, ETA1, law, base_offset)[0, 0])
        assert abs(col - (float(h.deltabar_m) - base_offset) / k0_sqrt) < 1e-10


# ----------------------------------------------------------------- rigid fixation


RIGID_CASES = [  # (n, h1 in m, omega_check, base_offset)
    (N_PUBLISHED, 20e-6, 1e4, 0.0),
    (N_PUBLISHED, 100e-6, 1e6, 0.0),
    (4.0, 60e-6, 3e3, 0.3),
    (N_PUBLISHED, 40e-6, 1e5, -0.3),
    (1.0, 20e-6, 1e5, 0.0),
]


@pytest.mark.parametrize("case", RIGID_CASES)
def test_rigid_solution_satisfies_both_equations_in_mpmath(case: tuple[float, float, float, float]) -> None:
    """Reference: the mpmath coefficients (25 digits) at the returned (abar_m, Abar): mean deltabar =
    base_offset to 1e-12 abar_m^2 and sqrt(deltabar_c^2 + deltabar_s^2) = etahat to 1e-11 relative; the
    returned w_eff/w0 = J0^2, A/a_m = A_over_ao/abar_m and P_m/|P_JKR| = mean Phat/(3/4) match them.
    """
    n, h1, omega_check, base_offset = case
    sol = rigid_fixation(h1 / RADIUS, omega_check, CHI0, GentSchultz(n), base_offset)
    A_over_ao = float(sol.Abar) / (omega_check * C_O)
    ref = [float(v) for v in harmonics_mp(float(sol.abar_m), float(sol.Abar), A_over_ao, n)]
    etahat = h1 / RADIUS / C_O**2
    assert abs(ref[0] - base_offset) < 1e-12 * sol.abar_m**2
    assert abs(math.hypot(ref[1], ref[2]) / etahat - 1) < 1e-11
    assert abs(sol.w_eff_ratio / ref[6] ** 2 - 1) < 1e-12
    assert abs(sol.A_over_am / (A_over_ao / sol.abar_m) - 1) < 1e-14
    assert abs(sol.pm_over_abs_pjkr / (ref[3] / 0.75) - 1) < 1e-11


def test_zero_amplitude_is_the_static_nominal_point_contact() -> None:
    """eta1 = 0: Abar = 0, abar_m = 1 (a = a_o, Eq. 86), w_eff = w0 and P_m = -(2/3) E* a_o^3/R, i.e.
    P_m/|P_JKR| = -8/9 (to rounding).
    """
    sol = rigid_fixation(0.0, 1e5, CHI0, GentSchultz(N_PUBLISHED))
    assert sol.Abar == 0.0 and abs(sol.abar_m - 1) < 1e-14 and sol.w_eff_ratio == 1.0 and sol.A_over_am == 0.0
    assert abs(sol.pm_over_abs_pjkr + 8 / 9) < 1e-14


def test_no_single_harmonic_state_is_reported_not_returned() -> None:
    """h1 = 100 um at omega_check = 1e4 (refined model: A/a_m = 1.5, geometrically impossible): the
    mean equation loses its stable root before the base amplitude is reached: NoSteadyStateError inside,
    the status ``no_solution`` (every number NaN) at the level's boundary.
    """
    with pytest.raises(NoSteadyStateError):
        solve_rigid_fixation(100e-6 / RADIUS, 1e4, CHI0, GentSchultz(N_PUBLISHED))
    sol = rigid_fixation(100e-6 / RADIUS, 1e4, CHI0, GentSchultz(N_PUBLISHED))
    assert sol.status == "no_solution" and math.isnan(sol.Abar) and math.isnan(sol.abar_m) and sol.message


def _amplitude_along_stable_branch(
    omega_check: float, Abar_grid: np.ndarray, law: GentSchultz
) -> list[tuple[float, float]]:
    """(A/a_m, sqrt(deltabar_c^2 + deltabar_s^2)) along the larger root of mean deltabar = 0, located on a
    grid of 400 radii by linear interpolation (independent of the solver's Brent iteration); stops
    where the mean equation has no root above A_over_ao.
    """
    out = []
    for Abar in Abar_grid:
        A_over_ao = Abar / (omega_check * C_O)
        radii = np.geomspace(max(1.01 * A_over_ao, 0.05), 5.0, 400)
        mean = exact_harmonics(radii, Abar, A_over_ao, law).deltabar_m
        crossing = np.flatnonzero((mean[:-1] < 0) & (mean[1:] >= 0))
        if crossing.size == 0:
            break
        k = crossing[-1]  # the larger root: the stable branch
        abar_m = radii[k] - mean[k] * (radii[k + 1] - radii[k]) / (mean[k + 1] - mean[k])
        h = exact_harmonics(abar_m, Abar, A_over_ao, law)
        out.append((A_over_ao / abar_m, math.hypot(float(h.deltabar_c), float(h.deltabar_s))))
    return out


def test_amplitude_along_the_branch_and_the_choice_of_the_smaller_root() -> None:
    """At omega_check = 1e4 (h1 = 20 um scale) the amplitude rises monotonically with Abar up to the edge of
    the ansatz's domain: one root. At omega_check = 1e3 it peaks near A/a_m = 0.75 and falls before the
    edge: for etahat between the edge value and the peak there are two roots, and the solver must return
    the smaller one (A/a_m below the peak's), whose amplitude and mean equation it satisfies.
    """
    law = GentSchultz(N_PUBLISHED)
    rising = _amplitude_along_stable_branch(1e4, np.geomspace(0.01, 300.0, 60), law)
    assert len(rising) > 20 and np.all(np.diff([v for _, v in rising]) > 0)
    peaked = _amplitude_along_stable_branch(1e3, np.geomspace(1.0, 14.0, 60), law)
    values = np.array([v for _, v in peaked])
    k = int(np.argmax(values))
    assert 0 < k < len(values) - 1 and values[-1] < values[k]
    etahat = 0.5 * (values[k] + values[-1])  # two roots: one on each side of the peak
    sol = rigid_fixation(etahat * C_O**2, 1e3, CHI0, law)
    assert sol.A_over_am < peaked[k][0]
    assert abs(np.interp(sol.A_over_am, *zip(*peaked[: k + 1])) / etahat - 1) < 1e-3


@pytest.mark.parametrize("n", [N_PUBLISHED, 2.0])
def test_small_base_amplitude_limit_against_the_refined_model(n: float) -> None:
    """eta1 -> 0 at fixed omega_check: the exact and refined (Eqs. 122–123) solutions differ at O(A_over_ao^2),
    with closed-form limits (J -> (1, 0, 1)):

    * abar_m(exact) - abar_m(refined) -> -(3/8) A_over_ao^2 (mean equation's A_over_ao^2 (1/2 + 1/16) over 3/2);
    * Abar(exact)/Abar(refined) - 1 -> c A_over_ao^2 with c = 19/32 for n > 1 (the amplitude is deltabar_s:
      (9/4)(3/8) + 3/64 over 3/2) and c = (3/16 + 1/(8(n+3)))/n for n < 1 (the amplitude is deltabar_c:
      half the radius change plus the Jc3 term, Jc3/Jc1 -> (n-1)/(n+3), divided by d ln|Jc1|/d ln Abar -> n).

    Tolerances (the limits are approached at rates set by the share of the other harmonic; A_over_ao^2 must
    stay above the rounding of abar_m): n = 0.531, omega_check = 30, eta1 = 3e-7 (A_over_ao = 2e-5): 1e-5 on the
    first, 3e-3 on the second; n = 2, omega_check = 3, eta1 = 1e-7 (A_over_ao = 3e-4): 1e-5 on both.
    """
    omega_check, eta1, tolerances = (30.0, 3e-7, (1e-5, 3e-3)) if n < 1 else (3.0, 1e-7, (1e-5, 1e-5))
    law = GentSchultz(n)
    exact = rigid_fixation(eta1, omega_check, CHI0, law)
    refined = refined_nominal_point_contact(eta1, omega_check, CHI0, law)
    A_over_ao = exact.Abar / (omega_check * C_O)
    assert abs((exact.abar_m - float(refined.abar_m)) / A_over_ao**2 / (-3 / 8) - 1) < tolerances[0]
    c = 19 / 32 if n > 1 else (3 / 16 + 1 / (8 * (n + 3))) / n
    assert abs((exact.Abar / float(refined.Abar) - 1) / A_over_ao**2 / c - 1) < tolerances[1]


def _j_integrals_scipy(Abar: float, n: float) -> tuple[float, float, float, float]:
    """J0, Jc1, J1 (Eqs. 28, 29, 36) and Jc3 (Eq. 29) by QUADPACK, split at pi/2: relative 1e-12, or
    absolute 1e-13 sqrt(1 + Abar^n) (the size of the integrand) where that is larger (Jc3 may be small).
    """

    def sqrt_f(x: float) -> float:
        v = Abar * math.cos(x)
        return math.sqrt(1 + (-v) ** n) if v < 0 else 1 / math.sqrt(1 + v**n)

    def integral(weight) -> float:
        return quad(lambda x: sqrt_f(x) * weight(x), 0, math.pi, points=[math.pi / 2],
                    epsabs=1e-13 * math.sqrt(1 + Abar**n), epsrel=1e-12, limit=400)[0]

    return (integral(lambda x: 1.0) / math.pi, 2 * integral(math.cos) / math.pi,
            2 * integral(lambda x: math.sin(x) ** 2) / math.pi, 2 * integral(lambda x: math.cos(3 * x)) / math.pi)


def high_frequency_expansion(
    eta1: float, omega_check: float, n: float, guess: tuple[float, float]
) -> tuple[float, float]:
    """(abar_m, Abar) of the rigid nominal point contact expanded to O(A_over_ao^2) (module docstring):

        abar_m^2 - J0 sqrt(abar_m) + A_over_ao^2 (1/2 + J1/(16 abar_m^(3/2))) = 0,
        (sqrt(abar_m) Jc1 - A_over_ao^2 (Jc1 - Jc3)/(32 abar_m^(3/2)))^2
            + (2 abar_m A_over_ao (1 - J1/(4 abar_m^(3/2))))^2 = etahat^2,

    solved by fsolve in logarithms with the QUADPACK J-integrals.
    """
    etahat = eta1 / C_O**2

    def equations(z: np.ndarray) -> list[float]:
        a, big_a = math.exp(z[0]), math.exp(z[1])
        e = big_a / (omega_check * C_O)
        j0, jc1, j1, jc3 = _j_integrals_scipy(big_a, n)
        mean = a**2 - j0 * math.sqrt(a) + e**2 * (0.5 + j1 / (16 * a**1.5))
        cos_term = math.sqrt(a) * jc1 - e**2 * (jc1 - jc3) / (32 * a**1.5)
        sin_term = 2 * a * e * (1 - j1 / (4 * a**1.5))
        return [mean / a**2, math.log(math.hypot(cos_term, sin_term) / etahat)]

    z = fsolve(equations, np.log(guess), xtol=1e-13, full_output=True)[0]  # status judged by the residual below
    assert max(abs(r) for r in equations(z)) < 1e-13
    return math.exp(z[0]), math.exp(z[1])


@pytest.mark.parametrize("case", [(N_PUBLISHED, 20e-6, 1e5), (N_PUBLISHED, 20e-6, 1e6), (2.0, 100e-6, 1e5)])
def test_high_frequency_limit_is_the_leading_order_plus_epsilon_squared_terms(case: tuple[float, float, float]) -> None:
    """omega_check -> infinity: the exact balance tends to the leading order (Eqs. 55, 123: refined model at
    omega_check = infinity) with an O(A_over_ao^2) difference, and to the O(A_over_ao^2)-expanded system
    (solved independently) with an O(A_over_ao^4) difference. Tolerances: |exact/expanded - 1| < A_over_ao^4
    (measured coefficients 0.09 and 0.005) for Abar and abar_m; |exact/leading - 1| > 0.01 A_over_ao^2.
    """
    n, h1, omega_check = case
    law = GentSchultz(n)
    exact = rigid_fixation(h1 / RADIUS, omega_check, CHI0, law)
    leading = refined_nominal_point_contact(h1 / RADIUS, math.inf, CHI0, law)
    abar_m, Abar = high_frequency_expansion(h1 / RADIUS, omega_check, n, (exact.abar_m, exact.Abar))
    A_over_ao = exact.Abar / (omega_check * C_O)
    assert abs(exact.Abar / Abar - 1) < A_over_ao**4 and abs(exact.abar_m / abar_m - 1) < A_over_ao**4
    assert abs(exact.Abar / float(leading.Abar) - 1) > 0.01 * A_over_ao**2
    assert abs(exact.abar_m / float(leading.abar_m) - 1) > 0.01 * A_over_ao**2


def test_k_integrals_of_constants_are_the_closed_form_quarter_period_integrals() -> None:
    """S = D = 1, g+ = g- = 1 (g_sum = 2, g_diff = 0) and g_diff = 1: K0 = (1/2pi) int_0^(pi/2) 2 dt = 1/2,
    Kc = (1/pi) int_0^(pi/2) 2 sin t dt = 2/pi, Ks = 0 and (1/pi) int_0^(pi/2) cos t dt = 1/pi. The folded
    rule integrates these smooth functions to rounding: 1e-14.
    """
    t, _, weights = folded_rule()
    ones = np.ones((1, t.size))
    for g_diff, ks in ((0.0, 0.0), (1.0, 1 / math.pi)):
        k0, kc, k_s = _k_integrals(2.0 * ones, g_diff * ones, ones, ones, math.pi * weights[:, 0], np.cos(t), np.sin(t))
        assert abs(k0[0] - 0.5) < 1e-14 and abs(kc[0] - 2 / math.pi) < 1e-14 and abs(k_s[0] - ks) < 1e-14
