import os

from vibroadhesion.pipeline.pages import REPORT_JOBS, THUMBNAILS


# Snakemake's report (`snakemake --report results/report.zip all validation`) shows the rendered report as one folder
# (pipeline.steps.site): a page marked for it on its own would land in a folder of its own in the zip, where its
# links to the index and the other pages lead nowhere. Part of the `validation` target, since the folder holds the
# pages of both indexes. The step reads the indexes' findings again in its copies, as the Snakefile's onsuccess does
# in results/report/ after it: the indexes are ancient() here, so that rewrite alone does not rerun this rule (a
# report job that runs does).
rule report_site:
    input:
        pages=[
            *ancient([path for job in REPORT_JOBS for path in getattr(rules, job).output.index]),
            *[path for job in REPORT_JOBS for path in getattr(rules, job).output.pages],
        ],
        figures=[os.path.normpath(f"results/report/{path}") for path in THUMBNAILS.values()],
        code=code("report_site"),
    output:
        report(
            directory("results/report_site"),
            htmlindex="report/index.html",
            caption="../report/site.rst",
            category="Report pages",
        ),
    log:
        "results/logs/report_site.log",
    localrule: True
    params:
        indexes={
            f"results/report/{index}.html": {stem: page_parameters(stem) for stem in pages}
            for index, pages in REPORT_JOBS.values()
            if index
        },
    script:
        "../scripts/report_site.py"
