"""Rigid fixation, Figs. 6-8: nominal point contact (Eqs. 122-123), refined pull-off (Eq. 106)
and the dynamic contact stiffness (Eqs. 117-121), along the figure tables the pipeline writes.

Independent references: the 30-digit mpmath J-integrals (``mpmath_reference``) substituted into
Eq. (122) as printed (it is correct; docs/errata.md E2), the small-amplitude closed form of the
J-integrals, the leading-order pull-off of Eq. (72) (Fig. 4's numbers), and the two limits of
Eq. (118) that the paper states (Greenwood–Johnson flat punch; Eq. C.2).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from conftest import AMPLITUDES_UM, CHI0, N_PUBLISHED, RADIUS, V0, W0
from mpmath_reference import j_integrals_mp

from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.figure_tables import APPLICABILITY_LIMIT
from vibroadhesion.experiments.figure_tables.fig4 import fig4_table
from vibroadhesion.experiments.figure_tables.fig8 import fig8_table
from vibroadhesion.experiments.figure_tables.rigid import FIG6_COLUMNS, fig6_table, fig7_table
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.models.refined import nominal_point_contact, nominal_point_contact_closure, rigid_amplitude_squared
from vibroadhesion.models.stiffness import dynamic_stiffness

EXPONENTS = [0.05, N_PUBLISHED, 4.0]  # the published n and the two extremes the issue names


def eq122_lhs_mp(Abar: float, omega_check: float, n: float) -> mp.mpf:
    """Eq. (122) as printed, with abar_m = J0^(2/3) (Eq. 123), in 30-digit arithmetic."""
    j0, jc1, j1 = j_integrals_mp(Abar, n)
    c, a, w = mp.mpf(CHI0), mp.mpf(Abar), mp.mpf(omega_check)
    am = mp.cbrt(j0) ** 2
    first = mp.mpf(2) ** (mp.mpf(4) / 3) * c**4 / mp.mpf(3) ** (mp.mpf(8) / 3) * am * jc1**2
    second = (mp.mpf(2) ** (mp.mpf(8) / 3) * c**2 / (mp.mpf(3) ** (mp.mpf(4) / 3) * w**2)) * a**2 * am**2 * (
        1 - j1 / (4 * am ** mp.mpf(1.5))
    ) ** 2
    return first + second


# ----------------------------------------------------------------- Eq. (122): root and uniqueness


@pytest.mark.parametrize("n", EXPONENTS)
@pytest.mark.parametrize("omega_check", [1e1, 1e3, 1e6, 1e9])
@pytest.mark.parametrize("h1_um", [20.0, 100.0])
def test_eq122_root_satisfies_printed_equation_with_mpmath_j_to_1e11(h1_um: float, omega_check: float, n: float) -> None:
    """Reference: Eq. (122) with Eq. (123), evaluated with 30-digit J-integrals at the returned root.

    Tolerance 1e-11 relative on the squared amplitude: the J-integrals are accurate to 1e-12
    (test_integrals) and enter squared.
    """
    eta1 = h1_um * 1e-6 / RADIUS
    sol = nominal_point_contact(eta1, omega_check, CHI0, GentSchultz(n))
    residual = float(abs(eq122_lhs_mp(float(sol.Abar), omega_check, n) / mp.mpf(eta1) ** 2 - 1))
    assert residual < 1e-11, f"Abar = {float(sol.Abar)!r}: relative residual {residual:.2e}"
    j0 = j_integrals_mp(float(sol.Abar), n)[0]
    assert abs(float(sol.abar_m) / float(mp.cbrt(j0) ** 2) - 1) < 1e-12  # Eq. (123)
    assert abs(float(sol.w_eff_ratio) / float(j0**2) - 1) < 1e-12  # Eq. (49)


@pytest.mark.parametrize("n", [0.05, N_PUBLISHED, 1.0, 2.0, 4.0, 5.9])
@pytest.mark.parametrize("omega_check", [1e1, 1e3, 1e6, 1e9, math.inf])
def test_eq122_lhs_rises_strictly_from_zero_to_infinity_so_one_root(omega_check: float, n: float) -> None:
    """Uniqueness (proof in the docstring of vibroadhesion.models.refined, valid for n < 6): the
    left-hand side of Eq. (122) along abar_m = J0^(2/3) rises strictly with Abar, from 0 to
    infinity, so Eq. (122) has exactly one root for every eta1 > 0 and omega_check > 0.
    Checked on Abar in logspace(-12, 12, 2401); the ends: exactly 0 at Abar = 0, and above
    eta1^2 = 1e-4 (h1 = 515 um) at Abar = exp(min(60/n, 150)) (an Abar^n of e^60, far past any root).
    """
    law = GentSchultz(n)
    Abar = np.logspace(-12, 12, 2401)
    lhs = rigid_amplitude_squared(Abar, law, CHI0, omega_check, nominal_point_contact_closure)
    assert np.all(np.diff(lhs) > 0), Abar[np.argmin(np.diff(lhs))]
    ends = rigid_amplitude_squared(np.array([0.0, math.exp(min(60.0 / n, 150.0))]), law, CHI0, omega_check,
                                   nominal_point_contact_closure)
    assert ends[0] == 0.0 and ends[1] > 1e-4


# ----------------------------------------------------------------- h1 -> 0: the small-amplitude limit


def small_amplitude_abar_mp(eta1: float, omega_check: float, n: float) -> float:
    """Independent reference for h1 -> 0: J0 -> 1, J1 -> 1 and, from sqrt(1 + u) and
    1/sqrt(1 + u) to first order in u = |Abar cos x|^n, Jc1 -> -(Abar^n/pi) int_0^pi |cos x|^(n+1) dx
    = -Abar^n Gamma(n/2 + 1) / (sqrt(pi) Gamma(n/2 + 3/2)). Eq. (122) then reads
    (2^(4/3) chi0^4 / 3^(8/3)) K^2 Abar^(2n) + (2^(8/3) chi0^2 / (3^(4/3) omega_check^2)) (9/16) Abar^2 = eta1^2,
    solved here with mpmath in ln Abar.
    """
    mp.mp.dps = 30
    n_ = mp.mpf(n)
    k = mp.gamma(n_ / 2 + 1) / (mp.sqrt(mp.pi) * mp.gamma(n_ / 2 + mp.mpf(3) / 2))
    c, w, e = mp.mpf(CHI0), mp.mpf(omega_check), mp.mpf(eta1)
    c1 = mp.mpf(2) ** (mp.mpf(4) / 3) * c**4 / mp.mpf(3) ** (mp.mpf(8) / 3) * k**2
    c2 = mp.mpf(2) ** (mp.mpf(8) / 3) * c**2 / (mp.mpf(3) ** (mp.mpf(4) / 3) * w**2) * mp.mpf(9) / 16

    def g(z):
        return mp.log(c1 * mp.exp(2 * n_ * z) + c2 * mp.exp(2 * z)) - 2 * mp.log(e)

    return float(mp.exp(mp.findroot(g, (mp.mpf(-200), mp.mpf(50)), solver="anderson")))


@pytest.mark.parametrize("n", EXPONENTS)
@pytest.mark.parametrize("omega_check", [1e1, 1e4, 1e9])
def test_h1_to_zero_abar_vanishes_and_abar_m_tends_to_one(omega_check: float, n: float) -> None:
    """h1 -> 0: Abar -> 0 along the small-amplitude closed form, abar_m -> 1 (Eq. 123 with J0(0) = 1),
    w_eff -> w0 and A/a_m -> 0. eta1 = 1e-10 .. 1e-14. The closed form drops terms of relative size
    Abar^n (next term of the expansions of J0, Jc1); tolerance 10 Abar^n plus 1e-9.
    """
    law = GentSchultz(n)
    for eta1 in (1e-10, 1e-12, 1e-14):
        sol = nominal_point_contact(eta1, omega_check, CHI0, law)
        Abar = float(sol.Abar)
        reference = small_amplitude_abar_mp(eta1, omega_check, n)
        assert abs(Abar / reference - 1) < 10 * Abar**n + 1e-9, (eta1, Abar, reference)
        assert abs(float(sol.abar_m) - 1) < 10 * Abar ** (2 * n) + 1e-12
        assert abs(float(sol.w_eff_ratio) - 1) < 10 * Abar ** (2 * n) + 1e-12
    assert 0 < float(sol.A_over_am) < 1e-6


def test_h1_zero_gives_the_static_nominal_point_contact_exactly() -> None:
    """h1 = 0 is the static JKR nominal point contact: Abar = 0, abar_m = 1, w_eff = w0 (Eq. 86)."""
    sol = nominal_point_contact(0.0, 1e5, CHI0, GentSchultz(N_PUBLISHED))
    assert (float(sol.Abar), float(sol.abar_m), float(sol.w_eff_ratio), float(sol.A_over_am)) == (0.0, 1.0, 1.0, 0.0)


# ----------------------------------------------------------------- A/a_m > 1: outside the model, reported


def test_large_amplitude_at_low_frequency_is_reported_outside_the_model_not_crashed() -> None:
    """h1 = 100 um .. 1 mm at omega_check = 10 gives A/a_m > 1 (geometrically impossible): the
    table keeps the rows with finite values so the figure can shade them, and the counts the
    fig6 rule logs follow from the column. The 20 um, 200 Hz point of the paper is inside A <= 0.1 a_m.
    """
    table = fig6_table([20.0, 100.0, 1000.0], np.array([1e1, 3.0e6]), chi0=CHI0, radius=RADIUS, n=N_PUBLISHED)
    assert np.isfinite(table[FIG6_COLUMNS].to_numpy()).all()
    low = table[table["omega_check"] == 1e1]
    assert (low["A_over_am"] > 1).all()
    # A/a_m from Eq. (45) and Eq. (86) (docs/errata.md E1), recomputed from the table's own columns
    c_o = 2 ** (1 / 3) * 3 ** (-2 / 3) * CHI0
    recomputed = table["Abar"] / (table["omega_check"] * c_o * table["abar_m"])
    assert np.allclose(table["A_over_am"], recomputed, rtol=1e-14, atol=0)
    experiment = table[(table["h1_um"] == 20.0) & (table["omega_check"] == 3.0e6)]
    assert float(experiment["A_over_am"].iloc[0]) < APPLICABILITY_LIMIT


# ----------------------------------------------------------------- Fig. 7: omega_check -> infinity


#: omega_check far enough out that the frequency terms (~ Abar/omega_check) are negligible: the
#: high-frequency Abar is ~1e1 (n = 4), ~1e3 (n = 0.531) but up to ~1e37 for n = 0.05.
HIGH_OMEGA_CHECK = {0.05: 1e50, N_PUBLISHED: 1e14, 4.0: 1e14}


@pytest.mark.parametrize("n", EXPONENTS)
def test_fig7_high_frequency_limit_equals_fig4_leading_order_to_1e9(n: float) -> None:
    """Reference: Fig. 4's leading-order pull-off, Eq. (72) (frequency independent). Eq. (106)'s
    frequency term is (3 Abar/(chi0 omega_check))^2 relative to the first: below 1e-20 at
    HIGH_OMEGA_CHECK, so the Fig. 7 table must equal Fig. 4's to 1e-9 there (and at omega_check = inf).
    """
    fig7 = fig7_table(AMPLITUDES_UM, np.array([HIGH_OMEGA_CHECK[n], math.inf]), chi0=CHI0, radius=RADIUS, n=n)
    w0 = W0  # J/m^2, Fig. 4 caption; E* chosen so that Eq. (64) gives chi0 = CHI0
    params = GentSchultzParameters(w0=w0, n=n, v0=V0)
    fig4 = fig4_table(params, [200.0], np.array(AMPLITUDES_UM),
                              radius=RADIUS, reduced_modulus=9 * math.pi * w0 / (RADIUS * CHI0**3))
    leading = fig4[fig4["model"] == "leading"].set_index("h1_um")["pulloff_ratio"]
    for omega_check, rows in fig7.groupby("omega_check"):
        got = rows.set_index("h1_um")["pulloff_ratio"]
        assert np.allclose(got.to_numpy(), leading.loc[got.index].to_numpy(), rtol=1e-9, atol=0), omega_check
    # and the refined ratio approaches it from below at finite frequency (delta_s only adds, Eq. 106)
    finite = fig7_table(AMPLITUDES_UM, np.array([1e3]), chi0=CHI0, radius=RADIUS, n=n)
    assert np.all(finite["pulloff_ratio"].to_numpy() < leading.loc[finite["h1_um"]].to_numpy())


# ----------------------------------------------------------------- Fig. 8: the two limits of Eq. (118)


@pytest.mark.parametrize("n", EXPONENTS)
def test_fig8_storage_stiffness_tends_to_flat_punch_as_omega_check_to_infinity(n: float) -> None:
    """Greenwood–Johnson: S'/(2E* a_m) -> 1 as omega_check -> infinity (Eq. 119). The deviation is
    O(r^2), r = delta_s/delta_c of Eq. (120) ~ Abar/omega_check; at HIGH_OMEGA_CHECK below 1e-9.
    """
    fig6 = fig6_table(AMPLITUDES_UM, np.array([HIGH_OMEGA_CHECK[n]]), chi0=CHI0, radius=RADIUS, n=n)
    fig8 = fig8_table(fig6, chi0=CHI0, n=n)
    assert np.allclose(fig8["S_storage_rel"], 1.0, rtol=0, atol=1e-9)
    assert np.all(np.abs(fig8["S_loss_rel"]) < 1e-4) and np.all(np.abs(fig8["phase_rad"]) < 1e-4)


LOW_OMEGA_CHECK = {0.05: 1e-60, N_PUBLISHED: 1e-6, 4.0: 1e-3}


@pytest.mark.parametrize("n", EXPONENTS)
@pytest.mark.parametrize("h1_um", [20.0, 100.0])
def test_fig8_storage_stiffness_low_frequency_limit_matches_eq_c2_form(h1_um: float, n: float) -> None:
    """omega_check -> 0: S'/(2E* a_m) -> (1 - q)^-1 (1 - 3q), q = J1/(4 abar_m^(3/2)) (text after
    Eq. 123), evaluated with 30-digit J-integrals at the solution's Abar. Eq. (118) differs from it by
    (r - r_P)/(r (1 + r^2)) with r = delta_s/delta_c of Eq. (120), also evaluated in mpmath: tolerance
    2/r^2 + 1e-10. Along the solution r grows only like omega_check^(-n) (Abar ~ omega_check eta1), so
    the omega_check needed for r > 1e3 depends strongly on n.
    """
    law = GentSchultz(n)
    omega_check = LOW_OMEGA_CHECK[n]
    sol = nominal_point_contact(h1_um * 1e-6 / RADIUS, omega_check, CHI0, law)
    s = dynamic_stiffness(sol.Abar, sol.abar_m, CHI0, omega_check, law)
    j0, jc1, j1 = j_integrals_mp(float(sol.Abar), n)
    q = j1 / (4 * j0)  # abar_m^(3/2) = J0, Eq. (123)
    r = -(mp.mpf(6) ** (mp.mpf(2) / 3)) * mp.mpf(float(sol.Abar)) * mp.cbrt(j0) * (1 - q) / (
        mp.mpf(omega_check) * mp.mpf(CHI0) * jc1)
    assert r > 1e3
    reference = float((1 - 3 * q) / (1 - q))
    assert abs(float(s.S_storage_rel) - reference) < float(2 / r**2) + 1e-10, (float(s.S_storage_rel), reference)


def test_fig8_storage_stiffness_is_one_third_as_abar_to_zero() -> None:
    """Eq. (C.2) at a_m = a_o: with J0(0) = J1(0) = 1 and abar_m = 1 the low-frequency limit is
    (1 - 1/4)^-1 (1 - 3/4) = 1/3 exactly. At omega_check = 1e-12 and h1 = 1 nm (n = 0.531) Abar ~ 1e-18,
    J1 - 1 and J0 - 1 are O(Abar^(2n)) and 1/r^2 ~ 1e-12: tolerance 1e-9.
    """
    law = GentSchultz(N_PUBLISHED)
    sol = nominal_point_contact(1e-9 / RADIUS, 1e-12, CHI0, law)
    s = dynamic_stiffness(sol.Abar, sol.abar_m, CHI0, 1e-12, law)
    assert float(sol.Abar) < 1e-15
    assert abs(float(s.S_storage_rel) - 1.0 / 3.0) < 1e-9


def test_fig8_along_fig6_grid_goes_from_one_third_to_one_monotonically() -> None:
    """Across the figure's range (omega_check 1e1 .. 1e9) the storage stiffness lies between the two
    limits 1/3 and 1 and increases with frequency for every amplitude (paper's Fig. 8).
    """
    grid = np.logspace(1, 9, 81)
    fig8 = fig8_table(fig6_table(AMPLITUDES_UM, grid, chi0=CHI0, radius=RADIUS, n=N_PUBLISHED),
                              chi0=CHI0, n=N_PUBLISHED)
    for _, rows in fig8.groupby("h1_um"):
        s = rows.sort_values("omega_check")["S_storage_rel"].to_numpy()
        assert np.all(np.diff(s) > 0) and s[0] > 1 / 3 - 1e-12 and s[-1] < 1 + 1e-12
