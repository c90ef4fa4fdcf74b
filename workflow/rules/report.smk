# Report: each page is a notebook executed by papermill and exported to HTML by nbconvert.
from functools import partial

from vibroadhesion.pipeline.pages import REPORT_JOBS

# The benchmarks page also lists the wall time of the timed jobs of the default target (`benchmark:`).
TIMED_RULES = ["fit_gent_schultz", "fig3_fig6_fig8_data", "fig4_fig7_data", "fig5_data"]


FIT_JSON, SETUP_JSON = FITTED["fit"], PUBLISHED["setup"]
PAGE_INPUTS = {
    "fig3": {
        "fig_csv": FIGURE_TABLE["fig3"],
        "fig_png": getattr(rules, PLOT_RULE["fig3"]).output.fig3_png,
        "setup_json": SETUP_JSON,
    },
    "fig4": {
        "fig_csv": FIGURE_TABLE["fig4"],
        "fig_png": getattr(rules, PLOT_RULE["fig4"]).output.fig4_png,
        "fit_json": FIT_JSON,
        "setup_json": SETUP_JSON,
        "pulloff_csv": rules.ingest_pulloff.output[0],
        "virtual_csv": FIGURE_VIRTUAL,
    },
    "fig5": {
        "fig_csv": rules.fig5_data.output.csv,
        "fig_png": getattr(rules, PLOT_RULE["fig5"]).output.fig5_png,
        "markers_csv": rules.fig5_data.output.markers,
        "counts_csv": rules.fig5_data.output.counts,
        "setup_json": SETUP_JSON,
    },
    **{
        fig: {
            "fig_csv": FIGURE_TABLE[fig],
            "fig_png": getattr(getattr(rules, PLOT_RULE[fig]).output, f"{fig}_png"),
            "setup_json": SETUP_JSON,
            **({"fit_json": FIT_JSON} if fig == "fig7" else {}),
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
    },
    "rigs": {
        "comparison_csv": rules.rigs_gather.output.csv,
        "equivalence_csv": rules.rigs_gather.output.summary,
        "figure_png": rules.rigs_plot.output.png,
    },
    "fit": {
        "fit_json": FIT_JSON,
        "setup_json": SETUP_JSON,
        "pulloff_csv": rules.ingest_pulloff.output[0],
    },
    "identifiability": {
        "fits_csv": rules.identifiability.output.fits,
        "information_csv": rules.identifiability.output.information,
        "sensitivity_csv": rules.identifiability.output.sensitivity,
        "design_csv": rules.identifiability_design.output.design,
        "candidates_csv": rules.identifiability_design.output.candidates,
        "coverage_csv": rules.fit_coverage.output.summary,
        "virtual_csv": VIRTUAL_RIGID,
        "setup_json": SETUP_JSON,
    },
    "benchmarks": {
        "bench_csv": rules.benchmark_j_integrals.output.csv,
        "bench_txt": rules.benchmark_j_integrals.output.txt,
        "simulate_txt": rules.benchmark_simulate.output[0],
        "speed_txt": rules.benchmark_speed_vs_error.output.txt,
        "speed_png": rules.benchmark_speed_vs_error.output.png,
    },
    "withdrawal": {
        "withdrawal_csv": rules.withdrawal_gather.output.csv,
        "withdrawal_limits_csv": rules.withdrawal_gather.output.limits,
        "withdrawal_png": rules.withdrawal_plot.output.png,
        "setup_json": SETUP_JSON,
    },
}


def page_parameters(page):
    """papermill parameters of ``page``: the path of every artefact it reads (strings)."""
    parameters = {name: str(path) for name, path in PAGE_INPUTS[page].items()}
    if page == "benchmarks":
        parameters["rule_tsv_glob"] = "results/benchmarks/rules/*.tsv"
    return parameters


def report_inputs(pages):
    """Every artefact ``pages`` read, named <page>_<parameter>, their notebooks and their code."""
    inputs = {f"{page}_{name}": path for page in pages for name, path in PAGE_INPUTS[page].items()}
    if "benchmarks" in pages:
        inputs["rule_tsvs"] = [getattr(rules, r).benchmark for r in TIMED_RULES]
    notebooks = [f"notebooks/{page}.ipynb" for page in pages]
    # The page template is code too: editing it re-renders the pages.
    template = "src/vibroadhesion/pipeline/templates/offline/index.html.j2"
    return {**inputs, "notebooks": notebooks, "code": code("report", *notebooks) + [template]}


# The report jobs in this run's DAG, i.e. asked for by its targets: Snakemake evaluates a job's input function only
# while it builds the DAG of the requested targets, so the end-of-run hooks (common.smk refresh_report) touch the
# indexes of these jobs only, never an output of a target that was not asked for.
ASKED_REPORT_JOBS = set()


def asked_report_inputs(job, wildcards):
    """Input function of report job ``job``: its inputs (report_inputs), and the job noted in ASKED_REPORT_JOBS."""
    ASKED_REPORT_JOBS.add(job)
    return report_inputs(REPORT_JOBS[job][1])


# One job per entry of REPORT_JOBS renders its pages in one kernel (pipeline.steps.report): a kernel's start
# costs about as much as executing a page. A page's output is its executed notebook and its HTML page; the job of an
# index also writes the index.
for job, (index, pages) in REPORT_JOBS.items():

    rule:
        name:
            job
        input:
            unpack(partial(asked_report_inputs, job)),
        output:
            notebooks=[f"results/report/notebooks/{stem}.ipynb" for stem in pages],
            pages=[f"results/report/{stem}.html" for stem in pages],
            index=[f"results/report/{index}.html"] if index else [],
        log:
            f"results/logs/{job}.log",
        localrule: True
        params:
            pages={stem: page_parameters(stem) for stem in pages},
        script:
            "../scripts/report.py"
