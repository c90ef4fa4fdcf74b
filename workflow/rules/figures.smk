# One compute rule (CSV) and one plot rule (PDF, PNG) per figure: restyling never reruns a solve.


rule fig3_data:
    """J-integrals (Eqs. 28, 29, 36) for the fitted n and the panel exponents."""
    input:
        fit=RIG["fit"],
        code=code("fig3_data"),
    output:
        "results/fig3/fig3.csv",
    log:
        "results/logs/fig3_data.log",
    benchmark:
        "results/benchmarks/rules/fig3_data.tsv"
    params:
        panel_n=config["fig3"]["panel_n"],
        lo=config["fig3"]["log10_abar_min"],
        hi=config["fig3"]["log10_abar_max"],
        points=config["fig3"]["points"],
    script:
        "../scripts/fig3_data.py"


rule fig3_plot:
    input:
        csv=rules.fig3_data.output[0],
        fit=RIG["fit"],
        code=code("fig3_plot"),
    output:
        pdf="results/fig3/fig3.pdf",
        png=report("results/fig3/fig3.png", caption="../report/fig3.rst", category="Figures"),
    log:
        "results/logs/fig3_plot.log",
    params:
        panel_n=config["fig3"]["panel_n"],
    script:
        "../scripts/fig3_plot.py"


rule fig4_data:
    """Pull-off amplification: leading order (Eqs. 71-72) and refined (Eq. 106) at the test frequencies."""
    input:
        **RIG,
        code=code("fig4_data"),
    output:
        "results/fig4/fig4.csv",
    log:
        "results/logs/fig4_data.log",
    benchmark:
        "results/benchmarks/rules/fig4_data.tsv"
    params:
        h1_max=config["fig4"]["h1_max_um"],
        points=config["fig4"]["points"],
    script:
        "../scripts/fig4_data.py"


rule fig4_plot:
    input:
        **RIG,
        csv=rules.fig4_data.output[0],
        pulloff=rules.ingest.output.pulloff,
        virtual=VIRTUAL_RIGID,
        code=code("fig4_plot"),
    output:
        pdf="results/fig4/fig4.pdf",
        png=report("results/fig4/fig4.png", caption="../report/fig4.rst", category="Figures"),
    log:
        "results/logs/fig4_plot.log",
    script:
        "../scripts/fig4_plot.py"


# Fig. 5: compliantly fixed indenter, refined model of Sec. 3.5.3, traced by continuation.


rule fig5_data:
    """A/a_m through resonance (Eqs. 87, 90-96) for every assumed (kappa, zeta); folds and solution counts."""
    input:
        **RIG,
        code=code("fig5_data"),
    output:
        csv="results/fig5/fig5.csv",
        markers="results/fig5/fig5_markers.csv",
        counts="results/fig5/fig5_solution_count.csv",
    log:
        "results/logs/fig5_data.log",
    benchmark:
        "results/benchmarks/rules/fig5_data.tsv"
    params:
        lo=config["fig5"]["omega_bar_min"],
        hi=config["fig5"]["omega_bar_max"],
        points=config["fig5"]["count_points"],
    script:
        "../scripts/fig5_data.py"


rule fig5_plot:
    input:
        setup=RIG["setup"],
        csv=rules.fig5_data.output.csv,
        markers=rules.fig5_data.output.markers,
        code=code("fig5_plot"),
    output:
        pdf="results/fig5/fig5.pdf",
        png=report("results/fig5/fig5.png", caption="../report/fig5.rst", category="Figures"),
    log:
        "results/logs/fig5_plot.log",
    script:
        "../scripts/fig5_plot.py"


# Figs. 6-8: rigidly fixed indenter, refined model (Secs. 3.5.4, 3.6, 3.7). Fig. 8 reuses the
# Fig. 6 solution and Fig. 7 takes its asymptotes from Fig. 4's leading-order rows.


rule fig6_data:
    """Nominal point contact: Abar, abar_m, w_eff/w0, A/a_m (Eqs. 122-123, 49, corrected 98)."""
    input:
        **RIG,
        code=code("fig6_data"),
    output:
        "results/fig6/fig6.csv",
    log:
        "results/logs/fig6_data.log",
    benchmark:
        "results/benchmarks/rules/fig6_data.tsv"
    params:
        lo=config["fig6"]["log10_omega_check_min"],
        hi=config["fig6"]["log10_omega_check_max"],
        points=config["fig6"]["points"],
    script:
        "../scripts/fig6_data.py"


rule fig7_data:
    """Refined pull-off estimate against omega_check (Eq. 106)."""
    input:
        **RIG,
        code=code("fig7_data"),
    output:
        "results/fig7/fig7.csv",
    log:
        "results/logs/fig7_data.log",
    benchmark:
        "results/benchmarks/rules/fig7_data.tsv"
    params:
        lo=config["fig7"]["log10_omega_check_min"],
        hi=config["fig7"]["log10_omega_check_max"],
        points=config["fig7"]["points"],
    script:
        "../scripts/fig7_data.py"


rule fig8_data:
    """Dynamic contact stiffness (Eqs. 117-121) along the Fig. 6 solution."""
    input:
        **RIG,
        fig6=rules.fig6_data.output[0],
        code=code("fig8_data"),
    output:
        "results/fig8/fig8.csv",
    log:
        "results/logs/fig8_data.log",
    benchmark:
        "results/benchmarks/rules/fig8_data.tsv"
    script:
        "../scripts/fig8_data.py"


rule fig6_plot:
    input:
        **RIG,
        csv=rules.fig6_data.output[0],
        grid=rules.simulation_rigid_grid.output[0],
        code=code("fig6_plot"),
    output:
        pdf="results/fig6/fig6.pdf",
        png=report("results/fig6/fig6.png", caption="../report/fig6.rst", category="Figures"),
    log:
        "results/logs/fig6_plot.log",
    script:
        "../scripts/fig6_plot.py"


rule fig7_plot:
    input:
        **RIG,
        csv=rules.fig7_data.output[0],
        fig4=rules.fig4_data.output[0],
        virtual=VIRTUAL_RIGID,
        code=code("fig7_plot"),
    output:
        pdf="results/fig7/fig7.pdf",
        png=report("results/fig7/fig7.png", caption="../report/fig7.rst", category="Figures"),
    log:
        "results/logs/fig7_plot.log",
    script:
        "../scripts/fig7_plot.py"


rule fig8_plot:
    input:
        **RIG,
        csv=rules.fig8_data.output[0],
        code=code("fig8_plot"),
    output:
        pdf="results/fig8/fig8.pdf",
        png=report("results/fig8/fig8.png", caption="../report/fig8.rst", category="Figures"),
    log:
        "results/logs/fig8_plot.log",
    script:
        "../scripts/fig8_plot.py"
