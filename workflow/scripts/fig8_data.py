"""Rule fig8_data: vibroadhesion.pipeline.steps.fig8.fig8_data."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.fig8 import fig8_data

with logged(snakemake.log[0], snakemake.rule):
    fig8_data(snakemake.input.setup, snakemake.input.get("fit"), snakemake.input.fig6, snakemake.output[0])
