"""Schema-valid but degenerate data sets (issue 26, item 1): none breaks the fit, the tables, the plots or a page.

Each data set of :data:`CASES` passes the input checks of data/pulloff.csv, is ingested with the repository's
data/setup.yaml, fitted (the step of rule ``fit_gent_schultz`` with the cheap levels only: the full-model fit of
these rows takes minutes; the pipeline test at the end runs it on the worst set), tabled and drawn (the steps of
Figs. 4 and 7), and its pages are executed: the code cells of notebooks/fig4.ipynb, fig7.ipynb and fit.ipynb run
in this process on the artefacts (what papermill runs in a kernel), then the index's findings. Each case asserts
what a reader is told: the number of rows, the statement that stands in for a missing comparison, the status of
the fit. The virtual pull-off that the pages show is the package's own at parameters no data support (w0 =
0.001 J/m^2, n = 0.98: the full-model fit of the issue's five rows), where the family ends on its step budget.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import IPython.display
import nbformat
import numpy as np
import pandas as pd
import pytest
from conftest import PLAUSIBLE_FIVE, RADIUS, REDUCED_MODULUS

from vibroadhesion.experiments import virtual_pulloff
from vibroadhesion.experiments.pulloff import GentSchultzParameters
from vibroadhesion.pipeline import data, figures, front_page, page_figures
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.pages import write_index
from vibroadhesion.pipeline.steps import fit as fit_step
from vibroadhesion.pipeline.steps.fig4_fig7 import fig4_fig7_data
from vibroadhesion.pipeline.steps.plots import fig4_plot, fig7_plot

ROOT = Path(__file__).resolve().parents[2]
HEADER = "frequency_hz,h1_um,pulloff_mN,source"
#: name -> (the CSV's rows after the header, the rows the fit counts). Static rows: h1_um = 0, frequency empty or 0.
CASES: dict[str, tuple[str, int]] = {
    "no_rows": ("", 0),
    "one_row": ("200,40,300,lab\n", 1),
    "two_rows": ("200,40,300,lab\n300,60,450,lab\n", 2),
    "one_frequency": ("200,20,150,lab\n200,40,260,lab\n200,60,380,lab\n200,80,500,lab\n", 4),
    "static_only": (",0,57,lab\n,0,58.5,lab\n0,0,56,lab\n", 3),
    "replicates_only": ("200,40,300,lab\n200,40,310,lab\n200,40,295,lab\n", 3),
    "force_falls_with_amplitude": ("200,20,400,lab\n200,40,300,lab\n300,60,200,lab\n400,80,120,lab\n"
                                   "300,100,90,lab\n", 5),
    "frequencies_not_in_setup": ("150,40,250,lab\n500,40,350,lab\n800,60,500,lab\n", 3),
    "plausible_five": (PLAUSIBLE_FIVE, 5),
}
#: The cheap levels the figures may use here (workflow/config.yaml's fit.figures_use is one of the registry's).
CHEAP_LEVELS = ("leading", "refined")
#: Parameters far from every data set (the full-model fit of PLAUSIBLE_FIVE today) and one test condition there.
ABSURD = GentSchultzParameters(0.001, 0.98, 44.5e-6)


@pytest.fixture(scope="module")
def virtual_at_absurd_parameters(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The rigid virtual pull-off table at :data:`ABSURD`, 300 Hz, h1 = 20 um, as rule virtual_pulloff writes it."""
    table = virtual_pulloff.pulloff_table(ABSURD, 300.0, np.array([20.0]), radius=RADIUS,
                                          reduced_modulus=REDUCED_MODULUS)
    out = tmp_path_factory.mktemp("virtual") / "virtual_pulloff_rigid.csv"
    write_csv(table, out)
    return out


def test_a_family_at_absurd_parameters_ends_on_its_budget_with_a_status(virtual_at_absurd_parameters: Path) -> None:
    """From the preloaded start (base_offset = etahat = 61 a_o^2/R here) 0.2 per step, the family cannot reach a
    tensile force within FAMILY_BUDGET steps: it ends as budget_exceeded (not as a missing steady state), NaN force,
    having solved at least the budget's orbits, and the predictions are still there."""
    table = pd.read_csv(virtual_at_absurd_parameters)
    simulated = table[table["model"] == "simulation"].iloc[0]
    assert simulated["status"] == "budget_exceeded"
    assert np.isnan(simulated["pulloff_ratio"]) and np.isnan(simulated["pulloff_mN"])
    assert virtual_pulloff.FAMILY_BUDGET <= simulated["steady_states"] <= virtual_pulloff.FAMILY_BUDGET + 2
    assert (table[table["model"] != "simulation"]["status"] == "ok").all()


class _Shown:
    """What a page's cells display, as text: Markdown, tables (their HTML) and how many images."""

    def __init__(self) -> None:
        self.texts: list[str] = []
        self.images = 0

    def __call__(self, *objects: Any, **_: Any) -> None:
        """IPython.display.display, recorded."""
        for shown in objects:
            if isinstance(shown, IPython.display.Image):
                self.images += 1
            elif isinstance(shown, IPython.display.Markdown):
                self.texts.append(str(shown.data))
            else:
                self.texts.append(shown._repr_html_())

    @property
    def text(self) -> str:
        """Everything displayed, one string."""
        return "\n".join(self.texts)


def run_page(stem: str, parameters: dict[str, str], monkeypatch: pytest.MonkeyPatch) -> _Shown:
    """Execute the code cells of notebooks/<stem>.ipynb in this process with ``parameters`` after its parameters
    cell, as papermill does in a kernel; what the page would show is recorded."""
    shown = _Shown()
    monkeypatch.setattr(IPython.display, "display", shown)
    namespace: dict[str, Any] = {"__name__": f"page_{stem}"}
    for cell in nbformat.read(ROOT / "notebooks" / f"{stem}.ipynb", as_version=4).cells:
        if cell.cell_type == "code":
            exec(compile(cell.source, f"{stem}.ipynb", "exec"), namespace)  # noqa: S102 - the page's own code
            if "parameters" in cell.metadata.get("tags", ()):
                namespace.update(parameters)
    return shown


@pytest.fixture
def cheap_fit(monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    """The fit step with the cheap levels only (the registry's full-model level takes minutes on these rows)."""
    monkeypatch.setattr(fit_step, "names", lambda role: CHEAP_LEVELS)
    yield


def _artefacts(work: Path, rows: str, virtual: Path) -> dict[str, str]:
    """Ingest ``rows``, fit them, write Figs. 4 and 7's tables and plots in ``work``: the pages' parameters."""
    (work / "data.csv").write_text(f"{HEADER}\n{rows}")
    setup, pulloff, fit = str(work / "setup.json"), str(work / "pulloff.csv"), str(work / "fit.json")
    fig4, fig7 = str(work / "fig4.csv"), str(work / "fig7.csv")
    data.ingest(ROOT / "data/setup.yaml", work / "data.csv", setup, pulloff)
    fit_step.fit(setup, pulloff, fit, figures_use="refined")
    fig4_fig7_data(setup, fit, {"fig4": fig4, "fig7": fig7}, {"h1_max_um": 120.0, "points": 13},
                   {"log10_omega_check_min": 2, "log10_omega_check_max": 9, "points": 15})
    fig4_plot(setup, fit, pulloff, str(virtual), fig4, str(work / "fig4.pdf"), str(work / "fig4.png"))
    fig7_plot(setup, fit, pulloff, fig7, fig4, str(virtual), str(work / "fig7.pdf"), str(work / "fig7.png"))
    return {"fit_json": fit, "setup_json": setup, "pulloff_csv": pulloff, "virtual_csv": str(virtual)}


@pytest.mark.parametrize("case", list(CASES))
def test_a_degenerate_data_set_gives_every_artefact_and_page_and_says_what_it_lacks(
        case: str, cheap_fit: None, virtual_at_absurd_parameters: Path, tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    rows, counted = CASES[case]
    artefacts = _artefacts(tmp_path, rows, virtual_at_absurd_parameters)
    fit = json.loads(Path(artefacts["fit_json"]).read_text())
    assert fit["data_rows"] == counted and set(fit["fits"]) == set(CHEAP_LEVELS)
    statuses = {name: r["status"] for name, r in fit["fits"].items()}
    assert set(statuses.values()) <= {"fitted", "poor_fit", "at_bound", "not_identifiable", "failed", "published"}
    if case == "force_falls_with_amplitude":  # no Gent-Schultz parameters make the force fall with amplitude
        assert "fitted" not in statuses.values(), statuses
    for result in fit["fits"].values():  # a parameter called fitted has a closed interval and a relative SE <= 0.5
        for entry in result["parameters"].values():
            if entry["status"] == "fitted":
                assert None not in entry["interval"] and entry["std_error"] <= 0.5 * entry["estimate"], entry
    if fit["figures_use"] != "published":
        assert fit["fits"][fit["figures_use"]]["status"] == "fitted"
    for fig in ("fig4", "fig7"):
        assert (tmp_path / f"{fig}.png").stat().st_size > 0 and (tmp_path / f"{fig}.pdf").stat().st_size > 0
    fig4_page = run_page("fig4", {**artefacts, "fig_csv": str(tmp_path / "fig4.csv"),
                                  "fig_png": str(tmp_path / "fig4.png")}, monkeypatch)
    assert fig4_page.images == 1
    assert (f"{counted} measured rows" if counted else "No measured rows") in fig4_page.text
    assert "No SIMULATED pull-off (rigid fixation)" in fig4_page.text and "budget_exceeded at 1 of 1" in fig4_page.text
    fig7_page = run_page("fig7", {"fit_json": artefacts["fit_json"], "setup_json": artefacts["setup_json"],
                                  "fig_csv": str(tmp_path / "fig7.csv"), "fig_png": str(tmp_path / "fig7.png")},
                         monkeypatch)
    assert fig7_page.images == 1
    fit_page = run_page("fit", {key: artefacts[key] for key in ("fit_json", "setup_json", "pulloff_csv")}, monkeypatch)
    assert fit_page.images == (1 if counted else 0)
    index = tmp_path / "index.html"
    write_index(index, findings=front_page.findings(artefacts, tmp_path / "absent.csv", tmp_path / "absent.html"))
    text = index.read_text()
    assert f"{counted} measured rows" in text and "No SIMULATED pull-off</strong>" not in text
    assert "<strong>No SIMULATED pull-off (rigid fixation)</strong>" in text


def test_measured_against_predicted_without_a_prediction_says_so_instead_of_drawing_nan_limits() -> None:
    """One or two rows for three parameters: no level fits, the fit page's plot has no point to draw."""
    empty = pd.DataFrame({"level": [], "measured_mN": [], "predicted_mN": [], "range": []})
    axes = page_figures.plot_measured_vs_predicted(empty).axes[0]
    assert [t.get_text() for t in axes.texts] == ["no model level fitted these rows:\nno prediction to compare with"]


def test_fig4_says_at_how_many_test_conditions_the_simulation_found_no_pulloff(
        virtual_at_absurd_parameters: Path) -> None:
    table = pd.DataFrame({"model": ["leading", "leading"], "frequency_hz": [np.nan, np.nan], "h1_um": [0.0, 20.0],
                          "pulloff_ratio": [1.0, 2.0], "A_over_am": [0.0, 0.01]})
    measured = pd.DataFrame({"frequency_hz": [], "h1_um": [], "pulloff_mN": [], "source": []})
    fig = figures.plot_fig4(table, measured, 57.27, pd.read_csv(virtual_at_absurd_parameters))
    assert ("SIMULATED pull-off: none at 1 of 1 test conditions\n(budget_exceeded at 1)"
            in [t.get_text() for t in fig.legends[0].get_texts()])
