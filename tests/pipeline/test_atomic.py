"""Atomic output files and their permissions (vibroadhesion.pipeline.atomic and its two users).

Every output must be readable like any file the user creates: mode ``0o666 & ~umask``, checked
under two umasks (the usual 0o022 and the private 0o077), for the result writers of
``artefacts`` and for the canonical inputs written by ``data.main``.
"""

from __future__ import annotations

import os
import stat
from collections.abc import Iterator
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import pytest

from vibroadhesion.pipeline.artefacts import write_csv, write_json
from vibroadhesion.pipeline.atomic import atomic_path, create_beside
from vibroadhesion.pipeline.data import main as data_main
from vibroadhesion.pipeline.figures import save_figure

ROOT = Path(__file__).resolve().parents[2]
UMASKS = {0o022: 0o644, 0o077: 0o600}  # umask -> the mode a file created with 0o666 gets


@pytest.fixture(params=sorted(UMASKS), ids=lambda u: f"umask{u:04o}")
def umask(request: pytest.FixtureRequest) -> Iterator[int]:
    """Run the test under a given process umask, restoring the previous one afterwards."""
    previous = os.umask(request.param)
    try:
        yield request.param
    finally:
        os.umask(previous)


def _mode(path: Path) -> int:
    return stat.S_IMODE(path.stat().st_mode)


def _hidden(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


def test_artefact_writers_respect_the_umask(tmp_path: Path, umask: int) -> None:
    write_csv(pd.DataFrame({"x": [1.0, 2.0]}), tmp_path / "t.csv")
    write_json({"a": 1}, tmp_path / "t.json")
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    save_figure(fig, tmp_path / "f.pdf", tmp_path / "f.png")
    for name in ("t.csv", "t.json", "f.pdf", "f.png"):
        assert _mode(tmp_path / name) == UMASKS[umask], name
    assert _hidden(tmp_path) == []


def test_data_main_outputs_respect_the_umask(tmp_path: Path, umask: int) -> None:
    out_json, out_csv = tmp_path / "canon" / "setup.json", tmp_path / "canon" / "pulloff.csv"
    inputs = [str(ROOT / "data" / "setup.yaml"), str(ROOT / "data" / "pulloff.csv")]
    assert data_main([*inputs, str(out_json), str(out_csv)]) == 0
    assert (_mode(out_json), _mode(out_csv)) == (UMASKS[umask], UMASKS[umask])
    assert _hidden(out_json.parent) == []


def test_replacing_an_existing_output_takes_the_umask_mode(tmp_path: Path, umask: int) -> None:
    target = tmp_path / "old.txt"
    target.write_text("old")
    target.chmod(0o640)
    with atomic_path(target) as tmp:
        tmp.write_text("new")
    assert target.read_text() == "new"
    assert _mode(target) == UMASKS[umask]


def test_failed_block_leaves_target_and_folder_as_they_were(tmp_path: Path) -> None:
    target = tmp_path / "keep.csv"
    target.write_text("before")
    with pytest.raises(RuntimeError, match="writer failed"), atomic_path(target) as tmp:
        tmp.write_text("partial")
        raise RuntimeError("writer failed")
    assert target.read_text() == "before"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keep.csv"]


def test_atomic_path_creates_missing_folders(tmp_path: Path) -> None:
    target = tmp_path / "a" / "b" / "c.json"
    with atomic_path(target) as tmp:
        assert tmp.parent == target.parent and tmp.name.startswith(".c.json.") and tmp.suffix == ".json"
        tmp.write_text("{}")
    assert target.read_text() == "{}"


def test_create_beside_never_reuses_an_existing_name(tmp_path: Path) -> None:
    target = tmp_path / "x.csv"
    names = {create_beside(target) for _ in range(50)}
    assert len(names) == 50
    assert all(p.exists() and p.stat().st_size == 0 for p in names)


def test_csv_floats_are_the_shortest_text_that_reads_back_to_the_same_double(tmp_path: Path) -> None:
    """Python's repr is the shortest round-tripping decimal (0.05, 4.45e-05; the old %.17g wrote
    0.050000000000000003): the text of typed values stays as typed, and any double reads back bit for bit."""
    values = np.random.default_rng(0).standard_normal(1000) * 10.0 ** np.random.default_rng(1).integers(-300, 300, 1000)
    write_csv(pd.DataFrame({"x": [0.05, 4.45e-05, 20.0, *values]}), tmp_path / "t.csv")
    lines = (tmp_path / "t.csv").read_text().splitlines()
    assert lines[1:4] == ["0.05", "4.45e-05", "20.0"]
    assert np.array_equal(pd.read_csv(tmp_path / "t.csv")["x"].to_numpy()[3:], values)
