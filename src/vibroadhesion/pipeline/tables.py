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
from dataclasses import dataclass, replace
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
    "Abar": Column("Ā = ωA/v0"), "Abar_cr": Column("Ā_cr"), "sqrt_w_eff_ratio": Column("√(w_eff/w0)"),
    "abar_m": Column("a_m/a_o"), "abar_cr": Column("a_cr/a_o"), "w_eff_ratio": Column("w_eff/w0"),
    "A_over_am": Column("A/a_m"), "pm_over_abs_pjkr": Column("P_m/|P_JKR|"),
    "steady_states": Column("steady states", format="int"),
    "kappa": Column("κ", format="exact"), "zeta": Column("ζ", format="exact"), "mu": Column("μ", format="exact"),
    "nu0": Column("ν0"),
    # words
    **{name: Column(name.replace("model", "model level"), format="text")
       for name in ("source", "status", "model", "fixation", "quantity", "unit", "definition", "direction")},
    "relative_error": Column("relative error", format="rel"), "value": Column("value"),
}

#: Column-name endings that mark a relative error or bias (shown in scientific notation).
_RELATIVE_ENDINGS = ("error", "_bias", "relative_residual")


def significant(value: object, digits: int = SIGNIFICANT) -> str:
    """``value`` to ``digits`` significant figures; integers as such.

    Trailing zeros are kept where the value was rounded (``1.010``, ``12.00``), none are added to a value that has
    no more figures (``0.25``, not ``0.2500``; ``4.45e-05``). Plain notation from 1e-3 to 1e5, scientific outside
    (``1.235e-05``).
    """
    x = _number(value)
    if x is None:
        return MISSING if _missing(value) else str(value)
    if x.is_integer() and abs(x) < 1e5:
        return f"{x:.0f}"
    rounded = float(f"{x:.{digits}g}")
    if rounded == x and 1e-3 <= abs(x) < 1e5:  # no more figures than shown: no padding zeros (0.25, not 0.2500)
        return repr(x)
    if not 1e-3 <= abs(x) < 1e5:
        shortest = (text for k in range(digits - 1) if float(text := f"{x:.{k}e}") == x)
        return next(shortest, f"{x:.{digits - 1}e}")
    if abs(rounded) >= 1e5:  # 99999.9 rounds out of the plain range
        return f"{x:.{digits - 1}e}"
    return f"{rounded:.{max(0, digits - 1 - math.floor(math.log10(abs(rounded))))}f}"


def relative(value: object, digits: int = RELATIVE) -> str:
    """A relative error in scientific notation with ``digits`` significant figures (``-3.38e-01``)."""
    x = _number(value)
    if x is None:
        return MISSING if _missing(value) else str(value)
    return f"{x:.{digits - 1}e}"


def exact(value: object) -> str:
    """An input value as typed: the shortest repr that round-trips (``4.45e-05``, ``0.531``), integers as such."""
    x = _number(value)
    if x is None:
        return MISSING if _missing(value) else str(value)
    return f"{x:.0f}" if x.is_integer() else repr(x)


#: ± between no-break spaces: a value and its error stay on one line.
_PM = "\u00a0±\u00a0"


def plus_minus(value: float, std_error: float) -> str:
    """``value ± std_error``: the error to 2 significant figures, the value to the same last decimal.

    Outside 1e-3 to 1e5 both share a power of ten: ``(4.450 ± 0.012)e-05``. Where that rounding would show a
    nonzero value as 0 (an error orders of magnitude above the value: a parameter the rows do not determine), both
    are shown to 4 significant figures instead.
    """
    if not (math.isfinite(value) and math.isfinite(std_error)) or std_error <= 0:
        return f"{significant(value)}{_PM}{significant(std_error)}"
    exponent = 0 if value == 0 or 1e-3 <= abs(value) < 1e5 else math.floor(math.log10(abs(value)))
    scale = 10.0 ** exponent
    decimals = max(0, 1 - math.floor(math.log10(std_error / scale)))
    if value != 0 and abs(value / scale) < 0.5 * 10.0**-decimals:
        return f"{significant(value)}{_PM}{significant(std_error)}"
    text = f"{value / scale:.{decimals}f}{_PM}{std_error / scale:.{decimals}f}"
    return text if exponent == 0 else f"({text})e{exponent:+03d}"


def column(name: str, columns: Mapping[str, Column] | None = None, relative: bool = False) -> Column:
    """How column ``name`` is shown: from ``columns``, else :data:`COLUMNS`, else by its name.

    A CSV name is read with spaces for underscores (not a label with a ratio in it); one ending in
    :data:`_RELATIVE_ENDINGS` is a relative error, and so is every number of a table of ``relative`` errors.
    """
    if columns and name in columns:
        return columns[name]
    label = name if "/" in name else name.replace("_", " ")  # A/a_m at 200 Hz is a label already
    spec = COLUMNS.get(name) or Column(label, format="rel" if name.endswith(_RELATIVE_ENDINGS) else "sig")
    return replace(spec, format="rel") if relative and spec.format == "sig" else spec


def specs(frame: pd.DataFrame, columns: Mapping[str, Column] | None = None,
          relative: bool = False) -> dict[str, Column]:
    """How each column of ``frame`` (index reset) is shown (:func:`column`); a column of words not listed is text."""
    out = {}
    for name in frame.columns:
        spec = column(str(name), columns, relative)
        listed = (columns and name in columns) or name in COLUMNS
        numeric = pd.api.types.is_numeric_dtype(frame[name]) and not pd.api.types.is_bool_dtype(frame[name])
        out[str(name)] = spec if listed or numeric else replace(spec, format="text")
    return out


def formatted(frame: pd.DataFrame, columns: Mapping[str, Column] | None = None,
              relative: bool = False) -> pd.DataFrame:
    """``frame`` as the page shows it: strings, headers ``label (unit)``, the index (if named) as leading columns.

    A ``sig`` column has one number format (:func:`uniform`); a status or method column reads in words
    (:func:`status_words`).
    """
    if frame.index.names != [None]:
        frame = frame.reset_index()
    out = {}
    for name, spec in specs(frame, columns, relative).items():
        values = list(frame[name])
        if name.partition(":")[0].endswith("status") or name == "method":
            values = [status_words(v) if isinstance(v, str) else v for v in values]
        out[spec.header] = uniform(values) if spec.format == "sig" else [_cell(v, spec.format) for v in values]
    return pd.DataFrame(out)


#: Status codes of the artefacts as a reader says them (others: underscores read as spaces).
STATUS_WORDS = {"pulloff": "pull-off found", "pull-off pulloff": "pull-off found", "ok": "ok"}


def status_words(status: str) -> str:
    """A status of an artefact in words: ``ok; pull-off pulloff`` -> ``ok; pull-off found``.

    Each part of a status joined by "; " alike; a code not in :data:`STATUS_WORDS` reads with spaces for underscores
    (``contact_loss`` -> ``contact loss``).
    """
    return "; ".join(STATUS_WORDS.get(part, part.replace("_", " ")) for part in status.split("; "))


def uniform(values: list[object]) -> list[str]:
    """A column of numbers in one format: the same significant figures and the same notation for every number.

    Whole numbers below 1e5 as such. Else as many significant figures as the most precise value needs (at most
    :data:`SIGNIFICANT`: 44.5 stays 44.5; 20, 59.99999 and 100.00001 read 20.00, 60.00 and 100.0), in plain notation
    where every number lies in 1e-3 to 1e5 (or is 0), else all in scientific notation. Missing numbers read
    :data:`MISSING`, words as they are.
    """
    numbers = [x for x in map(_number, values) if x is not None]
    nonzero = [abs(x) for x in numbers if x != 0]
    if all(x.is_integer() and abs(x) < 1e5 for x in numbers):
        return [f"{x:.0f}" if (x := _number(v)) is not None else _cell(v, "text") for v in values]
    digits = max((_figures(x) for x in nonzero), default=1)
    plain = all(1e-3 <= x < 1e5 for x in nonzero)
    return [(_plain(x, digits) if plain else f"{x:.{digits - 1}e}") if (x := _number(v)) is not None
            else _cell(v, "text") for v in values]


def _figures(x: float) -> int:
    """The significant figures that show ``x`` exactly, at most :data:`SIGNIFICANT`."""
    return next((k for k in range(1, SIGNIFICANT) if float(f"{x:.{k}g}") == x), SIGNIFICANT)


def _plain(x: float, digits: int) -> str:
    """``x`` to ``digits`` significant figures in plain notation, trailing zeros kept (``20.00``, ``100.0``)."""
    if x == 0:
        return f"{0:.{max(0, digits - 1)}f}"
    rounded = float(f"{x:.{digits}g}")
    return f"{rounded:.{max(0, digits - 1 - math.floor(math.log10(abs(rounded))))}f}"


def _cell(value: object, format: Format) -> str:
    """One cell in ``format`` (see the module docstring); a boolean as yes or no."""
    if isinstance(value, (bool, np.bool_)):
        return "yes" if value else "no"
    if format == "text":
        return MISSING if _missing(value) else str(value)
    if format == "int":
        x = _number(value)
        return MISSING if x is None else f"{x:.0f}"
    if format == "exact":
        return exact(value)
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

    Columns whose header is in ``left`` (text) are aligned left and may wrap, numbers right on one line; a table
    wider than the page scrolls instead of being clipped.
    """

    frame: pd.DataFrame
    left: frozenset[str] = frozenset()

    def _repr_html_(self) -> str:
        """The HTML table a page shows (Jupyter's rich display)."""
        align = ["left" if h in self.left else "right" for h in self.frame.columns]
        head = "".join(f'<th style="text-align: {a}">{html.escape(str(h))}</th>'
                       for h, a in zip(self.frame.columns, align, strict=True))
        cell = [f"text-align: {a}" + ("" if a == "left" else "; white-space: nowrap") for a in align]
        body = "".join("<tr>" + "".join(f'<td style="{c}">{html.escape(str(v))}</td>'
                                        for v, c in zip(row, cell, strict=True)) + "</tr>"
                       for row in self.frame.itertuples(index=False))
        return (f'<div style="overflow-x: auto"><table class="report-table"><thead><tr>{head}</tr></thead>'
                f"<tbody>{body}</tbody></table></div>")

    def __repr__(self) -> str:
        """The table as plain text, without an index."""
        return self.frame.to_string(index=False)


def show(frame: pd.DataFrame, columns: Mapping[str, Column] | None = None, relative: bool = False) -> Table:
    """The table a page displays for ``frame`` (:func:`formatted`; ``columns`` override :data:`COLUMNS`).

    ``relative``: every number not otherwise specified is a relative error (a table of errors).
    """
    shown = specs(frame.reset_index() if frame.index.names != [None] else frame, columns, relative)
    return Table(formatted(frame, columns, relative),
                 frozenset(spec.header for spec in shown.values() if spec.format == "text"))
