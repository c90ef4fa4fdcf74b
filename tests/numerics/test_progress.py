"""The log progress bar: bar length, counts and steady-state total after each item."""

import io

import pytest

from vibroadhesion.numerics.progress import BAR_WIDTH, ProgressBar


def test_bar_fills_in_proportion_and_sums_steady_states() -> None:
    out = io.StringIO()
    bar = ProgressBar(10, "points", stream=out)
    for solved in (4, 5, 6):
        bar.advance(solved, note="ok")
    last = out.getvalue().splitlines()[-1]
    assert last.startswith("[" + "#" * 9 + "." * (BAR_WIDTH - 9) + "]  3/10 points  15 steady states")
    assert last.endswith("  ok")
    assert len(out.getvalue().splitlines()) == 3


def test_empty_bar_is_an_error() -> None:
    with pytest.raises(ValueError, match="at least one item"):
        ProgressBar(0, "points")
