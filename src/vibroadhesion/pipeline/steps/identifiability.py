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

from vibroadhesion.experiments import identifiability, virtual_pulloff
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.numerics.progress import ProgressBar
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.inputs import rig


def sensitivity_run(setup_json: str | Path, fit_json: str | Path | None, out: str | Path, parameter: str,
                    sign: str) -> None:
    """Simulated pull-off with one parameter scaled by exp(+h) or exp(-h).

    Rigid fixation, every test frequency and amplitude of the rig; ``parameter`` is scaled by exp(+h)
    when ``sign`` is "plus", by exp(-h) when it is "minus".
    """
    setup, params, _ = rig(setup_json, fit_json)
    shifted = identifiability.perturbed(GentSchultzParameters(**params), parameter, {"plus": 1, "minus": -1}[sign])
    h1 = np.asarray(setup.amplitudes_um, dtype=float)
    progress = ProgressBar(len(h1) * len(setup.frequencies_hz), "amplitudes")
    tables = [virtual_pulloff.pulloff_table(shifted, f, h1, radius=setup.radius, reduced_modulus=setup.reduced_modulus,
                                            progress=progress, predictions=False) for f in setup.frequencies_hz]
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


def summary(virtual_csv: str | Path, sensitivity_parts: Sequence[str | Path], fit_parts: Sequence[str | Path],
            noise: Sequence[float], sensitivity_out: str | Path, information_out: str | Path,
            fits_out: str | Path) -> None:
    """Log-sensitivities of the simulated pull-off, standard errors per design and relative noise, fits table."""
    parts = {Path(p).stem: pd.read_csv(p) for p in sensitivity_parts}
    missing = [f"{n}_{s}" for n in identifiability.PARAMETERS for s in ("plus", "minus") if f"{n}_{s}" not in parts]
    if missing:
        raise ValueError(f"sensitivity runs missing: {', '.join(missing)}")
    sensitivity = identifiability.log_sensitivity(
        _simulated_rigid_rows(virtual_csv), {n: parts[f"{n}_plus"] for n in identifiability.PARAMETERS},
        {n: parts[f"{n}_minus"] for n in identifiability.PARAMETERS})
    information = identifiability.information_table(sensitivity, noise)
    write_csv(sensitivity, sensitivity_out)
    write_csv(information, information_out)
    write_csv(pd.concat([pd.read_csv(p) for p in fit_parts], ignore_index=True), fits_out)
    print(information.to_string(index=False))
