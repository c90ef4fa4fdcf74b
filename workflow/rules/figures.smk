# One compute rule (CSV) per figure, and one rule that draws them all (PDF, PNG): restyling never reruns a
# solve, and matplotlib is imported once, not once per figure.


rule fig3_data:
    """J-integrals (Eqs. 28, 29, 36) for the published n and the panel exponents."""
    input:
        **PUBLISHED,
        code=code("fig3_data"),
    output:
        report("results/fig3/fig3.csv", caption="../report/table.rst", category="Figures", subcategory="Tables"),
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
        **FITTED,
        code=code("fig4_data"),
    output:
        report("results/fig4/fig4.csv", caption="../report/table.rst", category="Figures", subcategory="Tables"),
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
        **PUBLISHED,
        code=code("fig5_data"),
    output:
        csv=report("results/fig5/fig5.csv", caption="../report/table.rst", category="Figures", subcategory="Tables"),
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
        **PUBLISHED,
        code=code("fig6_data"),
    output:
        report("results/fig6/fig6.csv", caption="../report/table.rst", category="Figures", subcategory="Tables"),
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
        **FITTED,
        code=code("fig7_data"),
    output:
        report("results/fig7/fig7.csv", caption="../report/table.rst", category="Figures", subcategory="Tables"),
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
        **PUBLISHED,
        fig6=rules.fig6_data.output[0],
        code=code("fig8_data"),
    output:
        report("results/fig8/fig8.csv", caption="../report/table.rst", category="Figures", subcategory="Tables"),
    log:
        "results/logs/fig8_data.log",
    benchmark:
        "results/benchmarks/rules/fig8_data.tsv"
    script:
        "../scripts/fig8_data.py"


# What each figure's plot reads besides its table, the setup and the fit.
PLOT_EXTRAS = {
    "fig3": {},
    "fig4": {"pulloff": rules.ingest_pulloff.output[0], "virtual": FIGURE_VIRTUAL},
    "fig5": {"fig5_markers": rules.fig5_data.output.markers},
    "fig6": {"grid": rules.simulation_rigid_grid.output[0]},
    "fig7": {"fig4": rules.fig4_data.output[0], "virtual": FIGURE_VIRTUAL},
    "fig8": {},
}
# The figures in two plot jobs (one matplotlib process each): Figs. 4 and 7 overlay the simulated pull-off, the
# longest chain of the DAG; the others are drawn, and their pages rendered, while it runs.
FIGURE_GROUPS = {"pulloff": ["fig4", "fig7"], "steady": ["fig3", "fig5", "fig6", "fig8"]}
PLOT_RULE = {fig: f"plot_{group}_figures" for group, figs in FIGURE_GROUPS.items() for fig in figs}
# Figs. 4 and 7 show the measured rows, so they take the fit the figures use; the others reproduce the paper.
GROUP_PARAMETERS = {"pulloff": FITTED, "steady": PUBLISHED}


for group, figs in FIGURE_GROUPS.items():

    rule:
        name:
            f"plot_{group}_figures"
        input:
            **GROUP_PARAMETERS[group],
            **plot_inputs(figs),
            code=code("plot_figures"),
        output:
            **{f"{fig}_pdf": f"results/{fig}/{fig}.pdf" for fig in figs},
            **{
                f"{fig}_png": report(f"results/{fig}/{fig}.png", caption=f"../report/{fig}.rst", category="Figures")
                for fig in figs
            },
        log:
            f"results/logs/plot_{group}_figures.log",
        localrule: True
        params:
            panel_n=config["fig3"]["panel_n"],
        script:
            "../scripts/plot_figures.py"
