"""Benchmark: the pull-off sensitivity jobs, old (re-traced perturbed families) against new (envelope derivatives).

Usage: python benchmarks/pulloff_sensitivity.py BASE [--repeats N] [OUT_TXT]

BASE is a checkout of the main before issue 13 (e.g. 2d16d49) with its own ``.venv``; this checkout is the
new one. Both need ``results/data/setup.json`` and ``results/fit/gent_schultz.json`` (``snakemake -c2
results/fit/gent_schultz.json``; the published parameters when data/pulloff.csv has no rows). Each job's
step function runs in a fresh process of its checkout's interpreter, as Snakemake runs it: old, the 6
``pulloff_sensitivity`` jobs (w0, n, v0 scaled by e^(+-0.05), 15 families each); new, the
``pulloff_sensitivity`` jobs of the rig's test frequencies (the rows of sensitivity.csv), and apart, those of
the design's other candidate frequencies (workflow/config.yaml, ``frequencies_per_job`` in each). A job's
wall and CPU seconds are measured inside its process, from before the package import to the step's
return (the interpreter's own start, ~0.05 s, and Snakemake's are not counted). Old and new alternate
within each repeat; min and median over the repeats of each side's total, and their ratios.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

from vibroadhesion.experiments.benchmarking import machine_description

NEW = Path(__file__).resolve().parents[1]
JOB = """
import json, sys, time
wall, cpu = time.perf_counter(), time.process_time()
from vibroadhesion.pipeline.steps import identifiability as step
setup, fit, out, kind, arg = sys.argv[1:6]
if kind == "old":
    step.sensitivity_run(setup, fit, out, *arg.split("_"))
else:
    step.sensitivity_part(setup, fit, out, [float(f) for f in arg.split("_")], json.loads(sys.argv[6]))
print(json.dumps({"wall": time.perf_counter() - wall, "cpu": time.process_time() - cpu}))
"""


def run_job(checkout: Path, out: Path, kind: str, arg: str, extra: list[str]) -> dict[str, float]:
    """Wall and CPU seconds of one job's step function in a fresh process of ``checkout``'s interpreter."""
    results = checkout / "results"
    command = [str(checkout / ".venv/bin/python"), "-c", JOB, str(results / "data/setup.json"),
               str(results / "fit/gent_schultz.json"), str(out), kind, arg, *extra]
    done = subprocess.run(command, cwd=checkout, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{kind} job {arg} failed in {checkout}:\n{done.stderr[-3000:]}")
    return dict(json.loads(done.stdout.strip().splitlines()[-1]))


def jobs(base: Path) -> dict[str, list[tuple[Path, str, str, list[str]]]]:
    """The jobs of each side: (checkout, kind, argument, extra arguments)."""
    config = yaml.safe_load((NEW / "workflow/config.yaml").read_text())["identifiability"]["design"]
    setup = json.loads((NEW / "results/data/setup.json").read_text())
    rig = [f"{float(f):g}" for f in setup["test_conditions"]["frequencies"]["value"]]
    extra = sorted({f"{float(f):g}" for f in config["frequencies_hz"]} - set(rig), key=float)
    per_job = config["frequencies_per_job"]
    rig_jobs, extra_jobs = (["_".join(f[i:i + per_job]) for i in range(0, len(f), per_job)] for f in (rig, extra))
    amplitudes = [json.dumps(config["amplitudes_um"])]
    return {"old": [(base, "old", f"{p}_{s}", []) for p in ("w0", "n", "v0") for s in ("plus", "minus")],
            "new sensitivity": [(NEW, "new", f, amplitudes) for f in rig_jobs],
            "new design-only": [(NEW, "new", f, amplitudes) for f in extra_jobs]}


def measure(base: Path, repeats: int) -> dict[str, dict[str, list[float]]]:
    """{side: {"wall" | "cpu": total seconds of its jobs per repeat}}, the sides alternating."""
    plan = jobs(base)
    totals: dict[str, dict[str, list[float]]] = {side: {"wall": [], "cpu": []} for side in plan}
    with tempfile.TemporaryDirectory() as tmp:
        for repeat in range(repeats):
            for side, side_jobs in plan.items():
                times = [run_job(c, Path(tmp) / f"{k}_{a}.csv", k, a, e) for c, k, a, e in side_jobs]
                for key in ("wall", "cpu"):
                    totals[side][key].append(sum(t[key] for t in times))
                print(f"repeat {repeat + 1}/{repeats} {side}: {len(side_jobs)} jobs, wall "
                      f"{totals[side]['wall'][-1]:.2f} s, cpu {totals[side]['cpu'][-1]:.2f} s", file=sys.stderr)
    return totals


def table(totals: dict[str, dict[str, list[float]]]) -> str:
    """Min and median totals per side, and the ratios old/new sensitivity."""
    lines = [f"{'jobs':<18} {'wall min s':>11} {'wall med s':>11} {'cpu min s':>10} {'cpu med s':>10}"]
    for side, t in totals.items():
        lines.append(f"{side:<18} {min(t['wall']):>11.2f} {statistics.median(t['wall']):>11.2f} "
                     f"{min(t['cpu']):>10.2f} {statistics.median(t['cpu']):>10.2f}")
    old, new = totals["old"], totals["new sensitivity"]
    ratios = [f(old[key]) / f(new[key]) for key in ("wall", "cpu") for f in (min, statistics.median)]
    lines.append(f"{'old/new sensitivity':<18} {ratios[0]:>11.1f} {ratios[1]:>11.1f} "
                 f"{ratios[2]:>10.1f} {ratios[3]:>10.1f}")
    return "\n".join(lines)


def main(argv: list[str]) -> None:
    """Parse the command line, measure, print (and with OUT_TXT write) the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base", type=Path, help="checkout of the old code, with its own .venv")
    parser.add_argument("out", nargs="?", type=Path, help="also write the table here")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_intermixed_args(argv)
    before = os.getloadavg()[0]
    result = table(measure(args.base.resolve(), args.repeats))
    load = f"load average (1 min) {before:.1f} before, {os.getloadavg()[0]:.1f} after"
    heading = f"pull-off sensitivity jobs, {args.repeats} repeats, old = {args.base.resolve()}, new = {NEW}"
    report = "\n".join([machine_description(), load, "", heading, result])
    print(report)
    if args.out:
        args.out.write_text(report + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
