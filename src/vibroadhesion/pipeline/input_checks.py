"""Schema checks and one-line error messages shared by the readers of the two user-edited inputs.

:mod:`vibroadhesion.pipeline.data` reads ``data/setup.yaml`` and ``data/pulloff.csv``; this module
holds what both readers share: :class:`DataError` (``"<file>, row <r>, column <c>: <what is wrong>"``),
the packaged JSON schemas (draft 2020-12, ``vibroadhesion/pipeline/schemas/``) with their validators,
the translation of a schema violation into that one-line message, the UTF-8 file reader, the line of
each YAML node (with the refusal of numbers that YAML 1.1 reads in another base), the checks of a CSV header
and row length, and the check of the two files against each other (a pull-off force on the scale of the setup's
JKR force).
"""

from __future__ import annotations

import difflib
import json
import math
import re
from collections.abc import Sequence
from functools import cache
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any, NoReturn

import yaml

if TYPE_CHECKING:
    from jsonschema import Draft202012Validator
    from jsonschema.exceptions import ValidationError


class DataError(ValueError):
    """One-line message: '<file>, row <r>, column <c>: <what is wrong>'."""

    def __init__(self, path: str | Path, row: int, column: str, message: str) -> None:
        """Locate the problem: ``path`` of the file, 1-based ``row`` (0: the whole file), ``column``."""
        self.path, self.row, self.column = str(path), int(row), str(column)
        self.message = " ".join(str(message).split())  # one line, whatever the source text
        super().__init__(f"{self.path}, row {self.row}, column {self.column}: {self.message}")


@cache
def schema(name: str) -> dict[str, Any]:
    """The packaged JSON schema ``name`` (``"setup"``, ``"pulloff"``, or ``"fit"``: the fit summary)."""
    schema_file = resources.files("vibroadhesion.pipeline").joinpath("schemas", f"{name}.schema.json")
    text = schema_file.read_text(encoding="utf-8")
    return json.loads(text)


@cache
def schema_validator(name: str) -> Draft202012Validator:
    """A validator for the packaged JSON schema ``name`` (built once per name).

    jsonschema is imported here, by the steps that validate (the ingest rules, the Snakefile), not by every step
    that reads the canonical copies through :mod:`vibroadhesion.pipeline.data` (0.06 CPU-s a process).
    """
    from jsonschema import Draft202012Validator

    return Draft202012Validator(schema(name))


def _fmt(value: object) -> str:
    if isinstance(value, bool) or value is None:
        return str(value).lower()
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return f'"{value}"'
    return kind_of(value)


def kind_of(value: object) -> str:
    """What ``value`` is, in words, for a message ("the number 2.0", "a list", ...)."""
    if value is None:
        return "an empty value"
    if isinstance(value, bool):
        return f"the boolean {str(value).lower()}"
    if isinstance(value, (int, float)):
        return f"the number {value!r}"
    if isinstance(value, str):
        return f'the text "{value}"'
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a mapping"
    return "an unsupported value"


_TYPE_NAMES = {"number": "a number", "array": "a list", "object": "a mapping", "string": "text"}


def schema_message(error: ValidationError) -> tuple[tuple[Any, ...], str, bool]:
    """(path of the offending node, message, whether the row is the parent key's line)."""
    path = tuple(error.absolute_path)
    custom = error.schema.get("x-messages", {}) if isinstance(error.schema, dict) else {}
    value = error.instance
    if error.validator in custom:
        return path, custom[error.validator].format(value=_fmt(value) if not isinstance(value, str) else value,
                                                    got=kind_of(value)), False
    if error.validator == "required":
        present = value if isinstance(value, dict) else {}
        missing = next(k for k in error.validator_value if k not in present)
        return path + (missing,), f'missing required key "{missing}"', True
    if error.validator == "additionalProperties":
        allowed = set(error.schema.get("properties", {}))
        extra = sorted(str(k) for k in value if k not in allowed)
        close = difflib.get_close_matches(extra[0], sorted(allowed), n=1)
        if close:
            hint = f'; did you mean "{close[0]}"?'
        else:
            hint = f"; allowed here: {', '.join(sorted(allowed))}" if allowed else ""
        return path + (extra[0],), f'unknown key "{extra[0]}" (not declared in the schema{hint})', True
    if error.validator == "type":
        expected = error.validator_value
        names = [_TYPE_NAMES.get(t, t) for t in ([expected] if isinstance(expected, str) else expected)]
        return path, f"expected {' or '.join(names)}, got {kind_of(value)}", False
    generic = {
        "exclusiveMinimum": f"must be > {_fmt(error.validator_value)}, got {_fmt(value)}",
        "minimum": f"must be >= {_fmt(error.validator_value)}, got {_fmt(value)}",
        "maximum": f"must be <= {_fmt(error.validator_value)}, got {_fmt(value)}",
        "minItems": "list must not be empty",
        "uniqueItems": "list repeats a value",
        "minLength": "must not be empty",
        "pattern": "must not be empty",
        "const": f"must be {_fmt(error.validator_value)}, got {_fmt(value)}",
    }
    return path, generic.get(error.validator, f"invalid value ({error.validator})"), False


KEYWORD_ORDER = {"required": 0, "additionalProperties": 1, "type": 2, "exclusiveMinimum": 3, "minimum": 4, "maximum": 5}


def dotted(path: Sequence[Any]) -> str:
    """A key path as the message's column: ``sample.poisson_ratio.value``, list items as ``[1]``."""
    out = ""
    for part in path:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out or "(document)"


def read_text(path: Path) -> str:
    """The UTF-8 text of ``path`` (a BOM is dropped); :class:`DataError` when unreadable or not UTF-8."""
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise DataError(path, 0, "(file)", f"cannot read file: {exc.strerror or type(exc).__name__}") from None
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        row = raw[: exc.start].count(b"\n") + 1
        raise DataError(path, row, "(file)", "file is not UTF-8 text") from None


#: A YAML integer as a person writes it in decimal. YAML 1.1, which PyYAML follows, also reads ``020`` as
#: octal 16, ``0x20`` as 32, ``0b10`` as 2 and ``1:20`` (base 60) as 80: such a number is refused, not read.
_DECIMAL_INT = re.compile(r"^[-+]?(?:0|[1-9][0-9]*)$")
_INT_TAG, _FLOAT_TAG = "tag:yaml.org,2002:int", "tag:yaml.org,2002:float"


def _check_number_text(path: str | Path, node: yaml.ScalarNode, prefix: tuple[Any, ...]) -> None:
    """Refuse a YAML number whose text is not plain decimal (the base-changing spellings of YAML 1.1)."""
    text = node.value
    plain = _DECIMAL_INT.match(text) if node.tag == _INT_TAG else (":" not in text and "_" not in text)
    if not plain:
        raise DataError(path, node.start_mark.line + 1, dotted(prefix),
                        f'"{text}" is not a plain decimal number (YAML reads a leading 0, 0x, 0b, ":" or "_" '
                        "in another base or as a separator): write it in decimal")


def _walk_nodes(path: str | Path, n: yaml.Node, prefix: tuple[Any, ...],
                lines: dict[tuple[Any, ...], tuple[int, int]]) -> None:
    """Record the lines of the nodes under ``n`` (key path ``prefix``) in ``lines``; check keys and numbers."""
    if isinstance(n, yaml.MappingNode):
        seen: dict[str, int] = {}
        for key_node, value_node in n.value:
            row = key_node.start_mark.line + 1
            if not isinstance(key_node, yaml.ScalarNode) or key_node.tag != "tag:yaml.org,2002:str":
                raise DataError(path, row, dotted(prefix), "keys must be plain text names")
            key = key_node.value
            if key in seen:
                raise DataError(path, row, dotted(prefix + (key,)), f"duplicate key (first given at row {seen[key]})")
            seen[key] = row
            lines[prefix + (key,)] = (row, value_node.start_mark.line + 1)
            _walk_nodes(path, value_node, prefix + (key,), lines)
    elif isinstance(n, yaml.SequenceNode):
        for i, item in enumerate(n.value):
            row = item.start_mark.line + 1
            lines[prefix + (i,)] = (row, row)
            _walk_nodes(path, item, prefix + (i,), lines)
    elif isinstance(n, yaml.ScalarNode) and n.tag in (_INT_TAG, _FLOAT_TAG):
        _check_number_text(path, n, prefix)


def yaml_node_lines(path: str | Path, node: yaml.Node) -> dict[tuple[Any, ...], tuple[int, int]]:
    """Map each key path to (line of its key, line of its value).

    Rejects duplicate or non-text keys and numbers that YAML 1.1 reads in another base (:func:`_check_number_text`).
    """
    lines: dict[tuple[Any, ...], tuple[int, int]] = {(): (node.start_mark.line + 1, node.start_mark.line + 1)}
    _walk_nodes(path, node, (), lines)
    return lines


#: A measured pull-off force below this fraction of |P_cr^JKR| (Eq. 70) at the setup's w0 and R is refused as a
#: unit slip. Vibration only raises the work of adhesion (w >= w0, Eq. 6), so every model level and the simulation
#: give at least |P_cr^JKR|; a force below 0.3 of it is far more likely newtons typed in the millinewton column.
MIN_PULLOFF_OVER_JKR = 0.3


def jkr_pulloff_mN(radius: float, w0: float) -> float:
    """|P_cr^JKR| = (3 pi / 2) R w0 (Eq. 70) in mN, R in m, w0 in J/m^2 (core.jkr.pulloff_force without numpy)."""
    return 1.5 * math.pi * radius * w0 * 1e3


def check_force_scale(radius: float, w0: float, records: Sequence[dict[str, Any]], pulloff_csv: str | Path) -> None:
    """Refuse the first row whose ``pulloff_mN`` is below :data:`MIN_PULLOFF_OVER_JKR` |P_cr^JKR| (a unit slip).

    ``radius`` (m) and ``w0`` (J/m^2) of data/setup.yaml; ``records`` the rows, each with its ``line`` in the file.
    """
    floor = MIN_PULLOFF_OVER_JKR * jkr_pulloff_mN(radius, w0)
    for rec in records:
        if rec["pulloff_mN"] < floor:
            raise DataError(pulloff_csv, rec["line"], "pulloff_mN",
                            f"pull-off force {rec['pulloff_mN']!r} mN is below {MIN_PULLOFF_OVER_JKR} |P_JKR| = "
                            f"{floor:.3g} mN of the setup's w0 and R (vibration only raises it): looks like N, "
                            "expected mN (for a weaker adhesive, set gent_schultz_published.w0 in the setup)")


def check_csv_header(path: str | Path, line_no: int, header: Sequence[str], required: Sequence[str],
                     optional: Sequence[str]) -> None:
    """Refuse a CSV header that is not the ``required`` columns (in any order) and any of the ``optional`` ones.

    A wrong delimiter, an empty, duplicate, unknown or missing column name: the first, as a :class:`DataError`.
    """
    expected = ",".join(required)
    if len(header) == 1 and (";" in header[0] or "\t" in header[0]):
        sep = "';'" if ";" in header[0] else "a tab"
        raise DataError(path, line_no, "header",
                        f"wrong delimiter: fields are separated by {sep}; use commas ({expected})")
    seen: set[str] = set()
    for name in header:
        if not name:
            raise DataError(path, line_no, "header", f"empty column name; expected {expected}")
        if name in seen:
            raise DataError(path, line_no, name, "duplicate column name")
        seen.add(name)
        if name not in (*required, *optional):
            raise DataError(path, line_no, name, f'unknown column "{name}"; expected exactly {expected} '
                            f"(and optionally {', '.join(optional)})")
    for name in required:
        if name not in seen:
            raise DataError(path, line_no, name, f'missing column "{name}"; expected {expected}')


def field_count_error(path: str | Path, line_no: int, header: Sequence[str], cells: Sequence[str]) -> NoReturn:
    """Raise the :class:`DataError` of a CSV row whose number of ``cells`` is not that of the ``header``."""
    n, m = len(cells), len(header)
    if n < m:
        hint = "; wrong delimiter? use commas" if n == 1 and (";" in cells[0] or "\t" in cells[0]) else ""
        raise DataError(path, line_no, header[n], f"too few fields: {n} instead of {m}, no value for this column{hint}")
    raise DataError(path, line_no, f"field {m + 1}",
                    f"too many fields: {n} instead of {m} (a decimal comma, or an unquoted comma in source?)")
