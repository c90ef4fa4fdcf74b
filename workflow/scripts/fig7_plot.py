"""Rule fig7_plot: vibroadhesion.pipeline.steps.plots.fig7_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import fig7_plot

i, out = snakemake.input, snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    fig7_plot(i.setup, i.fit, i.csv, i.fig4, i.virtual, out.pdf, out.png)
