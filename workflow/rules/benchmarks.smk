rule benchmark_j_integrals:
    """Speed against error of the J-integrals: fixed rule vs scipy quad, both against mpmath."""
    input:
        script="benchmarks/j_integrals.py",
        reference="tests/mpmath_reference.py",
        code=code("ratelaw", "integrals", "benchmarking", "artefacts"),
    output:
        csv="results/benchmarks/j_integrals.csv",
        txt="results/benchmarks/j_integrals.txt",
    log:
        "results/logs/benchmark_j_integrals.log",
    shell:
        "{PYTHON} {input.script} {output.csv} {output.txt} 2>&1 | tee {log}"


rule benchmark_simulate:
    """Speed against error of the direct simulation: shooting vs brute-force transients, rtol self-consistency."""
    input:
        script="benchmarks/simulate.py",
        code=code("ratelaw", "groups", "simulate", "benchmarking"),
    output:
        "results/benchmarks/simulate.txt",
    log:
        "results/logs/benchmark_simulate.log",
    shell:
        "{PYTHON} {input.script} {output} > {log} 2>&1"
