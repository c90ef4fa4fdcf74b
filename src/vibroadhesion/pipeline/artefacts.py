"""Deterministic writers for the pipeline's artefacts (CSV, JSON, PDF, PNG).

Same inputs give the same bytes: CSVs use a fixed float format and line ending, figures are
saved without timestamps or software versions in their metadata, and every file is written
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
from typing import Any, Iterator

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

STYLE = {
    "font.size": 9,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "legend.fontsize": 7.5,
    "figure.dpi": 100,
    "savefig.dpi": 200,
    "path.simplify": False,
    "svg.hashsalt": "vibroadhesion",
}
plt.rcParams.update(STYLE)

_PDF_METADATA = {"CreationDate": None, "Creator": None, "Producer": None}
_PNG_METADATA = {"Software": None}


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


def save_figure(fig: plt.Figure, pdf: str | Path, png: str | Path) -> None:
    """Save ``fig`` as PDF and PNG without time stamps, then close it."""
    _write_with(pdf, lambda tmp: fig.savefig(tmp, format="pdf", metadata=_PDF_METADATA, bbox_inches="tight"))
    _write_with(png, lambda tmp: fig.savefig(tmp, format="png", metadata=_PNG_METADATA, bbox_inches="tight"))
    plt.close(fig)
