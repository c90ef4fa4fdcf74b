"""Pull-off estimates of Eqs. (71), (72) and (106), and the closed-form groups and JKR relations.

Independent references: the 30-digit mpmath J-integrals (``mpmath_reference``) substituted into
the equations as printed in the paper, the closed-form monotonicity proofs, the limits
eta1 -> 0 and omega_check -> infinity, the classical JKR identities, and the paper's printed
numbers (Secs. 3.4, 3.5.3, Fig. 4-6 captions).
"""

from __future__ import annotations

import math
import warnings

import mpmath as mp
import numpy as np
import pytest
from conftest import CHI0, ETA1, N_PUBLISHED, NU0, RADIUS, REDUCED_MODULUS, V0, W0
from mpmath_reference import j_integrals_mp

from vibroadhesion.core import groups, jkr, levels
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters, predict_pulloff
from vibroadhesion.models.leading_pulloff import critical_internal_variable_leading, pulloff_leading, pulloff_lhs_leading
from vibroadhesion.models.refined import critical_internal_variable_refined, pulloff_lhs_refined, pulloff_refined
from vibroadhesion.numerics.roots import NoRootError

# ----------------------------------------------------------------------------- Eq. (72)


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 4.0])
@pytest.mark.parametrize("eta1", [1e-6, ETA1, 1e-3, 1e-2])
def test_eq72_root_satisfies_equation_with_mpmath_j_to_1e12(eta1: float, n: float) -> None:
    """Reference: Eq. (72), (chi0^2/3) J0^{1/3} |Jc1| = eta1, with 30-digit mpmath J at the returned root; 1e-12."""
    law = GentSchultz(n)
    Abar = critical_internal_variable_leading(eta1, CHI0, law)
    assert Abar > 0
    j0, jc1, _ = j_integrals_mp(Abar, n)
    lhs = mp.mpf(CHI0) ** 2 / 3 * mp.cbrt(j0) * abs(jc1)
    residual = float(abs(lhs / mp.mpf(eta1) - 1))
    assert residual < 1e-12, f"Abar_cr = {Abar!r}: relative residual {residual:.3e}"
    # Eq. (71): the reported amplification is J0(Abar_cr)^2, and pulloff_leading (the vectorised solver) agrees with
    # the scalar one: each locates ln Abar to 1e-14 + 4 eps |ln Abar| (numerics.roots), so the two differ by < 1e-13
    est = pulloff_leading(np.array([eta1]), CHI0, law)
    assert abs(est.Abar_cr[0] / Abar - 1) < 1e-13
    assert abs(est.pulloff_ratio[0] / float(j0**2) - 1) < 1e-12


@pytest.mark.parametrize("frequency_hz", [0.1, 10.0, 200.0, 400.0])
def test_refined_A_over_am_at_detachment_equals_the_physical_ratio(frequency_hz: float) -> None:
    """Reference: in SI units, A = Abar_cr v0 / omega (Eq. 105's scaling of the internal variable) and, at the
    criterion a_m = a_cr, a_cr = (9 pi R^2 w_eff / (8 E*))^(1/3) with w_eff = J0^2 w0 (Eqs. 49, 60); their ratio is
    what Figs. 4 and 7 flag against the applicability limit 0.1 (Sec. 3.5.3). Algebra only: 1e-12."""
    params = GentSchultzParameters(W0, N_PUBLISHED, V0)
    h1_um = np.array([20.0, 100.0])
    record = predict_pulloff("refined", params, frequency_hz, h1_um, radius=RADIUS, reduced_modulus=REDUCED_MODULUS)
    omega = 2 * math.pi * frequency_hz
    A = record.Abar_cr * V0 / omega
    a_cr = jkr.critical_radius(record.sqrt_w_eff_ratio**2 * W0, REDUCED_MODULUS, RADIUS)
    assert np.allclose(record.A_over_am, A / a_cr, rtol=1e-12, atol=0)
    # 200 Hz at 100 um is just inside the region, 0.1 Hz (omega_check ~ 730) far outside it at both amplitudes
    assert (record.A_over_am > 0.1).tolist() == {0.1: [True, True], 10.0: [False, True], 200.0: [False, False],
                                                  400.0: [False, False]}[frequency_hz]


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 1.0, 2.0, 4.0])
def test_eq72_and_eq106_lhs_strictly_increasing_as_proved(n: float) -> None:
    """Closed-form monotonicity proofs (docstrings of leading_order/refined; n < 6): both left-hand
    sides rise strictly with Abar. Dense grid Abar in logspace(-12, 12, 2401).
    """
    Abar = np.logspace(-12, 12, 2401)
    law = GentSchultz(n)
    lhs72 = pulloff_lhs_leading(Abar, law)
    assert np.all(np.diff(lhs72) > 0), (n, Abar[np.argmin(np.diff(lhs72))])
    for omega_check in (1e2, 1e6):
        lhs106 = pulloff_lhs_refined(Abar, law, CHI0, omega_check)
        assert np.all(np.diff(lhs106) > 0), (n, omega_check, Abar[np.argmin(np.diff(lhs106))])
        # the frequency term only adds: Eq. (106) LHS >= (Eq. 72 LHS * chi0^2 / 3)^2
        assert np.all(lhs106 >= (CHI0**2 / 3 * lhs72) ** 2 * (1 - 1e-13))


# ----------------------------------------------------------------------------- limits


def test_eta1_zero_gives_abar_zero_and_ratio_exactly_one() -> None:
    """Limit h1 -> 0: no vibration, Abar_cr = 0 and P_cr / P_cr^JKR = J0(0)^2 = 1 exactly (Eq. 71)."""
    law = GentSchultz(N_PUBLISHED)
    assert critical_internal_variable_leading(0.0, CHI0, law) == 0.0
    assert critical_internal_variable_refined(0.0, CHI0, 1e6, law) == 0.0
    lead = pulloff_leading(0.0, CHI0, law)
    ref = pulloff_refined(0.0, CHI0, 1e6, law)
    assert float(lead.Abar_cr) == 0.0 and float(ref.Abar_cr) == 0.0
    assert (float(lead.pulloff_ratio), float(ref.pulloff_ratio)) == (1.0, 1.0), (
        f"ratio - 1 = {float(lead.pulloff_ratio) - 1:.3e} (leading), {float(ref.pulloff_ratio) - 1:.3e} (refined)"
    )


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 4.0])
def test_tiny_eta1_gives_ratio_within_1e6_of_one(n: float) -> None:
    """Limit h1 -> 0 (Eq. 71 with J0 -> 1): eta1 = 1e-9 gives |ratio - 1| < 1e-6, both model levels."""
    law = GentSchultz(n)
    lead = pulloff_leading(1e-9, CHI0, law)
    ref = pulloff_refined(1e-9, CHI0, 1e4, law)
    assert abs(float(lead.pulloff_ratio) - 1) < 1e-6
    assert abs(float(ref.pulloff_ratio) - 1) < 1e-6
    assert float(lead.pulloff_ratio) >= 1 - 1e-14 and float(ref.pulloff_ratio) >= 1 - 1e-14  # J0 >= 1 (S >= 2)


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 4.0])
def test_very_large_eta1_gives_finite_ratio_without_warning(n: float) -> None:
    """eta1 = 0.05 (h1 = 2.6 mm at R = 51.5 mm): the root exists (LHS unbounded), the ratio is finite, > 1,
    no warning of any kind; and it matches Eq. (71) with J0 from the closed-form large-Abar bound J0 >= J0~.
    """
    law = GentSchultz(n)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        lead = pulloff_leading(0.05, CHI0, law)
        ref = pulloff_refined(0.05, CHI0, np.array([1e2, 1e6]), law)
    for est in (lead, ref):
        assert np.all(np.isfinite(est.Abar_cr)) and np.all(np.isfinite(est.pulloff_ratio))
        assert np.all(est.pulloff_ratio > 1)
    assert np.all(ref.pulloff_ratio <= float(lead.pulloff_ratio) * (1 + 1e-14))


@pytest.mark.parametrize(
    "n, eta1",
    [(0.05, 1e-6), (N_PUBLISHED, 1e-6), (N_PUBLISHED, ETA1), (N_PUBLISHED, 1e-2), (1.0, ETA1), (4.0, 1e-6),
     (4.0, ETA1), (4.0, 1e-2)],
)
def test_refined_tends_to_leading_as_omega_check_to_infinity(n: float, eta1: float) -> None:
    """Limit omega_check -> inf of Eq. (106) is Eq. (72) squared (delta_s -> 0, Eq. 104).

    omega_check = 1e14: the frequency term relative to the first is (3 Abar/(chi0 omega_check))^2
    J0^{2/3} (1 - J1/(3 J0))^2 / Jc1^2, < 1e-12 for these cases (checked below), so the roots agree to 1e-9.
    omega_check = inf: the same equation, solved twice: the roots agree to within the two solvers'
    tolerances in z = ln Abar, 2 (1e-14 + 4 eps |z|) (brentq xtol + rtol |z|, roots.py); that is
    1e-14 up to rounding for |z| < 10, and 2e-13 at Abar = 1e-43 (n = 0.05, eta1 = 1e-6).
    """
    law = GentSchultz(n)
    lead = critical_internal_variable_leading(eta1, CHI0, law)
    j0, jc1, j1 = (float(x) for x in j_integrals_mp(lead, n))
    term_ratio = (3 * lead / (CHI0 * 1e14)) ** 2 * j0 ** (2 / 3) * (1 - j1 / (3 * j0)) ** 2 / jc1**2
    assert term_ratio < 1e-12  # precondition of the limit for this case
    assert abs(critical_internal_variable_refined(eta1, CHI0, 1e14, law) / lead - 1) < 1e-9
    tol = 2 * (1e-14 + 4 * np.finfo(float).eps * abs(math.log(lead)))
    assert abs(critical_internal_variable_refined(eta1, CHI0, math.inf, law) / lead - 1) < tol


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 4.0])
def test_refined_ratio_not_above_leading_ratio(n: float) -> None:
    """Eq. (106) LHS = Eq. (72) LHS^2 + a nonnegative frequency term, and both increase: Abar_ref <= Abar_lead,
    hence J0(Abar_ref)^2 <= J0(Abar_lead)^2 (J0 increasing).
    """
    law = GentSchultz(n)
    eta1 = np.array([1e-5, ETA1, 2e-3])[:, None]
    omega = np.array([1e1, 1e3, 1e5, 1e8])[None, :]
    lead = pulloff_leading(eta1[:, 0], CHI0, law)
    ref = pulloff_refined(eta1, CHI0, omega, law)
    assert ref.pulloff_ratio.shape == (3, 4)
    assert np.all(ref.Abar_cr <= lead.Abar_cr[:, None] * (1 + 1e-13))
    assert np.all(ref.pulloff_ratio <= lead.pulloff_ratio[:, None] * (1 + 1e-14))
    # and increases towards the leading value with omega_check (frequency term shrinks as 1/omega^2)
    assert np.all(np.diff(ref.Abar_cr, axis=1) >= 0)


@pytest.mark.parametrize("n", [0.05, 4.0])
@pytest.mark.parametrize("omega_check", [1e2, 1e4, 1e6, 1e9])
def test_eq106_root_satisfies_printed_equation_with_mpmath_j(omega_check: float, n: float) -> None:
    """Reference: Eq. (106) as printed, with 30-digit mpmath J at the returned root; sqrt(LHS)/eta1 - 1 < 1e-12:

    chi0^4/9 J0^{2/3} Jc1^2 + chi0^2/omega^2 Abar^2 J0^{4/3} (1 - J1/(3 J0))^2 = eta1^2.
    """
    eta1 = ETA1
    Abar = critical_internal_variable_refined(eta1, CHI0, omega_check, GentSchultz(n))
    j0, jc1, j1 = j_integrals_mp(Abar, n)
    c, a, w = mp.mpf(CHI0), mp.mpf(Abar), mp.mpf(omega_check)
    lhs = c**4 / 9 * mp.cbrt(j0) ** 2 * jc1**2 + c**2 / w**2 * a**2 * mp.cbrt(j0) ** 4 * (1 - j1 / (3 * j0)) ** 2
    residual = float(abs(mp.sqrt(lhs) / mp.mpf(eta1) - 1))
    assert residual < 1e-12, f"Abar_cr = {Abar!r}: relative residual {residual:.3e}"


# ----------------------------------------------------------------------------- bounded LHS -> NoRootError


class Saturating:
    """A rate law with bounded amplification: f = 1 + 0.5|x|/(1+|x|) for x < 0, its reciprocal for x >= 0.

    sqrt(f) lies in [sqrt(2/3), sqrt(3/2)], so J0 <= sqrt(3/2) and |Jc1| <= (2/pi) int_0^pi |cos x| sqrt(3/2) dx
    = 4 sqrt(3/2)/pi: the LHS of Eq. (72) is below 1.07 * 1.56 < 1.7 for every Abar.
    """

    def f(self, x):
        x = np.asarray(x, dtype=float)
        g = 1.0 + 0.5 * np.abs(x) / (1.0 + np.abs(x))
        return np.where(x < 0, g, 1.0 / g)


def _saturating_j_mp(Abar: float) -> tuple[mp.mpf, mp.mpf]:
    """J0, Jc1 of the Saturating law straight from Eqs. (28), (29), mpmath at 30 digits."""
    with mp.workdps(30):
        a = mp.mpf(Abar)

        def sqrt_f(x):
            s = a * mp.cos(x)
            g = 1 + mp.mpf(1) / 2 * abs(s) / (1 + abs(s))
            return mp.sqrt(g) if s < 0 else 1 / mp.sqrt(g)

        pts = [0, mp.pi / 2, mp.pi]
        return mp.quad(sqrt_f, pts) / mp.pi, 2 * mp.quad(lambda x: sqrt_f(x) * mp.cos(x), pts) / mp.pi


def test_bounded_lhs_rate_law_raises_no_root_error() -> None:
    """Closed-form bound: LHS of Eq. (72) < 1.7 for the Saturating law; eta1 = 1e-2 needs 3 eta1/chi0^2 = 44.8,
    so there is no root: NoRootError, not a number (also for Eq. 106 with omega_check = inf); at the level's
    boundary (pulloff_leading) the status no_solution with NaN numbers.
    """
    law = Saturating()
    assert 3 * 1e-2 / CHI0**2 > 1.7
    with pytest.raises(NoRootError):
        critical_internal_variable_leading(1e-2, CHI0, law)
    unsolved = pulloff_leading(np.array([1e-6, 1e-2]), CHI0, law)
    assert unsolved.status.tolist() == ["ok", "no_solution"] and np.all(np.isnan(unsolved.pulloff_ratio[1:]))
    with pytest.raises(NoRootError):
        critical_internal_variable_refined(1e-2, CHI0, math.inf, law)


def test_bounded_lhs_rate_law_small_eta1_root_satisfies_eq72_with_mpmath() -> None:
    """Reference: Eq. (72) with the Saturating law's J0, Jc1 by mpmath quadrature of Eqs. (28), (29); 1e-10."""
    law = Saturating()
    eta1 = 1e-6
    Abar = critical_internal_variable_leading(eta1, CHI0, law)
    j0, jc1 = _saturating_j_mp(Abar)
    lhs = mp.mpf(CHI0) ** 2 / 3 * mp.cbrt(j0) * abs(jc1)
    residual = float(abs(lhs / mp.mpf(eta1) - 1))
    assert residual < 1e-10, f"Abar = {Abar!r}: relative residual {residual:.3e}"


@pytest.mark.parametrize("bad", [-1e-6, math.nan, math.inf])
def test_invalid_eta1_raises_value_error(bad: float) -> None:
    """eta1 = h1/R is a finite nonnegative ratio (Eq. 65)."""
    with pytest.raises(ValueError):
        critical_internal_variable_leading(bad, CHI0, GentSchultz(N_PUBLISHED))
    with pytest.raises(ValueError):
        critical_internal_variable_refined(bad, CHI0, 1e6, GentSchultz(N_PUBLISHED))


# ----------------------------------------------------------------------------- groups and JKR


def test_chi0_matches_paper_value_2_589e_2() -> None:
    """Paper, Sec. 3.5.3 / Fig. 5 caption: chi0 = 2.589e-2 (4 digits) for w0 = 0.236, E* = 2*2.8 MPa/0.75, R = 51.5 mm;
    closed form Eq. (64): (9 pi w0 / (E* R))^{1/3}.
    """
    chi0 = groups.chi0(W0, REDUCED_MODULUS, RADIUS)
    assert abs(chi0 - CHI0) <= 0.5e-5
    assert abs(chi0 / (9 * math.pi * W0 / (REDUCED_MODULUS * RADIUS)) ** (1 / 3) - 1) < 1e-15


@pytest.mark.parametrize("w0, e_star, radius", [(W0, REDUCED_MODULUS, RADIUS), (0.05, 1e9, 1e-3), (3.0, 2e5, 0.2)])
def test_contact_radius_scale_equals_eq86_in_terms_of_chi0(w0: float, e_star: float, radius: float) -> None:
    """Closed form below Eq. (86): a_o = 2^{1/3} 3^{-2/3} chi0 R; 1e-14 relative."""
    a_o = groups.contact_radius_scale(w0, e_star, radius)
    expected = 2 ** (1 / 3) * 3 ** (-2 / 3) * groups.chi0(w0, e_star, radius) * radius
    assert abs(a_o / expected - 1) < 1e-14


def test_eta1_matches_paper_value_3_883e_4() -> None:
    """Paper, Fig. 5 caption: eta1 = h1/R = 3.883e-4 for h1 = 20 um, R = 51.5 mm (4 digits)."""
    assert abs(float(groups.eta1(20e-6, RADIUS)) - ETA1) <= 0.5e-7


@pytest.mark.parametrize("w, e_star, radius", [(W0, REDUCED_MODULUS, RADIUS), (0.05, 1e9, 1e-3), (3.0, 2e5, 0.2)])
def test_jkr_force_at_critical_radius_is_classical_pulloff_force(w: float, e_star: float, radius: float) -> None:
    """Classical JKR identity: P(a_cr) = -(3 pi / 2) R w (Eqs. 4, 60, 70), to 1e-12; and dP/da = 0 at a_cr
    (central difference, step 1e-5 a_cr: truncation ~1e-10 and rounding ~1e-11 relative to P/a).
    """
    a_cr = float(jkr.critical_radius(w, e_star, radius))
    p_cr = float(jkr.contact_force(a_cr, w, e_star, radius))
    assert abs(p_cr / (-1.5 * math.pi * radius * w) - 1) < 1e-12
    assert abs(float(jkr.pulloff_force(w, radius)) / (-1.5 * math.pi * radius * w) - 1) < 1e-15
    h = 1e-5 * a_cr
    dp = (float(jkr.contact_force(a_cr + h, w, e_star, radius)) - float(jkr.contact_force(a_cr - h, w, e_star, radius))) / (2 * h)
    assert abs(dp) * a_cr / abs(p_cr) < 1e-8
    # a_cr is a minimum of P (maximum tension): P is larger on both sides
    assert float(jkr.contact_force(a_cr * 1.01, w, e_star, radius)) > p_cr
    assert float(jkr.contact_force(a_cr * 0.99, w, e_star, radius)) > p_cr


def test_nu0_matches_paper_value_1_227e_5() -> None:
    """Paper, Fig. 5 caption: nu0 = v0/(omega0 R) = 1.227e-5 with v0 = 44.5 um/s, omega0 = 70.4 rad/s (3 digits)."""
    assert abs(groups.nu0(V0, 70.4, RADIUS) / NU0 - 1) < 1e-3


def test_omega_check_equals_eq105_closed_form() -> None:
    """Eq. (105): omega_check = omega R / v0 with omega = 2 pi f; 200 Hz, R = 51.5 mm, v0 = 44.5 um/s; 1e-15."""
    got = float(groups.omega_check(200.0, V0, RADIUS))
    assert abs(got / (2 * math.pi * 200 * RADIUS / V0) - 1) < 1e-15


@pytest.mark.parametrize("model", ["exact_averaging", "exact_averaging_force_minimum"])
def test_predict_pulloff_solves_sorted_distinct_amplitudes_as_one_direct_call(model: str) -> None:
    """predict_pulloff solves a frequency-independent level on np.unique(eta1) and scatters back; for sorted,
    distinct amplitudes (the rig's, Fig. 4's grid) that is the same array, so the same operations give the
    same bits as the level's own call on eta1 (the route Fig. 4 and the virtual pull-off took before the
    registry); with repeated amplitudes each copy is the distinct value's result.
    """
    params = GentSchultzParameters(W0, N_PUBLISHED, V0)
    h1_um = np.array([0.0, 20.0, 40.0, 60.0, 80.0, 100.0])
    chi0 = groups.chi0(W0, REDUCED_MODULUS, RADIUS)
    direct = levels.level(model).pulloff_function()(h1_um * 1e-6 / RADIUS, chi0, GentSchultz(N_PUBLISHED))
    routed = predict_pulloff(model, params, 200.0, h1_um, radius=RADIUS, reduced_modulus=REDUCED_MODULUS)
    for field in ("pulloff_ratio", "Abar_cr", "sqrt_w_eff_ratio", "abar_m"):
        assert np.array_equal(getattr(routed, field), getattr(direct, field)), field
    repeated = predict_pulloff(model, params, 200.0, [40.0, 20.0, 40.0], radius=RADIUS, reduced_modulus=REDUCED_MODULUS)
    distinct = levels.level(model).pulloff_function()(np.array([20.0, 40.0]) * 1e-6 / RADIUS, chi0,
                                                      GentSchultz(N_PUBLISHED))
    assert np.array_equal(repeated.pulloff_ratio, distinct.pulloff_ratio[[1, 0, 1]])
