"""Leading-order steady state for any fixation (Sec. 3.1): Eqs. (43), (50)–(54) and their limits.

Independent references, all written here from the printed equations (in dimensional form with
E* = R = 1, w0 = chi0^3/(9 pi) from Eq. 64, a_o = (2 pi w0)^(1/3) from its definition, Eq. 86):

* rigid limit: Eqs. (55)–(56), solved in Abar (Eq. 55 gives a_m explicitly) with 30-digit
  mpmath J-integrals (``mpmath_reference``);
* free indenter: Eqs. (57), (58) (corrected, docs/errata.md) and (59) (a quadratic in a_m^(3/2)),
  solved in Abar with mpmath J-integrals;
* static limit: Eq. (82) with the load group on the right, a polynomial in (a/R)^(1/2), by
  ``mpmath.polyroots``; its stability from the sign of the polynomial's slope;
* compliant fixation: the residuals of Eq. (87) and of Eq. (43) with Eqs. (50)–(51) at the roots
  (30-digit J's), and the number of roots counted along Abar (Eq. 87 solved for abar_m at each
  Abar by bisection, sign changes of Eq. 43 counted; J's from the quadrature, which
  test_integrals checks against mpmath to 1e-12);
* Eqs. (67)–(69) and (72) for a_m = a_cr, and the roots of the printed Eqs. (67)–(69) (30-digit J's at
  each root, sign changes counted on a grid) for the pull-off of any fixation; its limits (rigid, stiff
  spring, mass far above resonance: Eq. 72) and the refined compliant pull-off as omega_check -> infinity;
  Appendix B's anti-resonance (Abar = 0 exactly);
* the nominal point contact of :mod:`vibroadhesion.models.refined` at omega_check = inf (Eqs. 99/123).
"""

from __future__ import annotations

import math
from dataclasses import replace

import mpmath as mp
import numpy as np
import pytest
from conftest import CHI0, ETA1, N_PUBLISHED
from mpmath_reference import j_integrals_mp

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.integrals import j_integrals
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import SteadyState
from vibroadhesion.models.compliant import pulloff_by_scan
from vibroadhesion.models.leading_order import (
    SCAN_STEP,
    MeanBalance,
    balance_state,
    in_monotone_tail,
    indentation_amplitude,
    internal_variables,
    mean_balance_residual,
    monotone_tail_start,
    scan_segments,
    steady_states,
)
from vibroadhesion.models.leading_pulloff import critical_internal_variables, critical_log_excess, pulloff_leading
from vibroadhesion.models.refined import nominal_point_contact
from vibroadhesion.numerics.roots import NoRootError

MU_SMALL = 1e-6  # m g/(E* R^2): about a third of the JKR pull-off force, (3/4) c_o^3 = 2.9e-6
EXPONENTS = [0.05, N_PUBLISHED, 4.0]


def spring(kappa: float, omega_bar: float, zeta: float, mu: float = 0.0) -> tuple[Fixation, float]:
    """A spring-mass-dashpot (Eqs. 65-66) and the omega_check at which it is excited at ``omega_bar``: with
    nu0 = 1, omega_check = omega_bar exactly (Eqs. 97, 105), so d = kappa (1 - omega_bar^2 + 2 i zeta omega_bar).
    """
    return Fixation.compliant(kappa, zeta, 1.0, mu), omega_bar


def free(beta: float, mu: float = 0.0) -> tuple[Fixation, float]:
    """A free indenter (Sec. 3.1.3) with d = -beta exactly: inertia beta at omega_check = 1."""
    return Fixation.free(beta, mu), 1.0


RIGID = (Fixation.rigid(), math.inf)

#: The numbers of a steady-state record, one value per element (vibroadhesion.core.records.SteadyState).
NUMBERS = ("Abar", "abar_m", "w_eff_ratio", "A_over_am", "pm_over_abs_pjkr", "deltabar_m")


def solutions(record: SteadyState) -> list[SteadyState]:
    """The elements of a leading-order record (one per steady state), each a record of shape (); all must be ok."""
    assert record.level == "leading" and record.status.ndim == 1 and record.ok.all(), record
    assert record.stable is not None and np.all(np.diff(record.abar_m) > 0), record  # sorted by abar_m
    return [replace(record, **{name: getattr(record, name)[k] for name in ("status", "stable", *NUMBERS)})
            for k in range(record.status.size)]

with mp.workdps(30):
    W0 = mp.mpf(CHI0) ** 3 / (9 * mp.pi)  # Eq. (64) with E* = R = 1
    A_O = mp.cbrt(2 * mp.pi * W0)  # Eq. (86), a_o / R


@pytest.fixture(autouse=True)
def thirty_digits():
    """mpmath arithmetic of the references at 30 digits, whatever other modules set."""
    with mp.workdps(30):
        yield


def assert_reference_root_within(residual, mean_radius, sol, rel: float = 1e-9) -> None:
    """The reference equation, reduced to one equation in Abar, changes sign between Abar (1 -+ rel):
    its root is within ``rel`` of the returned Abar. The reference a_m/a_o at those two points (a
    smooth function of Abar) brackets the returned abar_m, with the same slack.
    """
    ends = [sol.Abar * (1 - rel), sol.Abar * (1 + rel)]
    lo, hi = (residual(a) for a in ends)
    assert lo * hi < 0, (sol, float(lo), float(hi))
    radii = sorted(float(mean_radius(a) / A_O) for a in ends)
    assert radii[0] * (1 - rel) <= sol.abar_m <= radii[1] * (1 + rel), (sol, radii)


# ----------------------------------------------------------------- rigid fixation, Eqs. (55)-(56)


@pytest.mark.parametrize(("n", "base_offset"), [(0.531, 0.3), (4.0, -0.2)])
def test_rigid_limit_equals_eqs_55_56_to_1e9(n: float, base_offset: float) -> None:
    """Reference: Eqs. (55)-(56) with 30-digit J's. Eq. (55) gives a_m = h1^2 E*/(2 pi w0 Jc1^2) explicitly,
    and Eq. (56), a_m^2/R - sqrt(2 pi w0 a_m/E*) J0 = hhat - h0 = base_offset a_o^2/R, is then one equation
    in Abar. The rigid fixation must agree with it to 1e-9, and kappa = 1e12 (omega_bar = 5, zeta = 0.05)
    with the rigid one to 1e-10: the O(1/kappa) terms are ~1e-12 (mu/kappa, 2 c_o abar_m/|d|). For base_offset >= 0 the root is
    unique (proof in steady_states' docstring); the tensile offset -0.2 also has one (no unstable branch
    above abar_m_min, unlike the static case: vibration lifts deltabar_m near abar_m = 0). n = 0.05 (Abar ~ 1e35,
    slow in mpmath) and base_offset = 0 are covered by the nominal-point-contact test below.
    """
    law = GentSchultz(n)

    def mean_radius(Abar: float) -> mp.mpf:
        return mp.mpf(ETA1) ** 2 / (2 * mp.pi * W0 * j_integrals_mp(Abar, n)[1] ** 2)

    def residual(Abar: float) -> mp.mpf:
        am = mean_radius(Abar)
        return am**2 - mp.sqrt(2 * mp.pi * W0 * am) * j_integrals_mp(Abar, n)[0] - base_offset * A_O**2

    rigid = solutions(steady_states(ETA1, Fixation.rigid(), CHI0, law, base_offset=base_offset))
    fixation, omega_check = spring(1e12, 5.0, 0.05, MU_SMALL)
    stiff = solutions(steady_states(ETA1, fixation, CHI0, law, base_offset=base_offset, omega_check=omega_check))
    assert len(rigid) == len(stiff) == 1 and rigid[0].stable and stiff[0].stable
    assert_reference_root_within(residual, mean_radius, rigid[0])
    assert abs(stiff[0].Abar / rigid[0].Abar - 1) < 1e-10 and abs(stiff[0].abar_m / rigid[0].abar_m - 1) < 1e-10
    assert abs(rigid[0].deltabar_m - base_offset) < 1e-12  # Eq. (56) itself


# ----------------------------------------------------------------- free indenter, Eqs. (57)-(59)


@pytest.mark.parametrize(("n", "beta"), [(0.05, 0.03), (0.531, 0.01), (4.0, 0.3)])
def test_free_indenter_equals_eqs_57_59_to_1e9(n: float, beta: float) -> None:
    """Reference: Eqs. (57)-(59) with 30-digit J's and beta = m omega^2/(E* R). Eq. (59),
    m g = 4 E* a_m^3/(3R) - sqrt(8 pi w0 E* a_m^3) J0, is a quadratic in a_m^(3/2) with one positive root
    (m g >= 0), and |Xi_c| = m omega^2 h1 (Eq. 57, Eq. 58 corrected: Jc1 outside the root, as Eq. 50 at
    k = 0) is then one equation in Abar. Tolerance 1e-9. beta = 0.3 puts the contact resonance at
    abar_m = 9.56, with two more roots next to it (counted independently in the next test). P_m = m g:
    P_m/|P_JKR| = mu/((3/4)(a_o/R)^3) to 1e-10 (cancellation in Eq. 52).
    """

    def mean_radius(Abar: float) -> mp.mpf:
        b = mp.sqrt(8 * mp.pi * W0) * j_integrals_mp(Abar, n)[0]
        return ((b + mp.sqrt(b**2 + mp.mpf(16) / 3 * MU_SMALL)) / (mp.mpf(8) / 3)) ** (mp.mpf(2) / 3)

    def residual(Abar: float) -> mp.mpf:
        am, jc1 = mean_radius(Abar), j_integrals_mp(Abar, n)[1]
        xi_c = mp.sqrt(2 * mp.pi * W0 * am) * beta * jc1 - mp.sqrt(8 * mp.pi * W0 * am**3) * jc1
        return abs(xi_c) - beta * mp.mpf(ETA1)

    for sol in solutions(steady_states(ETA1, Fixation.free(beta, MU_SMALL), CHI0, GentSchultz(n), omega_check=1.0)):
        assert_reference_root_within(residual, mean_radius, sol)
        assert abs(sol.pm_over_abs_pjkr / float(MU_SMALL / (mp.mpf(3) / 4 * A_O**3)) - 1) < 1e-10


# ----------------------------------------------------------------- number of roots, counted along Abar


def count_roots_along_Abar(fixation_case: tuple[float, float, float], mu: float, n: float) -> tuple[int, np.ndarray]:
    """Independent count: for each Abar on a grid of step 0.002 in ln Abar, Eq. (87) (h0 = hhat) gives
    one abar_m (one sign change in its coefficients for mu >= 0, Descartes; bisection in abar_m^(1/2)),
    and the sign changes of Eq. (43) with Eqs. (50)-(51) along that curve are the solutions. The grid
    runs from Abar = e^-25 (Jc1 ~ 0: Eq. 43 negative) to where abar_m is far above any contact
    resonance (Eq. 43 positive). ``fixation_case`` = (k, m omega^2, c omega) / (E* R).
    """
    k, m_omega2, c_omega = fixation_case
    chi = CHI0
    Abar = np.exp(np.arange(-25.0, 50.0 if n < 1 else 12.0, 0.002))
    j0, jc1, _ = j_integrals(Abar, n)
    rhs = 3 ** (4 / 3) * mu / (2 ** (2 / 3) * chi**2)

    def eq87(s: np.ndarray) -> np.ndarray:
        x = s * s
        return (2 ** (7 / 3) * chi / 3 ** (5 / 3)) * x**3 + k * x**2 - j0 * (
            (2 ** (4 / 3) * chi / 3 ** (2 / 3)) * x**1.5 + k * np.sqrt(x)) - rhs

    lo, hi = np.full_like(Abar, 1e-6), 2.0 * (1.0 + np.cbrt(j0))
    assert np.all(eq87(lo) < 0) and np.all(eq87(hi) > 0)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        up = eq87(mid) > 0
        hi, lo = np.where(up, mid, hi), np.where(up, lo, mid)
    a_m = (0.5 * (lo + hi)) ** 2 * float(A_O)
    w0 = float(W0)
    xi_c = -np.sqrt(2 * math.pi * w0 * a_m) * (k - m_omega2) * jc1 - np.sqrt(8 * math.pi * w0 * a_m**3) * jc1
    xi_s = np.sqrt(2 * math.pi * w0 * a_m) * c_omega * jc1
    eq43 = xi_c**2 + xi_s**2 - ((k - m_omega2) ** 2 + c_omega**2) * ETA1**2
    assert eq43[0] < 0 < eq43[-1]
    changes = np.flatnonzero(np.sign(eq43[:-1]) != np.sign(eq43[1:]))
    return len(changes), Abar[changes]


COUNT_CASES = [  # (n, (fixation with its mu, omega_check), (k, m omega^2, c omega)/(E* R), expected number of roots)
    (0.531, spring(0.1, 2.0, 0.0), (0.1, 0.4, 0.0), 3),
    (0.531, spring(0.1, 2.0, 0.05), (0.1, 0.4, 0.02), 1),
    (0.531, free(1.0, MU_SMALL), (0.0, 1.0, 0.0), 3),
    (4.0, free(0.3, MU_SMALL), (0.0, 0.3, 0.0), 3),
    (0.531, spring(0.01, 0.1, 0.05, MU_SMALL), (0.01, 1e-4, 1e-4), 1),
]


@pytest.mark.parametrize(("n", "setting", "case", "expected"), COUNT_CASES)
def test_number_of_roots_equals_independent_count_along_Abar(n, setting, case, expected) -> None:
    """All roots are returned: the count along Abar (see count_roots_along_Abar) equals the solver's,
    each returned Abar lies in a grid cell where the count found a sign change (cell width 0.2 %),
    and stability alternates from the largest root (stable) down. Cases: undamped above the fixation
    resonance (contact resonance at abar_m = 9.56, two extra roots), the same damped (no pole), free
    indenters with beta = 1 and 0.3 (poles at abar_m = 31.9 and 9.56), and a damped case below resonance.
    """
    fixation, omega_check = setting
    assert fixation.d(omega_check) == pytest.approx(complex(case[0] - case[1], case[2]), rel=1e-14)
    sols = solutions(steady_states(ETA1, fixation, CHI0, GentSchultz(n), omega_check=omega_check))
    count, cells = count_roots_along_Abar(case, fixation.mu, n)
    assert len(sols) == count == expected
    for sol, cell in zip(sorted(sols, key=lambda s: s.Abar), cells):
        assert cell <= sol.Abar <= cell * math.exp(0.002) * (1 + 1e-12)
    assert [s.stable for s in sols][::-1] == [i % 2 == 0 for i in range(len(sols))]


# ----------------------------------------------------------------- compliant fixation: printed residuals


@pytest.mark.parametrize(
    ("kappa", "omega_bar", "zeta", "mu"),
    [(0.1, 0.1, 0.05, MU_SMALL), (0.01, 3.0, 0.0, 0.0), (0.1, 50.0, 0.05, MU_SMALL), (0.1, 2.0, 0.0, MU_SMALL)],
)
def test_compliant_roots_satisfy_printed_eq_87_and_eq_43_with_eqs_50_51(kappa, omega_bar, zeta, mu) -> None:
    """Reference: Eq. (87) as printed (h0 = hhat) and Eq. (43) with Eqs. (50)-(51) (E* = R = 1), with
    30-digit J's at each returned Abar. Tolerance 1e-13 C on Eq. (87) relative to its largest term and on
    Eq. (43) relative, with C = 1 + K/|d + K|, K = 2 E* a_m: a relative error e of abar_m (~1e-15 from
    the root polish) moves |d + K|, hence the target of Eq. (43), Abar and J0, by ~C e. C = 58 and 64 at
    the two roots next to the contact resonance (kappa = 0.1, omega_bar = 2, zeta = 0).
    """
    n = 0.531
    fixation, omega_check = spring(kappa, omega_bar, zeta, mu)
    d = mp.mpc(fixation.d(omega_check))
    for sol in solutions(steady_states(ETA1, fixation, CHI0, GentSchultz(n), omega_check=omega_check)):
        j0, jc1, _ = j_integrals_mp(float(sol.Abar), n)
        abar_m = float(sol.abar_m)
        terms = printed_eq_87_terms(abar_m, j0, kappa, mu)
        a_m = mp.mpf(abar_m) * A_O
        condition = 1 + 2 * a_m / abs(d + 2 * a_m)
        assert abs(sum(terms)) < 1e-13 * condition * max(abs(t) for t in terms), sol
        assert abs(printed_eq_43_ratio(abar_m, jc1, kappa, omega_bar, zeta) - 1) < 1e-13 * condition, sol


def printed_eq_87_terms(abar_m: float, j0: mp.mpf, kappa: float, mu: float) -> list[mp.mpf]:
    """The five terms of Eq. (87) as printed (h0 = hhat), at abar_m = a_m/a_o and J0."""
    chi, x = mp.mpf(CHI0), mp.mpf(abar_m)
    return [(2 ** (mp.mpf(7) / 3) * chi / 3 ** (mp.mpf(5) / 3)) * x**3, kappa * x**2,
            -j0 * (2 ** (mp.mpf(4) / 3) * chi / 3 ** (mp.mpf(2) / 3)) * x**1.5, -j0 * kappa * mp.sqrt(x),
            -(3 ** (mp.mpf(4) / 3)) * mu / (2 ** (mp.mpf(2) / 3) * chi**2)]


def printed_eq_43_ratio(abar_m: float, jc1: mp.mpf, kappa: float, omega_bar: float, zeta: float) -> mp.mpf:
    """Xi_c^2 + Xi_s^2 over [(k - m omega^2)^2 + c^2 omega^2] h1^2: Eq. (43) with Eqs. (50)-(51) (E* = R = 1),
    1 on a solution, for the spring-mass-dashpot k = kappa, m omega^2 = kappa omega_bar^2, c omega = 2 zeta kappa
    omega_bar (Eqs. 65-66).
    """
    a_m = mp.mpf(abar_m) * A_O
    k, m_omega2, c_omega = mp.mpf(kappa), mp.mpf(kappa) * omega_bar**2, 2 * zeta * mp.mpf(kappa) * omega_bar
    xi_c = -mp.sqrt(2 * mp.pi * W0 * a_m) * (k - m_omega2) * jc1 - mp.sqrt(8 * mp.pi * W0 * a_m**3) * jc1
    xi_s = mp.sqrt(2 * mp.pi * W0 * a_m) * c_omega * jc1
    rhs = ((k - m_omega2) ** 2 + c_omega**2) * mp.mpf(ETA1) ** 2
    return (xi_c**2 + xi_s**2) / rhs


# ----------------------------------------------------------------- static limit and anti-resonance, Eq. (82)


def eq82_roots(kappa: float, load_group: mp.mpf) -> list[tuple[float, bool]]:
    """Positive roots a_0/a_o of Eq. (82) with mu replaced by the load group lambda = mu + kappa (hhat - h0)/R,
    in s = (a_0/R)^(1/2):
    (4/3) s^6 + kappa s^4 - (2 sqrt2/3) chi0^(3/2) s^3 - (sqrt2/3) chi0^(3/2) kappa s - lambda = 0,
    each with the JKR stability under the spring (the polynomial increasing through the root).
    """
    c = mp.sqrt(2) / 3 * mp.mpf(CHI0) ** 1.5
    coefficients = [mp.mpf(4) / 3, 0, kappa, -2 * c, 0, -c * kappa, -load_group]
    slope = [6 * coefficients[0], 0, 4 * kappa, -6 * c, 0, -c * kappa]  # d/ds, descending powers
    roots = []
    for s in mp.polyroots(coefficients[::-1], maxsteps=200, extraprec=60, asc=True):
        if abs(mp.im(s)) < 1e-20 and mp.re(s) > 0:
            s = mp.re(s)
            roots.append((float(s**2 / A_O), bool(mp.polyval(slope[::-1], s, asc=True) > 0)))
    return sorted(roots)


STATIC_CASES = [(0.01, 0.0, 0.0), (0.1, MU_SMALL, 0.0), (0.01, MU_SMALL, -0.3), (0.1, 0.0, -0.45)]


@pytest.mark.parametrize(("kappa", "mu", "base_offset"), STATIC_CASES)
def test_static_limit_eta1_to_zero_equals_eq_82(kappa: float, mu: float, base_offset: float) -> None:
    """Reference: Eq. (82) (mu -> lambda) by polyroots. eta1 = 0 gives J0 = 1 exactly; eta1 = 1e-12 moves
    J0 by ~(eta1/c_o^2)^2 ~ 1e-17. Tolerance 1e-12 on every root, same count, same stability (tensile
    cases: JKR's unstable small root and stable large one).
    """
    load = mu + kappa * base_offset * A_O**2
    reference = eq82_roots(kappa, load)
    for eta1 in (0.0, 1e-12):
        fixation, omega_check = spring(kappa, 2.0, 0.05, mu)
        sols = solutions(steady_states(eta1, fixation, CHI0, GentSchultz(0.531), base_offset=base_offset,
                                       omega_check=omega_check))
        assert len(sols) == len(reference), (sols, reference)
        for sol, (abar_m, stable) in zip(sols, reference):
            assert abs(sol.abar_m / abar_m - 1) < 1e-12 and sol.stable == stable
    assert sols[-1].Abar > 0  # eta1 = 1e-12 did take the vibrating path


@pytest.mark.parametrize(("kappa", "mu", "base_offset"), STATIC_CASES)
def test_anti_resonance_of_appendix_b_gives_abar_zero_and_the_static_state(kappa, mu, base_offset) -> None:
    """Appendix B: at omega_bar = 1, zeta = 0 the fixation's dynamic stiffness vanishes (d = 0), the
    right-hand side of Eq. (43) is zero, so Jc1 = 0: Abar = 0 and J0 = 1 exactly, at any eta1, and the
    mean state is the static one of Eq. (82) (reference as above, 1e-12).
    """
    fixation, omega_check = spring(kappa, 1.0, 0.0, mu)
    assert fixation.d(omega_check) == 0 and fixation.transmissibility(1.0, CHI0, omega_check) == 0.0
    sols = solutions(steady_states(ETA1, fixation, CHI0, GentSchultz(0.531), base_offset=base_offset,
                                   omega_check=omega_check))
    reference = eq82_roots(kappa, mu + kappa * base_offset * A_O**2)
    assert len(sols) == len(reference)
    for sol, (abar_m, stable) in zip(sols, reference):
        assert (sol.Abar, sol.w_eff_ratio, sol.A_over_am) == (0.0, 1.0, 0.0)  # J0 = 1 exactly iff J0^2 = 1
        assert abs(sol.abar_m / abar_m - 1) < 1e-12 and sol.stable == stable


@pytest.mark.parametrize("kappa", [0.01, 0.1])
def test_two_roots_inside_one_scan_cell_next_to_the_fold_are_both_found(kappa: float) -> None:
    """Static state (eta1 = 0) under a tensile load just above the fold (the pull-off of the spring-loaded
    JKR contact): the two roots of Eq. (82) (mu -> lambda) lie within 2 % of each other, inside one
    5 % cell of the scan, with no sign change at the nodes. Reference: the fold s* from the polynomial's
    derivative (findroot), lambda = lambda_fold + p''(s*)/2 (0.004 s*)^2, roots by polyroots. Both roots
    must be returned, to 1e-10 (they are conditioned like 1/sqrt(lambda - lambda_fold)).
    """
    c = mp.sqrt(2) / 3 * mp.mpf(CHI0) ** 1.5

    def p(s, load=0):
        return mp.mpf(4) / 3 * s**6 + kappa * s**4 - 2 * c * s**3 - c * kappa * s - load

    s_fold = mp.findroot(lambda s: mp.diff(p, s), mp.sqrt(A_O))
    load = p(s_fold) + mp.diff(p, s_fold, 2) / 2 * (mp.mpf("0.004") * s_fold) ** 2
    reference = eq82_roots(kappa, load)
    assert len(reference) == 2 and math.log(reference[1][0] / reference[0][0]) < 0.02
    fixation, omega_check = spring(kappa, 2.0, 0.0)
    sols = solutions(steady_states(0.0, fixation, CHI0, GentSchultz(0.531), base_offset=float(load / (kappa * A_O**2)),
                                   omega_check=omega_check))
    assert len(sols) == 2
    for sol, (abar_m, stable) in zip(sols, reference):
        assert abs(sol.abar_m / abar_m - 1) < 1e-10 and sol.stable == stable


# ----------------------------------------------------------------- nominal point contact, Eqs. (99)/(123)


@pytest.mark.parametrize("n", EXPONENTS)
def test_rigid_nominal_point_contact_is_abar_m_cubed_half_equal_j0_and_matches_refined(n: float) -> None:
    """h0 = hhat, mu = 0, rigid: Eq. (56) with hhat - h0 = 0 is abar_m^(3/2) = J0 (Eqs. 99, 123), checked
    with the 30-digit J0 to 1e-12; and the refined model's nominal point contact at omega_check = inf
    (which then reduces to Eqs. 55, 99) gives the same Abar and abar_m to 1e-10. A/a_m follows Eq. (45)
    with Eq. (86), A/a_m = Abar / (omega_check abar_m a_o/R) (docs/errata.md E1), to 1e-13.
    """
    law = GentSchultz(n)
    (sol,) = solutions(steady_states(ETA1, Fixation.rigid(), CHI0, law, omega_check=1e6))
    assert abs(sol.abar_m**1.5 / float(j_integrals_mp(float(sol.Abar), n)[0]) - 1) < 1e-12
    refined = nominal_point_contact(ETA1, math.inf, CHI0, law)
    assert abs(sol.Abar / float(refined.Abar) - 1) < 1e-10 and abs(sol.abar_m / float(refined.abar_m) - 1) < 1e-10
    assert abs(sol.A_over_am / float(sol.Abar / (1e6 * sol.abar_m * A_O)) - 1) < 1e-13
    assert solutions(steady_states(ETA1, Fixation.rigid(), CHI0, law))[0].A_over_am == 0.0  # omega_check = inf


# ----------------------------------------------------------------- a_m = a_cr: Eqs. (67)-(69) and (72)


@pytest.mark.parametrize(("kappa", "omega_bar", "zeta"), [(0.01, 0.1, 0.0), (0.1, 2.0, 0.05), (0.1, 50.0, 0.0)])
def test_amplitude_equation_at_a_cr_reproduces_eqs_67_69_and_72(kappa: float, omega_bar: float, zeta: float) -> None:
    """With abar_m = a_cr/a_o = (9/16)^(1/3) J0^(2/3) (Eqs. 61, 86), (|delta_c|/R / transmissibility)^2 of the
    amplitude equation must equal the printed (xi_c^2 + xi_s^2)/((1 - omega_bar^2)^2 + 4 zeta^2 omega_bar^2)
    of Eqs. (67)-(69), and |delta_c|/R the printed (chi0^2/3) J0^(1/3) |Jc1| of Eq. (72) (rigid). Same
    30-digit J's on both sides: an identity, tolerance 1e-13.
    """
    n = 0.531
    fixation, omega_check = spring(kappa, omega_bar, zeta)
    chi = mp.mpf(CHI0)
    for Abar in (0.01, 3.0, 1e4):
        j0, jc1, _ = j_integrals_mp(Abar, n)
        abar_cr = float(mp.cbrt(mp.mpf(9) / 16) * mp.cbrt(j0) ** 2)
        amplitude = float(indentation_amplitude(abar_cr, float(jc1), CHI0))
        xi_c = chi**2 / 3 * mp.cbrt(j0) * (1 - omega_bar**2) * jc1 + chi**3 / (3 * kappa) * j0 * jc1
        xi_s = -2 * chi**2 / 3 * zeta * omega_bar * mp.cbrt(j0) * jc1
        printed = (xi_c**2 + xi_s**2) / ((1 - omega_bar**2) ** 2 + 4 * zeta**2 * omega_bar**2)
        ours = (amplitude / fixation.transmissibility(abar_cr, CHI0, omega_check)) ** 2
        assert abs(ours / float(printed) - 1) < 1e-13
        assert abs(amplitude / float(chi**2 / 3 * mp.cbrt(j0) * abs(jc1)) - 1) < 1e-13


def printed_eq_67_log_excess(Abar: float, kappa: float, omega_bar: float, zeta: float, eta1: float, j) -> float:
    """ln of the left-hand side of the printed Eq. (67), with Eqs. (68)-(69), over eta1^2, at J's ``j`` = (J0, Jc1)."""
    j0, jc1 = j
    chi = mp.mpf(CHI0)
    xi_c = chi**2 / 3 * mp.cbrt(j0) * (1 - omega_bar**2) * jc1 + chi**3 / (3 * kappa) * j0 * jc1
    xi_s = -2 * chi**2 / 3 * zeta * omega_bar * mp.cbrt(j0) * jc1
    return float(mp.log((xi_c**2 + xi_s**2) / ((1 - omega_bar**2) ** 2 + 4 * zeta**2 * omega_bar**2)) - 2 * mp.log(eta1))


@pytest.mark.parametrize(("kappa", "omega_bar", "zeta"), [(1e-3, 17.85, 0.01), (1e-2, 0.5, 0.05), (1e-2, 3.0, 0.0)])
def test_critical_log_excess_is_half_the_log_of_printed_eq_67(kappa: float, omega_bar: float, zeta: float) -> None:
    """critical_log_excess(ln Abar) is (IV) in logarithms: half ln of the printed Eq. (67) (Eqs. 68-69) over eta1^2,
    with 30-digit J's on the printed side, from Abar = 0.01 to 1e7; for a rigid fixation ln of Eq. (72)'s left-hand
    side over 3 eta1/chi0^2. Tolerance 1e-12 absolute in the logarithm: the J-integral quadrature agrees with
    mpmath to 1e-12 relative (test_integrals).
    """
    n = 0.531
    law = GentSchultz(n)
    fixation, omega_check = spring(kappa, omega_bar, zeta)
    for Abar in (0.01, 3.0, 1e4, 1e7):
        j0, jc1, _ = j_integrals_mp(Abar, n)
        ours = critical_log_excess(np.array([math.log(Abar)]), ETA1, fixation, CHI0, law, omega_check)[0]
        assert abs(2 * ours - printed_eq_67_log_excess(Abar, kappa, omega_bar, zeta, ETA1, (j0, jc1))) < 1e-12
        rigid = critical_log_excess(np.array([math.log(Abar)]), ETA1, Fixation.rigid(), CHI0, law, math.inf)[0]
        assert abs(rigid - float(mp.log(mp.cbrt(j0) * abs(jc1) / (3 * mp.mpf(ETA1) / mp.mpf(CHI0) ** 2)))) < 1e-12


@pytest.mark.parametrize(("kappa", "omega_bar", "zeta", "count"),
                         [(1e-3, 17.85, 0.01, 3), (1e-3, 17.85, 0.0, 3), (1e-2, 0.5, 0.05, 1), (1e-2, 3.0, 0.0, 3)])
def test_compliant_pulloff_roots_are_the_roots_of_printed_eqs_67_to_69(kappa, omega_bar, zeta, count) -> None:
    """Every root returned by critical_internal_variables is a root of the printed Eqs. (67)-(69): the printed residual,
    with 30-digit mpmath J's, changes sign between Abar (1 -+ 1e-9). Their number equals the sign changes of the
    printed residual on an independent grid (8001 points in ln Abar over [-40, 40], J's from the quadrature,
    which test_integrals checks against mpmath to 1e-12). Above the fixation's resonance a pair of roots
    sits at the contact resonance: Abar ~ 3e7 for omega_bar = 17.85, kappa = 0.001 (the rig of Sec. 3.5.3 with
    the assumed spring), Abar = 2.9e3 and 2.5e4 for omega_bar = 3, kappa = 0.01 (pull-off root 604); the
    pull-off is the smallest root.
    """
    n = 0.531
    fixation, omega_check = spring(kappa, omega_bar, zeta)
    roots = critical_internal_variables(ETA1, fixation, CHI0, GentSchultz(n), omega_check)
    assert len(roots) == count and roots == sorted(roots)
    for Abar in roots:
        lo, hi = (printed_eq_67_log_excess(Abar * f, kappa, omega_bar, zeta, ETA1, j_integrals_mp(Abar * f, n)[:2])
                  for f in (1 - 1e-9, 1 + 1e-9))
        assert lo * hi < 0, (Abar, lo, hi)
    grid = np.exp(np.linspace(-40.0, 40.0, 8001))
    j0, jc1, _ = j_integrals(grid, n)
    excess = [printed_eq_67_log_excess(a, kappa, omega_bar, zeta, ETA1, (mp.mpf(float(x)), mp.mpf(float(y))))
              for a, x, y in zip(grid, j0, jc1)]
    assert int(np.sum(np.diff(np.sign(excess)) != 0)) == count
    estimate = pulloff_leading(ETA1, CHI0, GentSchultz(n), fixation, omega_check)
    assert float(estimate.Abar_cr) == roots[0] and float(estimate.pulloff_ratio) == float(estimate.sqrt_w_eff_ratio) ** 2  # Eq. (71)


@pytest.mark.parametrize("n", EXPONENTS)
def test_fixation_pulloff_is_eq_72_for_rigid_and_tends_to_it_for_a_stiff_or_a_heavy_fixation(n: float) -> None:
    """Fixation.rigid() is Eq. (72) exactly (the same solver). A very stiff spring (kappa = 1e9, omega_bar = 0.5) and
    a mass far above its resonance (kappa = 1e-3, omega_bar = 1e6, |d| = 1e9 kappa) give the transmissibility
    |d|/|d + chi0 J0^(2/3)| = 1 + O(1e-10): Abar_cr within 1e-8 of Eq. (72), through the scan of Eqs. (67)-(69).
    """
    law = GentSchultz(n)
    rigid = pulloff_leading(ETA1, CHI0, law)
    same = pulloff_leading(ETA1, CHI0, law, Fixation.rigid())
    assert (same.Abar_cr, same.sqrt_w_eff_ratio, same.pulloff_ratio) == (rigid.Abar_cr, rigid.sqrt_w_eff_ratio,
                                                                         rigid.pulloff_ratio)
    for fixation, omega_check in (spring(1e9, 0.5, 0.05), spring(1e-3, 1e6, 0.01)):
        assert abs(pulloff_leading(ETA1, CHI0, law, fixation, omega_check).Abar_cr / rigid.Abar_cr - 1) < 1e-8


def test_fixation_pulloff_at_the_anti_resonance_is_the_static_jkr_pulloff() -> None:
    """zeta = 0, omega_bar = 1: d = 0, the contact spring is not deformed (Appendix B), Abar_cr = 0 and
    P_cr/P_JKR = J0(0)^2 = 1 exactly.
    """
    estimate = pulloff_leading(ETA1, CHI0, GentSchultz(0.531), *spring(1e-3, 1.0, 0.0))
    assert float(estimate.Abar_cr) == 0.0 and float(estimate.pulloff_ratio) == 1.0


@pytest.mark.parametrize(("kappa", "omega_bar", "zeta", "nu0"),
                         [(1e-3, 0.5, 0.01, 1e-12), (1e-3, 17.85, 0.01, 1e-12), (1e-3, 17.85, 0.0, 1e-12),
                          (1e-3, 1e4, 0.01, 1.227e-5)])
def test_refined_compliant_pulloff_tends_to_the_leading_order_one_as_omega_check_to_infinity(kappa, omega_bar, zeta, nu0):
    """The refined compliant pull-off (Eq. 90 at a_m = a_cr, compliant.pulloff_by_scan) differs from Eqs. (67)-(69)
    by the terms of Eqs. (94), (96) in Abar nu0/omega_bar = Abar/omega_check. With nu0 = 1e-12 (omega_check ~ 1e12
    at fixed omega_bar) and at omega_bar = 1e4 with the rig's nu0: the same roots, the smallest (the pull-off,
    Abar ~ 50) to 1e-10, those at the contact resonance (Abar ~ 3e7, so Abar/omega_check ~ 1e-6) to 1e-4.
    """
    law = GentSchultz(0.531)
    fixation, omega_check = spring(kappa, omega_bar, zeta)
    leading = critical_internal_variables(ETA1, fixation, CHI0, law, omega_check)
    roots = pulloff_by_scan(omega_bar, Fixation.compliant(kappa, zeta, nu0), CHI0, ETA1, law,
                            np.linspace(-40.0, 40.0, 4001))
    assert roots.level == "refined" and roots.found.all()
    refined = roots.Abar_cr.tolist()
    assert len(refined) == len(leading)
    assert abs(refined[0] / leading[0] - 1) < 1e-10
    assert all(abs(r / q - 1) < 1e-4 for r, q in zip(refined, leading))


def test_mean_balance_residual_is_eq_87_and_eq_82_term_by_term() -> None:
    """h0 = hhat: the residual equals Eq. (87) (printed coefficients) exactly, and c_o^2 times it at
    J0 = 1 is Eq. (82) at a/R = c_o abar_m; relative 1e-13 of the largest term, at random points.
    """
    rng = np.random.default_rng(1)
    chi = CHI0
    for abar_m, j0, kappa, mu in zip(rng.uniform(0.2, 3, 20), rng.uniform(1, 5, 20), rng.uniform(0, 1, 20),
                                     rng.uniform(0, 1e-5, 20)):
        fixation = Fixation.compliant(kappa, 0.0, 1.0, mu)  # d at omega_check = 0 is kappa: not used here
        eq87 = [(2 ** (7 / 3) * chi / 3 ** (5 / 3)) * abar_m**3, kappa * abar_m**2,
                -j0 * (2 ** (4 / 3) * chi / 3 ** (2 / 3)) * abar_m**1.5, -j0 * kappa * abar_m**0.5,
                -(3 ** (4 / 3)) * mu / (2 ** (2 / 3) * chi**2)]
        got = mean_balance_residual(abar_m, j0, fixation, chi, 0.0)
        assert abs(got - sum(eq87)) < 1e-13 * max(map(abs, eq87))
        x = abar_m * float(A_O)
        eq82 = [x**2 * (4 / 3 * x + kappa), -math.sqrt(2) * chi**1.5 / 3 * math.sqrt(x) * (2 * x + kappa), -mu]
        assert abs(float(A_O) ** 2 * mean_balance_residual(abar_m, 1.0, fixation, chi, 0.0) - sum(eq82)) < (
            1e-13 * max(map(abs, eq82)))


# ----------------------------------------------------------------- the monotone tail that ends the scan


@pytest.mark.parametrize("n", EXPONENTS)
def test_residual_increases_beyond_the_tail_criterion(n: float) -> None:
    """The proof in steady_states' docstring: once abar_m > max(0, -Re d/(2 c_o)) and
    abar_m^(3/2) >= (3/4) J0, the mean-balance residual along the amplitude equation increases strictly
    (here with mu and a base offset). Sampled on 150 points in steps of 5 % from the first such point.
    """
    law = GentSchultz(n)
    c_o = float(A_O)

    def residual_and_j0(x: float, fixation: Fixation, omega_check: float) -> tuple[float, float]:
        j0 = float(j_integrals(internal_variables(x, ETA1, fixation, CHI0, law, omega_check), n)[0][0])
        return mean_balance_residual(x, j0, fixation, CHI0, 0.2), j0

    for fixation, omega_check in (RIGID, free(0.3, MU_SMALL), spring(0.1, 2.0, 0.0, MU_SMALL),
                                  spring(0.01, 50.0, 0.05, MU_SMALL)):
        x = 1.0001 * max(0.0 if fixation.is_rigid else -fixation.d(omega_check).real / (2 * c_o), 1e-3)
        while x**1.5 < 0.75 * residual_and_j0(x, fixation, omega_check)[1]:
            x *= 1.05
        residual = [residual_and_j0(x * 1.05**i, fixation, omega_check)[0] for i in range(150)]
        assert np.all(np.diff(residual) > 0), fixation


# ----------------------------------------------------------------- the pieces of steady_states


@pytest.mark.parametrize(("kappa", "omega_bar", "zeta"), [(0.1, 2.0, 0.05), (0.01, 0.5, 0.0), (0.1, 50.0, 0.05)])
def test_balance_state_solves_printed_eq_43_and_returns_the_printed_eq_87_residual(kappa, omega_bar, zeta) -> None:
    """At given abar_m (h0 = hhat, so base offset 0): the returned Abar satisfies Eq. (43) with Eqs. (50)-(51)
    as printed, J0 is J0(Abar), and F is the printed Eq. (87), with 30-digit J's at the returned Abar.
    Tolerance 1e-12: the J-integral quadrature agrees with mpmath to 1e-12 (test_integrals), the root in
    ln Abar is polished to 1e-14, and F is a sum of a few rounded terms (relative to the largest).
    """
    n = 0.531
    fixation, omega_check = spring(kappa, omega_bar, zeta, MU_SMALL)
    balance = MeanBalance(ETA1, fixation, CHI0, GentSchultz(n), omega_check, 0.0)
    for abar_m in (0.3, 1.0, 4.0):
        f, Abar, j0 = balance_state(math.log(abar_m), balance)
        j0_mp, jc1_mp, _ = j_integrals_mp(Abar, n)
        assert abs(printed_eq_43_ratio(abar_m, jc1_mp, kappa, omega_bar, zeta) - 1) < 1e-12
        assert abs(j0 / j0_mp - 1) < 1e-12
        terms = printed_eq_87_terms(abar_m, j0_mp, kappa, MU_SMALL)
        assert abs(f - sum(terms)) < 1e-12 * max(abs(t) for t in terms)


def test_balance_state_for_rigid_fixation_is_eq_55_and_eq_56() -> None:
    """Rigid fixation: Abar solves Eq. (55), c_o^2 abar_m^(1/2) |Jc1(Abar)| = eta1 (a_o/R = c_o, Eq. 86), and F is
    Eq. (56) as a residual, deltabar_m - base_offset = abar_m^2 - J0 abar_m^(1/2) - base_offset; 30-digit J's,
    tolerance 1e-12 as above.
    """
    n, base_offset = 4.0, 0.2
    balance = MeanBalance(ETA1, Fixation.rigid(), CHI0, GentSchultz(n), math.inf, base_offset)
    for abar_m in (0.3, 1.0, 4.0):
        f, Abar, j0 = balance_state(math.log(abar_m), balance)
        j0_mp, jc1_mp, _ = j_integrals_mp(Abar, n)
        assert abs(A_O**2 * mp.sqrt(abar_m) * abs(jc1_mp) / ETA1 - 1) < 1e-12
        assert abs(f - (abar_m**2 - j0_mp * mp.sqrt(abar_m) - base_offset)) < 1e-12 * abar_m**2


def test_monotone_tail_start_and_criterion_follow_the_closed_forms() -> None:
    """abar_turn = max(0, -Re d/(2 c_o)) with c_o = a_o/R = (2 pi w0)^(1/3) (Eq. 86): 0 for a rigid fixation and
    below the fixation's resonance, beta/(2 c_o) for a free indenter, kappa (omega_bar^2 - 1)/(2 c_o) above the
    resonance (Eqs. 65-66); relative 1e-14 (a few roundings). The tail criterion abar_m > abar_turn and
    abar_m^(3/2) >= (3/4) J0 switches at the JKR radius (3/4)^(2/3) for J0 = 1 and at abar_turn.
    """
    c_o = float(A_O)
    assert monotone_tail_start(Fixation.rigid(), CHI0, math.inf) == 0.0
    assert monotone_tail_start(Fixation.compliant(0.1, 0.05, 1.0), CHI0, 0.5) == 0.0
    assert monotone_tail_start(Fixation.free(0.3), CHI0, 1.0) == pytest.approx(0.3 / (2 * c_o), rel=1e-14)
    above = monotone_tail_start(Fixation.compliant(0.1, 0.05, 1.0), CHI0, 2.0)
    assert above == pytest.approx(0.1 * (2.0**2 - 1) / (2 * c_o), rel=1e-14)
    z_jkr = math.log(0.75 ** (2 / 3))
    assert in_monotone_tail(z_jkr + 1e-12, 1.0, 0.0) and not in_monotone_tail(z_jkr - 1e-12, 1.0, 0.0)
    assert not in_monotone_tail(math.log(above) - 1e-12, 1.0, above) and in_monotone_tail(math.log(above) + 1e-12, 1.0, above)


@pytest.mark.parametrize("setting", [RIGID, free(0.3, MU_SMALL), spring(0.1, 2.0, 0.05, MU_SMALL)])
def test_scan_segments_split_at_the_contact_resonance_and_end_at_the_monotone_tail(setting) -> None:
    """The scan of F in ln abar_m starts at ln abar_m_min in steps of SCAN_STEP; for the free indenter it is split
    at the pole of Eq. (43), abar_m = beta/(2 c_o) (closed form, c_o = a_o/R), with F < 0 at the nodes next to
    it on both sides; it ends at the first node of the grid (past the refinement towards the pole) where abar_m > abar_turn and abar_m^(3/2) >= (3/4) J0, J0 from
    30-digit mpmath at the node's Abar (relative 1e-12 as above, far from the switch at these nodes).
    """
    n = 0.531
    fixation, omega_check = setting
    balance = MeanBalance(ETA1, fixation, CHI0, GentSchultz(n), omega_check, 0.0)
    resonance = 0.3 / (2 * float(A_O)) if fixation.kappa == 0 else None
    z_res = math.log(resonance) if resonance is not None else None
    abar_turn = monotone_tail_start(fixation, CHI0, omega_check)
    segments = scan_segments(balance, math.log(1e-4), z_res, abar_turn, "scan")
    assert len(segments) == (2 if resonance else 1)
    assert segments[0][0][0] == math.log(1e-4) and segments[0][1][0] == pytest.approx(math.log(1e-4) + SCAN_STEP)
    if z_res is not None:
        assert all(z < z_res for z, _ in segments[0]) and all(z > z_res for z, _ in segments[1])
        assert segments[0][-1][1] < 0 and segments[1][0][1] < 0
    grid = [z for z, _ in segments[-1] if z_res is None or z > z_res + SCAN_STEP * (1 - 1e-9)]  # not the refinement
    tail = []
    for z in grid[-2:]:
        j0 = j_integrals_mp(balance_state(z, balance)[1], n)[0]
        tail.append(math.exp(z) > abar_turn and math.exp(1.5 * z) >= 0.75 * float(j0))
    assert tail == [False, True][2 - len(tail):]


@pytest.mark.parametrize(
    "kwargs", [{"chi0": -1.0}, {"base_offset": math.inf}, {"abar_m_min": 0.0}, {"omega_check": 0.0}]
)
def test_steady_states_rejects_inputs_outside_its_domain(kwargs) -> None:
    """chi0 > 0 (Eq. 64), a finite base offset, abar_m_min > 0 and omega_check > 0 (Eq. 105): ValueError; a rate
    law other than Gent-Schultz: TypeError (the proof that ends the scan needs it). mu >= 0 (Eq. 81) is the
    fixation's rule (tests/core/test_fixation.py).
    """
    arguments = {"chi0": CHI0} | kwargs
    chi0 = arguments.pop("chi0")
    with pytest.raises(ValueError):
        steady_states(ETA1, Fixation.rigid(), chi0, GentSchultz(0.531), **arguments)
    with pytest.raises(TypeError):
        steady_states(ETA1, Fixation.rigid(), CHI0, object())


# ----------------------------------------------------------------- failures are a status, not numbers


def test_tensile_load_beyond_pulloff_has_no_solution() -> None:
    """No steady state for a base pulled far from the indenter (rigid: base_offset = -10 is below
    min deltabar_m; compliant: the same offset): one element of status no_solution, every number NaN,
    the reason in the message -- not a number.
    """
    law = GentSchultz(0.531)
    for fixation, omega_check in (RIGID, (Fixation.compliant(0.1, 0.05, 1.0), 0.5)):
        record = steady_states(ETA1, fixation, CHI0, law, base_offset=-10.0, omega_check=omega_check)
        assert record.level == "leading" and record.status.tolist() == ["no_solution"] and not record.ok.any()
        assert all(np.isnan(getattr(record, name)).all() for name in NUMBERS) and "pull-off" in record.message


def test_contact_resonance_raises_in_the_amplitude_equation() -> None:
    """d + 2 c_o abar_m = 0 exactly (free indenter with beta = 2 c_o): |delta_c| unbounded, NoRootError."""
    c_o = 2 ** (1 / 3) * 3 ** (-2 / 3) * CHI0
    fixation = Fixation.free(2.0 * c_o)
    assert fixation.contact_resonance(CHI0, 1.0) == pytest.approx(1.0, rel=1e-15)
    with pytest.raises(NoRootError, match="resonance"):
        internal_variables(1.0, ETA1, fixation, CHI0, GentSchultz(0.531), 1.0)
