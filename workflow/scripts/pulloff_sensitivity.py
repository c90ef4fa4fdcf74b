"""Rule pulloff_sensitivity: vibroadhesion.pipeline.steps.identifiability.sensitivity_part."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.identifiability import sensitivity_part

frequencies = [float(f) for f in snakemake.wildcards.frequency.split("_")]
with logged(snakemake.log[0], snakemake.rule):
    sensitivity_part(snakemake.input.setup, snakemake.input.get("fit"), snakemake.output[0], frequencies,
                     snakemake.params.amplitudes)
