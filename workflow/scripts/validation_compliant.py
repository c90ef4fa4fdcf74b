"""Rule validation_compliant: vibroadhesion.pipeline.steps.validation.compliant_sweep."""

from vibroadhesion.pipeline.steps import logged
from vibroadhesion.pipeline.steps.validation import compliant_sweep

sweep, out = snakemake.params.sweep, snakemake.output
with logged(snakemake.log[0], snakemake.rule):
    compliant_sweep(snakemake.input.setup, snakemake.input.get("fit"), out.csv, out.curve, sweep["omega_bar_min"],
                    sweep["omega_bar_max"], sweep["points"], tuple(snakemake.params.curve_range))
