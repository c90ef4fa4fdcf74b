"""Steps of the validation rules.

Every model level against the direct simulation (errors and their summary), and Fig. 5's folded resonance swept up
and down with the simulation.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from vibroadhesion.experiments import validation
from vibroadhesion.experiments.figure_tables.fig5 import fig5_tables
from vibroadhesion.numerics.progress import ProgressBar
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.fig5 import compliant_case
from vibroadhesion.pipeline.steps.inputs import experiment_omega_check, rig, setup_fixations


def rigid_errors(setup_json: str | Path, fit_json: str | Path | None, grid_csv: str | Path, errors_out: str | Path,
                 summary_out: str | Path) -> None:
    """Relative error of every level against the simulation on the rigid grid.

    Also its summary: the largest error per level and quantity, overall and at the test frequencies.
    """
    setup, params, _ = rig(setup_json, fit_json)
    errors = validation.relative_errors(pd.read_csv(grid_csv))
    summary = validation.error_summary(errors, list(experiment_omega_check(setup, params["v0"]).values()))
    write_csv(errors, errors_out)
    write_csv(summary, summary_out)
    print(summary.to_string(index=False))


def compliant_sweep(setup_json: str | Path, fit_json: str | Path | None, out: str | Path, curve_out: str | Path,
                    omega_bar_min: float, omega_bar_max: float, points: int,
                    curve_range: tuple[float, float]) -> None:
    """The simulated compliant case swept through resonance, with the refined curve.

    The case is data/setup.yaml's (kappa, zeta), swept up and down over ``points`` log-spaced
    omega_bar (Floquet stability); the refined model's curve of that case traced over
    Fig. 5's ``curve_range`` (Eqs. 87, 90) within the sweep's range, as Fig. 5 draws it.
    """
    setup, params, chi0 = rig(setup_json, fit_json)
    eta1, _ = compliant_case(setup)
    fixations = setup_fixations(setup, params["v0"], "compliant")
    table = validation.compliant_sweep(fixations[0], chi0, eta1, params["n"],
                                       list(np.geomspace(omega_bar_min, omega_bar_max, points)),
                                       ProgressBar(2 * points, "frequencies"))
    curve, _, _ = fig5_tables(fixations, chi0, eta1, params["n"], {}, curve_range, 2)
    write_csv(table, out)
    write_csv(curve[curve["omega_bar"].between(table["omega_bar"].min(), table["omega_bar"].max())], curve_out)
    sim = table[table["model"] == "simulation"]
    print(f"{len(sim)} simulated steady states ({int((sim['status'] != 'ok').sum())} not first time), "
          f"{int((~sim['stable'].astype(bool)).sum())} unstable or failed")
