"""Tables of the rendered report (results/report/); its pages and index: :mod:`vibroadhesion.pipeline.pages`.

Notebooks in notebooks/ call these functions on the pipeline's artefacts; they hold no model
code. Every table a page shows is built here, so the pages stay a few lines long.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from vibroadhesion.core import groups, levels
from vibroadhesion.core.records import PULLOFF_FOUND
from vibroadhesion.experiments.pulloff import jkr_mN
from vibroadhesion.pipeline import data
from vibroadhesion.pipeline.tables import Column, uniform

#: How a page shows :func:`setup_table`: the values as typed in data/setup.yaml (all digits), the source as text.
SETUP_COLUMNS = {"value": Column("value", format="exact"), "source": Column("source", format="text")}


#: The counts of the validation's error summary (results/validation/rigid_error_summary.csv); the rest are errors.
ERROR_SUMMARY_COLUMNS = {"points": Column("grid points", format="int"),
                         "points_below_5pct": Column("grid points within 5 %", format="int")}

#: How a page shows :func:`rule_timings`.
TIMING_COLUMNS = {"rule": Column("rule", format="text"), "wall_s": Column("wall time", "s"),
                  "cpu_s": Column("CPU time", "s"), "max_rss_MB": Column("peak memory", "MB")}


def setup_table(setup_json: str | Path) -> pd.DataFrame:
    """Every input value with its unit and source, as ingested from data/setup.yaml."""
    setup = data.read_canonical_setup(setup_json)
    rows = []
    for key, source in sorted(setup.sources.items()):
        rows.append({"quantity": key, "value": setup.values[key], "unit": setup.units.get(key, ""), "source": source})
    return pd.DataFrame(rows)


def derived_table(setup_json: str | Path, fit_json: str | Path | None = None) -> pd.DataFrame:
    """Dimensionless groups at one parameter set, with the formula of each.

    The set is the fit the figures use when ``fit_json`` is given (Figs. 4, 7), else the published set of
    data/setup.yaml (the paper's figures), as the page's figure uses it.
    """
    setup = data.read_canonical_setup(setup_json)
    if fit_json is None:
        which, w0, v0 = "published", setup.w0, setup.v0
    else:
        fit = json.loads(Path(fit_json).read_text())
        used = fit["figures_use"]
        p = fit["published"] if used == "published" else {
            name: entry["estimate"] for name, entry in fit["fits"][used]["parameters"].items()}
        which, w0, v0 = "published" if used == "published" else f"{used} fit", p["w0"], p["v0"]
    e_star, r = setup.reduced_modulus, setup.radius
    rows = [
        ("E*", e_star, "Pa", "f_storage E / (1 - nu^2) (Sec. 3.4, App. A)"),
        ("chi0", groups.chi0(w0, e_star, r), "1", "(9 pi w0 / (E* R))^(1/3), Eq. (64)"),
        ("a_o", groups.contact_radius_scale(w0, e_star, r), "m", "(2 pi w0 R^2 / E*)^(1/3), Eq. (86)"),
        ("|P_JKR|", jkr_mN(w0, r), "mN", "(3 pi / 2) R w0, Eq. (71)"),
    ]
    rows += [(f"eta1 at h1 = {h:g} um", float(groups.eta1(h * 1e-6, r)), "1", "h1 / R, Eq. (65)")
             for h in setup.amplitudes_um]
    rows += [(f"omega_check at {f:g} Hz", float(groups.omega_check(f, v0, r)), "1", "omega R / v0, Eq. (105)")
             for f in setup.frequencies_hz]
    return pd.DataFrame(rows, columns=["quantity", "value", "unit", "definition"]).assign(parameters=which)


def rows_at(table: pd.DataFrame, column: str, values: Sequence[float]) -> pd.DataFrame:
    """The rows of ``table`` whose ``column`` is closest to each of ``values`` (for compact display)."""
    picks = [int(np.argmin(np.abs(np.log(table[column].to_numpy()) - math.log(v)))) for v in values]
    return table.iloc[sorted(set(picks))]


def rows_at_each(table: pd.DataFrame, column: str, values: Sequence[float], by: str = "h1_um") -> pd.DataFrame:
    """:func:`rows_at` within each group of ``by`` (one block of rows per amplitude)."""
    return pd.concat([rows_at(rows, column, values) for _, rows in table.groupby(by, sort=True)])


def virtual_pulloff_tables(virtual_csv: str | Path) -> list[tuple[str, pd.DataFrame, str]]:
    """(heading, table, remark) per fixation of a virtual pull-off CSV.

    The table has P_cr/P_JKR of the SIMULATED pull-off and of each prediction present (columns in the
    order of the registry, :mod:`vibroadhesion.core.levels`), the
    relative error ``prediction / simulation - 1`` of each, the simulation's status and its
    number of steady states, indexed by (frequency, h1). The remark gives the simulated mean
    contact radius at pull-off as a share of the JKR critical radius (criterion a_m = a_cr, Eq. 60).
    """
    virtual = pd.read_csv(virtual_csv)
    out = []
    for fixation, rows in virtual.groupby("fixation", sort=False):
        case = ("" if fixation == "rigid" else
                f" (kappa = {rows['kappa'].iloc[0]:g}, zeta = {rows['zeta'].iloc[0]:g}; "
                "leading: Eqs. (67)-(69), refined: Eq. (90) at a_m = a_cr)")
        pulloff_ratio = model_ratios(rows)
        for model in pulloff_ratio.columns.drop("simulation"):
            pulloff_ratio[f"{model} error"] = pulloff_ratio[model] / pulloff_ratio["simulation"] - 1
        pulloff_ratio = pulloff_ratio.rename(columns={"simulation": "SIMULATED"})
        sim = rows[rows["model"] == "simulation"].set_index(["frequency_hz", "h1_um"])
        pulloff_ratio["status"], pulloff_ratio["steady states"] = sim["status"], sim["steady_states"]
        heading = (f"{fixation.upper()} fixation{case}. P_cr/P_JKR: the SIMULATED pull-off (a simulation, not a "
                   "measurement) and the predictions; \"error\" columns: prediction / simulation - 1.")
        out.append((heading, pulloff_ratio, _criterion_remark(str(fixation), sim)))
    return out


def model_ratios(rows: pd.DataFrame) -> pd.DataFrame:
    """P_cr/P_JKR of a virtual pull-off table's rows (one fixation) by (frequency, h1), one column per model level.

    Columns in the order of the registry (:mod:`vibroadhesion.core.levels`); the simulation's column is there even
    where no family found a pull-off (all NaN), so that the errors against it are NaN rather than missing.
    """
    ratio = rows.pivot(index=["frequency_hz", "h1_um"], columns="model", values="pulloff_ratio")
    return ratio[[m for m in levels.names("virtual_pulloff") if m in ratio.columns]]


def _criterion_remark(fixation: str, sim: pd.DataFrame) -> str:
    """The simulated mean contact radius at pull-off as a share of a_cr (Eqs. 60-61), or why there is none.

    ``sim``: the simulation's rows of one fixation (status, abar_m, abar_cr).
    """
    found = sim[sim["status"].isin(PULLOFF_FOUND)]
    if found.empty:
        counts = ", ".join(f"{status} at {count}" for status, count in sim["status"].value_counts(sort=False).items())
        budget = ("; budget_exceeded: the withdrawal took its budget of steps (FAMILY_BUDGET of "
                  "vibroadhesion.experiments.virtual_pulloff) first" if "budget_exceeded" in set(sim["status"]) else "")
        return (f"No SIMULATED pull-off ({fixation} fixation): every family ended without a tensile extremum of the "
                f"mean force ({counts} of {len(sim)} test conditions{budget}). The predictions have nothing to be "
                "compared with here.")
    share = found["abar_m"] / found["abar_cr"]
    return (f"At the simulated pull-off ({fixation} fixation, {len(found)} of {len(sim)} test conditions) the mean "
            f"contact radius is {100 * share.min():.0f}–{100 * share.max():.0f} % of the JKR critical radius a_cr of "
            "Eq. (61) (with the simulated w_eff): the paper's detachment criterion a_m = a_cr (Eq. 60) is not where "
            "the mean force peaks.")


def rule_timings(tsv_files: Sequence[str | Path]) -> pd.DataFrame:
    """Wall time, CPU time and peak memory of the rules that carry a ``benchmark:`` directive (one run each)."""
    rows = []
    for path in tsv_files:
        t = pd.read_csv(path, sep="\t")
        rows.append({"rule": Path(path).stem, "wall_s": float(t["s"].iloc[0]), "cpu_s": float(t["cpu_time"].iloc[0]),
                     "max_rss_MB": float(t["max_rss"].iloc[0])})
    return pd.DataFrame(rows)


def footnoted_limits(limits_csv: str | Path) -> tuple[pd.DataFrame, str]:
    """The withdrawal's speed limits (quasi_static_limits.csv) with the note that every row repeats as a footnote.

    Per share (1 %, 5 %): the speed V/v0 where there is one (one format: :func:`uniform`), else the row's own note
    in its place (no speed within that share); the method in words. The footnote is the note every row with a
    speed carries, once.
    """
    limits = pd.read_csv(limits_csv)
    out = limits[["fixation", "frequency_hz", "h1_um"]].copy()
    notes: set[str] = set()
    for share in ("1pct", "5pct"):
        speed, note = limits[f"V_over_v0_within_{share}"], limits[f"note_{share}"].astype(str)
        notes |= set(note[speed.notna()])
        shown = iter(uniform([v for v in speed if math.isfinite(v)]))
        out[f"V_over_v0_within_{share}"] = [next(shown) if math.isfinite(v) else n for v, n in zip(speed, note,
                                                                                                 strict=True)]
        out[f"method_{share}"] = limits[f"method_{share}"].astype(str).str.replace("_", " ").str.replace("/", " / ")
    footnote = f"Every speed: {'; '.join(sorted(notes))}." if notes else ""
    return out, footnote


#: How a page shows the benchmark of every model level (results/benchmarks/speed_vs_error.csv) in ms and per cent.
SPEED_COLUMNS = {"level": Column("model level", format="text"), "points": Column("points", format="int"),
                 "fastest_ms": Column("time per point, fastest", "ms"),
                 "median_ms": Column("time per point, median", "ms"),
                 "slowest_ms": Column("slowest point, median", "ms"),
                 "max_error_pct": Column("largest error vs simulation", "%"),
                 "median_error_pct": Column("median error vs simulation", "%")}


def speed_table(speed_csv: str | Path) -> pd.DataFrame:
    """The benchmark of every model level: times per solved point in ms, errors against the simulation in per cent."""
    table = pd.read_csv(speed_csv)
    return pd.DataFrame({"level": [levels.level(str(m)).label for m in table["model"]], "points": table["points"],
                         "fastest_ms": 1e3 * table["seconds_per_point_min"],
                         "median_ms": 1e3 * table["seconds_per_point_median"],
                         "slowest_ms": 1e3 * table["seconds_per_point_max"],
                         "max_error_pct": 100 * table["max_relative_error_vs_simulation"],
                         "median_error_pct": 100 * table["median_relative_error_vs_simulation"]})


def benchmark_conditions(txt: str | Path) -> str:
    """The lines of a benchmark's text report before its table (machine, load, repeats), as one paragraph."""
    head = Path(txt).read_text(encoding="utf-8").split("\n\n")[0]
    return " ".join(line.strip()[0].upper() + line.strip()[1:].rstrip(".") + "." for line in head.splitlines()
                    if line.strip())
