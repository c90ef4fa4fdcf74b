# Vibroadhesion pipeline: `snakemake -c2` regenerates the figures, the fit and their report pages;
# `snakemake -c2 validation` adds the checks against the direct simulation (slower; see README).
# Rules live in workflow/rules/*.smk; settings in workflow/config.yaml (schema-validated).
from snakemake.utils import min_version, validate

min_version("9.0")


configfile: "workflow/config.yaml"


validate(config, "workflow/schemas/config.schema.yaml")


include: "workflow/rules/common.smk"
include: "workflow/rules/ingest.smk"
include: "workflow/rules/fit.smk"
include: "workflow/rules/figures.smk"
include: "workflow/rules/benchmarks.smk"
include: "workflow/rules/validation.smk"
include: "workflow/rules/identifiability.smk"
include: "workflow/rules/report.smk"


rule all:
    default_target: True
    input:
        "results/fit/gent_schultz.json",
        expand("results/{fig}/{fig}.{ext}", fig=FIGURES, ext=["csv", "pdf", "png"]),
        "results/report/index.html",


rule validation:
    """Every model level against the direct simulation, the compliant resonance sweep, the
    identifiability of the Gent-Schultz parameters from the virtual pull-off experiment, the
    speed-against-error benchmarks, and their report pages."""
    input:
        "results/validation/rigid_error_maps.png",
        "results/validation/compliant_sweep.png",
        "results/validation/virtual_pulloff.csv",
        "results/validation/identifiability/fits.csv",
        "results/validation/identifiability/information.csv",
        "results/benchmarks/speed_vs_error.csv",
        "results/report/validation_index.html",
