rule ingest:
    """Validate data/setup.yaml and data/pulloff.csv against their schemas; write canonical copies."""
    input:
        setup=config["data"]["setup"],
        pulloff=config["data"]["pulloff"],
        code=code("data"),
        schemas=["src/vibroadhesion/pipeline/schemas/setup.schema.json", "src/vibroadhesion/pipeline/schemas/pulloff.schema.json"],
    output:
        setup="results/data/setup.json",
        pulloff="results/data/pulloff.csv",
    log:
        "results/logs/ingest.log",
    shell:
        "{PYTHON} -m vibroadhesion.pipeline.data {input.setup} {input.pulloff} {output.setup} {output.pulloff} 2>&1 | tee {log}"
