rule fit_gent_schultz:
    """Least-squares Gent–Schultz fit with the leading-order and the refined model (Sec. 3.4)."""
    input:
        setup=rules.ingest_setup.output[0],
        pulloff=rules.ingest_pulloff.output[0],
        code=code("fit_gent_schultz"),
    output:
        report("results/fit/gent_schultz.json", caption="../report/fit.rst", category="Fit"),
    log:
        "results/logs/fit_gent_schultz.log",
    benchmark:
        "results/benchmarks/rules/fit_gent_schultz.tsv"
    params:
        figures_use=config["fit"]["figures_use"],
        judgement={key: config["fit"][key] for key in ("relative_scatter", "alpha", "confidence")},
    script:
        "../scripts/fit_gent_schultz.py"


# The inputs that fix a job's Gent–Schultz parameters (vibroadhesion.pipeline.steps.inputs.rig). PUBLISHED: the rig
# and the published set of data/setup.yaml, for the paper's figures (3, 5, 6, 8), the simulation behind them, the
# validation and the identifiability study; an edit of data/pulloff.csv reruns none of them. FITTED: the rig and
# the fit the figures use, for what shows the measured rows (Figs. 4 and 7, the fit page).
PUBLISHED = {"setup": rules.ingest_setup.output[0]}
FITTED = {**PUBLISHED, "fit": rules.fit_gent_schultz.output[0]}
