"""The Snakemake pipeline end to end, run through its CLI in a temporary copy of the repository.

References: the issue's acceptance criteria (artefacts exist with the stated columns; a second
run has nothing to do; a data edit reruns the fit, the figures and the report and nothing
else; a code edit reruns exactly the rules whose step imports the module, checked against an
independent record of the imports (the modules Python loads, and the import instructions in the
bytecode of every function); bad input stops the run with one line naming file, row and column
and leaves no partial outputs; the rules run with the project under a path with spaces, and an interpreter under
one is refused with one line), the papermill convention of exactly one ``parameters`` cell, and byte-level
determinism of the writers.
"""

from __future__ import annotations

import functools
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import numpy as np
import pandas as pd
import pytest
from conftest import AMPLITUDES_UM, N_PUBLISHED, PLAUSIBLE_FIVE, RADIUS, REDUCED_MODULUS, V0, W0

from vibroadhesion.experiments.figure_tables.fig4 import fig4_table
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.experiments.virtual_pulloff import FAMILY_BUDGET
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.figures import plot_fig4, save_figure
from vibroadhesion.pipeline.imports import import_closure
from vibroadhesion.pipeline.pages import PAGES, REPORT_JOBS

ROOT = Path(__file__).resolve().parents[2]
# The launcher the shared build used (conftest._built_copy): the rules' interpreter (common.smk PYTHON = sys.executable,
# a parameter of the shell rules) is then the same path, .venv/bin/python3, however pytest itself was started.
SNAKEMAKE = [str(Path(sys.prefix) / "bin" / "snakemake")]
COPY = ["Snakefile", "workflow", "src", "data", "notebooks", "benchmarks", "environment.lock", "profiles"]
# What an edit of data/pulloff.csv reruns: the rows, the fit and what shows them (Figs. 4 and 7, the fit page and
# the index beside them); nothing at the published parameters (Figs. 3, 5, 6, 8, the simulations behind them).
DATA_RULES = {"ingest_pulloff", "fit_gent_schultz", "fig4_fig7_data", "plot_pulloff_figures", "report_index", "all"}
# With measured rows the fit leaves the published set: Figs. 4 and 7 then overlay a simulation of their own.
FITTED_SIMULATION_RULES = {"virtual_pulloff", "virtual_pulloff_fixation"}
# What `snakemake -c2 validation` adds to a finished default run: the checks against the simulation
# (including the compliant virtual pull-off; the default run made the rigid one for Figs. 4 and 7), and the rendered
# report as one folder for Snakemake's report (rule report_site).
VALIDATION_RULES = {"validation_errors", "validation_plot", "validation_compliant", "validation_compliant_plot",
                    "pulloff_sensitivity", "virtual_pulloff", "virtual_pulloff_fixation", "virtual_pulloff_gather",
                    "identifiability_fit", "identifiability", "identifiability_design", "fit_coverage", "benchmark_j_integrals",
                    "withdrawal", "withdrawal_slow_flow", "withdrawal_gather", "withdrawal_plot",
                    "benchmark_simulate", "benchmark_speed_vs_error", "rigs_part", "rigs_gather", "rigs_plot",
                    "report_validation_index", "report_site", "validation"}


def _copy_repo(dest: Path) -> Path:
    for name in COPY:
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, dest / name, ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
        else:
            shutil.copy2(src, dest / name)
    (dest / "tests" / "reference").mkdir(parents=True)
    for name in ("mpmath_reference.py", "reference/j_integrals_mpmath.csv"):  # the J-integral benchmark's reference
        shutil.copy2(ROOT / "tests" / name, dest / "tests" / name)
    return dest


def _snakemake(workdir: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([*SNAKEMAKE, "-c2", *args], cwd=workdir, capture_output=True, text=True, timeout=900)


def _planned_after_edit(workdir: Path, relative: str) -> set[str]:
    """Rules a dry run plans after a content edit of one file (Snakemake compares small files by
    content, so a bare touch would plan nothing); the file is restored afterwards."""
    path = workdir / relative
    original = path.read_text()
    try:
        path.write_text(original + "\n# edited\n")
        return _planned_rules(workdir)
    finally:
        path.write_text(original)


def _planned_rules(workdir: Path, *targets: str) -> set[str]:
    """Rules a dry run would execute (parsed from Snakemake's job-stats table)."""
    out = _snakemake(workdir, "-n", *targets)
    assert out.returncode == 0, out.stderr
    text = out.stdout + out.stderr
    if "Nothing to be done" in text:
        return set()
    stats = text.split("Job stats:", 1)[1]
    return {m.group(1) for m in re.finditer(r"^(\w+)\s+\d+\s*$", stats, re.MULTILINE) if m.group(1) != "total"}


@pytest.fixture(scope="module")
def pipeline_run(tmp_path_factory) -> Path:
    work = _copy_repo(tmp_path_factory.mktemp("pipeline"))
    out = _snakemake(work)
    assert out.returncode == 0, f"snakemake failed:\n{out.stdout[-3000:]}\n{out.stderr[-5000:]}"
    return work


@pytest.mark.pipeline
def test_pipeline_produces_every_artefact_with_the_stated_columns(pipeline_run: Path) -> None:
    results = pipeline_run / "results"
    for fig in ("fig3", "fig4", "fig6", "fig7", "fig8"):
        for ext in ("csv", "pdf", "png"):
            assert (results / fig / f"{fig}.{ext}").stat().st_size > 0
    assert list(pd.read_csv(results / "fig3/fig3.csv").columns) == ["n", "Abar", "J0", "Jc1", "J1"]
    fig4 = pd.read_csv(results / "fig4/fig4.csv")
    assert list(fig4.columns) == ["model", "frequency_hz", "h1_um", "Abar_cr", "sqrt_w_eff_ratio", "pulloff_ratio",
                                  "pulloff_mN", "A_over_am"]
    for model, n_freq in (("leading", 1), ("refined", 3)):
        rows = fig4[fig4["model"] == model]
        assert set(AMPLITUDES_UM) <= set(rows["h1_um"])
        assert rows["frequency_hz"].nunique(dropna=False) == n_freq
    assert fig4.loc[fig4["model"] == "leading", "frequency_hz"].isna().all()
    assert (results / "fit/gent_schultz.json").exists()
    virtual = pd.read_csv(results / "simulation/published/virtual_pulloff_rigid.csv")
    assert set(virtual["fixation"]) == {"rigid"}
    assert {"fixation", "frequency_hz", "h1_um", "model", "pulloff_ratio", "pulloff_mN"} <= set(virtual.columns)
    assert not (results / "simulation/published/virtual_pulloff/compliant_200Hz.csv").exists()
    assert not (results / "simulation/fitted").exists()  # no measured rows: the fit is the published set
    assert not (results / "validation").exists()  # the figures read no validation output
    for page in ("index", "fig3", "fig4", "fig5", "fig6", "fig7", "fig8", "fit"):
        assert (results / "report" / f"{page}.html").stat().st_size > 0


@pytest.mark.pipeline
def test_second_run_has_nothing_to_do(pipeline_run: Path) -> None:
    assert _planned_rules(pipeline_run) == set()


def _planned_after_pulloff_edit(workdir: Path, added: str, *targets: str) -> set[str]:
    """Rules a dry run of ``targets`` plans after ``added`` is appended to data/pulloff.csv (restored afterwards)."""
    pulloff = workdir / "data/pulloff.csv"
    original = pulloff.read_text()
    try:
        pulloff.write_text(original + added)
        return _planned_rules(workdir, *targets)
    finally:
        pulloff.write_text(original)


@pytest.mark.pipeline
def test_data_edit_reruns_fit_figures_and_report_only(pipeline_run: Path) -> None:
    planned = _planned_after_pulloff_edit(pipeline_run, "# an edit by the user\n")
    assert planned == DATA_RULES, planned ^ DATA_RULES


@pytest.mark.pipeline
def test_measured_rows_add_the_simulation_at_the_fit_and_keep_the_published_one(pipeline_run: Path) -> None:
    planned = _planned_after_pulloff_edit(pipeline_run, "200,60,700,my lab\n")
    assert planned == DATA_RULES | FITTED_SIMULATION_RULES, planned ^ (DATA_RULES | FITTED_SIMULATION_RULES)


def test_data_edit_leaves_the_validation_at_the_published_parameters(pipeline_results: Path, tmp_path: Path) -> None:
    """After `all validation`, measured rows reach the validation pages only through the rule timings that the
    benchmarks page lists (the fit's, Figs. 4 and 7's): no published simulation, check or identifiability fit reruns.

    The edit is made in a copy of the finished repository (times kept): the build is shared by the other tests."""
    if not (pipeline_results.parent / "Snakefile").exists():
        pytest.skip("VIBROADHESION_RESULTS names finished results without their repository")
    work = shutil.copytree(pipeline_results.parent, tmp_path / "repository", symlinks=True)
    planned = _planned_after_pulloff_edit(work, "200,60,700,my lab\n", "all", "validation")
    expected = DATA_RULES | FITTED_SIMULATION_RULES | {"report_validation_index", "report_site", "validation"}
    assert planned == expected, planned ^ expected


def _snapshot(results: Path) -> dict[str, tuple[bytes, int]]:
    """Every file under ``results`` with its bytes and its modification time (ns)."""
    return {str(p.relative_to(results)): (p.read_bytes(), p.stat().st_mtime_ns) for p in sorted(results.rglob("*"))
            if p.is_file()}


@pytest.mark.pipeline
@pytest.mark.parametrize("bad_row,column", [("200,40,0.165,lab", "pulloff_mN"), ("200,abc,120.0,lab", "h1_um")],
                         ids=["newtons-for-millinewtons", "not-a-number"])
def test_rejected_edit_changes_nothing_and_restoring_it_reruns_nothing(pipeline_run: Path, bad_row: str,
                                                                        column: str) -> None:
    """A rejected edit stops Snakemake before it plans a job (one line naming file, row and column): results/ keeps
    every byte and every modification time, and putting the file back plans nothing."""
    pulloff = pipeline_run / "data/pulloff.csv"
    original = pulloff.read_text()
    before = _snapshot(pipeline_run / "results")
    try:
        pulloff.write_text(original + bad_row + "\n")
        out = _snakemake(pipeline_run)
    finally:
        pulloff.write_text(original)
    assert out.returncode != 0
    lines = [ln for ln in (out.stdout + out.stderr).splitlines() if "pulloff.csv, row" in ln]
    assert len(lines) == 1 and f"column {column}" in lines[0], out.stderr[-3000:]
    assert _snapshot(pipeline_run / "results") == before
    assert _planned_rules(pipeline_run) == set()


@pytest.mark.pipeline
def test_a_run_stopped_by_a_failed_page_marks_it_on_the_index_until_a_run_rebuilds_it(pipeline_run: Path,
                                                                                      tmp_path: Path) -> None:
    """A report job that fails loses its pages (Snakemake removes a failed job's outputs): the index, which another
    job wrote, marks them out of date instead of linking them as if the report were one state (Snakefile onerror);
    the run that rebuilds them removes the marks (onsuccess)."""
    work = tmp_path / "work"
    shutil.copytree(pipeline_run, work, symlinks=True)  # copy2: modification times kept, so the copy is up to date
    notebook = work / "notebooks/fig8.ipynb"
    original = notebook.read_text()
    broken = nbformat.reads(original, as_version=4)
    broken.cells.append(nbformat.v4.new_code_cell("raise RuntimeError('a page that fails')"))
    notebook.write_text(nbformat.writes(broken))
    assert _snakemake(work).returncode != 0
    index = (work / "results/report/index.html").read_text()
    items = re.findall(r"<li>(.*?)</li>", index)
    marked = {stem for stem, title in PAGES for item in items if title in item and "(not built)" in item}
    assert marked == set(REPORT_JOBS["report_pages"][1]), marked
    assert not any(f'href="{stem}.html"' in index for stem in marked)  # no link to a page that is not there
    notebook.write_text(original)
    assert _snakemake(work).returncode == 0
    assert "out of date" not in (work / "results/report/index.html").read_text().lower()


@pytest.mark.pipeline
def test_the_worst_degenerate_data_set_runs_to_the_end_with_every_page_and_says_what_it_lacks(
        pipeline_run: Path, tmp_path: Path) -> None:
    """The five plausible rows of issue 26 (tests/pipeline/test_degenerate_data.py has the other data sets): their
    full-model fit ended on the lower bound of w0, where the virtual pull-off found no pull-off at any test condition
    (it walked 400 steps a family, over 20 minutes) and the index job failed on the missing simulated column. Now the
    run ends with exit 0, every page of the default target rebuilt, each family within its step budget, and where a
    family found no pull-off the pages say so."""
    work = tmp_path / "work"
    shutil.copytree(pipeline_run, work, symlinks=True)  # copy2: modification times kept, so the copy is up to date
    pulloff = work / "data/pulloff.csv"
    pulloff.write_text(pulloff.read_text() + PLAUSIBLE_FIVE)
    out = _snakemake(work)
    assert out.returncode == 0, f"snakemake failed:\n{out.stdout[-3000:]}\n{out.stderr[-5000:]}"
    report = work / "results/report"
    for page in ("index", *(stem for stem, _ in PAGES)):
        assert (report / f"{page}.html").stat().st_size > 0, page
    for page in ("index", "fig4", "fig7", "fit"):  # what shows the rows: rebuilt after the edit
        assert (report / f"{page}.html").stat().st_mtime_ns > pulloff.stat().st_mtime_ns, page
    assert "(not built)" not in (report / "index.html").read_text() and "out of date" not in (
        report / "index.html").read_text().lower()
    virtual = pd.read_csv(work / "results/simulation/fitted/virtual_pulloff_rigid.csv")
    simulated = virtual[virtual["model"] == "simulation"]
    assert len(simulated) == 15 and (simulated["steady_states"] <= FAMILY_BUDGET + 40).all()
    assert set(simulated["status"]) <= {"pulloff", "budget_exceeded", "contact_loss_before_extremum",
                                        "no_steady_state_before_extremum"}
    if not (simulated["status"] == "pulloff").any():
        assert "<strong>No SIMULATED pull-off (rigid fixation)</strong>" in (report / "index.html").read_text()
        assert "No SIMULATED pull-off (rigid fixation)" in (report / "fig4.html").read_text()


@pytest.mark.pipeline
def test_code_edit_reruns_the_rules_that_import_it(pipeline_run: Path) -> None:
    planned = _planned_after_edit(pipeline_run, "src/vibroadhesion/models/stiffness.py")
    assert planned == {"fig3_fig6_fig8_data", "plot_steady_figures", "report_pages", "all"}


@pytest.mark.pipeline
def test_validation_target_adds_only_the_checks_against_the_simulation(pipeline_run: Path) -> None:
    planned = _planned_rules(pipeline_run, "validation")
    assert planned == VALIDATION_RULES, planned ^ VALIDATION_RULES


@pytest.mark.pipeline
def test_bad_input_stops_with_one_line_and_leaves_no_outputs(tmp_path: Path) -> None:
    work = _copy_repo(tmp_path)
    with open(work / "data/pulloff.csv", "a") as fh:
        fh.write("200,abc,120.0,my lab\n")
    out = _snakemake(work, "results/fig4/fig4.csv")
    assert out.returncode != 0
    lines = [ln for ln in (out.stdout + out.stderr).splitlines() if "pulloff.csv, row" in ln]
    assert lines and "column h1_um" in lines[0], out.stderr[-3000:]
    produced = [p for p in (work / "results").rglob("*") if p.is_file() and "logs" not in p.parts]
    assert produced == [], produced


def test_every_notebook_has_exactly_one_parameters_cell() -> None:
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        nb = nbformat.read(path, as_version=4)
        tagged = [c for c in nb.cells if "parameters" in c.metadata.get("tags", [])]
        assert len(tagged) == 1, path.name


def test_figure_artefacts_are_byte_identical_when_rebuilt(tmp_path: Path) -> None:
    params = GentSchultzParameters(W0, N_PUBLISHED, V0)
    geometry = {"radius": RADIUS, "reduced_modulus": REDUCED_MODULUS}
    measured = pd.DataFrame({"frequency_hz": [200.0], "h1_um": [40.0], "pulloff_mN": [250.0], "source": ["simulated"]})
    digests = []
    for k in range(2):
        table = fig4_table(params, [200.0, 400.0], np.linspace(0, 120, 13), **geometry)
        write_csv(table, tmp_path / f"t{k}.csv")
        save_figure(plot_fig4(table, measured, 57.27), tmp_path / f"f{k}.pdf", tmp_path / f"f{k}.png")
        digests.append([(tmp_path / f"{s}{k}.{e}").read_bytes() for s, e in (("t", "csv"), ("f", "pdf"), ("f", "png"))])
    assert digests[0] == digests[1]


# --- Code dependencies: the import closure of each rule's step, against an independent record -----

# Run in a fresh interpreter: import the package modules named on the command line, then, until
# nothing new loads, every module named by an IMPORT_NAME instruction in the bytecode of a function
# (or method) of a loaded package module, and the modules of the registry's functions a loaded module
# resolves (its LEVEL_FUNCTIONS, imported by name at run time); print the files of the package modules
# Python loaded.
_REFERENCE = r"""
import dis, importlib, sys, types

def loaded():
    return {n: m for n, m in list(sys.modules.items()) if n.split(".")[0] == "vibroadhesion"}

def functions(module):
    for obj in vars(module).values():
        members = vars(obj).values() if isinstance(obj, type) and obj.__module__ == module.__name__ else [obj]
        for f in members:
            f = getattr(f, "__func__", getattr(f, "fget", f))
            if isinstance(f, types.FunctionType) and f.__module__ == module.__name__:
                yield f.__code__

def nested(code):
    yield code
    for const in code.co_consts:
        if isinstance(const, types.CodeType):
            yield from nested(const)

def imports(code):
    instructions = list(dis.get_instructions(code))
    for k, ins in enumerate(instructions):
        if ins.opname == "IMPORT_NAME" and ins.argval.split(".")[0] == "vibroadhesion":
            yield ins.argval, instructions[k - 1].argval or ()

def load(name):
    try:
        importlib.import_module(name)
    except ModuleNotFoundError:  # ``from a import b`` with b a name in module a, not a module
        pass

for name in sys.argv[1:]:
    load(name)
done = set()
while len(done) < len(loaded()):
    for name, module in loaded().items():
        if name in done:
            continue
        done.add(name)
        for role, function in getattr(module, "LEVEL_FUNCTIONS", ()):  # the registry's functions it resolves
            for level_module in importlib.import_module("vibroadhesion.core.levels").modules(role, function):
                load(level_module)
        for code in (c for top in functions(module) for c in nested(top)):
            for target, fromlist in imports(code):
                load(target)
                for item in fromlist:
                    load(f"{target}.{item}")
print("\n".join(sorted(m.__file__ for m in loaded().values())))
"""


def _named_modules(path: Path) -> list[str]:
    """Modules of the package a script or notebook names in its import lines (read as text, no ast)."""
    text = path.read_text()
    if path.suffix == ".ipynb":
        text = "\n".join("".join(c["source"]) for c in json.loads(text)["cells"] if c["cell_type"] == "code")
    names = []
    for line in text.splitlines():
        m = re.match(r"\s*(?:from\s+(vibroadhesion[\w.]*)\s+import\s+([\w, ]+)|import\s+(vibroadhesion[\w.]*))", line)
        if m and m.group(1):
            names += [m.group(1)] + [f"{m.group(1)}.{n.strip()}" for n in m.group(2).split(",")]
        elif m:
            names.append(m.group(3))
    return names


@functools.cache
def _reference_closure(path: Path) -> frozenset[str]:
    """Package files (relative to the repository) that running ``path`` loads, by the record above."""
    out = subprocess.run([sys.executable, "-c", _REFERENCE, *_named_modules(path)], capture_output=True, text=True,
                         check=True, cwd=ROOT)
    # one path per line: a checkout under a path with spaces must not split one
    return frozenset(Path(f).resolve().relative_to(ROOT).as_posix() for f in out.stdout.splitlines())


_SOURCES = sorted((ROOT / "workflow/scripts").glob("*.py")) + sorted((ROOT / "notebooks").glob("*.ipynb"))


@pytest.mark.parametrize("source", _SOURCES, ids=lambda p: p.name)
def test_import_closure_equals_the_modules_python_loads(source: Path) -> None:
    closure = set(import_closure([source.relative_to(ROOT)], ROOT)) - {source.relative_to(ROOT).as_posix()}
    reference = _reference_closure(source)
    assert closure == reference, (closure - reference, reference - closure)


def _adapter_closures() -> dict[str, set[str]]:
    """rule -> package files its adapter loads (reference); a report rule's include those of its pages' notebooks."""
    closures = {p.stem: set(_reference_closure(p)) for p in (ROOT / "workflow/scripts").glob("*.py")}
    report = closures.pop("report")
    for rule, (_, pages) in REPORT_JOBS.items():
        notebooks = (_reference_closure(ROOT / f"notebooks/{page}.ipynb") for page in pages)
        closures[rule] = report.union(*notebooks)
    plots = closures.pop("plot_figures")
    closures |= {"plot_pulloff_figures": plots, "plot_steady_figures": plots}
    return closures


def _downstream(workdir: Path, rules: set[str]) -> set[str]:
    """``rules`` and every rule that consumes their outputs, directly or not (Snakemake's rule graph)."""
    out = _snakemake(workdir, "--rulegraph", "--forceall")
    assert out.returncode == 0, out.stderr
    names = dict(re.findall(r"^\s*(\d+)\[label = \"(\w+)\"", out.stdout, re.MULTILINE))
    edges = re.findall(r"^\s*(\d+) -> (\d+)", out.stdout, re.MULTILINE)
    found, todo = set(rules), list(rules)
    while todo:
        rule = todo.pop()
        for a, b in edges:
            if names[a] == rule and names[b] not in found:
                found.add(names[b])
                todo.append(names[b])
    return found


@pytest.mark.pipeline
@pytest.mark.parametrize("module", ["src/vibroadhesion/core/jkr.py", "src/vibroadhesion/models/refined.py",
                                    "src/vibroadhesion/pipeline/figures.py", "src/vibroadhesion/pipeline/data.py"])
def test_editing_a_module_reruns_exactly_the_rules_whose_step_imports_it(pipeline_run: Path, module: str) -> None:
    """Planned: the rules whose adapter loads ``module`` (by the independent record) and the rules downstream
    of them, nothing else. (A dry run names one reason per job: a job downstream of a rerun says so even
    when it imports the module too, so the planned set, not the reasons, is compared.)
    """
    default_rules = _planned_rules(pipeline_run, "--forceall")
    importers = {rule for rule, files in _adapter_closures().items() if module in files and rule in default_rules}
    assert importers, f"no rule of the default target imports {module}"
    planned = _planned_after_edit(pipeline_run, module)
    expected = _downstream(pipeline_run, importers)
    assert importers <= planned and planned == expected, planned ^ expected


# --- Paths with spaces and the cost of a DAG build ---------------------------------------------------


@pytest.mark.pipeline
def test_rules_run_with_the_project_under_a_path_with_spaces(tmp_path: Path) -> None:
    """The project under a path with spaces builds; an interpreter under one is refused before any job, in one line
    naming the way round it (Snakemake runs a `script:` rule's interpreter unquoted, snakemake/snakemake#2645)."""
    (tmp_path / "a project with spaces").mkdir()
    work = _copy_repo(tmp_path / "a project with spaces")
    targets = ["results/fit/gent_schultz.json", "results/report/fig3.html"]
    env = {**os.environ, "PATH": os.defpath}
    (work / "the venv").symlink_to(Path(sys.prefix), target_is_directory=True)
    refused = subprocess.run([str(work / "the venv" / "bin" / "python"), "-m", "snakemake", "-c2", *targets], cwd=work,
                             capture_output=True, text=True, timeout=900, env=env)
    assert refused.returncode != 0
    lines = [ln for ln in (refused.stdout + refused.stderr).splitlines() if ln.startswith("error:")]
    assert len(lines) == 1 and "the venv" in lines[0] and "symbolic link" in lines[0], refused.stderr[-4000:]
    assert not (work / "results").exists()
    (tmp_path / "venv").symlink_to(Path(sys.prefix), target_is_directory=True)
    out = subprocess.run([str(tmp_path / "venv" / "bin" / "python"), "-m", "snakemake", "-c2", *targets], cwd=work,
                         capture_output=True, text=True, timeout=900, env=env)
    assert out.returncode == 0, out.stderr[-4000:]
    for artefact in ("fit/gent_schultz.json", "fig3/fig3.csv", "fig3/fig3.png", "report/fig3.html"):
        assert (work / "results" / artefact).stat().st_size > 0, artefact


def test_building_the_dag_imports_no_numerics() -> None:
    """The modules the Snakefile imports (pages, import closure, the input checks) load none of the numerics stack."""
    code = ("import sys, vibroadhesion.pipeline.imports, vibroadhesion.pipeline.pages, vibroadhesion.pipeline.data; "
            "print(' '.join(m for m in ('numpy', 'pandas', 'scipy', 'matplotlib') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


@pytest.mark.parametrize("step", sorted(p.stem for p in (ROOT / "src/vibroadhesion/pipeline/steps").glob("*.py")))
def test_only_plot_steps_import_matplotlib(step: str) -> None:
    code = f"import sys, vibroadhesion.pipeline.steps.{step}; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == str(step == "plots")
