"""Wall time of the pipeline in two checkouts, side by side: a cold run and a no-op run.

Usage: python benchmarks/pipeline_time.py CHECKOUT_A CHECKOUT_B [--repeats N] [TARGET ...]

Each checkout needs its own ``.venv`` (the README's install). For each of N repeats, and for A then
B in turn (so a change of the machine's load hits both alike), the script deletes ``results/``,
runs ``.venv/bin/snakemake -c2 [TARGET ...]`` from the checkout's root (cold: every job runs), then
runs it again (no-op: nothing to do, the cost of building the DAG). It prints the minimum and the
median of each, and the ratio B/A. A failed run stops the script with Snakemake's last lines.
It deletes and rebuilds each checkout's ``results/`` (keeping ``results/.gitkeep``); nothing else.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path


def timed_run(checkout: Path, targets: list[str]) -> float:
    """Seconds of one ``snakemake -c2`` in ``checkout`` with its own interpreter, the venv not activated."""
    env = {k: v for k, v in os.environ.items() if k != "VIRTUAL_ENV"}
    start = time.perf_counter()
    out = subprocess.run([str(checkout / ".venv/bin/snakemake"), "-c2", *targets], cwd=checkout, env=env,
                         capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if out.returncode != 0:
        sys.exit(f"snakemake failed in {checkout}:\n{out.stderr[-3000:]}")
    return seconds


def clear_results(checkout: Path) -> None:
    """Delete ``results/`` and put back the tracked ``results/.gitkeep``."""
    shutil.rmtree(checkout / "results", ignore_errors=True)
    (checkout / "results").mkdir()
    (checkout / "results/.gitkeep").touch()


def measure(checkouts: dict[str, Path], repeats: int, targets: list[str]) -> dict[tuple[str, str], list[float]]:
    """{(label, "cold" | "no-op"): seconds of each repeat}, A and B alternating."""
    times: dict[tuple[str, str], list[float]] = {(k, run): [] for k in checkouts for run in ("cold", "no-op")}
    for repeat in range(repeats):
        for label, checkout in checkouts.items():
            clear_results(checkout)
            times[label, "cold"].append(timed_run(checkout, targets))
            times[label, "no-op"].append(timed_run(checkout, targets))
            print(f"repeat {repeat + 1}/{repeats}, {label}: cold {times[label, 'cold'][-1]:.1f} s, "
                  f"no-op {times[label, 'no-op'][-1]:.2f} s", file=sys.stderr)
    return times


def table(checkouts: dict[str, Path], times: dict[tuple[str, str], list[float]]) -> str:
    """Min and median seconds per checkout and run, and the ratio B/A of each."""
    lines = [f"{'run':<6} {'checkout':<40} {'min s':>8} {'median s':>9}"]
    for run in ("cold", "no-op"):
        for label, checkout in checkouts.items():
            t = times[label, run]
            lines.append(f"{run:<6} {label + ' ' + str(checkout):<40} {min(t):>8.2f} {statistics.median(t):>9.2f}")
        a, b = times["A", run], times["B", run]
        lines.append(f"{run:<6} {'ratio B/A':<40} {min(b) / min(a):>8.2f} {statistics.median(b) / statistics.median(a):>9.2f}")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:
    """Parse the command line, measure, print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("a", type=Path, help="checkout A (e.g. the main the change starts from)")
    parser.add_argument("b", type=Path, help="checkout B (the change)")
    parser.add_argument("targets", nargs="*", help="Snakemake targets (default: the default target)")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_intermixed_args(argv)  # --repeats before, between or after the positionals
    checkouts = {"A": args.a.resolve(), "B": args.b.resolve()}
    print(table(checkouts, measure(checkouts, args.repeats, args.targets)))


if __name__ == "__main__":
    main()
