"""Rule fit_coverage: vibroadhesion.pipeline.steps.identifiability.fit_coverage."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.identifiability import fit_coverage

with logged(snakemake.log[0], snakemake.rule):
    fit_coverage(snakemake.input.setup, snakemake.output.fits, snakemake.output.summary, snakemake.params.level,
                 snakemake.params.relative_scatter, snakemake.params.seeds, snakemake.params.confidence)
