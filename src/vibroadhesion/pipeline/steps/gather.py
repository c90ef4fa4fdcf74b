"""Step of the gather rules: tables of one layout concatenated in the order given."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import pandas as pd

from vibroadhesion.pipeline.artefacts import write_csv


def concatenate(parts: Sequence[str | Path], out: str | Path) -> None:
    """``out``: the rows of every CSV of ``parts``, in that order, with the columns of the first."""
    write_csv(pd.concat([pd.read_csv(p) for p in parts], ignore_index=True), out)
