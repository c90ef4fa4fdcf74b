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
by a trust-region reflective least-squares search (scipy ``trf``) inside
:data:`~vibroadhesion.experiments.fit_summary.BOUNDS`, on relative residuals model/observed - 1 (pull-off forces
span an order of magnitude; measurement error is roughly proportional), with central-difference derivatives
(:class:`LevelResiduals`). What the fit determines -- one status per parameter and per level, the
profile-likelihood intervals, the goodness-of-fit test -- is :mod:`vibroadhesion.experiments.fit_summary`'s, by the
rules of :mod:`vibroadhesion.experiments.fit_statistics`. Every fit ends in a status, never in an exception that
takes the other levels down: ``published`` (no rows: the published values pass through); ``fitted``;
``poor_fit``; ``at_bound``; ``not_identifiable`` (fewer rows than parameters, or a parameter the rows do not
determine); ``failed`` (the model has no solution at a trial point, or the search does not converge, or a row's
pull-off force is not a positive number, e.g. NaN for a simulated row without a pull-off), with the reason.

Rows. The model is evaluated once per distinct (frequency, amplitude) pair, so replicate rows cost
nothing. A static JKR test (``h1_um`` = 0, no vibration) has the pull-off |P_cr^JKR| = (3 pi/2) R w0
(Eq. 70) at every level (Abar = 0, J0 = 1): it pins w0 and carries no frequency. A row measured at a
withdrawal speed (``withdrawal_speed_um_s`` > 0) is predicted by the simulation at that speed
(:mod:`vibroadhesion.experiments.speed_fit`); the asymptotic levels are quasi-static and fit it as if V -> 0.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd
from scipy.optimize import least_squares

from vibroadhesion.core import levels
from vibroadhesion.experiments.fit_statistics import Settings, relative_standard_errors
from vibroadhesion.experiments.fit_summary import BOUNDS, fit_record, fitted_summary, published_table
from vibroadhesion.experiments.pulloff import GentSchultzParameters, jkr_mN, predict_pulloff, pulloff_mN
from vibroadhesion.numerics.progress import Heartbeat
from vibroadhesion.numerics.roots import NoRootError

#: Step in ln theta of the central differences of :class:`LevelResiduals` (truncation O(h^2) ~ 1e-10 against the
#: levels' ~1e-12 relative rounding over h ~ 1e-7: the derivatives to ~1e-7 relative).
DIFFERENCE_STEP = 1e-5


class FitError(RuntimeError):
    """The least-squares iteration failed; no estimate is reported."""


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


class LevelResiduals:
    """Relative residuals P_model/P_observed - 1 of the rows for an asymptotic level, in ln(free), and their Jacobian.

    Each evaluation beats ``progress`` with its rms relative residual and parameters. The Jacobian is the central
    difference of step :data:`DIFFERENCE_STEP` in each ln theta.
    """

    def __init__(self, rows: pd.DataFrame, model: str, base: GentSchultzParameters, free: tuple[str, ...],
                 geometry: dict[str, float], progress: Heartbeat | None = None) -> None:
        """The rows, the level, the parameters held (``base``), the free names, R and E*."""
        self.model, self.base, self.free, self.geometry, self.progress = model, base, free, geometry, progress
        self.freq, self.h1, self.observed = (rows[c].to_numpy(float) for c in ("frequency_hz", "h1_um", "pulloff_mN"))

    def params_of(self, log_values: np.ndarray) -> GentSchultzParameters:
        """The parameter set at ln(free) = ``log_values``."""
        return replace(self.base, **{name: math.exp(v) for name, v in zip(self.free, log_values, strict=True)})

    def residuals(self, log_values: np.ndarray) -> np.ndarray:
        """P_model/P_observed - 1 per row."""
        params = self.params_of(log_values)
        relative = _model_mN(self.model, params, self.freq, self.h1, self.geometry) / self.observed - 1.0
        if self.progress is not None:
            self.progress.beat(f"rms relative residual {math.sqrt(np.mean(relative**2)):.4g} at {params}")
        return relative

    def jacobian(self, log_values: np.ndarray) -> np.ndarray:
        """d residual / d ln(free) by central differences."""
        steps = DIFFERENCE_STEP * np.eye(len(log_values))
        return np.column_stack([(self.residuals(log_values + e) - self.residuals(log_values - e))
                                / (2.0 * DIFFERENCE_STEP) for e in steps])


def _least_squares(rows: pd.DataFrame, model: str, base: GentSchultzParameters, free: tuple[str, ...],
                   geometry: dict[str, float], progress: Heartbeat | None = None) -> dict[str, Any]:
    """Least squares in ln(free) with bounds (trust-region reflective); the fit record (``fit_summary``)."""
    residual_model = LevelResiduals(rows, model, base, free, geometry, progress)
    lo, hi = np.log([BOUNDS[name] for name in free]).T
    x0 = np.clip(np.log([getattr(base, name) for name in free]), lo, hi)
    try:
        result = least_squares(residual_model.residuals, x0, method="trf", bounds=(lo, hi),
                               jac=residual_model.jacobian, xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=300)
    except NoRootError as exc:
        raise FitError(f"{model} fit of {free}: the model has no solution at a trial point ({exc})") from exc
    except FitError as exc:
        raise FitError(f"{model} fit of {free}: {exc}") from exc
    if result.status <= 0:
        raise FitError(f"{model} fit of {free} did not converge: {result.message}")
    residual_model.progress = None
    return fit_record(residual_model.params_of(result.x), result, result.fun, free, (lo, hi), residual_model)


def v0_gate(jac: np.ndarray, s2: float, settings: Settings) -> tuple[bool, str]:
    """Would v0 be determined if freed? Its relative standard error from the Jacobian in (ln w0, ln n, ln v0).

    The same threshold as every parameter's status (:func:`~vibroadhesion.experiments.fit_statistics.parameter_status`),
    at the residual scale floored at the noise floor.
    """
    s2 = max(s2, settings.noise_floor**2)
    rel_se = relative_standard_errors(jac, s2)
    if rel_se is None:
        return False, "v0 not identifiable: the Jacobian is singular in v0"
    if not np.isfinite(rel_se[-1]) or rel_se[-1] > settings.max_relative_se:
        return False, (f"v0 not identifiable: its relative standard error would be {rel_se[-1]:.3g} "
                       f"(> {settings.max_relative_se:g}) at a relative residual scale of {math.sqrt(s2):.3g}")
    return True, f"v0 identifiable: relative standard error {rel_se[-1]:.3g}"


def fit_gent_schultz(
    rows: pd.DataFrame,
    model: str,
    published: GentSchultzParameters,
    *,
    radius: float,
    reduced_modulus: float,
    settings: Settings | None = None,
    starts: Sequence[GentSchultzParameters] = (),
    progress: Heartbeat | None = None,
) -> dict[str, Any]:
    """Fit one model level to the rows; return a JSON-ready summary (see module docstring).

    ``starts``: further start points of the simulation's search (the fits of cheaper levels,
    :func:`vibroadhesion.experiments.simulation_fit.fit_simulation`); the asymptotic levels start from
    ``published``. A long search says where it is through ``progress`` (the pipeline's fit writes it to the log).
    """
    if model not in levels.names("fit"):
        raise ValueError(f"unknown model {model!r}; expected one of {levels.names('fit')}")
    settings = settings or Settings()
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

            return summary | fit_simulation(rows, published, **geometry, settings=settings, starts=starts,
                                            progress=progress)
        return summary | _fit_and_summarise(rows, model, published, geometry, v0_note, settings, progress)
    except FitError as exc:
        return summary | _unfitted(published, "failed", f"{exc}: published values kept", v0_note)


def _unfitted(published: GentSchultzParameters, status: str, note: str, v0_note: str) -> dict[str, Any]:
    """The summary of a level that fitted nothing: its status, why, and the published values (not estimates)."""
    return {"status": status, "determined": [], "note": note, "parameters": published_table(published),
            "v0_identifiable": False, "v0_note": v0_note or "no fit"}


def _fit_and_summarise(rows: pd.DataFrame, model: str, published: GentSchultzParameters, geometry: dict[str, float],
                       v0_note: str, settings: Settings, progress: Heartbeat | None) -> dict[str, Any]:
    """Fit (w0, n), then v0 as well where it is identifiable; the summary (:func:`fitted_summary`)."""
    free: tuple[str, ...] = ("w0", "n")
    fit = _least_squares(rows, model, published, free, geometry, progress)
    if not v0_note:
        three = LevelResiduals(rows, model, fit["params"], ("w0", "n", "v0"), geometry)
        jac = three.jacobian(np.log([fit["params"].w0, fit["params"].n, fit["params"].v0]))
        identifiable, v0_note = v0_gate(jac, fit["s2"], settings)
        if identifiable:
            with_v0 = _least_squares(rows, model, fit["params"], ("w0", "n", "v0"), geometry, progress)
            if "v0" in with_v0["at_bound"]:
                v0_note = f"v0 not identifiable: the fit drives it to its bound {with_v0['params'].v0:.3g} m/s"
            else:
                free, fit = ("w0", "n", "v0"), with_v0
    return fitted_summary(rows, fit, free, v0_note, settings)


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
