"""Rule identifiability_design: vibroadhesion.pipeline.steps.design.experiment_design."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.design import experiment_design

i, out, p = snakemake.input, snakemake.output, snakemake.params
with logged(snakemake.log[0], snakemake.rule):
    experiment_design(i.virtual, i.sensitivity, p.noise, p.added, out.design, out.candidates)
