"""Benchmark: the full model as a fit level (vibroadhesion.experiments.simulation_fit).

Usage: python benchmarks/simulation_fit.py [--fit] [--coverage] [--sets] [--starts] [--speed] [OUT_TXT]

1. Derivatives of the simulated pull-off, d ln P_cr / d ln theta for w0, n, v0 at the published parameters:
   the envelope theorem (two warm orbits per parameter at the fixed pull-off offset) against central
   differences of re-traced families (the sensitivity rule's way), step 1e-3 in ln theta. Per (f, h1):
   the time of each (min and median of 5 repeats, wall), their ratio, and the largest difference.
2. With ``--fit``: the issue-13 target, the fit of the 15 simulated rigid rows (200/300/400 Hz x 20..100 um,
   published parameters, noise-free) from w0 +50 %, n -40 %: wall time, families traced, recovered errors.
3. With ``--coverage``: the same 15 simulated rows with 1 % multiplicative noise, P (1 + 0.01 z) with z standard
   normal from ``numpy.random.default_rng(seed)``, seeds 0..9, fitted the same way. Per seed: status, the
   estimates with their standard errors, whether each true value lies within estimate +- 2 SE; then the number of
   seeds whose interval covers each parameter (target: at least 8 of 10).
4. With ``--sets``: the noise-free recovery of two other true parameter sets, n = 0.3 and n = 1.0 (w0 and v0 as
   published), from w0 +50 %, n -40 % of each. A row whose virtual pull-off at the truth ends without a pull-off
   (at n = 0.3 the vibration loses the contact at large h1 while the mean force is still compressive) has no
   simulated force: it is listed with its status and left out of the fit.
5. With ``--starts``: every 3 of the 7 rows of the n = 0.3 set that have a simulated pull-off at the truth (35
   triples, noise-free), fitted from w0 +50 %, n -40 % and from the published parameters (the fit's usual start):
   per triple and start the status, the largest relative error of w0 and n, the wall time; then the count fitted.
6. With ``--speed``: rows at a withdrawal speed (issue 15; vibroadhesion.experiments.speed_fit), 200/300/400 Hz x
   20, 60 um at V = v0 and 3 v0 (12 rows, the withdrawal at the published parameters), fitted from w0 +50 %,
   n -40 %: wall time (min and median of REPEATS fits), withdrawals run, recovered errors; and the same rows
   fitted as quasi-static (the speed column dropped), whose bias shows what ignoring the speed costs.

Every pull-off "measured" here is simulated (the virtual pull-off at the true parameters), never data.
"""

import itertools
import math
import statistics
import sys
import time
from dataclasses import replace

import numpy as np
import pandas as pd

from vibroadhesion.experiments.benchmarking import machine_description
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters, jkr_mN
from vibroadhesion.experiments.envelope import envelope_log_derivatives, pulloff_problem
from vibroadhesion.experiments.speed_fit import speed_pulloff
from vibroadhesion.experiments.virtual_pulloff import simulated_pulloff, traced_pulloff

RADIUS = 51.5e-3
REDUCED_MODULUS = 2 * 2.8e6 / (1 - 0.5**2)  # data/setup.yaml: E* = f_storage E/(1 - nu^2)
GEOMETRY = {"radius": RADIUS, "reduced_modulus": REDUCED_MODULUS}
PUBLISHED = GentSchultzParameters(0.236, 0.531, 44.5e-6)
NAMES = ("w0", "n", "v0")
STEP = 1e-3
REPEATS = 5
PAIRS = [(f, h) for f in (200.0, 300.0, 400.0) for h in (20.0, 40.0, 60.0, 80.0, 100.0)]
NOISE = 0.01
SEEDS = range(10)
OTHER_EXPONENTS = (0.3, 1.0)
SPEED_KEYS = [(f, h, r * PUBLISHED.v0 * 1e6) for f in (200.0, 300.0, 400.0) for h in (20.0, 60.0) for r in (1.0, 3.0)]


def simulated(params, frequency_hz, h1_um):
    """Status and |P_cr| in mN of the virtual pull-off (rigid fixation; NaN where the family has no pull-off)."""
    record = simulated_pulloff(pulloff_problem(params, frequency_hz, h1_um, **GEOMETRY))
    return str(record.status), float(record.pulloff_ratio) * jkr_mN(params.w0, RADIUS)


def simulated_mN(params, frequency_hz, h1_um):
    """|P_cr| in mN of the virtual pull-off (rigid fixation)."""
    return simulated(params, frequency_hz, h1_um)[1]


def family_derivatives(frequency_hz, h1_um):
    """d ln P_cr / d ln theta by central differences of re-traced families."""
    values = []
    for name in NAMES:
        plus, minus = (simulated_mN(replace(PUBLISHED, **{name: getattr(PUBLISHED, name) * math.exp(s * STEP)}),
                                    frequency_hz, h1_um) for s in (1, -1))
        values.append(math.log(plus / minus) / (2 * STEP))
    return np.array(values)


def timed(function):
    """Result, min and median wall time of REPEATS calls."""
    times, result = [], None
    for _ in range(REPEATS):
        began = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - began)
    return result, min(times), statistics.median(times)


def derivative_table():
    """Part 1 of the module docstring."""
    rows = []
    for frequency_hz, h1_um in ((200.0, 20.0), (200.0, 100.0), (400.0, 100.0)):
        at = traced_pulloff(pulloff_problem(PUBLISHED, frequency_hz, h1_um, **GEOMETRY))[1]
        envelope, env_min, env_med = timed(lambda f=frequency_hz, h=h1_um, a=at: envelope_log_derivatives(
            PUBLISHED, f, h, a, NAMES, **GEOMETRY, step=STEP))
        families, fam_min, fam_med = timed(lambda f=frequency_hz, h=h1_um: family_derivatives(f, h))
        rows.append({"frequency_hz": frequency_hz, "h1_um": h1_um, "envelope_s_min": env_min,
                     "envelope_s_median": env_med, "families_s_min": fam_min, "families_s_median": fam_med,
                     "speedup_min": fam_min / env_min, "speedup_median": fam_med / env_med,
                     "max_abs_difference": float(np.max(np.abs(envelope - families)))})
    return pd.DataFrame(rows)


def simulated_rows(truth):
    """The 15 rows (PAIRS) with the virtual pull-off at ``truth``, labelled simulated, and its status per row.

    A row whose family ends without a pull-off (status other than ``pulloff``) has no force (NaN): it is not a
    measurement, and the callers leave it out of the fit and report it.
    """
    statuses, forces = zip(*(simulated(truth, f, h) for f, h in PAIRS), strict=True)
    return pd.DataFrame({"frequency_hz": [f for f, _ in PAIRS], "h1_um": [h for _, h in PAIRS],
                         "pulloff_mN": forces, "source": "simulated", "line": np.arange(2, 2 + len(PAIRS)),
                         "status": statuses})


def with_noise(rows, seed):
    """The rows' pull-off times (1 + NOISE z), z standard normal from default_rng(seed), labelled so."""
    z = np.random.default_rng(seed).standard_normal(len(rows))
    return rows.assign(pulloff_mN=rows["pulloff_mN"] * (1.0 + NOISE * z), source=f"simulated, 1 % noise seed {seed}")


def recovery(rows, truth):
    """Fit of ``rows`` with the simulation level from w0 +50 %, n -40 % of ``truth``: status, time, estimates.

    Per parameter: the estimate, its standard error (None where not fitted or on a bound), its relative error
    against ``truth`` and whether ``truth`` lies within estimate +- 2 SE.
    """
    start = replace(truth, w0=1.5 * truth.w0, n=0.6 * truth.n)
    began = time.perf_counter()
    summary = fit_gent_schultz(rows, "simulation", start, **GEOMETRY)
    record = {"status": summary["status"], "wall_s": time.perf_counter() - began,
              "families": summary.get("families_traced"), "free": ",".join(summary.get("free_parameters", []))}
    for name in NAMES:
        entry, true = summary["parameters"][name], getattr(truth, name)
        se = entry["std_error"]
        record |= {name: entry["estimate"], f"{name}_se": se, f"{name}_relative_error": entry["estimate"] / true - 1,
                   f"{name}_covered": None if se is None else abs(entry["estimate"] - true) <= 2 * se}
    return record


def target_fit():
    """Part 2 of the module docstring."""
    record = recovery(simulated_rows(PUBLISHED), PUBLISHED)
    return pd.DataFrame([{key: record[key] for key in ("status", "wall_s", "families", "free")}
                         | {f"{name}_relative_error": record[f"{name}_relative_error"] for name in NAMES}])


def coverage_table():
    """Part 3 of the module docstring: the per-seed table (v0 in um/s) and summary lines.

    The summary: per parameter, the seeds whose 2-SE interval covers the true value out of those that report a
    standard error; and, over the seeds that fit (w0, n) only, the standard deviation of the estimates across
    seeds (a Monte-Carlo reference for the standard error) beside the root mean square of the reported ones.
    """
    rows = simulated_rows(PUBLISHED)
    table = pd.DataFrame([{"seed": seed} | recovery(with_noise(rows, seed), PUBLISHED) for seed in SEEDS])
    lines = [f"{name}: true value inside estimate +- 2 SE in {sum(c is True for c in table[f'{name}_covered'])} of "
             f"{int(table[f'{name}_se'].notna().sum())} seeds with a standard error ({len(table)} seeds)"
             for name in NAMES]
    two = table[table["free"] == "w0,n"]
    lines += [f"{name} over the {len(two)} seeds fitting (w0, n): sd of the estimates {two[name].std():.3g}, "
              f"rms of the reported SE {math.sqrt((two[f'{name}_se'] ** 2).mean()):.3g}" for name in ("w0", "n")]
    table = table.assign(v0=table["v0"] * 1e6, v0_se=table["v0_se"] * 1e6).rename(
        columns={"v0": "v0_um_s", "v0_se": "v0_se_um_s"})
    return table[["seed", "status", "free", "w0", "w0_se", "n", "n_se", "v0_um_s", "v0_se_um_s", "w0_covered",
                  "n_covered", "v0_covered", "wall_s", "families"]], lines


def sets_table():
    """Part 4 of the module docstring: the table, and a line per row left out (no simulated pull-off at the truth)."""
    records, left_out = [], []
    for exponent in OTHER_EXPONENTS:
        truth = replace(PUBLISHED, n=exponent)
        rows = simulated_rows(truth)
        has_pulloff = rows["status"] == "pulloff"
        left_out += [f"n = {exponent:g}, {r.frequency_hz:g} Hz, h1 = {r.h1_um:g} um: {r.status}"
                     for r in rows[~has_pulloff].itertuples()]
        record = recovery(rows[has_pulloff], truth)
        records.append({"true_n": exponent, "rows": f"{int(has_pulloff.sum())}/{len(rows)}"}
                       | {key: record[key] for key in ("status", "wall_s", "families", "free")}
                       | {f"{name}_relative_error": record[f"{name}_relative_error"] for name in NAMES})
    return pd.DataFrame(records), left_out


def starts_table():
    """Part 5 of the module docstring: the table and the summary line."""
    truth = replace(PUBLISHED, n=OTHER_EXPONENTS[0])
    rows = simulated_rows(truth)
    rows = rows[rows["status"] == "pulloff"].drop(columns="status")
    starts = {"w0 +50 %, n -40 %": replace(truth, w0=1.5 * truth.w0, n=0.6 * truth.n), "published": PUBLISHED}
    records = []
    for triple in itertools.combinations(range(len(rows)), 3):
        chosen = rows.iloc[list(triple)]
        for label, start in starts.items():
            began = time.perf_counter()
            summary = fit_gent_schultz(chosen, "simulation", start, **GEOMETRY)
            error = max(abs(summary["parameters"][name]["estimate"] / getattr(truth, name) - 1) for name in ("w0", "n"))
            pairs = " ".join(f"{r.frequency_hz:g}/{r.h1_um:g}" for r in chosen.itertuples())
            records.append({"rows (f Hz/h1 um)": pairs, "start": label, "status": summary["status"],
                            "max_relative_error": error, "wall_s": time.perf_counter() - began})
    table = pd.DataFrame(records)
    fitted = table[(table["status"] == "fitted") & (table["max_relative_error"] < 1e-3)]
    return table, f"recovered to 1e-3: {len(fitted)} of {len(table)} fits"


def speed_rows():
    """Part 6's rows: the withdrawal at the published parameters for each of SPEED_KEYS, labelled simulated."""
    forces = [speed_pulloff(PUBLISHED, *key, **GEOMETRY).force_mN for key in SPEED_KEYS]
    return pd.DataFrame({"frequency_hz": [k[0] for k in SPEED_KEYS], "h1_um": [k[1] for k in SPEED_KEYS],
                         "pulloff_mN": forces, "source": "simulated", "line": np.arange(2, 2 + len(SPEED_KEYS)),
                         "withdrawal_speed_um_s": [k[2] for k in SPEED_KEYS]})


def speed_table():
    """Part 6 of the module docstring."""
    rows = speed_rows()
    start = replace(PUBLISHED, w0=1.5 * PUBLISHED.w0, n=0.6 * PUBLISHED.n)
    records = []
    quasi_static = rows.drop(columns="withdrawal_speed_um_s")
    for label, fitted in (("speed rows", rows), ("same rows as quasi-static", quasi_static)):
        summary, wall_min, wall_median = timed(lambda r=fitted: fit_gent_schultz(r, "simulation", start, **GEOMETRY))
        records.append({"rows": label, "status": summary["status"], "wall_s_min": wall_min,
                        "wall_s_median": wall_median, "withdrawals": summary.get("withdrawals_run", 0),
                        "families": summary.get("families_traced"), "free": ",".join(summary["free_parameters"]),
                        "rms_relative_residual": summary["rms_relative_residual"]}
                       | {f"{name}_relative_error": summary["parameters"][name]["estimate"] / getattr(PUBLISHED, name)
                          - 1 for name in NAMES})
    return pd.DataFrame(records)


def main(argv):
    """Print (and with OUT_TXT write) the tables."""
    out = [a for a in argv if not a.startswith("--")]
    text = [machine_description(), "", "d ln P_cr / d ln theta: envelope theorem against re-traced families "
            f"(step {STEP}, {REPEATS} repeats, wall s)", derivative_table().to_string(index=False)]
    if "--fit" in argv:
        text += ["", "full-model fit of the 15 simulated rigid rows from w0 +50 %, n -40 %",
                 target_fit().to_string(index=False)]
    if "--coverage" in argv:
        table, lines = coverage_table()
        text += ["", f"coverage: the 15 simulated rows times (1 + {NOISE} z), z ~ N(0, 1) from default_rng(seed), "
                 "fitted from w0 +50 %, n -40 %; covered = |estimate - true| <= 2 SE; v0 held at its true value "
                 "where not freed", table.to_string(index=False), *lines]
    if "--sets" in argv:
        table, left_out = sets_table()
        text += ["", "other true parameter sets (w0, v0 published), the 15 simulated noise-free rows that have a "
                 "simulated pull-off at the truth, fitted from w0 +50 %, n -40 %", table.to_string(index=False),
                 "rows without a simulated pull-off at the truth (left out of the fit):", *left_out]
    if "--starts" in argv:
        table, line = starts_table()
        text += ["", "n = 0.3 (w0, v0 published): every 3 of the simulated noise-free rows with a pull-off at the "
                 "truth, from two starts", table.to_string(index=False), line]
    if "--speed" in argv:
        text += ["", f"rows at a withdrawal speed: 200/300/400 Hz x 20, 60 um at V = v0, 3 v0 (simulated), fitted from "
                 f"w0 +50 %, n -40 % ({REPEATS} fits, wall s)", speed_table().to_string(index=False)]
    report = "\n".join(text)
    print(report)
    if out:
        with open(out[0], "w") as handle:
            handle.write(report + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
