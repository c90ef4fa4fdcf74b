"""Rule rigs_part: vibroadhesion.pipeline.steps.rigs.rigs_part."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.rigs import rigs_part

with logged(snakemake.log[0], snakemake.rule):
    rigs_part(snakemake.input.setup, snakemake.input.virtual, snakemake.output[0], snakemake.wildcards.case)
