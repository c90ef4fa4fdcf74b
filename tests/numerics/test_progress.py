"""Log progress: the bar (length, counts and steady-state total after each item) and the heartbeat."""

import io

import pytest

from vibroadhesion.numerics.progress import BAR_WIDTH, Heartbeat, ProgressBar


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


def test_heartbeat_prints_only_after_its_interval_with_the_time_so_far() -> None:
    out = io.StringIO()
    times = iter([100.0, 103.0, 111.0, 115.0, 121.5])  # start, then one reading per beat
    beat = Heartbeat("fit simulation", interval=10.0, stream=out, clock=lambda: next(times))
    for note in ("a", "b", "c", "d"):
        beat.beat(note)
    assert out.getvalue().splitlines() == ["fit simulation: 11 s  b", "fit simulation: 22 s  d"]
