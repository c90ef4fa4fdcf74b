"""The fixation of the indenter (Secs. 2.1.1, 3.1.1–3.1.3, 3.5.3): rigid, spring–mass–dashpot, or free.

Dimensionless groups: kappa = k/(E* R) (Eq. 66), zeta = c/(2 sqrt(k m)) (Eq. 65), nu0 = v0/(omega0 R)
(Eq. 97), mu = m g/(E* R^2) (Eq. 81). The free indenter (k = c = 0, Sec. 3.1.3) is the limit kappa -> 0
at fixed mass, where nu0 diverges but the mass group inertia = kappa nu0^2 = m v0^2/(E* R^3) stays
finite: it is its own kind, so that its dynamic stiffness is exact. The parameters do not depend on
the excitation frequency; the dynamic stiffness is a method of omega_check = omega R/v0 (Eq. 105).
Validation is written here once.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.core.groups import contact_radius_ratio

#: "compliant" (the spring–mass–dashpot) is the CSV value of the column ``fixation``.
FixationKind = Literal["rigid", "compliant", "free"]


def _require(condition: bool, message: str) -> None:
    """Raise ValueError(``message``) unless ``condition`` (the ranges of Eqs. 65, 66, 81, 97)."""
    if not condition:
        raise ValueError(message)


def _finite_positive(name: str, value: float) -> None:
    """``value`` of the field ``name`` is a finite number > 0 (Eqs. 66, 97), else ValueError naming it."""
    _require(math.isfinite(value) and value > 0, f"{name} must be a positive number, got {value!r}")


def _finite_nonnegative(name: str, value: float) -> None:
    """``value`` of the field ``name`` is a finite number >= 0 (Eqs. 65, 81), else ValueError naming it."""
    _require(math.isfinite(value) and value >= 0, f"{name} must be a finite non-negative number, got {value!r}")


@dataclass(frozen=True)
class Fixation:
    """Fixation element of the indenter in the units of Eq. (66) (stiffnesses over E* R).

    Build it with :meth:`rigid`, :meth:`compliant` or :meth:`free`. ``kappa`` = k/(E* R) is the static
    stiffness of the mean balance (Eq. 54): inf for rigid, 0 for free. ``zeta`` and ``nu0`` belong to
    the compliant kind, ``inertia`` = m v0^2/(E* R^3) to the free one; ``mu`` = m g/(E* R^2) to the
    compliant and free kinds (for a rigid fixation the weight drops out, Eq. 56).
    """

    kind: FixationKind
    kappa: float = math.inf  # k/(E* R), Eq. (66)
    zeta: float = 0.0  # c/(2 sqrt(k m)), Eq. (65)
    nu0: float = math.nan  # v0/(omega0 R), Eq. (97)
    mu: float = 0.0  # m g/(E* R^2), Eq. (81)
    inertia: float = math.nan  # m v0^2/(E* R^3) = kappa nu0^2 (Sec. 3.1.3)

    def __post_init__(self) -> None:
        """Reject what no k >= 0, m >= 0, c >= 0 gives (Eqs. 65, 66, 81, 97); the ValueError names the field."""
        _finite_nonnegative("mu", self.mu)
        if self.kind == "rigid":
            _require(math.isinf(self.kappa) and self.kappa > 0, f"kappa of a rigid fixation is inf, got {self.kappa!r}")
            _require(self.zeta == 0, f"zeta: a rigid fixation has no damping ratio, got {self.zeta!r}")
            _require(math.isnan(self.nu0), f"nu0: a rigid fixation has no natural frequency, got {self.nu0!r}")
            _require(math.isnan(self.inertia), f"inertia: a rigid fixation has no inertia, got {self.inertia!r}")
            _require(self.mu == 0, f"mu: the weight drops out for a rigid fixation (Eq. 56), got {self.mu!r}")
        elif self.kind == "compliant":
            _finite_positive("kappa", self.kappa)
            _finite_nonnegative("zeta", self.zeta)
            _finite_positive("nu0", self.nu0)
            _require(math.isnan(self.inertia), f"inertia is kappa nu0^2 for a compliant fixation, got {self.inertia!r}")
        elif self.kind == "free":
            _require(self.kappa == 0, f"kappa of a free indenter is 0 (k = 0, Eq. 57), got {self.kappa!r}")
            _require(self.zeta == 0, f"zeta: a free indenter has no dashpot (c = 0, Eq. 57), got {self.zeta!r}")
            _require(math.isnan(self.nu0), f"nu0: a free indenter has no natural frequency, got {self.nu0!r}")
            _finite_positive("inertia", self.inertia)
        else:
            raise ValueError(f"kind must be 'rigid', 'compliant' or 'free', got {self.kind!r}")

    @classmethod
    def rigid(cls) -> Fixation:
        """Rigid fixation, k/(E* R) -> infinity (Sec. 3.1.2)."""
        return cls("rigid")

    @classmethod
    def compliant(cls, kappa: float, zeta: float, nu0: float, mu: float = 0.0) -> Fixation:
        """Spring k, mass m, dashpot c (Secs. 3.1.1, 3.5.3; Eqs. 65, 66, 81, 97)."""
        return cls("compliant", kappa=kappa, zeta=zeta, nu0=nu0, mu=mu)

    @classmethod
    def free(cls, inertia: float, mu: float = 0.0) -> Fixation:
        """Free indenter under its dead weight, k = c = 0 (Sec. 3.1.3): inertia = m v0^2/(E* R^3) > 0."""
        return cls("free", kappa=0.0, inertia=inertia, mu=mu)

    @property
    def is_rigid(self) -> bool:
        """The rigid fixation of Sec. 3.1.2 (kappa = inf)."""
        return self.kind == "rigid"

    def omega_bar(self, omega_check: float) -> float:
        """omega/omega0 = omega_check nu0 (Eqs. 65, 97, 105) of the compliant kind."""
        return omega_check * self.nu0

    def d(self, omega_check: float) -> complex:
        """d = (k - m omega^2 + i c omega)/(E* R) at omega = omega_check v0/R (Eqs. 43, 65, 66).

        rigid: inf; compliant: kappa (1 - omega_bar^2 + 2 i zeta omega_bar), so omega_bar = 1, zeta = 0 gives
        d = 0 exactly (the anti-resonance of Appendix B); free: -inertia omega_check^2 = -m omega^2/(E* R).
        A compliant or free fixation needs a finite omega_check >= 0 (ValueError naming it).
        """
        if self.is_rigid:
            return complex(math.inf, 0.0)
        _finite_nonnegative("omega_check", omega_check)
        if self.kind == "free":
            return complex(-self.inertia * omega_check**2, 0.0)
        omega_bar = self.omega_bar(omega_check)
        return self.kappa * complex(1.0 - omega_bar**2, 2.0 * self.zeta * omega_bar)

    def contact_resonance(self, chi0: float, omega_check: float) -> float | None:
        """abar_m at which d + 2 c_o abar_m = 0 (pole of Eq. 43: the mass resonates on fixation plus contact).

        c_o = a_o/R of ``chi0`` (Eqs. 64, 86). Exists only for a real negative d (no damping, above the fixation's own
        resonance, or a free indenter); there |delta_c| = infinity, no steady state. ``None`` otherwise.
        """
        if self.is_rigid:
            return None
        d = self.d(omega_check)
        if d.imag != 0 or d.real >= 0:
            return None
        return -d.real / (2.0 * contact_radius_ratio(chi0))

    def transmissibility(self, abar_m: float, chi0: float, omega_check: float) -> float:
        """|delta_c| / h1 = |d| / |d + 2 c_o abar_m|: Eq. (43) at leading order (Eq. B.3 with damping).

        c_o = a_o/R of ``chi0`` (Eqs. 64, 86). 1 for rigid fixation, infinite at the contact resonance
        (:meth:`contact_resonance`), zero at d = 0: :meth:`indentation_response` of the base rig per unit eta1.
        """
        return float(self.indentation_response(abar_m, chi0, omega_check, 1.0, 0.0))

    def indentation_response(
        self, abar_m: ArrayLike, chi0: float, omega_check: float, eta1: float, force: float
    ) -> NDArray[np.float64]:
        """|delta_c| / R = |force - eta1 d| / |d + 2 c_o abar_m| at leading order, both rigs (Eqs. 13, 20-22, 43).

        eta1 = h1/R of the base rig, ``force`` = F1/(E* R^2) of the force rig (Eq. 13). The oscillating forcing of
        Eq. (20) is Im[(F1 - h1 D) e^{i omega t}] (Eq. 22 for the base, F1 sin(omega t) for the force), and at
        leading order Xi = (D + 2 E* a_m) delta_c (Eqs. 41-42, 47-48), so Eq. (43) becomes |delta_c| |D + 2 E* a_m| =
        |F1 - h1 D|; divided by E* R^2 this is the formula. force = 0: eta1 times :meth:`transmissibility`. eta1 = 0:
        the mass on the fixation and the contact spring in parallel (Fig. 10a of Appendix B with damping), finite at
        the base rig's anti-resonance d = 0, where it is force/(2 c_o abar_m). Rigid: eta1 (a force is a ValueError).
        inf at the contact resonance (:meth:`contact_resonance`). Elementwise in ``abar_m`` (the shape of it).
        """
        abar_m = np.asarray(abar_m, dtype=float)
        if self.is_rigid:
            _require(force == 0, f"force: a rigid fixation carries the force of Eq. (13) itself, got {force!r}")
            return np.full_like(abar_m, eta1)
        d = self.d(omega_check)
        denominator = np.abs(d + 2.0 * contact_radius_ratio(chi0) * abar_m)
        with np.errstate(divide="ignore"):
            return np.where(denominator == 0, math.inf, abs(force - eta1 * d) / denominator)

    @property
    def csv_constants(self) -> dict[str, object]:
        """The ``fixation``, ``kappa``, ``zeta`` cells of the virtual pull-off rows (NaN for rigid)."""
        if self.is_rigid:
            return {"fixation": "rigid", "kappa": math.nan, "zeta": math.nan}
        return {"fixation": self.kind, "kappa": self.kappa, "zeta": self.zeta}
