"""Root scan of a scalar function (vibroadhesion.numerics.scan) on closed-form residuals.

Independent references: functions whose roots, poles and step sequences are known in closed form.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from vibroadhesion.numerics.roots import NoRootError
from vibroadhesion.numerics.scan import approach_pole, bracket_increasing_root, roots_on_nodes


def test_approach_pole_halves_towards_a_pole_until_the_residual_falls() -> None:
    """Closed form F(z) = 1 - 1e-4/(z - z_pole)^2, a pole with F -> -infinity: the nodes are z_pole + side h 2^-j,
    h = 0.05, and the first with F < min(F(previous), 0) is j = 3 (h 2^-j < 0.01 first for j = 3), from either
    side. A residual that never falls (F = 1) raises NoRootError after the allowed halvings.
    """
    z_pole = 0.7

    def pole(z: float) -> float:
        return 1.0 - 1e-4 / (z - z_pole) ** 2

    for side in (-1.0, 1.0):
        nodes = approach_pole(pole, z_pole, side, 0.05, 60, "pole")
        assert [z for z, _ in nodes] == [z_pole + side * 0.05 * 2.0**-j for j in (1, 2, 3)]
        assert [f for _, f in nodes] == pytest.approx([1.0 - 1e-4 / (0.05 * 2.0**-j) ** 2 for j in (1, 2, 3)], rel=1e-12)
    with pytest.raises(NoRootError, match="does not fall"):
        approach_pole(lambda z: 1.0, z_pole, 1.0, 0.05, 60, "flat")


def test_bracket_increasing_root_doubles_the_step_until_the_residual_is_non_negative() -> None:
    """Closed form F(z) = z - 3 from z = 0 with step 0.05: the bracket ends are 0.05 (2^k - 1); the first hi >= 3
    is 0.05 * 63 = 3.15 with lo = 0.05 * 31 = 1.55 (relative 1e-14: sums of a few binary fractions of 0.05).
    F(z) >= 0 at the start gives None; a residual that stays negative raises NoRootError.
    """
    lo, hi = bracket_increasing_root(lambda z: z - 3.0, 0.0, -3.0, 0.05, "line")
    assert lo == pytest.approx(1.55, rel=1e-14) and hi == pytest.approx(3.15, rel=1e-14)
    assert bracket_increasing_root(lambda z: z - 3.0, 3.0, 0.0, 0.05, "line") is None
    with pytest.raises(NoRootError, match="representable"):
        bracket_increasing_root(lambda z: -1.0, 0.0, -1.0, 0.05, "negative")


@pytest.mark.parametrize(
    ("residual", "expected"),
    [
        (lambda z: (z - 0.51) * (z - 0.52), [(0.51, False), (0.52, True)]),  # two roots hidden in one cell
        (lambda z: z - 0.33, [(0.33, True)]),
        (lambda z: 0.33 - z, [(0.33, False)]),
        (lambda z: (z - 0.51) * (z - 0.52) + 1e-3, []),  # a minimum of |F| without roots
        (lambda z: (z - 0.2) * (z - 0.51) * (z - 0.52), [(0.2, True), (0.51, False), (0.52, True)]),
    ],
)
def test_roots_on_nodes_finds_sign_changes_and_pairs_hidden_in_one_cell(residual, expected) -> None:
    """Closed-form residuals on the nodes z = 0, 0.05, ..., 1: every root e^z0 with F increasing through it or
    not, including the pair 0.51, 0.52 that leaves no sign change at the nodes. Tolerance 1e-12 relative in
    e^z0: Brent's method in z to 1e-14 absolute (numerics.roots).
    """
    nodes = [(z, residual(z)) for z in 0.05 * np.arange(21)]
    roots = roots_on_nodes(residual, nodes, "closed form")
    assert [increasing for _, increasing in roots] == [increasing for _, increasing in expected]
    for (root, _), (z0, _) in zip(roots, expected, strict=True):
        assert root == pytest.approx(math.exp(z0), rel=1e-12)
