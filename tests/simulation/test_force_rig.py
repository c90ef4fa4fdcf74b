"""The force-excitation rig (Fig. 2, Eq. 13) in the simulation, checked against independent references.

References, each named in the test that uses it:
* the base-excitation simulation: with y = xbar - etahat sin tau the base rig's Eq. (3') is forced by
  -etahat [(1 - omega_bar^2) sin tau + 2 zeta omega_bar cos tau] = etahat |D| sin(tau + theta + pi),
  D = 1 - omega_bar^2 + 2 i zeta omega_bar, theta = arg D, so the force rig with F1 = h1 |k - m omega^2 + i c omega|
  (force_amplitude = kappa eta1 |D|) is the same system shifted in phase: equal means, equal Floquet
  multipliers, and complex indentation harmonics (s + i c) related by Y_base = -e^(i theta) Y_force;
* the linear two-spring system of Appendix B (Fig. 10a, with damping): with the contact radius
  nearly frozen, Phat = 2 abar deltabar - (2/3) abar^3 is linear in deltabar and the indentation's
  complex amplitude is (force/c_o^2)/(d + 2 c_o abar_m), d = kappa D, in units of a_o^2/R. The radius
  moves by A: dPhat/dabar = 2 deltabar - 2 abar^2 adds ~2 abar_m^2 (A/a_o) to the force 2 abar_m |delta_1|,
  a relative error e = (A/a_m) abar_m^2/|delta_1| (delta_1 in a_o^2/R): tolerance 10 e, plus 1e-6 for the
  integration (the harmonic is a quadrature of xbar/S at rtol 1e-12 over ~1e3 steps, S up to 1e3 |delta_1|);
* the anti-resonance of the base rig (Appendix B, Eq. B.3): omega_bar = 1, zeta = 0 leaves the base rig
  unforced (the static state, Eq. 82), while the force rig drives the contact spring alone,
  |delta_c| = F1/(2 E* a_m) to the same 10 e;
* the free-indenter limit (Sec. 3.1.3, Eq. 59): kappa -> 0 at fixed m, where the mean contact force
  tends to m g (= 0 here) and the response to force/(2 c_o abar_m - inertia omega_check^2).
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest
from conftest import C_O, CHI0, N_PUBLISHED, NU0, RADIUS

from vibroadhesion import simulation as sim
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import SteadyState

LAW = GentSchultz(N_PUBLISHED)
ETA1 = 20e-6 / RADIUS


def harmonic(r: SteadyState) -> complex:
    """s + i c of the indentation deltabar ~ c cos tau + s sin tau (Im of it times e^(i tau))."""
    assert r.orbit is not None
    return complex(r.orbit.deltabar_s, r.orbit.deltabar_c)


def frozen_error(r: SteadyState) -> float:
    """e = (A/a_m) abar_m^2/|delta_1|: the relative error of the frozen-contact response (module docstring)."""
    return float(r.A_over_am) * float(r.abar_m) ** 2 / abs(harmonic(r))


def forced(fixation: Fixation, omega_bar: float, force: float) -> SteadyState:
    return sim.steady_state(Problem(LAW, CHI0, 0.0, omega_bar / fixation.nu0, fixation, force_amplitude=force))


@pytest.mark.parametrize("kappa, zeta, omega_bar", [(0.01, 0.01, 17.85), (0.001, 0.01, 17.85), (0.01, 0.05, 5.0),
                                                    (0.1, 0.2, 1.5)])
def test_force_rig_with_f1_equal_h1_times_dynamic_stiffness_is_the_base_rig(kappa, zeta, omega_bar) -> None:
    """Reference: the base-rig simulation (module docstring). Means, Abar and the multipliers agree to 1e-9
    (both orbits converged at rtol 1e-12, residual < 1e-10), the indentation harmonics after the phase shift too.
    """
    fixation = Fixation.compliant(kappa, zeta, NU0)
    D = complex(1.0 - omega_bar**2, 2.0 * zeta * omega_bar)
    base = sim.steady_state(Problem(LAW, CHI0, ETA1, omega_bar / NU0, fixation))
    force = forced(fixation, omega_bar, kappa * ETA1 * abs(D))
    assert base.status == "ok" and force.status == "ok"
    for field in ("abar_m", "Abar", "w_eff_ratio", "pm_over_abs_pjkr", "deltabar_m"):
        assert getattr(force, field) == pytest.approx(getattr(base, field), rel=1e-9, abs=1e-12), field
    assert abs(harmonic(base) + cmath.exp(1j * cmath.phase(D)) * harmonic(force)) <= 1e-9 * abs(harmonic(base))
    assert np.allclose(np.sort_complex(force.orbit.floquet_multipliers),
                       np.sort_complex(base.orbit.floquet_multipliers), rtol=0, atol=1e-8)


@pytest.mark.parametrize("kappa, zeta, omega_bar", [(0.01, 0.01, 17.85), (0.001, 0.05, 30.0), (0.01, 0.0, 1.0)])
def test_nearly_frozen_contact_responds_as_the_linear_two_spring_system(kappa, zeta, omega_bar) -> None:
    """Reference: the linear two-spring system (module docstring) at omega_check >= 8e4 with small force:
    complex amplitude (force/c_o^2)/(d + 2 c_o abar_m) to 10 e + 1e-6 (module docstring); the mean force balance Eq. (15) to 1e-9.
    """
    fixation = Fixation.compliant(kappa, zeta, NU0)
    force = 2e-3 * kappa * ETA1 * max(omega_bar**2, 1.0)
    r = forced(fixation, omega_bar, force)
    assert r.status == "ok" and 0 < r.A_over_am < 0.05
    d = fixation.d(omega_bar / NU0)
    expected = (force / C_O**2) / (d + 2 * C_O * float(r.abar_m))
    assert abs(harmonic(r) - expected) <= (10 * frozen_error(r) + 1e-6) * abs(expected)
    assert r.deltabar_m == pytest.approx(-C_O / kappa * r.orbit.phat_m, rel=1e-9)  # Eq. (15), mu = 0


def test_base_rig_at_its_anti_resonance_stays_static_and_force_rig_drives_the_contact_alone() -> None:
    """Hard case (Appendix B): omega_bar = 1, zeta = 0. Base rig: the static state (Eq. 82), w_eff = w0, to
    1e-9. Force rig: a vibrating orbit with |delta_c| = F1/(2 E* a_m) (d = 0) to 10 e + 1e-6, and w_eff > w0.
    """
    fixation = Fixation.compliant(0.001, 0.0, NU0)
    static = sim.static_state(Problem(LAW, CHI0, ETA1, 1.0 / NU0, fixation))
    base = sim.steady_state(Problem(LAW, CHI0, ETA1, 1.0 / NU0, fixation))
    assert base.status == "ok"
    assert base.abar_m == pytest.approx(static.abar_0, rel=1e-9) and base.w_eff_ratio == pytest.approx(1.0, rel=1e-9)
    force = 2e-3 * fixation.kappa * ETA1
    r = forced(fixation, 1.0, force)
    assert r.status == "ok" and 0 < r.A_over_am < 0.05 and r.w_eff_ratio > 1.0
    expected = (force / C_O**2) / (2 * C_O * float(r.abar_m))
    assert abs(abs(harmonic(r)) - expected) <= (10 * frozen_error(r) + 1e-6) * expected


def test_soft_spring_tends_to_the_free_indenter() -> None:
    """Reference: the free indenter under F1 sin(omega t) (Sec. 3.1.3, Eq. 59, mu = 0): as kappa -> 0 at fixed
    inertia = kappa nu0^2, P_m -> m g = 0 (|Phat_m| <= 10 kappa |mean xbar|/c_o, Eq. 15) and the complex amplitude
    tends to (force/c_o^2)/(2 c_o abar_m - inertia omega_check^2), to 10 e + 1e-6 + 10 kappa/|d| (the spring's
    share of the dynamic stiffness).
    """
    inertia, omega_check, force = 1e-10, 2e5, 1e-9
    for kappa in (1e-5, 1e-6):
        fixation = Fixation.compliant(kappa, 0.0, math.sqrt(inertia / kappa))
        r = forced(fixation, omega_check * fixation.nu0, force)
        assert r.status == "ok" and 0 < r.A_over_am < 0.05
        assert abs(r.orbit.phat_m) <= 10 * kappa * abs(float(r.deltabar_m)) / C_O
        d_free = -inertia * omega_check**2
        expected = (force / C_O**2) / (2 * C_O * float(r.abar_m) + d_free)
        tolerance = 10 * frozen_error(r) + 1e-6 + 10 * kappa / abs(d_free)
        assert abs(harmonic(r) - expected) <= tolerance * abs(expected)
