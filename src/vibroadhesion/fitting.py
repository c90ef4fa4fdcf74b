"""Least-squares fit of the Gent–Schultz parameters to pull-off measurements (Sec. 3.4).

Each row is (frequency f, base amplitude h1, |P_cr| in mN). The model is the pull-off
estimate of one asymptotic level (:func:`vibroadhesion.pulloff.predict_pulloff`):

* ``leading`` (Eqs. 71–72) is frequency independent, so v0 does not enter: w0 and n are
  fitted, v0 keeps its published value;
* ``refined`` (Eqs. 71, 106) depends on v0 through omega_check = 2 pi f R / v0. v0 is fitted
  only when it is identifiable: the rows span at least two frequencies and, with v0 free,
  its relative standard error is below ``max_relative_se_v0``. Otherwise the fit says why and
  keeps the published v0.

The parameters are fitted in logarithms (positivity; ln-standard errors are relative errors)
by Levenberg–Marquardt on relative residuals model/observed - 1 (pull-off forces span an
order of magnitude; measurement error is roughly proportional). The covariance is
s^2 (J^T J)^-1 with s^2 = RSS/(m - p), mapped back to natural units by the delta method. For the
identifiability test the relative residual scale is floored at ``noise_floor``, so that
noise-free (synthetic) rows do not make any parameter look identifiable.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd
from scipy.optimize import least_squares

from vibroadhesion.pulloff import MODELS, GentSchultzParameters, Model, predict_pulloff

UNITS = {"w0": "J/m^2", "n": "1", "v0": "m/s"}


class FitError(RuntimeError):
    """The least-squares iteration failed; no estimate is reported."""


def _residual_function(rows: pd.DataFrame, model: Model, base: GentSchultzParameters, free: tuple[str, ...], geometry: dict[str, float]):
    freq, h1, observed = (rows[c].to_numpy(float) for c in ("frequency_hz", "h1_um", "pulloff_mN"))

    def params_of(log_values: np.ndarray) -> GentSchultzParameters:
        return replace(base, **{name: math.exp(v) for name, v in zip(free, log_values)})

    def residuals(log_values: np.ndarray) -> np.ndarray:
        return predict_pulloff(model, params_of(log_values), freq, h1, **geometry).pulloff_mN / observed - 1.0

    return residuals, params_of


def _least_squares(rows, model, base, free, geometry) -> dict[str, Any]:
    residuals, params_of = _residual_function(rows, model, base, free, geometry)
    x0 = np.log([getattr(base, name) for name in free])
    result = least_squares(residuals, x0, method="lm", jac="3-point", xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=2000)
    if result.status <= 0:
        raise FitError(f"{model} fit of {free} did not converge: {result.message}")
    m, p = len(rows), len(free)
    rss = float(result.fun @ result.fun)
    jtj = result.jac.T @ result.jac
    s2 = rss / (m - p)
    return {
        "params": params_of(result.x),
        "log_values": result.x,
        "jtj": jtj,
        "s2": s2,
        "residuals": result.fun,
        "nfev": int(result.nfev),
        "message": str(result.message),
    }


def _v0_identifiability(fit: dict[str, Any], rows: pd.DataFrame, max_relative_se: float, noise_floor: float) -> tuple[bool, str, float]:
    s2 = max(fit["s2"], noise_floor**2)
    try:
        cov = s2 * np.linalg.inv(fit["jtj"])
    except np.linalg.LinAlgError:
        return False, "v0 not identifiable: the Jacobian is singular in v0", math.inf
    rel_se = math.sqrt(max(cov[-1, -1], 0.0))
    if not np.isfinite(rel_se) or rel_se > max_relative_se:
        return False, (
            f"v0 not identifiable: its relative standard error would be {rel_se:.3g} "
            f"(> {max_relative_se:g}) at a relative residual scale of {math.sqrt(s2):.3g}"
        ), rel_se
    return True, f"v0 identifiable: relative standard error {rel_se:.3g}", rel_se


def fit_gent_schultz(
    rows: pd.DataFrame,
    model: Model,
    published: GentSchultzParameters,
    *,
    radius: float,
    reduced_modulus: float,
    max_relative_se_v0: float = 0.5,
    noise_floor: float = 1e-3,
) -> dict[str, Any]:
    """Fit one model level to the rows; return a JSON-ready summary (see module docstring)."""
    if model not in MODELS:
        raise ValueError(f"unknown model {model!r}; expected one of {MODELS}")
    geometry = {"radius": radius, "reduced_modulus": reduced_modulus}
    frequencies = sorted(set(rows["frequency_hz"].tolist()))
    summary: dict[str, Any] = {"model": model, "rows": len(rows)}

    if model == "leading":
        free, v0_note = ("w0", "n"), "v0 not identifiable: the leading-order model (Eq. 72) does not depend on v0"
    elif len(frequencies) < 2:
        free, v0_note = ("w0", "n"), f"v0 not identifiable: the rows span {len(frequencies)} frequency (at least 2 needed)"
    else:
        free, v0_note = ("w0", "n", "v0"), ""
    if len(rows) <= 2:
        summary.update(status="published", note=f"{len(rows)} rows cannot determine w0 and n: published values kept",
                       parameters=_parameter_table(published, (), None), v0_identifiable=False, v0_note=v0_note or "no fit")
        return summary
    if "v0" in free and len(rows) <= 3:
        free, v0_note = ("w0", "n"), f"v0 not identifiable: {len(rows)} rows leave no degree of freedom for a third parameter"

    fit = _least_squares(rows, model, published, free, geometry)
    if "v0" in free:
        identifiable, v0_note, _ = _v0_identifiability(fit, rows, max_relative_se_v0, noise_floor)
        if not identifiable:
            free = ("w0", "n")
            fit = _least_squares(rows, model, published, free, geometry)

    theta = np.array([getattr(fit["params"], name) for name in free])
    cov_log = fit["s2"] * np.linalg.inv(fit["jtj"])
    cov = cov_log * np.outer(theta, theta)
    summary.update(
        status="fitted",
        free_parameters=list(free),
        parameters=_parameter_table(fit["params"], free, cov),
        covariance={"parameters": list(free), "matrix": cov.tolist()},
        residuals_mN=[{"line": int(line), "residual": float(r * obs)}
                      for line, r, obs in zip(rows["line"], fit["residuals"], rows["pulloff_mN"])],
        rms_relative_residual=float(np.sqrt(np.mean(fit["residuals"] ** 2))),
        v0_identifiable="v0" in free,
        v0_note=v0_note,
        function_evaluations=fit["nfev"],
        optimizer_message=fit["message"],
    )
    return summary


def _parameter_table(params: GentSchultzParameters, free: tuple[str, ...], cov: np.ndarray | None) -> dict[str, Any]:
    table = {}
    for name in ("w0", "n", "v0"):
        entry: dict[str, Any] = {"estimate": getattr(params, name), "unit": UNITS[name]}
        if name in free and cov is not None:
            k = free.index(name)
            entry.update(std_error=math.sqrt(max(cov[k, k], 0.0)), source="fitted")
        else:
            entry.update(std_error=None, source="published (Fig. 4 caption)")
        table[name] = entry
    return table


def parameters_from_fit(summary: dict[str, Any]) -> GentSchultzParameters:
    """The parameter set a fit summary reports (fitted where free, published otherwise)."""
    p = summary["parameters"]
    return GentSchultzParameters(p["w0"]["estimate"], p["n"]["estimate"], p["v0"]["estimate"])
