"""Rule withdrawal: vibroadhesion.pipeline.steps.withdrawal.withdrawal_part."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.withdrawal import withdrawal_part

wc = snakemake.wildcards
with logged(snakemake.log[0], snakemake.rule):
    withdrawal_part(snakemake.input.setup, snakemake.input.virtual_pulloff[0], snakemake.output[0], wc.fixation,
                    [float(f) for f in wc.frequency.split("_")], snakemake.params.speed_ratios,
                    snakemake.params.stop)
