"""The full model as a fit level: least squares of w0, n (and v0) on the simulated pull-off (Sec. 3.4).

Forward model. A row (frequency f, base amplitude h1, |P_cr| in mN) is predicted by the virtual pull-off
of the rigidly fixed indenter (:func:`vibroadhesion.experiments.virtual_pulloff.traced_pulloff`: the
quasi-static family of periodic steady states of Eqs. 4-11 in the base offset, the pull-off at its most
tensile mean force), solved once per distinct (f, h1) pair and scattered back to the rows; a static JKR
test (h1 = 0) is |P_cr^JKR| = (3 pi/2) R w0 (Eq. 70), d ln P/d ln w0 = 1. After the
first evaluation every family starts warm, from its pair's last most tensile orbit, WARM_MARGIN steps on
the compressive side of it (the extremum moves little between the trial points of the search); a warm
start past the new extremum is traced again from the cold start.

Derivatives (envelope theorem). The pull-off is P*(theta) = min over the base offset d of P_m(d, theta),
and at the minimiser d* the mean force is stationary in d, so

    dP*/dtheta = dP_m/dtheta (d*, theta)        at fixed d*,

whatever coordinate d is measured in (here base_offset = (hhat - h0) R/a_o^2, itself a function of w0
through a_o). Each column of the Jacobian is therefore a central difference in ln theta of two periodic
orbits at the fixed d*, warm-started from the orbit at d* (a few shooting periods each), instead of two
re-traced families. Its error: the central difference O(h^2) (h = ENVELOPE_STEP) plus the orbits'
error over h (~1e-10/h), and the extremum's location: |d_found - d*| <= 1e-4 step (Brent's tolerance,
:func:`traced_pulloff`) leaves dP_m/dd = P_m'' (d_found - d*) = O(1e-5), so the envelope derivative
differs from the exact one by O(1e-5) |P_m'' dd*/dtheta|; the test compares it with central differences
of whole families.

Rows without a pull-off. The pull-off is the minimum of the mean force over the base offsets D(theta) at
which the family has steady states,

    P*(theta) = min over d in D(theta) of P_m(d, theta),

attained inside D at a tensile extremum (a pull-off, dP_m/dd = 0: the envelope derivative above) or, where the
family loses contact (or finds no steady state) while P_m still grows more tensile, at the end d_e(theta) of D:
P*(theta) = P_m(d_e(theta), theta), the most tensile mean force the family reached
(:func:`~vibroadhesion.experiments.virtual_pulloff.traced_family`; compressive, a negative force, where the
family ends before its mean force turns tensile). Both are the same minimum, so P* is continuous where the
extremum reaches the end of D (the boundary of the region with a pull-off), as long as d_e moves continuously;
d_e is located to 2^-6 family steps, which leaves P* a jitter of |dP_m/dd| 0.2/64. The search uses P* for every
row: a row whose family ends without a pull-off at a trial point keeps an informative residual
P_m(d_e)/P_observed - 1 and the gradient of its first term, d ln P_m/d ln theta at the fixed d_e by the two
shifted orbits above (the end's own motion dd_e/dtheta is not known without re-tracing; 0 where no shifted orbit
converges next to the end). The trust region accepts a step only where the cost of the residuals falls, so this
partial gradient can slow the search but not make it accept a worse point. With residual -1 and a zero gradient
instead (a zero predicted force), a start where families had no pull-off left too few informative rows and the
search stopped there, and a row predicted far above its measurement made the constant -1 cheaper, drawing the
search into the region without pull-offs: 30 of 70 noise-free 3-row fits at n = 0.3 failed
(benchmarks/simulation_fit.py --starts; none now). A family without any orbit still gets residual -1 and no
gradient.

The fit states its model: a row without a pull-off at the fit is counted as zero force (residual -1, its Jacobian
row 0 in the covariance), named in the note with its status (``row_status``), never dropped. P* is the search's
only: a second search minimises the stated misfit from where the search on P* ends (the rows with a pull-off
fitted, the others a constant), so that the fit is a minimum of the misfit it reports. It also continues past a
jump of P*: the steady states are not unique, and the family traced from the cold (preloaded) start can lose
contact where the family warm-started from a neighbouring pull-off has one (200 Hz, 40 um at w0 = 0.318,
n = 0.264: P*/P_observed - 1 = 0.003 cold, 0.020 warm), so the first search can stop at such a jump (one of the
70 fits above, 35 % off in w0); the second, whose families start warm from the first's end, goes on. A search
that ends with no more pairs with a pull-off than free parameters is a
:class:`~vibroadhesion.experiments.fitting.FitError`.

A row with a withdrawal speed V > 0 (:data:`SPEED_COLUMN`) is predicted instead by the withdrawal at that speed,
once per distinct (f, h1, V), with its own Jacobian (central differences):
:mod:`vibroadhesion.experiments.speed_fit`; a withdrawal without a pull-off is a row without one, as above.

The least-squares search, the identifiability rule for v0 (at least two frequencies and a relative
standard error below ``max_relative_se_v0``) and the summary are those of
:mod:`vibroadhesion.experiments.fitting`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import pandas as pd
from scipy.optimize import OptimizeResult, least_squares

from vibroadhesion import simulation
from vibroadhesion.core import groups
from vibroadhesion.core.groups import PHAT_JKR
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import OrbitDiagnostics, SteadyState
from vibroadhesion.experiments.fitting import BOUNDS, FitError, fit_record, fitted_summary, v0_note_before_fit
from vibroadhesion.experiments.pulloff import GentSchultzParameters, jkr_mN
from vibroadhesion.experiments.virtual_pulloff import traced_family
from vibroadhesion.numerics.progress import Heartbeat

#: Step h in ln theta of the envelope derivative (module docstring: O(h^2) + 1e-10/h, ~1e-6 relative).
ENVELOPE_STEP = 1e-3
#: Shooting periods allowed to an orbit warm-started next to a known one (3-6 suffice, as in a family).
WARM_ITERATIONS = 15
#: The warm family starts this many family steps (0.2 in deltabar_m) on the compressive side of the last pull-off.
WARM_MARGIN = 2
_FAMILY_STEP = 0.2

#: The key of the static JKR rows (h1 = 0, no frequency): their pull-off is |P_cr^JKR| (Eq. 70).
STATIC = (0.0, 0.0)
#: The optional column of a row's withdrawal speed V in um/s (0: quasi-static). A row with V > 0 is keyed
#: (f, h1, V) and predicted by the withdrawal at that speed (:mod:`vibroadhesion.experiments.speed_fit`).
SPEED_COLUMN = "withdrawal_speed_um_s"
#: A pair's key: (f, h1) of a quasi-static test (or :data:`STATIC`), (f, h1, V) of a test at a withdrawal speed.
Key = tuple[float, ...]

#: The most tensile orbit of a pair's family: (base offset d*, orbit there).
Extremum = tuple[float, SteadyState]

#: Statuses of a pair whose force is a pull-off (the virtual pull-off's, or Eq. 70 for a static test).
WITH_PULLOFF = ("pulloff", "static_jkr")


def pulloff_problem(params: GentSchultzParameters, frequency_hz: float, h1_um: float, *, radius: float,
                    reduced_modulus: float, base_offset: float = 0.0) -> Problem:
    """The rigidly fixed problem of one test (Eqs. 4-11): chi0 (Eq. 64), eta1 (Eq. 65), omega_check (Eq. 105)."""
    return Problem(GentSchultz(params.n), groups.chi0(params.w0, reduced_modulus, radius), h1_um * 1e-6 / radius,
                   float(groups.omega_check(frequency_hz, params.v0, radius)), base_offset=base_offset)


def envelope_log_derivatives(params: GentSchultzParameters, frequency_hz: float, h1_um: float, at: Extremum,
                             names: tuple[str, ...], *, radius: float, reduced_modulus: float,
                             step: float = ENVELOPE_STEP) -> np.ndarray:
    """d ln|P_cr| / d ln theta for theta in ``names`` at the pull-off orbit ``at`` (module docstring).

    Central differences in ln theta of the mean force Phat_m of two orbits at the fixed base offset d* of
    ``at``, warm-started from its state (envelope theorem), plus 1 for w0 (|P_cr^JKR| is proportional to w0,
    Eq. 70). Where one shifted orbit does not converge, the one-sided difference with the orbit of ``at``
    (error O(step), ~1e-3 of the derivative); NaN where neither does.
    """
    d_star, orbit = at
    if orbit.orbit is None:
        raise TypeError("the pull-off orbit has no orbit diagnostics")
    derivatives = np.empty(len(names))
    for k, name in enumerate(names):
        plus, minus = (_shifted_phat(params, name, sign * step, frequency_hz, h1_um, at, radius=radius,
                                     reduced_modulus=reduced_modulus) for sign in (1.0, -1.0))
        derivatives[k] = log_difference(plus, minus, orbit.orbit.phat_m, step) + (1.0 if name == "w0" else 0.0)
    return derivatives


def log_difference(plus: float, minus: float, center: float, step: float) -> float:
    """d ln|F|/d ln theta from F at ln theta +- ``step``: central, ln(plus/minus)/(2 step), error O(step^2).

    Where one of them is NaN, the one-sided difference with ``center`` (F at ln theta; error O(step)); NaN where
    both are, or where the two values compared differ in sign (no logarithm).
    """
    pair = ((plus, minus, 2.0 * step) if not (math.isnan(plus) or math.isnan(minus))
            else (plus, center, step) if math.isnan(minus) else (center, minus, step))
    ratio = pair[0] / pair[1]
    return math.log(ratio) / pair[2] if ratio > 0 else math.nan


def shifted(params: GentSchultzParameters, name: str, log_shift: float) -> GentSchultzParameters:
    """``params`` with ``name`` scaled by exp(``log_shift``) (a step in ln theta of Eq. 73's parameters)."""
    return replace(params, **{name: getattr(params, name) * math.exp(log_shift)})


def _shifted_phat(params: GentSchultzParameters, name: str, log_shift: float, frequency_hz: float, h1_um: float,
                  at: Extremum, *, radius: float, reduced_modulus: float) -> float:
    """Phat_m (Eq. 4') of the orbit at the fixed base offset of ``at`` with ``name`` scaled by exp(``log_shift``).

    Warm-started from the orbit of ``at`` with WARM_ITERATIONS periods, then with the shooting's default cap
    (a shooting that stalls next to the pull-off converges then); NaN if neither converges.
    """
    d_star, orbit = at
    problem = pulloff_problem(shifted(params, name, log_shift), frequency_hz, h1_um, radius=radius,
                              reduced_modulus=reduced_modulus, base_offset=d_star)
    state = _start_state(orbit)
    found = simulation.steady_state(problem, initial_state=state, max_iterations=WARM_ITERATIONS)
    if not found.ok:
        found = simulation.steady_state(problem, initial_state=state)
    return found.orbit.phat_m if found.ok and found.orbit is not None else math.nan


@dataclass
class _Families:
    """The distinct (f, h1) pairs of the rows, their last pull-off orbits (warm starts) and the last evaluation.

    An evaluation gives per pair its status, the minimum P* of the mean force over its family in mN (the
    pull-off, or where the family ended without one the most tensile force it reached: module docstring; NaN
    for a family without orbits) and the orbit where it is attained.

    The last evaluation is kept, with the envelope derivatives computed there (least_squares asks the Jacobian
    where it evaluated the residuals last; the v0 test and the 3-parameter search ask it again at the
    2-parameter fit), keyed by ln of the parameters to 1e-12 (the searches reach them through ln).
    """

    pairs: list[Key]
    geometry: dict[str, float]
    warm: dict[Key, Extremum] = field(default_factory=dict)
    key: tuple[float, ...] = ()
    last: tuple[list[str], np.ndarray, list[Extremum | None]] = ([], np.empty(0), [])
    derivatives: dict[str, np.ndarray] = field(default_factory=dict)
    families: int = 0
    withdrawals: int = 0
    progress: Heartbeat | None = None

    def evaluate(self, params: GentSchultzParameters) -> tuple[list[str], np.ndarray, list[Extremum | None]]:
        """Status, P* in mN (module docstring; NaN without orbits) and its orbit for every pair at ``params``."""
        key = tuple(round(math.log(getattr(params, name)), 12) for name in ("w0", "n", "v0"))
        if key == self.key:
            return self.last
        statuses: list[str] = []
        extrema: list[Extremum | None] = []
        forces = np.full(len(self.pairs), math.nan)
        for i, pair in enumerate(self.pairs):
            if pair == STATIC:  # Eq. (70): the static JKR test
                statuses.append("static_jkr")
                extrema.append(None)
                forces[i] = jkr_mN(params.w0, self.geometry["radius"])
                continue
            if len(pair) == 3:  # a test at a withdrawal speed: its dynamic pull-off (experiments/speed_fit.py)
                status, forces[i] = self._withdraw(params, pair)
                statuses.append(status)
                extrema.append(None)
                continue
            problem = pulloff_problem(params, *pair, **self.geometry)
            warm = self.warm.get(pair)
            start = None if warm is None else (warm[0] + WARM_MARGIN * _FAMILY_STEP, _start_state(warm[1]))
            record, at = traced_family(problem, warm=start, iterations=WARM_ITERATIONS)
            self.families += 1
            if self.progress is not None:
                self.progress.beat(f"{i + 1}/{len(self.pairs)} (f, h1) pairs traced at {params}, {self.families} "
                                   "families so far")
            statuses.append(str(record.status))
            extrema.append(at)
            if at is not None:
                if record.status == "pulloff":
                    self.warm[pair] = at
                forces[i] = _diagnostics(at[1]).phat_m / PHAT_JKR * jkr_mN(params.w0, self.geometry["radius"])
        self.key, self.last, self.derivatives = key, (statuses, forces, extrema), {}
        return self.last

    def _withdraw(self, params: GentSchultzParameters, key: Key) -> tuple[str, float]:
        """Status and reading (mN) of the withdrawal of the speed key (f, h1, V) at ``params`` (speed_fit.py)."""
        from vibroadhesion.experiments.speed_fit import speed_pulloff  # imports this module: no cycle

        run = speed_pulloff(params, key[0], key[1], key[2], **self.geometry)
        self.withdrawals += 1
        if self.progress is not None:
            self.progress.beat(f"withdrawal at {key[2]:g} um/s ({key[0]:g} Hz, {key[1]:g} um) at {params}: "
                               f"{run.status}, {self.withdrawals} withdrawals so far")
        return run.status, run.force_mN

    def _log_derivative(self, params: GentSchultzParameters, key: Key, at: Extremum | None, name: str,
                        force: float) -> float:
        """d ln P*/d ln ``name`` of one key (:meth:`log_derivatives`); ``force`` its P* in mN at ``params``."""
        if key == STATIC:
            return float(name == "w0")  # Eq. (70): |P_cr^JKR| is proportional to w0
        if len(key) == 3:
            from vibroadhesion.experiments.speed_fit import speed_log_derivative  # imports this module: no cycle

            self.withdrawals += 2
            return speed_log_derivative(params, key[0], key[1], key[2], name, force, **self.geometry)
        return 0.0 if at is None else float(envelope_log_derivatives(params, key[0], key[1], at, (name,),
                                                                     **self.geometry)[0])

    def log_derivatives(self, params: GentSchultzParameters, name: str) -> np.ndarray:
        """d ln P* / d ln ``name`` per pair at ``params`` (:func:`envelope_log_derivatives` at P*'s orbit).

        0 for a family without orbits. Where the family ended without a pull-off, the derivative at the fixed end
        (module docstring), 0 where no shifted orbit converges there; a pull-off whose shifted orbits both fail has
        no derivative: :class:`FitError`, never a silent 0.
        """
        statuses, forces, extrema = self.evaluate(params)
        if name not in self.derivatives:
            derivatives = np.array([0.0 if math.isnan(force) else self._log_derivative(params, pair, at, name, force)
                                    for pair, at, force in zip(self.pairs, extrema, forces, strict=True)])
            pulloff = np.isin(statuses, WITH_PULLOFF)
            if not np.all(np.isfinite(derivatives[pulloff])):
                raise FitError(f"simulation fit: no orbit next to the pull-off of a pair at {params} when {name} "
                               "is shifted: no derivative")
            self.derivatives[name] = np.nan_to_num(derivatives, nan=0.0)
        return self.derivatives[name]

    def with_pulloff(self, params: GentSchultzParameters) -> np.ndarray:
        """Per pair: does its family have a pull-off at ``params`` (:data:`WITH_PULLOFF`)?"""
        return np.isin(self.evaluate(params)[0], WITH_PULLOFF)


def _pair_keys(rows: pd.DataFrame) -> list[Key]:
    """Each row's key (:data:`Key`).

    (frequency, amplitude); :data:`STATIC` for a static JKR test (h1 = 0, frequency empty); (frequency, amplitude,
    V) for a test at a withdrawal speed V > 0 in um/s (:data:`SPEED_COLUMN`, optional).
    """
    speeds = rows[SPEED_COLUMN] if SPEED_COLUMN in rows else np.zeros(len(rows))
    return [STATIC if float(h) == 0.0 else (float(f), float(h)) if not v > 0 else (float(f), float(h), float(v))
            for f, h, v in zip(rows["frequency_hz"], rows["h1_um"], speeds, strict=True)]


def _start_state(orbit: SteadyState) -> np.ndarray:
    """The state at tau = 0 of a simulated orbit (its diagnostics' ``start_state``)."""
    return _diagnostics(orbit).start_state


def _diagnostics(orbit: SteadyState) -> OrbitDiagnostics:
    """The orbit diagnostics of a simulated steady state (every simulated record has them)."""
    if orbit.orbit is None:
        raise TypeError("a simulated orbit has diagnostics")
    return orbit.orbit


class _Objective:
    """Relative residuals P_model/P_observed - 1 of the rows in ln(free), and their envelope Jacobian."""

    def __init__(self, rows: pd.DataFrame, base: GentSchultzParameters, free: tuple[str, ...],
                 families: _Families) -> None:
        """Rows (frequency_hz, h1_um, pulloff_mN), the parameters not fitted (``base``), the fitted names."""
        self.base, self.free, self.families = base, free, families
        self.observed = rows["pulloff_mN"].to_numpy(float)
        index = {pair: i for i, pair in enumerate(families.pairs)}
        self.row_pair = np.array([index[pair] for pair in _pair_keys(rows)])

    def params_of(self, log_values: np.ndarray) -> GentSchultzParameters:
        """The parameter set at ln(free) = ``log_values``."""
        return replace(self.base, **{name: math.exp(v) for name, v in zip(self.free, log_values, strict=True)})

    def residuals(self, log_values: np.ndarray) -> np.ndarray:
        """The search's residuals P*/P_observed - 1 per row (module docstring); -1 for a family without orbits."""
        _, forces, _ = self.families.evaluate(self.params_of(log_values))
        return np.nan_to_num(forces[self.row_pair] / self.observed - 1.0, nan=-1.0)

    def with_pulloff(self, log_values: np.ndarray) -> np.ndarray:
        """Per row: does its pair have a pull-off at ln(free) = ``log_values``?"""
        per_row: np.ndarray = self.families.with_pulloff(self.params_of(log_values))[self.row_pair]
        return per_row

    def stated_residuals(self, log_values: np.ndarray) -> np.ndarray:
        """The fit's residuals P_cr/P_observed - 1 per row; -1 (zero force) where the pair has no pull-off."""
        return np.where(self.with_pulloff(log_values), self.residuals(log_values), -1.0)

    def stated_jacobian(self, log_values: np.ndarray) -> np.ndarray:
        """The Jacobian of :meth:`stated_residuals`: :meth:`jacobian`, 0 in rows without a pull-off (a constant -1)."""
        return np.where(self.with_pulloff(log_values)[:, None], self.jacobian(log_values), 0.0)

    def jacobian(self, log_values: np.ndarray) -> np.ndarray:
        """d residual / d ln(free) = (P*/P_observed) d ln P*/d ln theta (envelope theorem) of the search's residuals.

        At the fixed end of a family without a pull-off, its partial derivative; 0 for a family without orbits; for a
        row at a withdrawal speed, central differences (:mod:`vibroadhesion.experiments.speed_fit`).
        """
        params = self.params_of(log_values)
        _, forces, _ = self.families.evaluate(params)
        per_pair = np.column_stack([self.families.log_derivatives(params, name) for name in self.free])
        return (np.nan_to_num(forces)[:, None] * per_pair)[self.row_pair] / self.observed[:, None]


def _search(residuals: Callable[[np.ndarray], np.ndarray], jacobian: Callable[[np.ndarray], np.ndarray],
            x0: np.ndarray, log_bounds: tuple[np.ndarray, np.ndarray]) -> OptimizeResult:
    """scipy's trust-region reflective least squares in ln(free) from ``x0`` (tolerances of :func:`_least_squares`)."""
    return least_squares(residuals, x0, jac=jacobian, method="trf", bounds=log_bounds, xtol=1e-8, ftol=1e-10,
                         gtol=1e-10, max_nfev=60)


def _least_squares(rows: pd.DataFrame, base: GentSchultzParameters, free: tuple[str, ...],
                   families: _Families) -> dict[str, Any]:
    """Least squares in ln(free) inside BOUNDS with the envelope Jacobian; the fit record of ``fitting``.

    The search on P* (module docstring), then the stated model's search from where it ends (rows without a
    pull-off a constant -1: the rows with a pull-off fitted), so that the record is a minimum of the misfit it
    states. Tolerances: steps below 1e-8 in ln theta (the parameters to 1e-8 relative)
    or cost changes below 1e-10 relative end a search; the residuals carry the extremum's ~1e-8 relative error
    (:func:`~vibroadhesion.experiments.virtual_pulloff.traced_pulloff`).
    """
    objective = _Objective(rows, base, free, families)
    lo, hi = np.log([BOUNDS[name] for name in free]).T
    x0 = np.clip(np.log([getattr(base, name) for name in free]), lo, hi)
    result = _search(objective.residuals, objective.jacobian, x0, (lo, hi))
    if result.status > 0:
        result = _search(objective.stated_residuals, objective.stated_jacobian, result.x, (lo, hi))
    if result.status <= 0:
        raise FitError(f"simulation fit of {free} did not converge: {result.message}")
    params = objective.params_of(result.x)
    residuals = objective.stated_residuals(result.x)  # re-evaluated: the search may have ended on a rejected trial
    result.jac = np.where(objective.with_pulloff(result.x)[:, None], result.jac, 0.0)  # the stated model's
    found = int(np.count_nonzero(families.with_pulloff(params)))
    if found <= len(free):
        raise FitError(f"simulation fit of {free}: {found} of {len(families.pairs)} (f, h1) pairs have a simulated "
                       f"pull-off at the end of the search ({params}): too few to determine {len(free)} parameters")
    return fit_record(params, result, residuals, free, (lo, hi))


def _v0_relative_se(rows: pd.DataFrame, fit: dict[str, Any], families: _Families, noise_floor: float) -> float:
    """Relative standard error v0 would have if freed at the (w0, n) fit (``fitting``'s rule, envelope Jacobian).

    s^2 (J^T J)^-1 in (ln w0, ln n, ln v0) at a residual scale floored at ``noise_floor``; inf if singular.
    """
    params = fit["params"]
    objective = _Objective(rows, params, ("w0", "n", "v0"), families)
    log_values = np.log([params.w0, params.n, params.v0])
    jac = objective.stated_jacobian(log_values)
    try:
        variance = max(fit["s2"], noise_floor**2) * np.linalg.inv(jac.T @ jac)[-1, -1]
    except np.linalg.LinAlgError:
        return math.inf
    return math.sqrt(max(variance, 0.0)) if np.isfinite(variance) else math.inf


def fit_simulation(rows: pd.DataFrame, published: GentSchultzParameters, *, radius: float, reduced_modulus: float,
                   max_relative_se_v0: float, noise_floor: float, progress: Heartbeat | None = None) -> dict[str, Any]:
    """The fitted part of ``fitting.fit_gent_schultz``'s summary for the level ``simulation`` (module docstring).

    w0 and n are fitted from ``published``; v0 too when the rows span two frequencies and its relative
    standard error at the (w0, n) fit is below ``max_relative_se_v0`` (residual scale floored at
    ``noise_floor``). Adds ``row_status`` (status and model force per row at the fit, with its withdrawal speed
    where the rows have speeds) and ``families_traced`` (and ``withdrawals_run``). Each traced family and
    withdrawal beats ``progress``.
    """
    pairs = sorted(set(_pair_keys(rows)))
    families = _Families(pairs, {"radius": radius, "reduced_modulus": reduced_modulus}, progress=progress)
    free: tuple[str, ...] = ("w0", "n")
    fit = _least_squares(rows, published, free, families)
    v0_note = v0_note_before_fit("simulation", len({pair[0] for pair in pairs if pair != STATIC}), len(rows))
    if not v0_note:
        rel_se = _v0_relative_se(rows, fit, families, noise_floor)
        if rel_se > max_relative_se_v0:
            scale = max(fit["s2"] ** 0.5, noise_floor)
            v0_note = (f"v0 not identifiable: its relative standard error would be {rel_se:.3g} "
                       f"(> {max_relative_se_v0:g}) at a relative residual scale of {scale:.3g}")
        else:
            with_v0 = _least_squares(rows, fit["params"], ("w0", "n", "v0"), families)
            if "v0" in with_v0["at_bound"]:
                v0_note = f"v0 not identifiable: the fit drives it to its bound {with_v0['params'].v0:.3g} m/s"
            else:
                free, fit = ("w0", "n", "v0"), with_v0
                v0_note = f"v0 identifiable: relative standard error {rel_se:.3g}"
    summary = fitted_summary(rows, fit, free, v0_note)
    return summary | _row_statuses(rows, fit["params"], families, summary["note"])


def _row_statuses(rows: pd.DataFrame, params: GentSchultzParameters, families: _Families,
                  note: str) -> dict[str, Any]:
    """Per row: the virtual pull-off's status and force at the fitted parameters; a note naming rows without one."""
    statuses, forces, _ = families.evaluate(params)
    forces = np.where(families.with_pulloff(params), forces, math.nan)
    index = {pair: i for i, pair in enumerate(families.pairs)}
    speeds = any(len(pair) == 3 for pair in families.pairs)  # then each row says its speed (0: quasi-static)
    table = []
    for line, f, h, pair in zip(rows["line"], rows["frequency_hz"], rows["h1_um"], _pair_keys(rows), strict=True):
        i = index[pair]
        table.append({"line": int(line), "frequency_hz": float(f), "h1_um": float(h), "status": statuses[i],
                      "model_mN": None if math.isnan(forces[i]) else float(forces[i])}
                     | ({SPEED_COLUMN: pair[2] if len(pair) == 3 else 0.0} if speeds else {}))
    lost = [f"line {r['line']} ({r['frequency_hz']:g} Hz, {r['h1_um']:g} um"
            f"{f', {r[SPEED_COLUMN]:g} um/s' if r.get(SPEED_COLUMN) else ''}): {r['status']}"
            for r in table if r["model_mN"] is None]
    if lost:
        note = "; ".join(filter(None, [note, "no simulated pull-off at the fit, counted as zero force (residual -1): "
                                       + ", ".join(lost)]))
    return {"note": note, "row_status": table, "families_traced": families.families} | (
        {"withdrawals_run": families.withdrawals} if speeds else {})
