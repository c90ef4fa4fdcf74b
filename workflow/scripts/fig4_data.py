"""Rule fig4_data: vibroadhesion.pipeline.steps.fig4.fig4_data."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.fig4 import fig4_data

with logged(snakemake.log[0], snakemake.rule):
    fig4_data(snakemake.input.setup, snakemake.input.fit, snakemake.output[0], snakemake.params.h1_max,
              snakemake.params.points)
