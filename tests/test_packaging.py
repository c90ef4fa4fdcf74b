"""Packaging: license metadata, the dependency split, the hashed lock and the install commands (README, .ci/run).

The README's two commands install everything from ``environment.lock`` with hashes, the build
backend included, and then the package itself with ``--no-build-isolation``, so that nothing is
downloaded unhashed. These tests keep pyproject.toml, the lock, the README and .ci/run in step, offline:
the lock satisfies every requirement of pyproject.toml on every supported target (the targets and the
lock's parser are those of ``.ci/lock_platforms.py``, which checks the wheels and the resolution online),
and the library's dependencies are what the package outside its pipeline layer imports.
"""

from __future__ import annotations

import importlib.metadata
import importlib.util
import re
import sys
import tomllib
from pathlib import Path
from types import ModuleType

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name
from test_layers import PACKAGE, _imported_modules

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
LOCK = (ROOT / "environment.lock").read_text(encoding="utf-8")
INSTALL = (
    "python3 -m venv .venv && .venv/bin/pip install -q --require-hashes -r environment.lock"
    " && .venv/bin/pip install -q --no-deps --no-build-isolation -e ."
)


def _lock_platforms() -> ModuleType:
    """.ci/lock_platforms.py as a module (registered first: its dataclasses look their module up)."""
    spec = importlib.util.spec_from_file_location("lock_platforms", ROOT / ".ci" / "lock_platforms.py")
    assert spec is not None and spec.loader is not None
    module = sys.modules.setdefault("lock_platforms", importlib.util.module_from_spec(spec))
    spec.loader.exec_module(module)
    return module


LP = _lock_platforms()
PINS = LP.read_lock(LOCK)


def _pins() -> dict[str, tuple[str, list[str]]]:
    """name -> (version, hashes) of the lock's pins for CPython 3.11 on manylinux x86_64 (this machine)."""
    linux = LP.PLATFORMS[0]
    return {p.name: (p.version, list(p.hashes)) for p in PINS if LP.applies(p, (3, 11), linux)}


def _requirements() -> list[Requirement]:
    """Every requirement of pyproject.toml: dependencies, every extra, every dependency group, the build backend."""
    extras = PYPROJECT["project"]["optional-dependencies"].values()
    groups = PYPROJECT["dependency-groups"].values()
    return [Requirement(r) for r in PYPROJECT["project"]["dependencies"] + sum([*extras, *groups], [])]


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


def test_every_pin_has_a_hash_and_the_header_compiles_every_extra_and_group_universally() -> None:
    assert len(PINS) == len(re.findall(r"^[A-Za-z0-9._-]+==", LOCK, re.M)) > 100
    assert all(p.hashes for p in PINS), [p.name for p in PINS if not p.hashes]
    header = LOCK.splitlines()[1].split()
    assert header[1:5] == ["uv", "pip", "compile", "pyproject.toml"], header
    assert {"--universal", "--generate-hashes"} <= set(header)
    # the lowest supported Python is the one the lock is compiled for, and every extra and group is in it
    assert header[header.index("--python-version") + 1] == "3.11"
    assert PYPROJECT["project"]["requires-python"] == ">=3.11,<3.14"
    options = list(zip(header, header[1:], strict=False))
    assert {("--extra", e) for e in PYPROJECT["project"]["optional-dependencies"]} <= set(options)
    assert {("--group", g) for g in PYPROJECT["dependency-groups"]} <= set(options)


def test_the_supported_python_versions_are_stated_and_checked() -> None:
    classifiers = PYPROJECT["project"]["classifiers"]
    stated = {c.rsplit(" ", 1)[1] for c in classifiers if re.fullmatch(r"Programming Language :: Python :: 3\.\d+", c)}
    assert stated == {"3.11", "3.12", "3.13"} == {f"{a}.{b}" for a, b in LP.PYTHONS}
    assert {p.name for p in LP.PLATFORMS if p.required} == {
        "manylinux x86_64", "manylinux aarch64", "macOS x86_64", "macOS arm64"}


@pytest.mark.parametrize("target", LP.TARGETS, ids=lambda t: f"cp3{t[0][1]}-{t[1].name.replace(' ', '-')}")
def test_the_lock_satisfies_pyproject_on_every_target(target: tuple[tuple[int, int], object]) -> None:
    """Offline: on each Python and platform, every requirement that applies there has one pin, inside it.

    The pins' own dependencies are checked online by .ci/lock_platforms.py (uv resolves the lock per target).
    """
    python, platform = target
    environment = LP.marker_environment(python, platform)
    pins: dict[str, list[str]] = {}
    for pin in PINS:
        if LP.applies(pin, python, platform):
            pins.setdefault(pin.name, []).append(pin.version)
    assert all(len(versions) == 1 for versions in pins.values()), {n: v for n, v in pins.items() if len(v) > 1}
    unmet = [str(r) for r in _requirements() if (r.marker is None or r.marker.evaluate(environment))
             and not r.specifier.contains(pins.get(canonicalize_name(r.name), ["absent"])[0], prereleases=True)]
    assert not unmet, f"not satisfied by the lock on CPython {python} {platform.name}: {unmet}"


def test_the_offline_check_sees_an_unmet_requirement() -> None:
    """The check itself: a pin outside a requirement, or a platform-only pin, is told apart (it can fail)."""
    lock = "numba==0.62.1 ; sys_platform == 'darwin' \\\n    --hash=sha256:" + "0" * 64 + "\n"
    (pin,) = LP.read_lock(lock)
    assert (pin.name, pin.version, pin.hashes) == ("numba", "0.62.1", ("0" * 64,))
    mac, linux = LP.PLATFORMS[3], LP.PLATFORMS[0]
    assert LP.applies(pin, (3, 12), mac) and not LP.applies(pin, (3, 12), linux)
    assert not Requirement("numba>=0.63").specifier.contains(pin.version)


def test_marker_environment_agrees_with_this_interpreter() -> None:
    """The marker variables of CPython 3.11 on manylinux x86_64 are those packaging reads from this machine."""
    from packaging.markers import default_environment

    here = default_environment()
    if (sys.version_info[:2], here["sys_platform"], here["platform_machine"]) != ((3, 11), "linux", "x86_64"):
        pytest.skip("this machine is not CPython 3.11 on Linux x86_64")
    ours = LP.marker_environment((3, 11), LP.PLATFORMS[0])
    keys = ["implementation_name", "os_name", "platform_machine", "platform_python_implementation",
            "platform_system", "python_version", "sys_platform"]
    assert {k: ours[k] for k in keys} == {k: here[k] for k in keys}


@pytest.mark.parametrize(("filename", "python", "platform", "expected"), [
    ("numba-0.68.1-cp311-cp311-macosx_12_0_arm64.whl", (3, 11), "macOS arm64", True),
    ("numba-0.68.1-cp311-cp311-macosx_12_0_arm64.whl", (3, 12), "macOS arm64", False),  # other CPython ABI
    ("numba-0.68.1-cp311-cp311-macosx_12_0_arm64.whl", (3, 11), "macOS x86_64", False),  # other architecture
    ("numpy-2.3.5-cp313-cp313-macosx_14_0_x86_64.whl", (3, 13), "macOS x86_64", True),  # macOS 14 itself
    ("numpy-2.3.5-cp313-cp313-macosx_15_0_x86_64.whl", (3, 13), "macOS x86_64", False),  # needs a newer macOS
    ("x-1.0-cp311-abi3-macosx_11_0_universal2.whl", (3, 13), "macOS x86_64", True),  # stable ABI, fat binary
    ("x-1.0-cp311-abi3-macosx_11_0_universal2.whl", (3, 13), "macOS arm64", True),
    ("n-1.0-cp312-cp312-manylinux_2_27_aarch64.manylinux_2_28_aarch64.whl", (3, 12), "manylinux aarch64", True),
    ("n-1.0-cp312-cp312-manylinux_2_34_x86_64.whl", (3, 12), "manylinux x86_64", False),  # glibc 2.34 > 2.28
    ("n-1.0-cp312-cp312-manylinux2014_x86_64.whl", (3, 12), "manylinux x86_64", True),  # = manylinux_2_17
    ("n-1.0-cp312-cp312-manylinux1_x86_64.whl", (3, 12), "manylinux x86_64", True),  # = manylinux_2_5
    ("n-1.0-cp312-cp312-musllinux_1_2_x86_64.whl", (3, 12), "manylinux x86_64", False),
    ("p-1.0-py3-none-any.whl", (3, 13), "Windows x86_64", True),
    ("p-1.0.tar.gz", (3, 11), "manylinux x86_64", False),  # an sdist is no wheel
])
def test_which_wheels_install_where(filename: str, python: tuple[int, int], platform: str, expected: bool) -> None:
    """PEP 425/600 and the macOS tag rules: a wheel installs where its interpreter, ABI and platform tags match."""
    (target,) = [p for p in LP.PLATFORMS if p.name == platform]
    assert LP.installs([filename], python, target) is expected
    assert LP.is_platform_wheel(filename) is not (filename.startswith("p-"))


def _third_party(layers: set[str]) -> dict[str, set[str]]:
    """Distribution -> modules of the package (in ``layers``) that import it; stdlib and the package left out."""
    distributions = importlib.metadata.packages_distributions()
    found: dict[str, set[str]] = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        relative = path.relative_to(PACKAGE)
        if len(relative.parts) < 2 or relative.parts[0] not in layers:
            continue
        for _, name in _imported_modules(path):
            top = name.split(".")[0]
            if top in sys.stdlib_module_names or top in ("vibroadhesion", "__future__"):
                continue
            for distribution in distributions.get(top, [f"<no distribution: {top}>"]):
                found.setdefault(canonicalize_name(distribution), set()).add(str(relative))
    return found


def test_the_library_imports_exactly_its_runtime_dependencies() -> None:
    """Outside vibroadhesion.pipeline the package imports exactly project.dependencies: no Snakemake, no Jupyter."""
    runtime = {canonicalize_name(Requirement(r).name) for r in PYPROJECT["project"]["dependencies"]}
    imported = _third_party({"numerics", "core", "models", "simulation", "experiments"})
    assert set(imported) == runtime, {d: m for d, m in imported.items() if d not in runtime}
    workflow = {"snakemake", "papermill", "ipykernel", "nbconvert", "nbformat", "jupyter-client", "matplotlib"}
    assert not runtime & workflow


def test_the_pipeline_imports_only_runtime_and_pipeline_dependencies() -> None:
    project = PYPROJECT["project"]
    allowed = {canonicalize_name(Requirement(r).name)
               for r in project["dependencies"] + project["optional-dependencies"]["pipeline"]}
    imported = _third_party({"pipeline"})
    assert set(imported) <= allowed, {d: m for d, m in imported.items() if d not in allowed}
    assert {"matplotlib", "papermill", "nbconvert", "pyyaml", "jsonschema"} <= set(imported)


def test_the_slurm_executor_is_locked_in_the_cluster_group() -> None:
    """profiles/slurm's executor plugin (and the jobstep plugin it runs inside a job) comes from the lock, hashed."""
    assert "--group cluster" in LOCK.splitlines()[1]
    (plugin,) = map(Requirement, PYPROJECT["dependency-groups"]["cluster"])
    pins = _pins()
    assert plugin.specifier.contains(pins[canonicalize_name(plugin.name)][0])
    assert pins["snakemake-executor-plugin-slurm"][1] and pins["snakemake-executor-plugin-slurm-jobstep"][1]


@pytest.mark.parametrize("tool", ["pytest", "pytest-xdist", "ruff", "mypy", "snakefmt"])
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
