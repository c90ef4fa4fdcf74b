"""Rule validation_compliant_plot: vibroadhesion.pipeline.steps.plots.compliant_sweep_plot."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import compliant_sweep_plot

out = snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    compliant_sweep_plot(snakemake.input.csv, snakemake.input.curve, out.pdf, out.png)
