"""Rate-dependent work of adhesion: w = w0 f(da/dt / v0), Eq. (6).

Sign convention of the paper (Sec. 2.1.1): the argument x = da/dt / v0 is negative when the
contact shrinks (the interface crack opens) and positive when it grows (the crack closes);
f(x) > 1 for x < 0, f(x) < 1 for x > 0 and f(0) = 1.

Any object with a vectorised method ``f(x)`` is a rate law (:class:`RateLaw`); the
J-integrals of Eqs. (28), (29) and (36) are defined for all of them
(:func:`vibroadhesion.core.integrals.j_integrals_general`). The Gent–Schultz law of
Eqs. (73)–(75) is the one the paper fits, and its structure (the speed enters only as
|x|^n) gives the fast path :func:`vibroadhesion.core.integrals.j_integrals`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray


@runtime_checkable
class RateLaw(Protocol):
    """A positive function f of the signed contact-front speed x = (da/dt)/v0, Eq. (6)."""

    def f(self, x: ArrayLike) -> NDArray[np.float64]:
        """Return w/w0 at the signed dimensionless contact-front speed ``x``."""
        ...


@dataclass(frozen=True)
class GentSchultz:
    """Gent–Schultz law, Eqs. (73)–(75).

    Opening (shrinking contact, x < 0): f = f_op(|x|) = 1 + |x|^n, Eq. (73).
    Closing (growing contact, x > 0): f = 1/f_op(x), Eq. (74).
    """

    n: float

    def __post_init__(self) -> None:
        """Reject an exponent that is not a positive finite number (Eq. 73 needs n > 0)."""
        if not (np.isfinite(self.n) and self.n > 0):
            raise ValueError(f"Gent–Schultz exponent n must be a positive number, got {self.n!r}")

    def f_open(self, speed: ArrayLike) -> NDArray[np.float64]:
        """f_op(|x|) = 1 + |x|^n for an opening crack, Eq. (73)."""
        return 1.0 + np.abs(np.asarray(speed, dtype=float)) ** self.n

    def f(self, x: ArrayLike) -> NDArray[np.float64]:
        """Signed law of Eq. (75): f_op(|x|) for x < 0, 1/f_op(x) for x >= 0."""
        x = np.asarray(x, dtype=float)
        f_op = self.f_open(x)
        return np.where(x < 0, f_op, 1.0 / f_op)

    def speed(self, w_ratio: ArrayLike) -> NDArray[np.float64]:
        """Inverse of Eq. (75): the signed speed x with f(x) = ``w_ratio`` = w/w0 > 0.

        Opening (w_ratio > 1): x = -(w_ratio - 1)^(1/n); closing (w_ratio < 1): x = (1/w_ratio - 1)^(1/n);
        x = 0 at w_ratio = 1. Speeds beyond the double range come back as -inf or +inf (the
        overflow is not warned about: it is the exact answer rounded to the nearest double).
        """
        w_ratio = np.asarray(w_ratio, dtype=float)
        if np.any(~(w_ratio > 0)):
            raise ValueError("w/w0 must be positive for the Gent–Schultz law to be inverted")
        opening = w_ratio > 1
        excess = np.where(opening, w_ratio - 1.0, (1.0 - w_ratio) / w_ratio)
        with np.errstate(over="ignore"):
            magnitude = excess ** (1.0 / self.n)
        return np.where(opening, -magnitude, magnitude)
