"""Rule rigs_gather: vibroadhesion.pipeline.steps.rigs.rigs_gather."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.rigs import rigs_gather

with logged(snakemake.log[0], snakemake.rule):
    rigs_gather(snakemake.input.parts, snakemake.output.csv, snakemake.output.summary)
