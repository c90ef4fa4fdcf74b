"""Rule report_site: vibroadhesion.pipeline.steps.site.report_site."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.site import report_site

with logged(snakemake.log[0], snakemake.rule):
    report_site([*snakemake.input.pages, *snakemake.input.figures], snakemake.output[0], snakemake.params.indexes)
