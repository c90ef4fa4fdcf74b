"""Rule fig4_plot: vibroadhesion.pipeline.steps.plots.fig4_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import fig4_plot

i, out = snakemake.input, snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    fig4_plot(i.setup, i.fit, i.pulloff, i.virtual, i.csv, out.pdf, out.png)
