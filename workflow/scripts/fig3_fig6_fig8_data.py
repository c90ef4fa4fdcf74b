"""Rule fig3_fig6_fig8_data: vibroadhesion.pipeline.steps.fig3_fig6_fig8.fig3_fig6_fig8_data."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.fig3_fig6_fig8 import fig3_fig6_fig8_data

p = snakemake.params
with logged(snakemake.log[0], snakemake.rule):
    fig3_fig6_fig8_data(snakemake.input.setup, snakemake.input.get("fit"), dict(snakemake.output.items()), p.fig3,
                        p.fig6)
