"""Ingestion and validation of data/setup.yaml and data/pulloff.csv (vibroadhesion.pipeline.data)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pandas as pd
import pytest
from conftest import (
    AMPLITUDES_UM,
    FREQUENCIES_HZ,
    N_PUBLISHED,
    POISSON_RATIO,
    RADIUS,
    REDUCED_MODULUS,
    STORAGE_FACTOR,
    V0,
    W0,
    YOUNGS_MODULUS,
)
from jsonschema import Draft202012Validator

from vibroadhesion.pipeline import data
from vibroadhesion.pipeline.data import Setup, load_pulloff, load_setup, main
from vibroadhesion.pipeline.input_checks import DataError, schema

ROOT = Path(__file__).resolve().parents[2]
SETUP_YAML = ROOT / "data" / "setup.yaml"
PULLOFF_CSV = ROOT / "data" / "pulloff.csv"
HEADER = "frequency_hz,h1_um,pulloff_mN,source"
SPEED_HEADER = HEADER + ",withdrawal_speed_um_s"


# ----------------------------------------------------------------------------- helpers


def _write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _assert_located(exc: DataError, path: Path, row: int, column: str, *fragments: str) -> None:
    """The message is one line naming the file, the row and the column, and no internals."""
    msg = str(exc)
    assert "\n" not in msg
    assert msg.startswith(f"{path}, row {row}, column {column}: "), msg
    assert (exc.row, exc.column) == (row, column)
    for fragment in fragments:
        assert fragment in msg, msg
    for leak in ("Traceback", "<", "object at", "ValidationError", "Node("):
        assert leak not in msg, msg


def _assert_main_fails(tmp_path: Path, setup: Path, pulloff: Path, capsys: pytest.CaptureFixture[str], expected: str) -> None:
    out = tmp_path / "out"
    out.mkdir()
    rc = main([str(setup), str(pulloff), str(out / "setup.json"), str(out / "pulloff.csv")])
    err = capsys.readouterr().err
    assert rc == 1
    assert err.strip() == expected
    assert err.count("\n") == 1
    assert list(out.iterdir()) == []  # nothing written, no temporary left behind


def _csv(tmp_path: Path, body: str) -> Path:
    return _write(tmp_path, "pulloff.csv", body)


def _setup_variant(tmp_path: Path, old: str, new: str) -> Path:
    text = SETUP_YAML.read_text(encoding="utf-8")
    assert text.count(old) == 1, old
    return _write(tmp_path, "setup.yaml", text.replace(old, new))


def _line_of(path: Path, needle: str, nth: int = 0) -> int:
    hits = [i for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1) if needle in line]
    return hits[nth]


# ----------------------------------------------------------------------------- shipped files and schemas


@pytest.mark.parametrize("name", ["setup", "pulloff"])
def test_schemas_are_valid_draft_2020_12(name: str) -> None:
    schema_doc = schema(name)
    assert schema_doc["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    Draft202012Validator.check_schema(schema_doc)


def test_shipped_setup_loads() -> None:
    setup = load_setup(SETUP_YAML)
    assert isinstance(setup, Setup)
    assert setup.radius == RADIUS
    assert setup.youngs_modulus == YOUNGS_MODULUS
    assert setup.storage_modulus_factor == STORAGE_FACTOR
    assert setup.poisson_ratio == POISSON_RATIO
    assert setup.density == 965.0 and setup.thickness == 0.02
    assert setup.frequencies_hz == FREQUENCIES_HZ
    assert setup.amplitudes_um == AMPLITUDES_UM
    assert (setup.w0, setup.n, setup.v0) == (W0, N_PUBLISHED, V0)
    assert setup.sources["indenter.radius"].startswith("Sec. 3.4:")
    assert len(setup.sources) == 19 and all(s.strip() for s in setup.sources.values())
    # Fig. 5's amplitude and marked test frequency (its caption)
    assert setup.values["test_conditions.fig5_amplitude"] == 20.0
    assert setup.values["test_conditions.fig5_highlight_frequency"] == 200.0
    assert setup.sources["test_conditions.fig5_amplitude"].startswith("Fig. 5 caption")
    # the compliant fixation of Fig. 5, and the case of it the simulation checks: assumed values, each
    # with its reasoning (Sec. 3.5.3 gives none)
    fixation = {key.removeprefix("fixation."): v for key, v in setup.values.items() if key.startswith("fixation.")}
    assert fixation == {"natural_frequency": 70.42, "stiffness_ratio_kappa": (0.001, 0.01),
                        "weight_ratio_mu": 0.0, "damping_ratio_zeta": (0.0, 0.01, 0.05),
                        "simulated_stiffness_ratio_kappa": 0.001, "simulated_damping_ratio_zeta": 0.01}
    assert all(setup.sources[f"fixation.{k}"].startswith(("assumed", "given")) for k in fixation)
    assert setup.units["gent_schultz_published.v0"] == "m/s"
    assert setup.values["test_conditions.frequencies"] == FREQUENCIES_HZ


def test_shipped_reduced_modulus_closed_form() -> None:
    assert load_setup(SETUP_YAML).reduced_modulus == pytest.approx(REDUCED_MODULUS, rel=1e-15)


def test_shipped_pulloff_loads_empty_with_dtypes() -> None:
    rows = load_pulloff(PULLOFF_CSV)
    assert rows.empty
    assert list(rows.columns) == ["frequency_hz", "h1_um", "pulloff_mN", "source", "line", "withdrawal_speed_um_s"]
    assert [str(rows[c].dtype) for c in ("frequency_hz", "h1_um", "pulloff_mN", "line", "withdrawal_speed_um_s")] == [
        "float64"] * 3 + ["int64", "float64"]
    assert pd.api.types.is_string_dtype(rows["source"])


def test_main_on_shipped_files_writes_canonical_copies(tmp_path: Path) -> None:
    out_json, out_csv = tmp_path / "setup.json", tmp_path / "pulloff.csv"
    assert main([str(SETUP_YAML), str(PULLOFF_CSV), str(out_json), str(out_csv)]) == 0
    canonical = json.loads(out_json.read_text())
    assert canonical["indenter"]["radius"] == {"value": RADIUS, "unit": "m", "source": load_setup(SETUP_YAML).sources["indenter.radius"]}
    assert out_csv.read_text() == "line," + HEADER + "\n"
    assert data.read_canonical_setup(out_json) == load_setup(SETUP_YAML)
    assert data.read_canonical_pulloff(out_csv).empty
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pulloff.csv", "setup.json"]


# ----------------------------------------------------------------------------- derived values


def _derived(tmp_path: Path, setup_yaml: Path) -> dict[str, dict[str, object]]:
    """The group ``derived`` of the canonical copy that rule ingest_setup writes of ``setup_yaml``."""
    out = tmp_path / "setup.json"
    data.ingest_setup(setup_yaml, out)
    canonical = json.loads(out.read_text(encoding="utf-8"))
    assert data.read_canonical_setup(out) == load_setup(setup_yaml)  # the derived group is shown, not read back
    return canonical["derived"]


def test_no_shipped_value_is_labelled_derived() -> None:
    """Every entry of data/setup.yaml is given: its source never starts with "derived" (the schema refuses it)."""
    assert not [key for key, source in load_setup(SETUP_YAML).sources.items() if source.lower().startswith("derived")]


def test_derived_values_of_the_shipped_rig_are_those_the_paper_prints(tmp_path: Path) -> None:
    """E*, chi0 (Eq. 64), nu0 (Eq. 97) and omega_bar (Eq. 65) of the shipped rig against Sec. 3.4 and Sec. 3.5.3, to
    the printed digits; omega_bar to 6e-4: the paper's nu0 and omega_bar = 17.85 imply omega0 = 70.42 and 70.40 rad/s
    (3e-4 apart), and 26.78 is 1.5 x 17.85 rounded up. Each value carries its formula and equation."""
    derived = _derived(tmp_path, SETUP_YAML)
    assert derived["reduced_modulus"]["value"] == pytest.approx(7.467e6, abs=0.5e3)
    assert derived["chi0"]["value"] == pytest.approx(2.589e-2, abs=0.5e-5)
    assert derived["nu0"]["value"] == pytest.approx(1.227e-5, abs=0.5e-8)
    assert derived["omega_bar"]["value"] == pytest.approx([17.85, 26.78, 35.7], rel=6e-4)
    assert all(entry["formula"] and "Eq." in str(entry["source"]) for entry in derived.values())


def test_an_edited_input_changes_the_derived_values_by_their_formulas(tmp_path: Path) -> None:
    """R, v0, omega0 and E edited in data/setup.yaml: the canonical copy's derived values are the formulas evaluated
    here, E* = 2E/(1 - nu^2), chi0 = (9 pi w0/(E* R))^(1/3), nu0 = v0/(omega0 R), omega_bar = 2 pi f/omega0; the
    given natural frequency is the edited one, whatever R and v0."""
    text = SETUP_YAML.read_text(encoding="utf-8")
    edits = {"value: 51.5e-3": "value: 40.0e-3", "value: 44.5e-6": "value: 30.0e-6", "value: 70.42": "value: 50.0",
             "value: 2.8e6": "value: 3.1e6"}
    for old, new in edits.items():
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    radius, v0, omega0, modulus = 40.0e-3, 30.0e-6, 50.0, 3.1e6
    derived = _derived(tmp_path, _write(tmp_path, "setup.yaml", text))
    e_star = 2.0 * modulus / (1.0 - 0.5**2)
    assert derived["reduced_modulus"]["value"] == pytest.approx(e_star, rel=1e-15)
    assert derived["chi0"]["value"] == pytest.approx((9.0 * math.pi * W0 / (e_star * radius)) ** (1 / 3), rel=1e-14)
    assert derived["nu0"]["value"] == pytest.approx(v0 / (omega0 * radius), rel=1e-15)
    assert derived["omega_bar"]["value"] == pytest.approx([2 * math.pi * f / omega0 for f in FREQUENCIES_HZ], rel=1e-15)
    assert load_setup(tmp_path / "setup.yaml").values["fixation.natural_frequency"] == omega0
    assert derived != _derived(tmp_path, SETUP_YAML)


# ----------------------------------------------------------------------------- pulloff.csv: valid rows


def test_valid_rows_parse_with_line_numbers(tmp_path: Path) -> None:
    path = _csv(tmp_path, "# a comment\n\n" + HEADER + "\n"
                "200,40,250.5,Fig. 4 (ref. 35)\n"
                "   # indented comment\n"
                "\n"
                '300, 1e2 ,3.25e2,"lab, run 2"\n')
    rows = load_pulloff(path)
    assert rows["frequency_hz"].tolist() == [200.0, 300.0]
    assert rows["h1_um"].tolist() == [40.0, 100.0]
    assert rows["pulloff_mN"].tolist() == [250.5, 325.0]
    assert rows["source"].tolist() == ["Fig. 4 (ref. 35)", "lab, run 2"]
    assert rows["line"].tolist() == [4, 7]


def test_columns_in_other_order_and_crlf(tmp_path: Path) -> None:
    path = _csv(tmp_path, "source,pulloff_mN,h1_um,frequency_hz\r\nx,250,40,200\r\n")
    rows = load_pulloff(path)
    assert rows.iloc[0][["frequency_hz", "h1_um", "pulloff_mN", "source", "line"]].tolist() == [200.0, 40.0, 250.0, "x", 2]


def test_main_writes_canonical_csv_with_repr_floats(tmp_path: Path) -> None:
    pulloff = _csv(tmp_path, "# c\n" + HEADER + "\n200,40,20.1,\"a, b\"\n400,60.5,1e3,lab\n")
    out_json, out_csv = tmp_path / "o.json", tmp_path / "o.csv"
    assert main([str(SETUP_YAML), str(pulloff), str(out_json), str(out_csv)]) == 0
    assert out_csv.read_text() == "line," + HEADER + "\n3,200.0,40.0,20.1,\"a, b\"\n4,400.0,60.5,1000.0,lab\n"
    back = data.read_canonical_pulloff(out_csv)
    assert back["pulloff_mN"].tolist() == [20.1, 1000.0]


def test_withdrawal_speed_column_is_optional_empty_and_zero_are_quasi_static(tmp_path: Path) -> None:
    """The optional speed (um/s): empty and 0 read as 0 (quasi-static); the canonical CSV carries it only where a row
    has a speed, so a file without one ingests to the same bytes as before the column existed."""
    pulloff = _csv(tmp_path, "withdrawal_speed_um_s," + HEADER + "\n,200,40,250,a\n0,300,40,260,b\n44.5,400,40,270,c\n")
    rows = load_pulloff(pulloff)
    assert rows["withdrawal_speed_um_s"].tolist() == [0.0, 0.0, 44.5]
    out_json, out_csv = tmp_path / "o.json", tmp_path / "o.csv"
    assert main([str(SETUP_YAML), str(pulloff), str(out_json), str(out_csv)]) == 0
    assert out_csv.read_text() == ("line," + SPEED_HEADER + "\n2,200.0,40.0,250.0,a,0.0\n3,300.0,40.0,260.0,b,0.0\n"
                                   "4,400.0,40.0,270.0,c,44.5\n")
    assert data.read_canonical_pulloff(out_csv)["withdrawal_speed_um_s"].tolist() == [0.0, 0.0, 44.5]
    quasi_static = _csv(tmp_path, SPEED_HEADER + "\n200,40,20.1,\"a, b\",\n400,60.5,1e3,lab,0\n")
    assert main([str(SETUP_YAML), str(quasi_static), str(out_json), str(out_csv)]) == 0
    assert out_csv.read_text() == "line," + HEADER + "\n2,200.0,40.0,20.1,\"a, b\"\n3,400.0,60.5,1000.0,lab\n"
    assert load_pulloff(_csv(tmp_path, HEADER + "\n200,40,250,a\n"))["withdrawal_speed_um_s"].tolist() == [0.0]


def test_canonical_copy_names_each_row_by_its_line_in_the_users_file(tmp_path: Path) -> None:
    """Comments and blank lines before, between and after the rows: the canonical ``line`` of each row, read back
    and as written, is the row's line in data/pulloff.csv, counted here by the text of the rows."""
    text = ("# my rig\n\n# units: Hz, um, mN\n" + HEADER + "\n\n200,40,250,run A\n   # a remark\n\n\n"
            "300,60,420,run B\n# replicate of run B:\n300,60,425,run C\n\n# end\n")
    pulloff = _csv(tmp_path, text)
    expected = [number for number, line in enumerate(text.split("\n"), start=1) if ",run " in line]
    assert expected == [6, 10, 12]
    out_json, out_csv = tmp_path / "o.json", tmp_path / "o.csv"
    assert main([str(SETUP_YAML), str(pulloff), str(out_json), str(out_csv)]) == 0
    assert pd.read_csv(out_csv)["line"].tolist() == expected
    back = data.read_canonical_pulloff(out_csv)
    assert back["line"].tolist() == expected
    assert back["source"].tolist() == ["run A", "run B", "run C"]
    assert back.equals(load_pulloff(pulloff))


def test_user_file_may_not_carry_a_line_column(tmp_path: Path) -> None:
    """``line`` belongs to the canonical copy: in data/pulloff.csv it is an unknown column."""
    path = _csv(tmp_path, "line," + HEADER + "\n7,200,40,250,a\n")
    with pytest.raises(DataError) as info:
        load_pulloff(path)
    _assert_located(info.value, path, 1, "line", 'unknown column "line"')


# ----------------------------------------------------------------------------- pulloff.csv: bad input

ROW = "200,40,250,lab"

BAD_CSV = [
    # id, body, row, column, fragment
    ("empty-file", "", 1, "header", "file is empty"),
    ("only-comments", "# one\n# two\n\n", 3, "header", "no header line"),
    ("missing-column", "frequency_hz,h1_um,source\n200,40,lab\n", 1, "pulloff_mN", "missing column"),
    ("unknown-column", HEADER + ",operator\n200,40,250,lab,me\n", 1, "operator", "unknown column"),
    ("semicolon", "# c\nfrequency_hz;h1_um;pulloff_mN;source\n200;40;250;lab\n", 2, "header", "wrong delimiter"),
    ("tab", "frequency_hz\th1_um\tpulloff_mN\tsource\n", 1, "header", "wrong delimiter"),
    ("too-few-fields", HEADER + "\n200,40,250\n", 2, "source", "too few fields"),
    ("too-many-fields", HEADER + "\n200,40,250,5,lab\n", 2, "field 5", "too many fields"),
    ("non-numeric", HEADER + "\n" + ROW + "\n300,abc,250,lab\n", 3, "h1_um", 'not a number: "abc"'),
    ("nan", HEADER + "\nnan,40,250,lab\n", 2, "frequency_hz", "not a finite number"),
    ("inf", HEADER + "\n200,40,inf,lab\n", 2, "pulloff_mN", "not a finite number"),
    ("empty-numeric", HEADER + "\n200,,250,lab\n", 2, "h1_um", "empty value"),
    ("negative-frequency", HEADER + "\n-200,40,250,lab\n", 2, "frequency_hz", "must be > 0"),
    ("negative-amplitude", HEADER + "\n200,-40,250,lab\n", 2, "h1_um", "must be >= 0 um (0: a static JKR test)"),
    ("zero-frequency-with-vibration", HEADER + "\n0,40,250,lab\n", 2, "frequency_hz", "only for a static test"),
    ("empty-frequency-with-vibration", HEADER + "\n,40,250,lab\n", 2, "frequency_hz", "empty value"),
    ("zero-force", HEADER + "\n200,40,0,lab\n", 2, "pulloff_mN", "must be > 0"),
    ("negative-force", HEADER + "\n200,40,-250,lab\n", 2, "pulloff_mN", "must be > 0"),
    ("amplitude-in-mm", HEADER + "\n200,0.04,250,lab\n", 2, "h1_um", "expected micrometres; looks like mm/m"),
    ("amplitude-in-nm", HEADER + "\n200,40000,250,lab\n", 2, "h1_um", "expected micrometres; looks like nm"),
    ("force-too-large", HEADER + "\n200,40,250000,lab\n", 2, "pulloff_mN", "above 1e5 mN"),
    ("empty-source", HEADER + "\n200,40,250,\n", 2, "source", "empty source"),
    ("blank-source", HEADER + "\n200,40,250,   \n", 2, "source", "empty source"),
    ("negative-speed", SPEED_HEADER + "\n200,40,250,lab,-44.5\n", 2, "withdrawal_speed_um_s", "must be >= 0 um/s"),
    ("non-numeric-speed", SPEED_HEADER + "\n200,40,250,lab,fast\n", 2, "withdrawal_speed_um_s",
     'not a number: "fast" (expected a number in um/s'),
    ("unit-suffixed-speed", SPEED_HEADER + "\n200,40,250,lab,44.5um/s\n", 2, "withdrawal_speed_um_s", "not a number"),
    ("inf-speed", SPEED_HEADER + "\n200,40,250,lab,inf\n", 2, "withdrawal_speed_um_s", "not a finite number"),
    ("nan-speed", SPEED_HEADER + "\n200,40,250,lab,nan\n", 2, "withdrawal_speed_um_s", "not a finite number"),
    ("speed-in-nm-s", SPEED_HEADER + "\n200,40,250,lab,4.45e7\n", 2, "withdrawal_speed_um_s", "looks like nm/s"),
    ("static-test-at-a-speed", SPEED_HEADER + "\n,0,60,lab,44.5\n", 2, "withdrawal_speed_um_s",
     "static JKR test (h1_um = 0) at a withdrawal speed is not modelled"),
]


@pytest.mark.parametrize("body,row,column,fragment", [c[1:] for c in BAD_CSV], ids=[c[0] for c in BAD_CSV])
def test_bad_pulloff_is_located(tmp_path: Path, capsys: pytest.CaptureFixture[str], body: str, row: int, column: str,
                                fragment: str) -> None:
    path = _csv(tmp_path, body)
    with pytest.raises(DataError) as info:
        load_pulloff(path)
    _assert_located(info.value, path, row, column, fragment)
    _assert_main_fails(tmp_path, SETUP_YAML, path, capsys, str(info.value))


def test_zero_byte_pulloff_file(tmp_path: Path) -> None:
    path = tmp_path / "pulloff.csv"
    path.write_bytes(b"")
    with pytest.raises(DataError) as info:
        load_pulloff(path)
    _assert_located(info.value, path, 1, "header", "file is empty")


def test_missing_pulloff_file(tmp_path: Path) -> None:
    path = tmp_path / "absent.csv"
    with pytest.raises(DataError) as info:
        load_pulloff(path)
    _assert_located(info.value, path, 0, "(file)", "cannot read file")


def test_rows_differing_only_in_source_are_not_duplicates(tmp_path: Path) -> None:
    rows = load_pulloff(_csv(tmp_path, HEADER + "\n200,40,250,run 1\n200,40,250,run 2\n"))
    assert rows["line"].tolist() == [2, 3]


def test_replicate_rows_are_measurements_and_are_kept(tmp_path: Path) -> None:
    """A test run twice gives the same row twice (a lab records replicates): both are read and both written."""
    path = _csv(tmp_path, HEADER + "\n" + ROW + "\n# c\n200.0,40,2.5e2,lab\n")
    rows = load_pulloff(path)
    assert rows["line"].tolist() == [2, 4]
    assert rows["pulloff_mN"].tolist() == [250.0, 250.0]
    out_json, out_csv = tmp_path / "setup.json", tmp_path / "canonical.csv"
    assert main([str(SETUP_YAML), str(path), str(out_json), str(out_csv)]) == 0
    assert len(data.read_canonical_pulloff(out_csv)) == 2


# Forces on the scale of newtons typed in the millinewton column. |P_JKR| = (3 pi/2) R w0 = 57.27 mN at the
# published R = 51.5 mm and w0 = 0.236 J/m^2; the floor is 0.3 of it, 17.18 mN.
JKR_MN = 1.5 * math.pi * RADIUS * W0 * 1e3


def test_static_jkr_rows_need_no_frequency(tmp_path: Path) -> None:
    """h1_um = 0 is a static JKR test: its frequency may be empty (read as 0, written as 0.0) or given."""
    path = _csv(tmp_path, HEADER + "\n,0,60.0,static test\n200,0,61.0,static at the rig\n" + ROW + "\n")
    rows = load_pulloff(path)
    assert rows["frequency_hz"].tolist() == [0.0, 200.0, 200.0]
    assert rows["h1_um"].tolist() == [0.0, 0.0, 40.0]
    out_json, out_csv = tmp_path / "setup.json", tmp_path / "canonical.csv"
    assert main([str(SETUP_YAML), str(path), str(out_json), str(out_csv)]) == 0
    assert out_csv.read_text().splitlines()[1] == "2,0.0,0.0,60.0,static test"
    assert data.read_canonical_pulloff(out_csv)["h1_um"].tolist() == [0.0, 0.0, 40.0]


@pytest.mark.parametrize("force_mN", [0.165, 1.25, 0.299 * JKR_MN])
def test_pulloff_in_newtons_is_refused_against_the_setup(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                         force_mN: float) -> None:
    path = _csv(tmp_path, HEADER + "\n" + ROW + f"\n300,60,{force_mN!r},lab\n")
    with pytest.raises(DataError) as info:
        data.check_inputs(SETUP_YAML, path)
    _assert_located(info.value, path, 3, "pulloff_mN", "looks like N, expected mN", "17.2 mN")
    _assert_main_fails(tmp_path, SETUP_YAML, path, capsys, str(info.value))


def test_pulloff_just_above_the_floor_is_accepted(tmp_path: Path) -> None:
    path = _csv(tmp_path, HEADER + f"\n300,60,{0.301 * JKR_MN!r},lab\n")
    assert len(data.check_inputs(SETUP_YAML, path)[2]) == 1


def test_force_floor_uses_the_jkr_force_of_the_package() -> None:
    """input_checks computes |P_JKR| without numpy; it is core.jkr.pulloff_force (Eq. 70) in mN."""
    from vibroadhesion.core.jkr import pulloff_force
    from vibroadhesion.pipeline.input_checks import jkr_pulloff_mN

    assert jkr_pulloff_mN(RADIUS, W0) == pytest.approx(-1e3 * float(pulloff_force(W0, RADIUS)), rel=1e-15)
    assert jkr_pulloff_mN(RADIUS, W0) == pytest.approx(57.2744, rel=1e-5)  # (3 pi/2)(0.0515 m)(0.236 J/m^2)


# ----------------------------------------------------------------------------- setup.yaml: bad input

BAD_SETUP = [
    # id, old text, new text, needle locating the row (nth hit), column, fragment
    ("string-for-number", "value: 0.236", 'value: "0.236 J/m2"', ("0.236 J/m2", 0), "gent_schultz_published.w0.value",
     'expected a number, got the text "0.236 J/m2"'),
    ("missing-source", '    source: "Sec. 4: H = 2 cm"\n', "", ("thickness:", 0), "sample.thickness.source",
     'missing required key "source"'),
    ("empty-source", 'source: "Sec. 4: H = 2 cm"', 'source: ""', ('source: ""', 0), "sample.thickness.source", "empty source"),
    ("blank-source", 'source: "Sec. 4: H = 2 cm"', 'source: "   "', ('source: "   "', 0), "sample.thickness.source", "empty source"),
    ("derived-source", 'source: "Sec. 4: H = 2 cm"', 'source: "derived: H = 2R/5"', ("derived: H", 0),
     "sample.thickness.source", "given, not derived"),
    ("unknown-entry", "  thickness:\n", "  colour: {value: 1.0, unit: '1', source: x}\n  thickness:\n", ("colour", 0),
     "sample.colour", 'unknown key "colour"'),
    ("unknown-group", "indenter:\n", "rig:\n  mass: {value: 1.0, unit: kg, source: x}\nindenter:\n", ("rig:", 0), "rig",
     'unknown key "rig"'),
    ("unknown-field", '    unit: m/s\n', "    unit: m/s\n    note: printed um\n", ("note:", 0),
     "gent_schultz_published.v0.note", 'unknown key "note"'),
    ("missing-entry", "  radius:\n    value: 51.5e-3\n    unit: m\n", "  radiuss:\n    value: 51.5e-3\n    unit: m\n",
     ("radiuss", 0), "indenter.radiuss", 'unknown key "radiuss" (not declared in the schema; did you mean "radius"?)'),
    ("zero-radius", "value: 51.5e-3", "value: 0", ("value: 0", 0), "indenter.radius.value", "radius must be > 0"),
    ("negative-modulus", "value: 2.8e6", "value: -2.8e6", ("-2.8e6", 0), "sample.youngs_modulus.value", "must be > 0"),
    ("zero-w0", "value: 0.236", "value: 0.000", ("0.000", 0), "gent_schultz_published.w0.value", "w0 must be > 0"),
    ("negative-n", "value: 0.531", "value: -0.531", ("-0.531", 0), "gent_schultz_published.n.value", "n must be > 0"),
    ("zero-v0", "value: 44.5e-6", "value: 0.0e-6", ("0.0e-6", 0), "gent_schultz_published.v0.value", "v0 must be > 0"),
    ("poisson-above", "value: 0.5\n", "value: 0.6\n", ("value: 0.6", 0), "sample.poisson_ratio.value", "[0, 0.5]"),
    ("poisson-below", "value: 0.5\n", "value: -0.1\n", ("value: -0.1", 0), "sample.poisson_ratio.value", "[0, 0.5]"),
    ("empty-frequencies", "value: [200.0, 300.0, 400.0]", "value: []", ("value: []", 0),
     "test_conditions.frequencies.value", "must not be empty"),
    ("negative-frequency-item", "value: [200.0, 300.0, 400.0]", "value: [200.0, -300.0]", ("-300.0", 0),
     "test_conditions.frequencies.value[1]", "must be > 0"),
    ("wrong-unit", "    unit: Pa\n", "    unit: MPa\n", ("unit: MPa", 0), "sample.youngs_modulus.unit", 'unit must be "Pa"'),
    ("nan-value", "value: 965.0", "value: .nan", (".nan", 0), "sample.density.value", "finite"),
    ("null-value", "value: 965.0", "value: ~", ("value: ~", 0), "sample.density.value", "expected a number, got an empty value"),
    ("duplicate-key", "  thickness:\n", "  density:\n    value: 1.0\n  thickness:\n", ("density:", 1), "sample.density",
     "duplicate key (first given at row"),
    ("yaml-syntax", "    unit: kg/m^3\n", "    unit: [kg/m^3\n", ("[kg/m^3", 0), "(document)", "YAML syntax error"),
    # unit slips: a value outside the physical range of the stated unit
    ("radius-in-mm", "value: 51.5e-3", "value: 51.5", ("value: 51.5", 0), "indenter.radius.value", "looks like mm"),
    ("modulus-in-MPa", "value: 2.8e6", "value: 2.8", ("value: 2.8", 0), "sample.youngs_modulus.value",
     "looks like MPa"),
    ("density-in-g-per-cm3", "value: 965.0", "value: 0.965", ("value: 0.965", 0), "sample.density.value",
     "looks like g/cm^3"),
    ("thickness-in-mm", "value: 0.02", "value: 20.0", ("value: 20.0", 0), "sample.thickness.value", "looks like mm"),
    ("w0-in-mJ", "value: 0.236", "value: 236.0", ("value: 236.0", 0), "gent_schultz_published.w0.value",
     "looks like mJ/m^2"),
    ("v0-in-um-per-s", "value: 44.5e-6", "value: 44.5", ("value: 44.5", 0), "gent_schultz_published.v0.value",
     "looks like um/s"),
    ("amplitude-in-nm", "value: [20.0, 40.0, 60.0, 80.0, 100.0]", "value: [20.0, 40000.0]", ("40000.0", 0),
     "test_conditions.amplitudes.value[1]", "looks like nm"),
    # the range of n in which the model levels are validated
    ("n-above-validated", "value: 0.531", "value: 10", ("value: 10", 0), "gent_schultz_published.n.value",
     "outside the range in which the model levels are validated"),
    ("n-below-validated", "value: 0.531", "value: 0.01", ("value: 0.01", 0), "gent_schultz_published.n.value",
     "outside the range in which the model levels are validated"),
    ("negative-kappa", "value: [0.001, 0.01]", "value: [0.001, -0.01]", ("-0.01", 0),
     "fixation.stiffness_ratio_kappa.value[1]", "kappa must be >= 0"),
    ("negative-zeta", "value: [0.0, 0.01, 0.05]", "value: -0.05", ("value: -0.05", 0), "fixation.damping_ratio_zeta.value",
     "zeta must be >= 0"),
    # YAML 1.1 reads these in another base: 020 is 16, 0x20 is 32, 1:20 is 80
    ("octal", "    value: 20.0\n", "    value: 020\n", ("value: 020", 0), "test_conditions.fig5_amplitude.value",
     '"020" is not a plain decimal number'),
    ("hexadecimal", "    value: 20.0\n", "    value: 0x20\n", ("value: 0x20", 0), "test_conditions.fig5_amplitude.value",
     '"0x20" is not a plain decimal number'),
    ("sexagesimal", "    value: 20.0\n", "    value: 1:20\n", ("value: 1:20", 0), "test_conditions.fig5_amplitude.value",
     '"1:20" is not a plain decimal number'),
]


@pytest.mark.parametrize("old,new,needle,column,fragment", [c[1:] for c in BAD_SETUP], ids=[c[0] for c in BAD_SETUP])
def test_bad_setup_is_located(tmp_path: Path, capsys: pytest.CaptureFixture[str], old: str, new: str,
                              needle: tuple[str, int], column: str, fragment: str) -> None:
    path = _setup_variant(tmp_path, old, new)
    with pytest.raises(DataError) as info:
        load_setup(path)
    if column == "(document)":  # the parser reports the line where it notices the problem
        assert info.value.row >= _line_of(path, *needle)
        row = info.value.row
    else:
        row = _line_of(path, *needle)
    _assert_located(info.value, path, row, column, fragment)
    _assert_main_fails(tmp_path, path, PULLOFF_CSV, capsys, str(info.value))


def test_missing_required_entry_names_the_parent(tmp_path: Path) -> None:
    path = _setup_variant(tmp_path, "  n:\n    value: 0.531\n    unit: \"1\"\n    source: \"Fig. 4 caption: n = 0.531\"\n", "")
    with pytest.raises(DataError) as info:
        load_setup(path)
    _assert_located(info.value, path, _line_of(path, "gent_schultz_published:"), "gent_schultz_published.n",
                    'missing required key "n"')


def test_missing_required_group(tmp_path: Path) -> None:
    text = SETUP_YAML.read_text(encoding="utf-8")
    path = _write(tmp_path, "setup.yaml", text[: text.index("gent_schultz_published:")])
    with pytest.raises(DataError) as info:
        load_setup(path)
    _assert_located(info.value, path, _line_of(path, "indenter:"), "gent_schultz_published", 'missing required key')


@pytest.mark.parametrize("text,row", [("", 1), ("# only a comment\n", 1), ("\n\n", 1)], ids=["zero-bytes", "comment", "blank"])
def test_empty_setup(tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str, row: int) -> None:
    path = _write(tmp_path, "setup.yaml", text)
    with pytest.raises(DataError) as info:
        load_setup(path)
    _assert_located(info.value, path, row, "(document)", "file is empty")
    _assert_main_fails(tmp_path, path, PULLOFF_CSV, capsys, str(info.value))


def test_setup_top_level_not_a_mapping(tmp_path: Path) -> None:
    path = _write(tmp_path, "setup.yaml", "# c\n- 1\n- 2\n")
    with pytest.raises(DataError) as info:
        load_setup(path)
    _assert_located(info.value, path, 2, "(document)", "expected a mapping")


def test_yaml_syntax_error_row_from_mark(tmp_path: Path) -> None:
    path = _write(tmp_path, "setup.yaml", "indenter:\n  radius:\n    value: 1.0\n   unit: m\n")
    with pytest.raises(DataError) as info:
        load_setup(path)
    _assert_located(info.value, path, 4, "(document)", "YAML syntax error")


def test_exponent_without_dot_is_a_number(tmp_path: Path) -> None:
    setup = load_setup(_setup_variant(tmp_path, "value: 2.8e6", "value: 2e6"))
    assert setup.youngs_modulus == 2e6


def _shipped_without_fixation() -> str:
    """The shipped setup.yaml up to (not including) its fixation group, which is optional."""
    text = SETUP_YAML.read_text(encoding="utf-8")
    return text[: text.index("\n# Compliant fixation")] + "\n"


def test_optional_fixation_group(tmp_path: Path) -> None:
    extra = ("fixation:\n"
             "  stiffness_ratio_kappa: {value: 0.5, unit: '1', source: 'Sec. 2'}\n"
             "  damping_ratio_zeta: {value: [0.01, 0.1], unit: '1', source: 'Fig. 6'}\n")
    path = _write(tmp_path, "setup.yaml", _shipped_without_fixation() + extra)
    setup = load_setup(path)
    fixation = {key.removeprefix("fixation."): v for key, v in setup.values.items() if key.startswith("fixation.")}
    assert fixation == {"stiffness_ratio_kappa": 0.5, "damping_ratio_zeta": (0.01, 0.1)}
    assert setup.sources["fixation.damping_ratio_zeta"] == "Fig. 6"
    assert setup.reduced_modulus == load_setup(SETUP_YAML).reduced_modulus


@pytest.mark.parametrize("entry,row_offset,column,fragment", [
    ("  mass_ratio: {value: 1.0, unit: '1', source: x}\n", 1, "fixation.mass_ratio", 'unknown key "mass_ratio"'),
    ("  weight_ratio_mu: {value: 0.1, unit: '1'}\n", 1, "fixation.weight_ratio_mu.source", 'missing required key "source"'),
    ("  weight_ratio_mu: {value: high, unit: '1', source: x}\n", 1, "fixation.weight_ratio_mu.value",
     "expected a number or a list"),
], ids=["unknown", "no-source", "text-value"])
def test_bad_fixation(tmp_path: Path, entry: str, row_offset: int, column: str, fragment: str) -> None:
    path = _write(tmp_path, "setup.yaml", _shipped_without_fixation() + "fixation:\n" + entry)
    with pytest.raises(DataError) as info:
        load_setup(path)
    _assert_located(info.value, path, _line_of(path, "fixation:") + row_offset, column, fragment)


def test_setup_is_frozen() -> None:
    setup = load_setup(SETUP_YAML)
    with pytest.raises(AttributeError):
        setup.radius = 1.0  # type: ignore[misc]
    assert math.isfinite(setup.reduced_modulus)


def test_main_replaces_existing_outputs_only_on_success(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out_json, out_csv = tmp_path / "s.json", tmp_path / "p.csv"
    out_json.write_text("old"), out_csv.write_text("old")
    bad = _csv(tmp_path, HEADER + "\n200,40,-1,lab\n")
    assert main([str(SETUP_YAML), str(bad), str(out_json), str(out_csv)]) == 1
    assert out_json.read_text() == "old" and out_csv.read_text() == "old"
    assert main([str(SETUP_YAML), str(PULLOFF_CSV), str(out_json), str(out_csv)]) == 0
    assert out_csv.read_text() == "line," + HEADER + "\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.csv", "pulloff.csv", "s.json"]
    capsys.readouterr()
