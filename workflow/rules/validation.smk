# Ground truth: every model level against the direct simulation (rigid nominal point contact).
# One job per base amplitude (independent, so a cluster runs them in parallel), then a gather.

VALIDATION_AMPLITUDES = config["validation"]["h1_um"]


rule validation_rigid:
    """Simulation, leading, refined, exact harmonic balance and exact averaging at one h1."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code(*NUMERICS, *SIMULATION, "progress", "exact_averaging", "frozen_radius", "exact_harmonic_balance", "compliant", "continuation",
                  "validation", "figures", "fitting", "data", "cli", "artefacts"),
    output:
        "results/validation/rigid/h1_{h1}.csv",
    params:
        lo=config["validation"]["log10_omega_check_min"],
        hi=config["validation"]["log10_omega_check_max"],
    log:
        "results/logs/validation_rigid_h1_{h1}.log",
    benchmark:
        "results/benchmarks/rules/validation_rigid_h1_{h1}.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli validate-rigid --setup {input.setup} --fit {input.fit} --h1-um {wildcards.h1} "
        "--log10-omega-min {params.lo} --log10-omega-max {params.hi} --out {output} 2>&1 | tee {log}"


rule validation_gather:
    """rigid_grid.csv (all levels), relative errors against the simulation and their summary."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        parts=expand("results/validation/rigid/h1_{h1}.csv", h1=VALIDATION_AMPLITUDES),
        code=code("validation", "data", "fitting", "cli", "artefacts"),
    output:
        grid="results/validation/rigid_grid.csv",
        errors="results/validation/rigid_errors.csv",
        summary="results/validation/rigid_error_summary.csv",
    log:
        "results/logs/validation_gather.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli validate-gather --setup {input.setup} --fit {input.fit} --parts {input.parts} "
        "--grid {output.grid} --errors {output.errors} --summary {output.summary} 2>&1 | tee {log}"


rule validation_plot:
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        grid="results/validation/rigid_grid.csv",
        errors="results/validation/rigid_errors.csv",
        code=code("figures", "data", "fitting", "cli", "artefacts"),
    output:
        pdf="results/validation/rigid_error_maps.pdf",
        png=report("results/validation/rigid_error_maps.png", caption="../report/validation.rst", category="Validation"),
    log:
        "results/logs/validation_plot.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli validate-plot --setup {input.setup} --fit {input.fit} --grid {input.grid} "
        "--errors {input.errors} --pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"


rule validation_compliant:
    """Fig. 5's folded resonance swept up and down with the simulation (hysteresis, Floquet stability)."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code(*NUMERICS, *SIMULATION, "progress", "compliant", "continuation", "validation", "figures", "fitting", "data", "cli",
                  "artefacts"),
    output:
        "results/validation/compliant_sweep.csv",
    params:
        sweep=config["validation"]["compliant_sweep"],
        h1=config["fig5"]["h1_um"],
    log:
        "results/logs/validation_compliant.log",
    benchmark:
        "results/benchmarks/rules/validation_compliant.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli validate-compliant --setup {input.setup} --fit {input.fit} --h1-um {params.h1} "
        "--kappa {params.sweep[kappa]} --zeta {params.sweep[zeta]} --omega-bar-min {params.sweep[omega_bar_min]} "
        "--omega-bar-max {params.sweep[omega_bar_max]} --points {params.sweep[points]} --out {output} 2>&1 | tee {log}"


rule validation_compliant_plot:
    input:
        csv="results/validation/compliant_sweep.csv",
        fig5="results/fig5/fig5.csv",
        code=code("figures", "cli", "artefacts"),
    output:
        pdf="results/validation/compliant_sweep.pdf",
        png=report("results/validation/compliant_sweep.png", caption="../report/validation.rst", category="Validation"),
    params:
        sweep=config["validation"]["compliant_sweep"],
    log:
        "results/logs/validation_compliant_plot.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli validate-compliant-plot --csv {input.csv} --fig5 {input.fig5} "
        "--kappa {params.sweep[kappa]} --zeta {params.sweep[zeta]} --pdf {output.pdf} --png {output.png} 2>&1 | tee {log}"


# Virtual pull-off experiment (simulated; no measured pull-off numbers are published): one job per
# fixation (rigid, or the compliant case of config virtual_pulloff.compliant) and test frequency,
# then a gather. Its rows never go to data/, which holds measurements.
VIRTUAL_PULLOFF = config["virtual_pulloff"]


def spring_arguments(wildcards):
    """--kappa/--zeta for the compliant jobs only (so a change of them does not rerun the rigid ones)."""
    if wildcards.fixation != "compliant":
        return ""
    return f"--kappa {VIRTUAL_PULLOFF['compliant']['kappa']} --zeta {VIRTUAL_PULLOFF['compliant']['zeta']}"


rule virtual_pulloff:
    """Quasi-static withdrawal of the base through periodic steady states: the simulated pull-off force."""
    input:
        setup="results/data/setup.json",
        fit="results/fit/gent_schultz.json",
        code=code(*NUMERICS, *SIMULATION, "progress", "exact_averaging", "frozen_radius", "compliant", "continuation", "virtual_pulloff",
                  "fitting", "data", "cli", "artefacts"),
    output:
        "results/validation/virtual_pulloff/{fixation}_{frequency}Hz.csv",
    wildcard_constraints:
        fixation="rigid|compliant",
        frequency=r"\d+",
    params:
        spring=spring_arguments,
    log:
        "results/logs/virtual_pulloff_{fixation}_{frequency}Hz.log",
    benchmark:
        "results/benchmarks/rules/virtual_pulloff_{fixation}_{frequency}Hz.tsv"
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli virtual-pulloff --setup {input.setup} --fit {input.fit} "
        "--frequency-hz {wildcards.frequency} --fixation {wildcards.fixation} {params.spring} --out {output} 2>&1 | tee {log}"


rule virtual_pulloff_fixation:
    """The three test frequencies of one fixation in one table. The rigid one is what Figs. 4 and 7
    overlay (built by the default target); the compliant one belongs to the validation target."""
    input:
        parts=expand("results/validation/virtual_pulloff/{{fixation}}_{frequency}Hz.csv",
                     frequency=VIRTUAL_PULLOFF["frequencies_hz"]),
        code=code("cli", "artefacts"),
    output:
        "results/validation/virtual_pulloff_{fixation}.csv",
    wildcard_constraints:
        fixation="rigid|compliant",
    log:
        "results/logs/virtual_pulloff_{fixation}.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli virtual-pulloff-gather --parts {input.parts} --out {output} 2>&1 | tee {log}"


rule virtual_pulloff_gather:
    """results/validation/virtual_pulloff.csv: both fixations, the table the issue and the README name."""
    input:
        parts=expand("results/validation/virtual_pulloff_{fixation}.csv", fixation=["rigid", "compliant"]),
        code=code("cli", "artefacts"),
    output:
        "results/validation/virtual_pulloff.csv",
    log:
        "results/logs/virtual_pulloff_gather.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.cli virtual-pulloff-gather --parts {input.parts} --out {output} 2>&1 | tee {log}"
