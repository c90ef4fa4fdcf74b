"""Rule pulloff_sensitivity: vibroadhesion.pipeline.steps.identifiability.sensitivity_run."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.identifiability import sensitivity_run

wc = snakemake.wildcards
with logged(snakemake.log[0], snakemake.rule):
    sensitivity_run(snakemake.input.setup, snakemake.input.get("fit"), snakemake.output[0], wc.parameter, wc.sign)
