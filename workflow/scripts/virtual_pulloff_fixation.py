"""Rule virtual_pulloff_fixation: vibroadhesion.pipeline.steps.gather.concatenate."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.gather import concatenate

with logged(snakemake.log[0], snakemake.rule):
    concatenate(snakemake.input.parts, snakemake.output[0])
