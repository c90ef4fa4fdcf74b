"""Rule rigs_plot: vibroadhesion.pipeline.steps.plots.rigs_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import rigs_plot

with logged(snakemake.log[0], snakemake.rule):
    rigs_plot(snakemake.input.csv, snakemake.output.pdf, snakemake.output.png)
