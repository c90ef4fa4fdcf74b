rule simulation_kernels:
    """Compile the numba kernels of the simulation once and cache them, before the simulation jobs run in parallel."""
    input:
        code=code("simulation_kernels"),
    output:
        "results/simulation/kernels.txt",
    log:
        "results/logs/simulation_kernels.log",
    script:
        "../scripts/simulation_kernels.py"


# The direct simulation of the full model (ground truth), upstream of the figures that overlay it and of
# the validation that compares with it: results/simulation/.


rule simulation_rigid:
    """Simulation, leading, refined, exact harmonic balance and exact averaging at the base amplitudes of one job
    (wildcard h1: "20_40", the amplitudes in um joined by "_"; simulation_jobs.amplitudes_per_job), rigid nominal
    point contact."""
    input:
        **PUBLISHED,
        kernels=rules.simulation_kernels.output[0],
        code=code("simulation_rigid"),
    output:
        "results/simulation/rigid/h1_{h1}.csv",
    log:
        "results/logs/simulation_rigid_h1_{h1}.log",
    benchmark:
        "results/benchmarks/rules/simulation_rigid_h1_{h1}.tsv"
    wildcard_constraints:
        h1=r"[0-9._e+-]+",
    params:
        lo=config["validation"]["log10_omega_check_min"],
        hi=config["validation"]["log10_omega_check_max"],
    script:
        "../scripts/simulation_rigid.py"


rule simulation_rigid_grid:
    """rigid_grid.csv: every level at every amplitude; Fig. 6 overlays its simulated points."""
    input:
        parts=expand(rules.simulation_rigid.output[0], h1=AMPLITUDE_JOBS),
        code=code("simulation_rigid_grid"),
    output:
        "results/simulation/rigid_grid.csv",
    log:
        "results/logs/simulation_rigid_grid.log",
    script:
        "../scripts/simulation_rigid_grid.py"


# Virtual pull-off experiment (simulated; no measured pull-off numbers are published): one job per parameter set,
# fixation (rigid, or the simulated compliant case of data/setup.yaml) and share of the rig's test frequencies
# (wildcard frequency: "200_300", joined by "_"; simulation_jobs.frequencies_per_job), then a gather. Its rows never
# go to data/, which holds measurements. Two parameter sets, each its own named outputs: `published` (data/setup.yaml:
# the validation and the identifiability study) and `fitted` (the fit the figures use: the markers of Figs. 4 and 7,
# rerun by a data edit).


rule virtual_pulloff:
    """Quasi-static withdrawal of the base through periodic steady states: the simulated pull-off force."""
    input:
        unpack(parameter_inputs),
        kernels=rules.simulation_kernels.output[0],
        code=code("virtual_pulloff"),
    output:
        "results/simulation/{parameters}/virtual_pulloff/{fixation}_{frequency}Hz.csv",
    log:
        "results/logs/virtual_pulloff_{parameters}_{fixation}_{frequency}Hz.log",
    benchmark:
        "results/benchmarks/rules/virtual_pulloff_{parameters}_{fixation}_{frequency}Hz.tsv"
    wildcard_constraints:
        parameters="published|fitted",
        fixation="rigid|compliant",
        frequency=r"[0-9._]+",
    script:
        "../scripts/virtual_pulloff.py"


rule virtual_pulloff_fixation:
    """The test frequencies of one parameter set and fixation in one table."""
    input:
        parts=expand(
            rules.virtual_pulloff.output[0], parameters="{parameters}", fixation="{fixation}", frequency=FREQUENCY_JOBS
        ),
        code=code("virtual_pulloff_fixation"),
    output:
        "results/simulation/{parameters}/virtual_pulloff_{fixation}.csv",
    log:
        "results/logs/virtual_pulloff_{parameters}_{fixation}.log",
    wildcard_constraints:
        parameters="published|fitted",
        fixation="rigid|compliant",
    script:
        "../scripts/virtual_pulloff_fixation.py"


rule virtual_pulloff_gather:
    """virtual_pulloff.csv: both fixations at the published parameters, the table the README names."""
    input:
        parts=expand(rules.virtual_pulloff_fixation.output[0], parameters="published", fixation=["rigid", "compliant"]),
        code=code("virtual_pulloff_gather"),
    output:
        "results/simulation/virtual_pulloff.csv",
    log:
        "results/logs/virtual_pulloff_gather.log",
    script:
        "../scripts/virtual_pulloff_gather.py"


# The simulated rigid pull-off at the published parameters (the identifiability study's truth), and the one that
# Figs. 4 and 7 overlay: at the fit the figures use, which with no measured rows is the published set itself.
VIRTUAL_RIGID = expand(rules.virtual_pulloff_fixation.output[0], parameters="published", fixation="rigid")[0]
FIGURE_VIRTUAL = expand(
    rules.virtual_pulloff_fixation.output[0], parameters="fitted" if MEASURED_ROWS else "published", fixation="rigid"
)[0]
