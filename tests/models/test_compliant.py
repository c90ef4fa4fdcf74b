"""Compliant fixation, Fig. 5 (Sec. 3.5.3): Eqs. (87), (90)-(96) and their continuation.

Independent references: a curve with known folds (the unit circle) for the continuation code;
the scalar root scan of Eq. (90) along the unique abar_m(Abar) of Eq. (87) (no continuation) for
the number of solutions; the printed polynomial forms of Eqs. (87) and (90); the rigid-fixation
solvers of Figs. 6 and 7 (kappa -> infinity); the free-indenter Eqs. (57)-(59) solved as printed
(kappa -> 0); the exact anti-resonance of Appendix B (zeta = 0).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from conftest import CHI0, ETA1, N_PUBLISHED, NU0, OMEGA_BAR_200HZ
from mpmath_reference import j_integrals_mp
from scipy.optimize import root
from test_leading_order_steady_state import printed_eq_67_log_excess, printed_eq_87_terms

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.integrals import j_integrals
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import SteadyState
from vibroadhesion.experiments.figure_tables.fig5 import fig5_tables
from vibroadhesion.models.compliant import (
    amplitude_residual_on_closure,
    mean_balance_excess,
    newton_at_frequency,
    pulloff_by_scan,
    residual,
    residual_linear,
    solutions_by_scan,
    static_abar_0,
)
from vibroadhesion.models.leading_pulloff import pulloff_closure
from vibroadhesion.models.refined import nominal_point_contact, pulloff_refined
from vibroadhesion.models.response_curve import NOTCH_FLOOR, trace_response_curve
from vibroadhesion.numerics.continuation import (
    ContinuationSettings,
    _corrected_at,
    crossings,
    locate_folds,
    trace,
)

LAW = GentSchultz(N_PUBLISHED)
SCAN = np.linspace(-40.0, 40.0, 4001)  # ln Abar grid of the independent root scan
FOLDING = Fixation.compliant(kappa=1e-3, zeta=0.0, nu0=NU0, mu=0.0)  # the folded curve of Fig. 5


def solved(record: SteadyState) -> list[tuple[float, float]]:
    """(abar_m, Abar) of every element of a record of level refined, in its order; every element must be solved."""
    assert record.level == "refined" and record.ok.all(), record
    return list(zip(np.ravel(record.abar_m).tolist(), np.ravel(record.Abar).tolist(), strict=True))


# ----------------------------------------------------------------- continuation on a known curve


def test_continuation_follows_the_unit_circle_through_both_folds_of_x() -> None:
    """F(x, y) = x^2 + y^2 - 1 with parameter x: folds at (1, 0) and (-1, 0). Starting at (0, -1)
    towards +x the trace passes both and comes back; folds located to 1e-12, points on the circle to 1e-12.
    """
    circle = lambda p: (p[:, 0] ** 2 + p[:, 1] ** 2 - 1.0)[:, None]  # noqa: E731
    visited_upper_half = []

    def stop(x: np.ndarray) -> bool:  # back in the starting quadrant after a full turn
        visited_upper_half.append(x[1] > 0)
        return any(visited_upper_half) and x[0] > 0 and x[1] < 0

    curve = trace(circle, np.array([0.0, -1.0]), np.array([1.0, 0.0]), stop)
    assert np.max(np.abs(np.hypot(curve.points[:, 0], curve.points[:, 1]) - 1)) < 1e-12
    folds = locate_folds(circle, curve)
    assert len(folds) == 2
    assert sorted(np.round(folds[:, 0], 12)) == [-1.0, 1.0] and np.max(np.abs(folds[:, 1])) < 1e-6
    # x = 0.5 is crossed on both halves (y = +-sqrt(3)/2; the chord interpolation is within the step^2)
    ys = sorted(g[1] for g in crossings(curve, 0.5))
    assert len(ys) == 2 and abs(ys[0] + math.sqrt(3) / 2) < 0.02 and abs(ys[1] - math.sqrt(3) / 2) < 0.02


# ----------------------------------------------------------------- the folded curve


@pytest.fixture(scope="module")
def folded() -> tuple:
    return trace_response_curve(FOLDING, CHI0, ETA1, LAW)


def test_corrected_point_lies_on_the_circle_in_the_arclength_hyperplane() -> None:
    """From x0 = (0, -1) along t0 = (1, 0), sigma = 0.6: the point of the unit circle with x = 0.6 is
    (0.6, -0.8) and its unit tangent oriented along t0 is (0.8, 0.6) (closed forms). Point to 1e-12 (the
    corrector's tolerance on F), tangent to 1e-8 (central differences with step 1e-7: rounding ~1e-9).
    """
    circle = lambda p: (p[:, 0] ** 2 + p[:, 1] ** 2 - 1.0)[:, None]  # noqa: E731
    x0, t0, settings = np.array([0.0, -1.0]), np.array([1.0, 0.0]), ContinuationSettings()
    jac0 = np.array([[0.0, -2.0]])  # F'(x0), exact
    x, t = _corrected_at(0.6, circle, x0, t0, jac0, settings)
    assert np.max(np.abs(x - [0.6, -0.8])) < 1e-12 and np.max(np.abs(t - [0.8, 0.6])) < 1e-8


def test_continuation_passes_both_folds_and_reaches_the_end_of_the_range(folded) -> None:
    """kappa = 1e-3, zeta = 0 folds near omega_bar = 10.6 and 11.1. The trace locates two folds
    (the Jacobian in (ln abar_m, ln Abar) is singular there: smallest/largest singular value < 1e-6),
    and continues to omega_bar = 50 on the upper piece.
    """
    assert len(folded.folds) == 2
    lo, hi = sorted(np.exp(folded.folds[:, 0]))
    assert 10.0 < lo < hi < 12.0
    upper = folded.pieces[-1]
    assert math.isclose(math.exp(upper.points[0, 0]), 50.0, rel_tol=1e-12)  # the upper piece starts at the top
    for fold in folded.folds:
        from vibroadhesion.numerics.continuation import jacobian

        jac = jacobian(lambda x: residual(x, FOLDING, CHI0, ETA1, LAW), fold, 1e-7)[:, 1:]
        sv = np.linalg.svd(jac, compute_uv=False)
        assert sv[-1] / sv[0] < 1e-6, sv


def test_three_solutions_between_the_folds_each_satisfying_eqs_87_and_90_to_1e10(folded) -> None:
    """Between the folds the curve crosses omega_bar three times. Each crossing, polished by Newton,
    satisfies the printed polynomial Eqs. (87) and (90) to 1e-10 relative, and the three are the
    three roots found independently by the scalar scan (no continuation) to 1e-9.
    """
    lo, hi = sorted(np.exp(folded.folds[:, 0]))
    for omega_bar in (lo + 0.05 * (hi - lo), 0.5 * (lo + hi), hi - 0.05 * (hi - lo)):
        on_curve = sorted(solved(folded.steady_states_at(omega_bar, LAW)), key=lambda s: s[1])
        assert len(on_curve) == 3
        for abar_m, Abar in on_curve:
            r87, r90 = residual_linear(omega_bar, abar_m, Abar, FOLDING, CHI0, ETA1, LAW)
            assert abs(r87) < 1e-10 and abs(r90) < 1e-10, (omega_bar, abar_m, Abar, r87, r90)
        scanned = sorted(solved(solutions_by_scan(omega_bar, FOLDING, CHI0, ETA1, LAW, SCAN)), key=lambda s: s[1])
        assert len(scanned) == 3
        assert np.allclose(np.array(on_curve), np.array(scanned), rtol=1e-9, atol=0)
    for omega_bar in (0.5 * lo, 2.0 * hi):  # outside the fold interval: one solution, both ways
        assert len(solved(folded.steady_states_at(omega_bar, LAW))) == 1 == len(
            solved(solutions_by_scan(omega_bar, FOLDING, CHI0, ETA1, LAW, SCAN)))


def test_the_records_of_the_compliant_level_are_sorted_and_say_where_there_is_no_solution(folded) -> None:
    """The records of level refined: the three solutions between the folds by increasing Abar, with
    w_eff/w0 = J0^2 (Eq. 49) and A/a_m (corrected Eq. 98, omega_check = omega_bar/nu0) of their Abar and
    abar_m to 1e-13; no crossing of the traced curve (omega_bar beyond its range), no root on a scan grid
    far below the solutions, and a Newton iteration from Abar = 1e-100 (ln Abar 230 below the solution,
    while 40 steps clipped to 2 in ln Abar cover 80) are statuses with NaN numbers, not numbers and not
    exceptions.
    """
    lo, hi = sorted(np.exp(folded.folds[:, 0]))
    states = folded.steady_states_at(0.5 * (lo + hi), LAW)
    assert states.status.tolist() == ["ok"] * 3 and np.all(np.diff(states.Abar) > 0) and states.stable is None
    j0 = np.array([float(j_integrals_mp(a, N_PUBLISHED)[0]) for a in states.Abar])
    assert np.allclose(states.w_eff_ratio, j0**2, rtol=1e-13, atol=0)
    c_o = 2 ** (1 / 3) * 3 ** (-2 / 3) * CHI0
    expected = states.Abar * NU0 / (0.5 * (lo + hi) * c_o * states.abar_m)
    assert np.allclose(states.A_over_am, expected, rtol=1e-13, atol=0)
    outside = folded.steady_states_at(100.0, LAW)
    below = solutions_by_scan(2.0, FOLDING, CHI0, ETA1, LAW, np.linspace(-60.0, -50.0, 11))
    no_pulloff = pulloff_by_scan(2.0, FOLDING, CHI0, ETA1, LAW, np.linspace(-60.0, -50.0, 11))
    for record in (outside, below, no_pulloff):
        assert record.level == "refined" and record.status.tolist() == ["no_solution"] and record.message
        assert np.isnan(record.abar_m).all()
    assert np.isnan(below.Abar).all() and np.isnan(no_pulloff.pulloff_ratio).all()
    diverged = newton_at_frequency(2.0, FOLDING, CHI0, ETA1, LAW, (static_abar_0(FOLDING, CHI0), 1e-100))
    assert diverged.status == "not_converged" and np.isnan(diverged.Abar) and "Newton" in diverged.message


# ----------------------------------------------------------------- zeta = 0, omega_bar = 1


def test_zeta_zero_anti_resonance_splits_the_curve_into_two_pieces_ending_in_the_notch(folded) -> None:
    """Appendix B: at omega_bar = 1 and zeta = 0 the forcing vanishes and Abar = 0 exactly. The two
    pieces run from each end of the range into the notch, ending when A/a_m < NOTCH_FLOOR, from below
    and from above omega_bar = 1; the approach is to the static contact radius (Eq. 82).
    """
    lower, upper = folded.pieces
    for piece, side in ((lower, -1.0), (upper, 1.0)):
        end = piece.points[-1]
        assert folded.A_over_am(end[None, :])[0] < NOTCH_FLOOR
        assert side * end[0] > 0 and abs(end[0]) < 1e-2
        assert abs(math.exp(end[1]) / static_abar_0(FOLDING, CHI0) - 1) < 1e-6


def test_zeta_zero_at_omega_bar_one_is_exact_and_nearby_solutions_tend_to_it() -> None:
    """Just off omega_bar = 1 (1 +- 1e-9) Newton from the static state converges to Abar < 1e-12 and
    abar_m within 1e-9 of the static root of Eq. (82); the Fig. 5 table carries the exact point.
    """
    static = static_abar_0(FOLDING, CHI0)
    for omega_bar in (1 - 1e-9, 1 + 1e-9):
        (abar_m, Abar), = solved(newton_at_frequency(omega_bar, FOLDING, CHI0, ETA1, LAW, (static, 1e-14)))
        assert Abar < 1e-12 and abs(abar_m / static - 1) < 1e-9
    curves, _, _ = fig5_tables([FOLDING], CHI0, ETA1, N_PUBLISHED, {}, (0.1, 50.0), 20)
    exact = curves[curves["branch"] == "anti-resonance"]
    assert len(exact) == 1 and exact["omega_bar"].iloc[0] == 1.0 and exact["Abar"].iloc[0] == 0.0
    assert exact["abar_m"].iloc[0] == static


@pytest.mark.parametrize(("abar_m", "j0", "mu"), [(0.3, 1.0, 1e-6), (1.0, 2.5, 0.0), (4.0, 1.3, 1e-6)])
def test_mean_balance_excess_is_printed_eq_87_over_its_j0_part(abar_m: float, j0: float, mu: float) -> None:
    """positive/negative - 1 of Eq. (87) = (sum of the printed terms) / (minus its J0 terms), 30 digits;
    tolerance 1e-13 times the largest term over the J0 part (a few roundings per term).
    """
    kappa = 0.1
    with mp.workdps(30):
        terms = printed_eq_87_terms(abar_m, mp.mpf(j0), kappa, mu)
        j0_part = -(terms[2] + terms[3])
        ours = mean_balance_excess(math.log(abar_m), j0, Fixation.compliant(kappa, 0.0, NU0, mu), CHI0)
        assert abs(float(ours - sum(terms) / j0_part)) < 1e-13 * float(max(abs(t) for t in terms) / j0_part)


@pytest.mark.parametrize(("kappa", "omega_bar", "zeta"), [(1e-3, 17.85, 0.01), (1e-2, 0.5, 0.05), (1e-2, 3.0, 0.0)])
def test_amplitude_residual_at_a_cr_tends_to_half_the_log_of_printed_eq_67(kappa, omega_bar, zeta) -> None:
    """Eq. (90) along a_m = a_cr (Eq. 61) in logarithms becomes Eqs. (67)-(69) as omega_check -> infinity: with
    nu0 = 1e-15 it equals half ln of the printed Eq. (67) over eta1^2 (30-digit J's) up to the refined terms
    of Eqs. (94), (96), O(Abar nu0/omega_bar); tolerance 1e-12 + 10 Abar nu0/omega_bar.
    """
    nu0 = 1e-15
    p = Fixation.compliant(kappa, zeta, nu0, 0.0)
    for Abar in (0.01, 3.0, 1e4):
        ours = amplitude_residual_on_closure(np.log([Abar]), math.log(omega_bar), p, CHI0, ETA1, LAW, pulloff_closure)[0]
        with mp.workdps(30):
            printed = printed_eq_67_log_excess(Abar, kappa, omega_bar, zeta, ETA1, j_integrals_mp(Abar, LAW.n)[:2])
        assert abs(ours - 0.5 * printed) < 1e-12 + 10 * Abar * nu0 / omega_bar


def test_static_contact_radius_solves_eq_82() -> None:
    """Eq. (82) in a_0/R (not the a_o-scaled Eq. 87 the code uses), mu = 1e-4, kappa = 0.01, in mpmath: 1e-12."""
    p = Fixation.compliant(kappa=0.01, zeta=0.0, nu0=NU0, mu=1e-4)
    r = mp.mpf(static_abar_0(p, CHI0)) * mp.mpf(2) ** (mp.mpf(1) / 3) * mp.mpf(3) ** (-mp.mpf(2) / 3) * mp.mpf(CHI0)
    lhs = r**2 * (mp.mpf(4) / 3 * r + mp.mpf(p.kappa)) - mp.sqrt(2) * mp.mpf(CHI0) ** 1.5 / 3 * mp.sqrt(r) * (2 * r + mp.mpf(p.kappa))
    assert abs(float(lhs / mp.mpf(p.mu) - 1)) < 1e-12


# ----------------------------------------------------------------- kappa -> infinity: Figs. 6 and 7


@pytest.mark.parametrize("zeta", [0.0, 0.05])
@pytest.mark.parametrize("omega_bar", [0.5, OMEGA_BAR_200HZ, 40.0])
def test_stiff_fixation_reproduces_rigid_figs_6_and_7_to_1e6(omega_bar: float, zeta: float) -> None:
    """kappa = 1e12: Eq. (87) -> abar_m^(3/2) = J0 (Eq. 123) and Eq. (90) -> Eq. (100), so the solution is
    Fig. 6's nominal point contact at omega_check = omega_bar/nu0; with a_m = a_cr it is Fig. 7's Eq. (106).
    The differences are O(1/kappa): tolerance 1e-6.
    """
    p = Fixation.compliant(kappa=1e12, zeta=zeta, nu0=NU0, mu=0.0)
    (abar_m, Abar), = solved(solutions_by_scan(omega_bar, p, CHI0, ETA1, LAW, SCAN))
    rigid = nominal_point_contact(ETA1, omega_bar / NU0, CHI0, LAW)
    assert abs(Abar / float(rigid.Abar) - 1) < 1e-6 and abs(abar_m / float(rigid.abar_m) - 1) < 1e-6
    roots = pulloff_by_scan(omega_bar, p, CHI0, ETA1, LAW, SCAN)
    assert roots.level == "refined" and roots.status.tolist() == ["ok"]
    abar_cr = float(roots.Abar_cr[0])
    assert abs(abar_cr / float(pulloff_refined(ETA1, CHI0, omega_bar / NU0, LAW).Abar_cr) - 1) < 1e-6


# ----------------------------------------------------------------- kappa -> 0: free indenter, Eqs. (57)-(59)


def free_indenter(beta: float, mu: float, n: float, start: tuple[float, float]) -> tuple[float, float]:
    """Eqs. (57)-(59) with k = c = 0, in a_o units: with c_o = a_o/R and beta = m omega^2/(E* R),
    Eq. (58) (erratum: the square root does not cover Jc1) gives |Xi_c|/(E* R^2) = c_o^2 abar_m^(1/2) |Jc1| |beta - 2 c_o abar_m|
    = beta eta1 (Eq. 57), and Eq. (59), P_m = m g, reads c_o [(4/3) abar_m^3 - 2 J0 abar_m^(3/2)] = mu / c_o^2.
    Solved with scipy's hybrid root finder on these printed equations (J-integrals checked against
    mpmath in test_integrals), independently of the compliant-fixation code; ``start`` (abar_m, Abar) is
    only the initial guess.
    """
    c = 2 ** (1 / 3) * 3 ** (-2 / 3) * CHI0

    def equations(v: np.ndarray) -> list[float]:
        am, a = math.exp(v[0]), math.exp(v[1])
        j0, jc1, _ = (float(x[0]) for x in j_integrals(np.array([a]), n))
        return [math.log(c**2 * math.sqrt(am) * abs(jc1) * abs(beta - 2 * c * am)) - math.log(beta * ETA1),
                c**3 * ((4 / 3) * am**3 - 2 * j0 * am**1.5) / mu - 1.0]

    sol = root(equations, np.log(start), method="hybr", tol=1e-14)
    assert max(abs(r) for r in equations(sol.x)) < 1e-12, sol.message
    return math.exp(sol.x[0]), math.exp(sol.x[1])


@pytest.mark.parametrize("beta", [1e-2, 1e-1])
def test_soft_fixation_reproduces_the_free_indenter_eqs_57_to_59(beta: float) -> None:
    """kappa = 1e-10 at omega_bar = sqrt(beta/kappa) (so m omega^2 = beta E* R stays fixed), zeta = 0, mu = 1e-5:
    the refined compliant solution tends to the leading-order free indenter. Differences: O(kappa/beta) from
    k, O(1/omega_check) from the refined terms (omega_check ~ 1e9 here): tolerance 1e-6.
    """
    kappa, mu = 1e-10, 1e-5
    p = Fixation.compliant(kappa=kappa, zeta=0.0, nu0=NU0, mu=mu)
    omega_bar = math.sqrt(beta / kappa)
    found = solved(solutions_by_scan(omega_bar, p, CHI0, ETA1, LAW, SCAN))
    assert len(found) == 1
    abar_m, Abar = found[0]
    reference_am, reference_Abar = free_indenter(beta, mu, N_PUBLISHED, (1.1 * abar_m, 0.9 * Abar))
    assert abs(abar_m / reference_am - 1) < 1e-6 and abs(Abar / reference_Abar - 1) < 1e-6, (found, reference_am, reference_Abar)
