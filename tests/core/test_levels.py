"""The registry of model levels (vibroadhesion.core.levels): references, row orders, DAG-time cost, one source.

The row orders are checked against the artefacts the pipeline writes (fixture ``pipeline_results``):
the registry's canonical order must be the order every CSV already has. The other checks read the
registry, the sources and the workflow files: no list of levels may be written anywhere else.
"""

from __future__ import annotations

import inspect
import re
import subprocess
import sys
import typing
from pathlib import Path

import pandas as pd
import pytest
import yaml
from conftest import ROOT

from vibroadhesion.core import levels
from vibroadhesion.core.fixation import FixationKind
from vibroadhesion.core.records import Pulloff, SteadyState

#: Documented leading parameters of each kind of function (module docstring of core/levels.py).
STEADY_STATE_PARAMETERS = ["eta1", "omega_check", "chi0", "law"]
PULLOFF_PARAMETERS = {False: ["eta1", "chi0", "law"], True: ["eta1", "chi0", "omega_check", "law"]}
SIMULATED_PULLOFF_PARAMETERS = ["problem"]


def _leading_parameters(function, count: int) -> list[str]:
    return list(inspect.signature(function).parameters)[:count]


@pytest.mark.parametrize("entry", levels.LEVELS, ids=lambda e: e.name)
def test_every_reference_resolves_to_a_function_with_the_documented_signature(entry: levels.ModelLevel) -> None:
    assert entry.steady_state is not None or entry.pulloff is not None, entry.name
    if entry.steady_state is not None:
        function = entry.steady_state_function()
        assert _leading_parameters(function, 4) == STEADY_STATE_PARAMETERS
        assert inspect.signature(function).return_annotation in ("SteadyState", SteadyState)
    if entry.pulloff is not None:
        function = entry.pulloff_function()
        expected = (SIMULATED_PULLOFF_PARAMETERS if entry.cost == "simulation"
                    else PULLOFF_PARAMETERS[entry.frequency_dependent])
        assert _leading_parameters(function, len(expected)) == expected
        assert inspect.signature(function).return_annotation in ("Pulloff", Pulloff)


def test_names_are_unique_and_a_missing_function_or_level_says_so() -> None:
    all_names = [entry.name for entry in levels.LEVELS]
    assert len(set(all_names)) == len(all_names)
    with pytest.raises(ValueError, match="exact_hb"):
        levels.level("exact_hb").pulloff_function()
    with pytest.raises(ValueError, match="expected one of .*'leading'"):
        levels.level("first_order")


def test_modules_of_a_role_are_the_modules_of_its_functions() -> None:
    assert levels.modules("fit", "pulloff") == ("vibroadhesion.experiments.virtual_pulloff",
                                                "vibroadhesion.models.exact_averaging",
                                                "vibroadhesion.models.leading_pulloff", "vibroadhesion.models.refined")
    assert levels.modules("validation_rigid", "steady_state") == (
        "vibroadhesion.experiments.validation", "vibroadhesion.models.exact_averaging",
        "vibroadhesion.models.exact_harmonic_balance", "vibroadhesion.models.refined")


def test_roles_name_the_levels_of_the_paper_and_its_checks() -> None:
    assert levels.names("validation_rigid") == ("simulation", "leading", "refined", "exact_hb", "exact_averaging")
    assert levels.names("fit") == ("simulation", "leading", "refined", "exact_averaging",
                                   "exact_averaging_force_minimum")
    assert levels.fig4_names() == ("leading", "exact_averaging", "refined")
    assert levels.names("virtual_pulloff") == ("simulation", "leading", "refined", "exact_averaging",
                                               "exact_averaging_force_minimum")


def test_fixations_select_the_levels_whose_model_covers_the_fixation() -> None:
    """Rigid: every level; the spring-mass-dashpot: the simulation, the leading order (Eqs. 67-69) and the
    refined model (Eq. 90), not the exact models of the rigidly fixed contact; free (Sec. 3.1.3): leading only.
    Every kind named is a kind of Fixation.
    """
    assert levels.names("virtual_pulloff", "rigid") == levels.names("virtual_pulloff")
    assert levels.names("virtual_pulloff", "compliant") == ("simulation", "leading", "refined")
    assert levels.names("validation_rigid", "rigid") == levels.names("validation_rigid")
    assert levels.names("fit", "free") == ("leading",)
    assert levels.names("fit", "rigid")[0] == "simulation"
    kinds = set(typing.get_args(FixationKind))
    assert all(entry.fixations and entry.fixations <= kinds and "rigid" in entry.fixations for entry in levels.LEVELS)


def _first_appearance(column: pd.Series) -> tuple[str, ...]:
    return tuple(dict.fromkeys(column))


def test_canonical_order_is_the_row_order_of_every_artefact(pipeline_results: Path) -> None:
    grid = pd.read_csv(pipeline_results / "simulation/rigid_grid.csv")
    validation = levels.names("validation_rigid")
    assert grid["model"].tolist() == list(validation) * (len(grid) // len(validation))
    for fixation in ("rigid", "compliant"):
        virtual = pd.read_csv(pipeline_results / f"simulation/published/virtual_pulloff_{fixation}.csv")
        for _, rows in virtual.groupby("frequency_hz", sort=False):
            assert _first_appearance(rows["model"]) == levels.names("virtual_pulloff", fixation), fixation
    fits = pd.read_csv(pipeline_results / "validation/identifiability/fits.csv")
    assert tuple(fits["model"]) == levels.names("fit")
    speed = pd.read_csv(pipeline_results / "benchmarks/speed_vs_error.csv")
    assert tuple(speed["model"]) == validation
    fig4 = pd.read_csv(pipeline_results / "fig4/fig4.csv")
    assert _first_appearance(fig4["model"]) == levels.fig4_names()


def test_importing_the_registry_loads_no_third_party_module() -> None:
    """Snakemake reads the registry while it builds the DAG: standard library only (fresh interpreter)."""
    code = ("import sys, vibroadhesion.core.levels; "
            "print(' '.join(m for m in ('numpy', 'scipy', 'pandas', 'matplotlib') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def _strings(node) -> list[str]:
    """Every string in a parsed YAML document (keys and values)."""
    if isinstance(node, dict):
        return [s for k, v in node.items() for s in (*_strings(k), *_strings(v))]
    if isinstance(node, list):
        return [s for item in node for s in _strings(item)]
    return [node] if isinstance(node, str) else []


def test_config_schema_has_no_list_of_levels() -> None:
    schema = yaml.safe_load((ROOT / "workflow/schemas/config.schema.yaml").read_text(encoding="utf-8"))
    known = {entry.name for entry in levels.LEVELS}
    assert known.isdisjoint(_strings(schema))


def _code_without_comments(path: Path) -> str:
    return "\n".join(line.split("#")[0] for line in path.read_text(encoding="utf-8").splitlines())


def test_identifiability_rules_name_no_level_literally() -> None:
    code = _code_without_comments(ROOT / "workflow/rules/identifiability.smk")
    for entry in levels.LEVELS:
        assert not re.search(rf"[\"'|]{entry.name}[\"'|]", code), entry.name


def test_every_source_that_resolves_level_functions_declares_them() -> None:
    """Whoever calls steady_state_function()/pulloff_function() declares LEVEL_FUNCTIONS.

    So its rules rerun when a level's module changes (vibroadhesion.pipeline.imports); the registry itself
    is excepted.
    """
    sources = [*(ROOT / "src/vibroadhesion").rglob("*.py"), *(ROOT / "workflow/scripts").glob("*.py"),
               *(ROOT / "benchmarks").glob("*.py")]
    for path in sources:
        text = path.read_text(encoding="utf-8")
        if path.name != "levels.py" and re.search(r"\.(steady_state|pulloff)_function\(\)", text):
            assert re.search(r"^LEVEL_FUNCTIONS = ", text, re.MULTILINE), path


def test_snakefile_refuses_a_figures_level_outside_the_registry_in_one_line(tmp_path: Path) -> None:
    config = yaml.safe_load((ROOT / "workflow/config.yaml").read_text(encoding="utf-8"))
    config["fit"]["figures_use"] = "exact_hb"
    (tmp_path / "config.yaml").write_text(yaml.safe_dump(config), encoding="utf-8")
    out = subprocess.run([str(Path(sys.executable).parent / "snakemake"), "-n", "--configfile",
                          str(tmp_path / "config.yaml")], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert out.returncode != 0
    lines = [line for line in out.stderr.splitlines() if "figures_use" in line]
    # the Snakefile lists the registry's fitted levels (every one may supply the figures' parameters)
    assert lines == ["workflow/config.yaml: fit.figures_use = 'exact_hb' is not one of "
                     + ", ".join(levels.names("fit"))], out.stderr
    assert "leading, refined, exact_averaging" in lines[0]
