"""Rule report_page: vibroadhesion.pipeline.steps.report.page."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.report import page

out = snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    page(snakemake.input.notebook, out.notebook, out.html, snakemake.params.parameters)
