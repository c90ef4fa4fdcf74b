"""The cluster path: ingest -> fit -> Fig. 3 -> its page through a real Slurm with profiles/slurm.

Runs only where ``sinfo`` reports an idle node (``profiles/slurm/local-slurm.sh start`` makes one on Debian as root;
.ci/run does that after the test suite) and skips with the reason otherwise. References: the run succeeds; every job that is not a local rule went
through Slurm (the executor plugin's "submitted with SLURM jobid" lines, one per job of the dry run's job count,
and Slurm's own record of each of those jobs as COMPLETED, kept by squeue for MinJobAge); the local rules ran on
the submit host; and every CSV and the fit equal, byte for byte, those of a local ``-c2`` run of the same targets.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import time
from pathlib import Path

import pytest
from test_pipeline import SNAKEMAKE, _copy_repo, _planned_rules

TARGETS = ["results/report/fig3.html", "results/fit/gent_schultz.json"]
# The jobs of TARGETS that go to Slurm: the computing rules. The rest are local rules (the Snakefile's localrules,
# the plot and report rules): inputs checked in milliseconds, a gather, matplotlib, papermill.
SUBMITTED = {"simulation_kernels", "simulation_rigid", "fit_gent_schultz", "fig3_fig6_fig8_data", "fig5_data"}
LOCAL = {"ingest_setup", "ingest_pulloff", "simulation_rigid_grid", "plot_steady_figures", "report_pages"}

def _idle_node() -> str | None:
    """Why the test cannot run, or None when sinfo reports an idle node."""
    if shutil.which("sinfo") is None:
        return "no Slurm here (sinfo not found); profiles/slurm/local-slurm.sh starts one on Debian as root"
    try:
        out = subprocess.run(["sinfo", "-h", "-N", "-o", "%t"], capture_output=True, text=True, timeout=20)
    except subprocess.TimeoutExpired:
        return "sinfo did not answer in 20 s"
    if "idle" not in out.stdout.split():
        return f"no idle Slurm node (sinfo: {(out.stdout + out.stderr).strip()[:120]!r})"
    return None


WHY_NOT = _idle_node()
# .ci/run sets VIBROADHESION_REQUIRE_SLURM after starting the local Slurm: there, no node is a failure, not a skip.
if WHY_NOT is not None and os.environ.get("VIBROADHESION_REQUIRE_SLURM"):
    raise RuntimeError(f"VIBROADHESION_REQUIRE_SLURM is set, but {WHY_NOT}")
pytestmark = [pytest.mark.pipeline, pytest.mark.skipif(WHY_NOT is not None, reason=WHY_NOT or "")]


@pytest.fixture(scope="module")
def runs(tmp_path_factory: pytest.TempPathFactory) -> dict[str, tuple[Path, str]]:
    """The same targets run through Slurm and locally (-c2): each copy's directory and its Snakemake output."""
    done = {}
    for name, args in (("slurm", ["--profile", "profiles/slurm", "--slurm-init-seconds-before-status-checks", "5"]),
                       ("local", ["-c2"])):
        work = _copy_repo(tmp_path_factory.mktemp(name))
        start = time.monotonic()
        out = subprocess.run([*SNAKEMAKE, *args, *TARGETS], cwd=work, capture_output=True, text=True, timeout=1800)
        log = out.stdout + out.stderr
        assert out.returncode == 0, f"{name} run failed:\n{log[-6000:]}"
        print(f"{name}: {time.monotonic() - start:.0f} s wall")
        done[name] = (work, log)
    return done


def _submitted(log: str) -> dict[str, str]:
    """Snakemake job id -> Slurm job id, from the plugin's lines "Job N has been submitted with SLURM jobid M"."""
    return dict(re.findall(r"Job (\d+) has been submitted with SLURM jobid (\d+)", log))


def _rule_of_job(log: str) -> dict[str, str]:
    """Snakemake job id -> rule, from the job headers ("rule NAME:" or "localrule NAME:" then "jobid: N")."""
    return {jobid: rule for rule, jobid in re.findall(r"^(?:local)?rule (\w+):\n(?:\s+.*\n)*?\s+jobid: (\d+)", log,
                                                         re.MULTILINE)}


def test_the_computing_jobs_went_through_slurm_and_completed(runs: dict[str, tuple[Path, str]],
                                                             tmp_path: Path) -> None:
    _, log = runs["slurm"]
    submitted = _submitted(log)
    rules = _rule_of_job(log)
    assert {rules[job] for job in submitted} == SUBMITTED
    planned = _planned_rules(_copy_repo(tmp_path), *TARGETS)
    assert planned == SUBMITTED | LOCAL, planned ^ (SUBMITTED | LOCAL)
    # One submission per job: the five amplitudes of simulation_rigid and one job of every other computing rule.
    assert len(submitted) == len(SUBMITTED) - 1 + 5
    squeue = subprocess.run(["squeue", "-h", "-t", "all", "-j", ",".join(submitted.values()), "-o", "%i %T"],
                            capture_output=True, text=True, timeout=20)
    states = dict(line.split() for line in squeue.stdout.splitlines())
    assert states == dict.fromkeys(submitted.values(), "COMPLETED"), squeue.stdout + squeue.stderr


def test_the_small_rules_ran_on_the_submit_host(runs: dict[str, tuple[Path, str]]) -> None:
    _, log = runs["slurm"]
    submitted = _submitted(log)
    local = {rule for job, rule in _rule_of_job(log).items() if job not in submitted}
    assert local == LOCAL


def _is_part(path: Path) -> bool:
    """Whether ``path`` is a simulation job's part file, named by its chunk of amplitudes, frequencies or rig cases.

    The profile sets the chunks: profiles/slurm/simulation.yaml one per job, workflow/config.yaml all in one.
    """
    return path.parent.name in ("rigid", "virtual_pulloff", "rigs")


def test_the_artefacts_equal_those_of_a_local_run(runs: dict[str, tuple[Path, str]]) -> None:
    """Every gathered artefact is byte-identical; only the simulation's part files are chunked differently."""
    slurm, local = (runs[name][0] / "results" for name in ("slurm", "local"))
    csvs = {name: sorted(p.relative_to(root) for p in root.rglob("*.csv")) for name, root in
            (("slurm", slurm), ("local", local))}
    parts = {name: [p for p in found if _is_part(p)] for name, found in csvs.items()}
    assert len(parts["slurm"]) > len(parts["local"]) >= 1, parts
    files = [p for p in csvs["local"] if not _is_part(p)] + [Path("fit/gent_schultz.json")]
    assert len(files) >= 5, files
    assert [p for p in csvs["slurm"] if not _is_part(p)] == files[:-1]
    for name in files:
        assert (slurm / name).read_bytes() == (local / name).read_bytes(), name
