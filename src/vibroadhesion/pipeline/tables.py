"""Tables as the report pages show them: readable headers with units, rounded numbers, no index.

The artefact CSVs keep every digit; only the pages round. A column is shown by its :class:`Column`: a label
(the paper's symbol, docs/notation.md), its unit (the header reads ``label (unit)``; none for a dimensionless
number) and a format: ``sig`` (:data:`SIGNIFICANT` significant figures), ``rel`` (a relative error, in
scientific notation with :data:`RELATIVE` significant figures), ``int``, ``exact`` (an input value as typed: the
shortest repr that round-trips) or ``text``. The columns the pipeline's
CSVs share are in :data:`COLUMNS`; a page passes its own for the others.
"""

from __future__ import annotations

import html
import math
import numbers
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

import numpy as np
import pandas as pd

Format = Literal["sig", "rel", "int", "exact", "text"]

#: Significant figures of a value on a page (the CSVs keep all 17).
SIGNIFICANT = 4
#: Significant figures of a relative error (scientific notation).
RELATIVE = 3
#: What a page shows for a number that is missing (NaN, None): not computed or no solution.
MISSING = "—"


@dataclass(frozen=True)
class Column:
    """How a page shows one column: header ``label (unit)`` (unit empty: dimensionless) and the format."""

    label: str
    unit: str = ""
    format: Format = "sig"

    @property
    def header(self) -> str:
        """``label (unit)``, or the label alone for a dimensionless number."""
        return f"{self.label} ({self.unit})" if self.unit else self.label


#: The columns of the pipeline's artefacts, by CSV name: symbol, unit and equation from docs/notation.md.
COLUMNS: dict[str, Column] = {
    # test conditions and pull-off (§2 of docs/notation.md)
    "frequency_hz": Column("f", "Hz"), "h1_um": Column("h1", "µm"), "pulloff_mN": Column("|P_cr|", "mN"),
    "pulloff_ratio": Column("P_cr/P_JKR"), "eta1": Column("η1 = h1/R"), "chi0": Column("χ0"),
    "omega_check": Column("ωR/v0 (ω̌, Eq. 105)"), "omega_bar": Column("ω/ω0 (ω̄, Eq. 65)"),
    # rate law (§1)
    "w0": Column("w0", "J/m²"), "v0": Column("v0", "m/s"), "n": Column("n"),
    # steady state (§4) and fixation (§3)
    "Abar": Column("Ā = ωA/v0"), "abar_m": Column("a_m/a_o"), "abar_cr": Column("a_cr/a_o"),
    "w_eff_ratio": Column("w_eff/w0"), "A_over_am": Column("A/a_m"), "steady_states": Column("steady states",
                                                                                           format="int"),
    "kappa": Column("κ"), "zeta": Column("ζ"), "mu": Column("μ"), "nu0": Column("ν0"),
    # words
    **{name: Column(name.replace("model", "model level"), format="text")
       for name in ("source", "status", "model", "fixation", "quantity", "unit", "definition", "direction")},
    "relative_error": Column("relative error", format="rel"), "value": Column("value"),
}

#: Column-name endings that mark a relative error or bias (shown in scientific notation).
_RELATIVE_ENDINGS = ("error", "_bias", "relative_residual")


def significant(value: object, digits: int = SIGNIFICANT) -> str:
    """``value`` to ``digits`` significant figures (trailing zeros kept: ``1.010``; whole numbers as integers).

    Plain notation from 1e-3 to 1e5, scientific outside (``1.235e-05``).
    """
    x = _number(value)
    if x is None:
        return MISSING if _missing(value) else str(value)
    if x == 0.0 or not 1e-3 <= abs(x) < 1e5:
        return "0" if x == 0.0 else f"{x:.{digits - 1}e}"
    rounded = float(f"{x:.{digits}g}")
    if rounded.is_integer():
        return f"{rounded:.0f}"
    return f"{rounded:.{max(0, digits - 1 - math.floor(math.log10(abs(rounded))))}f}"


def relative(value: object, digits: int = RELATIVE) -> str:
    """A relative error in scientific notation with ``digits`` significant figures (``-3.38e-01``)."""
    x = _number(value)
    if x is None:
        return MISSING if _missing(value) else str(value)
    return f"{x:.{digits - 1}e}"


def plus_minus(value: float, std_error: float) -> str:
    """``value ± std_error``: the error to 2 significant figures, the value to the same last decimal.

    Outside 1e-3 to 1e5 both share a power of ten: ``(4.450 ± 0.012)e-05``.
    """
    if not (math.isfinite(value) and math.isfinite(std_error)) or std_error <= 0:
        return f"{significant(value)} ± {significant(std_error)}"
    exponent = 0 if value == 0 or 1e-3 <= abs(value) < 1e5 else math.floor(math.log10(abs(value)))
    scale = 10.0 ** exponent
    decimals = max(0, 1 - math.floor(math.log10(std_error / scale)))
    text = f"{value / scale:.{decimals}f} ± {std_error / scale:.{decimals}f}"
    return text if exponent == 0 else f"({text})e{exponent:+03d}"


def column(name: str, columns: Mapping[str, Column] | None = None) -> Column:
    """How column ``name`` is shown: from ``columns``, else :data:`COLUMNS`, else by its name.

    A name is read with spaces for underscores; one ending in :data:`_RELATIVE_ENDINGS` is a relative error.
    """
    if columns and name in columns:
        return columns[name]
    if name in COLUMNS:
        return COLUMNS[name]
    return Column(name.replace("_", " "), format="rel" if name.endswith(_RELATIVE_ENDINGS) else "sig")


def formatted(frame: pd.DataFrame, columns: Mapping[str, Column] | None = None) -> pd.DataFrame:
    """``frame`` as the page shows it: strings, headers ``label (unit)``, the index (if named) as leading columns."""
    if frame.index.names != [None]:
        frame = frame.reset_index()
    shown = {}
    for name in frame.columns:
        spec = column(str(name), columns)
        shown[spec.header] = [_cell(value, spec.format) for value in frame[name]]
    return pd.DataFrame(shown)


def _cell(value: object, format: Format) -> str:
    """One cell in ``format`` (see the module docstring)."""
    if format == "text":
        return MISSING if _missing(value) else str(value)
    x = _number(value)
    if format == "int" or (format == "exact" and x is not None and x.is_integer()):
        return MISSING if x is None else f"{x:.0f}"
    if format == "exact":
        return MISSING if _missing(value) else repr(x) if x is not None else str(value)
    return relative(value) if format == "rel" else significant(value)


def _number(value: object) -> float | None:
    """``value`` as a finite float, or None (missing, NaN, a boolean or not a number)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        return None
    x = float(value)
    return x if math.isfinite(x) else None


def _missing(value: object) -> bool:
    """Whether ``value`` is a missing number (None or NaN)."""
    return value is None or (isinstance(value, float) and math.isnan(value))


@dataclass(frozen=True)
class Table:
    """A formatted table that a notebook displays: HTML without an index, plain text in the executed notebook.

    Columns whose header is in ``left`` (text) are aligned left, numbers right.
    """

    frame: pd.DataFrame
    left: frozenset[str] = frozenset()

    def _repr_html_(self) -> str:
        """The HTML table a page shows (Jupyter's rich display)."""
        align = ["left" if h in self.left else "right" for h in self.frame.columns]
        head = "".join(f'<th style="text-align: {a}">{html.escape(str(h))}</th>'
                       for h, a in zip(self.frame.columns, align, strict=True))
        body = "".join("<tr>" + "".join(f'<td style="text-align: {a}">{html.escape(str(v))}</td>'
                                        for v, a in zip(row, align, strict=True)) + "</tr>"
                       for row in self.frame.itertuples(index=False))
        return f'<table class="report-table"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>'

    def __repr__(self) -> str:
        """The table as plain text, without an index."""
        return self.frame.to_string(index=False)


def show(frame: pd.DataFrame, columns: Mapping[str, Column] | None = None) -> Table:
    """The table a page displays for ``frame`` (:func:`formatted`; ``columns`` override :data:`COLUMNS`)."""
    names = frame.reset_index().columns if frame.index.names != [None] else frame.columns
    left = frozenset(column(str(n), columns).header for n in names if column(str(n), columns).format == "text")
    return Table(formatted(frame, columns), left)
