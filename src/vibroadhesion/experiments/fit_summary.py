"""The summary of a finished Gent–Schultz fit: estimates, statuses, intervals, goodness of fit (Sec. 3.4).

Every level's search (:mod:`vibroadhesion.experiments.fitting`, :mod:`vibroadhesion.experiments.simulation_fit`)
ends in a *fit record* (:func:`fit_record`): the parameters at the optimum x = ln theta of the free ones, the
Jacobian and residuals there, the box, and the residual model the search minimised. :func:`fitted_summary` turns it
into the JSON-ready summary of results/fit/gent_schultz.json (schema: pipeline/schemas/fit.schema.json): one status
per parameter and per level by the rules of :mod:`vibroadhesion.experiments.fit_statistics`, the profile-likelihood
interval of each parameter inside the box, the standard errors (Gauss-Newton, s^2 (J^T J)^-1 in ln theta mapped to
natural units by the delta method, s^2 = RSS/(m - p) floored at the noise floor) and the goodness-of-fit test.
Intervals are computed only for a fit with no parameter on a bound: parameters conditional on another at a bound
are not determined by the rows (``not_identifiable``, with the reason), and their profiles would cost the slowest
refits (the full model far out in the box). A ``poor_fit`` level keeps its intervals, conditional on a model the
rows reject: the level's status says so wherever they are shown, and the figures never use it.

A level's status is the first of: ``poor_fit`` (the goodness-of-fit test rejects the misfit), ``at_bound`` (a
parameter ends on a bound), ``not_identifiable`` (a freed parameter is not determined by the rows), ``fitted``
(every freed parameter is determined); ``determined`` lists the parameters that are.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd
from scipy.optimize import OptimizeResult

from vibroadhesion.experiments.fit_statistics import (
    GoodnessOfFit,
    Interval,
    ResidualModel,
    Settings,
    condition_groups,
    goodness_of_fit,
    parameter_status,
    profile_interval,
    relative_standard_errors,
)
from vibroadhesion.experiments.pulloff import GentSchultzParameters

PARAMETERS = ("w0", "n", "v0")
UNITS = {"w0": "J/m^2", "n": "1", "v0": "m/s"}

#: Box searched by the fit (natural units). n: the exponents for which the J-integrals, the roots
#: of Eqs. (72), (106) and the simulation are tested (tests/test_integrals.py, test_simulate.py);
#: w0: 1 mJ/m^2 to 10 J/m^2 spans van der Waals surfaces to tacky elastomers (the paper's 0.236);
#: v0: 1 nm/s to 1 m/s, the reference speeds of Gent–Schultz fits (the paper's 44.5 um/s).
BOUNDS = {"w0": (1e-3, 10.0), "n": (0.05, 4.0), "v0": (1e-9, 1.0)}

#: A log-parameter closer than this to ln of a bound is on it.
_ON_BOUND = 1e-6
#: A parameter within _NEAR_BOUND of a bound in ln (1 %) whose bound lies within _BOUND_SE of its standard errors is
#: reported on it: where the rows hardly constrain it the search stops short of the bound they push it to (by its
#: ftol/gtol, with standard errors up to 1e10), and the rows do not exclude the bound.
_NEAR_BOUND = 1e-2
_BOUND_SE = 2.0

INTERVAL_METHOD = "profile likelihood (profile t, Bates & Watts 1988, Sec. 6.1)"


def fit_record(params: GentSchultzParameters, result: OptimizeResult, residuals: np.ndarray, free: tuple[str, ...],
               log_bounds: tuple[np.ndarray, np.ndarray], model: ResidualModel | None = None) -> dict[str, Any]:
    """The fit record of a finished search in ln(free) (every level's, the simulation's too).

    ``params`` and ``residuals`` at ``result.x``; the free parameters within 1e-6 of ln of a bound are
    ``at_bound``, and ``bound_distance`` keeps each one's distance to the nearer bound in ln; s^2 = RSS/(m - p)
    over the m rows and p free parameters; ``model`` the residuals the search minimised (for the intervals).
    """
    lo, hi = log_bounds
    distance = np.minimum(result.x - lo, hi - result.x)
    dof = len(residuals) - len(free)
    return {
        "params": params,
        "x": np.asarray(result.x, dtype=float),
        "log_bounds": log_bounds,
        "model": model,
        "jac": result.jac,
        "at_bound": [name for name, d in zip(free, distance, strict=True) if d < _ON_BOUND],
        "bound_distance": dict(zip(free, distance.tolist(), strict=True)),
        "s2": float(residuals @ residuals) / dof if dof > 0 else math.inf,
        "residuals": residuals,
        "nfev": int(result.nfev),
        "message": str(result.message),
    }


def condition_keys(rows: pd.DataFrame) -> list[tuple[float, float, float]]:
    """Each row's test condition (frequency, h1, withdrawal speed); static rows (h1 = 0) share one condition."""
    speeds = rows["withdrawal_speed_um_s"].fillna(0.0) if "withdrawal_speed_um_s" in rows else np.zeros(len(rows))
    return [(0.0, 0.0, 0.0) if float(h) == 0.0 else (float(f), float(h), float(v))
            for f, h, v in zip(rows["frequency_hz"], rows["h1_um"], speeds, strict=True)]


def fitted_summary(rows: pd.DataFrame, fit: dict[str, Any], free: tuple[str, ...], v0_note: str,
                   settings: Settings | None = None) -> dict[str, Any]:
    """Statuses, estimates, intervals, standard errors, goodness of fit and residuals of a fit record."""
    settings = settings or Settings()
    s2 = max(fit["s2"], settings.noise_floor**2)
    at_bound, notes = _bound_statuses(fit, free, s2)
    inside = tuple(name for name in free if name not in at_bound)
    rel_se = relative_standard_errors(fit["jac"][:, [free.index(name) for name in inside]], s2)
    gof = goodness_of_fit(fit["residuals"], condition_groups(condition_keys(rows)), len(free), settings)
    judged = rel_se is not None and not at_bound
    profiled = () if rel_se is None else tuple(  # a relative SE above the threshold is not_identifiable already
        name for name, se in zip(inside, rel_se, strict=True) if se <= settings.max_relative_se)
    intervals = _intervals(fit, free, profiled, s2, settings) if judged else {}
    statuses = {name: parameter_status(name in at_bound, None if rel_se is None else float(rel_se[inside.index(name)])
                                       if name in inside else None, intervals.get(name), settings.max_relative_se)
                for name in free}
    if rel_se is None and inside:
        notes.append(f"the Jacobian has lower rank than the {len(inside)} free parameters inside the box: the rows "
                     f"do not determine {', '.join(inside)} separately (no standard errors)")
    elif not judged:
        notes.append(f"no intervals: {', '.join(at_bound)} at a bound leaves the others conditional on it")
        statuses = {name: ("not_identifiable", "no interval: another parameter is at a bound") if status == "fitted"
                    else (status, why) for name, (status, why) in statuses.items()}
    notes += [f"{name} not determined by these rows: {why}" for name, (status, why) in statuses.items()
              if status == "not_identifiable" and judged]
    theta = np.array([getattr(fit["params"], name) for name in inside])
    cov = None if rel_se is None else _natural_covariance(fit["jac"][:, [free.index(n) for n in inside]], s2, theta)
    return {
        "status": level_status([status for status, _ in statuses.values()], gof),
        "determined": [name for name in free if statuses[name][0] == "fitted"],
        "note": "; ".join(notes),
        "free_parameters": list(free),
        "at_bound": at_bound,
        "parameters": parameter_table(fit["params"], statuses, inside, cov, intervals),
        "covariance": {"parameters": [] if cov is None else list(inside),
                       "matrix": [] if cov is None else cov.tolist()},
        "goodness_of_fit": goodness_record(gof),
        "interval_method": INTERVAL_METHOD,
        "residuals_mN": [{"line": int(line), "residual": float(r * obs)}
                         for line, r, obs in zip(rows["line"], fit["residuals"], rows["pulloff_mN"], strict=True)],
        "rms_relative_residual": float(np.sqrt(np.mean(fit["residuals"] ** 2))),
        "v0_identifiable": "v0" in free,
        "v0_note": v0_note,
        "function_evaluations": fit["nfev"],
        "optimizer_message": fit["message"],
    }


def _bound_statuses(fit: dict[str, Any], free: tuple[str, ...], s2: float) -> tuple[list[str], list[str]]:
    """The free parameters on a bound (on it, or within 1 % and two standard errors of it) and a note for each."""
    notes = [f"{name} ends on its bound {getattr(fit['params'], name):.3g} {UNITS[name]}: "
             f"the model cannot represent the rows inside {BOUNDS[name]}" for name in fit["at_bound"]]
    inside = [name for name in free if name not in fit["at_bound"]]
    rel_se = relative_standard_errors(fit["jac"][:, [free.index(name) for name in inside]], s2)
    near = [] if rel_se is None else [
        name for name, se in zip(inside, rel_se, strict=True) if fit["bound_distance"][name] < min(_NEAR_BOUND,
                                                                                                 _BOUND_SE * se)]
    notes += [f"{name} = {getattr(fit['params'], name):.4g} {UNITS[name]} ends within 1 % and {_BOUND_SE:g} standard "
              f"errors of its bound in {BOUNDS[name]}: the rows do not determine it inside the box" for name in near]
    return [*fit["at_bound"], *near], notes


def _intervals(fit: dict[str, Any], free: tuple[str, ...], inside: tuple[str, ...], s2: float,
               settings: Settings) -> dict[str, Interval]:
    """The profile interval of each parameter of ``inside`` (none without the residual model or a spare row)."""
    dof = len(fit["residuals"]) - len(free)
    if fit["model"] is None or dof < 1:
        return {}
    return {name: profile_interval(fit["model"], fit["x"], free.index(name), fit["log_bounds"], s2, dof,
                                   settings.confidence) for name in inside}


def level_status(statuses: list[str], gof: GoodnessOfFit) -> str:
    """``poor_fit``, ``at_bound``, ``not_identifiable`` or ``fitted``: the first that holds (module docstring)."""
    if gof.rejected:
        return "poor_fit"
    for status in ("at_bound", "not_identifiable"):
        if status in statuses:
            return status
    return "fitted"


def goodness_record(gof: GoodnessOfFit) -> dict[str, Any]:
    """The goodness-of-fit test as JSON."""
    return {"test": gof.test, "statistic": gof.statistic, "dof": list(gof.dof), "p_value": gof.p_value,
            "rejected": gof.rejected, "text": gof.text}


def _natural_covariance(jac: np.ndarray, s2: float, theta: np.ndarray) -> np.ndarray | None:
    """Gauss-Newton covariance s^2 (J^T J)^-1 in ln theta mapped to theta (delta method); None if singular."""
    if jac.shape[1] == 0:
        return np.zeros((0, 0))
    try:
        cov = s2 * np.linalg.inv(jac.T @ jac) * np.outer(theta, theta)
    except np.linalg.LinAlgError:
        return None
    return cov if np.all(np.isfinite(cov)) else None


def parameter_table(params: GentSchultzParameters, statuses: Mapping[str, tuple[str, str]], inside: tuple[str, ...],
                    cov: np.ndarray | None, intervals: dict[str, Interval]) -> dict[str, Any]:
    """Per parameter: estimate, unit, status and why, standard error, interval; ``published`` where not freed."""
    table = {}
    for name in PARAMETERS:
        status, why = statuses.get(name, ("published", "not fitted: the published value (Fig. 4 caption)"))
        entry: dict[str, Any] = {"estimate": getattr(params, name), "unit": UNITS[name], "status": status,
                                 "reason": why, "std_error": None, "interval": None}
        if name in inside and cov is not None:
            entry["std_error"] = math.sqrt(max(cov[inside.index(name), inside.index(name)], 0.0))
        if name in intervals:
            entry["interval"] = [intervals[name].lower, intervals[name].upper]
        table[name] = entry
    return table


def published_table(params: GentSchultzParameters) -> dict[str, Any]:
    """The parameter table of a level that fitted nothing: the published values, status ``published``."""
    return parameter_table(params, {}, (), None, {})


def start_from_fit(summary: dict[str, Any], published: GentSchultzParameters) -> GentSchultzParameters | None:
    """A start point of the full model's search from a cheaper level's fit: what it determined, published elsewhere.

    None where the level determined nothing or the rows reject its model (``poor_fit``, ``at_bound``, failed): an
    undetermined estimate is any point of a flat valley (n = 3.8 where the rows say nothing on n), where the full model
    costs most to evaluate and which the search would have to leave again.
    """
    if summary["status"] not in ("fitted", "not_identifiable") or not summary.get("determined"):
        return None
    p = summary["parameters"]
    kept = {name: p[name]["estimate"] for name in summary["determined"]}
    return replace(published, **kept)


#: The fitted levels from the most to the least faithful to the full model (the simulation is the reference; the
#: exact averaging with force-controlled detachment is within 0.3 % of it up to 47 um at the rig, results/validation):
#: the order in which the figures fall back when the preferred level's fit is not ``fitted``.
FIDELITY = ("simulation", "exact_averaging_force_minimum", "exact_averaging", "refined", "leading")


#: A level's status in a reason a figure's title gives.
_STATUS_PHRASES = {"poor_fit": "poor (the rows reject it)", "at_bound": "at a bound of the box",
                   "not_identifiable": "not determined by the rows", "failed": "failed"}


def figures_choice(fits: dict[str, dict[str, Any]], preferred: str) -> tuple[str, str]:
    """Which parameter set the figures use, and why (a short clause for the figures' titles).

    The ``preferred`` level's fit if it is ``fitted``, else the most faithful level (:data:`FIDELITY`) whose fit is,
    else ``"published"``; never a fit that is at a bound, poor or not determined.
    """
    if all(fit["status"] == "published" for fit in fits.values()):
        return "published", "no measured rows"
    status = fits[preferred]["status"] if preferred in fits else "not run"
    if status == "fitted":
        return preferred, f"the {preferred} fit determines every parameter it fits"
    why = f"the {preferred} fit is {_STATUS_PHRASES.get(status, status)}"
    for level in (name for name in FIDELITY if name in fits and name != preferred):
        if fits[level]["status"] == "fitted":
            return level, f"{why}; {level} is the most faithful level whose fit is determined"
    return "published", f"{why}, and no level's fit is determined"
