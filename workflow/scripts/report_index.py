"""Rule report_index: vibroadhesion.pipeline.pages.write_index."""

from vibroadhesion.pipeline.pages import write_index
from vibroadhesion.pipeline.steps import logged

with logged(snakemake.log[0], snakemake.rule):
    write_index(snakemake.output[0])
