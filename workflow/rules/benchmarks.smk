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
        code=code("ratelaw", "groups", *SIMULATION, "benchmarking"),
    output:
        "results/benchmarks/simulate.txt",
    log:
        "results/logs/benchmark_simulate.log",
    shell:
        "{PYTHON} {input.script} {output} > {log} 2>&1"


rule benchmark_speed_vs_error:
    """Every model level: time per solved point against its error vs the simulation at the test conditions."""
    input:
        script="benchmarks/speed_vs_error.py",
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        errors="results/validation/rigid_errors.csv",
        code=code(*NUMERICS, *SIMULATION, "exact_averaging", "frozen_radius", "exact_harmonic_balance", "validation", "benchmarking",
                  "data", "artefacts"),
    output:
        csv="results/benchmarks/speed_vs_error.csv",
        txt="results/benchmarks/speed_vs_error.txt",
        png="results/benchmarks/speed_vs_error.png",
        pdf="results/benchmarks/speed_vs_error.pdf",
    log:
        "results/logs/benchmark_speed_vs_error.log",
    shell:
        "{PYTHON} {input.script} {input.setup} {input.fit} {input.errors} {output.csv} {output.txt} {output.png} > {log} 2>&1"
