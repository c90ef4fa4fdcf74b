"""The findings on the report's index pages (results/report/index.html, validation_index.html), read from artefacts.

Nothing here is typed in: the build (commit and its date, from git), the pull-off amplification of every model
level against the SIMULATED pull-off at the test conditions (the virtual pull-off CSV), the fit (the fit JSON) and
the validity of each level (the validation's error summary, when the ``validation`` target has built it). The date
is the commit's, not the time of the build, so that the same tree gives the same page.
"""

from __future__ import annotations

import html
import time
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from vibroadhesion.core import levels
from vibroadhesion.pipeline import fit_report
from vibroadhesion.pipeline.pages import (
    VALIDATION_INDEX,
    VALIDATION_SUMMARY,
    build_paragraph,
    findings_of,
    findings_read_at,
    index_artefacts,
    write_index,
)
from vibroadhesion.pipeline.report import model_ratios
from vibroadhesion.pipeline.steps.inputs import parameter_label
from vibroadhesion.pipeline.tables import Column, show, significant

AMPLIFICATION_COLUMNS = {
    "level": Column("model level", format="text"),
    "fixation": Column("fixation", format="text"),
    "ratio_min": Column("P_cr/P_JKR, smallest"),
    "ratio_max": Column("P_cr/P_JKR, largest"),
    "error_min": Column("prediction/simulation − 1, from", format="rel"),
    "error_max": Column("prediction/simulation − 1, to", format="rel"),
    "points": Column("test conditions", format="int"),
}

VALIDITY_COLUMNS = {
    "level": Column("model level", format="text"),
    "max_error_experiments_applicable": Column("largest relative error at the test frequencies", format="rel"),
    "max_error_applicable": Column("largest relative error, A ≤ 0.1 a_m", format="rel"),
    "max_error_outside": Column("largest relative error, A > 0.1 a_m", format="rel"),
    "within": Column("grid points within 5 %", format="text"),
}


def amplification(virtual_csv: str | Path) -> pd.DataFrame:
    """Per fixation and level: P_cr/P_JKR over the test conditions and its error against the SIMULATED pull-off.

    The simulation's own row gives its range (a virtual experiment: periodic steady states of Eqs. 4-11); each
    prediction (Eq. 71 with its level's Abar_cr) is compared where the simulation found a pull-off.
    """
    virtual = pd.read_csv(virtual_csv)
    out = []
    for fixation, rows in virtual.groupby("fixation", sort=False):
        ratio = model_ratios(rows)
        sim = rows[rows["model"] == "simulation"].set_index(["frequency_hz", "h1_um"])
        simulated = ratio["simulation"].where(sim["status"].reindex(ratio.index) == "pulloff")
        for name in [m for m in levels.names("virtual_pulloff") if m in ratio.columns]:
            error = ratio[name] / simulated - 1
            label = levels.level(name).label + (" (SIMULATED)" if name == "simulation" else "")
            out.append({"level": label, "fixation": fixation, "ratio_min": ratio[name].min(),
                        "ratio_max": ratio[name].max(),
                        "error_min": None if name == "simulation" else error.min(),
                        "error_max": None if name == "simulation" else error.max(),
                        "points": int(error.notna().sum())})
    return pd.DataFrame(out, columns=list(AMPLIFICATION_COLUMNS))


def validity(summary_csv: str | Path) -> pd.DataFrame:
    """Per level: the largest relative error against the simulation (test frequencies; applicable; outside)."""
    summary = pd.read_csv(summary_csv)
    order = [name for name in levels.names("validation_rigid") if name in set(summary["model"])]
    summary = summary.set_index("model").loc[order].reset_index()
    summary["level"] = [levels.level(name).label for name in summary["model"]]
    summary["within"] = [f"{int(k)} of {int(n)}" for k, n in zip(summary["points_below_5pct"], summary["points"],
                                                                   strict=True)]
    return summary[list(VALIDITY_COLUMNS)]


def _table(frame: pd.DataFrame, columns: Mapping[str, Column]) -> str:
    return show(frame, columns)._repr_html_()


def fit_lead(fit: dict[str, Any]) -> str:
    """The index's first finding where the preferred level's fit of the measured rows is not used.

    Poor, at a bound or not determined: what the figures use instead and why; empty otherwise.
    """
    if not fit["data_rows"] or fit["figures_use"] == fit["figures_preferred"]:
        return ""
    preferred = fit["fits"][fit["figures_preferred"]]
    gof = preferred.get("goodness_of_fit", {}).get("text", "")
    used = "the published parameters" if fit["figures_use"] == "published" else f"the {fit['figures_use']} fit"
    return (f"<p class=\"lead\"><b>Your {fit['data_rows']} rows: {html.escape(fit['figures_reason'])}.</b> The "
            f"figures use {html.escape(used)}. {html.escape(gof)}{'.' if gof else ''} See the "
            "<a href=\"fit.html\">fit page</a>.</p>")


def findings(artefacts: Mapping[str, str | Path], validation_summary: str | Path = VALIDATION_SUMMARY,
             validation_index: str | Path = VALIDATION_INDEX) -> str:
    """The HTML of the findings: build, measured rows, the fit, the amplification per level, the validity per level.

    ``artefacts`` are the papermill parameters of the index's pages (``setup_json``, ``fit_json``, ``virtual_csv``);
    the validity comes from ``validation_summary`` when it exists (the Snakefile's onsuccess reads it again at the end
    of a run: :func:`refresh_findings`), linked to ``validation_index`` where that exists; Fig. 4's page, in the same
    directory, likewise. Each table's heading names its parameter set (:func:`parameter_label`): the fit and the
    SIMULATED pull-off of the figure index are at the set the figures use (with ``fit_json``; the validation index:
    the published set), the validity always at the published set.
    """
    parts = [build_paragraph()]
    setup_json, fit_json = artefacts["setup_json"], artefacts.get("fit_json")
    used_set = html.escape(parameter_label(setup_json, fit_json, math=False))
    if fit_json is not None:
        fit = fit_report.read_fit(fit_json)
        parts.append(fit_lead(fit))
        used = (html.escape(fit["status"]) if fit["data_rows"] else
                "nothing is fitted: the figures use the published parameters")
        fitted = fit_report.figures_fit(fit).drop(columns="reason")
        parts += [f"<h2>The fit (<a href=\"fit.html\">fit page</a>): the figures use the {used_set}</h2><p>"
                  f"{fit['data_rows']} measured rows in <code>data/pulloff.csv</code>; {used}.</p>",
                  _table(fitted, fit_report.ESTIMATE_COLUMNS) if len(fitted) else ""]
    if "virtual_csv" in artefacts:
        parts.insert(1, headline(amplification(artefacts["virtual_csv"])))
        fig4 = '<a href="fig4.html">Fig. 4</a>' if (Path(validation_index).parent / "fig4.html").exists() else "Fig. 4"
        page = fig4 if fit_json else '<a href="validation.html">validation page</a>'
        parts += [f"<h2>Pull-off amplification per model level against the SIMULATED pull-off ({page}) at the "
                  f"{used_set}</h2><p>P_cr/P_JKR over the test conditions (frequencies × amplitudes) of the virtual "
                  "pull-off experiment, a simulation of the full model, not a measurement, and each level's relative "
                  "error against it.</p>",
                  *_amplification_parts(amplification(artefacts["virtual_csv"]))]
    published_set = html.escape(parameter_label(setup_json, math=False))
    if "summary_csv" in artefacts:  # the validation index itself: its own pages
        parts.append(_validity_part(Path(artefacts["summary_csv"]), None, published_set))
    else:
        parts.append(_validity_part(Path(validation_summary), Path(validation_index), published_set))
    return "\n".join(parts)


def headline(table: pd.DataFrame) -> str:
    """The index's first finding: the paper's formulas and the exact averaging against the SIMULATED pull-off.

    ``table``: :func:`amplification` (rigid fixation, the figures' model); empty where the simulation found no
    pull-off (the table's notes say so).
    """
    rigid = table[table["fixation"] == "rigid"].set_index("level")
    label = {name: levels.level(name).label for name in ("leading", "refined", "exact_averaging")}
    sim = rigid[rigid.index.str.endswith("(SIMULATED)")]
    if sim.empty or not sim["points"].iloc[0] or label["leading"] not in rigid.index:
        return ""
    lead = rigid.loc[label["leading"]]
    text = (f"<p class=\"lead\"><b>What the reproduction found.</b> At the paper's test conditions the SIMULATED "
            f"pull-off of the full model (rigid fixation) is {significant(sim['ratio_min'].iloc[0], 3)}–"
            f"{significant(sim['ratio_max'].iloc[0], 3)} times the static JKR force. The paper's leading-order "
            f"formula predicts {significant(lead['ratio_min'], 3)}–{significant(lead['ratio_max'], 3)} times, "
            f"{significant(-100 * lead['error_max'], 2)}–{significant(-100 * lead['error_min'], 2)} % below the "
            "simulation" if lead["error_max"] < 0 else
            f"<p class=\"lead\"><b>What the reproduction found.</b> The paper's leading-order formula errs by "
            f"{_signed(100 * lead['error_min'])} % to {_signed(100 * lead['error_max'])} % against the "
            "SIMULATED pull-off of the full model")
    if label["exact_averaging"] in rigid.index:
        exact = rigid.loc[label["exact_averaging"]]
        text += (f"; the exact high-frequency averaging errs by {_signed(100 * exact['error_min'])} % to "
                 f"{_signed(100 * exact['error_max'])} %")
    return text + ".</p>"


def _signed(percent: float) -> str:
    """A per cent with its sign, two significant figures: ``−6.7``, ``+12``."""
    return ("+" if percent > 0 else "−" if percent < 0 else "") + significant(abs(percent), 2)


def _amplification_parts(table: pd.DataFrame) -> list[str]:
    """The amplification table, after a sentence for each fixation whose simulation found no pull-off at all."""
    simulated = table[table["level"].str.endswith("(SIMULATED)")]
    none = [str(fixation) for fixation, points in zip(simulated["fixation"], simulated["points"], strict=True)
            if points == 0]
    notes = [f"<p class=\"stale\"><strong>No SIMULATED pull-off ({html.escape(fixation)} fixation)</strong> at this "
             "parameter set: every family ended first (status on the Fig. 4 page), so no level is compared with "
             "it.</p>" for fixation in none]
    return [*notes, _table(table, AMPLIFICATION_COLUMNS)]


def _validity_part(summary_csv: Path, validation_index: Path | None, published_set: str) -> str:
    """The validity of each level at the published parameters (named by ``published_set``), or how to build it.

    The validation ignores the fit: its heading names the published set whatever the figures use. On the figure
    index the validation pages are linked only where ``validation_index`` exists (a stopped validation run may leave
    the summary without its pages); on the validation index itself (None) they are listed below.
    """
    head = "<h2>Validity of each level against the simulation"
    if not summary_csv.exists():
        return (f"{head}</h2><p>Not built yet: run <code>snakemake -c2 validation</code> for the validation pages "
                "(every level against the direct simulation).</p>")
    table = validity(summary_csv)
    if table["max_error_experiments_applicable"].isna().all():
        return (f"{head} at the {published_set}</h2><p>No level was compared with the simulation at the test "
                "frequencies: the simulation found no steady state there at the published parameters (validation "
                "page).</p>")
    best = table.loc[table["max_error_experiments_applicable"].idxmin()]
    pages = ("" if validation_index is None else '(<a href="validation_index.html">validation pages</a>) '
             if validation_index.exists() else "(its pages not built: run <code>snakemake -c2 validation</code>) ")
    return (f"{head} {pages}at the {published_set}</h2><p>At the published parameters, "
            "the largest relative errors of Ā, ā_m, w_eff/w0, A/a_m and P_m/|P_JKR| against the periodic steady states "
            f"of the full model. The most accurate level at the test frequencies, {html.escape(best['level'])}, errs "
            f"by up to {significant(100 * best['max_error_experiments_applicable'], 2)} %.</p>"
            + _table(table, VALIDITY_COLUMNS))


def refresh_findings(indexes: Mapping[str, Mapping[str, Mapping[str, str]]]) -> list[str]:
    """After every run (the Snakefile's onsuccess and onerror): rewrite the findings of each index that exists.

    ``indexes`` maps each index file to the papermill parameters of its pages (as :func:`render`). The job that
    writes an index may run before the artefacts of another target it reports on (the validity, built by the
    ``validation`` target in the same run); read again at the end, the findings show what the run left. An index
    whose artefacts are not all there (a run that stopped midway) keeps its findings: its stale marks say why. Each
    index is rewritten only when its findings change, else only its time is set to the reading's
    (:func:`~vibroadhesion.pipeline.pages.findings_read_at`, so the next run does not read them again); returns the
    indexes rewritten.
    """
    rewritten = []
    for index, parameters in indexes.items():
        artefacts = index_artefacts(parameters)
        if not Path(index).exists() or not all(Path(path).exists() for path in artefacts.values()):
            continue
        as_of = time.time_ns()
        text = findings(artefacts)
        if text != findings_of(index):
            write_index(index, findings=text, as_of_ns=as_of)
            rewritten.append(index)
        else:  # the same findings: the index keeps its bytes, and its time says they are current
            findings_read_at(index, as_of)
    return rewritten
