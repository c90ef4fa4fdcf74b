"""The report's table formatting: significant figures, relative errors in scientific notation, units, no index.

Expected strings are written out by hand from the rule (4 significant figures, trailing zeros kept; relative
errors with 3 in scientific notation; value ± SE with the SE to 2 figures); the CSVs are never rounded.
"""

import math

import numpy as np
import pandas as pd
import pytest

from vibroadhesion.pipeline import tables
from vibroadhesion.pipeline.tables import Column


@pytest.mark.parametrize(("value", "text"), [
    (0.236, "0.236"), (0.25, "0.25"), (0.2360001, "0.2360"), (1.00969, "1.010"), (172.87509505524881, "172.9"),
    (12345.6, "12350"), (200.0, "200"), (-0.33813384611164277, "-0.3381"), (0.0012345, "0.001234"),
    (4.45e-05, "4.45e-05"), (4.4512345e-05, "4.451e-05"), (1.0e8, "1e+08"), (0.0, "0"), (np.int64(14), "14"),
    (11.9994, "12.00"), (164.98, "165.0"), (99999.9, "1.000e+05"), (float("nan"), "—"), (None, "—"),
    ("pulloff", "pulloff"),
])
def test_significant_figures(value: object, text: str) -> None:
    assert tables.significant(value) == text


def test_significant_figures_agree_with_the_value_to_half_a_unit_in_the_last_place() -> None:
    """Round trip: |shown - x| <= 0.5e-3 |x| for 4 figures, over 12 decades."""
    for x in np.geomspace(1.234567e-6, 9.87654e6, 97):
        shown = float(tables.significant(x))
        assert abs(shown - x) <= 0.5e-3 * abs(x) * (1 + 1e-12)


@pytest.mark.parametrize(("value", "text"), [(-0.3381338, "-3.38e-01"), (2.693e-05, "2.69e-05"),
                                             (0.0, "0.00e+00"), (float("nan"), "—")])
def test_relative_errors_in_scientific_notation(value: float, text: str) -> None:
    assert tables.relative(value) == text


@pytest.mark.parametrize(("value", "se", "text"), [
    (0.2361234, 0.001234, "0.2361\u00a0±\u00a00.0012"), (0.531, 0.25, "0.53\u00a0±\u00a00.25"),
    (1234.5, 56.0, "1234\u00a0±\u00a056"),
    (4.503121e-05, 1.87152e-07, "(4.503\u00a0±\u00a00.019)e-05"), (0.6473955, 1.343, "0.6\u00a0±\u00a01.3"),
    (0.00336433, 191717168.0, "0.003364\u00a0±\u00a01.917e+08"),  # rounded to the error's decimal it would read 0
])
def test_value_plus_minus_standard_error(value: float, se: float, text: str) -> None:
    assert tables.plus_minus(value, se) == text


def test_headers_carry_the_unit_and_dimensionless_numbers_none() -> None:
    assert Column("f", "Hz").header == "f (Hz)"
    assert Column("P_cr/P_JKR").header == "P_cr/P_JKR"
    assert tables.column("pulloff_mN").header == "|P_cr| (mN)"
    assert tables.column("h1_um").header == "h1 (µm)"
    assert tables.column("w0").header == "w0 (J/m²)"
    assert tables.column("refined error").format == "rel"
    assert tables.column("some_ratio") == Column("some ratio")
    assert tables.column("A/a_m at 200 Hz") == Column("A/a_m at 200 Hz")  # a label already: kept
    assert tables.column("exact_averaging error") == Column("exact averaging error", format="rel")
    assert tables.column("pulloff_mN", {"pulloff_mN": Column("measured", "mN")}).header == "measured (mN)"


def test_a_table_has_no_index_and_keeps_the_index_levels_as_columns() -> None:
    frame = pd.DataFrame({"frequency_hz": [200.0, 300.0], "h1_um": [20.0, 40.0], "refined": [2.2113178, 4.7534538],
                          "refined error": [-0.2673, -0.3612], "status": ["pulloff", "contact_loss"]},
                         index=[141, 161])
    table = tables.show(frame)
    html = table._repr_html_()
    assert "141" not in html and "161" not in html  # the pandas index is not shown
    assert list(table.frame.columns) == ["f (Hz)", "h1 (µm)", "refined", "refined error", "status"]
    assert table.frame.iloc[1].tolist() == ["300", "40", "4.753", "-3.61e-01", "contact loss"]
    assert '<td style="text-align: left">contact loss</td>' in html
    pivoted = tables.show(frame.set_index(["frequency_hz", "h1_um"]))
    assert list(pivoted.frame.columns)[:2] == ["f (Hz)", "h1 (µm)"]
    assert "141" not in repr(table)


def test_formatting_leaves_the_frame_unrounded() -> None:
    frame = pd.DataFrame({"pulloff_mN": [172.87509505524881]})
    tables.show(frame)
    assert frame["pulloff_mN"].iloc[0] == 172.87509505524881


def test_exact_format_shows_an_input_as_typed() -> None:
    spec = {"value": Column("value", format="exact")}
    shown = tables.formatted(pd.DataFrame({"value": [4.45e-05, 0.531, 2.8e6, "(20.0, 40.0)"]}), spec)
    assert shown["value"].tolist() == ["4.45e-05", "0.531", "2800000", "(20.0, 40.0)"]
    assert not math.isnan(float(shown["value"].iloc[0]))


def test_a_table_of_errors_shows_every_number_as_a_relative_error() -> None:
    frame = pd.DataFrame({"model": ["refined"], "w_eff_ratio": [0.33834041556742633], "points": [33]})
    shown = tables.show(frame, {"points": Column("points", format="int")}, relative=True).frame
    assert shown.iloc[0].tolist() == ["refined", "3.38e-01", "33"]


def test_a_column_of_words_not_listed_is_text_aligned_left() -> None:
    table = tables.show(pd.DataFrame({"method": ["fixed rule (72 nodes)"], "evals_per_s": [3.163e6]}))
    assert table.frame.iloc[0].tolist() == ["fixed rule (72 nodes)", "3.163e+06"]
    assert table.left == frozenset({"method"})


def test_a_column_of_numbers_has_one_format() -> None:
    """Issue 27's rigs table: 60.00, 100.0 and 20 in one column read 60.00, 100.0, 20.00 (four figures each); whole
    numbers stay whole; a value with fewer figures is not padded where no other needs more; a column spanning 1e-6
    to 1 is scientific throughout."""
    assert tables.uniform([59.99999, 100.00001, 20.0]) == ["60.00", "100.0", "20.00"]
    assert tables.uniform([20.0, 40.0, float("nan")]) == ["20", "40", tables.MISSING]
    assert tables.uniform([44.5, float("nan")]) == ["44.5", tables.MISSING]
    assert tables.uniform([1.494, 2.753e-06, 0.25]) == ["1.494e+00", "2.753e-06", "2.500e-01"]
    assert tables.uniform([100.0, 1e4, 1e6, 1e9]) == ["1e+02", "1e+04", "1e+06", "1e+09"]
    assert tables.uniform([2.0236, 42.36, 4432.4]) == ["2.024", "42.36", "4432"]


def test_booleans_and_statuses_read_as_words() -> None:
    frame = pd.DataFrame({"stable": [True, False], "status": ["ok; pull-off pulloff", "budget_exceeded"]})
    assert tables.formatted(frame).values.tolist() == [["yes", "ok; pull-off found"], ["no", "budget exceeded"]]
