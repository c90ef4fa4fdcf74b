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
        "{PYTHON} -m vibroadhesion.pipeline.cli fig3-data --fit {input.fit} --panel-n {params.panel_n} "
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
        "{PYTHON} -m vibroadhesion.pipeline.cli fig3-plot --fit {input.fit} --panel-n {params.panel_n} "
        "--csv {input.csv} --pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"


rule fig4_data:
    """Pull-off amplification: leading order (Eqs. 71-72) and refined (Eq. 106) at the test frequencies."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code(*NUMERICS, "exact_averaging", "frozen_radius", "figures", "fitting", "data", "cli", "artefacts"),
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
        "{PYTHON} -m vibroadhesion.pipeline.cli fig4-data --setup {input.setup} --fit {input.fit} "
        "--h1-max-um {params.h1_max} --points {params.points} --out {output} 2>&1 | tee {log}"


rule fig4_plot:
    input:
        csv="results/fig4/fig4.csv",
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        pulloff="results/data/pulloff.csv",
        virtual="results/validation/virtual_pulloff_rigid.csv",
        code=code("figures", "jkr", "fitting", "data", "cli", "artefacts"),
    output:
        pdf="results/fig4/fig4.pdf",
        png=report("results/fig4/fig4.png", caption="../report/fig4.rst", category="Figures"),
    log:
        "results/logs/fig4_plot.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fig4-plot --setup {input.setup} --fit {input.fit} --pulloff {input.pulloff} "
        "--virtual {input.virtual} "
        "--csv {input.csv} --pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"


# Fig. 5: compliantly fixed indenter, refined model of Sec. 3.5.3, traced by continuation.


rule fig5_data:
    """A/a_m through resonance (Eqs. 87, 90-96) for every assumed (kappa, zeta); folds and solution counts."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code(*NUMERICS, "compliant", "continuation", "figures", "fitting", "data", "cli", "artefacts"),
    output:
        csv="results/fig5/fig5.csv",
        markers="results/fig5/fig5_markers.csv",
        counts="results/fig5/fig5_solution_count.csv",
    params:
        h1=config["fig5"]["h1_um"],
        lo=config["fig5"]["omega_bar_min"],
        hi=config["fig5"]["omega_bar_max"],
        points=config["fig5"]["count_points"],
    log:
        "results/logs/fig5_data.log",
    benchmark:
        "results/benchmarks/rules/fig5_data.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fig5-data --setup {input.setup} --fit {input.fit} --h1-um {params.h1} "
        "--omega-bar-min {params.lo} --omega-bar-max {params.hi} --count-points {params.points} "
        "--out {output.csv} --markers {output.markers} --counts {output.counts} 2>&1 | tee {log}"


rule fig5_plot:
    input:
        csv="results/fig5/fig5.csv",
        markers="results/fig5/fig5_markers.csv",
        code=code("figures", "cli", "artefacts"),
    output:
        pdf="results/fig5/fig5.pdf",
        png=report("results/fig5/fig5.png", caption="../report/fig5.rst", category="Figures"),
    params:
        highlight=config["fig5"]["highlight_hz"],
    log:
        "results/logs/fig5_plot.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fig5-plot --csv {input.csv} --markers {input.markers} "
        "--highlight-hz {params.highlight} --pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"


# Figs. 6-8: rigidly fixed indenter, refined model (Secs. 3.5.4, 3.6, 3.7). Fig. 8 reuses the
# Fig. 6 solution and Fig. 7 takes its asymptotes from Fig. 4's leading-order rows.


rule fig6_data:
    """Nominal point contact: Abar, abar_m, w_eff/w0, A/a_m (Eqs. 122-123, 49, corrected 98)."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code(*NUMERICS, "figures", "fitting", "data", "cli", "artefacts"),
    output:
        "results/fig6/fig6.csv",
    params:
        lo=config["fig6"]["log10_omega_check_min"],
        hi=config["fig6"]["log10_omega_check_max"],
        points=config["fig6"]["points"],
    log:
        "results/logs/fig6_data.log",
    benchmark:
        "results/benchmarks/rules/fig6_data.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fig6-data --setup {input.setup} --fit {input.fit} --log10-omega-min {params.lo} "
        "--log10-omega-max {params.hi} --points {params.points} --out {output} 2>&1 | tee {log}"


rule fig7_data:
    """Refined pull-off estimate against omega_check (Eq. 106)."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code(*NUMERICS, "figures", "fitting", "data", "cli", "artefacts"),
    output:
        "results/fig7/fig7.csv",
    params:
        lo=config["fig7"]["log10_omega_check_min"],
        hi=config["fig7"]["log10_omega_check_max"],
        points=config["fig7"]["points"],
    log:
        "results/logs/fig7_data.log",
    benchmark:
        "results/benchmarks/rules/fig7_data.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fig7-data --setup {input.setup} --fit {input.fit} --log10-omega-min {params.lo} "
        "--log10-omega-max {params.hi} --points {params.points} --out {output} 2>&1 | tee {log}"


rule fig8_data:
    """Dynamic contact stiffness (Eqs. 117-121) along the Fig. 6 solution."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        fig6="results/fig6/fig6.csv",
        code=code("ratelaw", "integrals", "stiffness", "groups", "figures", "fitting", "data", "cli", "artefacts"),
    output:
        "results/fig8/fig8.csv",
    log:
        "results/logs/fig8_data.log",
    benchmark:
        "results/benchmarks/rules/fig8_data.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fig8-data --setup {input.setup} --fit {input.fit} --fig6 {input.fig6} "
        "--out {output} 2>&1 | tee {log}"


rule fig6_plot:
    input:
        csv="results/fig6/fig6.csv",
        validation="results/validation/rigid_grid.csv",
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code("figures", "groups", "fitting", "data", "cli", "artefacts"),
    output:
        pdf="results/fig6/fig6.pdf",
        png=report("results/fig6/fig6.png", caption="../report/fig6.rst", category="Figures"),
    log:
        "results/logs/fig6_plot.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fig6-plot --setup {input.setup} --fit {input.fit} --csv {input.csv} --validation {input.validation} "
        "--pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"


rule fig8_plot:
    input:
        csv="results/fig8/fig8.csv",
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code("figures", "groups", "fitting", "data", "cli", "artefacts"),
    output:
        pdf="results/fig8/fig8.pdf",
        png=report("results/fig8/fig8.png", caption="../report/fig8.rst", category="Figures"),
    log:
        "results/logs/fig8_plot.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fig8-plot --setup {input.setup} --fit {input.fit} --csv {input.csv} "
        "--pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"


rule fig7_plot:
    input:
        csv="results/fig7/fig7.csv",
        fig4="results/fig4/fig4.csv",
        virtual="results/validation/virtual_pulloff_rigid.csv",
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code("figures", "groups", "fitting", "data", "cli", "artefacts"),
    output:
        pdf="results/fig7/fig7.pdf",
        png=report("results/fig7/fig7.png", caption="../report/fig7.rst", category="Figures"),
    log:
        "results/logs/fig7_plot.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli fig7-plot --setup {input.setup} --fit {input.fit} --csv {input.csv} "
        "--fig4 {input.fig4} --virtual {input.virtual} --pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"
