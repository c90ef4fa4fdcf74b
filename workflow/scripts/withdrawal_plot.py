"""Rule withdrawal_plot: vibroadhesion.pipeline.steps.plots.withdrawal_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import withdrawal_plot

out = snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    withdrawal_plot(snakemake.input.csv, out.pdf, out.png)
