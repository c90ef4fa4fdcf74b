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

Starts. The misfit surface of the full model has more than one basin (the families' branches above), and from
the published parameters alone the search can run to a bound while a cheaper level fits the same rows inside the
box. The search therefore starts from several points (:func:`start_points`): the published set and what the
cheaper levels determined (:func:`~vibroadhesion.experiments.fit_summary.start_from_fit`), each with w0 scaled
by the ratio of the simulated to the observed forces there (one
evaluation: the least-squares factor c = sum q_i / sum q_i^2 of q_i = P*_i/P_observed,i, since |P_cr| scales
with w0 through |P_JKR|, Eq. 70, and the amplification moves less); the :data:`SEARCHES` starts of least predicted
misfit are searched (a further one only while the best so far ends on a bound), each with its own families, and
the fit of least stated misfit is kept.

The least-squares search, the identifiability rule for v0 (at least two frequencies and a relative
standard error below the threshold of every parameter's status) and the summary are those of
:mod:`vibroadhesion.experiments.fitting` and :mod:`vibroadhesion.experiments.fit_summary`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import pandas as pd
from scipy.optimize import OptimizeResult, least_squares

from vibroadhesion.core.groups import PHAT_JKR
from vibroadhesion.experiments.envelope import (
    WARM_ITERATIONS,
    Extremum,
    diagnostics,
    envelope_log_derivatives,
    pulloff_problem,
    start_state,
)
from vibroadhesion.experiments.fit_statistics import Settings
from vibroadhesion.experiments.fit_summary import BOUNDS, fit_record, fitted_summary
from vibroadhesion.experiments.fitting import FitError, v0_gate, v0_note_before_fit
from vibroadhesion.experiments.pulloff import GentSchultzParameters, jkr_mN
from vibroadhesion.experiments.virtual_pulloff import traced_family
from vibroadhesion.numerics.progress import Heartbeat

#: The warm family starts this many family steps (0.2 in deltabar_m) on the compressive side of the last pull-off.
WARM_MARGIN = 2
_FAMILY_STEP = 0.2
#: How many of the start points (:func:`start_points`) are searched in full: the best one (a second search from the
#: next start, tried while the best ends on a bound, doubled the cost of rows the full model cannot represent, whose
#: searches run far out in the box where families are long).
SEARCHES = 1

#: The key of the static JKR rows (h1 = 0, no frequency): their pull-off is |P_cr^JKR| (Eq. 70).
STATIC = (0.0, 0.0)
#: The optional column of a row's withdrawal speed V in um/s (0: quasi-static). A row with V > 0 is keyed
#: (f, h1, V) and predicted by the withdrawal at that speed (:mod:`vibroadhesion.experiments.speed_fit`).
SPEED_COLUMN = "withdrawal_speed_um_s"
#: A pair's key: (f, h1) of a quasi-static test (or :data:`STATIC`), (f, h1, V) of a test at a withdrawal speed.
Key = tuple[float, ...]

#: Statuses of a pair whose force is a pull-off (the virtual pull-off's, or Eq. 70 for a static test).
WITH_PULLOFF = ("pulloff", "static_jkr")


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
            start = None if warm is None else (warm[0] + WARM_MARGIN * _FAMILY_STEP, start_state(warm[1]))
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
                forces[i] = diagnostics(at[1]).phat_m / PHAT_JKR * jkr_mN(params.w0, self.geometry["radius"])
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


class _StatedMisfit:
    """The stated model's residuals and Jacobian of an objective (the misfit the fit reports; for the intervals)."""

    def __init__(self, objective: _Objective) -> None:
        """The objective whose :meth:`_Objective.stated_residuals` the fit minimised last."""
        self.objective = objective

    def residuals(self, log_values: np.ndarray) -> np.ndarray:
        """P_cr/P_observed - 1 per row; -1 where the pair has no pull-off."""
        return self.objective.stated_residuals(log_values)

    def jacobian(self, log_values: np.ndarray) -> np.ndarray:
        """Their envelope Jacobian."""
        return self.objective.stated_jacobian(log_values)


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
    return fit_record(params, result, residuals, free, (lo, hi), _StatedMisfit(objective))


def start_points(rows: pd.DataFrame, candidates: Sequence[GentSchultzParameters], geometry: dict[str, float],
                 progress: Heartbeat | None = None) -> list[GentSchultzParameters]:
    """The candidates with w0 scaled to the rows (module docstring), least predicted misfit first, without repeats.

    One evaluation per candidate (candidates within 1 % of one already evaluated in every parameter are passed over):
    q_i = P*_i/P_observed,i there, the scale c = sum q_i / sum q_i^2 and the predicted misfit sum (c q_i - 1)^2 of
    the scaled start. A candidate whose families give no force is kept unscaled, after the others.
    """
    scored: list[tuple[float, int, GentSchultzParameters]] = []
    for index, candidate in enumerate(candidates):
        if any(_close(candidate, other) for other in candidates[:index]):
            continue
        families = _Families(sorted(set(_pair_keys(rows))), geometry, progress=progress)
        q = _Objective(rows, candidate, ("w0",), families).residuals(np.log([candidate.w0])) + 1.0
        q = q[np.isfinite(q) & (q > 0)]
        if q.size == 0:
            scored.append((math.inf, index, candidate))
            continue
        scale = float(q.sum() / (q @ q))
        w0 = float(np.clip(candidate.w0 * scale, *BOUNDS["w0"]))
        predicted = float(np.sum((scale * q - 1.0) ** 2))
        scored.append((predicted if math.isfinite(predicted) else math.inf, index, replace(candidate, w0=w0)))
    return [params for _, _, params in sorted(scored)]  # (misfit, order given): the indices are distinct


def _close(a: GentSchultzParameters, b: GentSchultzParameters, tolerance: float = 1e-2) -> bool:
    """Do ``a`` and ``b`` differ by less than ``tolerance`` (relative) in every parameter?"""
    return all(abs(getattr(a, name) / getattr(b, name) - 1.0) < tolerance for name in ("w0", "n", "v0"))


def _best_search(rows: pd.DataFrame, starts: list[GentSchultzParameters], geometry: dict[str, float],
                 progress: Heartbeat | None) -> tuple[dict[str, Any], _Families]:
    """The (w0, n) fit of least stated misfit over searches from the first :data:`SEARCHES` starts, and its families.

    The next start is searched only while the best fit so far ends on a bound (a search that ends inside the box is
    a minimum the rows admit; another start costs as much again). A search that fails is passed over while another
    succeeds; :class:`FitError` (the first reason) if none does.
    """
    best: tuple[float, dict[str, Any], _Families] | None = None
    failures: list[str] = []
    for start in starts[:SEARCHES]:
        families = _Families(sorted(set(_pair_keys(rows))), geometry, progress=progress)
        try:
            fit = _least_squares(rows, start, ("w0", "n"), families)
        except FitError as exc:
            failures.append(str(exc))
            continue
        cost = float(fit["residuals"] @ fit["residuals"])
        if best is None or cost < best[0]:
            best = (cost, fit, families)
        if not best[1]["at_bound"]:
            break
    if best is None:
        raise FitError(failures[0] if failures else "simulation fit: no start point")
    return best[1], best[2]


def fit_simulation(rows: pd.DataFrame, published: GentSchultzParameters, *, radius: float, reduced_modulus: float,
                   settings: Settings, starts: Sequence[GentSchultzParameters] = (),
                   progress: Heartbeat | None = None) -> dict[str, Any]:
    """The fitted part of ``fitting.fit_gent_schultz``'s summary for the level ``simulation`` (module docstring).

    w0 and n are fitted from the best of ``published`` and ``starts`` (:func:`start_points`, :func:`_best_search`);
    v0 too when the rows span two frequencies and its relative standard error at the (w0, n) fit passes the
    threshold of ``settings`` (residual scale floored at its noise floor). Adds ``row_status`` (status and model force
    per row at the fit, with its withdrawal speed where the rows have speeds), ``families_traced`` (and
    ``withdrawals_run``) and ``starts`` (the start points searched). Each traced family and withdrawal beats
    ``progress``.
    """
    pairs = sorted(set(_pair_keys(rows)))
    geometry = {"radius": radius, "reduced_modulus": reduced_modulus}
    ranked = start_points(rows, [published, *starts], geometry)  # one evaluation each: no heartbeat needed
    fit, families = _best_search(rows, ranked, geometry, progress)
    free: tuple[str, ...] = ("w0", "n")
    v0_note = v0_note_before_fit("simulation", len({pair[0] for pair in pairs if pair != STATIC}), len(rows))
    if not v0_note:
        params = fit["params"]
        objective = _Objective(rows, params, ("w0", "n", "v0"), families)
        jac = objective.stated_jacobian(np.log([params.w0, params.n, params.v0]))
        identifiable, v0_note = v0_gate(jac, fit["s2"], settings)
        if identifiable:
            with_v0 = _least_squares(rows, params, ("w0", "n", "v0"), families)
            if "v0" in with_v0["at_bound"]:
                v0_note = f"v0 not identifiable: the fit drives it to its bound {with_v0['params'].v0:.3g} m/s"
            else:
                free, fit = ("w0", "n", "v0"), with_v0
    summary = fitted_summary(rows, fit, free, v0_note, settings)
    searched = [{name: getattr(start, name) for name in ("w0", "n", "v0")} for start in ranked[:SEARCHES]]
    return summary | _row_statuses(rows, fit["params"], families, summary["note"]) | {"starts": searched}


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
