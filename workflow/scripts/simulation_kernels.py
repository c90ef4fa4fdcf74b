"""Rule simulation_kernels: vibroadhesion.pipeline.steps.kernels.compile_kernels."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.kernels import compile_kernels

with logged(snakemake.log[0], snakemake.rule):
    compile_kernels(snakemake.output[0])
