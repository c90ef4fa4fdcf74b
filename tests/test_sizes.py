"""The house rule on size (DEVELOPERS.md, issue 12): no module over 500 lines, no function over 60.

No module of the package over 500 lines, no function
over 60 lines with its docstring excluded. Both limits are checked on every file under src/vibroadhesion;
the counting itself is checked on a small source whose sizes are known by construction.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "src" / "vibroadhesion"
MODULES = sorted(PACKAGE.rglob("*.py"))
MAX_MODULE_LINES = 500
MAX_FUNCTION_LINES = 60


def function_lengths(source: str) -> dict[str, int]:
    """Lines of every function and method (nested ones included, by qualified name), docstrings excluded."""
    lengths: dict[str, int] = {}
    _collect(ast.parse(source), "", lengths)
    return lengths


def _collect(node: ast.AST, prefix: str, lengths: dict[str, int]) -> None:
    for child in ast.iter_child_nodes(node):
        name = f"{prefix}{getattr(child, 'name', '')}"
        if isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef):
            assert child.end_lineno is not None
            lengths[name] = child.end_lineno - child.lineno + 1 - _docstring_lines(child)
        _collect(child, f"{name}." if isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef)
                 else prefix, lengths)


def _docstring_lines(function: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    first = function.body[0]
    if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and isinstance(first.value.value, str):
        assert first.end_lineno is not None
        return first.end_lineno - first.lineno + 1
    return 0


def test_function_lengths_count_code_lines_without_the_docstring() -> None:
    source = ('def f(x):\n    """One.\n\n    Three.\n    """\n    y = x\n    return y\n\n\n'
              "class C:\n    def m(self):\n        def inner():\n            return 1\n        return inner()\n")
    assert function_lengths(source) == {"f": 3, "C.m": 4, "C.m.inner": 2}


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_module_is_at_most_500_lines(path: Path) -> None:
    assert len(path.read_text(encoding="utf-8").splitlines()) <= MAX_MODULE_LINES


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_every_function_is_at_most_60_lines_without_its_docstring(path: Path) -> None:
    long = {name: n for name, n in function_lengths(path.read_text(encoding="utf-8")).items()
            if n > MAX_FUNCTION_LINES}
    assert not long, long
