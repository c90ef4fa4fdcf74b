"""Deterministic writers for the pipeline's tables (CSV, JSON); figures: :func:`vibroadhesion.pipeline.figures.save_figure`.

Same inputs give the same bytes: CSVs use a fixed float format and line ending, and every file is written
to a temporary name in its folder and moved into place, so a failed step leaves no partial
output behind.
"""

from __future__ import annotations

import json
import os
import tempfile
from collections.abc import Callable
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Any, Iterator

if TYPE_CHECKING:
    import pandas as pd


@contextmanager
def atomic_path(path: str | Path) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; move it onto ``path`` only if the block succeeds."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=path.suffix)
    os.close(fd)
    try:
        yield Path(tmp)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def _write_with(path: str | Path, writer: Callable[[Path], None]) -> None:
    with atomic_path(path) as tmp:
        writer(tmp)


def write_csv(table: pd.DataFrame, path: str | Path) -> None:
    """CSV with 17 significant digits (round-trips doubles), '\\n' line ends, no index."""
    _write_with(path, lambda tmp: table.to_csv(tmp, index=False, float_format="%.17g", lineterminator="\n"))


def write_json(data: Any, path: str | Path) -> None:
    """Indented JSON with sorted keys and a final newline."""
    _write_with(path, lambda tmp: tmp.write_text(json.dumps(data, indent=2, sort_keys=True, allow_nan=False) + "\n"))
