"""The package modules a script or notebook runs: the import closure the Snakemake rules depend on.

Snakemake does not track code a step imports. Each rule lists as inputs the files this module
finds: the adapter script it runs (or the notebook a report page executes) and every module of the
package reachable from it through import statements, those inside functions included and those
under ``if TYPE_CHECKING:`` excluded (they never run). Importing ``a.b.c`` runs the packages
``a`` and ``a.b`` first, so their ``__init__.py`` count too. Editing one of these files (its
content: Snakemake compares small files by content) reruns exactly the rules that import it.

The registry of model levels (:mod:`vibroadhesion.core.levels`) imports the functions of the levels
by name, which no import statement shows: a source that resolves them declares which
(``LEVEL_FUNCTIONS``, pairs of role and function), and the modules of those functions count as
imported by it.

Standard library only (and the registry, itself standard library only): the Snakefile imports this
module while it builds the DAG.
"""

from __future__ import annotations

import ast
import json
from collections.abc import Iterable, Iterator
from functools import cache
from pathlib import Path

from vibroadhesion.core import levels

PACKAGE = "vibroadhesion"


def _is_type_checking(node: ast.AST) -> bool:
    """Whether ``node`` is ``if TYPE_CHECKING:`` (or ``if typing.TYPE_CHECKING:``)."""
    if not isinstance(node, ast.If):
        return False
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _runtime_statements(body: list[ast.stmt]) -> Iterator[ast.AST]:
    """Every statement in ``body`` and in the blocks nested in it.

    The blocks are those of functions, classes, if, try, with, loops and match; the body of
    ``if TYPE_CHECKING:`` is left out. Imports are statements: expressions need no visit.
    """
    stack: list[ast.AST] = list(body)
    while stack:
        node = stack.pop()
        if _is_type_checking(node):
            stack.extend(node.orelse)  # type: ignore[attr-defined]
            continue
        yield node
        for block in ("body", "orelse", "finalbody", "handlers", "cases"):
            stack.extend(getattr(node, block, ()))


def level_modules(body: list[ast.stmt]) -> set[str]:
    """Modules of the registry's functions that a source declares it resolves: its ``LEVEL_FUNCTIONS``.

    A module-level ``LEVEL_FUNCTIONS = (("fit", "pulloff"), ...)`` names the modules of
    :func:`vibroadhesion.core.levels.modules` for each pair.
    """
    found: set[str] = set()
    for node in body:
        if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "LEVEL_FUNCTIONS"
                                                for t in node.targets):
            for role, function in ast.literal_eval(node.value):
                found.update(levels.modules(role, function))
    return found


def imported_names(source: str, where: str) -> set[str]:
    """Dotted names of the package that the Python ``source`` imports.

    ``from a import b`` gives ``a`` and ``a.b`` (``b`` may be a module or a name in ``a``); the modules of the
    registry's functions it declares (:func:`level_modules`) count too. ``where`` names the source in the
    error of a relative import.
    """
    body = ast.parse(source).body
    names: set[str] = level_modules(body)
    for node in _runtime_statements(body):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                raise ValueError(f"{where}:{node.lineno}: relative import; write the absolute module")
            names.add(node.module or "")
            names.update(f"{node.module}.{alias.name}" for alias in node.names)
    return {n for n in names if n == PACKAGE or n.startswith(PACKAGE + ".")}


def _code_of(path: Path) -> str:
    """The Python code of a script, or of a notebook's code cells (IPython magics and shell lines dropped)."""
    text = path.read_text(encoding="utf-8")
    if path.suffix != ".ipynb":
        return text
    cells = [c["source"] for c in json.loads(text)["cells"] if c["cell_type"] == "code"]
    lines = [line for cell in cells for line in ("".join(cell) if isinstance(cell, list) else cell).splitlines()]
    return "\n".join(line for line in lines if not line.lstrip().startswith(("%", "!")))


@cache
def _imports_of(path: Path) -> frozenset[str]:
    return frozenset(imported_names(_code_of(path), str(path)))


@cache
def module_file(name: str, src: Path) -> Path | None:
    """The file of module ``name`` under ``src`` (a package's ``__init__.py``), or None (not a module)."""
    base = src.joinpath(*name.split("."))
    for candidate in (base / "__init__.py", base.with_suffix(".py")):
        if candidate.is_file():
            return candidate
    return None


def _modules_run_by(name: str, src: Path) -> Iterator[Path]:
    """The files an import of ``name`` runs: each enclosing package's ``__init__.py``, then the module."""
    parts = name.split(".")
    for k in range(1, len(parts) + 1):
        found = module_file(".".join(parts[:k]), src)
        if found is not None:
            yield found


def import_closure(sources: Iterable[str | Path], root: str | Path = ".") -> list[str]:
    """``sources`` and every package module they import, directly or through other modules.

    ``sources`` are scripts or notebooks relative to ``root``, the package's modules are under
    ``root/src``; the result is sorted paths relative to ``root``.
    """
    root = Path(root)
    src = root / "src"
    seen: set[Path] = set()
    todo = [root / s for s in sources]
    while todo:
        path = todo.pop()
        if path in seen:
            continue
        seen.add(path)
        for name in _imports_of(path):
            todo.extend(f for f in _modules_run_by(name, src) if f not in seen)
    return sorted(p.relative_to(root).as_posix() for p in seen)
