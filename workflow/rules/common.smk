# Helpers shared by the rules: the rig's test conditions (read at DAG time) and each rule's code.
import sys

import yaml

from vibroadhesion.pipeline.imports import import_closure
from vibroadhesion.pipeline.pages import findings_inputs, findings_outdated, refresh_indexes

# Each step is workflow/scripts/<name>.py, run by `script:` with the interpreter that runs Snakemake
# (sys.executable: the project's .venv, activated or not); the shell commands use the same one.
PYTHON = sys.executable

FIGURES = ["fig3", "fig4", "fig5", "fig6", "fig7", "fig8"]


def _rig_values(group, entry):
    """A list of data/setup.yaml (validated before any job is planned) as wildcard values, 200.0 -> "200"."""
    with open(config["data"]["setup"], encoding="utf-8") as stream:
        return [f"{float(v):g}" for v in yaml.safe_load(stream)[group][entry]["value"]]


# The rig's test frequencies (Hz) and base amplitudes (um): one job per value where a rule splits.
FREQUENCIES = _rig_values("test_conditions", "frequencies")
AMPLITUDES = _rig_values("test_conditions", "amplitudes")


def job_chunks(values, per_job):
    """``values`` split into consecutive jobs of ``per_job`` each, as wildcard values: ["200", "300"] -> "200_300"."""
    return ["_".join(values[i : i + per_job]) for i in range(0, len(values), per_job)]


# The direct simulation split into jobs (workflow/config.yaml, simulation_jobs): the rig's amplitudes of the rigid
# grid, the test frequencies of the virtual pull-off.
AMPLITUDE_JOBS = job_chunks(AMPLITUDES, config["simulation_jobs"]["amplitudes_per_job"])
FREQUENCY_JOBS = job_chunks(FREQUENCIES, config["simulation_jobs"]["frequencies_per_job"])


def figure_tables(figs):
    """The CSV tables of ``figs`` (results/<fig>/<fig>.csv), named by figure, in Snakemake's report (the
    figures' compute rules)."""
    return {
        fig: report(f"results/{fig}/{fig}.csv", caption="../report/table.rst", category="Figures", subcategory="Tables")
        for fig in figs
    }


def plot_inputs(figs):
    """The tables of ``figs`` and what their plots read besides (FIGURE_TABLE and PLOT_EXTRAS of figures.smk; Fig. 7
    reads Fig. 4's table too)."""
    tables = {fig: FIGURE_TABLE[fig] for fig in figs}
    return {**tables, **{k: v for fig in figs for k, v in PLOT_EXTRAS[fig].items()}}


def code(*sources):
    """The code a job runs, as inputs: the adapter scripts (workflow/scripts/<name>.py) or other scripts and
    notebooks named, every package module they import (vibroadhesion.pipeline.imports), and the lock.
    Editing any of them reruns the job; a module its step does not import cannot."""
    paths = [s if s.endswith((".py", ".ipynb")) else f"workflow/scripts/{s}.py" for s in sources]
    return import_closure(paths) + ["environment.lock"]


def parameter_inputs(wildcards):
    """The inputs that fix the parameter set ``wildcards.parameters`` (PUBLISHED or FITTED of fit.smk): an input
    function of rule virtual_pulloff."""
    return FITTED if wildcards.parameters == "fitted" else PUBLISHED


def refresh_report():
    """The Snakefile's onsuccess and onerror, on the indexes of the run's targets only (report.smk ASKED_REPORT_JOBS):
    their findings read again from the artefacts the run left, where one of them is newer than the index or the build
    changed (pipeline.pages.findings_outdated, standard library only; pipeline.front_page.refresh_findings imports
    pandas and the refined model, about a second, only then), then the pages missing or older than an artefact they
    show marked on them (pipeline.pages.refresh_indexes) and printed."""
    asked = [REPORT_JOBS[job] for job in sorted(ASKED_REPORT_JOBS)]
    indexes = {
        f"results/report/{index}.html": {stem: page_parameters(stem) for stem in pages}
        for index, pages in asked
        if index
    }
    outdated = {index: pages for index, pages in indexes.items() if findings_outdated(index, findings_inputs(pages))}
    if outdated:
        from vibroadhesion.pipeline.front_page import refresh_findings

        refresh_findings(outdated)
    pages = {page: list(inputs.values()) for page, inputs in PAGE_INPUTS.items()}
    stale = refresh_indexes(pages, "results/report", [index for index, _ in asked if index])
    if stale:
        print(f"report: out of date, marked on the index: {', '.join(stale)}", file=sys.stderr)
