# Identifiability of the Gent-Schultz parameters from pull-off data, asked of the virtual
# (simulated) pull-off experiment whose true parameters are known, and which tests to add to the
# rig's (D-optimal design). Part of the `validation` target. One job per frequency of the
# sensitivities (the rig's test frequencies and the design's candidates) and per fitted model level.

from vibroadhesion.core.levels import names

# The fitted model levels, one job each, in the registry's order (the row order of fits.csv).
FITTED_LEVELS = names("fit")
DESIGN = config["identifiability"]["design"]
COVERAGE = config["identifiability"]["coverage"]
# The sensitivity jobs: the rig's test frequencies (the rows of sensitivity.csv), then the design's other candidate
# frequencies, frequencies_per_job in each (wildcard "200_300_400": the frequencies in Hz joined by "_").
_EXTRA = sorted({f"{float(f):g}" for f in DESIGN["frequencies_hz"]} - set(FREQUENCIES), key=float)
_PER_JOB = DESIGN["frequencies_per_job"]
RIG_SENSITIVITY_JOBS = job_chunks(FREQUENCIES, _PER_JOB)
SENSITIVITY_JOBS = RIG_SENSITIVITY_JOBS + job_chunks(_EXTRA, _PER_JOB)


rule pulloff_sensitivity:
    """Envelope sensitivities d ln P/d ln (w0, n, v0) of the simulated pull-off (rigid fixation) at the
    frequencies of one job, every amplitude of the rig and of the design's candidates."""
    input:
        **PUBLISHED,
        kernels=rules.simulation_kernels.output[0],
        code=code("pulloff_sensitivity"),
    output:
        "results/validation/identifiability/sensitivity/{frequency}Hz.csv",
    log:
        "results/logs/pulloff_sensitivity_{frequency}Hz.log",
    benchmark:
        "results/benchmarks/rules/pulloff_sensitivity_{frequency}Hz.tsv"
    wildcard_constraints:
        frequency=r"[0-9._e+-]+",
    params:
        amplitudes=DESIGN["amplitudes_um"],
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
        sensitivity=expand(rules.pulloff_sensitivity.output[0], frequency=RIG_SENSITIVITY_JOBS),
        fits=expand(rules.identifiability_fit.output[0], model=FITTED_LEVELS),
        code=code("identifiability"),
    output:
        sensitivity=report(
            "results/validation/identifiability/sensitivity.csv",
            caption="../report/identifiability.rst",
            category="Identifiability",
        ),
        information=report(
            "results/validation/identifiability/information.csv",
            caption="../report/identifiability.rst",
            category="Identifiability",
        ),
        fits=report(
            "results/validation/identifiability/fits.csv",
            caption="../report/identifiability.rst",
            category="Identifiability",
        ),
    log:
        "results/logs/identifiability.log",
    params:
        noise=config["identifiability"]["relative_noise"],
    script:
        "../scripts/identifiability.py"


rule identifiability_design:
    """Which tests to add to the rig's: the D-optimal few among the candidates, with the expected standard errors."""
    input:
        virtual=VIRTUAL_RIGID,
        sensitivity=expand(rules.pulloff_sensitivity.output[0], frequency=SENSITIVITY_JOBS),
        code=code("identifiability_design"),
    output:
        design=report(
            "results/validation/identifiability/design.csv",
            caption="../report/identifiability.rst",
            category="Identifiability",
        ),
        candidates=report(
            "results/validation/identifiability/candidates.csv",
            caption="../report/identifiability.rst",
            category="Identifiability",
        ),
    log:
        "results/logs/identifiability_design.log",
    params:
        noise=config["identifiability"]["relative_noise"],
        added=DESIGN["added_tests"],
    script:
        "../scripts/identifiability_design.py"


rule fit_coverage:
    """How often the fit's nominal interval holds the true parameters: simulated rows at the rig's tests with relative
    scatter, fitted by the pipeline's fit (one level: see vibroadhesion.experiments.fit_coverage)."""
    input:
        **PUBLISHED,
        code=code("fit_coverage"),
    output:
        fits="results/validation/identifiability/fit_coverage_fits.csv",
        summary=report(
            "results/validation/identifiability/fit_coverage.csv",
            caption="../report/identifiability.rst",
            category="Identifiability",
        ),
    log:
        "results/logs/fit_coverage.log",
    benchmark:
        "results/benchmarks/rules/fit_coverage.tsv"
    params:
        level=COVERAGE["level"],
        relative_scatter=COVERAGE["relative_scatter"],
        seeds=COVERAGE["seeds"],
        confidence=config["fit"]["confidence"],
    script:
        "../scripts/fit_coverage.py"
