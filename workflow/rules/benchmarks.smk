rule benchmark_j_integrals:
    """Speed against error of the J-integrals: fixed rule vs scipy quad, both against mpmath."""
    input:
        script="benchmarks/j_integrals.py",
        reference="tests/mpmath_reference.py",
        reference_table="tests/reference/j_integrals_mpmath.csv",
        code=code("benchmarks/j_integrals.py"),
    output:
        csv=report(
            "results/benchmarks/j_integrals.csv",
            caption="../report/benchmarks_tables.rst",
            category="Benchmarks",
            subcategory="Tables",
        ),
        txt="results/benchmarks/j_integrals.txt",
    log:
        "results/logs/benchmark_j_integrals.log",
    params:
        python=PYTHON,
    shell:
        "{params.python:q} {input.script:q} {output.csv:q} {output.txt:q} > {log:q} 2>&1"


rule benchmark_simulate:
    """Speed against error of the direct simulation: shooting vs brute-force transients, rtol self-consistency."""
    input:
        script="benchmarks/simulate.py",
        kernels=rules.simulation_kernels.output[0],
        code=code("benchmarks/simulate.py"),
    output:
        txt=report(
            "results/benchmarks/simulate.txt",
            caption="../report/benchmarks_tables.rst",
            category="Benchmarks",
            subcategory="Tables",
        ),
        csv=report(
            "results/benchmarks/simulate.csv",
            caption="../report/benchmarks_tables.rst",
            category="Benchmarks",
            subcategory="Tables",
        ),
    log:
        "results/logs/benchmark_simulate.log",
    params:
        python=PYTHON,
    shell:
        "{params.python:q} {input.script:q} {output.txt:q} {output.csv:q} > {log:q} 2>&1"


rule benchmark_speed_vs_error:
    """Every model level: time per solved point against its error vs the simulation at the test conditions."""
    input:
        **PUBLISHED,
        script="benchmarks/speed_vs_error.py",
        errors=rules.validation_errors.output.errors,
        kernels=rules.simulation_kernels.output[0],
        code=code("benchmarks/speed_vs_error.py"),
    output:
        csv=report(
            "results/benchmarks/speed_vs_error.csv",
            caption="../report/benchmarks_tables.rst",
            category="Benchmarks",
            subcategory="Tables",
        ),
        txt="results/benchmarks/speed_vs_error.txt",
        png=report(
            "results/benchmarks/speed_vs_error.png", caption="../report/speed_vs_error.rst", category="Benchmarks"
        ),
        pdf="results/benchmarks/speed_vs_error.pdf",
    log:
        "results/logs/benchmark_speed_vs_error.log",
    params:
        python=PYTHON,
    shell:
        "{params.python:q} {input.script:q} {input.setup:q} {input.errors:q} {output.csv:q} {output.txt:q} "
        "{output.png:q} > {log:q} 2>&1"
