"""Ingest and validate the two user-edited inputs, ``data/setup.yaml`` and ``data/pulloff.csv``.

Both are checked against JSON schemas (draft 2020-12) shipped in ``vibroadhesion/pipeline/schemas/``:
``setup.schema.json`` describes the whole YAML document, ``pulloff.schema.json`` ONE row of the
CSV (each row is validated against it); the schemas, their messages and :class:`DataError` live
in :mod:`vibroadhesion.pipeline.input_checks`. Every problem raises a ``DataError`` whose message is
a single line ``"<file>, row <r>, column <c>: <what is wrong>"``:

* CSV: ``row`` is the 1-based line number in the file, ``column`` the column name (or ``header``);
* YAML: ``row`` is the 1-based line of the offending node, ``column`` the dotted key path, e.g.
  ``sample.poisson_ratio.value`` (list items as ``...value[1]``).

Row 0 means the file as a whole (it cannot be read).
``python -m vibroadhesion.pipeline.data SETUP PULLOFF OUT_JSON OUT_CSV`` validates both files and
writes canonical copies atomically (see :func:`main`).
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import re
import sys
from collections.abc import Callable, Iterator, Sequence
from contextlib import ExitStack
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import yaml

from vibroadhesion.pipeline.atomic import atomic_path
from vibroadhesion.pipeline.input_checks import (
    KEYWORD_ORDER,
    DataError,
    check_csv_header,
    check_force_scale,
    dotted,
    field_count_error,
    kind_of,
    read_text,
    schema_message,
    schema_validator,
    yaml_node_lines,
)

if TYPE_CHECKING:  # pandas is imported where a frame is built: checking the inputs (the Snakefile) needs none
    import pandas as pd

PULLOFF_COLUMNS: tuple[str, ...] = ("frequency_hz", "h1_um", "pulloff_mN", "source")
NUMERIC_COLUMNS: tuple[str, ...] = ("frequency_hz", "h1_um", "pulloff_mN")
#: The optional column: the withdrawal speed V of the test in um/s (empty or 0: quasi-static, read as 0).
SPEED_COLUMN = "withdrawal_speed_um_s"
#: The first column of the canonical copy: each row's 1-based line in data/pulloff.csv (the rows' one reference).
LINE_COLUMN = "line"
_UNITS = {"frequency_hz": "Hz", "h1_um": "um", "pulloff_mN": "mN", SPEED_COLUMN: "um/s"}

# (group, entry) behind each scalar field of Setup.
_SETUP_FIELDS: dict[str, tuple[str, str]] = {
    "radius": ("indenter", "radius"),
    "youngs_modulus": ("sample", "youngs_modulus"),
    "storage_modulus_factor": ("sample", "storage_modulus_factor"),
    "poisson_ratio": ("sample", "poisson_ratio"),
    "density": ("sample", "density"),
    "thickness": ("sample", "thickness"),
    "w0": ("gent_schultz_published", "w0"),
    "n": ("gent_schultz_published", "n"),
    "v0": ("gent_schultz_published", "v0"),
}
_SETUP_LISTS: dict[str, tuple[str, str]] = {
    "frequencies_hz": ("test_conditions", "frequencies"),
    "amplitudes_um": ("test_conditions", "amplitudes"),
}


#: The group of the canonical setup JSON with the values derived from the given ones (:mod:`.derived`): not an input.
DERIVED_GROUP = "derived"

#: The value of an entry of data/setup.yaml: a number or a list of numbers.
SetupValue = float | tuple[float, ...]


@dataclass(frozen=True)
class Setup:
    """Validated contents of ``data/setup.yaml`` (SI units, amplitudes in micrometres)."""

    radius: float  # m
    youngs_modulus: float  # Pa
    storage_modulus_factor: float
    poisson_ratio: float
    density: float  # kg/m^3
    thickness: float  # m
    frequencies_hz: tuple[float, ...]
    amplitudes_um: tuple[float, ...]
    w0: float  # J/m^2
    n: float
    v0: float  # m/s
    sources: dict[str, str]  # "group.entry" -> source text
    values: dict[str, SetupValue] = field(default_factory=dict)  # "group.entry" -> value
    units: dict[str, str] = field(default_factory=dict)  # "group.entry" -> unit

    @property
    def reduced_modulus(self) -> float:
        """E* = f_storage * E / (1 - nu^2) (Appendix A, Sec. 3.4)."""
        return self.storage_modulus_factor * self.youngs_modulus / (1.0 - self.poisson_ratio**2)

# ----------------------------------------------------------------------------- setup.yaml


# yaml has no type information in the lock (no py.typed, no stubs), so its classes are Any to mypy.
class _Loader(yaml.SafeLoader):  # type: ignore[misc]
    """Safe loader that also reads ``1e-3`` / ``2E6`` as floats (YAML 1.2 style)."""


_Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:\d[\d_]*)?(?:\.\d*)?[eE][-+]?\d+$"),
    list("-+0123456789."),
)


def _iter_nonfinite(value: Any, prefix: tuple[Any, ...] = ()) -> Iterator[tuple[Any, ...]]:
    if isinstance(value, float) and not math.isfinite(value):
        yield prefix
    elif isinstance(value, dict):
        for k, v in value.items():
            yield from _iter_nonfinite(v, prefix + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from _iter_nonfinite(v, prefix + (i,))


def _setup_from_document(path: str | Path, doc: Any, locate: Callable[[tuple[Any, ...], bool], int]) -> Setup:
    """Validate a setup document (parsed YAML or canonical JSON) and build :class:`Setup`.

    ``locate(path, key_line)`` gives the 1-based line of the node at ``path`` (of its key when
    ``key_line``, e.g. for a missing or unknown key).
    """
    if doc is None:
        raise DataError(path, 1, "(document)",
                        "file is empty; expected the groups indenter, sample, test_conditions, gent_schultz_published")
    if not isinstance(doc, dict):
        raise DataError(path, locate((), False), "(document)",
                        f"expected a mapping of groups at the top level, got {kind_of(doc)}")
    for bad in _iter_nonfinite(doc):
        raise DataError(path, locate(bad, False), dotted(bad), "value must be a finite number (got nan or inf)")
    errors = []
    for error in schema_validator("setup").iter_errors(doc):
        node_path, message, key_line = schema_message(error)
        parent_key = key_line and error.validator != "additionalProperties"
        row = locate(node_path[:-1] if parent_key else node_path, key_line)
        # an unknown key (often a misspelt one) is reported before the missing key it stands for
        errors.append((error.validator != "additionalProperties", row, KEYWORD_ORDER.get(error.validator, 9),
                       dotted(node_path), message))
    if errors:
        _, row, _, column, message = min(errors)
        raise DataError(path, row, column, message)

    def value(group: str, entry: str) -> Any:
        return doc[group][entry]["value"]

    sources: dict[str, str] = {}
    values: dict[str, SetupValue] = {}
    units: dict[str, str] = {}
    for group, entries in doc.items():
        for entry, spec in entries.items():
            key = f"{group}.{entry}"
            v = spec["value"]
            sources[key] = spec["source"]
            values[key] = tuple(float(x) for x in v) if isinstance(v, list) else float(v)
            units[key] = spec["unit"]
    scalars: dict[str, Any] = {name: float(value(*where)) for name, where in _SETUP_FIELDS.items()}
    lists: dict[str, Any] = {name: tuple(float(x) for x in value(*where)) for name, where in _SETUP_LISTS.items()}
    return Setup(
        **scalars,
        **lists,
        sources=sources,
        values=values,
        units=units,
    )


def _parse_setup(path: str | Path) -> tuple[Setup, dict[str, Any]]:
    path = Path(path)
    text = read_text(path)
    try:
        loader = _Loader(text)
        try:
            node = loader.get_single_node()
            if node is None:
                doc: Any = None
                lines: dict[tuple[Any, ...], tuple[int, int]] = {}
            else:
                lines = yaml_node_lines(path, node)
                doc = loader.construct_document(node)
        finally:
            loader.dispose()
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        row = mark.line + 1 if mark is not None else 1
        where = f" (character {mark.column + 1})" if mark is not None else ""
        what = re.sub(r"'?<([^>]*)>'?", r"\1", exc.problem or exc.context or "invalid YAML")
        if "block" in what:
            what += "; check the indentation"
        raise DataError(path, row, "(document)", f"YAML syntax error: {what}{where}") from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "position", None)
        row = text[:mark].count("\n") + 1 if isinstance(mark, int) else 1
        raise DataError(path, row, "(document)", "YAML syntax error: unreadable character") from None

    def locate(node_path: tuple[Any, ...], key_line: bool) -> int:
        while node_path not in lines and node_path:
            node_path = node_path[:-1]
        key_row, value_row = lines.get(node_path, (1, 1))
        return key_row if key_line else value_row

    return _setup_from_document(path, doc, locate), doc


def load_setup(path: str | Path) -> Setup:
    """Read and validate ``data/setup.yaml``; raise :class:`DataError` naming file, row and key path."""
    return _parse_setup(path)[0]


def _canonical_setup(doc: dict[str, Any]) -> dict[str, Any]:
    """The validated document with every number as a float (keys in file order)."""

    def num(v: Any) -> Any:
        return [float(x) for x in v] if isinstance(v, list) else float(v)

    return {g: {e: {"value": num(s["value"]), "unit": s["unit"], "source": s["source"]} for e, s in entries.items()}
            for g, entries in doc.items()}


def read_canonical_setup(path: str | Path) -> Setup:
    """Read the canonical JSON written by :func:`main` (the given values re-validated against the same schema).

    Its :data:`DERIVED_GROUP` is not read: the steps compute a derived value from the given ones where they use it.
    """
    path = Path(path)
    text = read_text(path)
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        raise DataError(path, exc.lineno, "(document)", f"invalid JSON: {exc.msg}") from None
    if isinstance(doc, dict):
        doc.pop(DERIVED_GROUP, None)
    return _setup_from_document(path, doc, lambda node_path, key_line: 1)


# ----------------------------------------------------------------------------- pulloff.csv


def _pulloff_frame(records: list[dict[str, Any]]) -> pd.DataFrame:
    import pandas as pd

    return pd.DataFrame({
        "frequency_hz": pd.Series([r["frequency_hz"] for r in records], dtype="float64"),
        "h1_um": pd.Series([r["h1_um"] for r in records], dtype="float64"),
        "pulloff_mN": pd.Series([r["pulloff_mN"] for r in records], dtype="float64"),
        "source": pd.Series([r["source"] for r in records], dtype="str"),
        "line": pd.Series([r["line"] for r in records], dtype="int64"),
        SPEED_COLUMN: pd.Series([r[SPEED_COLUMN] for r in records], dtype="float64"),
    })


def _split(path: Path, line_no: int, line: str, column: str) -> list[str]:
    try:
        return next(csv.reader([line], strict=True))
    except csv.Error as exc:
        raise DataError(path, line_no, column, f"malformed CSV line ({exc})") from None


def _number(path: Path, line_no: int, column: str, cell: str) -> float:
    text = cell.strip()
    unit = _UNITS[column]
    if not text:
        raise DataError(path, line_no, column, f"empty value; expected a number in {unit}")
    try:
        value = float(text)
    except ValueError:
        value = None
    if value is None or "_" in text:
        raise DataError(path, line_no, column, f'not a number: "{text}" (expected a number in {unit}, no unit suffix)')
    if not math.isfinite(value):
        raise DataError(path, line_no, column, f'"{text}" is not a finite number')
    return value


def _row_numbers(path: Path, line_no: int, row: dict[str, str]) -> dict[str, Any]:
    """The numeric columns of one row.

    A static JKR test (h1_um = 0) has no excitation: its frequency may be empty (read as 0); any other row
    needs a frequency > 0. The optional withdrawal speed (um/s) is 0 where the column is absent or empty
    (quasi-static); a static test at a speed (the rate-dependent JKR pull-off) is not modelled: refused.
    """
    h1 = _number(path, line_no, "h1_um", row["h1_um"])
    if h1 == 0 and not row["frequency_hz"].strip():
        frequency = 0.0
    else:
        frequency = _number(path, line_no, "frequency_hz", row["frequency_hz"])
        if frequency == 0 and h1 != 0:
            raise DataError(path, line_no, "frequency_hz", "frequency must be > 0 Hz (0 or empty only for a static "
                            f"test, h1_um = 0), got {frequency!r}")
    speed = _number(path, line_no, SPEED_COLUMN, row[SPEED_COLUMN]) if row.get(SPEED_COLUMN, "").strip() else 0.0
    if h1 == 0 and speed > 0:
        raise DataError(path, line_no, SPEED_COLUMN, "a static JKR test (h1_um = 0) at a withdrawal speed is not "
                        "modelled (only the quasi-static Eq. 70): leave the speed empty")
    return {"frequency_hz": frequency, "h1_um": h1, "pulloff_mN": _number(path, line_no, "pulloff_mN",
                                                                          row["pulloff_mN"]), SPEED_COLUMN: speed}


def load_pulloff(path: str | Path) -> pd.DataFrame:
    """Read and validate ``data/pulloff.csv`` (:func:`pulloff_records`) as a frame.

    Columns ``frequency_hz``, ``h1_um``, ``pulloff_mN`` (float64), ``source`` (str), ``line``
    (int64, 1-based line in the file) and ``withdrawal_speed_um_s`` (float64, 0: quasi-static); zero data rows
    give an empty frame with those columns and dtypes.
    """
    return _pulloff_frame(pulloff_records(path))


def pulloff_records(path: str | Path, canonical: bool = False) -> list[dict[str, Any]]:
    """Read and validate ``data/pulloff.csv``: one dict per row, the columns and its ``line``.

    Lines whose first non-blank character is ``#`` and blank lines are skipped; the first other
    line is the header (the four columns and the optional :data:`SPEED_COLUMN`, in any order). Rows that
    repeat another are replicates (a test run twice): they are kept. ``line`` is the row's line in the file; in
    the ``canonical`` copy (:func:`ingest`) it is its :data:`LINE_COLUMN`, the line in data/pulloff.csv.
    """
    path = Path(path)
    text = read_text(path)
    lines = text.splitlines()
    if not text.strip():
        raise DataError(path, 1, "header", f"file is empty; expected the header line {','.join(PULLOFF_COLUMNS)}")
    header: list[str] | None = None
    records: list[dict[str, Any]] = []
    row_validator = schema_validator("pulloff")
    for line_no, line in enumerate(lines, start=1):
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        if header is None:
            header = [h.strip() for h in _split(path, line_no, line, "header")]
            check_csv_header(path, line_no, header, ((LINE_COLUMN,) if canonical else ()) + PULLOFF_COLUMNS,
                             (SPEED_COLUMN,))
            continue
        cells = _split(path, line_no, line, "(row)")
        if len(cells) != len(header):
            field_count_error(path, line_no, header, cells)
        row = dict(zip(header, cells, strict=True))
        record = _row_numbers(path, line_no, row)
        record["source"] = row["source"].strip()
        errors = []
        for error in row_validator.iter_errors(record):
            node_path, message, _ = schema_message(error)
            column = str(node_path[0]) if node_path else "(row)"
            errors.append((PULLOFF_COLUMNS.index(column) if column in PULLOFF_COLUMNS else 9,
                           KEYWORD_ORDER.get(error.validator, 9), column, message))
        if errors:
            _, _, column, message = min(errors)
            raise DataError(path, line_no, column, message)
        record["line"] = int(row[LINE_COLUMN]) if canonical else line_no
        records.append(record)
    if header is None:
        raise DataError(path, len(lines), "header",
                        f"no header line (only comments or blank lines); expected {','.join(PULLOFF_COLUMNS)}")
    return records


def read_canonical_pulloff(path: str | Path) -> pd.DataFrame:
    """Read the canonical CSV written by :func:`ingest` (the frame and validation of :func:`load_pulloff`).

    ``line`` is each row's line in ``data/pulloff.csv`` (the canonical :data:`LINE_COLUMN`), the line that the
    input errors, the fit's residuals and its row statuses name.
    """
    return _pulloff_frame(pulloff_records(path, canonical=True))


# ----------------------------------------------------------------------------- CLI


def _pulloff_csv_text(records: list[dict[str, Any]]) -> str:
    """The canonical CSV: each row's line in data/pulloff.csv first; the speed column only where a row has a speed."""
    columns = 6 if any(rec[SPEED_COLUMN] > 0 for rec in records) else 5
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow([LINE_COLUMN, *PULLOFF_COLUMNS, SPEED_COLUMN][:columns])
    for rec in records:
        writer.writerow([str(rec["line"]), repr(float(rec["frequency_hz"])), repr(float(rec["h1_um"])),
                         repr(float(rec["pulloff_mN"])), str(rec["source"]), repr(float(rec[SPEED_COLUMN]))][:columns])
    return buf.getvalue()


def _write_atomically(outputs: list[tuple[Path, str]]) -> None:
    """Write every file beside its target first (:func:`atomic_path`), then move all into place."""
    with ExitStack() as stack:
        temps = [(stack.enter_context(atomic_path(target)), text) for target, text in outputs]
        for tmp, text in temps:
            tmp.write_text(text, encoding="utf-8", newline="")


def check_inputs(setup_yaml: str | Path, pulloff_csv: str | Path) -> tuple[Setup, dict[str, Any], list[dict[str, Any]]]:
    """Validate both inputs, each alone and against each other (:func:`check_force_scale`); no numerics imported.

    Returns the setup, its YAML document and the pull-off rows; raises :class:`DataError` on the first problem.
    The Snakefile calls it before it plans any job, so that a rejected edit changes nothing in ``results/``.
    """
    setup, doc = _parse_setup(setup_yaml)
    records = pulloff_records(pulloff_csv)
    check_force_scale(setup.radius, setup.w0, records, pulloff_csv)
    return setup, doc, records


def _setup_json_text(setup: Setup, doc: dict[str, Any]) -> str:
    """The canonical setup JSON: the validated document (floats), then the values derived from it.

    Each derived value with its formula (:data:`DERIVED_GROUP`, :func:`vibroadhesion.pipeline.derived.derived_values`).
    """
    from vibroadhesion.pipeline.derived import derived_values  # numerics: not for the Snakefile's checks

    canonical = _canonical_setup(doc) | {DERIVED_GROUP: derived_values(setup)}
    return json.dumps(canonical, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def ingest(setup_yaml: str | Path, pulloff_csv: str | Path, out_json: str | Path, out_csv: str | Path) -> str:
    """Validate both inputs (:func:`check_inputs`) and write their canonical copies atomically (:func:`main`).

    The canonical setup JSON keeps values, units and sources, and adds the values derived from them with their
    formulas (:data:`DERIVED_GROUP`); the canonical pull-off CSV has no
    comments, the columns line (the row's line in data/pulloff.csv), frequency_hz, h1_um, pulloff_mN, source
    (withdrawal_speed_um_s where a row has a speed) and floats written with repr.
    Raises :class:`DataError` (nothing written) on a bad input; returns a one-line summary.
    """
    setup, doc, records = check_inputs(setup_yaml, pulloff_csv)
    _write_atomically([(Path(out_json), _setup_json_text(setup, doc)), (Path(out_csv), _pulloff_csv_text(records))])
    return f"validated {setup_yaml} ({len(setup.sources)} entries) and {pulloff_csv} ({len(records)} rows)"


def ingest_setup(setup_yaml: str | Path, out_json: str | Path) -> str:
    """Rule ``ingest_setup``: validate data/setup.yaml and write its canonical JSON (as :func:`ingest`)."""
    setup, doc = _parse_setup(setup_yaml)
    _write_atomically([(Path(out_json), _setup_json_text(setup, doc))])
    return f"validated {setup_yaml} ({len(setup.sources)} entries)"


def ingest_pulloff(setup_json: str | Path, pulloff_csv: str | Path, out_csv: str | Path) -> str:
    """Rule ``ingest_pulloff``: validate data/pulloff.csv against the canonical rig and write its canonical CSV.

    The same checks as :func:`check_inputs` (schema, then :func:`check_force_scale` with R and w0 of the rig); the
    rule of its own, so that an edit of the rows does not rewrite the setup that the published-parameter jobs read.
    """
    setup = read_canonical_setup(setup_json)
    records = pulloff_records(pulloff_csv)
    check_force_scale(setup.radius, setup.w0, records, pulloff_csv)
    _write_atomically([(Path(out_csv), _pulloff_csv_text(records))])
    return f"validated {pulloff_csv} ({len(records)} rows) against {setup_json}"


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m vibroadhesion.pipeline.data SETUP PULLOFF OUT_JSON OUT_CSV``: :func:`ingest` from the shell.

    Returns 0 on success; on a :class:`DataError` prints its one-line message to stderr, writes
    nothing and returns 1.
    """
    parser = argparse.ArgumentParser(prog="python -m vibroadhesion.pipeline.data", description=__doc__.splitlines()[0])
    parser.add_argument("setup", help="data/setup.yaml")
    parser.add_argument("pulloff", help="data/pulloff.csv")
    parser.add_argument("out_json", help="canonical setup (JSON)")
    parser.add_argument("out_csv", help="canonical pull-off rows (CSV)")
    args = parser.parse_args(argv)
    try:
        print(ingest(args.setup, args.pulloff, args.out_json, args.out_csv))
    except DataError as exc:
        print(str(exc), file=sys.stderr)
        return 1
    except OSError as exc:
        print(f"error: cannot write output: {exc.strerror or type(exc).__name__}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
