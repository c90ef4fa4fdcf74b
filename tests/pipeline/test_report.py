"""Report: the indices of both targets (each page linked once) and the tables the pages show."""

from pathlib import Path

import pytest

from vibroadhesion.pipeline import report
from vibroadhesion.pipeline.pages import PAGES, VALIDATION_PAGES, write_index


@pytest.mark.parametrize(("name", "pages", "other"), [("index", PAGES, VALIDATION_PAGES),
                                                      ("validation_index", VALIDATION_PAGES, PAGES)])
def test_index_links_its_own_pages_only(tmp_path: Path, name, pages, other) -> None:
    out = tmp_path / f"{name}.html"
    write_index(out)
    text = out.read_text()
    for stem, _ in pages:
        assert text.count(f'<li><a href="{stem}.html">') == 1
    for stem, _ in other:
        assert f'<li><a href="{stem}.html">' not in text


def test_unknown_index_name_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="unknown index"):
        write_index(tmp_path / "other.html")
    assert list(tmp_path.iterdir()) == []


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
