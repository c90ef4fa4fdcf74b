"""Rule ingest_setup: validate data/setup.yaml, write its canonical copy."""

from vibroadhesion.pipeline.data import ingest_setup
from vibroadhesion.pipeline.steps import logged

with logged(snakemake.log[0], snakemake.rule):
    print(ingest_setup(snakemake.input.setup, snakemake.output[0]))
