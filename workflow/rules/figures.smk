# One compute rule (CSV) and one plot rule (PDF, PNG) per figure: restyling never reruns a solve.


rule fig3_data:
    """J-integrals (Eqs. 28, 29, 36) for the fitted n and the panel exponents."""
    input:
        fit="results/fit/gent_schultz.json",
        code=code("ratelaw", "integrals", "figures", "fitting", "cli", "artefacts"),
    output:
        "results/fig3/fig3.csv",
    params:
        panel_n=config["fig3"]["panel_n"],
        lo=config["fig3"]["log10_abar_min"],
        hi=config["fig3"]["log10_abar_max"],
        points=config["fig3"]["points"],
    log:
        "results/logs/fig3_data.log",
    benchmark:
        "results/benchmarks/rules/fig3_data.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.cli fig3-data --fit {input.fit} --panel-n {params.panel_n} "
        "--log10-abar-min {params.lo} --log10-abar-max {params.hi} --points {params.points} --out {output} "
        "2>&1 | tee {log}"


rule fig3_plot:
    input:
        csv="results/fig3/fig3.csv",
        fit="results/fit/gent_schultz.json",
        code=code("integrals", "figures", "cli", "artefacts"),
    output:
        pdf="results/fig3/fig3.pdf",
        png=report("results/fig3/fig3.png", caption="../report/fig3.rst", category="Figures"),
    params:
        panel_n=config["fig3"]["panel_n"],
    log:
        "results/logs/fig3_plot.log",
    shell:
        "{PYTHON} -m vibroadhesion.cli fig3-plot --fit {input.fit} --panel-n {params.panel_n} "
        "--csv {input.csv} --pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"


rule fig4_data:
    """Pull-off amplification: leading order (Eqs. 71-72) and refined (Eq. 106) at the test frequencies."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code(*NUMERICS, "figures", "fitting", "data", "cli", "artefacts"),
    output:
        "results/fig4/fig4.csv",
    params:
        h1_max=config["fig4"]["h1_max_um"],
        points=config["fig4"]["points"],
    log:
        "results/logs/fig4_data.log",
    benchmark:
        "results/benchmarks/rules/fig4_data.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.cli fig4-data --setup {input.setup} --fit {input.fit} "
        "--h1-max-um {params.h1_max} --points {params.points} --out {output} 2>&1 | tee {log}"


rule fig4_plot:
    input:
        csv="results/fig4/fig4.csv",
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        pulloff="results/data/pulloff.csv",
        code=code("figures", "jkr", "fitting", "data", "cli", "artefacts"),
    output:
        pdf="results/fig4/fig4.pdf",
        png=report("results/fig4/fig4.png", caption="../report/fig4.rst", category="Figures"),
    log:
        "results/logs/fig4_plot.log",
    shell:
        "{PYTHON} -m vibroadhesion.cli fig4-plot --setup {input.setup} --fit {input.fit} --pulloff {input.pulloff} "
        "--csv {input.csv} --pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"
