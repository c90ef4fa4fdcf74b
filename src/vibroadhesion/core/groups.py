"""Dimensionless groups of the model (Eqs. 64–66, 81, 86, 97, 105).

Plain functions of dimensional inputs in SI units; each returns a float or an array.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

STANDARD_GRAVITY = 9.80665  # m/s^2


def chi0(w0: float, reduced_modulus: float, radius: float) -> float:
    """chi0 = (9 pi w0 / (E* R))^(1/3), Eq. (64)."""
    return (9.0 * math.pi * w0 / (reduced_modulus * radius)) ** (1.0 / 3.0)


def contact_radius_scale(w0: float, reduced_modulus: float, radius: float) -> float:
    """a_o = (2 pi w0 R^2 / E*)^(1/3), the JKR contact radius of the nominal point contact (Eq. 86).

    Equal to 2^(1/3) 3^(-2/3) chi0 R (text below Eq. 86).
    """
    return (2.0 * math.pi * w0 * radius**2 / reduced_modulus) ** (1.0 / 3.0)


#: The JKR pull-off force in the units Phat = P R/(E* a_o^3): P_JKR = -(3/2) pi w0 R and
#: pi w0 R^2/(E* a_o^3) = 1/2 (Eq. 86), so Phat_JKR = -3/4 and P/|P_JKR| = Phat/(3/4).
PHAT_JKR = -0.75


def contact_radius_ratio(chi0: float) -> float:
    """c_o = a_o / R = 2^(1/3) 3^(-2/3) chi0 (text below Eq. 86)."""
    return 2.0 ** (1 / 3) * 3.0 ** (-2 / 3) * chi0


def etahat(eta1: ArrayLike, chi0: float) -> NDArray[np.float64]:
    """etahat = h1 R / a_o^2 = eta1 / c_o^2: the base amplitude on the indentation scale a_o^2/R (Eq. 86)."""
    eta1 = np.asarray(eta1, dtype=float)
    if np.any(~np.isfinite(eta1)) or np.any(eta1 < 0):
        raise ValueError("eta1 must be finite and non-negative")
    return eta1 / contact_radius_ratio(chi0) ** 2


def A_over_am(
    Abar: ArrayLike, abar_m: ArrayLike, chi0: float, omega_check: ArrayLike
) -> NDArray[np.float64]:
    """A / a_m = 3^(2/3) Abar / (2^(1/3) chi0 abar_m omega_check) = Abar / (c_o abar_m omega_check).

    From Eqs. (45), (86), (105): A = Abar v0/omega, so A/a_m = Abar (v0/(omega R)) / (c_o abar_m). The
    printed Eq. (98) drops the factor 1/omega_bar (docs/errata.md, E1).
    """
    return 3.0 ** (2 / 3) * np.asarray(Abar) / (2.0 ** (1 / 3) * chi0 * np.asarray(abar_m) * np.asarray(omega_check))


def eta1(h1: ArrayLike, radius: float) -> NDArray[np.float64]:
    """eta1 = h1 / R, Eq. (65)."""
    return np.asarray(h1, dtype=float) / radius


def natural_frequency(stiffness: float, mass: float) -> float:
    """omega0 = sqrt(k/m), Eq. (65)."""
    return math.sqrt(stiffness / mass)


def damping_ratio(damping: float, stiffness: float, mass: float) -> float:
    """zeta = c / (2 sqrt(k m)), Eq. (65)."""
    return damping / (2.0 * math.sqrt(stiffness * mass))


def kappa(stiffness: float, reduced_modulus: float, radius: float) -> float:
    """kappa = k / (E* R), Eq. (66)."""
    return stiffness / (reduced_modulus * radius)


def mu(mass: float, reduced_modulus: float, radius: float, gravity: float = STANDARD_GRAVITY) -> float:
    """mu = m g / (E* R^2), Eq. (81)."""
    return mass * gravity / (reduced_modulus * radius**2)


def nu0(v0: float, omega0: float, radius: float) -> float:
    """nu0 = v0 / (omega0 R), Eq. (97)."""
    return v0 / (omega0 * radius)


def omega_bar(frequency_hz: float, omega0: float) -> float:
    """omega_bar = omega / omega0 with omega = 2 pi f, Eq. (65)."""
    return 2.0 * math.pi * frequency_hz / omega0


def omega_check(frequency_hz: ArrayLike, v0: float, radius: float) -> NDArray[np.float64]:
    """omega_check = omega R / v0 with omega = 2 pi f, Eq. (105)."""
    return 2.0 * math.pi * np.asarray(frequency_hz, dtype=float) * radius / v0
