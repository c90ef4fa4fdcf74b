"""Rule validation_errors: vibroadhesion.pipeline.steps.validation.rigid_errors."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.validation import rigid_errors

i, out = snakemake.input, snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    rigid_errors(i.setup, i.get("fit"), i.grid, out.errors, out.summary)
