# Pull-off at a finite withdrawal speed (issue 15): the full model integrated in time with the base withdrawn
# at V (simulated), one job per fixation and simulation_jobs.frequencies_per_job test frequencies (wildcard
# "200_300_400", as the virtual pull-off's), at the published parameters; part of `validation`.
# The V -> 0 value of each test is the published virtual pull-off (read, not re-traced). The averaged slow flow
# (rigid only: the exact averaging's fixation) does not depend on the frequency: one job, placed at each
# frequency by the gather.


rule withdrawal:
    """Every amplitude of the rig at the job's frequencies withdrawn at the speeds of config withdrawal.speed_ratios
    down to the stopping rule (simulated)."""
    input:
        **PUBLISHED,
        kernels=rules.simulation_kernels.output[0],
        virtual_pulloff=expand(rules.virtual_pulloff_fixation.output[0], parameters="published", fixation="{fixation}"),
        code=code("withdrawal"),
    output:
        "results/withdrawal/{fixation}_{frequency}Hz.csv",
    log:
        "results/logs/withdrawal_{fixation}_{frequency}Hz.log",
    benchmark:
        "results/benchmarks/rules/withdrawal_{fixation}_{frequency}Hz.tsv"
    wildcard_constraints:
        fixation="rigid|compliant",
        frequency=r"[0-9.]+(_[0-9.]+)*",
    params:
        speed_ratios=lambda wildcards: config["withdrawal"]["speed_ratios"][wildcards.fixation],
        stop=lambda wildcards: config["withdrawal"]["stop"][wildcards.fixation],
    script:
        "../scripts/withdrawal.py"


rule withdrawal_slow_flow:
    """The averaged slow flow of every amplitude (rigid) at the speeds of config withdrawal.slow_flow_speed_ratios."""
    input:
        **PUBLISHED,
        code=code("withdrawal_slow_flow"),
    output:
        "results/withdrawal/slow_flow.csv",
    log:
        "results/logs/withdrawal_slow_flow.log",
    benchmark:
        "results/benchmarks/rules/withdrawal_slow_flow.tsv"
    params:
        speed_ratios=config["withdrawal"]["slow_flow_speed_ratios"],
    script:
        "../scripts/withdrawal_slow_flow.py"


rule withdrawal_gather:
    """speed_sweep.csv (both fixations, every test) and the speeds below which the quasi-static value holds."""
    input:
        **PUBLISHED,
        parts=expand(rules.withdrawal.output[0], fixation=["rigid", "compliant"], frequency=FREQUENCY_JOBS),
        slow_flow=rules.withdrawal_slow_flow.output[0],
        code=code("withdrawal_gather"),
    output:
        csv=report(
            "results/withdrawal/speed_sweep.csv",
            caption="../report/withdrawal_tables.rst",
            category="Withdrawal",
            subcategory="Tables",
        ),
        limits=report(
            "results/withdrawal/quasi_static_limits.csv",
            caption="../report/withdrawal_tables.rst",
            category="Withdrawal",
            subcategory="Tables",
        ),
    log:
        "results/logs/withdrawal_gather.log",
    localrule: True
    script:
        "../scripts/withdrawal_gather.py"


rule withdrawal_plot:
    input:
        csv=rules.withdrawal_gather.output.csv,
        code=code("withdrawal_plot"),
    output:
        pdf="results/withdrawal/speed_sweep.pdf",
        png=report("results/withdrawal/speed_sweep.png", caption="../report/withdrawal.rst", category="Withdrawal"),
    log:
        "results/logs/withdrawal_plot.log",
    localrule: True
    script:
        "../scripts/withdrawal_plot.py"
