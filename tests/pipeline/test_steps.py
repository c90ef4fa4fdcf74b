"""Pipeline steps on their own: a rig other than the paper's (issue 13, item 7), the kernel step, the sensitivity and
design steps.

The steps run as the rules run them (ingest, fit, tables, plot) on a setup with test frequencies 150/250 Hz and
amplitudes 25.5, 50 and 150 um, off Fig. 4's 1 um grid and beyond its 120 um; no simulated rows. The sensitivity
and design steps run on the paper's rig at one test frequency, against its virtual pull-off job.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from vibroadhesion.pipeline.data import ingest
from vibroadhesion.pipeline.steps.design import experiment_design
from vibroadhesion.pipeline.steps.fig4 import fig4_data
from vibroadhesion.pipeline.steps.fit import fit
from vibroadhesion.pipeline.steps.plots import fig7_plot
from vibroadhesion.pipeline.steps.identifiability import rig_sensitivity, sensitivity_part
from vibroadhesion.pipeline.steps.rigid import fig7_data
from vibroadhesion.pipeline.steps.gather import concatenate, rigid_grid
from vibroadhesion.pipeline.steps.simulation import rigid_part, virtual_pulloff_part
from vibroadhesion.pipeline.steps.rigs import rigs_part
from vibroadhesion.pipeline.steps.inputs import rig, setup_fixations, setup_number
from vibroadhesion.experiments.rigs import simulated_row
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.groups import eta1

from conftest import RADIUS, V0, W0

from vibroadhesion.pipeline import figures

ROOT = Path(__file__).resolve().parents[2]
AMPLITUDES = [25.5, 50.0, 150.0]
VIRTUAL_COLUMNS = ["fixation", "model", "status", "frequency_hz", "h1_um", "pulloff_ratio"]


def _other_rig(tmp_path: Path) -> tuple[Path, Path]:
    text = (ROOT / "data/setup.yaml").read_text(encoding="utf-8")
    for old, new in (("value: [200.0, 300.0, 400.0]", "value: [150.0, 250.0]"),
                     ("value: [20.0, 40.0, 60.0, 80.0, 100.0]", f"value: {AMPLITUDES}")):
        assert text.count(old) == 1
        text = text.replace(old, new)
    (tmp_path / "setup.yaml").write_text(text, encoding="utf-8")
    setup_json, pulloff_csv, fit_json = tmp_path / "setup.json", tmp_path / "pulloff.csv", tmp_path / "fit.json"
    ingest(tmp_path / "setup.yaml", ROOT / "data/pulloff.csv", setup_json, pulloff_csv)
    fit(setup_json, pulloff_csv, fit_json, "refined")
    return setup_json, fit_json


def test_fig4_grid_holds_the_rig_amplitudes_and_fig7_draws_them(tmp_path: Path) -> None:
    """Fig. 7 reads the leading-order and exact-averaging values at each rig amplitude from Fig. 4's table: the
    amplitudes must be on its grid (an IndexError before), and the plot must label the rig's frequencies."""
    setup_json, fit_json = _other_rig(tmp_path)
    fig4_csv, fig7_csv = tmp_path / "fig4.csv", tmp_path / "fig7.csv"
    fig4_data(setup_json, fit_json, fig4_csv, 120.0, 121)
    table = pd.read_csv(fig4_csv)
    for model in ("leading", "exact_averaging"):
        h1 = table.loc[table["model"] == model, "h1_um"].to_numpy()
        assert all(np.any(h1 == a) for a in AMPLITUDES), model
        assert np.all(np.diff(h1) > 0)
    assert sorted(table.loc[table["model"] == "refined", "frequency_hz"].unique()) == [150.0, 250.0]
    fig7_data(setup_json, fit_json, fig7_csv, 2.0, 9.0, 8)
    virtual = tmp_path / "virtual.csv"
    pd.DataFrame(columns=VIRTUAL_COLUMNS).to_csv(virtual, index=False)
    fig7_plot(setup_json, fit_json, tmp_path / "pulloff.csv", fig7_csv, fig4_csv, virtual, tmp_path / "fig7.pdf",
              tmp_path / "fig7.png")
    assert (tmp_path / "fig7.png").stat().st_size > 0


def test_fig7_draws_the_measured_rows_at_their_omega_check_labelled_by_source(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Fig. 7 (b) shows the measured rows as Fig. 4 does: at omega_check = 2 pi f R/v0 (Eq. 105) and P/|P_JKR| with
    |P_JKR| = (3 pi/2) R w0 (Eq. 70) of the figure's set (no rows fitted here: the published one), one legend entry
    per source and amplitude; a static test (no frequency) is not on the axis; without rows nothing is drawn."""
    setup_json, fit_json = _other_rig(tmp_path)
    fig4_csv, fig7_csv, virtual = tmp_path / "fig4.csv", tmp_path / "fig7.csv", tmp_path / "virtual.csv"
    fig4_data(setup_json, fit_json, fig4_csv, 120.0, 121)
    fig7_data(setup_json, fit_json, fig7_csv, 2.0, 9.0, 8)
    pd.DataFrame(columns=VIRTUAL_COLUMNS).to_csv(virtual, index=False)
    measured = tmp_path / "measured.csv"
    measured.write_text("line,frequency_hz,h1_um,pulloff_mN,source\n9,150.0,50.0,120.0,lab A\n"
                        "12,250.0,50.0,130.0,lab B\n14,0.0,0.0,58.0,lab B\n", encoding="utf-8")
    drawn = []
    monkeypatch.setattr(figures, "save_figure", lambda fig, pdf, png: drawn.append(fig))
    for rows in (measured, tmp_path / "pulloff.csv"):
        fig7_plot(setup_json, fit_json, rows, fig7_csv, fig4_csv, virtual, tmp_path / "fig7.pdf", tmp_path / "fig7.png")
    points = {line.get_label(): line.get_xydata() for line in drawn[0].axes[1].lines}
    without = {line.get_label() for line in drawn[1].axes[1].lines}
    jkr_mN = 1.5 * np.pi * RADIUS * W0 * 1e3
    assert {label for label in set(points) - without if not label.startswith("_")} == {
        "lab A, $h_1$ = 50 µm", "lab B, $h_1$ = 50 µm"}
    assert len(drawn[0].axes[1].lines) == len(without) + 2
    for label, f, force in (("lab A, $h_1$ = 50 µm", 150.0, 120.0), ("lab B, $h_1$ = 50 µm", 250.0, 130.0)):
        np.testing.assert_allclose(points[label], [[2 * np.pi * f * RADIUS / V0, force / jkr_mN]], rtol=1e-12)


def test_kernel_step_records_the_same_bytes_every_run(tmp_path: Path) -> None:
    """Rule simulation_kernels: both compiled paths run to a steady state; its output is deterministic (the time
    taken goes to the log, not the file)."""
    from vibroadhesion.pipeline.steps.kernels import compile_kernels

    texts = []
    for k in range(2):
        compile_kernels(tmp_path / f"kernels{k}.txt")
        texts.append((tmp_path / f"kernels{k}.txt").read_text(encoding="utf-8"))
    assert texts[0] == texts[1]
    assert "rigid steady state ok, compliant ok" in texts[0]


def test_sensitivity_and_design_steps_agree_with_the_virtual_pulloff_and_refuse_a_mixed_table(tmp_path: Path) -> None:
    """The paper's rig at 200 Hz: the sensitivity job (rig amplitudes and the candidates 0, 120 um; 0 is the static
    test, not simulated) traces the same families as the virtual pull-off job, so its forces equal the virtual rows'
    to rounding (1e-12); the design step writes the candidates with the static test and a design table. A virtual
    table from other parameters (one force off by 1e-6) is refused, never mixed in."""
    setup_json, pulloff_csv, fit_json = tmp_path / "setup.json", tmp_path / "pulloff.csv", tmp_path / "fit.json"
    ingest(ROOT / "data/setup.yaml", ROOT / "data/pulloff.csv", setup_json, pulloff_csv)
    fit(setup_json, pulloff_csv, fit_json, "refined")
    part, virtual = tmp_path / "200Hz.csv", tmp_path / "virtual.csv"
    sensitivity_part(setup_json, fit_json, part, [200.0], [0.0, 120.0])
    virtual_pulloff_part(setup_json, fit_json, virtual, "rigid", [200.0])
    assert pd.read_csv(part)["h1_um"].tolist() == [20.0, 40.0, 60.0, 80.0, 100.0, 120.0]
    rows = rig_sensitivity(virtual, [part])
    simulated = pd.read_csv(virtual).query("model == 'simulation'")
    assert rows["h1_um"].tolist() == simulated["h1_um"].tolist()
    assert np.allclose(rows["pulloff_mN"], simulated["pulloff_mN"], rtol=1e-12, atol=0)
    assert np.isfinite(rows[["dlnP_dlnw0", "dlnP_dlnn", "dlnP_dlnv0"]].to_numpy(float)).all()
    design_csv, candidates_csv = tmp_path / "design.csv", tmp_path / "candidates.csv"
    experiment_design(virtual, [part], [0.01], [1], design_csv, candidates_csv)
    candidates = pd.read_csv(candidates_csv)
    assert len(candidates) == 7 and candidates["status"].iloc[-1] == "static_jkr"
    assert pd.read_csv(design_csv)["design"].tolist() == ["current", "current + 1 test"]
    table = pd.read_csv(virtual)
    table.loc[table.index[table["model"] == "simulation"][2], "pulloff_mN"] *= 1 + 1e-6
    table.to_csv(virtual, index=False)
    with pytest.raises(ValueError, match="disagree at 200 Hz, h1 = 60 um"):
        rig_sensitivity(virtual, [part])



def test_rigs_step_takes_the_base_rigs_pulloffs_from_the_virtual_pulloff_of_the_same_families(tmp_path: Path) -> None:
    """Rule rigs_part at 200 Hz: the base rig's simulated pull-offs are the compliant virtual pull-off job's rows (the
    same problems, taken, not traced again); traced by the rig comparison itself (h1 = 20 um) the family gives the
    same force to 1e-12 (the two jobs form omega_check in a different order: 6e-14 was measured)."""
    setup_json, pulloff_csv = tmp_path / "setup.json", tmp_path / "pulloff.csv"
    ingest(ROOT / "data/setup.yaml", ROOT / "data/pulloff.csv", setup_json, pulloff_csv)
    virtual, out = tmp_path / "virtual.csv", tmp_path / "200.csv"
    virtual_pulloff_part(setup_json, None, virtual, "compliant", [200.0])
    rigs_part(setup_json, [virtual], out, "200")
    simulated = pd.read_csv(virtual).query("model == 'simulation'")
    base = pd.read_csv(out).query("rig == 'base' and level == 'simulation'")
    assert base["pulloff_ratio"].tolist() == simulated["pulloff_ratio"].tolist()
    assert (base["status"] == "ok; pull-off " + simulated["status"].to_numpy()).all()
    setup, params, chi0 = rig(setup_json)
    (fixation,) = setup_fixations(setup, params["v0"], "compliant")
    omega_bar = 2.0 * np.pi * 200.0 / setup_number(setup, "fixation.natural_frequency")
    traced = simulated_row("base", float(eta1(20e-6, setup.radius)), fixation, chi0, GentSchultz(params["n"]),
                           omega_bar / fixation.nu0)
    assert traced["pulloff_ratio"] == pytest.approx(simulated["pulloff_ratio"].iloc[0], rel=1e-12, abs=0)



def _simulation_job(kind: str, setup_json: Path, out: Path, values: list[float]) -> None:
    """One simulation job at the published parameters: the rigid grid's amplitudes ``values`` (omega_check 1e3-1e4,
    to stay quick) or the rigid virtual pull-off's test frequencies ``values``."""
    if kind == "rigid_grid":
        rigid_part(setup_json, None, out, values, 3, 4)
    else:
        virtual_pulloff_part(setup_json, None, out, "rigid", values)


@pytest.mark.parametrize("kind,values,gather", [("rigid_grid", [20.0, 100.0], rigid_grid),
                                                ("virtual_pulloff", [200.0, 400.0], concatenate)])
def test_a_job_of_several_amplitudes_or_frequencies_gives_the_bytes_of_one_job_each(tmp_path: Path, kind: str,
                                                                                     values: list[float],
                                                                                     gather: Callable) -> None:
    """workflow/config.yaml simulation_jobs.*_per_job: the rigid grid (two amplitudes) and the virtual pull-off table (two
    test frequencies) gathered from one job are byte for byte those gathered from one job per amplitude or frequency
    (the split of profiles/slurm), as the gather rules (simulation_rigid_grid, virtual_pulloff_fixation) write them."""
    setup_json, pulloff_csv = tmp_path / "setup.json", tmp_path / "pulloff.csv"
    ingest(ROOT / "data/setup.yaml", ROOT / "data/pulloff.csv", setup_json, pulloff_csv)
    _simulation_job(kind, setup_json, tmp_path / "one_job.csv", values)
    parts = [tmp_path / f"part{k}.csv" for k in range(len(values))]
    for part, value in zip(parts, values, strict=True):
        _simulation_job(kind, setup_json, part, [value])
    gather([tmp_path / "one_job.csv"], tmp_path / "from_one_job.csv")
    gather(parts, tmp_path / "from_parts.csv")
    assert (tmp_path / "from_one_job.csv").read_bytes() == (tmp_path / "from_parts.csv").read_bytes()
