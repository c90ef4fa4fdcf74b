# Report: each page is a notebook executed by papermill and exported to HTML by nbconvert.
from vibroadhesion.pipeline.pages import PAGES, VALIDATION_PAGES

# The two indexes of the report and their pages: the default target builds the first, `validation` the second.
REPORT_INDEXES = {"index": PAGES, "validation_index": VALIDATION_PAGES}

# The benchmarks page also lists the wall time of the timed jobs of the default target (`benchmark:`).
TIMED_RULES = ["fit_gent_schultz", "fig3_data", "fig4_data", "fig5_data", "fig6_data", "fig7_data", "fig8_data"]


FIT_JSON, SETUP_JSON = RIG["fit"], RIG["setup"]
PAGE_INPUTS = {
    "fig3": {"fig_csv": rules.fig3_data.output[0], "fig_png": rules.plot_figures.output.fig3_png, "fit_json": FIT_JSON},
    "fig4": {
        "fig_csv": rules.fig4_data.output[0],
        "fig_png": rules.plot_figures.output.fig4_png,
        "fit_json": FIT_JSON,
        "setup_json": SETUP_JSON,
        "pulloff_csv": rules.ingest.output.pulloff,
        "virtual_csv": VIRTUAL_RIGID,
    },
    "fig5": {
        "fig_csv": rules.fig5_data.output.csv,
        "fig_png": rules.plot_figures.output.fig5_png,
        "markers_csv": rules.fig5_data.output.markers,
        "counts_csv": rules.fig5_data.output.counts,
        "setup_json": SETUP_JSON,
        "fit_json": FIT_JSON,
    },
    **{
        fig: {
            "fig_csv": getattr(rules, f"{fig}_data").output[0],
            "fig_png": getattr(rules.plot_figures.output, f"{fig}_png"),
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


def page_parameters(page):
    """papermill parameters of ``page``: the path of every artefact it reads (strings)."""
    parameters = {name: str(path) for name, path in PAGE_INPUTS[page].items()}
    if page == "benchmarks":
        parameters["rule_tsv_glob"] = "results/benchmarks/rules/*.tsv"
    return parameters


def report_inputs(index):
    """Every artefact the pages of ``index`` read, named <page>_<parameter>, their notebooks and their code."""
    pages = [stem for stem, _ in REPORT_INDEXES[index]]
    inputs = {f"{page}_{name}": path for page in pages for name, path in PAGE_INPUTS[page].items()}
    if "benchmarks" in pages:
        inputs["rule_tsvs"] = [getattr(rules, r).benchmark for r in TIMED_RULES]
    notebooks = [f"notebooks/{page}.ipynb" for page in pages]
    return {**inputs, "notebooks": notebooks, "code": code("report", *notebooks)}


def report_pages(index):
    """page -> papermill parameters (artefact paths) of the pages of ``index``, in the index's order."""
    return {stem: page_parameters(stem) for stem, _ in REPORT_INDEXES[index]}


# One job per index renders its pages in one kernel (pipeline.steps.report): starting a kernel per page
# cost as much as executing it. A page's output is its executed notebook and its HTML page.
for index in REPORT_INDEXES:

    rule:
        name:
            f"report_{index}"
        input:
            **report_inputs(index),
        output:
            notebooks=[f"results/report/notebooks/{stem}.ipynb" for stem, _ in REPORT_INDEXES[index]],
            pages=[f"results/report/{stem}.html" for stem, _ in REPORT_INDEXES[index]],
            index=f"results/report/{index}.html",
        log:
            f"results/logs/report_{index}.log",
        localrule: True
        params:
            pages=report_pages(index),
        script:
            "../scripts/report.py"
