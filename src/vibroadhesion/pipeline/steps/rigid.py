"""Figs. 6 and 7's tables: rigidly fixed indenter, refined model (Secs. 3.5.4, 3.6).

Run by rules ``fig3_fig6_fig8_data`` and ``fig4_fig7_data``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from vibroadhesion.experiments.figure_tables import APPLICABILITY_LIMIT
from vibroadhesion.experiments.figure_tables.rigid import fig6_table, fig7_table
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.inputs import rig


def fig6_data(setup_json: str | Path, fit_json: str | Path | None, out: str | Path, log10_omega_check_min: float,
              log10_omega_check_max: float, points: int) -> None:
    """results/fig6/fig6.csv: Abar, abar_m, w_eff/w0, A/a_m (Eqs. 122-123, 49, corrected 98) per amplitude."""
    setup, params, chi0 = rig(setup_json, fit_json)
    omega = np.logspace(log10_omega_check_min, log10_omega_check_max, points)
    table = fig6_table(setup.amplitudes_um, omega, chi0=chi0, radius=setup.radius, n=params["n"])
    write_csv(table, out)
    outside = table["A_over_am"] > APPLICABILITY_LIMIT
    impossible = table["A_over_am"] > 1.0
    print(f"{len(table)} points solved; {int(outside.sum())} with A/a_m > {APPLICABILITY_LIMIT} (outside the "
          f"asymptotic model), of which {int(impossible.sum())} with A/a_m > 1 (geometrically impossible)")


def fig7_data(setup_json: str | Path, fit_json: str | Path | None, out: str | Path, log10_omega_check_min: float,
              log10_omega_check_max: float, points: int) -> None:
    """results/fig7/fig7.csv: the refined pull-off estimate against omega_check (Eq. 106) per amplitude."""
    setup, params, chi0 = rig(setup_json, fit_json)
    omega = np.logspace(log10_omega_check_min, log10_omega_check_max, points)
    write_csv(fig7_table(setup.amplitudes_um, omega, chi0=chi0, radius=setup.radius, n=params["n"]), out)
