"""JKR relations with a rate-dependent work of adhesion (Eqs. 4, 5, 60, 70; Appendix A).

Sign convention of the paper: compressive contact force positive, tensile negative.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray


def contact_force(a: ArrayLike, w: ArrayLike, reduced_modulus: float, radius: float) -> NDArray[np.float64]:
    """P = 4 E* a^3 / (3R) - sqrt(8 pi w E* a^3), Eq. (4) (Eq. A.4 with w = w0)."""
    a = np.asarray(a, dtype=float)
    return (
        4.0 * reduced_modulus * a**3 / (3.0 * radius)
        - np.sqrt(8.0 * math.pi * np.asarray(w) * reduced_modulus * a**3)
    )


def indentation(a: ArrayLike, w: ArrayLike, reduced_modulus: float, radius: float) -> NDArray[np.float64]:
    """delta = a^2 / R - sqrt(2 pi w a / E*), Eq. (5) (Eq. A.5 with w = w0)."""
    a = np.asarray(a, dtype=float)
    return a**2 / radius - np.sqrt(2.0 * math.pi * np.asarray(w) * a / reduced_modulus)


def critical_radius(w: ArrayLike, reduced_modulus: float, radius: float) -> NDArray[np.float64]:
    """JKR contact radius at pull-off under force control, a_cr = (9 pi R^2 w / (8 E*))^(1/3), Eq. (60)."""
    return (9.0 * math.pi * radius**2 * np.asarray(w, dtype=float) / (8.0 * reduced_modulus)) ** (1.0 / 3.0)


def pulloff_force(w: ArrayLike, radius: float) -> NDArray[np.float64]:
    """JKR pull-off force P_cr = -(3 pi / 2) R w, Eq. (70); with w = w0 it is P_cr^JKR (Eq. 71)."""
    return -1.5 * math.pi * radius * np.asarray(w, dtype=float)
