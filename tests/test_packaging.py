"""Packaging: license metadata, the hashed lock and the install commands (README, .ci/run).

The README's two commands install everything from ``environment.lock`` with hashes, the build
backend included, and then the package itself with ``--no-build-isolation``, so that nothing is
downloaded unhashed. These tests keep pyproject.toml, the lock, the README and .ci/run in step.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
LOCK = (ROOT / "environment.lock").read_text(encoding="utf-8")
INSTALL = (
    "python3 -m venv .venv && .venv/bin/pip install -q --require-hashes -r environment.lock"
    " && .venv/bin/pip install -q --no-deps --no-build-isolation -e ."
)


def _pins() -> dict[str, tuple[str, list[str]]]:
    """name -> (version, hashes) of every requirement in the lock (a pin line and its continuation lines)."""
    pins: dict[str, tuple[str, list[str]]] = {}
    for block in re.split(r"\n(?=[A-Za-z0-9])", LOCK):
        head = re.match(r"([A-Za-z0-9._-]+)==(\S+)", block)
        if head:
            pins[canonicalize_name(head[1])] = (head[2], re.findall(r"--hash=sha256:([0-9a-f]{64})", block))
    return pins


def test_license_is_an_spdx_expression_with_its_file() -> None:
    project = PYPROJECT["project"]
    assert project["license"] == "MIT"
    assert project["license-files"] == ["LICENSE"]
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License") and "Copyright (c) 2026 the vibroadhesion developers" in text


def test_build_backend_is_locked_with_hashes() -> None:
    """The lock's dependency group ``build`` is the build-system requirement, and the lock satisfies it."""
    requires = PYPROJECT["build-system"]["requires"]
    assert PYPROJECT["dependency-groups"]["build"] == requires
    pins = _pins()
    for req in map(Requirement, requires):
        version, hashes = pins[canonicalize_name(req.name)]
        assert req.specifier.contains(version), f"{req.name}=={version} does not satisfy {req}"
        assert hashes, req.name


def test_every_pin_has_a_hash_and_the_header_compiles_extras_and_build() -> None:
    pins = _pins()
    assert len(pins) == LOCK.count("==")
    assert all(hashes for _, hashes in pins.values()), [n for n, (_, h) in pins.items() if not h]
    assert "uv pip compile pyproject.toml --extra test --group build --generate-hashes" in LOCK.splitlines()[1]


def test_the_slurm_executor_is_locked_in_the_cluster_group() -> None:
    """profiles/slurm's executor plugin (and the jobstep plugin it runs inside a job) comes from the lock, hashed."""
    assert "--group cluster" in LOCK.splitlines()[1]
    (plugin,) = map(Requirement, PYPROJECT["dependency-groups"]["cluster"])
    pins = _pins()
    assert plugin.specifier.contains(pins[canonicalize_name(plugin.name)][0])
    assert pins["snakemake-executor-plugin-slurm"][1] and pins["snakemake-executor-plugin-slurm-jobstep"][1]


@pytest.mark.parametrize("tool", ["pytest", "ruff", "mypy", "snakefmt"])
def test_test_tools_are_in_the_extra_and_the_lock(tool: str) -> None:
    assert tool in {Requirement(r).name for r in PYPROJECT["project"]["optional-dependencies"]["test"]}
    assert canonicalize_name(tool) in _pins()


def test_readme_commands_and_ci_install_the_same_way() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    commands = [line for line in readme.splitlines() if line.startswith("python3 -m venv .venv")]
    assert len(commands) == 2 and all(c.startswith(INSTALL + " && ") for c in commands), commands
    test_command = next(c for c in commands if c.endswith("&& .venv/bin/pytest"))
    # verbatim, in a subshell: set -e then stops .ci/run when any command of the chain fails, not only the last
    assert f"({test_command})" in ci.splitlines(), ".ci/run must call the README's test command"
