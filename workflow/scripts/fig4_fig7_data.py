"""Rule fig4_fig7_data: vibroadhesion.pipeline.steps.fig4_fig7.fig4_fig7_data."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.fig4_fig7 import fig4_fig7_data

p = snakemake.params
with logged(snakemake.log[0], snakemake.rule):
    fig4_fig7_data(snakemake.input.setup, snakemake.input.fit, dict(snakemake.output.items()), p.fig4, p.fig7)
