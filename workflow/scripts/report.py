"""Rules report_index, report_pages, report_validation_index: vibroadhesion.pipeline.steps.report.render."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.report import render

out = snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    render(snakemake.params.pages, out.notebooks, out.pages, out.index)
