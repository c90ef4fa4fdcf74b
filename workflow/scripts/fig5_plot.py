"""Rule fig5_plot: vibroadhesion.pipeline.steps.plots.fig5_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import fig5_plot

i, out = snakemake.input, snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    fig5_plot(i.setup, i.csv, i.markers, out.pdf, out.png)
