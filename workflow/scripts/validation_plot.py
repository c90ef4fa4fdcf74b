"""Rule validation_plot: vibroadhesion.pipeline.steps.plots.validation_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import validation_plot

i, out = snakemake.input, snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    validation_plot(i.setup, i.get("fit"), i.grid, i.errors, out.pdf, out.png)
