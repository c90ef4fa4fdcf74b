"""Rule ingest_pulloff: validate data/pulloff.csv against the ingested rig, write its canonical copy."""

from vibroadhesion.pipeline.data import ingest_pulloff
from vibroadhesion.pipeline.steps import logged

with logged(snakemake.log[0], snakemake.rule):
    print(ingest_pulloff(snakemake.input.setup, snakemake.input.pulloff, snakemake.output[0]))
