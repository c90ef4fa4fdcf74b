"""Rule virtual_pulloff: vibroadhesion.pipeline.steps.simulation.virtual_pulloff_part."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.simulation import virtual_pulloff_part

wc = snakemake.wildcards
with logged(snakemake.log[0], snakemake.rule):
    virtual_pulloff_part(snakemake.input.setup, snakemake.input.get("fit"), snakemake.output[0], wc.fixation,
                         [float(f) for f in wc.frequency.split("_")])
