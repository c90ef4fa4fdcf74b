# Report: each page is a notebook executed by papermill, then rendered to HTML by nbconvert.
from vibroadhesion.pipeline.report import PAGES as REPORT_PAGES, VALIDATION_PAGES as VALIDATION_REPORT_PAGES

PAGE_INPUTS = {
    "fig3": {"fig_csv": "results/fig3/fig3.csv", "fig_png": "results/fig3/fig3.png",
             "fit_json": "results/fit/gent_schultz.json"},
    "fig4": {"fig_csv": "results/fig4/fig4.csv", "fig_png": "results/fig4/fig4.png",
             "fit_json": "results/fit/gent_schultz.json", "setup_json": "results/data/setup.json",
             "pulloff_csv": "results/data/pulloff.csv", "virtual_csv": "results/validation/virtual_pulloff_rigid.csv"},
    "fig5": {"fig_csv": "results/fig5/fig5.csv", "fig_png": "results/fig5/fig5.png",
             "markers_csv": "results/fig5/fig5_markers.csv", "counts_csv": "results/fig5/fig5_solution_count.csv",
             "setup_json": "results/data/setup.json", "fit_json": "results/fit/gent_schultz.json"},
    **{fig: {"fig_csv": f"results/{fig}/{fig}.csv", "fig_png": f"results/{fig}/{fig}.png",
             "fit_json": "results/fit/gent_schultz.json", "setup_json": "results/data/setup.json"}
       for fig in ("fig6", "fig7", "fig8")},
    "validation": {"grid_csv": "results/validation/rigid_grid.csv", "errors_csv": "results/validation/rigid_errors.csv",
                   "summary_csv": "results/validation/rigid_error_summary.csv",
                   "maps_png": "results/validation/rigid_error_maps.png",
                   "sweep_csv": "results/validation/compliant_sweep.csv",
                   "sweep_png": "results/validation/compliant_sweep.png",
                   "virtual_csv": "results/validation/virtual_pulloff.csv",
                   "setup_json": "results/data/setup.json", "fit_json": "results/fit/gent_schultz.json"},
    "fit": {"fit_json": "results/fit/gent_schultz.json", "setup_json": "results/data/setup.json"},
    "identifiability": {"fits_csv": "results/validation/identifiability/fits.csv",
                        "information_csv": "results/validation/identifiability/information.csv",
                        "sensitivity_csv": "results/validation/identifiability/sensitivity.csv",
                        "virtual_csv": "results/validation/virtual_pulloff_rigid.csv", "fit_json": "results/fit/gent_schultz.json"},
    "benchmarks": {"bench_csv": "results/benchmarks/j_integrals.csv", "bench_txt": "results/benchmarks/j_integrals.txt",
                   "simulate_txt": "results/benchmarks/simulate.txt",
                   "speed_txt": "results/benchmarks/speed_vs_error.txt", "speed_png": "results/benchmarks/speed_vs_error.png",
                   "rule_tsvs": [f"results/benchmarks/rules/{r}.tsv" for r in ("fit_gent_schultz", "fig3_data", "fig4_data", "fig5_data", "fig6_data", "fig7_data", "fig8_data")]},
}


def papermill_parameters(wildcards, input):
    """-r NAME PATH for every artefact the page reads (paths as strings: -r, not -p)."""
    args = [f"-r {name} {getattr(input, name)}" for name in PAGE_INPUTS[wildcards.page] if name != "rule_tsvs"]
    if wildcards.page == "benchmarks":
        args.append("-r rule_tsv_glob 'results/benchmarks/rules/*.tsv'")
    return " ".join(args)


rule execute_notebook:
    """Run one report notebook with papermill on the pipeline's artefacts."""
    input:
        unpack(lambda wc: PAGE_INPUTS[wc.page]),
        notebook="notebooks/{page}.ipynb",
        code=code("report", "data", "groups", "jkr"),
    output:
        "results/report/notebooks/{page}.ipynb",
    params:
        parameters=papermill_parameters,
    log:
        "results/logs/notebook_{page}.log",
    shell:
        "{PYTHON} -m papermill --no-progress-bar -k python3 --cwd . {input.notebook} {output} {params.parameters} "
        "> {log} 2>&1 || (cat {log} >&2; exit 1)"


rule render_page:
    """Render an executed notebook to a self-contained HTML page."""
    input:
        "results/report/notebooks/{page}.ipynb",
    output:
        "results/report/{page}.html",
    log:
        "results/logs/render_{page}.log",
    localrule: True
    shell:
        "{PYTHON} -m nbconvert --to html --output-dir results/report --output {wildcards.page} {input} > {log} 2>&1"


rule report_index:
    """Index of the figure pages (default target) or of the validation pages (``validation`` target)."""
    input:
        lambda wc: expand("results/report/{page}.html",
                          page=[stem for stem, _ in (REPORT_PAGES if wc.index == "index" else VALIDATION_REPORT_PAGES)]),
        code=code("report"),
    output:
        "results/report/{index}.html",
    wildcard_constraints:
        index="index|validation_index",
    log:
        "results/logs/report_{index}.log",
    localrule: True
    shell:
        "{PYTHON} -c 'from vibroadhesion.pipeline.report import write_index; write_index(\"{output}\")' > {log} 2>&1"
