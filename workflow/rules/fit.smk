rule fit_gent_schultz:
    """Least-squares Gent–Schultz fit with the leading-order and the refined model (Sec. 3.4)."""
    input:
        setup=rules.ingest.output.setup,
        pulloff=rules.ingest.output.pulloff,
        code=code("fit_gent_schultz"),
    output:
        "results/fit/gent_schultz.json",
    log:
        "results/logs/fit_gent_schultz.log",
    benchmark:
        "results/benchmarks/rules/fit_gent_schultz.tsv"
    params:
        figures_use=config["fit"]["figures_use"],
    script:
        "../scripts/fit_gent_schultz.py"


# The rig and the fit every model rule starts from.
RIG = {"setup": rules.ingest.output.setup, "fit": rules.fit_gent_schultz.output[0]}
