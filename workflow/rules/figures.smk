# One compute rule (CSV) per figure, and one rule that draws them all (PDF, PNG): restyling never reruns a
# solve, and matplotlib is imported once, not once per figure.


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
        lo=config["fig3"]["log10_Abar_min"],
        hi=config["fig3"]["log10_Abar_max"],
        points=config["fig3"]["points"],
    script:
        "../scripts/fig3_data.py"


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


rule plot_figures:
    """Figs. 3-8 from their tables, with the measured rows and the simulated overlays (no solve)."""
    input:
        **RIG,
        **{fig: getattr(rules, f"{fig}_data").output[0] for fig in FIGURES},
        fig5_markers=rules.fig5_data.output.markers,
        pulloff=rules.ingest.output.pulloff,
        virtual=VIRTUAL_RIGID,
        grid=rules.simulation_rigid_grid.output[0],
        code=code("plot_figures"),
    output:
        **{f"{fig}_pdf": f"results/{fig}/{fig}.pdf" for fig in FIGURES},
        **{
            f"{fig}_png": report(f"results/{fig}/{fig}.png", caption=f"../report/{fig}.rst", category="Figures")
            for fig in FIGURES
        },
    log:
        "results/logs/plot_figures.log",
    params:
        panel_n=config["fig3"]["panel_n"],
    script:
        "../scripts/plot_figures.py"
