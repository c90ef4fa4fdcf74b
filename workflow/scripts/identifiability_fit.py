"""Rule identifiability_fit: vibroadhesion.pipeline.steps.identifiability.fit_level."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.identifiability import fit_level

i = snakemake.input
with logged(snakemake.log[0], snakemake.rule):
    fit_level(i.setup, i.get("fit"), i.virtual, snakemake.wildcards.model, snakemake.output[0])
