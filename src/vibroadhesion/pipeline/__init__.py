"""The only layer that knows files, Snakemake, matplotlib and notebooks.

Ingestion and validation of ``data/``, deterministic artefact writers, figures, the report and the steps the rules
call.

Layer 5: imports from every layer below; nothing imports from it.
"""

__all__ = ["data", "artefacts", "imports", "figures", "pages", "report", "steps"]
