"""Rule fig3_data: vibroadhesion.pipeline.steps.fig3.fig3_data."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.fig3 import fig3_data

p = snakemake.params
with logged(snakemake.log[0], snakemake.rule):
    fig3_data(snakemake.input.setup, snakemake.input.get("fit"), snakemake.output[0], p.panel_n, p.lo, p.hi, p.points)
