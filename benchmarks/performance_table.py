"""Rewrite docs/performance.md from the artefacts of a finished run.

Usage: python benchmarks/performance_table.py [RESULTS] [-o docs/performance.md]

RESULTS is the ``results/`` of one ``snakemake -c2 all validation`` (default: results). The tables are written by
:func:`vibroadhesion.pipeline.performance.performance_markdown`; this script only reads and writes the files.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from vibroadhesion.pipeline.performance import performance_markdown


def main() -> None:
    """Parse the arguments and write the document."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", nargs="?", default="results", type=Path)
    parser.add_argument("-o", "--output", default=Path("docs/performance.md"), type=Path)
    args = parser.parse_args()
    args.output.write_text(performance_markdown(args.results), encoding="utf-8")
    print(args.output.read_text(encoding="utf-8"))


if __name__ == "__main__":
    main()
