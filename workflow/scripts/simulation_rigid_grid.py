"""Rule simulation_rigid_grid: vibroadhesion.pipeline.steps.gather.rigid_grid."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.gather import rigid_grid

with logged(snakemake.log[0], snakemake.rule):
    rigid_grid(snakemake.input.parts, snakemake.output[0])
