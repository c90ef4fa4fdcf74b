# The base- and the force-excitation rigs compared (Figs. 1, 2; Eq. 13; Appendix B): the test frequencies and the
# fixation's anti-resonance omega0 (the cases), simulation_jobs.rig_cases_per_job of them per job (wildcard "200_300":
# the cases joined by "_"), gathered into one table, its summary and its figure.
RIG_CASES = FREQUENCIES + ["antiresonance"]
RIG_CASE_JOBS = job_chunks(RIG_CASES, config["simulation_jobs"]["rig_cases_per_job"])


rule rigs_part:
    """Leading order and simulation of both rigs at the cases of one job, every amplitude (published parameters)."""
    input:
        **PUBLISHED,
        kernels=rules.simulation_kernels.output[0],
        # The base rig's pull-offs at the test frequencies: the compliant virtual pull-off's (the same families).
        virtual=expand(
            rules.virtual_pulloff.output[0], parameters="published", fixation="compliant", frequency=FREQUENCY_JOBS
        ),
        code=code("rigs_part"),
    output:
        "results/validation/rigs/{case}.csv",
    log:
        "results/logs/rigs_part_{case}.log",
    benchmark:
        "results/benchmarks/rules/rigs_part_{case}.tsv"
    wildcard_constraints:
        case=r"(antiresonance|[0-9.]+)(_(antiresonance|[0-9.]+))*",
    script:
        "../scripts/rigs_part.py"


rule rigs_gather:
    """Every case in results/validation/rig_comparison.csv, and the force rig's difference from the base rig."""
    input:
        parts=expand(rules.rigs_part.output[0], case=RIG_CASE_JOBS),
        code=code("rigs_gather"),
    output:
        csv=report(
            "results/validation/rig_comparison.csv",
            caption="../report/rigs_tables.rst",
            category="Rigs",
            subcategory="Tables",
        ),
        summary=report(
            "results/validation/rig_equivalence.csv",
            caption="../report/rigs_tables.rst",
            category="Rigs",
            subcategory="Tables",
        ),
    log:
        "results/logs/rigs_gather.log",
    localrule: True
    script:
        "../scripts/rigs_gather.py"


rule rigs_plot:
    input:
        csv=rules.rigs_gather.output.csv,
        code=code("rigs_plot"),
    output:
        pdf="results/validation/rig_comparison.pdf",
        png=report("results/validation/rig_comparison.png", caption="../report/rigs.rst", category="Rigs"),
    log:
        "results/logs/rigs_plot.log",
    localrule: True
    script:
        "../scripts/rigs_plot.py"
