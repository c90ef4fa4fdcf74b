"""Benchmark: periodic steady states of the full model by shooting (vibroadhesion.simulation).

Usage: python benchmarks/simulate.py [OUT_TXT [OUT_CSV]] [--against PYTHON] [--compile]

OUT_CSV: the table of cases, one row per case (the report's benchmarks page shows it).

For each case it prints
* the time per steady state (min and median of 5 of process CPU time, of 3 for a case slower than 0.5 s; median
  of wall time), with the machine's load before and after the timings (a shared machine: the minimum is the least
  disturbed run),
* the periods integrated by the shooting,
* the self-consistency error: the largest relative change of a_m, Abar, w_eff/w0 and Pm when
  rtol goes from the default 1e-12 to 1e-13,
* the cost of reaching the same state by brute-force integration from the static state: the
  measured time per transient period times the number of periods the transient needs to come
  within 1e-10 of the orbit, ln(1e-10)/ln|multiplier| (the slowest Floquet multiplier), and the
  speed-up of the shooting over it.

With ``--compile`` (not in the pipeline's rule: it takes about a minute) also the one-off compilation
of the numba kernel: the first steady state of a fresh process with an empty cache, then with the
cache it wrote (every later call in any process is warm).

With ``--against PYTHON`` (the interpreter of another clone's environment, e.g. the main branch's
.venv/bin/python) it then times the paper's 200 Hz test (rigid, n = 0.531, h1 = 20, 60, 100 um):
one steady state from the static state and one whole virtual pull-off, in two worker processes
(this interpreter and PYTHON) asked in turn, so that both see the same load; it prints the min and
median wall time of each, their ratio and the largest relative difference of the results (a_m,
Abar, w_eff/w0, Pm of a steady state; the pull-off force of a pull-off, defined to ~1e-8: the state
at the pull-off, located to 1e-4 step in base_offset on a flat extremum, only to ~1e-6).
"""

import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
import pandas as pd

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.benchmarking import load_average, load_note, machine_description
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.simulation import steady_state, transient

CHI0, RADIUS, NU0 = 2.589e-2, 51.5e-3, 1.227e-5
FIELDS = ("abar_m", "Abar", "w_eff_ratio", "pm_over_abs_pjkr")
TRANSIENT_PERIODS = 5
REPEATS = 5
#: A case whose run takes longer than this (n = 4 at omega_check = 1e8: about 2 s) is timed 3 times, not REPEATS.
SLOW_RUN_S = 0.5
SLOW_REPEATS = 3
OMEGA_200HZ = 1454310.3070550503  # omega_check of 200 Hz for v0 = 44.5 um/s, R = 51.5 mm (groups.omega_check)
#: Run by each interpreter of the side-by-side comparison: reads "ss H1" or "vp H1", answers in JSON.
WORKER = f"""
import json, sys, time
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.virtual_pulloff import simulated_pulloff
from vibroadhesion.simulation import steady_state
def problem(h1):
    return Problem(GentSchultz(0.531), {CHI0!r}, h1 * 1e-6 / {RADIUS!r}, {OMEGA_200HZ!r})
steady_state(problem(20.0))
print("ready", flush=True)
for line in sys.stdin:
    kind, h1 = line.split()
    start = time.perf_counter()
    if kind == "ss":
        r = steady_state(problem(float(h1)))
        out = {{f: float(getattr(r, f)) for f in {FIELDS!r}}}
    else:
        r = simulated_pulloff(problem(float(h1)))
        out = {{"pulloff_ratio": float(r.pulloff_ratio)}}
    out["seconds"] = time.perf_counter() - start
    print(json.dumps(out), flush=True)
"""


def rigid(n, h1_um, omega_check):
    return Problem(GentSchultz(n), CHI0, h1_um * 1e-6 / RADIUS, omega_check)


def cases():
    for n in (0.531,):
        for h1 in (20.0, 60.0, 100.0):
            for omega_check in (1e4, 1e5, 1e6, 1e7, 1e8, 1e9):
                yield f"rigid n={n} h1={h1:g}um", rigid(n, h1, omega_check)
    for n, h1 in ((0.05, 5.0), (4.0, 20.0)):
        for omega_check in (1e4, 1e6, 1e8):
            yield f"rigid n={n} h1={h1:g}um", rigid(n, h1, omega_check)
    for kappa, zeta in ((0.01, 0.05), (0.1, 0.2)):
        for omega_bar in (1.0, 2.0, 17.85):
            yield (f"spring k={kappa} z={zeta}",
                   Problem(GentSchultz(0.531), CHI0, 20e-6 / RADIUS, omega_bar / NU0,
                           Fixation.compliant(kappa, zeta, NU0)))


def timed(function):
    cpu, wall, result = [], [], None
    while len(cpu) < (SLOW_REPEATS if cpu and cpu[0] > SLOW_RUN_S else REPEATS):
        c0, w0 = time.process_time(), time.perf_counter()
        result = function()
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
    return result, min(cpu), statistics.median(cpu), statistics.median(wall)


def row(label, problem):
    result, cpu_min, cpu, wall = timed(lambda: steady_state(problem))
    line = {"case": label, "omega_check": problem.omega_check, "status": str(result.status),
            "periods": result.orbit.iterations, "cpu_min_ms": 1e3 * cpu_min, "cpu_ms": 1e3 * cpu,
            "wall_ms": 1e3 * wall}
    if not result.ok:
        return line
    tight = steady_state(problem, rtol=1e-13)
    line["self_consistency"] = max(abs(float(getattr(tight, f) / getattr(result, f)) - 1) for f in FIELDS)
    slowest = float(np.max(np.abs(result.orbit.floquet_multipliers)))
    needed = math.inf if slowest >= 1 else max(1.0, math.log(1e-10) / math.log(max(slowest, 1e-300)))
    start = time.process_time()
    transient(problem, periods=TRANSIENT_PERIODS, initial_state=result.orbit.start_state)
    per_period = (time.process_time() - start) / TRANSIENT_PERIODS
    line.update(multiplier=slowest, transient_periods=needed, transient_s=needed * per_period,
                speedup=needed * per_period / cpu)
    return line


def format_rows(rows, load):
    """The table, at most 140 characters wide (a report page shows it unwrapped); "tr.": the brute-force transient."""
    header = (f"{'case':<23}{'omega_check':>11}{'status':>13}{'periods':>8}{'cpu min':>9}{'cpu med':>9}{'wall ms':>9}"
              f"{'rtol 1e-13 diff':>16}{'|m|max':>9}{'tr. periods':>12}{'tr. s':>12}{'speed-up':>9}")
    lines = [f"Shooting benchmark on {machine_description()}", load, "", header]
    for r in rows:
        text = (f"{r['case']:<23}{r['omega_check']:>11.0e}{r['status']:>13}{r['periods']:>8}"
                f"{r['cpu_min_ms']:>9.2f}{r['cpu_ms']:>9.2f}{r['wall_ms']:>9.2f}")
        if "self_consistency" in r:
            text += (f"{r['self_consistency']:>16.1e}{r['multiplier']:>9.6f}{r['transient_periods']:>12.3g}"
                     f"{r['transient_s']:>12.3g}{r['speedup']:>9.3g}")
        lines.append(text)
    cpu = [r["cpu_ms"] for r in rows if r["status"] == "ok" and r["case"].startswith("rigid n=0.531")]
    lines += ["", f"rigid n = 0.531, ok: median {statistics.median(cpu):.2f} ms, max {max(cpu):.2f} ms CPU "
              f"per steady state ({len(cpu)} cases)"]
    return "\n".join(lines) + "\n"


def start_worker(python):
    """A process of ``python`` running WORKER, once it has warmed up (imports, compiled-code cache)."""
    worker = subprocess.Popen([python, "-c", WORKER], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    if worker.stdout.readline().strip() != "ready":
        raise RuntimeError(f"{python}: the worker did not start")
    return worker


def ask(worker, command):
    """One timed command to a worker, its JSON answer."""
    worker.stdin.write(command + "\n")
    worker.stdin.flush()
    return json.loads(worker.stdout.readline())


#: Run in a fresh process: the time from the import of the package to the end of the first steady state.
FIRST_CALL = f"""
import time
start = time.perf_counter()
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.simulation import steady_state
steady_state(Problem(GentSchultz(0.531), {CHI0!r}, 20e-6 / {RADIUS!r}, {OMEGA_200HZ!r}))
print(time.perf_counter() - start)
"""


def compile_cost():
    """The one-off cost of the compiled kernel, min of 3 each.

    The first steady state of a fresh process with an empty numba cache (it compiles and writes the
    cache), then with that cache (it loads it).
    """
    cold, warm = [], []
    for _ in range(3):
        with tempfile.TemporaryDirectory() as cache:
            env = {**os.environ, "NUMBA_CACHE_DIR": cache}
            for times in (cold, warm):
                out = subprocess.run([sys.executable, "-c", FIRST_CALL], env=env, capture_output=True, text=True,
                                     check=True)
                times.append(float(out.stdout))
    return (f"\nFirst steady state of a fresh process (package import included, min of 3): "
            f"{min(cold):.2f} s with an empty numba cache (compiles it once), {min(warm):.2f} s with the cache\n")


def side_by_side(other_python):
    """Old (``other_python``) against new (this interpreter), asked in turn: min/median wall times and ratios."""
    workers = {"new": start_worker(sys.executable), "old": start_worker(other_python)}
    lines = ["", f"Side by side: old = {other_python}, new = {sys.executable} (wall ms, alternating, min / median)",
             f"{'what':<28}{'repeats':>8}{'old min':>10}{'old med':>10}{'new min':>10}{'new med':>10}"
             f"{'ratio min':>10}{'ratio med':>10}{'max rel diff':>14}"]
    for kind, h1, repeats in [("ss", h1, 3 * REPEATS) for h1 in ("20", "60", "100")] + [
            ("vp", h1, REPEATS) for h1 in ("20", "100")]:
        seconds, answers = {"old": [], "new": []}, {}
        for k in range(repeats):
            for name in ("old", "new") if k % 2 == 0 else ("new", "old"):
                answers[name] = ask(workers[name], f"{kind} {h1}")
                seconds[name].append(answers[name].pop("seconds"))
        diff = max(abs(answers["new"][f] / answers["old"][f] - 1) for f in answers["old"])
        old, new = seconds["old"], seconds["new"]
        what = ("steady state" if kind == "ss" else "virtual pull-off") + f", h1 = {h1} um"
        lines.append(f"{what:<28}{repeats:>8}{1e3 * min(old):>10.2f}{1e3 * statistics.median(old):>10.2f}"
                     f"{1e3 * min(new):>10.2f}{1e3 * statistics.median(new):>10.2f}{min(old) / min(new):>10.2f}"
                     f"{statistics.median(old) / statistics.median(new):>10.2f}{diff:>14.1e}")
    for worker in workers.values():
        worker.stdin.close()
        worker.wait()
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    args = sys.argv[1:]
    against = None
    if "--against" in args:
        at = args.index("--against")
        against = args[at + 1]
        del args[at : at + 2]
    before = load_average()
    rows = [row(*case) for case in cases()]
    text = format_rows(rows, load_note(before))
    if "--compile" in args:
        args.remove("--compile")
        text += compile_cost()
    print(text, end="", flush=True)
    if against is not None:
        comparison = side_by_side(against)
        print(comparison, end="")
        text += comparison
    if args:
        with open(args[0], "w", encoding="utf-8") as fh:
            fh.write(text)
    if len(args) > 1:
        write_csv(pd.DataFrame(rows), args[1])
