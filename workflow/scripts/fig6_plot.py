"""Rule fig6_plot: vibroadhesion.pipeline.steps.plots.fig6_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import fig6_plot

i, out = snakemake.input, snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    fig6_plot(i.setup, i.fit, i.csv, i.grid, out.pdf, out.png)
