"""The excitation switched on or off, or its amplitude ramped, during a withdrawal: :class:`ExcitationSchedule`.

The paper's Discussion proposes to control the detachment by making the excitation time-dependent. Here
the base amplitude of Eq. (11) becomes etahat(tau) = etahat s(tau) (and the force rig's drive fhat s(tau),
Eq. 13), with s piecewise linear in tau = omega t counted from the start of the withdrawal
(:func:`vibroadhesion.simulation.withdrawal.withdraw`):

    s(tau) = s0 (tau < tau_a),  s0 + (s1 - s0)(tau - tau_a)/(tau_b - tau_a) (tau_a <= tau < tau_b),  s1 (tau >= tau_b),

so that deltabar = base_offset - ramp tau - etahat s(tau) sin tau (+ xbar, compliant; Eqs. 7, 11'). Switched off
at tau_off: s0 = 1, s1 = 0, tau_a = tau_b = tau_off (a jump of the base, right-continuous: s = 0 from tau_off on);
switched on: s0 = 0, s1 = 1; ramped: tau_a < tau_b. The default, s = 1 throughout, is the constant excitation
of every periodic steady state and leaves the integration unchanged to the bit. The schedule enters the
compiled model as four constants (:data:`vibroadhesion.simulation.kernel.CONSTANTS`), in the time of each
integrated period (:meth:`ExcitationSchedule.kernel_constants`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from vibroadhesion.simulation.kernel import CONSTANT_EXCITATION


@dataclass(frozen=True)
class ExcitationSchedule:
    """s(tau) of the module docstring: s0 before tau_a, s1 from tau_b on, linear in between (Eq. 11, etahat s).

    Validated: s0, s1 finite and >= 0; 0 <= tau_a <= tau_b, tau_b finite unless tau_a = tau_b = inf (never).
    """

    s0: float = CONSTANT_EXCITATION[0]
    s1: float = CONSTANT_EXCITATION[1]
    tau_a: float = CONSTANT_EXCITATION[2]
    tau_b: float = CONSTANT_EXCITATION[3]

    def __post_init__(self) -> None:
        """Reject a schedule that is not a finite, non-negative piecewise linear s(tau) (Eq. 11 with etahat s(tau))."""
        for name in ("s0", "s1"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0.0):
                raise ValueError(f"{name} must be finite and >= 0, got {value}")
        if not (0.0 <= self.tau_a <= self.tau_b):
            raise ValueError(f"need 0 <= tau_a <= tau_b, got tau_a = {self.tau_a}, tau_b = {self.tau_b}")
        if math.isinf(self.tau_b) and self.tau_a != self.tau_b:
            raise ValueError(f"a ramp from tau_a = {self.tau_a} needs a finite tau_b")

    @classmethod
    def switched_off(cls, tau_off: float) -> ExcitationSchedule:
        """The excitation on until ``tau_off``, off (s = 0) from then on (Eq. 11 with etahat s(tau))."""
        return cls(1.0, 0.0, tau_off, tau_off)

    @classmethod
    def switched_on(cls, tau_on: float) -> ExcitationSchedule:
        """The excitation off (s = 0) until ``tau_on``, on from then on (Eq. 11 with etahat s(tau))."""
        return cls(0.0, 1.0, tau_on, tau_on)

    def kernel_constants(self, period_start: float) -> list[float]:
        """(s0, s1, tau_a, tau_b) in the time of a period that starts at tau = ``period_start`` (Eq. 11')."""
        return [self.s0, self.s1, self.tau_a - period_start, self.tau_b - period_start]


#: The constant excitation s = 1 of every periodic steady state (the default of a withdrawal).
CONSTANT_SCHEDULE = ExcitationSchedule()
