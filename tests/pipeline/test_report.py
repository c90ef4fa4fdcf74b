"""Report: the indices of both targets (each page linked once, stale pages marked) and the tables the pages show."""

import os
from pathlib import Path

import pytest

from vibroadhesion.pipeline import report
from vibroadhesion.pipeline.pages import PAGES, VALIDATION_PAGES, refresh_indexes, stale_pages, write_index


@pytest.mark.parametrize(("name", "pages", "other"), [("index", PAGES, VALIDATION_PAGES),
                                                      ("validation_index", VALIDATION_PAGES, PAGES)])
def test_index_links_its_own_pages_only(tmp_path: Path, name, pages, other) -> None:
    for stem, _ in PAGES + VALIDATION_PAGES:
        (tmp_path / f"{stem}.html").write_text("page")
    out = tmp_path / f"{name}.html"
    write_index(out)
    text = out.read_text()
    for stem, _ in pages:
        assert text.count(f'<li><a href="{stem}.html">') == 1
    for stem, _ in other:
        assert f'<li><a href="{stem}.html">' not in text


def test_index_lists_a_page_that_is_not_built_without_a_link(tmp_path: Path) -> None:
    """A link to a missing page would lead nowhere: its title is marked "(not built)" instead."""
    write_index(tmp_path / "validation_index.html")  # no index.html beside it yet: not linked
    assert 'href="index.html"' not in (tmp_path / "validation_index.html").read_text()
    (tmp_path / "fig3.html").write_text("page")
    write_index(tmp_path / "index.html")
    text = (tmp_path / "index.html").read_text()
    assert '<a href="fig3.html">' in text and 'href="fig4.html"' not in text
    assert f"<li>{PAGES[1][1]} <strong class=\"stale\">(not built)</strong></li>" in text


def test_unknown_index_name_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="unknown index"):
        write_index(tmp_path / "other.html")
    assert list(tmp_path.iterdir()) == []


def _page_with_inputs(tmp_path: Path, page: str, page_time: int, input_times: list[int | None]) -> list[Path]:
    """results/report/<page>.html built at ``page_time`` (s) and its inputs written at ``input_times`` (None: absent)."""
    built = tmp_path / "report" / f"{page}.html"
    built.parent.mkdir(exist_ok=True)
    built.write_text("page")
    os.utime(built, (page_time, page_time))
    inputs = []
    for k, when in enumerate(input_times):
        path = tmp_path / f"{page}_{k}.csv"
        if when is not None:
            path.write_text("x")
            os.utime(path, (when, when))
        inputs.append(path)
    return inputs


def test_a_missing_page_or_one_older_than_or_missing_an_artefact_is_stale(tmp_path: Path) -> None:
    inputs = {"fig3": _page_with_inputs(tmp_path, "fig3", 2000, [1000, 1500]),   # built after its inputs
              "fig4": _page_with_inputs(tmp_path, "fig4", 2000, [1000, 3000]),   # one input rewritten later
              "fig5": _page_with_inputs(tmp_path, "fig5", 2000, [1000, None]),   # one input gone
              "fig6": _page_with_inputs(tmp_path, "fig6", 2000, [1000]),         # built after its input
              "fig7": [tmp_path / "fig3_0.csv"]}                                  # page missing (its job failed)
    assert stale_pages(inputs, tmp_path / "report") == ["fig4", "fig5", "fig7"]


def test_refresh_marks_the_stale_pages_of_each_index_and_leaves_a_consistent_one_untouched(tmp_path: Path) -> None:
    report_dir = tmp_path / "report"
    inputs = {"fig3": _page_with_inputs(tmp_path, "fig3", 2000, [1000]),
              "validation": _page_with_inputs(tmp_path, "validation", 2000, [3000])}
    write_index(report_dir / "index.html")
    write_index(report_dir / "validation_index.html")
    os.utime(report_dir / "index.html", (2500, 2500))
    assert refresh_indexes(inputs, report_dir) == ["validation"]
    assert (report_dir / "index.html").stat().st_mtime == 2500  # nothing stale there: not rewritten
    assert "Out of date" not in (report_dir / "index.html").read_text()
    text = (report_dir / "validation_index.html").read_text()
    assert "Out of date" in text and "snakemake -c2 validation" in text
    assert text.count("(out of date)") == 1 and '<a href="validation.html">' in text.split("(out of date)")[0]
    os.utime(report_dir / "validation.html", (4000, 4000))  # the page rebuilt: the mark goes
    assert refresh_indexes(inputs, report_dir) == []
    assert "out of date" not in (report_dir / "validation_index.html").read_text().lower()


def test_refresh_touches_only_the_indexes_asked_for_and_writes_a_missing_one_with_its_pages_marked(
        tmp_path: Path) -> None:
    """The end-of-run hooks of a `snakemake -c2 validation` run (asked: the validation index) leave index.html's bytes
    and time as they were, though its page is stale; the validation index, removed with its failed job, is written
    again with its pages marked and a statement instead of findings."""
    report_dir = tmp_path / "report"
    inputs = {"fig3": _page_with_inputs(tmp_path, "fig3", 2000, [3000]),
              "validation": _page_with_inputs(tmp_path, "validation", 2000, [3000])}
    write_index(report_dir / "index.html")
    os.utime(report_dir / "index.html", (2500, 2500))
    before = (report_dir / "index.html").read_bytes()
    assert refresh_indexes(inputs, report_dir, ["validation_index"]) == ["validation"]
    assert (report_dir / "index.html").read_bytes() == before and (report_dir / "index.html").stat().st_mtime == 2500
    text = (report_dir / "validation_index.html").read_text()
    assert "The run stopped before the job that writes this index finished" in text
    assert '<a href="validation.html">' in text and text.count("(out of date)") == 1 and "(not built)" in text
    assert 'href="index.html"' in text  # the figure pages' index exists beside it


def test_virtual_pulloff_tables_give_one_table_per_fixation_with_errors_against_the_simulation(tmp_path: Path) -> None:
    """Hand-made rows: errors are prediction / simulation - 1, shares a_m/a_cr of the simulated rows."""
    rows = [
        # fixation, kappa, zeta, f, h1, model, status, ratio, abar_m, abar_cr, steady_states
        ("rigid", "", "", 200, 20, "simulation", "ok", 4.0, 0.8, 1.0, 12),
        ("rigid", "", "", 200, 20, "leading", "ok", 3.0, "", "", ""),
        ("compliant", 0.001, 0.01, 200, 20, "simulation", "ok", 5.0, 0.9, 1.0, 30),
        ("compliant", 0.001, 0.01, 200, 20, "leading", "ok", 6.0, "", "", ""),
    ]
    header = "fixation,kappa,zeta,frequency_hz,h1_um,model,status,pulloff_ratio,abar_m,abar_cr,steady_states\n"
    csv = tmp_path / "virtual_pulloff.csv"
    csv.write_text(header + "".join(",".join(str(v) for v in r) + "\n" for r in rows))
    (rigid_heading, rigid, rigid_remark), (compliant_heading, compliant, compliant_remark) = \
        report.virtual_pulloff_tables(csv)
    assert rigid_heading.startswith("RIGID fixation") and "kappa = 0.001" in compliant_heading
    assert rigid.loc[(200, 20), "leading error"] == pytest.approx(3.0 / 4.0 - 1, rel=1e-15)
    assert compliant.loc[(200, 20), "leading error"] == pytest.approx(6.0 / 5.0 - 1, rel=1e-15)
    assert rigid.loc[(200, 20), "SIMULATED"] == 4.0 and compliant.loc[(200, 20), "steady states"] == 30
    assert "80–80 %" in rigid_remark and "90–90 %" in compliant_remark


def test_rule_timings_give_wall_and_cpu_time_and_peak_memory_of_each_rule(tmp_path: Path) -> None:
    """The columns s, cpu_time and max_rss of Snakemake's benchmark file (one run of the rule), named by the file."""
    tsv = tmp_path / "fig3_data.tsv"
    tsv.write_text("s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"
                   "3.84\t0:00:03\t117.49\t278.80\t88.57\t95.68\t0.03\t0.01\t18.77\t0.86\n")
    table = report.rule_timings([tsv])
    assert table.to_dict("records") == [{"rule": "fig3_data", "wall_s": 3.84, "cpu_s": 0.86, "max_rss_MB": 117.49}]


def test_index_shows_each_page_figure_as_a_thumbnail_linking_to_the_page(tmp_path: Path) -> None:
    """The run's figure of each page (relative to results/report/), inside a link to that page; the fit page, which
    has none, by its title only."""
    for stem, _ in PAGES + VALIDATION_PAGES:
        (tmp_path / f"{stem}.html").write_text("page")
    out = tmp_path / "index.html"
    write_index(out)
    text = out.read_text()
    for stem in ("fig3", "fig5", "fig8"):
        assert f'<a href="{stem}.html"><img src="../{stem}/{stem}.png"' in text
    assert '<li><a href="fit.html">' in text and "fit.png" not in text
    write_index(tmp_path / "validation_index.html")
    validation = (tmp_path / "validation_index.html").read_text()
    assert '<a href="validation.html"><img src="../validation/rigid_error_maps.png"' in validation
    assert '<a href="benchmarks.html"><img src="../benchmarks/speed_vs_error.png"' in validation
