# Report: each page is a notebook executed by papermill and exported to HTML by nbconvert, in one job.
from vibroadhesion.pipeline.pages import PAGES as REPORT_PAGES, VALIDATION_PAGES as VALIDATION_REPORT_PAGES

FIT_JSON, SETUP_JSON = RIG["fit"], RIG["setup"]
PAGE_INPUTS = {
    "fig3": {"fig_csv": rules.fig3_data.output[0], "fig_png": rules.fig3_plot.output.png, "fit_json": FIT_JSON},
    "fig4": {
        "fig_csv": rules.fig4_data.output[0],
        "fig_png": rules.fig4_plot.output.png,
        "fit_json": FIT_JSON,
        "setup_json": SETUP_JSON,
        "pulloff_csv": rules.ingest.output.pulloff,
        "virtual_csv": VIRTUAL_RIGID,
    },
    "fig5": {
        "fig_csv": rules.fig5_data.output.csv,
        "fig_png": rules.fig5_plot.output.png,
        "markers_csv": rules.fig5_data.output.markers,
        "counts_csv": rules.fig5_data.output.counts,
        "setup_json": SETUP_JSON,
        "fit_json": FIT_JSON,
    },
    **{
        fig: {
            "fig_csv": getattr(rules, f"{fig}_data").output[0],
            "fig_png": getattr(rules, f"{fig}_plot").output.png,
            "fit_json": FIT_JSON,
            "setup_json": SETUP_JSON,
        }
        for fig in ("fig6", "fig7", "fig8")
    },
    "validation": {
        "grid_csv": rules.simulation_rigid_grid.output[0],
        "errors_csv": rules.validation_errors.output.errors,
        "summary_csv": rules.validation_errors.output.summary,
        "maps_png": rules.validation_plot.output.png,
        "sweep_csv": rules.validation_compliant.output.csv,
        "sweep_png": rules.validation_compliant_plot.output.png,
        "virtual_csv": rules.virtual_pulloff_gather.output[0],
        "setup_json": SETUP_JSON,
        "fit_json": FIT_JSON,
    },
    "fit": {"fit_json": FIT_JSON, "setup_json": SETUP_JSON},
    "identifiability": {
        "fits_csv": rules.identifiability.output.fits,
        "information_csv": rules.identifiability.output.information,
        "sensitivity_csv": rules.identifiability.output.sensitivity,
        "virtual_csv": VIRTUAL_RIGID,
        "fit_json": FIT_JSON,
    },
    "benchmarks": {
        "bench_csv": rules.benchmark_j_integrals.output.csv,
        "bench_txt": rules.benchmark_j_integrals.output.txt,
        "simulate_txt": rules.benchmark_simulate.output[0],
        "speed_txt": rules.benchmark_speed_vs_error.output.txt,
        "speed_png": rules.benchmark_speed_vs_error.output.png,
    },
}


rule report_page:
    """Execute one report notebook on the pipeline's artefacts and export it to a self-contained HTML page."""
    input:
        unpack(page_inputs),
        notebook="notebooks/{page}.ipynb",
        code=lambda wildcards: code("report_page", f"notebooks/{wildcards.page}.ipynb"),
    output:
        notebook="results/report/notebooks/{page}.ipynb",
        html="results/report/{page}.html",
    log:
        "results/logs/report_page_{page}.log",
    wildcard_constraints:
        page="|".join(PAGE_INPUTS),
    localrule: True
    params:
        parameters=page_parameters,
    script:
        "../scripts/report_page.py"


rule report_index:
    """Index of the figure pages (default target) or of the validation pages (``validation`` target)."""
    input:
        pages=lambda wc: expand(
            rules.report_page.output.html,
            page=[stem for stem, _ in (REPORT_PAGES if wc.index == "index" else VALIDATION_REPORT_PAGES)],
        ),
        code=code("report_index"),
    output:
        "results/report/{index}.html",
    log:
        "results/logs/report_{index}.log",
    wildcard_constraints:
        index="index|validation_index",
    localrule: True
    script:
        "../scripts/report_index.py"
