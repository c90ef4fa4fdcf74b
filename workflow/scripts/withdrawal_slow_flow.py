"""Rule withdrawal_slow_flow: vibroadhesion.pipeline.steps.withdrawal.withdrawal_slow_flow."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.withdrawal import withdrawal_slow_flow

with logged(snakemake.log[0], snakemake.rule):
    withdrawal_slow_flow(snakemake.input.setup, snakemake.output[0], snakemake.params.speed_ratios)
