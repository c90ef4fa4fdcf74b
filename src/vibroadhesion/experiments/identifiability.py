"""Can pull-off data determine w0, n and v0? Two answers from the virtual experiment.

No measured pull-off numbers behind Fig. 4 are published, so the question is asked of the simulated
(virtual) pull-off rows of :mod:`vibroadhesion.experiments.virtual_pulloff`, whose true parameters are known:

1. **What each model level recovers.** The pipeline's own fit
   (:func:`vibroadhesion.experiments.fitting.fit_gent_schultz`) is run on the noise-free simulated
   rows with every model level. Its misfit is pure model error,
   so the distance of the recovered parameters from the true ones is the bias a user would get
   from that level on perfect data.

2. **What the data hold at all.** The local sensitivity of the simulated pull-off itself,
   S_ij = d ln P_i / d ln theta_j (theta = w0, n, v0), at the detachment point of each row's family by
   the envelope theorem (:func:`envelope_sensitivity`: two warm-started orbits per parameter at the
   fixed base offset of the pull-off, :func:`vibroadhesion.experiments.envelope.envelope_log_derivatives`).
   A row whose family ends without a pull-off keeps its status and has no derivative. For relative
   measurement scatter sigma the Fisher information is S^T S / sigma^2 and the smallest attainable
   standard errors of ln theta are the square roots of the diagonal of its inverse (Cramer-Rao). A
   parameter is called identifiable when that relative standard error is below
   :data:`IDENTIFIABLE_RELATIVE_SE`, the threshold the fit uses for v0. Since v0 enters only through
   omega_check = omega R / v0 (Eqs. 97, 105), d ln P / d ln v0 = -d ln P / d ln omega: the v0 column
   can be checked against the frequency dependence of the simulated rows.

A static (h1 = 0) pull-off test, the JKR value P = (3 pi / 2) R w0 (Eq. 70 with w_eff = w0), adds the
exact sensitivity row (1, 0, 0); :func:`information_table` reports the design with and without it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import pandas as pd

from vibroadhesion.experiments.envelope import envelope_log_derivatives, pulloff_problem
from vibroadhesion.experiments.fit_statistics import MAX_RELATIVE_SE
from vibroadhesion.experiments.fitting import FitError, fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters, jkr_mN
from vibroadhesion.experiments.virtual_pulloff import traced_pulloff
from vibroadhesion.numerics.progress import ProgressBar

PARAMETERS = ("w0", "n", "v0")

#: Relative standard error above which a parameter is not identifiable (the fit's status rule).
IDENTIFIABLE_RELATIVE_SE = MAX_RELATIVE_SE

#: Columns of the sensitivity table: the row, its status and force, and S_ij = d ln P_i / d ln theta_j.
SENSITIVITY_COLUMNS = ["frequency_hz", "h1_um", "status", "pulloff_mN", *(f"dlnP_dln{n}" for n in PARAMETERS)]

FIT_COLUMNS = ["model", "status", "w0", "w0_se", "w0_relative_bias", "n", "n_se", "n_relative_bias", "v0", "v0_se",
               "v0_relative_bias", "v0_identifiable", "rms_relative_residual", "max_relative_residual", "note"]


def fit_level(rows: pd.DataFrame, model: str, truth: GentSchultzParameters, *, radius: float,
              reduced_modulus: float) -> dict[str, Any]:
    """One row of the fits table: the pipeline's fit of ``model`` started from the true parameters.

    ``*_relative_bias`` is estimate/true - 1; a fit that fails (:class:`FitError`), or that fits nothing (its summary
    has no free parameters: e.g. no simulated row has a pull-off), is a row with its status and the reason, never
    numbers.
    """
    try:
        summary = fit_gent_schultz(rows, model, truth, radius=radius, reduced_modulus=reduced_modulus)
    except FitError as exc:
        return {"model": model, "status": "failed", "note": str(exc)}
    if "free_parameters" not in summary:
        return {"model": model, "status": summary["status"], "note": summary["note"]}
    row: dict[str, Any] = {"model": model, "status": summary["status"]}
    for name in PARAMETERS:
        entry = summary["parameters"][name]
        row[name], row[f"{name}_se"] = entry["estimate"], entry["std_error"]
        free = name in summary["free_parameters"]
        row[f"{name}_relative_bias"] = entry["estimate"] / getattr(truth, name) - 1.0 if free else math.nan
    relative = np.array([r["residual"] for r in summary["residuals_mN"]]) / rows["pulloff_mN"].to_numpy(float)
    row.update(v0_identifiable=summary["v0_identifiable"], rms_relative_residual=summary["rms_relative_residual"],
               max_relative_residual=float(np.max(np.abs(relative))),
               note="; ".join(s for s in (summary.get("note", ""), summary["v0_note"]) if s))
    return row


def envelope_sensitivity(params: GentSchultzParameters, frequency_hz: float, h1_um: Sequence[float], *,
                         radius: float, reduced_modulus: float, progress: ProgressBar | None = None) -> pd.DataFrame:
    """Rows of S = d ln P / d ln theta of the simulated pull-off at one frequency (Eqs. 4-11, 70), rigid fixation.

    Per amplitude: the virtual pull-off's family (:func:`~vibroadhesion.experiments.virtual_pulloff.traced_pulloff`
    from the nominal point contact, as :func:`~vibroadhesion.experiments.virtual_pulloff.pulloff_table`), then the
    envelope derivatives at its most tensile orbit (error O(1e-5), the module docstring of
    :mod:`vibroadhesion.experiments.simulation_fit`). A family that ends without a pull-off keeps its status,
    with no force and no derivative; a pull-off whose shifted orbits converge on neither side has the status
    ``no_derivative`` and no derivative (NaN, never a number).
    """
    rows = []
    for h1 in h1_um:
        record, at = traced_pulloff(pulloff_problem(params, frequency_hz, h1, radius=radius,
                                                    reduced_modulus=reduced_modulus))
        row: dict[str, Any] = {"frequency_hz": frequency_hz, "h1_um": h1, "status": str(record.status),
                               "pulloff_mN": float(record.pulloff_ratio) * jkr_mN(params.w0, radius)}
        if at is not None:
            derivatives = envelope_log_derivatives(params, frequency_hz, h1, at, PARAMETERS, radius=radius,
                                                   reduced_modulus=reduced_modulus)
            if np.all(np.isfinite(derivatives)):
                row.update(zip(SENSITIVITY_COLUMNS[-3:], derivatives, strict=True))
            else:
                row["status"] = "no_derivative"
        rows.append(row)
        if progress is not None:
            progress.advance(record.steady_states or 0, f"{frequency_hz:g} Hz, h1 = {h1:g} um: {row['status']}")
    return pd.DataFrame(rows).reindex(columns=SENSITIVITY_COLUMNS)


def frequency_derivative(simulated: pd.DataFrame, at_hz: float) -> pd.DataFrame:
    """-d ln P / d ln omega at ``at_hz`` per amplitude, from the parabola in ln f through the simulated rows.

    The independent check of the v0 column of :func:`envelope_sensitivity` (module docstring); needs
    three or more frequencies per amplitude (a least-squares parabola beyond three).
    """
    rows = []
    for h1, group in simulated.groupby("h1_um", sort=True):
        count = group["frequency_hz"].nunique()
        if count < 3:
            raise ValueError(f"h1 = {h1:g} um: need three frequencies for a parabola, got {count}")
        log_f, log_p = np.log(group["frequency_hz"].to_numpy(float)), np.log(group["pulloff_mN"].to_numpy(float))
        coefficients = np.polyfit(log_f, log_p, 2)
        rows.append({"h1_um": h1, "minus_dlnP_dlnomega": -float(np.polyval(np.polyder(coefficients), math.log(at_hz)))})
    return pd.DataFrame(rows)


def standard_errors(sensitivity: np.ndarray, noise: float) -> tuple[np.ndarray, np.ndarray]:
    """Cramer-Rao standard errors of ln theta and the correlation matrix for relative scatter ``noise``.

    A rank-deficient S (fewer usable rows than parameters, or dependent ones) determines no parameter:
    infinite standard errors and no correlations (NaN). The rank is decided on the singular values of S
    (numpy's matrix_rank: those above sigma_max max(rows, columns) eps), not by whether inverting S^T S
    happens to raise: in floating point a rank-2 S^T S of three parameters may be inverted, with a negative
    variance, on one CPU and refused on another.
    """
    size = sensitivity.shape[1]
    if sensitivity.shape[0] < size or np.linalg.matrix_rank(sensitivity) < size:
        return np.full(size, math.inf), np.full((size, size), math.nan)
    covariance = noise**2 * np.linalg.inv(sensitivity.T @ sensitivity)
    se = np.sqrt(np.diag(covariance))
    return se, covariance / np.outer(se, se)


def information_table(sensitivity: pd.DataFrame, noises: Sequence[float]) -> pd.DataFrame:
    """Smallest relative standard errors of w0, n, v0 and their correlations, per design and noise level.

    Designs: the rows as given (``virtual experiment``) and the same plus one static JKR pull-off
    (sensitivity row (1, 0, 0), exact). The singular values of S say how many combinations of
    ln theta the pull-off data determine at all. Rows without a derivative (no pull-off, their status in
    the sensitivity table) carry no information and are left out; ``rows`` counts those used.
    """
    s = sensitivity[[f"dlnP_dln{n}" for n in PARAMETERS]].to_numpy(float)
    s = s[np.all(np.isfinite(s), axis=1)]
    designs = {"virtual experiment": s, "virtual experiment + static JKR pull-off": np.vstack([s, [1.0, 0.0, 0.0]])}
    rows = []
    for design, matrix in designs.items():
        singular = np.linalg.svd(matrix, compute_uv=False)
        for noise in noises:
            se, corr = standard_errors(matrix, noise)
            row = {"design": design, "rows": len(matrix), "relative_noise": noise}
            for k, name in enumerate(PARAMETERS):
                row[f"{name}_relative_se"] = float(se[k])
                row[f"{name}_identifiable"] = bool(se[k] < IDENTIFIABLE_RELATIVE_SE)
            row.update(corr_w0_n=float(corr[0, 1]), corr_w0_v0=float(corr[0, 2]), corr_n_v0=float(corr[1, 2]),
                       singular_values=" ".join(f"{v:.4g}" for v in singular))
            rows.append(row)
    return pd.DataFrame(rows)


def recommendation(fits: pd.DataFrame, information: pd.DataFrame, sensitivity: pd.DataFrame, noise: float) -> str:
    """The model to fit real pull-off data with, and which of its estimates to trust, in numbers.

    The level is the fitted one with the smallest rms misfit to the simulated rows (its model error).
    Of its estimates, a parameter is trusted when its bias on the noise-free rows is within the
    Cramer-Rao standard error that ``noise`` allows for the same rows; a parameter is reported as not
    identifiable when even the simulated pull-off cannot fix it (:data:`IDENTIFIABLE_RELATIVE_SE`).
    """
    usable = fits[fits["status"] != "failed"].sort_values("rms_relative_residual", kind="stable")
    if usable.empty:
        return "No model level could be fitted to the simulated rows: fit none of them to real data."
    best, rest = usable.iloc[0], usable.iloc[1:]
    at_noise = information[information["relative_noise"] == noise]
    bound = at_noise[at_noise["design"] == "virtual experiment"].iloc[0]
    with_static = at_noise[at_noise["design"] != "virtual experiment"].iloc[0]
    others = ", ".join(f"{100 * r.rms_relative_residual:.1f} % ({r.model})" for r in rest.itertuples())
    text = [f"Fit real data with **{best.model}**: its misfit to the noise-free simulated rows, "
            f"which is pure model error, is {100 * best.rms_relative_residual:.1f} % rms "
            f"({100 * best.max_relative_residual:.1f} % at worst), "
            f"against {others}."]
    fitted = [name for name in PARAMETERS if np.isfinite(best[f"{name}_relative_bias"])]
    trusted = [name for name in fitted if abs(best[f"{name}_relative_bias"]) <= bound[f"{name}_relative_se"]]
    biased = [name for name in fitted if name not in trusted]
    if trusted:
        text.append("Trust its " + ", ".join(f"**{name}** (bias {100 * best[f'{name}_relative_bias']:+.1f} %, "
                                            f"within the {100 * bound[f'{name}_relative_se']:.2g} % that "
                                            f"{100 * noise:g} % scatter allows)" for name in trusted) + ".")
    for name in biased:
        column = f"dlnP_dln{name}"
        strongest = sensitivity.loc[sensitivity[column].abs().idxmax()]
        text.append(f"Do not trust its {name}: bias {100 * best[f'{name}_relative_bias']:+.0f} % where the scatter "
                    f"alone would allow {100 * bound[f'{name}_relative_se']:.2g} %. The rows that carry the "
                    f"information on {name} (|d ln P/d ln {name}| up to {abs(strongest[column]):.2g}, "
                    f"at h1 = {strongest['h1_um']:g} um) are those where the asymptotic levels are wrong by up to "
                    f"{100 * best.max_relative_residual:.0f} %; "
                    f"only a fit with the full model (the simulation) could recover it.")
    lost = [name for name in PARAMETERS if not bound[f"{name}_identifiable"]]
    for name in lost:
        text.append(f"{name} is not identifiable from these rows by any model: even the simulated pull-off fixes it "
                    f"only to {100 * bound[f'{name}_relative_se']:.3g} % at {100 * noise:g} % scatter "
                    f"(correlation of n and v0 {bound['corr_n_v0']:.3f}); take it from an independent rate test.")
    text.append(f"One static (h1 = 0) JKR pull-off test added to the design pins w0 to "
                f"{100 * with_static['w0_relative_se']:.2g} % (from {100 * bound['w0_relative_se']:.2g} %).")
    return " ".join(text)
