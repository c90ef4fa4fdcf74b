"""Fig. 5 at the edges of the validated exponent range, n = 0.05 and n = 4 (issue 13, item 7).

For the setup's kappa x zeta (data/setup.yaml: kappa in {0.001, 0.01}, zeta in {0, 0.01, 0.05}) the traced
curves are checked against references independent of the continuation: points re-solved by a root finder of
this module (scipy's hybr on Eqs. 87 and 90 written out here from Eqs. 91-96) at the traced omega_bar, and the
number of solutions against the scalar root scan of Eq. (90) along abar_m(Abar) of Eq. (87) (no continuation).
"""

from __future__ import annotations

import math
from functools import partial

import numpy as np
import pytest
from conftest import CHI0, ETA1, NU0
from scipy.optimize import minimize_scalar, root

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.integrals import j_integrals
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.figure_tables.fig5 import fig5_tables
from vibroadhesion.models.compliant import abar_m_from_mean_balance, amplitude_residual_on_closure
from vibroadhesion.models.response_curve import AMPLITUDE_CEILING, NOTCH_GAP, OPEN_ENDS, trace_response_curve

EDGES = (0.05, 4.0)
KAPPAS, ZETAS = (0.001, 0.01), (0.0, 0.01, 0.05)
CASES = [(n, kappa, zeta) for n in EDGES for kappa in KAPPAS for zeta in ZETAS]


def printed_equations(z: np.ndarray, omega_bar: float, kappa: float, zeta: float, n: float) -> np.ndarray:
    """Eqs. (87) and (90) as printed (mu = 0), relative: ((lhs - rhs)/rhs of each), at z = (ln abar_m, ln Abar).

    Eq. (90): xi_c^2 + xi_s^2 = eta1^2 [(1 - omega_bar^2)^2 + 4 zeta^2 omega_bar^2] with Eqs. (91)-(96) written
    out here (nu0/omega_bar = 1/omega_check, Eq. 105).
    """
    abar, Abar = math.exp(z[0]), math.exp(z[1])
    j0, jc1, j1 = (float(v) for v in j_integrals(Abar, n))
    c = CHI0
    eq87 = ((2 ** (7 / 3) * c / 3 ** (5 / 3)) * abar**3 + kappa * abar**2) / (
        j0 * ((2 ** (4 / 3) * c / 3 ** (2 / 3)) * abar**1.5 + kappa * math.sqrt(abar))) - 1.0
    r = NU0 / omega_bar
    dc = -(2 ** (2 / 3) / 3 ** (4 / 3)) * c**2 * math.sqrt(abar) * jc1
    ds = (2 ** (4 / 3) / 3 ** (2 / 3)) * c * r * Abar * abar * (1 - j1 / (4 * abar**1.5))
    pc = -(4 * c**3 / (9 * kappa)) * abar**1.5 * jc1
    ps = (2 ** (8 / 3) / 3 ** (4 / 3)) * c**2 * (r / kappa) * Abar * abar**2 * (1 - 3 * j1 / (4 * abar**1.5))
    stiffness = -math.expm1(2 * math.log(omega_bar))
    xi_c = stiffness * dc + 2 * zeta * omega_bar * ds + pc
    xi_s = stiffness * ds - 2 * zeta * omega_bar * dc + ps
    rhs = ETA1**2 * (stiffness**2 + 4 * zeta**2 * omega_bar**2)
    return np.array([eq87, (xi_c**2 + xi_s**2) / rhs - 1.0])


def roots_by_refined_scan(omega_bar: float, fixation: Fixation, law: GentSchultz) -> int:
    """Roots of Eq. (90) along abar_m(Abar) of Eq. (87) (scalar, no continuation) with ln Abar in [-700, 60].

    Sign changes on a grid of step 0.1, plus two for every grid extremum (a dip or a spike between values of
    one sign) whose bounded minimisation crosses zero: next to the backbone xi = 0 of a resonance peak the
    residual, ln|xi| - ln(eta1 |1 - omega_bar^2 + 2 i zeta omega_bar|), dips to -infinity between two roots
    4e-4 apart, far closer than the grid.
    """
    g = partial(amplitude_residual_on_closure, log_omega_bar=math.log(omega_bar), fixation=fixation, chi0=CHI0,
                eta1=ETA1, law=law, abar_m_of_j0=partial(abar_m_from_mean_balance, fixation=fixation, chi0=CHI0))
    grid = np.linspace(-700.0, 60.0, 7601)
    values = g(grid)
    count = int(np.count_nonzero(np.sign(values[:-1]) != np.sign(values[1:])))
    for k in range(1, len(grid) - 1):
        side = np.sign(values[k])
        if side * values[k] < min(side * values[k - 1], side * values[k + 1]) and side == np.sign(values[k - 1]) \
                == np.sign(values[k + 1]):
            best = minimize_scalar(lambda y: side * float(g(np.array([y]))[0]), bounds=(grid[k - 1], grid[k + 1]),
                                   method="bounded", options={"xatol": 1e-12})
            count += 2 if best.fun < 0 else 0
    return count


@pytest.fixture(scope="module")
def curves() -> dict:
    return {(n, kappa, zeta): trace_response_curve(Fixation.compliant(kappa, zeta, NU0, 0.0), CHI0, ETA1,
                                                    GentSchultz(n))
            for n, kappa, zeta in CASES}


@pytest.mark.parametrize(("n", "kappa", "zeta"), CASES)
def test_edge_curves_are_traced_to_their_ends_or_report_why_not(curves, n, kappa, zeta) -> None:
    """Every piece ends at the range end, in the notch (zeta = 0), or with a reported status (OPEN_ENDS); with
    zeta > 0 the curve spans the range; a notch end lies within NOTCH_GAP of omega_bar = 1 or below A/a_m = 1e-12.
    """
    curve = curves[n, kappa, zeta]
    assert set(curve.ends) <= {"range_end", "notch", *OPEN_ENDS}
    for piece, end in zip(curve.pieces, curve.ends, strict=True):
        if end == "unbounded_amplitude":
            assert curve.A_over_am(piece.points[-1:])[0] > AMPLITUDE_CEILING
        if end == "notch":
            last = piece.points[-1:]
            assert abs(last[0, 0]) < NOTCH_GAP or curve.A_over_am(last)[0] < 1e-12
    if zeta > 0:
        assert curve.names == ("full",) and curve.ends == ("range_end",)
        assert np.isclose(curve.pieces[0].points[-1, 0], math.log(50.0), rtol=0, atol=1e-15)


@pytest.mark.parametrize(("n", "kappa", "zeta"), CASES)
def test_traced_points_solve_the_printed_equations_by_an_independent_root_finder(curves, n, kappa, zeta) -> None:
    """Five points per piece with A/a_m <= 1 (beyond, the printed forms lose digits to the cancellation of Eq. 90):
    the printed Eqs. (87), (90) hold at the traced point to 1e-9 relative (traced to 1e-12 in logarithms,
    i.e. 2e-12 relative, plus the J-integrals' 1e-13 times the cancellation of Eq. 90, below 1e3 there).
    hybr from 1e-6 off (in ln abar_m, ln Abar; below half the closest root pair, 4e-4 apart across the backbone
    xi = 0 of the n = 4 resonance peaks) converges (printed residuals below 1e-9) back to the traced point within
    the perturbation bound 10 (|F(traced)| + |F(hybr)|) / sigma_min(F') (F' by central differences, step 1e-6),
    which near a fold, where sigma_min -> 0, allows the flat direction its due.
    """
    curve = curves[n, kappa, zeta]
    for piece in curve.pieces:
        inside = piece.points[curve.A_over_am(piece.points) <= 1.0]
        for x in inside[np.linspace(0, len(inside) - 1, min(5, len(inside))).astype(int)]:
            args = (math.exp(x[0]), kappa, zeta, n)
            traced = np.max(np.abs(printed_equations(x[1:], *args)))
            assert traced < 1e-9
            sol = root(printed_equations, x[1:] + 1e-6, args=args, method="hybr", tol=1e-14)
            found = np.max(np.abs(printed_equations(sol.x, *args)))
            assert found < 1e-9, sol
            steps = np.diag([1e-6, 1e-6])
            jac = np.column_stack([(printed_equations(x[1:] + h, *args) - printed_equations(x[1:] - h, *args)) / 2e-6
                                   for h in steps])
            bound = 10 * (traced + found) / np.linalg.svd(jac, compute_uv=False)[-1]
            assert np.max(np.abs(sol.x - x[1:])) < max(bound, 1e-9), (x, sol.x, bound)


@pytest.mark.parametrize(("n", "kappa", "zeta"), [c for c in CASES if c[2] > 0])
def test_fold_count_and_solution_counts_agree_with_a_dense_scan(curves, n, kappa, zeta) -> None:
    """Solutions per omega_bar on 120 log-spaced frequencies: the traced curve's crossings equal the refined scan's
    roots (:func:`roots_by_refined_scan`; ln Abar down to -700: Abar is tiny near the notch for n = 0.05) wherever no
    fold is within 1 % (a root pair born at a fold is closer than any grid there), and the folds equal the count's
    steps of two.
    """
    curve = curves[n, kappa, zeta]
    law = GentSchultz(n)
    fixation = curve.fixation
    grid = np.geomspace(0.1, 50.0, 120)
    scanned = np.array([roots_by_refined_scan(w, fixation, law) for w in grid])
    fold_omega = np.exp(curve.folds[:, 0])
    away = np.array([np.all(np.abs(w / fold_omega - 1) > 0.01) for w in grid])
    traced = np.array([curve.count_at(w) for w in grid])
    assert np.array_equal(traced[away], scanned[away])
    assert len(curve.folds) == int(np.sum(np.abs(np.diff(scanned)))) // 2


def test_fig5_tables_at_the_edges_report_ended_pieces_as_markers() -> None:
    """fig5_tables at n = 0.05 (zeta = 0: the curve leaves to unbounded amplitude near omega_bar = 5.3) has a
    marker of kind unbounded_amplitude per such piece, at A/a_m > AMPLITUDE_CEILING, and no table fails.
    """
    fixations = [Fixation.compliant(kappa, zeta, NU0, 0.0) for kappa in KAPPAS for zeta in ZETAS]
    curves, markers, counts = fig5_tables(fixations, CHI0, ETA1, 0.05, {200.0: 17.85}, (0.1, 50.0), 50)
    ended = markers[markers["kind"] == "unbounded_amplitude"]
    assert len(ended) >= 2 and set(ended["zeta"]) == {0.0}
    assert (ended["A_over_am"] > AMPLITUDE_CEILING).all()
    assert len(counts) == 6 * 50 and set(curves["zeta"]) == set(ZETAS)
