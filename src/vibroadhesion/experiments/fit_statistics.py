"""What a Gent–Schultz fit determines: profile-likelihood intervals, one status rule, goodness of fit (Sec. 3.4).

The fits of :mod:`vibroadhesion.experiments.fitting` minimise the sum of squares S(x) of the relative residuals
r_i = P_model,i/P_observed,i - 1 over x = ln theta (theta the free parameters among w0, n, v0) inside the box
BOUNDS. This module says, for a finished fit, how well each parameter is determined and whether the model
represents the rows at all.

**Intervals: the profile t statistic** (Bates & Watts, *Nonlinear Regression Analysis and Its Applications*,
Wiley 1988, Sec. 6.1). For parameter k, S_k(x_k) is the least S with x_k held and the other free parameters
refitted, and

    tau_k(x_k) = sign(x_k - xhat_k) sqrt(S_k(x_k) - S(xhat)) / s,        s^2 = S(xhat)/(m - p),

with m rows and p free parameters. The nominal 1 - alpha interval is {x_k : |tau_k| <= t_(m-p)(1 - alpha/2)}. For
a model linear in x it is the exact t interval (tau_k is then linear in x_k and equals (x_k - xhat_k)/se_k); for a
nonlinear one it follows the curvature of the misfit surface that the Wald interval xhat_k +- t se_k ignores, which
matters here: with a few rows the pull-off is far from linear in ln n, and an interval symmetric in ln n would
cover values the rows exclude. Its cost is a one-dimensional root search per end, each trial a refit of the
other p - 1 parameters (none for p = 1), warm-started: 4-8 refits per end. A parametric bootstrap would need
hundreds of whole fits, which the simulated level cannot afford in a refit. s is floored at ``noise_floor`` so
that noise-free (synthetic) rows do not give intervals of zero width. The coverage is measured, not assumed:
:mod:`vibroadhesion.experiments.fit_coverage`.

An end that does not close inside the box (tau_k stays below the quantile up to the bound) is open: the rows do
not exclude the bound, and the parameter is not determined by them inside the box.

**One status rule** for w0, n and v0 (:func:`parameter_status`): ``at_bound`` where the estimate ends on a bound
(or within 1 % of it in ln and within two standard errors: the rows do not exclude it); ``not_identifiable`` where
the rows leave it undetermined: no standard error (a Jacobian of lower rank), a relative standard error above
:data:`MAX_RELATIVE_SE`, or an interval open at an end; ``fitted`` otherwise. A parameter that was not freed keeps
its published value (``published``).

**Goodness of fit** (:func:`goodness_of_fit`). With replicates (rows at the same condition), the lack-of-fit F
test of the misfit against their pure error (Draper & Smith, *Applied Regression Analysis*, 3rd ed., Wiley
1998, Sec. 2.1): F = (S_lof/(g - p)) / (S_pe/(m - g)) with g conditions, S_pe the scatter of the replicates'
residuals about their condition's mean, S_lof = S - S_pe. Without replicates (or without the degrees of freedom
for it), the chi-square test of S against a stated relative scatter sigma: S/sigma^2 ~ chi^2_(m-p) when the
model holds. The fit is rejected (``poor_fit``) at the significance level ``alpha``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal, Protocol

import numpy as np
from numpy.typing import NDArray
from scipy import stats
from scipy.optimize import least_squares

Vector = NDArray[np.float64]
ParameterStatus = Literal["fitted", "not_identifiable", "at_bound", "published"]

#: A relative standard error above this leaves a parameter not determined (the rule of the v0 gate too).
MAX_RELATIVE_SE = 0.5
#: The profile's end is located to this fraction of the t quantile in tau (the interval's ends to ~1 % of the
#: half-width: tau is close to linear in x_k).
TAU_RTOL = 1e-2
#: Relative tolerances of the refits along the profile: S_k to ~1e-6 relative, far below the 0.1-10 S(xhat) of the
#: rise t*^2 s^2 that the ends are located by.
_REFIT_TOL = 1e-6
#: At most this many secant steps per end.
_SECANT_STEPS = 12
#: At most this many extensions of the bracket towards a bound before an end is declared open.
_EXPANSIONS = 8


class ResidualModel(Protocol):
    """Relative residuals of the rows and their Jacobian as functions of x = ln theta of the free parameters."""

    def residuals(self, x: Vector) -> Vector:
        """r_i(x) = P_model,i/P_observed,i - 1."""

    def jacobian(self, x: Vector) -> Vector:
        """d r_i / d x_j, one column per free parameter."""


@dataclass(frozen=True)
class Settings:
    """How a fit is judged: confidence of the intervals, the status threshold, the stated scatter, the test level.

    ``stated_scatter`` is the relative scatter of one pull-off measurement assumed where the rows carry no
    replicates (``fit.relative_scatter`` of workflow/config.yaml); ``noise_floor`` floors the residual scale.
    """

    confidence: float = 0.95
    max_relative_se: float = MAX_RELATIVE_SE
    stated_scatter: float = 0.05
    alpha: float = 0.05
    noise_floor: float = 1e-3


@dataclass(frozen=True)
class Interval:
    """The profile-likelihood interval of one parameter in natural units; an end None is open (reaches the box)."""

    lower: float | None
    upper: float | None
    refits: int

    @property
    def closed(self) -> bool:
        """Both ends lie inside the box."""
        return self.lower is not None and self.upper is not None


@dataclass(frozen=True)
class GoodnessOfFit:
    """The test of the misfit: its name, statistic, degrees of freedom, p-value, verdict and a sentence."""

    test: Literal["lack_of_fit", "stated_scatter", "none"]
    statistic: float | None
    dof: tuple[int, ...]
    p_value: float | None
    rejected: bool
    text: str


def t_quantile(confidence: float, dof: int) -> float:
    """t_(dof)(1 - alpha/2) of a two-sided interval of ``confidence`` = 1 - alpha."""
    return float(stats.t.ppf(0.5 + confidence / 2.0, dof))


class _Profile:
    """tau_k - t* along one side of x_k: S_k(x_k) with the other free parameters refitted from the last optimum."""

    def __init__(self, model: ResidualModel, x_hat: Vector, k: int, log_bounds: tuple[Vector, Vector],
                 scale: tuple[float, float, float], side: float) -> None:
        """The fit's model, optimum ``x_hat``, held index ``k``, box in ln theta; ``scale`` = (S(xhat), s^2, t*)."""
        self.model, self.k, self.side = model, k, side
        self.rss, self.s2, self.t_star = scale
        self.others = [j for j in range(len(x_hat)) if j != k]
        self.bounds = (log_bounds[0][self.others], log_bounds[1][self.others])
        self.start, self.x_hat_k, self.refits = x_hat[self.others].copy(), float(x_hat[k]), 0
        self.x_k = self.start_k = self.x_hat_k
        self.slope = np.zeros(len(self.others))

    def predict_along(self, jac: Vector) -> None:
        """Start each refit on the linearised profile.

        dy/dx_k = -(J_y^T J_y)^-1 J_y^T J_k from the Jacobian at xhat: the others' optimum moves along it as x_k is
        held away from xhat_k.
        """
        if self.others:
            j_y, j_k = jac[:, self.others], jac[:, self.k]
            self.slope = -np.asarray(np.linalg.lstsq(j_y, j_k, rcond=None)[0], dtype=np.float64)

    def _full(self, y: Vector) -> Vector:
        """The full x with x_k held and the others ``y``."""
        x = np.empty(len(self.others) + 1)
        x[self.k], x[self.others] = self.x_k, y
        return x

    def _residuals(self, y: Vector) -> Vector:
        """The residuals with x_k held."""
        return self.model.residuals(self._full(y))

    def _jacobian(self, y: Vector) -> Vector:
        """Their Jacobian in the refitted parameters."""
        return self.model.jacobian(self._full(y))[:, self.others]

    def misfit(self, x_k: float) -> float:
        """S_k(x_k); the refit starts from the optimum of the previous call (warm)."""
        self.x_k = x_k
        if not self.others:
            r = self.model.residuals(self._full(np.empty(0)))
            return float(r @ r)
        start = np.clip(self.start + self.slope * (x_k - self.start_k), *self.bounds)
        result = least_squares(self._residuals, start, jac=self._jacobian, method="trf", bounds=self.bounds,
                               xtol=_REFIT_TOL, ftol=_REFIT_TOL, gtol=_REFIT_TOL, max_nfev=40)
        self.refits += 1
        self.start, self.start_k = result.x, x_k
        return float(result.fun @ result.fun)

    def excess(self, distance: float) -> float:
        """|tau_k| - t* at x_k = xhat_k + side * ``distance`` (negative inside the interval)."""
        return math.sqrt(max(self.misfit(self.x_hat_k + self.side * distance) - self.rss, 0.0) / self.s2) - self.t_star


def profile_interval(model: ResidualModel, x_hat: Vector, k: int, log_bounds: tuple[Vector, Vector],
                     s2: float, dof: int, confidence: float = 0.95) -> Interval:
    """The profile-t interval of parameter k (module docstring) in natural units, exp of its ends in ln theta.

    ``s2`` is the residual variance s^2 (floored by the caller). Each end: :func:`_profile_end`.
    """
    r_hat = model.residuals(x_hat)
    rss, jac = float(r_hat @ r_hat), model.jacobian(x_hat)
    t_star = t_quantile(confidence, dof)
    try:
        se_k = math.sqrt(s2 * float(np.linalg.inv(jac.T @ jac)[k, k]))
    except (np.linalg.LinAlgError, ValueError):
        se_k = math.inf
    ends, refits = [], 0
    for side in (-1.0, 1.0):
        profile = _Profile(model, x_hat, k, log_bounds, (rss, s2, t_star), side)
        profile.predict_along(jac)
        room = float(log_bounds[1][k] - x_hat[k] if side > 0 else x_hat[k] - log_bounds[0][k])
        distance = _profile_end(profile, room, t_star * se_k)
        ends.append(None if distance is None else float(x_hat[k]) + side * distance)
        refits += profile.refits
    lower, upper = (None if end is None else math.exp(end) for end in ends)
    return Interval(lower, upper, refits)


def _profile_end(profile: _Profile, room: float, wald: float) -> float | None:
    """The distance from xhat_k to the end of the interval on the profile's side; None where it is open.

    A first step of the Wald half-width ``wald`` = t* se_k (all the ``room`` to the bound where se_k is not
    finite), doubled until tau_k passes t* or the bound is reached (open), then :func:`_illinois` on tau_k - t*
    from the bracket (tau_k - t* is -t* at xhat_k) to :data:`TAU_RTOL` of t*.
    """
    step = min(wald if math.isfinite(wald) and wald > 0.0 else room, room)
    inside, value_inside = 0.0, -profile.t_star
    for _ in range(_EXPANSIONS):
        if step <= 0.0:
            return None
        value = profile.excess(step)
        if value >= 0.0:
            return _illinois(profile, (inside, value_inside), (step, value), TAU_RTOL * profile.t_star)
        if step >= room * (1.0 - 1e-12):
            return None
        inside, value_inside, step = step, value, min(2.0 * step, room)
    return None


def _illinois(profile: _Profile, below: tuple[float, float], above: tuple[float, float], tolerance: float) -> float:
    """The root of :meth:`_Profile.excess` in the bracket (distance, value) ``below`` < 0 <= ``above``.

    The Illinois variant of regula falsi (Dowell & Jarratt, BIT 11, 1971: superlinear, the bracket kept), to
    |excess| <= ``tolerance``; the bracket's end nearer the root after :data:`_SECANT_STEPS` steps.
    """
    (a, fa), (b, fb), side = below, above, 0
    for _ in range(_SECANT_STEPS):
        c = b - fb * (b - a) / (fb - fa)
        fc = profile.excess(c)
        if abs(fc) <= tolerance:
            return c
        if fc < 0.0:
            a, fa = c, fc
            fb, side = (fb / 2.0 if side == -1 else fb), -1
        else:
            b, fb = c, fc
            fa, side = (fa / 2.0 if side == 1 else fa), 1
    return a if abs(fa) < abs(fb) else b


def relative_standard_errors(jac: Vector, s2: float) -> Vector | None:
    """sqrt(diag(s^2 (J^T J)^-1)): the standard errors of ln theta; None where J has lower numerical rank."""
    if jac.shape[1] == 0:
        return np.zeros(0)
    if np.linalg.matrix_rank(jac) < jac.shape[1]:
        return None
    try:
        variance = s2 * np.diag(np.linalg.inv(jac.T @ jac))
    except np.linalg.LinAlgError:
        return None
    return np.sqrt(np.maximum(variance, 0.0)) if np.all(np.isfinite(variance)) else None


def parameter_status(at_bound: bool, relative_se: float | None, interval: Interval | None,
                     max_relative_se: float = MAX_RELATIVE_SE) -> tuple[ParameterStatus, str]:
    """The status of one freed parameter and why (module docstring: one rule for w0, n and v0)."""
    if at_bound:
        return "at_bound", "ends on (or next to) its bound: the rows push it out of the box"
    if relative_se is None or not math.isfinite(relative_se):
        return "not_identifiable", "no standard error: the rows do not separate it from the other parameters"
    if relative_se > max_relative_se:
        return "not_identifiable", f"relative standard error {relative_se:.3g} > {max_relative_se:g}"
    if interval is None or not interval.closed:
        return "not_identifiable", "its interval reaches the bound of the box: the rows do not exclude the bound"
    return "fitted", f"relative standard error {relative_se:.3g}"


def condition_groups(keys: Sequence[tuple[float, ...]]) -> NDArray[np.int64]:
    """Each row's condition as an integer label (rows with equal keys are replicates), in order of first appearance."""
    labels: dict[tuple[float, ...], int] = {}
    return np.array([labels.setdefault(key, len(labels)) for key in keys], dtype=np.int64)


def goodness_of_fit(residuals: Vector, groups: NDArray[np.int64], parameters: int, settings: Settings) -> GoodnessOfFit:
    """The lack-of-fit F test against the replicates' pure error, else the chi-square test against the stated scatter.

    ``residuals`` are the relative residuals at the fit, ``groups`` each row's condition (:func:`condition_groups`),
    ``parameters`` the number of free parameters p (module docstring).
    """
    m, g = len(residuals), int(groups.max()) + 1 if len(groups) else 0
    rss = float(residuals @ residuals)
    means = np.bincount(groups, weights=residuals, minlength=g) / np.maximum(np.bincount(groups, minlength=g), 1)
    pure = float(np.sum((residuals - means[groups]) ** 2))
    if g - parameters >= 1 and m - g >= 1 and pure > 0.0:
        dof = (g - parameters, m - g)
        statistic = ((rss - pure) / dof[0]) / (pure / dof[1])
        p_value = float(stats.f.sf(statistic, *dof))
        return GoodnessOfFit("lack_of_fit", statistic, dof, p_value, p_value < settings.alpha,
                             f"lack-of-fit F test against the replicates' pure error: F({dof[0]}, {dof[1]}) = "
                             f"{statistic:.3g}, p = {p_value:.2g}")
    if m - parameters >= 1:
        statistic = rss / settings.stated_scatter**2
        p_value = float(stats.chi2.sf(statistic, m - parameters))
        return GoodnessOfFit("stated_scatter", statistic, (m - parameters,), p_value, p_value < settings.alpha,
                             f"chi-square test against a stated relative scatter of {settings.stated_scatter:g} "
                             f"(no replicates to measure it): chi2({m - parameters}) = {statistic:.3g}, "
                             f"p = {p_value:.2g}")
    return GoodnessOfFit("none", None, (), None, False,
                         f"no test: {m} rows leave no degree of freedom beyond {parameters} parameters")
