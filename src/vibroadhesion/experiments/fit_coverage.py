"""How often the fit's nominal interval holds the true parameters: a coverage study on simulated rows (Sec. 3.4).

Rows are simulated at the rig's test conditions (its frequencies × amplitudes, data/setup.yaml) from known
parameters with one model level, each force multiplied by 1 + sigma eps (eps standard normal, one seed per
replicate data set), and fitted with the same level by the pipeline's fit
(:func:`vibroadhesion.experiments.fitting.fit_gent_schultz`), started away from the truth (w0 x 1.5, n x 0.6). A
parameter is covered when the fit determines it (status ``fitted``) and its profile-likelihood interval
(:mod:`vibroadhesion.experiments.fit_statistics`) contains the true value; a parameter the fit does not determine
is counted apart (``not_determined``), never as covered.

Which level. The study measures a property of the interval method -- how well the profile t statistic's nominal
level holds for a nonlinear two-parameter model with 15 rows -- so the rows must come from the model that is
fitted. The simulation's fit costs seconds per data set (families of periodic orbits per row and trial point), 40
data sets minutes; the leading order (Eqs. 71-72) has the same parameters, the same w0, n dependence through chi0
(Eq. 64) and J-integrals of the Gent–Schultz law, and costs milliseconds. The pipeline runs the study on it
(``fit_coverage.level`` of workflow/config.yaml) and says so on its page.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd

from vibroadhesion.experiments.fit_statistics import Settings
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters, predict_pulloff, pulloff_mN
from vibroadhesion.numerics.progress import ProgressBar

#: The fitted parameters whose coverage is measured (v0 does not enter the frequency-independent levels).
PARAMETERS = ("w0", "n")
#: The start of every fit relative to the truth.
START_FACTORS = {"w0": 1.5, "n": 0.6}

FIT_COLUMNS = ["level", "relative_scatter", "seed", "status", "parameter", "truth", "estimate", "lower", "upper",
               "parameter_status", "covered"]
SUMMARY_COLUMNS = ["level", "relative_scatter", "parameter", "data_sets", "covered", "not_determined", "coverage",
                   "nominal", "median_relative_half_width"]


def simulated_rows(level: str, truth: GentSchultzParameters, frequencies_hz: Sequence[float],
                   amplitudes_um: Sequence[float], scatter: float, seed: int, *, radius: float,
                   reduced_modulus: float) -> pd.DataFrame:
    """One simulated data set: every (frequency, amplitude) once.

    Forces of ``level`` at ``truth`` with relative Gaussian scatter ``scatter`` (seeded), labelled ``source`` =
    ``simulated (<level>, sigma = ...)``.
    """
    f = np.repeat(np.asarray(frequencies_hz, dtype=float), len(amplitudes_um))
    h1 = np.tile(np.asarray(amplitudes_um, dtype=float), len(frequencies_hz))
    clean = pulloff_mN(predict_pulloff(level, truth, f, h1, radius=radius, reduced_modulus=reduced_modulus),
                       truth.w0, radius)
    noisy = clean * (1.0 + scatter * np.random.default_rng(seed).standard_normal(clean.size))
    return pd.DataFrame({"frequency_hz": f, "h1_um": h1, "pulloff_mN": noisy,
                         "source": f"simulated ({level}, sigma = {scatter:g})", "line": np.arange(2, 2 + f.size)})


def coverage_fits(level: str, truth: GentSchultzParameters, frequencies_hz: Sequence[float],
                  amplitudes_um: Sequence[float], scatters: Sequence[float], seeds: int, *, radius: float,
                  reduced_modulus: float, settings: Settings | None = None,
                  progress: ProgressBar | None = None) -> pd.DataFrame:
    """Per data set and parameter: the fit's status, estimate, interval and whether it covers the truth.

    Columns :data:`FIT_COLUMNS`; seeds 0 .. ``seeds`` - 1 at each scatter.
    """
    start = replace(truth, **{name: getattr(truth, name) * factor for name, factor in START_FACTORS.items()})
    records: list[dict[str, Any]] = []
    for scatter in scatters:
        for seed in range(seeds):
            rows = simulated_rows(level, truth, frequencies_hz, amplitudes_um, scatter, seed, radius=radius,
                                  reduced_modulus=reduced_modulus)
            summary = fit_gent_schultz(rows, level, start, radius=radius, reduced_modulus=reduced_modulus,
                                       settings=settings)
            records += [_parameter_record(level, scatter, seed, summary, name, getattr(truth, name))
                        for name in PARAMETERS]
            if progress is not None:
                progress.advance(1)
    return pd.DataFrame(records, columns=FIT_COLUMNS)


def _parameter_record(level: str, scatter: float, seed: int, summary: dict[str, Any], name: str,
                      truth: float) -> dict[str, Any]:
    """One row of :func:`coverage_fits`."""
    entry = summary["parameters"][name]
    lower, upper = entry["interval"] if entry["interval"] is not None else (None, None)
    covered = entry["status"] == "fitted" and lower is not None and upper is not None and lower <= truth <= upper
    return {"level": level, "relative_scatter": scatter, "seed": seed, "status": summary["status"],
            "parameter": name, "truth": truth, "estimate": entry["estimate"],
            "lower": np.nan if lower is None else lower, "upper": np.nan if upper is None else upper,
            "parameter_status": entry["status"], "covered": bool(covered)}


def coverage_summary(fits: pd.DataFrame, confidence: float) -> pd.DataFrame:
    """Per level, scatter and parameter: how many intervals cover the truth (:data:`SUMMARY_COLUMNS`).

    Data sets, covered, not determined, the coverage (covered / data sets), the nominal level and the median
    half-width relative to the truth.
    """
    groups = fits.groupby(["level", "relative_scatter", "parameter"], sort=False)
    table = groups.agg(data_sets=("covered", "size"), covered=("covered", "sum"),
                       not_determined=("parameter_status", _not_fitted)).reset_index()
    half = (fits["upper"] - fits["lower"]) / (2.0 * fits["truth"])
    table["median_relative_half_width"] = half.groupby([fits[c] for c in ("level", "relative_scatter", "parameter")],
                                                       sort=False).median().to_numpy()
    table["coverage"] = table["covered"] / table["data_sets"]
    table["nominal"] = confidence
    return table[SUMMARY_COLUMNS]


def _not_fitted(statuses: pd.Series) -> int:
    """How many of ``statuses`` are not ``fitted``."""
    return int((statuses != "fitted").sum())
