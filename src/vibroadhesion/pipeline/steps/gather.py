"""Steps of the gather rules: tables of one layout concatenated in the order given, or sorted (the rigid grid)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import pandas as pd

from vibroadhesion.pipeline.artefacts import write_csv


def concatenate(parts: Sequence[str | Path], out: str | Path) -> None:
    """``out``: the rows of every CSV of ``parts``, in that order, with the columns of the first."""
    write_csv(pd.concat([pd.read_csv(p) for p in parts], ignore_index=True), out)


def rigid_grid(parts: Sequence[str | Path], out: str | Path) -> None:
    """results/simulation/rigid_grid.csv: every amplitude's rows, sorted by (h1, omega_check).

    Here, not beside the simulation's steps: a gather imports pandas only, not the simulation (numba, scipy).
    """
    grid = pd.concat([pd.read_csv(p) for p in parts], ignore_index=True)
    write_csv(grid.sort_values(["h1_um", "omega_check"], kind="stable").reset_index(drop=True), out)
