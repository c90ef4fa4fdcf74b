"""Rule withdrawal_gather: vibroadhesion.pipeline.steps.withdrawal.withdrawal_gather."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.withdrawal import withdrawal_gather

with logged(snakemake.log[0], snakemake.rule):
    withdrawal_gather(snakemake.input.setup, snakemake.input.parts, snakemake.input.slow_flow, snakemake.output.csv,
                      snakemake.output.limits)
