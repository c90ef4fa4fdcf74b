"""The package's layers and the direction of its imports (README, "Layout").

Data flow one way: numerics -> core -> models -> simulation -> experiments -> pipeline. A
module may import from its own layer and the layers before it, never from a later one; every
import statement counts, including those inside functions. The 30-digit reference of the
tests stays independent of the package.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "vibroadhesion"
LAYERS = ("numerics", "core", "models", "simulation", "experiments", "pipeline")


def _imported_modules(path: Path) -> list[tuple[int, str]]:
    """(line, dotted module) of every absolute import in ``path``; ``from a import b`` yields a.b too."""
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found += [(node.lineno, alias.name) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            assert node.level == 0, f"{path}:{node.lineno}: relative import (write the absolute module)"
            found.append((node.lineno, node.module or ""))
            found += [(node.lineno, f"{node.module}.{alias.name}") for alias in node.names]
    return found


def _layer(dotted: str) -> int | None:
    """Rank of the layer a dotted name of the package lies in (None outside the package's layers)."""
    parts = dotted.split(".")
    if parts[0] != "vibroadhesion" or len(parts) < 2 or parts[1] not in LAYERS:
        return None
    return LAYERS.index(parts[1])


def _modules() -> list[Path]:
    return sorted(p for p in PACKAGE.rglob("*.py"))


def test_every_module_lies_in_a_layer() -> None:
    """Each module of the package sits in one of the six layer sub-packages (only the top __init__ is outside)."""
    stray = [p.relative_to(PACKAGE) for p in _modules() if p.parent == PACKAGE and p.name != "__init__.py"]
    assert not stray, f"modules outside the layers: {stray}"
    assert {p.name for p in PACKAGE.iterdir() if p.is_dir() and (p / "__init__.py").exists()} == set(LAYERS)


@pytest.mark.parametrize("path", _modules(), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_module_imports_from_a_later_layer(path: Path) -> None:
    own = _layer("vibroadhesion." + ".".join(path.relative_to(PACKAGE).with_suffix("").parts))
    if own is None:
        return  # the package's top __init__ imports nothing
    upward = [(line, name) for line, name in _imported_modules(path) if (_layer(name) or 0) > own]
    assert not upward, f"{path.relative_to(PACKAGE)} ({LAYERS[own]}) imports from a later layer: {upward}"


def test_the_walker_sees_imports_inside_functions(tmp_path: Path) -> None:
    """The check itself: a function-level upward import is found (a check that sees nothing cannot fail)."""
    module = tmp_path / "m.py"
    module.write_text("def f():\n    from vibroadhesion.pipeline import figures\n    import vibroadhesion.experiments.fitting\n")
    names = [name for _, name in _imported_modules(module)]
    assert "vibroadhesion.pipeline.figures" in names and "vibroadhesion.experiments.fitting" in names
    assert _layer("vibroadhesion.pipeline.figures") > _layer("vibroadhesion.models.refined")


def test_mpmath_reference_is_independent_of_the_package() -> None:
    """The 30-digit reference must not share code with what it checks."""
    reference = Path(__file__).with_name("mpmath_reference.py")
    assert not [name for _, name in _imported_modules(reference) if name.split(".")[0] == "vibroadhesion"]
