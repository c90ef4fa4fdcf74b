# Compute rules (CSV) and plot rules (PDF, PNG): restyling never reruns a solve. Figs. 3, 6 and 8 (published
# parameters) and Figs. 4 and 7 (the fit the figures use) are computed in one job each, Fig. 5's continuation in its
# own; the figures are drawn in two jobs, matplotlib imported once per job. Fig. 8 reuses the Fig. 6 solution and
# Fig. 7 takes its asymptotes from Fig. 4's leading-order rows.


rule fig3_fig6_fig8_data:
    """J-integrals (Eqs. 28, 29, 36) for the published n and the panel exponents; rigid nominal point contact, Abar,
    abar_m, w_eff/w0, A/a_m (Eqs. 122-123, 49, corrected 98); dynamic contact stiffness (Eqs. 117-121) along the
    Fig. 6 solution. One job: each table costs less than a process's start-up."""
    input:
        **PUBLISHED,
        code=code("fig3_fig6_fig8_data"),
    output:
        **figure_tables(["fig3", "fig6", "fig8"]),
    log:
        "results/logs/fig3_fig6_fig8_data.log",
    benchmark:
        "results/benchmarks/rules/fig3_fig6_fig8_data.tsv"
    params:
        fig3=config["fig3"],
        fig6=config["fig6"],
    script:
        "../scripts/fig3_fig6_fig8_data.py"


rule fig4_fig7_data:
    """Pull-off amplification: leading order (Eqs. 71-72) and refined (Eq. 106) at the test frequencies; the refined
    pull-off estimate against omega_check (Eq. 106). One job: each table costs less than a process's start-up."""
    input:
        **FITTED,
        code=code("fig4_fig7_data"),
    output:
        **figure_tables(["fig4", "fig7"]),
    log:
        "results/logs/fig4_fig7_data.log",
    benchmark:
        "results/benchmarks/rules/fig4_fig7_data.tsv"
    params:
        fig4=config["fig4"],
        fig7=config["fig7"],
    script:
        "../scripts/fig4_fig7_data.py"


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


# Each figure's table, and what its plot reads besides its table, the setup and the fit.
FIGURE_TABLE = {
    "fig3": rules.fig3_fig6_fig8_data.output.fig3,
    "fig4": rules.fig4_fig7_data.output.fig4,
    "fig5": rules.fig5_data.output.csv,
    "fig6": rules.fig3_fig6_fig8_data.output.fig6,
    "fig7": rules.fig4_fig7_data.output.fig7,
    "fig8": rules.fig3_fig6_fig8_data.output.fig8,
}
PLOT_EXTRAS = {
    "fig3": {},
    "fig4": {"pulloff": rules.ingest_pulloff.output[0], "virtual": FIGURE_VIRTUAL},
    "fig5": {"fig5_markers": rules.fig5_data.output.markers},
    "fig6": {"grid": rules.simulation_rigid_grid.output[0]},
    "fig7": {
        "fig4": rules.fig4_fig7_data.output.fig4,
        "pulloff": rules.ingest_pulloff.output[0],
        "virtual": FIGURE_VIRTUAL,
    },
    "fig8": {},
}
# The figures in two plot jobs (one matplotlib process each).
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
