"""Least-squares fit of the Gent–Schultz parameters to pull-off measurements (Sec. 3.4).

Each row is (frequency f, base amplitude h1, |P_cr| in mN). The model is the pull-off
estimate of one level (:func:`vibroadhesion.experiments.pulloff.predict_pulloff`):

* ``leading`` (Eqs. 71–72) and the two exact-averaging levels are frequency independent, so v0
  does not enter: w0 and n are fitted, v0 keeps its published value;
* ``simulation``, the full model (Eqs. 4-11) through the virtual pull-off, is fitted by
  :mod:`vibroadhesion.experiments.simulation_fit` with the same rule for v0 as the refined level;
* ``refined`` (Eqs. 71, 106) depends on v0 through omega_check = 2 pi f R / v0. v0 is fitted
  only when it is identifiable: the rows span at least two frequencies and, with v0 free,
  it stays off its bound and its relative standard error is below ``max_relative_se_v0``.
  Otherwise the fit says why and keeps the published v0.

The parameters are fitted in logarithms (positivity; ln-standard errors are relative errors)
by a trust-region reflective least-squares search (scipy ``trf``) inside :data:`BOUNDS`, on
relative residuals model/observed - 1 (pull-off forces span an order of magnitude; measurement
error is roughly proportional). A parameter that ends on its bound is reported as such
(``status`` ``at_bound``, no standard error): the data push it out of the physical range, which
means the model cannot represent them, not that the bound is the answer; so is a parameter that ends within 1 %
of a bound lying within two of its standard errors (the rows do not exclude the bound). The covariance of the
parameters inside the box is s^2 (J^T J)^-1 with s^2 = RSS/(m - p), mapped back to natural units
by the delta method. For the identifiability test the relative residual scale is floored at
``noise_floor``, so that noise-free (synthetic) rows do not make any parameter look identifiable.
Every fit ends in a status, never in an exception that takes the other levels down: ``published``
(no rows: the published values pass through); ``fitted``;
``at_bound``; ``not_identifiable`` (fewer rows than parameters, or a Jacobian of lower rank than the
free parameters: no standard errors, the published values kept where nothing was fitted); ``failed``
(the model has no solution at a trial point, or the search does not converge, or a row's pull-off force
is not a positive number, e.g. NaN for a simulated row without a pull-off), with the reason.

Rows. The model is evaluated once per distinct (frequency, amplitude) pair, so replicate rows cost
nothing. A static JKR test (``h1_um`` = 0, no vibration) has the pull-off |P_cr^JKR| = (3 pi/2) R w0
(Eq. 70) at every level (Abar = 0, J0 = 1): it pins w0 and carries no frequency. A row measured at a
withdrawal speed (``withdrawal_speed_um_s`` > 0) is predicted by the simulation at that speed
(:mod:`vibroadhesion.experiments.speed_fit`); the asymptotic levels are quasi-static and fit it as if V -> 0.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd
from scipy.optimize import OptimizeResult, least_squares

from vibroadhesion.core import levels
from vibroadhesion.experiments.pulloff import GentSchultzParameters, jkr_mN, predict_pulloff, pulloff_mN
from vibroadhesion.numerics.progress import Heartbeat
from vibroadhesion.numerics.roots import NoRootError

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


class FitError(RuntimeError):
    """The least-squares iteration failed; no estimate is reported."""


ResidualFunction = Callable[[np.ndarray], np.ndarray]
ParameterMap = Callable[[np.ndarray], GentSchultzParameters]


def _model_mN(model: str, params: GentSchultzParameters, freq: np.ndarray, h1: np.ndarray,
              geometry: dict[str, float]) -> np.ndarray:
    """Pull-off (mN) of ``model`` at each row: Eq. (70) for static rows (h1 = 0), the level's estimate otherwise.

    :func:`predict_pulloff` solves the level once per distinct condition; :class:`FitError` where it has no solution.
    """
    out = np.full(h1.shape, jkr_mN(params.w0, geometry["radius"]))
    dynamic = h1 > 0
    if np.any(dynamic):
        pulloff = predict_pulloff(model, params, freq[dynamic], h1[dynamic], **geometry)
        if not np.all(pulloff.found):
            raise FitError(f"{model}: the model has no solution at a trial point ({params})")
        out[dynamic] = pulloff_mN(pulloff, params.w0, geometry["radius"])
    return out


def _residual_function(
    rows: pd.DataFrame, model: str, base: GentSchultzParameters, free: tuple[str, ...], geometry: dict[str, float],
    progress: Heartbeat | None = None,
) -> tuple[ResidualFunction, ParameterMap]:
    """Relative residuals P_model/P_observed - 1 of the rows as a function of ln(free), and the parameter map.

    Each evaluation beats ``progress`` with its rms relative residual and parameters.
    """
    freq, h1, observed = (rows[c].to_numpy(float) for c in ("frequency_hz", "h1_um", "pulloff_mN"))

    def params_of(log_values: np.ndarray) -> GentSchultzParameters:
        return replace(base, **{name: math.exp(v) for name, v in zip(free, log_values, strict=True)})

    def residuals(log_values: np.ndarray) -> np.ndarray:
        params = params_of(log_values)
        relative = _model_mN(model, params, freq, h1, geometry) / observed - 1.0
        if progress is not None:
            progress.beat(f"rms relative residual {math.sqrt(np.mean(relative**2)):.4g} at {params}")
        return relative

    return residuals, params_of


def _least_squares(
    rows: pd.DataFrame, model: str, base: GentSchultzParameters, free: tuple[str, ...], geometry: dict[str, float],
    progress: Heartbeat | None = None,
) -> dict[str, Any]:
    """Least squares in ln(free) with bounds (trust-region reflective); the fit record of ``fit_gent_schultz``."""
    residuals, params_of = _residual_function(rows, model, base, free, geometry, progress)
    lo, hi = np.log([BOUNDS[name] for name in free]).T
    x0 = np.clip(np.log([getattr(base, name) for name in free]), lo, hi)
    try:
        result = least_squares(residuals, x0, method="trf", bounds=(lo, hi), jac="3-point",
                               xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=300)
    except NoRootError as exc:
        raise FitError(f"{model} fit of {free}: the model has no solution at a trial point ({exc})") from exc
    except FitError as exc:
        raise FitError(f"{model} fit of {free}: {exc}") from exc
    if result.status <= 0:
        raise FitError(f"{model} fit of {free} did not converge: {result.message}")
    return fit_record(params_of(result.x), result, result.fun, free, (lo, hi))


def fit_record(params: GentSchultzParameters, result: OptimizeResult, residuals: np.ndarray, free: tuple[str, ...],
               log_bounds: tuple[np.ndarray, np.ndarray]) -> dict[str, Any]:
    """The fit record of a finished search in ln(free) (every level's, the simulation's too).

    ``params`` and ``residuals`` at ``result.x``; the free parameters within 1e-6 of ln of a bound are
    ``at_bound``, and ``bound_distance`` keeps each one's distance to the nearer bound in ln (for
    :func:`fitted_summary`); s^2 = RSS/(m - p) over the m rows and p free parameters.
    """
    lo, hi = log_bounds
    distance = np.minimum(result.x - lo, hi - result.x)
    return {
        "params": params,
        "jac": result.jac,
        "at_bound": [name for name, d in zip(free, distance, strict=True) if d < _ON_BOUND],
        "bound_distance": dict(zip(free, distance.tolist(), strict=True)),
        "s2": float(residuals @ residuals) / (len(residuals) - len(free)),
        "residuals": residuals,
        "nfev": int(result.nfev),
        "message": str(result.message),
    }


def _v0_identifiability(
    rows: pd.DataFrame, model: str, fit: dict[str, Any], geometry: dict[str, float], max_relative_se: float,
    noise_floor: float,
) -> tuple[bool, str]:
    """Would v0 be determined if freed at the (w0, n) fit?

    Relative standard error of v0 from the central-difference Jacobian in (ln w0, ln n, ln v0)
    there, at a residual scale floored at ``noise_floor``.
    """
    residuals, _ = _residual_function(rows, model, fit["params"], ("w0", "n", "v0"), geometry)
    x = np.log([fit["params"].w0, fit["params"].n, fit["params"].v0])
    step = 1e-4
    jac = np.column_stack([(residuals(x + step * e) - residuals(x - step * e)) / (2 * step) for e in np.eye(3)])
    s2 = max(fit["s2"], noise_floor**2)
    try:
        rel_se = math.sqrt(max(s2 * np.linalg.inv(jac.T @ jac)[-1, -1], 0.0))
    except np.linalg.LinAlgError:
        return False, "v0 not identifiable: the Jacobian is singular in v0"
    if not np.isfinite(rel_se) or rel_se > max_relative_se:
        return False, (f"v0 not identifiable: its relative standard error would be {rel_se:.3g} "
                       f"(> {max_relative_se:g}) at a relative residual scale of {math.sqrt(s2):.3g}")
    return True, f"v0 identifiable: relative standard error {rel_se:.3g}"


def fit_gent_schultz(
    rows: pd.DataFrame,
    model: str,
    published: GentSchultzParameters,
    *,
    radius: float,
    reduced_modulus: float,
    max_relative_se_v0: float = 0.5,
    noise_floor: float = 1e-3,
    progress: Heartbeat | None = None,
) -> dict[str, Any]:
    """Fit one model level to the rows; return a JSON-ready summary (see module docstring).

    A long search says where it is through ``progress`` (the pipeline's fit writes it to the rule's log).
    """
    if model not in levels.names("fit"):
        raise ValueError(f"unknown model {model!r}; expected one of {levels.names('fit')}")
    geometry = {"radius": radius, "reduced_modulus": reduced_modulus}
    frequencies = sorted(set(rows.loc[rows["h1_um"] > 0, "frequency_hz"].tolist()))
    summary: dict[str, Any] = {"model": model, "rows": len(rows)}
    v0_note = v0_note_before_fit(model, len(frequencies), len(rows))
    if rows.empty:
        return summary | _unfitted(published, "published", "no rows: published values kept", v0_note)
    forces = rows["pulloff_mN"].to_numpy(float)
    unusable = rows.loc[~(np.isfinite(forces) & (forces > 0)), "line"].tolist()
    if unusable:
        return summary | _unfitted(published, "failed", f"line(s) {', '.join(map(str, unusable))}: the pull-off "
                                   "force is not a positive number: published values kept", v0_note)
    if len(rows) <= 2:
        return summary | _unfitted(published, "not_identifiable",
                                   f"{len(rows)} rows cannot determine w0 and n: published values kept", v0_note)
    try:
        if model == "simulation":  # the full model: its own search (envelope Jacobian, warm-started families)
            from vibroadhesion.experiments.simulation_fit import fit_simulation  # imports this module: no cycle

            return summary | fit_simulation(rows, published, **geometry, max_relative_se_v0=max_relative_se_v0,
                                            noise_floor=noise_floor, progress=progress)
        return summary | _fit_and_summarise(rows, model, published, geometry, v0_note, max_relative_se_v0,
                                            noise_floor, progress)
    except FitError as exc:
        return summary | _unfitted(published, "failed", f"{exc}: published values kept", v0_note)


def _unfitted(published: GentSchultzParameters, status: str, note: str, v0_note: str) -> dict[str, Any]:
    """The summary of a level that fitted nothing: its status, why, and the published values (not estimates)."""
    return {"status": status, "note": note, "parameters": _parameter_table(published, (), (), None),
            "v0_identifiable": False, "v0_note": v0_note or "no fit"}


def _fit_and_summarise(rows: pd.DataFrame, model: str, published: GentSchultzParameters, geometry: dict[str, float],
                       v0_note: str, max_relative_se_v0: float, noise_floor: float,
                       progress: Heartbeat | None) -> dict[str, Any]:
    """Fit (w0, n), then v0 as well where it is identifiable; the summary (:func:`fitted_summary`)."""
    free: tuple[str, ...] = ("w0", "n")
    fit = _least_squares(rows, model, published, free, geometry, progress)
    if not v0_note:
        identifiable, v0_note = _v0_identifiability(rows, model, fit, geometry, max_relative_se_v0, noise_floor)
        if identifiable:
            with_v0 = _least_squares(rows, model, fit["params"], ("w0", "n", "v0"), geometry, progress)
            if "v0" in with_v0["at_bound"]:
                v0_note = f"v0 not identifiable: the fit drives it to its bound {with_v0['params'].v0:.3g} m/s"
            else:
                free, fit = ("w0", "n", "v0"), with_v0
    return fitted_summary(rows, fit, free, v0_note)


def v0_note_before_fit(model: str, frequencies: int, rows: int) -> str:
    """Why v0 cannot be freed whatever the fit gives (empty if it may be).

    v0 enters only the frequency-dependent levels (the refined one: Eq. 106 through omega R/v0, Eq. 105),
    and needs two frequencies and a spare degree of freedom.
    """
    if not levels.level(model).frequency_dependent:
        return f"v0 not identifiable: the {model} model is frequency independent, v0 does not enter it"
    if frequencies == 0:
        return "v0 not identifiable: no vibrated rows (at least 2 frequencies needed)"
    if frequencies < 2:
        return f"v0 not identifiable: the rows span {frequencies} frequency (at least 2 needed)"
    if rows <= 3:
        return f"v0 not identifiable: {rows} rows leave no degree of freedom for a third parameter"
    return ""


def fitted_summary(rows: pd.DataFrame, fit: dict[str, Any], free: tuple[str, ...], v0_note: str) -> dict[str, Any]:
    """Status, estimates, covariance (Gauss-Newton, J^T J at the optimum, in logarithms), residuals."""
    inside, cov = _inside_and_covariance(fit, free, fit["at_bound"])
    se = {name: _ln_se(cov, inside, name, fit) for name in inside} if cov is not None else {}
    near = [name for name in se if fit["bound_distance"][name] < min(_NEAR_BOUND, _BOUND_SE * se[name])]
    notes = [f"{name} ends on its bound {getattr(fit['params'], name):.3g} {UNITS[name]}: "
             f"the model cannot represent the rows inside {BOUNDS[name]}" for name in fit["at_bound"]]
    notes += [f"{name} = {getattr(fit['params'], name):.4g} {UNITS[name]} ends within 1 % and {_BOUND_SE:g} standard "
              f"errors (relative {se[name]:.3g}) of its bound in {BOUNDS[name]}: the rows do not determine it inside "
              "the box (no standard error)" for name in near]
    at_bound = [*fit["at_bound"], *near]
    if near:
        inside, cov = _inside_and_covariance(fit, free, at_bound)
    status = "at_bound" if at_bound else "fitted"
    if cov is None:
        status = "not_identifiable"
        notes.append(f"the Jacobian has lower rank than the {len(inside)} free parameters inside the box: the rows "
                     f"do not determine {', '.join(inside)} separately (no standard errors)")
        inside = ()
    return {
        "status": status,
        "note": "; ".join(notes),
        "free_parameters": list(free),
        "at_bound": at_bound,
        "parameters": _parameter_table(fit["params"], free, inside, cov),
        "covariance": {"parameters": list(inside), "matrix": [] if cov is None else cov.tolist()},
        "residuals_mN": [{"line": int(line), "residual": float(r * obs)}
                         for line, r, obs in zip(rows["line"], fit["residuals"], rows["pulloff_mN"], strict=True)],
        "rms_relative_residual": float(np.sqrt(np.mean(fit["residuals"] ** 2))),
        "v0_identifiable": "v0" in free,
        "v0_note": v0_note,
        "function_evaluations": fit["nfev"],
        "optimizer_message": fit["message"],
    }


def _inside_and_covariance(fit: dict[str, Any], free: tuple[str, ...],
                           at_bound: list[str]) -> tuple[tuple[str, ...], np.ndarray | None]:
    """The free parameters not on a bound and their covariance (:func:`_covariance`) with the others held."""
    inside = tuple(name for name in free if name not in at_bound)
    theta = np.array([getattr(fit["params"], name) for name in inside])
    return inside, _covariance(fit["jac"][:, [free.index(name) for name in inside]], fit["s2"], theta)


def _ln_se(cov: np.ndarray, inside: tuple[str, ...], name: str, fit: dict[str, Any]) -> float:
    """Standard error of ln ``name`` (its relative standard error) from the natural-unit covariance."""
    k = inside.index(name)
    return math.sqrt(max(float(cov[k, k]), 0.0)) / float(getattr(fit["params"], name))


def _covariance(jac: np.ndarray, s2: float, theta: np.ndarray) -> np.ndarray | None:
    """Gauss-Newton covariance s^2 (J^T J)^-1 in ln theta mapped to theta (delta method).

    None where J (in the logarithms of the parameters inside the box) has a lower numerical rank than its
    columns (numpy's tolerance: largest singular value times max(J.shape) times the machine epsilon).
    """
    if jac.shape[1] == 0:
        return np.zeros((0, 0))
    if np.linalg.matrix_rank(jac) < jac.shape[1]:
        return None
    try:
        cov = s2 * np.linalg.inv(jac.T @ jac) * np.outer(theta, theta)
    except np.linalg.LinAlgError:
        return None
    return cov if np.all(np.isfinite(cov)) else None


def _parameter_table(params: GentSchultzParameters, free: tuple[str, ...], inside: tuple[str, ...],
                     cov: np.ndarray | None) -> dict[str, Any]:
    table = {}
    for name in ("w0", "n", "v0"):
        entry: dict[str, Any] = {"estimate": getattr(params, name), "unit": UNITS[name]}
        if name in inside and cov is not None:
            k = inside.index(name)
            entry.update(std_error=math.sqrt(max(cov[k, k], 0.0)), source="fitted")
        elif name in free:
            entry.update(std_error=None, source=f"fitted, on its bound {BOUNDS[name]}")
        else:
            entry.update(std_error=None, source="published (Fig. 4 caption)")
        table[name] = entry
    return table


def parameters_from_fit(summary: dict[str, Any]) -> GentSchultzParameters:
    """The parameter set a fit summary reports (fitted where free, published otherwise)."""
    p = summary["parameters"]
    return GentSchultzParameters(p["w0"]["estimate"], p["n"]["estimate"], p["v0"]["estimate"])
