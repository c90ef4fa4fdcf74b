"""Benchmark: this checkout's J-integral rule against another checkout's, side by side in one process.

Usage: python benchmarks/j_integrals_versions.py BASE_CHECKOUT [--repeats N] [--size N]

Loads ``BASE_CHECKOUT/src/vibroadhesion/core/integrals.py`` as a separate module (its imports,
the rate laws, come from this checkout) and times both ``j_integrals`` in turn, repeat after
repeat, on the same Abar; the error of each is against the tests' 30-digit mpmath reference
(tests/mpmath_reference.py). Prints min and median throughput, the error, and the speed-up of
this checkout over the base.
"""

import argparse
import importlib.util
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from mpmath_reference import j_integrals_mp  # noqa: E402

from vibroadhesion.core.integrals import j_integrals  # noqa: E402
from vibroadhesion.experiments.benchmarking import compare_j_integrals, format_comparison  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("base", type=Path, help="the other checkout (e.g. the main a change starts from)")
parser.add_argument("--repeats", type=int, default=7)
parser.add_argument("--size", type=int, default=200_000)
args = parser.parse_args()
spec = importlib.util.spec_from_file_location("base_integrals", args.base / "src/vibroadhesion/core/integrals.py")
assert spec is not None and spec.loader is not None
base = importlib.util.module_from_spec(spec)
spec.loader.exec_module(base)
rules = {f"base {args.base}": base.j_integrals, "this checkout": j_integrals}
print(format_comparison(compare_j_integrals(rules, j_integrals_mp, size=args.size, repeats=args.repeats), args.repeats),
      end="")
