"""Rule fig5_data: vibroadhesion.pipeline.steps.fig5.fig5_data."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.fig5 import fig5_data

out, p = snakemake.output, snakemake.params
with logged(snakemake.log[0], snakemake.rule):
    fig5_data(snakemake.input.setup, snakemake.input.get("fit"), out.csv, out.markers, out.counts, p.lo, p.hi, p.points)
