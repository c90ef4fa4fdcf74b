"""The fit page (notebooks/fit.ipynb): every model level's Gent–Schultz fit as a reader compares them.

Reads the fit summary of rule ``fit_gent_schultz`` (results/fit/gent_schultz.json, written by
:func:`vibroadhesion.experiments.fitting.fit_gent_schultz` per level) and the ingested rows. The levels come in the
registry's order (:mod:`vibroadhesion.core.levels`), which puts the simulation of the full model first: it is the
headline when its fit converged (``fitted`` or ``at_bound``), the cheaper levels say what they would have given.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from vibroadhesion.core import levels
from vibroadhesion.pipeline import data
from vibroadhesion.pipeline.tables import Column, exact, plus_minus, significant

#: Statuses of a fit that converged to an estimate (:mod:`vibroadhesion.experiments.fitting`).
CONVERGED = ("fitted", "at_bound")

#: Columns of :func:`estimates` as the page shows them (units of docs/notation.md §1).
ESTIMATE_COLUMNS = {
    "level": Column("model level", format="text"),
    "status": Column("status", format="text"),
    "w0": Column("w0", "J/m²", "text"),
    "n": Column("n", format="text"),
    "v0": Column("v0", "m/s", "text"),
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
    """One parameter of one level's fit (Eqs. 71-72, 106): ``value ± SE``, or the value and why it has no SE.

    ``at bound`` (the search ended on the box), ``not identifiable`` (fitted, but the rows do not determine it),
    ``published`` (no rows), ``fixed: published`` (not fitted by this level, e.g. v0 of a frequency-independent one).
    Published values are shown as typed (:func:`~vibroadhesion.pipeline.tables.exact`), a bound to 3 figures (the
    page does not import the fit's box: :mod:`vibroadhesion.experiments.fitting` costs half a second to import).
    """
    entry = summary["parameters"][name]
    value = entry["estimate"]
    if entry["std_error"] is not None:
        return plus_minus(value, entry["std_error"])
    if name in summary.get("at_bound", ()):
        return f"{significant(value, 3)} (at bound)"
    if name in summary.get("free_parameters", ()):
        return f"{significant(value)} (not identifiable)"
    return f"{exact(value)} ({'published' if summary['status'] == 'published' else 'fixed: published'})"


def estimates(fit: dict[str, Any]) -> pd.DataFrame:
    """Per level: estimates with standard errors, misfit, status and its reason (:data:`ESTIMATE_COLUMNS`)."""
    rows = []
    for name in ordered_levels(fit):
        summary = fit["fits"][name]
        reasons = [text for text in (summary.get("note", ""), summary.get("v0_note", "")) if text]
        rows.append({"level": levels.level(name).label, "status": summary["status"],
                     **{p: estimate_text(p, summary) for p in ("w0", "n", "v0")},
                     "rms_relative_residual": summary.get("rms_relative_residual", np.nan),
                     "reason": "; ".join(reasons)})
    return pd.DataFrame(rows, columns=list(ESTIMATE_COLUMNS))


def figures_fit(fit: dict[str, Any]) -> pd.DataFrame:
    """:func:`estimates` of the fit the figures use, and of the headline fit when that is another level."""
    shown = {headline(fit), fit["figures_use"]} - {None}
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


def measured_vs_predicted(fit: dict[str, Any], rows: pd.DataFrame) -> pd.DataFrame:
    """Per measured row: frequency, h1, source, measured and predicted pull-off (mN) per level that fitted.

    Then the relative residual predicted/measured - 1 of the headline level (else of the figures' level), and the
    status of the simulation's virtual pull-off per row when the simulation was fitted (``contact_loss_*`` where
    the family lost contact before a pull-off).
    """
    table = rows[["line", "frequency_hz", "h1_um", "source", "pulloff_mN"]].set_index("line")
    reference = headline(fit) or fit["figures_use"]
    for name in ordered_levels(fit):
        predicted = predicted_mN(fit["fits"][name], rows)
        if predicted is not None:
            table[f"predicted_mN:{name}"] = predicted
    if f"predicted_mN:{reference}" in table:
        table[f"relative_residual:{reference}"] = table[f"predicted_mN:{reference}"] / table["pulloff_mN"] - 1
    status = {r["line"]: r["status"] for r in fit["fits"].get("simulation", {}).get("row_status", ())}
    if status:
        table["status:simulation"] = pd.Series(status)
    return table.reset_index(drop=True)


def measured_vs_predicted_columns(table: pd.DataFrame) -> dict[str, Column]:
    """How :func:`measured_vs_predicted`'s columns read: the level's name (short: the table is wide) and mN."""
    columns = {"pulloff_mN": Column("measured |P_cr|", "mN")}
    for name in table.columns:
        kind, _, level = str(name).partition(":")
        if kind == "predicted_mN":
            columns[name] = Column(f"predicted, {level.replace('_', ' ')}", "mN")
        elif kind == "relative_residual":
            columns[name] = Column(f"relative residual, {level}", format="rel")
        elif kind == "status":
            columns[name] = Column(f"row status, {level}", format="text")
    return columns


def long_predictions(table: pd.DataFrame) -> pd.DataFrame:
    """:func:`measured_vs_predicted` as (level label, measured, predicted) rows with a prediction, for the plot."""
    parts = [pd.DataFrame({"level": levels.level(str(name).partition(":")[2]).label,
                           "measured_mN": table["pulloff_mN"], "predicted_mN": table[name]})
             for name in table.columns if str(name).startswith("predicted_mN:")]
    if not parts:
        return pd.DataFrame(columns=["level", "measured_mN", "predicted_mN"])
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
        head = f"The headline is the fit of the full model (the simulation): **{simulation['status']}**"
    elif simulation:
        head = (f"The fit of the full model (the simulation) did not converge (**{simulation['status']}**: "
                f"{simulation.get('note', '')}); the cheaper levels are shown as they are")
    else:
        head = "The simulation is not among the fitted levels"
    return (f"{fit['data_rows']} measured rows. {head}. The figures use the **{fit['figures_use']}** fit.")


def measured_rows(pulloff_csv: str | Path) -> pd.DataFrame:
    """The ingested rows (results/data/pulloff.csv) with the ``line`` the fit's residuals refer to."""
    return data.read_canonical_pulloff(pulloff_csv)
