rule ingest:
    """Validate data/setup.yaml and data/pulloff.csv against their schemas; write canonical copies."""
    input:
        setup=config["data"]["setup"],
        pulloff=config["data"]["pulloff"],
        code=code("data"),
        schemas=["src/vibroadhesion/schemas/setup.schema.json", "src/vibroadhesion/schemas/pulloff.schema.json"],
    output:
        setup="results/data/setup.json",
        pulloff="results/data/pulloff.csv",
    log:
        "results/logs/ingest.log",
    shell:
        "{PYTHON} -m vibroadhesion.data {input.setup} {input.pulloff} {output.setup} {output.pulloff} 2>&1 | tee {log}"
