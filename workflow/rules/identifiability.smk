# Identifiability of the Gent-Schultz parameters from pull-off data, asked of the virtual
# (simulated) pull-off experiment whose true parameters are known. Part of the `validation`
# target. One job per perturbed simulation and per fitted model level.

from vibroadhesion.core.levels import names

SENSITIVITY_RUNS = [f"{p}_{s}" for p in ("w0", "n", "v0") for s in ("plus", "minus")]
# The fitted model levels, one job each, in the registry's order (the row order of fits.csv).
FITTED_LEVELS = names("fit")


rule pulloff_sensitivity:
    """Simulated pull-off (rigid fixation, every test frequency and amplitude) with one parameter scaled by exp(+-h)."""
    input:
        **PUBLISHED,
        kernels=rules.simulation_kernels.output[0],
        code=code("pulloff_sensitivity"),
    output:
        "results/validation/identifiability/sensitivity/{parameter}_{sign}.csv",
    log:
        "results/logs/pulloff_sensitivity_{parameter}_{sign}.log",
    benchmark:
        "results/benchmarks/rules/pulloff_sensitivity_{parameter}_{sign}.tsv"
    wildcard_constraints:
        parameter="w0|n|v0",
        sign="plus|minus",
    script:
        "../scripts/pulloff_sensitivity.py"


rule identifiability_fit:
    """The pipeline's Gent-Schultz fit of one model level on the noise-free simulated pull-off rows."""
    input:
        **PUBLISHED,
        virtual=VIRTUAL_RIGID,
        code=code("identifiability_fit"),
    output:
        "results/validation/identifiability/fits/{model}.csv",
    log:
        "results/logs/identifiability_fit_{model}.log",
    benchmark:
        "results/benchmarks/rules/identifiability_fit_{model}.tsv"
    wildcard_constraints:
        model="|".join(FITTED_LEVELS),
    script:
        "../scripts/identifiability_fit.py"


rule identifiability:
    """Sensitivity of the simulated pull-off, Cramer-Rao standard errors per design and noise, fits of every level."""
    input:
        virtual=VIRTUAL_RIGID,
        sensitivity=expand(
            rules.pulloff_sensitivity.output[0],
            zip,
            parameter=[r.split("_")[0] for r in SENSITIVITY_RUNS],
            sign=[r.split("_")[1] for r in SENSITIVITY_RUNS],
        ),
        fits=expand(rules.identifiability_fit.output[0], model=FITTED_LEVELS),
        code=code("identifiability"),
    output:
        sensitivity="results/validation/identifiability/sensitivity.csv",
        information="results/validation/identifiability/information.csv",
        fits="results/validation/identifiability/fits.csv",
    log:
        "results/logs/identifiability.log",
    params:
        noise=config["identifiability"]["relative_noise"],
    script:
        "../scripts/identifiability.py"
