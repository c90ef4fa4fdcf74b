"""Intervals, the status rule and the goodness-of-fit tests of vibroadhesion.experiments.fit_statistics.

References are closed forms: the t interval of a model linear in ln theta (Bates & Watts 1988, Sec. 6.1: there the
profile t statistic is exactly linear), the profile of a one-parameter model linear in theta (a quadratic misfit
in theta, its ends by the quadratic formula), the F and chi-square tests computed by hand from their definitions
(Draper & Smith 1998, Sec. 2.1) with scipy's distribution functions.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import LinearResiduals
from scipy import stats

from vibroadhesion.experiments import fit_statistics as fs
from vibroadhesion.experiments.fit_summary import figures_choice



class _Proportional:
    """r_i(x) = e^x q_i - 1: one parameter theta = e^x that scales every prediction (like w0 of Eq. 70)."""

    def __init__(self, q: np.ndarray) -> None:
        self.q = q

    def residuals(self, x: np.ndarray) -> np.ndarray:
        return math.exp(x[0]) * self.q - 1.0

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        return (math.exp(x[0]) * self.q)[:, None]


BOX = (np.log([1e-3, 0.05]), np.log([10.0, 4.0]))


def _optimum(jac: np.ndarray, rng: np.random.Generator) -> tuple[LinearResiduals, np.ndarray, float]:
    """A linear model whose optimum is x_hat = ln(0.3, 0.7): residuals orthogonal to J's columns there."""
    x_hat = np.log([0.3, 0.7])
    noise = 0.02 * rng.standard_normal(jac.shape[0])
    r_hat = noise - jac @ np.linalg.lstsq(jac, noise, rcond=None)[0]
    return LinearResiduals(r_hat, jac, x_hat), x_hat, float(r_hat @ r_hat)


@pytest.mark.parametrize("k", [0, 1])
def test_profile_interval_of_a_linear_model_is_the_t_interval(k: int) -> None:
    """Linear in ln theta: the profile ends are xhat_k +- t_(m-p)(0.975) s sqrt((J^T J)^-1_kk) exactly; the secant
    lands on them in one step, so only the refits' tolerance (1e-6 relative in S) is left: 1e-6 of the half-width."""
    rng = np.random.default_rng(4)
    jac = rng.standard_normal((9, 2)) * [1.0, 0.4] + [0.0, 0.3]
    model, x_hat, rss = _optimum(jac, rng)
    s2 = rss / 7
    half = fs.t_quantile(0.95, 7) * math.sqrt(s2 * np.linalg.inv(jac.T @ jac)[k, k])
    interval = fs.profile_interval(model, x_hat, k, BOX, s2, 7)
    assert interval.closed
    assert math.log(interval.lower) == pytest.approx(x_hat[k] - half, abs=1e-6 * half)
    assert math.log(interval.upper) == pytest.approx(x_hat[k] + half, abs=1e-6 * half)


def test_profile_interval_of_a_proportional_model_follows_the_quadratic_in_theta() -> None:
    """r_i = theta q_i - 1: S(theta) = A theta^2 - 2 B theta + m (A = sum q^2, B = sum q), minimal at B/A, and
    S - S_min = A (theta - B/A)^2, so the ends are B/A +- t s / sqrt(A) in theta: symmetric in theta, not in
    ln theta, which the interval in ln theta must reproduce (to the 1 % of t* that the ends are located to,
    i.e. 1 % of the half-width)."""
    q = np.array([0.8, 1.3, 0.9, 1.25, 1.1, 0.7])
    a, b, m = float(q @ q), float(q.sum()), len(q)
    theta = b / a
    rss = m - b * b / a
    s2 = rss / (m - 1)
    half = fs.t_quantile(0.95, m - 1) * math.sqrt(s2 / a)
    interval = fs.profile_interval(_Proportional(q), np.array([math.log(theta)]), 0, (np.log([1e-3]), np.log([1e3])),
                                   s2, m - 1)
    assert interval.lower == pytest.approx(theta - half, abs=1e-2 * half)
    assert interval.upper == pytest.approx(theta + half, abs=1e-2 * half)
    assert math.log(interval.upper / theta) < math.log(theta / interval.lower)  # symmetric in theta, not in ln theta


def test_an_end_beyond_the_box_is_open() -> None:
    """A column of J 1e-3 (n hardly moves the residuals): the t interval in ln n is thousands wide, far past the box
    (ln 0.05 .. ln 4): both ends open, status not_identifiable."""
    rng = np.random.default_rng(1)
    jac = np.column_stack([np.ones(8), 1e-3 * rng.standard_normal(8)])
    model, x_hat, rss = _optimum(jac, rng)
    interval = fs.profile_interval(model, x_hat, 1, BOX, rss / 6, 6)
    assert interval.lower is None and interval.upper is None and not interval.closed
    status, why = fs.parameter_status(False, 1e3, interval)
    assert status == "not_identifiable"


@pytest.mark.parametrize(("at_bound", "relative_se", "closed", "status"), [
    (True, 0.01, True, "at_bound"),
    (False, None, True, "not_identifiable"),
    (False, 0.51, True, "not_identifiable"),
    (False, 0.49, False, "not_identifiable"),
    (False, 0.49, True, "fitted"),
])
def test_one_status_rule(at_bound: bool, relative_se: float | None, closed: bool, status: str) -> None:
    """The rule of the module docstring, case by case: a bound first, then no SE, SE > 0.5, an open interval."""
    interval = fs.Interval(0.1, 0.2 if closed else None, 0)
    assert fs.parameter_status(at_bound, relative_se, interval)[0] == status


def test_lack_of_fit_f_test_by_hand() -> None:
    """Three conditions, two replicates each, p = 2: S_pe = sum of squares about the condition means (3 dof),
    S_lof = S - S_pe (1 dof), F = (S_lof/1)/(S_pe/3), p-value from F(1, 3)."""
    residuals = np.array([0.10, 0.12, -0.05, -0.02, 0.01, 0.04])
    groups = np.array([0, 0, 1, 1, 2, 2])
    pure = 2 * (0.01**2 + 0.015**2 + 0.015**2)
    lof = float(residuals @ residuals) - pure
    f = lof / (pure / 3)
    gof = fs.goodness_of_fit(residuals, groups, 2, fs.Settings())
    assert gof.test == "lack_of_fit" and gof.dof == (1, 3)
    assert gof.statistic == pytest.approx(f, rel=1e-12)
    assert gof.p_value == pytest.approx(stats.f.sf(f, 1, 3), rel=1e-12)
    assert gof.rejected == (stats.f.sf(f, 1, 3) < 0.05)


@pytest.mark.parametrize(("rms", "rejected"), [(0.03, False), (0.15, True)])
def test_without_replicates_the_stated_scatter_decides(rms: float, rejected: bool) -> None:
    """Six distinct conditions, p = 2: chi2 = S/sigma^2 with 4 dof at sigma = 5 %; rms 3 % passes, 15 % fails."""
    residuals = rms * np.array([1, -1, 1, -1, 1, -1], dtype=float)
    gof = fs.goodness_of_fit(residuals, np.arange(6), 2, fs.Settings(stated_scatter=0.05))
    assert gof.test == "stated_scatter" and gof.dof == (4,)
    assert gof.p_value == pytest.approx(stats.chi2.sf(6 * rms**2 / 0.05**2, 4), rel=1e-12)
    assert gof.rejected is rejected


def test_no_spare_row_no_test() -> None:
    """Two rows, two parameters: nothing to test the misfit against, and it is said."""
    gof = fs.goodness_of_fit(np.zeros(2), np.arange(2), 2, fs.Settings())
    assert gof.test == "none" and not gof.rejected and "no degree of freedom" in gof.text


def _fit(status: str) -> dict[str, str]:
    return {"status": status}


@pytest.mark.parametrize(("statuses", "used"), [
    ({"simulation": "fitted", "refined": "fitted"}, "simulation"),
    ({"simulation": "at_bound", "leading": "fitted", "exact_averaging": "fitted"}, "exact_averaging"),
    ({"simulation": "poor_fit", "refined": "not_identifiable", "leading": "poor_fit"}, "published"),
    ({"simulation": "published", "refined": "published"}, "published"),
])
def test_the_figures_never_use_a_fit_that_is_not_fitted(statuses: dict[str, str], used: str) -> None:
    """The preferred level (simulation) if fitted, else the most faithful fitted level, else the published set."""
    choice, why = figures_choice({name: _fit(status) for name, status in statuses.items()}, "simulation")
    assert choice == used and why
