"""Rule identifiability: vibroadhesion.pipeline.steps.identifiability.summary."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.identifiability import summary

i, out = snakemake.input, snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    summary(i.virtual, i.sensitivity, i.fits, snakemake.params.noise, out.sensitivity, out.information, out.fits)
