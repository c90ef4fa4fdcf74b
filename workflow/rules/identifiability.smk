# Identifiability of the Gent-Schultz parameters from pull-off data, asked of the virtual
# (simulated) pull-off experiment whose true parameters are known. Part of the `validation`
# target. One job per perturbed simulation and per fitted model level.

SENSITIVITY_RUNS = [f"{p}_{s}" for p in ("w0", "n", "v0") for s in ("plus", "minus")]


rule pulloff_sensitivity:
    """Simulated pull-off (rigid fixation, every test frequency and amplitude) with one parameter scaled by exp(+-h)."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code(*NUMERICS, *SIMULATION, "progress", "exact_averaging", "frozen_radius", "compliant", "continuation", "virtual_pulloff",
                  "identifiability", "fitting", "data", "cli", "artefacts"),
    output:
        "results/validation/identifiability/sensitivity/{parameter}_{sign}.csv",
    wildcard_constraints:
        parameter="w0|n|v0",
        sign="plus|minus",
    params:
        frequencies=" ".join(str(f) for f in config["virtual_pulloff"]["frequencies_hz"]),
    log:
        "results/logs/pulloff_sensitivity_{parameter}_{sign}.log",
    benchmark:
        "results/benchmarks/rules/pulloff_sensitivity_{parameter}_{sign}.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli pulloff-sensitivity --setup {input.setup} --fit {input.fit} "
        "--parameter {wildcards.parameter} --sign {wildcards.sign} --frequencies-hz {params.frequencies} "
        "--out {output} 2>&1 | tee {log}"


rule identifiability_fit:
    """The pipeline's Gent-Schultz fit of one model level on the noise-free simulated pull-off rows."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        virtual="results/validation/virtual_pulloff_rigid.csv",
        code=code(*NUMERICS, "exact_averaging", "frozen_radius", "identifiability", "fitting", "data", "cli", "artefacts"),
    output:
        "results/validation/identifiability/fits/{model}.csv",
    wildcard_constraints:
        model="leading|refined|exact_averaging|exact_averaging_force_minimum",
    log:
        "results/logs/identifiability_fit_{model}.log",
    benchmark:
        "results/benchmarks/rules/identifiability_fit_{model}.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli identifiability-fit --setup {input.setup} --fit {input.fit} "
        "--virtual {input.virtual} --model {wildcards.model} --out {output} 2>&1 | tee {log}"


rule identifiability:
    """Sensitivity of the simulated pull-off, Cramer-Rao standard errors per design and noise, fits of every level."""
    input:
        virtual="results/validation/virtual_pulloff_rigid.csv",
        sensitivity=expand("results/validation/identifiability/sensitivity/{run}.csv", run=SENSITIVITY_RUNS),
        fits=expand("results/validation/identifiability/fits/{model}.csv",
                    model=["leading", "refined", "exact_averaging", "exact_averaging_force_minimum"]),
        code=code("identifiability", "fitting", "cli", "artefacts"),
    output:
        sensitivity="results/validation/identifiability/sensitivity.csv",
        information="results/validation/identifiability/information.csv",
        fits="results/validation/identifiability/fits.csv",
    params:
        noise=" ".join(str(s) for s in config["identifiability"]["relative_noise"]),
    log:
        "results/logs/identifiability.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli identifiability --virtual {input.virtual} "
        "--sensitivity-parts {input.sensitivity} --fits {input.fits} --noise {params.noise} "
        "--sensitivity-out {output.sensitivity} --information-out {output.information} --fits-out {output.fits} "
        "2>&1 | tee {log}"
