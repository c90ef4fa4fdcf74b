"""Rule fig3_plot: vibroadhesion.pipeline.steps.plots.fig3_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import fig3_plot

out = snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    fig3_plot(snakemake.input.fit, snakemake.input.csv, out.pdf, out.png, snakemake.params.panel_n)
