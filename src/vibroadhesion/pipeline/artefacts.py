"""Deterministic writers for the pipeline's tables (CSV, JSON).

Figures are written by :func:`vibroadhesion.pipeline.figures.save_figure`.

Same inputs give the same bytes: CSVs write floats as repr (the shortest text that round-trips) with
one line ending, and every file is written to a temporary name in its folder and moved into place
(:func:`~vibroadhesion.pipeline.atomic.atomic_path`: mode 0o666 & ~umask, like any file the user
creates), so a failed step leaves no partial output behind. Standard library only (pandas for
types): a step that writes no figure does not pay for matplotlib.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

from vibroadhesion.pipeline.atomic import atomic_path

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["write_csv", "write_json"]


def write_csv(table: pd.DataFrame, path: str | Path) -> None:
    r"""CSV with each float as repr, '\n' line ends, no index.

    repr is the shortest text that reads back to the same double: 0.05, not 0.050000000000000003.
    """
    with atomic_path(path) as tmp:
        table.to_csv(tmp, index=False, lineterminator="\n")


def write_json(data: Any, path: str | Path) -> None:
    """Indented JSON with sorted keys and a final newline."""
    with atomic_path(path) as tmp:
        tmp.write_text(json.dumps(data, indent=2, sort_keys=True, allow_nan=False) + "\n")
