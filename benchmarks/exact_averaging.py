"""Benchmark: exact averaging per point, this checkout against another checkout, side by side in one run.

Usage: python benchmarks/exact_averaging.py BASE_CHECKOUT [--repeats N] [--n N ...]

The levels of :mod:`vibroadhesion.models.exact_averaging` -- steady state (nominal point contact, 200 Hz),
pull-off at the critical radius (a_m = a_cr) and at the force minimum -- are timed one point per call at
the paper's conditions (published w0 and R, chi0 = 2.589e-2, h1 = 20, 40, 60, 80, 100 um) for each
exponent n. Each checkout runs in a worker process with its own interpreter (``BASE/.venv/bin/python``
for the base, this one's for this checkout; the two packages cannot share a process), and the workers
take turns, one repeat each, so that the machine's load hits both alike. A repeat is the mean time per
point over the five amplitudes; the table gives the min and median over the repeats and their ratios
(base/this). ``warm``: the table of alpha* for this n already built (every call after the first);
``cold``: each repeat at a fresh exponent (n perturbed by 1e-9 k + 1e-6 per level, relative), so this checkout
pays its table's pieces (the first amplitude builds those the five touch).
The largest relative difference between the checkouts over every number of the records is printed last.
"""

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

CHI0, RADIUS, OMEGA_CHECK_200HZ = 2.589e-2, 51.5e-3, 2 * np.pi * 200.0 * 51.5e-3 / 44.5e-6
AMPLITUDES_UM = (20.0, 40.0, 60.0, 80.0, 100.0)
FIELDS = {
    "steady state": ("Abar", "abar_m", "w_eff_ratio", "A_over_am", "pm_over_abs_pjkr"),
    "pull-off, a_m = a_cr": ("pulloff_ratio", "Abar_cr", "abar_m", "w_eff_ratio"),
    "pull-off, force minimum": ("pulloff_ratio", "Abar_cr", "abar_m", "w_eff_ratio"),
}


def solve(kind: str, eta1: float, law: object) -> object:
    """One point of one level, by the checkout this interpreter imports."""
    from vibroadhesion.models import exact_averaging as ea

    if kind == "steady state":
        return ea.nominal_point_contact(eta1, OMEGA_CHECK_200HZ, CHI0, law)
    if kind == "pull-off, a_m = a_cr":
        return ea.pulloff_at_critical_radius(eta1, CHI0, law)
    return ea.pulloff_at_force_minimum(eta1, CHI0, law)


def worker() -> None:
    """Answer one JSON request per stdin line: {kind, n} -> {mean seconds per point, numbers per point}."""
    from vibroadhesion.core.ratelaw import GentSchultz

    for line in sys.stdin:
        request = json.loads(line)
        law = GentSchultz(request["n"])
        seconds, numbers = [], []
        for h1 in AMPLITUDES_UM:
            start = time.perf_counter()
            record = solve(request["kind"], h1 * 1e-6 / RADIUS, law)
            seconds.append(time.perf_counter() - start)
            numbers.append([float(getattr(record, f)) for f in FIELDS[request["kind"]]])
        print(json.dumps({"seconds": statistics.mean(seconds), "numbers": numbers}), flush=True)


def ask(process: subprocess.Popen, kind: str, n: float) -> dict:
    """One request to a worker process and its answer."""
    process.stdin.write(json.dumps({"kind": kind, "n": n}) + "\n")
    process.stdin.flush()
    return json.loads(process.stdout.readline())


def main() -> None:
    """Time both checkouts in turn and print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base", type=Path, help="the other checkout (e.g. the main a change starts from)")
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--n", type=float, nargs="+", default=[0.531, 2.5])
    args = parser.parse_args()
    pythons = {"base": str(args.base / ".venv/bin/python"), "this": sys.executable}
    workers = {
        name: subprocess.Popen(
            [python, __file__, "--worker"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            cwd=str(args.base if name == "base" else Path(__file__).parents[1]),
        )
        for name, python in pythons.items()
    }
    rows, worst = [], 0.0
    for n in args.n:
        for index, kind in enumerate(FIELDS):
            for mode in ("warm", "cold"):
                times = {"base": [], "this": []}
                for k in range(args.repeats + 1):  # repeat 0 warms both up (imports, this checkout's table)
                    trial = n * (1 + 1e-9 * (k + 1) + 1e-6 * index) if mode == "cold" else n
                    answers = {name: ask(workers[name], kind, trial) for name in ("base", "this")}
                    if k:
                        for name in times:
                            times[name].append(answers[name]["seconds"])
                    base, this = np.array(answers["base"]["numbers"]), np.array(answers["this"]["numbers"])
                    worst = max(worst, float(np.nanmax(np.abs(this / base - 1))))
                row = {"n": n, "level": kind, "mode": mode}
                for stat, f in (("min", min), ("median", statistics.median)):
                    row |= {
                        f"base {stat} ms": 1e3 * f(times["base"]),
                        f"this {stat} ms": 1e3 * f(times["this"]),
                        f"ratio {stat}": f(times["base"]) / f(times["this"]),
                    }
                rows.append(row)
    for w in workers.values():
        w.stdin.close()
        w.wait()
    import pandas as pd

    print(
        f"Exact averaging per point: base {args.base} against this checkout, {args.repeats} repeats in turn "
        f"(mean over h1 = {', '.join(f'{h:g}' for h in AMPLITUDES_UM)} um per repeat)"
    )
    print(pd.DataFrame(rows).to_string(index=False, float_format=lambda v: f"{v:.3g}"))
    print(f"largest relative difference between the checkouts, every number of every record: {worst:.2e}")


if __name__ == "__main__":
    worker() if sys.argv[1:] == ["--worker"] else main()
