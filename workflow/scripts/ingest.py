"""Rule ingest: validate data/setup.yaml and data/pulloff.csv, write their canonical copies."""

from vibroadhesion.pipeline.data import ingest
from vibroadhesion.pipeline.steps import logged

with logged(snakemake.log[0], snakemake.rule):
    print(ingest(snakemake.input.setup, snakemake.input.pulloff, snakemake.output.setup, snakemake.output.pulloff))
