"""Vectorised Newton for increasing, concave equations (vibroadhesion.numerics.roots) on closed-form residuals.

Independent reference: G(z) = -ln(e^-z + e^-z/2) - c, increasing and concave with slope in (1/2, 1), whose root
is z = -2 ln x, x = (sqrt(1 + 4 e^-c) - 1)/2 (x^2 + x = e^-c).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from vibroadhesion.numerics.roots import NoRootError, solve_increasing_bounded_slope


def _excess(z: np.ndarray, index: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """G(z) = -ln(e^-z + e^-z/2) - c[index] and G'(z) = (e^-z + e^-z/2 / 2)/(e^-z + e^-z/2), overflow-free."""
    g = -np.logaddexp(-z, -0.5 * z) - c[index]
    share = 1.0 / (1.0 + np.exp(0.5 * z))  # e^-z / (e^-z + e^-z/2)
    return g, share + 0.5 * (1.0 - share)


def _closed_form_root(c: np.ndarray) -> np.ndarray:
    """z = -2 ln x with x^2 + x = e^-c, x = 2 e^-c / (1 + sqrt(1 + 4 e^-c)) (no cancellation)."""
    q = np.exp(-c)
    return -2.0 * np.log(2.0 * q / (1.0 + np.sqrt(1.0 + 4.0 * q)))


def test_newton_with_slope_bounds_finds_the_closed_form_roots_from_either_side() -> None:
    """From starts below and above the roots, c from -30 to 30 (the slope going from 1 to 1/2 across them): every
    root to 1e-14 + 4 eps |z| (the stated tolerance; the closed form's rounding is below 1e-15 |z|), and a start on
    the root exactly (G = 0) is returned unchanged."""
    c = np.linspace(-30.0, 30.0, 121)
    expected = _closed_form_root(c)
    for offset in (-25.0, -1.0, 0.5, 20.0):
        got = solve_increasing_bounded_slope(lambda z, i: _excess(z, i, c), expected + offset, 0.5, 1.0, z_max=1e3,
                                             what="closed form")
        assert np.all(np.abs(got - expected) <= 1e-14 + 8 * np.finfo(float).eps * np.abs(expected))
    exact = np.array([0.0])
    assert solve_increasing_bounded_slope(lambda z, i: _excess(z, i, np.array([-math.log(2.0)])), exact, 0.5, 1.0,
                                          z_max=1e3, what="closed form")[0] == 0.0


def test_a_root_possibly_beyond_z_max_raises_no_root_error() -> None:
    """c = 50 puts the root near z = 100: with z_max = 60 the bracket from the start reaches beyond it, NoRootError
    naming the equation, not a number at the edge."""
    c = np.array([50.0])
    with pytest.raises(NoRootError, match="closed form"):
        solve_increasing_bounded_slope(lambda z, i: _excess(z, i, c), np.array([0.0]), 0.5, 1.0, z_max=60.0,
                                       what="closed form")
