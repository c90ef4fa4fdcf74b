# The user's inputs, validated (again: the Snakefile checked them before planning) and written as canonical
# copies. Two rules, so that an edit of data/pulloff.csv reaches only what depends on the measured rows (the
# fit, Figs. 4 and 7, their pages), while everything at the published parameters of data/setup.yaml stays.


rule ingest_setup:
    """Validate data/setup.yaml against its schema; write its canonical copy (values, units, sources)."""
    input:
        setup=config["data"]["setup"],
        schema="src/vibroadhesion/pipeline/schemas/setup.schema.json",
        code=code("ingest_setup"),
    output:
        "results/data/setup.json",
    log:
        "results/logs/ingest_setup.log",
    script:
        "../scripts/ingest_setup.py"


rule ingest_pulloff:
    """Validate data/pulloff.csv against its schema and the force scale of the rig; write its canonical copy."""
    input:
        pulloff=config["data"]["pulloff"],
        setup=rules.ingest_setup.output[0],
        schema="src/vibroadhesion/pipeline/schemas/pulloff.schema.json",
        code=code("ingest_pulloff"),
    output:
        "results/data/pulloff.csv",
    log:
        "results/logs/ingest_pulloff.log",
    script:
        "../scripts/ingest_pulloff.py"
