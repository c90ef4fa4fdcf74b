rule fit_gent_schultz:
    """Least-squares Gent–Schultz fit with the leading-order and the refined model (Sec. 3.4)."""
    input:
        setup="results/data/setup.json",
        pulloff="results/data/pulloff.csv",
        code=code(*NUMERICS, "fitting", "data", "cli", "artefacts"),
    output:
        "results/fit/gent_schultz.json",
    params:
        figures_use=config["fit"]["figures_use"],
    log:
        "results/logs/fit_gent_schultz.log",
    benchmark:
        "results/benchmarks/rules/fit_gent_schultz.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fit --setup {input.setup} --pulloff {input.pulloff} "
        "--figures-use {params.figures_use} --out {output} 2>&1 | tee {log}"
