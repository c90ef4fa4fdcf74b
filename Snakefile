# Vibroadhesion pipeline: `snakemake -c2` regenerates every artefact under results/.
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
        "results/validation/rigid_error_maps.png",
        "results/validation/compliant_sweep.png",
        "results/report/index.html",
