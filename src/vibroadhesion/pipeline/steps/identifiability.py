"""Steps of the identifiability rules.

What the simulated pull-off determines of w0, n, v0, and which model level recovers them (sensitivities, Cramer-Rao
standard errors, fits).
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from vibroadhesion.experiments import fit_coverage as fit_coverage_study
from vibroadhesion.experiments import identifiability
from vibroadhesion.experiments.fit_statistics import Settings
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.numerics.progress import ProgressBar
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.inputs import rig


def sensitivity_part(setup_json: str | Path, fit_json: str | Path | None, out: str | Path,
                     frequencies_hz: Sequence[float], candidate_amplitudes_um: Sequence[float]) -> None:
    """Envelope sensitivities of the simulated pull-off (rigid fixation) at the frequencies of one job.

    The amplitudes are the rig's and the design's candidates (h1 = 0, the static test, is exact and not
    simulated): rows of :func:`vibroadhesion.experiments.identifiability.envelope_sensitivity`.
    """
    setup, params, _ = rig(setup_json, fit_json)
    h1 = sorted({float(h) for h in (*setup.amplitudes_um, *candidate_amplitudes_um) if h > 0})
    progress = ProgressBar(len(h1) * len(frequencies_hz), "amplitudes")
    tables = [identifiability.envelope_sensitivity(GentSchultzParameters(**params), f, h1, radius=setup.radius,
                                                   reduced_modulus=setup.reduced_modulus, progress=progress)
              for f in frequencies_hz]
    write_csv(pd.concat(tables, ignore_index=True), out)


def _simulated_rigid_rows(virtual_csv: str | Path) -> pd.DataFrame:
    """The simulated rigid-fixation pull-off rows, as fit input (``line`` = row number)."""
    table = pd.read_csv(virtual_csv)
    rows = table[(table["model"] == "simulation") & (table["fixation"] == "rigid")].reset_index(drop=True)
    return rows.assign(line=np.arange(len(rows)))


def fit_level(
    setup_json: str | Path, fit_json: str | Path | None, virtual_csv: str | Path, model: str, out: str | Path
) -> None:
    """The pipeline's Gent-Schultz fit of one model level on the noise-free simulated pull-off rows."""
    setup, params, _ = rig(setup_json, fit_json)
    start = time.perf_counter()
    row = identifiability.fit_level(_simulated_rigid_rows(virtual_csv), model, GentSchultzParameters(**params),
                                    radius=setup.radius, reduced_modulus=setup.reduced_modulus)
    write_csv(pd.DataFrame([row]).reindex(columns=identifiability.FIT_COLUMNS), out)
    print(f"{model}: {row['status']} in {time.perf_counter() - start:.1f} s; {row['note']}")


def rig_sensitivity(virtual_csv: str | Path, sensitivity_parts: Sequence[str | Path]) -> pd.DataFrame:
    """The sensitivity rows at the rig's test conditions: those of the simulated rigid rows, in their order.

    The parts trace the same families as the virtual pull-off: a row whose status or force differs (the
    parts computed at other parameters) is a ValueError, never a mixed table.
    """
    rows = _simulated_rigid_rows(virtual_csv)
    parts = pd.concat([pd.read_csv(p) for p in sensitivity_parts], ignore_index=True)
    table = rows[["frequency_hz", "h1_um"]].merge(parts, on=["frequency_hz", "h1_um"], how="left",
                                                  validate="one_to_one")
    same = (table["status"].fillna("") == rows["status"]) | (table["status"] == "no_derivative")
    force = np.isclose(table["pulloff_mN"], rows["pulloff_mN"], rtol=1e-9, atol=0.0, equal_nan=True)
    if not np.all(same & force):
        bad = table[~(same & force)].iloc[0]
        raise ValueError(f"sensitivity parts and the virtual pull-off disagree at {bad['frequency_hz']:g} Hz, "
                         f"h1 = {bad['h1_um']:g} um (status {bad['status']}): were they computed at other parameters?")
    return table


def summary(virtual_csv: str | Path, sensitivity_parts: Sequence[str | Path], fit_parts: Sequence[str | Path],
            noise: Sequence[float], sensitivity_out: str | Path, information_out: str | Path,
            fits_out: str | Path) -> None:
    """Log-sensitivities of the simulated pull-off at the rig's tests, standard errors per design and noise, fits."""
    sensitivity = rig_sensitivity(virtual_csv, sensitivity_parts)
    information = identifiability.information_table(sensitivity, noise)
    write_csv(sensitivity, sensitivity_out)
    write_csv(information, information_out)
    write_csv(pd.concat([pd.read_csv(p) for p in fit_parts], ignore_index=True), fits_out)
    print(information.to_string(index=False))


def fit_coverage(setup_json: str | Path, fits_out: str | Path, summary_out: str | Path, level: str,
                 relative_scatter: Sequence[float], seeds: int, confidence: float) -> None:
    """The coverage study of the fit's intervals (:mod:`vibroadhesion.experiments.fit_coverage`).

    At the rig's test conditions and published parameters: every data set's fit, and the coverage per scatter and
    parameter.
    """
    setup, params, _ = rig(setup_json)
    progress = ProgressBar(len(relative_scatter) * seeds, "simulated data sets fitted")
    fits = fit_coverage_study.coverage_fits(
        level, GentSchultzParameters(**params), setup.frequencies_hz, setup.amplitudes_um, relative_scatter, seeds,
        radius=setup.radius, reduced_modulus=setup.reduced_modulus, settings=Settings(confidence=confidence),
        progress=progress)
    write_csv(fits, fits_out)
    write_csv(fit_coverage_study.coverage_summary(fits, confidence), summary_out)
