"""The front page: its numbers are those of the artefacts it reads, and it says what is not built yet.

The artefacts are written here by hand (a virtual pull-off CSV, a fit summary, a validation error summary), so each
expected number is arithmetic on the fixture: prediction / simulation - 1 and the shown roundings.
"""

import json
import os
import time
from pathlib import Path

import pytest

from vibroadhesion.core import levels
from vibroadhesion.pipeline.input_checks import schema_validator
from vibroadhesion.pipeline import front_page
from vibroadhesion.pipeline.data import ingest_setup
from vibroadhesion.pipeline.front_page import refresh_findings
from vibroadhesion.pipeline.pages import (FILE_TIME_MARGIN_NS, VALIDATION_INDEX, VALIDATION_SUMMARY, build,
                                          build_paragraph, findings_of, findings_outdated, index_artefacts, write_index)

VIRTUAL = """fixation,kappa,zeta,frequency_hz,h1_um,model,status,pulloff_ratio,pulloff_mN,abar_m,abar_cr,steady_states
rigid,,,200,20,simulation,pulloff,3.0,171.8,1.0,1.2,14
rigid,,,200,40,simulation,pulloff,8.0,458.2,1.3,1.6,18
rigid,,,200,60,simulation,contact_loss_before_extremum,,,,,3
rigid,,,200,20,leading,ok,2.4,137.4,,,
rigid,,,200,40,leading,ok,6.0,343.6,,,
rigid,,,200,60,leading,ok,9.0,515.5,,,
"""

SUMMARY = ("model,max_error_applicable,max_error_outside,max_error_experiments_applicable,"
           "max_error_experiments_outside,points,points_below_5pct\n") + """\
refined,0.36319642951418363,0.12711986555662846,0.33834041556742633,,33,0
leading,0.36319594834484814,0.1536646465138114,0.33813384611164277,,33,0
exact_averaging,0.2296544227080406,0.28412306859331204,0.15149715242435424,,33,25
"""


ROOT = Path(__file__).resolve().parents[2]


def _setup_json(tmp_path: Path) -> Path:
    """The canonical copy of the shipped data/setup.yaml (published w0 = 0.236 J/m^2, n = 0.531, v0 = 44.5 um/s)."""
    ingest_setup(ROOT / "data" / "setup.yaml", tmp_path / "setup.json")
    return tmp_path / "setup.json"


def _fit_json(tmp_path: Path) -> Path:
    parameters = {"w0": {"estimate": 0.2361234, "std_error": 0.001234, "unit": "J/m^2", "status": "fitted",
                         "reason": "", "interval": [0.2337, 0.2386]},
                  "n": {"estimate": 0.531, "std_error": 0.25, "unit": "1", "status": "fitted", "reason": "",
                        "interval": [0.31, 1.42]},
                  "v0": {"estimate": 4.45e-05, "std_error": None, "unit": "m/s", "status": "published", "reason": "",
                         "interval": None}}
    fit = {"data_rows": 7, "figures_preferred": "simulation", "figures_use": "simulation",
           "figures_reason": "the simulation fit determines every parameter it fits",
           "status": "the figures use the simulation fit: the simulation fit determines every parameter it fits",
           "settings": {"confidence": 0.95, "relative_scatter": 0.05, "alpha": 0.05, "max_relative_se": 0.5},
           "published": {"w0": 0.236, "n": 0.531, "v0": 4.45e-05, "source": "Fig. 4 caption"},
           "fits": {"simulation": {"model": "simulation", "rows": 7, "status": "fitted", "determined": ["w0", "n"],
                                   "note": "", "v0_note": "", "free_parameters": ["w0", "n"], "v0_identifiable": False,
                                   "parameters": parameters, "rms_relative_residual": 2.693e-05}}}
    schema_validator("fit").validate(fit)
    path = tmp_path / "fit.json"
    path.write_text(json.dumps(fit))
    return path


def test_amplification_is_each_level_against_the_simulated_pulloff(tmp_path: Path) -> None:
    (tmp_path / "virtual.csv").write_text(VIRTUAL)
    table = front_page.amplification(tmp_path / "virtual.csv").set_index("level")
    leading = table.loc[levels.level("leading").label]
    assert leading["error_min"] == pytest.approx(6.0 / 8.0 - 1, rel=1e-15)  # -0.25
    assert leading["error_max"] == pytest.approx(2.4 / 3.0 - 1, rel=1e-15)  # -0.2
    assert leading["points"] == 2  # the contact-loss condition is not compared
    assert (leading["ratio_min"], leading["ratio_max"]) == (2.4, 9.0)
    simulated = table.loc[levels.level("simulation").label + " (SIMULATED)"]
    assert (simulated["ratio_min"], simulated["ratio_max"], simulated["points"]) == (3.0, 8.0, 2)


def test_front_page_numbers_are_those_of_the_artefacts(tmp_path: Path) -> None:
    (tmp_path / "virtual.csv").write_text(VIRTUAL)
    summary = tmp_path / "summary.csv"
    summary.write_text(SUMMARY)
    fit_json = _fit_json(tmp_path)
    os.utime(summary, (os.stat(fit_json).st_mtime + 10,) * 2)  # validation newer than the fit: no warning
    out = tmp_path / "index.html"
    artefacts = {"fit_json": fit_json, "virtual_csv": tmp_path / "virtual.csv", "setup_json": _setup_json(tmp_path)}
    for page in ("validation_index", "fig4"):  # the pages its findings link, built
        (tmp_path / f"{page}.html").write_text("page")
    write_index(out, findings=front_page.findings(artefacts, summary, tmp_path / "validation_index.html"))
    text = out.read_text()
    assert "7 measured rows" in text and "0.236 [0.234, 0.239]" in text and "0.531 [0.31, 1.42]" in text
    assert "4.45e-05 (fixed: published)" in text and "2.69e-05" in text
    assert "-2.50e-01" in text and "-2.00e-01" in text  # leading against the simulated pull-off
    assert "3.38e-01" in text and "1.51e-01" in text and "25 of 33" in text  # validation summary
    assert "up to 15 %" in text  # the most accurate level at the test frequencies: exact averaging, 0.1515
    assert text.index(levels.level("leading").label) < text.index(levels.level("refined").label)
    assert 'href="fit.html"' in text and 'href="fig4.html"' in text and 'href="validation_index.html"' in text
    assert "Warning" not in text and "Built from commit " in text


def test_front_page_without_validation_says_how_to_build_it_and_with_it_links_it(tmp_path: Path) -> None:
    """The validation runs at the published parameters, so a summary older than the fit is not stale: no warning."""
    fit_json = _fit_json(tmp_path)
    setup_json = _setup_json(tmp_path)
    missing = front_page.findings({"fit_json": fit_json, "setup_json": setup_json}, tmp_path / "absent.csv")
    assert "run <code>snakemake -c2 validation</code>" in missing and "validation_index.html" not in missing
    summary = tmp_path / "summary.csv"
    summary.write_text(SUMMARY)
    os.utime(summary, (os.stat(fit_json).st_mtime - 10,) * 2)
    validation_index = tmp_path / "validation_index.html"
    stopped = front_page.findings({"fit_json": fit_json, "setup_json": setup_json}, summary,
                                  validation_index)  # a validation run stopped
    assert "its pages not built" in stopped and "validation_index.html" not in stopped
    validation_index.write_text("page")
    built = front_page.findings({"fit_json": fit_json, "setup_json": setup_json}, summary, validation_index)
    assert 'href="validation_index.html"' in built and "older than the fit" not in built


def test_every_table_heading_names_its_parameter_set(tmp_path: Path) -> None:
    """The figure index: the fit and the SIMULATED pull-off at the fit the figures use (here the simulation fit,
    w0 = 0.2361234 shown to 3 digits), the validity at the published set; the validation index (no fit): all at the
    published set of data/setup.yaml, its amplification linked to the validation page, not to Fig. 4."""
    (tmp_path / "virtual.csv").write_text(VIRTUAL)
    summary = tmp_path / "summary.csv"
    summary.write_text(SUMMARY)
    setup_json, virtual = _setup_json(tmp_path), tmp_path / "virtual.csv"
    fitted = ("simulation fit of 7 measured rows, 95% intervals: w0 = 0.236 [0.234, 0.239] J/m², n = 0.531 [0.31, 1.42],"
              " v0 = 44.5 µm/s")
    published = "published parameters: w0 = 0.236 J/m², n = 0.531, v0 = 44.5 µm/s"
    (tmp_path / "fig4.html").write_text("page")  # Fig. 4's page is linked where it exists
    index = front_page.findings({"fit_json": _fit_json(tmp_path), "setup_json": setup_json, "virtual_csv": virtual},
                                summary, tmp_path / "validation_index.html")
    headings = [part.split("</h2>")[0] for part in index.split("<h2>")[1:]]
    assert [h.endswith(f"the {fitted}") for h in headings] == [True, True, False]
    assert headings[2].endswith(f"at the {published}") and 'href="fig4.html"' in headings[1]
    validation = front_page.findings({"setup_json": setup_json, "virtual_csv": virtual}, summary)
    headings = [part.split("</h2>")[0] for part in validation.split("<h2>")[1:]]
    assert len(headings) == 2 and all(h.endswith(f"at the {published}") for h in headings)
    assert 'href="validation.html"' in headings[0] and "fig4.html" not in validation


def test_build_names_the_commit_not_the_time(tmp_path: Path) -> None:
    assert build(tmp_path) == "an unknown commit (not a git checkout)"
    here = build(Path(__file__).parent)
    assert here.startswith("commit ") and " of 20" in here


def test_marking_stale_pages_keeps_the_findings_of_the_index(tmp_path: Path) -> None:
    out = tmp_path / "index.html"
    (tmp_path / "fig4.html").write_text("page")
    write_index(out, findings="<p>finding 42</p>")
    write_index(out, stale=["fig4"])  # what refresh_indexes does after a run
    text = out.read_text()
    assert text.count("<p>finding 42</p>") == 1 and "(out of date)" in text
    write_index(out, findings="")
    assert "finding 42" not in out.read_text()


def test_an_index_reads_the_artefact_of_the_first_page_that_names_it() -> None:
    pages = {"validation": {"virtual_csv": "all.csv", "summary_csv": "s.csv"},
             "identifiability": {"virtual_csv": "rigid.csv", "fit_json": "fit.json"}}
    assert index_artefacts(pages) == {"virtual_csv": "all.csv", "summary_csv": "s.csv", "fit_json": "fit.json"}


def test_refresh_reads_the_findings_again_from_what_the_run_left(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """`snakemake -c2 all validation` may write the index before the validation summary exists: the end-of-run
    refresh (Snakefile onsuccess) puts the validity in; an unchanged index is not rewritten; an index whose artefacts
    are not all there (a run that stopped midway) keeps its findings."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "virtual.csv").write_text(VIRTUAL)
    index = tmp_path / "index.html"
    pages = {"fit": {"fit_json": str(_fit_json(tmp_path)), "setup_json": str(_setup_json(tmp_path))},
             "fig4": {"virtual_csv": str(tmp_path / "virtual.csv")}}
    write_index(index, findings="<p>written by the report job</p>")
    assert refresh_findings({str(index): pages}) == [str(index)]
    assert "run <code>snakemake -c2 validation</code>" in findings_of(index)
    VALIDATION_SUMMARY.parent.mkdir(parents=True)
    VALIDATION_SUMMARY.write_text(SUMMARY)
    assert refresh_findings({str(index): pages}) == [str(index)]
    assert "its pages not built" in findings_of(index) and "validation_index.html" not in findings_of(index)
    VALIDATION_INDEX.parent.mkdir(parents=True)
    VALIDATION_INDEX.write_text("page")
    assert refresh_findings({str(index): pages}) == [str(index)]
    assert 'href="validation_index.html"' in findings_of(index)
    assert refresh_findings({str(index): pages}) == []
    for artefact in (*index_artefacts(pages).values(), VALIDATION_SUMMARY, VALIDATION_INDEX):  # a second before
        os.utime(artefact, ns=(time.time_ns() - 10**9, time.time_ns() - 10**9))
    assert refresh_findings({str(index): pages}) == []
    assert not findings_outdated(index, index_artefacts(pages).values())  # read again, the same: marked current
    (tmp_path / "virtual.csv").unlink()
    before = index.read_text()
    assert refresh_findings({str(index): pages}) == [] and index.read_text() == before


def test_findings_are_outdated_when_an_artefact_is_newer_than_their_reading_or_the_build_changed(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The Snakefile's onsuccess reads the findings again only when pages.findings_outdated says so: an index written
    with the time before its findings read the artefacts (as_of_ns, less the file-time margin) is outdated by an
    artefact written after that time, even while the findings were being read, not by one written before; and by a
    findings text that names another build than the checkout's."""
    monkeypatch.chdir(tmp_path)
    artefact, index = tmp_path / "virtual.csv", tmp_path / "index.html"
    artefact.write_text(VIRTUAL)
    os.utime(artefact, ns=(10**18, 10**18))
    assert not findings_outdated(index, [artefact])  # no index: nothing to refresh
    current = build_paragraph() + "<p>rows</p>"
    read_at = 10**18 + 2 * FILE_TIME_MARGIN_NS  # the artefact was written before the reading started
    write_index(index, findings=current, as_of_ns=read_at)
    assert index.stat().st_mtime_ns == read_at - FILE_TIME_MARGIN_NS
    assert not findings_outdated(index, [artefact, tmp_path / "absent.csv"])
    os.utime(artefact, ns=(read_at + 1, read_at + 1))  # written while the findings were read
    assert findings_outdated(index, [artefact])
    os.utime(artefact, ns=(10**18, 10**18))
    write_index(index, findings="<p>Built from commit 0123456789ab of 2020-01-01.</p>", as_of_ns=read_at)
    assert findings_outdated(index, [artefact])
