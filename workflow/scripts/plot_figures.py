"""Rules plot_pulloff_figures, plot_steady_figures: vibroadhesion.pipeline.steps.plots.all_figures."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.plots import all_figures

with logged(snakemake.log[0], snakemake.rule):
    all_figures(dict(snakemake.input.items()), dict(snakemake.output.items()), snakemake.params.panel_n)
