"""Schema checks and one-line error messages shared by the readers of the two user-edited inputs.

:mod:`vibroadhesion.pipeline.data` reads ``data/setup.yaml`` and ``data/pulloff.csv``; this module
holds what both readers share: :class:`DataError` (``"<file>, row <r>, column <c>: <what is wrong>"``),
the packaged JSON schemas (draft 2020-12, ``vibroadhesion/pipeline/schemas/``) with their validators,
the translation of a schema violation into that one-line message, the UTF-8 file reader, and the
check of the two files against each other (a pull-off force on the scale of the setup's JKR force).
"""

from __future__ import annotations

import difflib
import json
import math
from collections.abc import Sequence
from functools import cache
from importlib import resources
from pathlib import Path
from typing import Any

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
    """The packaged JSON schema ``name`` (``"setup"`` or ``"pulloff"``)."""
    schema_file = resources.files("vibroadhesion.pipeline").joinpath("schemas", f"{name}.schema.json")
    text = schema_file.read_text(encoding="utf-8")
    return json.loads(text)


@cache
def schema_validator(name: str) -> Draft202012Validator:
    """A validator for the packaged JSON schema ``name`` (built once per name)."""
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
