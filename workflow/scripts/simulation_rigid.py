"""Rule simulation_rigid: vibroadhesion.pipeline.steps.simulation.rigid_part."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.simulation import rigid_part

p = snakemake.params
with logged(snakemake.log[0], snakemake.rule):
    rigid_part(snakemake.input.setup, snakemake.input.get("fit"), snakemake.output[0],
               [float(h) for h in snakemake.wildcards.h1.split("_")], p.lo, p.hi)
