"""Deterministic writers for the pipeline's artefacts (CSV, JSON, PDF, PNG).

Same inputs give the same bytes: CSVs use a fixed float format and line ending, figures are
saved without timestamps or software versions in their metadata, and every file is written
to a temporary name in its folder and moved into place (:func:`~vibroadhesion.pipeline.atomic.atomic_path`:
mode 0o666 & ~umask, like any file the user creates), so a failed step leaves no partial output behind.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

from vibroadhesion.pipeline.atomic import atomic_path  # noqa: E402  (re-exported for report and benchmarks)

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
