# Ground truth: every model level against the direct simulation (rigid nominal point contact, the
# simulated rows of results/simulation/), and the compliant resonance swept with the simulation.


rule validation_errors:
    """Relative errors of every level against the simulation and their summary."""
    input:
        **PUBLISHED,
        grid=rules.simulation_rigid_grid.output[0],
        code=code("validation_errors"),
    output:
        errors=report(
            "results/validation/rigid_errors.csv",
            caption="../report/validation_tables.rst",
            category="Validation",
            subcategory="Tables",
        ),
        summary=report(
            "results/validation/rigid_error_summary.csv",
            caption="../report/validation_tables.rst",
            category="Validation",
            subcategory="Tables",
        ),
    log:
        "results/logs/validation_errors.log",
    script:
        "../scripts/validation_errors.py"


rule validation_plot:
    input:
        **PUBLISHED,
        grid=rules.simulation_rigid_grid.output[0],
        errors=rules.validation_errors.output.errors,
        code=code("validation_plot"),
    output:
        pdf="results/validation/rigid_error_maps.pdf",
        png=report("results/validation/rigid_error_maps.png", caption="../report/validation.rst", category="Validation"),
    log:
        "results/logs/validation_plot.log",
    script:
        "../scripts/validation_plot.py"


rule validation_compliant:
    """Fig. 5's folded resonance (the simulated case of data/setup.yaml) swept up and down with the
    simulation (hysteresis, Floquet stability), and the refined model's curve of that case."""
    input:
        **PUBLISHED,
        kernels=rules.simulation_kernels.output[0],
        code=code("validation_compliant"),
    output:
        csv=report(
            "results/validation/compliant_sweep.csv",
            caption="../report/validation_tables.rst",
            category="Validation",
            subcategory="Tables",
        ),
        curve="results/validation/compliant_sweep_refined.csv",
    log:
        "results/logs/validation_compliant.log",
    benchmark:
        "results/benchmarks/rules/validation_compliant.tsv"
    params:
        sweep=config["validation"]["compliant_sweep"],
        curve_range=[config["fig5"]["omega_bar_min"], config["fig5"]["omega_bar_max"]],
    script:
        "../scripts/validation_compliant.py"


rule validation_compliant_plot:
    input:
        csv=rules.validation_compliant.output.csv,
        curve=rules.validation_compliant.output.curve,
        code=code("validation_compliant_plot"),
    output:
        pdf="results/validation/compliant_sweep.pdf",
        png=report(
            "results/validation/compliant_sweep.png", caption="../report/compliant_sweep.rst", category="Validation"
        ),
    log:
        "results/logs/validation_compliant_plot.log",
    script:
        "../scripts/validation_compliant_plot.py"
