"""Rule fig6_data: vibroadhesion.pipeline.steps.rigid.fig6_data."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.rigid import fig6_data

p = snakemake.params
with logged(snakemake.log[0], snakemake.rule):
    fig6_data(snakemake.input.setup, snakemake.input.get("fit"), snakemake.output[0], p.lo, p.hi, p.points)
