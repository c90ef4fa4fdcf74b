# Vibroadhesion pipeline: `snakemake -c2` regenerates the figures, the fit and their report pages;
# `snakemake -c2 validation` adds the checks against the direct simulation (slower; see README).
# Rules live in workflow/rules/*.smk and run workflow/scripts/<rule>.py (Snakemake's `script:`), each
# a few lines calling one function of vibroadhesion.pipeline.steps; settings in workflow/config.yaml
# (schema-validated; grids and switches only: every physical value is in data/setup.yaml).
import sys

from snakemake.utils import min_version, validate

from vibroadhesion.core.levels import names
from vibroadhesion.pipeline.data import DataError, check_inputs

min_version("9.0")
# Snakemake runs a Python `script:` as `{py_exec} {fname:q}`, the interpreter unquoted (snakemake/snakemake#2645):
# under a path with whitespace every such rule would fail; refused here, before any job, with the way round it.
if any(c.isspace() for c in sys.executable):
    sys.exit(
        f"error: the Python interpreter's path has whitespace ({sys.executable}), which Snakemake's script: rules "
        "cannot run (snakemake/snakemake#2645): create the .venv under a path without any, or run "
        "`<link>/bin/python -m snakemake` through a symbolic link to the .venv whose path has none"
    )


configfile: "workflow/config.yaml"


report: "workflow/report/workflow.rst"


validate(config, "workflow/schemas/config.schema.yaml")
# Any fitted level of the registry (vibroadhesion.core.levels) may supply the figures' parameters.
if config["fit"]["figures_use"] not in names("fit"):
    sys.exit(
        f"workflow/config.yaml: fit.figures_use = {config['fit']['figures_use']!r} is not one of "
        f"{', '.join(names('fit'))}"
    )


# The user's inputs are checked before any job is planned: a rejected edit stops here with one line naming
# the file, row and column, and changes nothing in results/ (rules ingest_setup and ingest_pulloff write their
# canonical copies).
try:
    _, _, MEASURED = check_inputs(config["data"]["setup"], config["data"]["pulloff"])
except DataError as error:
    sys.exit(f"error: {error}")
# With no measured rows the fit is the published parameter set, and Figs. 4 and 7 overlay its simulation.
MEASURED_ROWS = len(MEASURED)


include: "workflow/rules/common.smk"
include: "workflow/rules/ingest.smk"
include: "workflow/rules/fit.smk"
include: "workflow/rules/simulation.smk"
include: "workflow/rules/figures.smk"
include: "workflow/rules/validation.smk"
include: "workflow/rules/withdrawal.smk"
include: "workflow/rules/rigs.smk"
include: "workflow/rules/identifiability.smk"
include: "workflow/rules/benchmarks.smk"
include: "workflow/rules/report.smk"
include: "workflow/rules/report_site.smk"


# Under a cluster executor (profiles/slurm) these run on the submit host, as the plot and report rules do
# (`localrule: True`): each reads or gathers small files in seconds and under 200 MB (peak RSS and wall time measured
# on a `snakemake -c2 all validation` run, listed in profiles/slurm/config.yaml), less than a job's start on a node.
localrules:
    ingest_setup,
    ingest_pulloff,
    simulation_rigid_grid,
    virtual_pulloff_fixation,
    virtual_pulloff_gather,
    validation_errors,
    validation_plot,
    validation_compliant_plot,
    identifiability,


rule all:
    default_target: True
    input:
        rules.fit_gent_schultz.output,
        expand("results/{fig}/{fig}.{ext}", fig=FIGURES, ext=["csv", "pdf", "png"]),
        rules.report_index.output.index,
        rules.report_pages.output.pages,


rule validation:
    """Every model level against the direct simulation, the compliant resonance sweep, the
    identifiability of the Gent-Schultz parameters from the virtual pull-off experiment, the
    speed-against-error benchmarks, their report pages, and the rendered report as one folder for Snakemake's
    report (`snakemake --report results/report.zip all validation`)."""
    input:
        rules.validation_plot.output.png,
        rules.validation_compliant_plot.output.png,
        rules.rigs_plot.output.png,
        rules.virtual_pulloff_gather.output,
        rules.withdrawal_plot.output.png,
        rules.withdrawal_gather.output.limits,
        rules.identifiability.output.fits,
        rules.identifiability.output.information,
        rules.identifiability_design.output.design,
        rules.fit_coverage.output.summary,
        rules.benchmark_speed_vs_error.output.csv,
        rules.report_validation_index.output.index,
        rules.report_site.output,


# After every run, finished or stopped by a failed job, the indexes mark the pages older than an artefact they
# show: the report never presents a mix of outputs of two runs as one state.
onsuccess:
    refresh_report()


onerror:
    refresh_report()
