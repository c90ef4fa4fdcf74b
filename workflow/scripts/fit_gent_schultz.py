"""Rule fit_gent_schultz: vibroadhesion.pipeline.steps.fit.fit."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.fit import fit

with logged(snakemake.log[0], snakemake.rule):
    fit(snakemake.input.setup, snakemake.input.pulloff, snakemake.output[0], snakemake.params.figures_use,
        snakemake.params.judgement)
