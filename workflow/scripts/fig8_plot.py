"""Rule fig8_plot: vibroadhesion.pipeline.steps.plots.fig8_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import fig8_plot

i, out = snakemake.input, snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    fig8_plot(i.setup, i.fit, i.csv, out.pdf, out.png)
