rule ingest:
    """Validate data/setup.yaml and data/pulloff.csv against their schemas; write canonical copies."""
    input:
        setup=config["data"]["setup"],
        pulloff=config["data"]["pulloff"],
        schemas=[
            "src/vibroadhesion/pipeline/schemas/setup.schema.json",
            "src/vibroadhesion/pipeline/schemas/pulloff.schema.json",
        ],
        code=code("ingest"),
    output:
        setup="results/data/setup.json",
        pulloff="results/data/pulloff.csv",
    log:
        "results/logs/ingest.log",
    script:
        "../scripts/ingest.py"
