"""The code checks of the house rules, run by the README's test command (and so by ``.ci/run``).

ruff (pyflakes, pycodestyle, import order, naming, docstrings, numpy and bugbear rules) and mypy
(strict) on the package, snakefmt on the workflow, and Snakemake's own linter, which may report
nothing but its notice that no rule names a conda environment or container: this pipeline
installs one locked virtual environment for every rule instead (README, "The two commands").
The tools are pinned in ``environment.lock`` and configured in ``pyproject.toml``.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
CONDA_NOTICE = "* Specify a conda environment or container for each rule.:"


def _run(*args: str | Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(a) for a in args], cwd=ROOT, capture_output=True, text=True, timeout=900)


def test_ruff_passes_on_the_package_and_the_rule_scripts() -> None:
    result = _run(BIN / "ruff", "check", "src", "workflow/scripts")
    assert result.returncode == 0, result.stdout + result.stderr


def test_mypy_strict_passes_on_the_package(tmp_path: Path) -> None:
    result = _run(BIN / "mypy", "--cache-dir", tmp_path / "mypy-cache")  # files = src (pyproject.toml)
    assert result.returncode == 0, result.stdout + result.stderr


def test_snakefmt_leaves_the_workflow_unchanged() -> None:
    result = _run(BIN / "snakefmt", "--check", "Snakefile", "workflow")
    assert result.returncode == 0, result.stdout + result.stderr


def test_snakemake_lint_reports_only_the_conda_notice() -> None:
    """Every lint item is the conda/container notice (one per rule); any other item fails.

    The notice itself must be found: if a Snakemake upgrade changes the output's layout, the parser
    below sees no item at all and this test says so rather than passing on nothing.
    """
    result = _run(BIN / "snakemake", "--lint")
    items = [line.strip() for line in (result.stdout + result.stderr).splitlines() if line.startswith("    * ")]
    assert items, "no lint item parsed from `snakemake --lint`: its output format changed\n" + result.stderr
    assert set(items) == {CONDA_NOTICE}, sorted(set(items) - {CONDA_NOTICE})
