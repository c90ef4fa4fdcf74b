"""Step of rule ``fig5_data``: the compliantly fixed indenter through resonance (refined model, Sec. 3.5.3)."""

from __future__ import annotations

from pathlib import Path

from vibroadhesion.core import groups
from vibroadhesion.experiments.figure_tables.fig5 import fig5_tables
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.data import Setup
from vibroadhesion.pipeline.steps.inputs import rig, setup_fixations, setup_number


def compliant_case(setup: Setup) -> tuple[float, dict[float, float]]:
    """Fig. 5's amplitude eta1 = h1/R (Eq. 65), and omega_bar = omega/omega0 at each test frequency (Eq. 65)."""
    omega0 = setup_number(setup, "fixation.natural_frequency")
    h1_um = setup_number(setup, "test_conditions.fig5_amplitude")
    omega_bar = {f: groups.omega_bar(f, omega0) for f in setup.frequencies_hz}
    return float(groups.eta1(h1_um * 1e-6, setup.radius)), omega_bar


def fig5_data(setup_json: str | Path, fit_json: str | Path | None, out: str | Path, markers_out: str | Path,
              counts_out: str | Path, omega_bar_min: float, omega_bar_max: float, count_points: int) -> None:
    """A/a_m through resonance (Eqs. 87, 90-96) for every assumed (kappa, zeta) of data/setup.yaml.

    Folds, the test frequencies, and the number of solutions on ``count_points`` log-spaced omega_bar.
    """
    setup, params, chi0 = rig(setup_json, fit_json)
    eta1, experiments = compliant_case(setup)
    curves, markers, counts = fig5_tables(setup_fixations(setup, params["v0"], "fig5"), chi0, eta1, params["n"],
                                          experiments, (omega_bar_min, omega_bar_max), count_points)
    write_csv(curves, out)
    write_csv(markers, markers_out)
    write_csv(counts, counts_out)
    for (kappa, zeta), rows in markers[markers["kind"] == "fold"].groupby(["kappa", "zeta"]):
        folds = ", ".join(f"{w:.6f}" for w in rows["omega_bar"])
        print(f"kappa = {kappa:g}, zeta = {zeta:g}: folds at omega_bar = {folds}")
    for row in markers[~markers["kind"].isin(["fold", "experiment"])].itertuples():
        print(f"kappa = {row.kappa:g}, zeta = {row.zeta:g}: branch {row.branch} ended ({row.kind}) at omega_bar = "
              f"{row.omega_bar:.6f}, A/a_m = {row.A_over_am:.3g}")
    several = counts[counts["solutions"] > 1]
    print(f"{len(curves)} points traced; {len(several)} of {len(counts)} grid frequencies with more than one solution")
