"""One steady-state problem: contact, rate law, excitation, fixation.

Eqs. (4)–(7), (11): the Gent–Schultz law (Eqs. 73–75), chi0 (Eq. 64), eta1 = h1/R (Eq. 65),
omega_check = omega R/v0 (Eq. 105), the fixation of the indenter (:class:`Fixation`) and the base
offset (hhat - h0) R/a_o^2 (0 for the nominal point contact, Eq. 78).

Two rigs. Base excitation (Fig. 1): the base moves, h = h0 + h1 sin(omega t) (Eq. 11), amplitude
eta1. Force excitation (Fig. 2, Eq. 13): the base stays at h0 and a force F1 sin(omega t) acts on the
indenter, amplitude ``force_amplitude`` = F1/(E* R^2) (the units of the weight group mu, Eq. 81).
Both may be set (their forcings add); a rigid fixation carries any force itself, so it has none.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import contact_radius_ratio
from vibroadhesion.core.ratelaw import GentSchultz


@dataclass(frozen=True)
class Problem:
    """The parameters of one periodic steady state of the full model (Eqs. 4–7, 11)."""

    law: GentSchultz
    chi0: float  # (9 pi w0 / (E* R))^(1/3), Eq. (64)
    eta1: float  # h1 / R, Eq. (65)
    omega_check: float  # omega R / v0, Eq. (105)
    fixation: Fixation = Fixation.rigid()
    base_offset: float = 0.0  # (hhat - h0) R / a_o^2; 0 = nominal point contact, Eq. (78)
    force_amplitude: float = 0.0  # F1 / (E* R^2) of the force rig, Eq. (13); 0 = base rig only

    def __post_init__(self) -> None:
        """Reject a law other than Gent–Schultz (Eqs. 73–75), non-finite or negative scales, a forced rigid fixation."""
        if not isinstance(self.law, GentSchultz):
            raise TypeError("the problem is posed for the Gent–Schultz law (Eqs. 73–75)")
        if not (math.isfinite(self.chi0) and self.chi0 > 0):
            raise ValueError(f"chi0 must be positive, got {self.chi0}")
        if not (math.isfinite(self.eta1) and self.eta1 >= 0):
            raise ValueError(f"eta1 must be finite and non-negative, got {self.eta1}")
        if not (math.isfinite(self.omega_check) and self.omega_check > 0):
            raise ValueError(f"omega_check must be positive, got {self.omega_check}")
        if not math.isfinite(self.base_offset):
            raise ValueError(f"base_offset must be finite, got {self.base_offset}")
        if not (math.isfinite(self.force_amplitude) and self.force_amplitude >= 0):
            raise ValueError(f"force_amplitude must be finite and non-negative, got {self.force_amplitude}")
        if self.force_amplitude > 0 and self.fixation.is_rigid:
            raise ValueError("force_amplitude: a rigid fixation carries the force of Eq. (13) itself")

    @property
    def c_o(self) -> float:
        """c_o = a_o/R (text below Eq. 86)."""
        return contact_radius_ratio(self.chi0)

    @property
    def etahat(self) -> float:
        """etahat = h1 R/a_o^2 = eta1/c_o^2, the base amplitude in units of a_o^2/R (Eq. 86)."""
        return self.eta1 / self.c_o**2

    @property
    def speed_scale(self) -> float:
        """omega_check c_o = omega a_o/v0: d abar/d tau = x / (omega_check c_o), Eq. (6')."""
        return self.omega_check * self.c_o
