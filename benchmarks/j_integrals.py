"""Benchmark: J-integrals by the fixed rule and by scipy quad, speed against error.

Usage: python benchmarks/j_integrals.py [OUT_CSV [OUT_TXT]]

Prints the table; writes it as CSV and text when paths are given. The 30-digit reference is
the tests' own mpmath evaluation of Eqs. (28), (29), (36) (tests/mpmath_reference.py; stored at the error points,
tests/reference/j_integrals_mpmath.csv). Each method
is timed REPEATS times, the two in turn (min and median), with the machine's load before and after.
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from mpmath_reference import j_integrals_mp  # noqa: E402

from vibroadhesion.experiments.benchmarking import (  # noqa: E402
    benchmark_j_integrals,
    format_table,
    load_average,
    load_note,
)
from vibroadhesion.pipeline.artefacts import write_csv  # noqa: E402
from vibroadhesion.pipeline.atomic import atomic_path  # noqa: E402

REPEATS = 5

before = load_average()
table = benchmark_j_integrals(j_integrals_mp, repeats=REPEATS)
text = format_table(table, REPEATS, load_note(before))
print(text, end="")
if len(sys.argv) > 1:
    write_csv(table, sys.argv[1])
if len(sys.argv) > 2:
    with atomic_path(sys.argv[2]) as tmp:
        tmp.write_text(text)
