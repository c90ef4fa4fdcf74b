"""The paper's constants, written once for every test, and the pipeline's artefacts as a fixture.

Constants: the values the paper prints, each with its place in the paper (the text of Sec. 3.4,
Sec. 3.5.3 and the captions of Figs. 4-8). Test modules import them (``from conftest import CHI0``)
because many are needed at import time (parametrize lists, module-level fixations); a test that
deliberately uses another value writes that value itself. ``data/setup.yaml`` holds the same
numbers for the pipeline; ``tests/pipeline/test_data.py`` checks that file against these.

Fixture ``pipeline_results``: the ``results/`` directory of one ``snakemake -c2 all validation`` run
(about 2-4 min on 2 cores) in a temporary copy of the repository (the files ``git ls-files``
lists, as they are in the working tree), made once per session and shared by the xdist workers; tests
read it and never change it (one that edits the data works in a copy). Set the environment variable
``VIBROADHESION_RESULTS`` to a finished results directory (for example ``results`` after your own
run) to use it instead of running the pipeline.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]

# --- rig and material, Sec. 3.4 -----------------------------------------------------------------
RADIUS = 51.5e-3  # m, indenter radius R (Sec. 3.4; captions of Figs. 6 and 8)
YOUNGS_MODULUS = 2.8e6  # Pa, equilibrium modulus E of the PDMS sample (Sec. 3.4, Sec. 4)
STORAGE_FACTOR = 2.0  # E amplified by 2 for the storage modulus at omega <= 2500 rad/s (Sec. 3.4)
POISSON_RATIO = 0.5  # not printed: incompressible PDMS, the value that reproduces chi0 below (Eq. 64)
REDUCED_MODULUS = STORAGE_FACTOR * YOUNGS_MODULUS / (1 - POISSON_RATIO**2)  # E* = 2E/(1 - nu^2), Pa

# --- published Gent-Schultz fit, Fig. 4 caption ------------------------------------------------
W0 = 0.236  # J/m^2
N_PUBLISHED = 0.531  # exponent n
V0 = 44.5e-6  # m/s (printed "um", a velocity; docs/errata.md)

# --- dimensionless groups of the paper's figures -----------------------------------------------
CHI0 = 2.589e-2  # Sec. 3.5.3 (Fig. 5 text) and Sec. 3.5.4 (Fig. 6 text); Eq. (64)
ETA1 = 3.883e-4  # eta1 = h1/R for h1 = 20 um, R = 51.5 mm (Sec. 3.5.3, Fig. 5 text)
NU0 = 1.227e-5  # nu0 = v0/(omega0 R) (Sec. 3.5.3, Fig. 5 text; printed there as "v0")
C_O = 2 ** (1 / 3) * 3 ** (-2 / 3) * CHI0  # a_o/R, text below Eq. (86)

# --- test conditions ---------------------------------------------------------------------------
FREQUENCIES_HZ = (200.0, 300.0, 400.0)  # excitation frequencies (Sec. 3.5.3; Fig. 4)
OMEGA_BAR_200HZ = 17.85  # omega/omega0 at 200 Hz (Sec. 3.5.3; 26.78 and 35.7 at 300 and 400 Hz)
AMPLITUDES_UM = (20.0, 40.0, 60.0, 80.0, 100.0)  # base amplitudes h1 (captions of Figs. 6, 7, 8)

# --- a user's data set (not the paper's) --------------------------------------------------------
# Five plausible rows of data/pulloff.csv (issue 26): the leading and refined levels fit them at w0 = 0.220 J/m^2,
# n = 0.54 with 3.4 % rms; the full-model fit of main c91ccb3 ends on the lower bound w0 = 0.001 J/m^2.
PLAUSIBLE_FIVE = ("300,54.75,406.74,lab\n300,36.09,222.12,lab\n400,74.93,631.41,lab\n400,29.47,192.62,lab\n"
                  "200,37.18,249.56,lab\n")


def _copy_tracked_files(dest: Path) -> Path:
    """Copy the files git tracks, as they are in the working tree, into ``dest`` (a fresh clone's content)."""
    listed = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, text=True, check=True).stdout
    for name in filter(None, listed.split("\0")):
        source = ROOT / name
        if source.is_file():  # a tracked file deleted in the working tree is not copied
            (dest / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, dest / name)
    return dest


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """A test that uses the pipeline's artefacts (fixture ``pipeline_results``) is a ``pipeline`` test."""
    for item in items:
        if "pipeline_results" in getattr(item, "fixturenames", ()):
            item.add_marker(pytest.mark.pipeline)


def _built_copy(work: Path) -> Path:
    """``results/`` of ``<venv>/bin/snakemake -c2 all validation`` in a copy of the repository made at ``work``."""
    _copy_tracked_files(work)
    snakemake = Path(sys.prefix) / "bin" / "snakemake"
    out = subprocess.run([str(snakemake), "-c2", "all", "validation"], cwd=work, capture_output=True, text=True,
                         timeout=3600)
    assert out.returncode == 0, f"snakemake failed:\n{out.stdout[-3000:]}\n{out.stderr[-5000:]}"
    return work / "results"


@pytest.fixture(scope="session")
def pipeline_results(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """``results/`` of ``<venv>/bin/snakemake -c2 all validation`` in a copy of the repository, or $VIBROADHESION_RESULTS."""
    finished = os.environ.get("VIBROADHESION_RESULTS")
    if finished:
        return Path(finished)
    if "PYTEST_XDIST_WORKER" not in os.environ:
        return _built_copy(tmp_path_factory.mktemp("repository"))
    # Under pytest-xdist (pyproject.toml: -n 2) the workers share one build in their common temporary directory:
    # the first to get the lock builds, the other waits for it (the pattern of pytest-xdist's documentation).
    import fcntl  # POSIX; the suite runs on Linux (CI)

    shared = tmp_path_factory.getbasetemp().parent
    work = shared / "repository-all-validation"
    built = shared / "repository-all-validation.built"
    with (shared / "repository-all-validation.lock").open("w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not built.exists():
            shutil.rmtree(work, ignore_errors=True)
            _built_copy(work)
            built.touch()
    return work / "results"


class LinearResiduals:
    """r(x) = r0 + J (x - x0): a residual model linear in ln theta, the closed-form case of the fit's intervals
    (vibroadhesion.experiments.fit_statistics: there the profile t statistic is exactly linear)."""

    def __init__(self, r0: np.ndarray, jac: np.ndarray, x0: np.ndarray) -> None:
        self.r0, self.jac, self.x0 = r0, jac, x0

    def residuals(self, x: np.ndarray) -> np.ndarray:
        return self.r0 + self.jac @ (x - self.x0)

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        return self.jac
