"""The fit page (notebooks/fit.ipynb): every model level's Gent–Schultz fit as a reader compares them.

Reads the fit summary of rule ``fit_gent_schultz`` (results/fit/gent_schultz.json, written by
:func:`vibroadhesion.experiments.fitting.fit_gent_schultz` per level) and the ingested rows. The levels come in the
registry's order (:mod:`vibroadhesion.core.levels`), which puts the simulation of the full model first: it is the
headline when its search reached an estimate (any status but ``failed`` and ``published``), the cheaper levels say
what they would have given. Each parameter is shown with its profile-likelihood interval where the rows determine
it, and as "not determined by these rows" where they do not (:mod:`vibroadhesion.experiments.fit_statistics`).

Each measured row is flagged where it lies outside the asymptotic levels' range (:func:`applicability`): the
refined model's A/a_m at detachment above APPLICABILITY_LIMIT (the paper's A <= 0.1 a_m, Sec. 3.5.3), or
omega_check (Eq. 105) outside VALIDATED_OMEGA_CHECK, where the validation has not compared them with the simulation.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from vibroadhesion.core import groups, levels
from vibroadhesion.experiments.pulloff import GentSchultzParameters, predict_pulloff
from vibroadhesion.models.refined import APPLICABILITY_LIMIT, VALIDATED_OMEGA_CHECK
from vibroadhesion.numerics.roots import NoRootError
from vibroadhesion.pipeline import data
from vibroadhesion.pipeline.tables import Column, exact, significant

#: Statuses of a fit whose search reached an estimate (:mod:`vibroadhesion.experiments.fit_summary`).
CONVERGED = ("fitted", "poor_fit", "at_bound", "not_identifiable")

#: A level's status as a reader says it.
STATUS_WORDS = {"fitted": "fitted", "poor_fit": "poor fit: the rows reject the model", "at_bound": "at a bound",
                "not_identifiable": "not every parameter determined", "failed": "failed",
                "published": "no rows: published values"}

#: Columns of :func:`estimates` as the page shows them (units of docs/notation.md §1).
ESTIMATE_COLUMNS = {
    "level": Column("model level", format="text"),
    "status": Column("status", format="text"),
    "w0": Column("w0 [interval]", "J/m²", "text"),
    "n": Column("n [interval]", format="text"),
    "v0": Column("v0 [interval]", "m/s", "text"),
    "rms_relative_residual": Column("misfit: rms relative residual", format="rel"),
    "reason": Column("status reason and notes", format="text"),
}


def read_fit(fit_json: str | Path) -> dict[str, Any]:
    """The fit summary of rule ``fit_gent_schultz``."""
    fit: dict[str, Any] = json.loads(Path(fit_json).read_text())
    return fit


def headline(fit: dict[str, Any]) -> str | None:
    """The level whose fit is the page's headline: the simulation of the full model when its fit converged."""
    simulation = fit["fits"].get("simulation")
    return "simulation" if simulation and simulation["status"] in CONVERGED else None


def ordered_levels(fit: dict[str, Any]) -> list[str]:
    """The fitted levels in the registry's order (the simulation first)."""
    return [name for name in levels.names("fit") if name in fit["fits"]]


def estimate_text(name: str, summary: dict[str, Any]) -> str:
    """One parameter of one level's fit (Eqs. 71-72, 106): ``value [lower, upper]``, or why it has no interval.

    ``fitted``: the estimate and its profile-likelihood interval; ``at_bound`` and ``not_identifiable``: "not
    determined by these rows" (with the bound it ran to); ``published``: the published value as typed
    (:func:`~vibroadhesion.pipeline.tables.exact`), "(published)" where nothing was fitted, "(fixed: published)"
    where this level did not fit it (e.g. v0 of a frequency-independent level).
    """
    entry = summary["parameters"][name]
    value, status = entry["estimate"], entry.get("status", "published")
    if status == "fitted":
        lower, upper = entry["interval"]
        return f"{significant(value, 3)} [{significant(lower, 3)}, {significant(upper, 3)}]"
    if status == "at_bound":
        return f"not determined by these rows (on its bound {significant(value, 3)})"
    if status == "not_identifiable":
        return "not determined by these rows"
    return f"{exact(value)} ({'published' if summary['status'] == 'published' else 'fixed: published'})"


def estimates(fit: dict[str, Any]) -> pd.DataFrame:
    """Per level: estimates with standard errors, misfit, status and its reason (:data:`ESTIMATE_COLUMNS`)."""
    rows = []
    for name in ordered_levels(fit):
        summary = fit["fits"][name]
        gof = summary.get("goodness_of_fit", {}).get("text", "")
        reasons = [text for text in (summary.get("note", ""), gof, summary.get("v0_note", "")) if text]
        rows.append({"level": levels.level(name).label, "status": STATUS_WORDS.get(summary["status"],
                                                                                    summary["status"]),
                     **{p: estimate_text(p, summary) for p in ("w0", "n", "v0")},
                     "rms_relative_residual": summary.get("rms_relative_residual", np.nan),
                     "reason": "; ".join(reasons)})
    return pd.DataFrame(rows, columns=list(ESTIMATE_COLUMNS))


def figures_fit(fit: dict[str, Any]) -> pd.DataFrame:
    """:func:`estimates` of the fit the figures use, and of the headline fit when that is another level."""
    shown = {headline(fit), fit["figures_use"]} - {None, "published"}
    labels = [levels.level(name).label for name in ordered_levels(fit) if name in shown]
    table = estimates(fit)
    return table[table["level"].isin(labels)].reset_index(drop=True)


def predicted_mN(summary: dict[str, Any], rows: pd.DataFrame) -> pd.Series | None:
    """One level's pull-off force at its fit per row (mN), or None when it fitted nothing.

    residual = model - measured (``residuals_mN``); a row whose simulated family ended without a pull-off
    (``row_status``, ``model_mN`` null) has no prediction (NaN), whatever the misfit counted for it.
    """
    if "residuals_mN" not in summary:
        return None
    residual = pd.Series({r["line"]: r["residual"] for r in summary["residuals_mN"]})
    predicted = rows.set_index("line")["pulloff_mN"] + residual.reindex(rows["line"]).to_numpy()
    for row in summary.get("row_status", ()):
        if row["model_mN"] is None:
            predicted.loc[row["line"]] = np.nan
    return predicted


def reference_level(fit: dict[str, Any]) -> str:
    """The level the page's residuals and ranges refer to.

    The headline, else the fit the figures use, else the first level whose search reached an estimate, else the
    first level.
    """
    if headline(fit):
        return "simulation"
    if fit["figures_use"] in fit["fits"]:
        return str(fit["figures_use"])
    reached = [name for name in ordered_levels(fit) if fit["fits"][name]["status"] in CONVERGED]
    return (reached or ordered_levels(fit))[0]


def outside_text(omega_check: float, a_over_am: float) -> str:
    """``inside``, or ``outside the asymptotic levels' range: `` and why (module docstring).

    ``a_over_am``: the refined model's A/a_m at detachment (NaN: it has no pull-off there); ``omega_check`` NaN for
    a static JKR test (h1 = 0, Eq. 70 at every level, inside).
    """
    reasons = []
    if math.isnan(a_over_am):
        reasons.append("A/a_m unknown (the refined model has no pull-off)")
    elif a_over_am > APPLICABILITY_LIMIT:
        reasons.append(f"A/a_m = {a_over_am:.2g} > {APPLICABILITY_LIMIT:g}")
    lo, hi = VALIDATED_OMEGA_CHECK
    if not math.isnan(omega_check) and not lo <= omega_check <= hi:
        reasons.append(f"ωR/v0 = {omega_check:.3g} outside {_validated_range()}")
    return "outside the asymptotic levels' range: " + ", ".join(reasons) if reasons else "inside"


def applicability(fit: dict[str, Any], rows: pd.DataFrame, setup_json: str | Path) -> pd.DataFrame:
    """Per row (index ``line``): omega_check, A/a_m and range at the reference fit (module docstring).

    omega_check = 2 pi f R/v0 (Eq. 105), the refined model's A/a_m at detachment (Eqs. 98, 106) and
    :func:`outside_text`, at the parameters of :func:`reference_level`'s fit. The refined model is solved once
    per distinct (f, h1) (:func:`predict_pulloff`); a static JKR test (h1 = 0, no frequency) has A = 0.
    """
    setup = data.read_canonical_setup(setup_json)
    estimates = fit["fits"][reference_level(fit)]["parameters"]
    params = GentSchultzParameters(*(float(estimates[name]["estimate"]) for name in ("w0", "n", "v0")))
    keys = [(0.0, 0.0) if h == 0 else (float(f), float(h)) for f, h in zip(rows["frequency_hz"], rows["h1_um"],
                                                                          strict=True)]
    ratio = {key: 0.0 if key[1] == 0 else _refined_ratio(params, *key, setup.radius, setup.reduced_modulus)
             for key in set(keys)}
    table = pd.DataFrame({"line": rows["line"], "omega_check": np.where(
        rows["h1_um"] > 0, groups.omega_check(rows["frequency_hz"], params.v0, setup.radius), np.nan)})
    table["A_over_am:refined"] = [ratio[key] for key in keys]
    table["range"] = [outside_text(w, r) for w, r in zip(table["omega_check"], table["A_over_am:refined"], strict=True)]
    return table.set_index("line")


def _refined_ratio(params: GentSchultzParameters, frequency_hz: float, h1_um: float, radius: float,
                    reduced_modulus: float) -> float:
    """A/a_m at the refined pull-off (Eqs. 98, 106) of one vibrated test; NaN where Eq. (106) has no root."""
    try:
        pulloff = predict_pulloff("refined", params, frequency_hz, h1_um, radius=radius,
                                  reduced_modulus=reduced_modulus)
    except NoRootError:
        return math.nan
    return float(pulloff.A_over_am)


#: How the columns of :func:`measured_table` read on a page.
MEASURED_COLUMNS = {"pulloff_mN": Column("measured |P_cr|", "mN"),
                    data.SPEED_COLUMN: Column("V, withdrawal speed", "µm/s")}


def measured_table(rows: pd.DataFrame) -> pd.DataFrame:
    """The measured rows (:func:`measured_rows`) as a page shows them: frequency, h1, source, |P_cr| in mN.

    A static JKR test has no frequency (NaN, shown "—", not the 0 of the canonical file); where a row has a withdrawal
    speed, the column ``withdrawal_speed_um_s`` (NaN, "—", for a quasi-static row).
    """
    speeds = rows[data.SPEED_COLUMN] if data.SPEED_COLUMN in rows else pd.Series(0.0, index=rows.index)
    table = rows[["frequency_hz", "h1_um", "source", "pulloff_mN"]].assign(
        frequency_hz=rows["frequency_hz"].where(rows["h1_um"] > 0))
    if (speeds > 0).any():
        table.insert(2, data.SPEED_COLUMN, speeds.where(speeds > 0))
    return table


def measured_vs_predicted(fit: dict[str, Any], rows: pd.DataFrame, setup_json: str | Path) -> pd.DataFrame:
    """Per measured row: :func:`measured_table`'s columns and the predicted pull-off (mN) per level that fitted.

    Then the relative residual predicted/measured - 1 of :func:`reference_level`, the status of the simulation's
    virtual pull-off per row when the simulation was fitted (``contact_loss_*`` where the family lost contact before
    a pull-off), and the asymptotic levels' range at that level's fit (:func:`applicability`).
    """
    table = measured_table(rows).set_axis(rows["line"])
    reference = reference_level(fit)
    for name in ordered_levels(fit):
        predicted = predicted_mN(fit["fits"][name], rows)
        if predicted is not None:
            table[f"predicted_mN:{name}"] = predicted
    if f"predicted_mN:{reference}" in table:
        table[f"relative_residual:{reference}"] = table[f"predicted_mN:{reference}"] / table["pulloff_mN"] - 1
    status = {r["line"]: r["status"] for r in fit["fits"].get("simulation", {}).get("row_status", ())}
    if status:
        table["status:simulation"] = pd.Series(status)
    table = table.join(applicability(fit, rows, setup_json))
    return table.reset_index(drop=True)


def measured_vs_predicted_columns(table: pd.DataFrame) -> dict[str, Column]:
    """How :func:`measured_vs_predicted`'s columns read: the level's name (short: the table is wide) and mN."""
    columns = dict(MEASURED_COLUMNS)
    for name in table.columns:
        kind, _, level = str(name).partition(":")
        if kind == "predicted_mN":
            columns[name] = Column(f"predicted, {level.replace('_', ' ')}", "mN")
        elif kind == "relative_residual":
            columns[name] = Column(f"relative residual, {level}", format="rel")
        elif kind == "status":
            columns[name] = Column(f"row status, {level}", format="text")
    columns |= {"omega_check": Column("ω̌ = ωR/v0 at the fit (Eq. 105)"),
                "A_over_am:refined": Column("A/a_m at detachment, refined"),
                "range": Column("asymptotic levels' range", format="text")}
    return columns


def long_predictions(table: pd.DataFrame) -> pd.DataFrame:
    """:func:`measured_vs_predicted` as (level label, measured, predicted, range) rows with a prediction, for the plot.

    ``range`` is the row's :func:`outside_text` (``inside`` where the table has no range column).
    """
    ranges = table["range"] if "range" in table else pd.Series("inside", index=table.index)
    parts = [pd.DataFrame({"level": levels.level(str(name).partition(":")[2]).label,
                           "measured_mN": table["pulloff_mN"], "predicted_mN": table[name], "range": ranges})
             for name in table.columns if str(name).startswith("predicted_mN:")]
    if not parts:
        return pd.DataFrame(columns=["level", "measured_mN", "predicted_mN", "range"])
    return pd.concat(parts, ignore_index=True).dropna(subset=["predicted_mN"])


#: How :func:`published_table` reads: the values as published (all their digits).
PUBLISHED_COLUMNS = {"value": Column("value", format="exact"), "unit": Column("unit", format="text")}


def published_table(fit: dict[str, Any]) -> pd.DataFrame:
    """The published Gent–Schultz parameters (Fig. 4 caption) with their units."""
    published = fit["published"]
    units = {"w0": "J/m²", "n": "–", "v0": "m/s"}
    return pd.DataFrame([{"quantity": name, "value": published[name], "unit": units[name]}
                         for name in ("w0", "n", "v0")])


def summary_sentence(fit: dict[str, Any]) -> str:
    """What the page shows, in a sentence: the headline fit and its status, or that there are no measured rows."""
    if fit["data_rows"] == 0:
        return ("`data/pulloff.csv` holds no measured rows, so nothing is fitted: every level and every figure "
                f"uses the published parameters (w0 = {exact(fit['published']['w0'])} J/m², n = "
                f"{exact(fit['published']['n'])}, v0 = {exact(fit['published']['v0'])} m/s).")
    lead = headline(fit)
    simulation = fit["fits"].get("simulation")
    if lead:
        head = f"The headline is the fit of the full model (the simulation): **{STATUS_WORDS[simulation['status']]}**"
    elif simulation:
        head = (f"The fit of the full model (the simulation) reached no estimate (**{simulation['status']}**: "
                f"{simulation.get('note', '')}); the cheaper levels are shown as they are")
    else:
        head = "The simulation is not among the fitted levels"
    used = ("the **published parameters**" if fit["figures_use"] == "published"
            else f"the **{fit['figures_use']}** fit")
    return (f"{fit['data_rows']} measured rows. {head}. The figures use {used}: {fit['figures_reason']}. Intervals "
            f"are {fit['settings']['confidence']:.0%} profile-likelihood intervals.")


def _validated_range() -> str:
    """VALIDATED_OMEGA_CHECK as text: ``10^3–10^8``."""
    lo, hi = VALIDATED_OMEGA_CHECK
    return f"10^{math.log10(lo):g}–10^{math.log10(hi):g}"


def range_sentence(table: pd.DataFrame) -> str:
    """One sentence on the rows outside the asymptotic levels' range (:func:`measured_vs_predicted`'s ``range``)."""
    outside = int((table["range"] != "inside").sum())
    limits = (f"the refined model's A/a_m at detachment at most {APPLICABILITY_LIMIT:g} (the paper's A ≤ 0.1 a_m, "
              f"Sec. 3.5.3) and ω̌ = ωR/v0 within {_validated_range()}, where the validation compares the levels "
              "with the simulation")
    if not outside:
        return f"All {len(table)} rows lie inside the asymptotic levels' range: {limits}."
    return (f"{outside} of {len(table)} rows lie outside the asymptotic levels' range ({limits}), marked in the plot "
            "and the table: there the cheaper levels' predictions are extrapolations, and only the full model (the "
            "simulation) applies.")


def speed_sentence(table: pd.DataFrame) -> str:
    """What the page says of rows measured at a withdrawal speed (:func:`measured_vs_predicted`); empty if none."""
    if data.SPEED_COLUMN not in table:
        return ""
    count = int(table[data.SPEED_COLUMN].notna().sum())
    return (f"{count} of {len(table)} rows were measured at a withdrawal speed V (`{data.SPEED_COLUMN}`; — in the "
            "table: quasi-static). The full "
            "model (the simulation) predicts each by the simulated withdrawal at that speed, read as the most tensile "
            "one-period mean of the load-cell force: the reading whose V → 0 limit is the quasi-static pull-off the "
            "other rows are fitted to. The asymptotic levels are quasi-static: they fit these rows as if V → 0, so "
            "their residuals there include the effect of the speed (a faster withdrawal pulls harder). A speed row "
            "without a prediction (—) is one whose withdrawal lost contact before its period-mean force passed an "
            "extremum, or did not run to detachment (its row status), counted as zero force in the misfit.")


def measured_rows(pulloff_csv: str | Path) -> pd.DataFrame:
    """The ingested rows (results/data/pulloff.csv) with the ``line`` the fit's residuals refer to."""
    return data.read_canonical_pulloff(pulloff_csv)


#: The parts of :func:`measured_vs_predicted` a page shows as tables of their own (one would be wider than the page):
#: heading, and the column-name prefixes of the part (each row also keeps its test conditions).
MEASURED_VS_PREDICTED_PARTS = (
    ("Pull-off force: measured and predicted by each level at its own fit", ("source", "pulloff_mN", "predicted_mN:")),
    ("Relative residual of each level (predicted / measured − 1)", ("relative_residual:",)),
    ("Status of each row's prediction per level", ("status:",)),
    ("The asymptotic levels' range at each row", ("omega_check", "A_over_am:", "range")),
)


def measured_vs_predicted_parts(table: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    """:func:`measured_vs_predicted` in the narrower tables of :data:`MEASURED_VS_PREDICTED_PARTS` (heading, rows).

    Each keeps the row's test conditions (frequency, amplitude, withdrawal speed where shown); a part without a column
    in ``table`` is left out.
    """
    keys = [c for c in ("frequency_hz", "h1_um", data.SPEED_COLUMN) if c in table.columns]
    out = []
    for heading, prefixes in MEASURED_VS_PREDICTED_PARTS:
        columns = [c for c in table.columns if c not in keys and str(c).startswith(prefixes)]
        if columns:
            out.append((heading, table[keys + columns]))
    return out
