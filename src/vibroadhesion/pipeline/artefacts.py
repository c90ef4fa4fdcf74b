"""Deterministic writers for the pipeline's artefacts (CSV, JSON, PDF, PNG).

Same inputs give the same bytes: CSVs use a fixed float format and line ending, figures are
saved without timestamps or software versions in their metadata, and every file is written
to a temporary name in its folder and moved into place (:func:`~vibroadhesion.pipeline.atomic.atomic_path`:
mode 0o666 & ~umask, like any file the user creates), so a failed step leaves no partial output behind.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

from vibroadhesion.pipeline.atomic import atomic_path  # noqa: E402

if TYPE_CHECKING:
    from matplotlib.figure import Figure
    from matplotlib.typing import RcKeyType

__all__ = ["STYLE", "atomic_path", "save_figure", "write_csv", "write_json"]  # atomic_path: for report, benchmarks

STYLE: dict[RcKeyType, Any] = {
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


def write_csv(table: pd.DataFrame, path: str | Path) -> None:
    r"""CSV with 17 significant digits (round-trips doubles), '\n' line ends, no index."""
    with atomic_path(path) as tmp:
        table.to_csv(tmp, index=False, float_format="%.17g", lineterminator="\n")


def write_json(data: Any, path: str | Path) -> None:
    """Indented JSON with sorted keys and a final newline."""
    with atomic_path(path) as tmp:
        tmp.write_text(json.dumps(data, indent=2, sort_keys=True, allow_nan=False) + "\n")


def save_figure(fig: Figure, pdf: str | Path, png: str | Path) -> None:
    """Save ``fig`` as PDF and PNG without time stamps, then close it."""
    with atomic_path(pdf) as tmp:
        fig.savefig(tmp, format="pdf", metadata=_PDF_METADATA, bbox_inches="tight")
    with atomic_path(png) as tmp:
        fig.savefig(tmp, format="png", metadata=_PNG_METADATA, bbox_inches="tight")
    plt.close(fig)
