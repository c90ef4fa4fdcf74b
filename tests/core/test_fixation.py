"""The fixation of the indenter (vibroadhesion.core.fixation): its validation rules, once, and its dynamic stiffness.

References: d = kappa (1 - omega_bar^2 + 2 i zeta omega_bar) with omega_bar = omega_check nu0 (Eqs. 65, 66, 97,
105), written out here as the expression the package used before the fixation types were merged; d = -beta for
the free indenter (Eq. 57); |d|/|d + 2 c_o abar_m| (Eq. B.3 with damping) with c_o = 2^(1/3) 3^(-2/3) chi0.
"""

from __future__ import annotations

import math

import pytest
from conftest import CHI0, NU0

from vibroadhesion.core.fixation import Fixation


@pytest.mark.parametrize(("kappa", "zeta", "nu0", "omega_check"),
                         [(1e-3, 0.01, NU0, 1.4543e6), (0.1, 0.05, 1.0, 2.0), (1e12, 0.0, 1.0, 5.0),
                          (0.01, 0.2, 0.37, 3.3), (1e-3, 0.0, 1.0, 1.0)])
def test_compliant_d_is_the_spring_mass_dashpot_expression_bit_for_bit(kappa, zeta, nu0, omega_check) -> None:
    fixation = Fixation.compliant(kappa, zeta, nu0)
    omega_bar = omega_check * nu0
    assert fixation.omega_bar(omega_check) == omega_bar
    assert fixation.d(omega_check) == kappa * complex(1.0 - omega_bar**2, 2.0 * zeta * omega_bar)


def test_compliant_d_vanishes_exactly_at_the_undamped_anti_resonance() -> None:
    """omega_bar = 1, zeta = 0 (Appendix B): d = 0, transmissibility 0, no contact resonance."""
    fixation = Fixation.compliant(0.01, 0.0, 1.0)
    assert fixation.d(1.0) == 0
    assert fixation.transmissibility(1.0, CHI0, 1.0) == 0.0 and fixation.contact_resonance(CHI0, 1.0) is None


@pytest.mark.parametrize("beta", [1e-3, 0.3, 1.0, 7.25])
def test_free_d_is_minus_beta_exactly(beta: float) -> None:
    assert Fixation.free(beta).d(1.0) == complex(-beta, 0.0)
    assert Fixation.free(beta).d(2.0) == complex(-4.0 * beta, 0.0)  # m omega^2: scaled by omega_check^2 exactly


def test_rigid_fixation_is_infinitely_stiff_and_transmits_the_base_motion() -> None:
    rigid = Fixation.rigid()
    assert rigid.is_rigid and rigid.kappa == math.inf and rigid.d(1e6) == complex(math.inf, 0.0)
    assert rigid.transmissibility(1.0, CHI0, 1e6) == 1.0 and rigid.contact_resonance(CHI0, 1e6) is None
    assert not Fixation.compliant(1e12, 0.0, 1.0).is_rigid and not Fixation.free(1.0).is_rigid


def test_contact_resonance_and_transmissibility_follow_eq_b3() -> None:
    """Free indenter with beta = 2 c_o: pole at abar_m = 1; a damped spring: |d|/|d + 2 c_o abar_m| to 1e-15."""
    c_o = 2 ** (1 / 3) * 3 ** (-2 / 3) * CHI0
    free = Fixation.free(2.0 * c_o)
    assert free.contact_resonance(CHI0, 1.0) == pytest.approx(1.0, rel=1e-15)
    assert free.transmissibility(1.0, CHI0, 1.0) == math.inf
    spring = Fixation.compliant(0.1, 0.05, 1.0)
    d = 0.1 * complex(1.0 - 4.0, 2.0 * 0.05 * 2.0)
    assert spring.transmissibility(1.3, CHI0, 2.0) == pytest.approx(abs(d) / abs(d + 2.0 * c_o * 1.3), rel=1e-15)
    assert spring.contact_resonance(CHI0, 2.0) is None  # damped: d is not real
    assert Fixation.compliant(0.1, 0.0, 1.0).contact_resonance(CHI0, 2.0) == pytest.approx(0.3 / (2 * c_o), rel=1e-15)


def test_indentation_response_of_both_rigs_follows_eqs_13_and_43() -> None:
    """|force - eta1 d|/|d + 2 c_o abar_m| written out for a damped spring (to 1e-15): the base rig alone is
    eta1 times the transmissibility, the force rig alone force/|d + K|; at the undamped anti-resonance (d = 0)
    the base rig gives 0 and the force rig force/(2 c_o abar_m) (Appendix B); rigid gives eta1, a forced rigid
    fixation is a ValueError.
    """
    c_o = 2 ** (1 / 3) * 3 ** (-2 / 3) * CHI0
    spring = Fixation.compliant(0.1, 0.05, 1.0)
    d = 0.1 * complex(1.0 - 4.0, 2.0 * 0.05 * 2.0)
    assert spring.indentation_response(1.3, CHI0, 2.0, 1e-4, 0.0) == pytest.approx(
        1e-4 * spring.transmissibility(1.3, CHI0, 2.0), rel=1e-15)
    assert spring.indentation_response(1.3, CHI0, 2.0, 0.0, 3e-5) == pytest.approx(
        3e-5 / abs(d + 2 * c_o * 1.3), rel=1e-15)
    assert spring.indentation_response(1.3, CHI0, 2.0, 1e-4, 3e-5) == pytest.approx(
        abs(3e-5 - 1e-4 * d) / abs(d + 2 * c_o * 1.3), rel=1e-15)
    undamped = Fixation.compliant(0.1, 0.0, 1.0)
    assert undamped.indentation_response(1.3, CHI0, 1.0, 1e-4, 0.0) == 0.0
    assert undamped.indentation_response(1.3, CHI0, 1.0, 0.0, 3e-5) == pytest.approx(3e-5 / (2 * c_o * 1.3), rel=1e-15)
    assert Fixation.rigid().indentation_response(1.3, CHI0, 2.0, 1e-4, 0.0) == 1e-4
    with pytest.raises(ValueError, match="force"):
        Fixation.rigid().indentation_response(1.3, CHI0, 2.0, 0.0, 1e-5)


def test_csv_constants_are_the_cells_of_the_virtual_pulloff_rows() -> None:
    rigid = Fixation.rigid().csv_constants
    assert rigid["fixation"] == "rigid" and math.isnan(rigid["kappa"]) and math.isnan(rigid["zeta"])
    assert Fixation.compliant(1e-3, 0.01, NU0, 0.0).csv_constants == {"fixation": "compliant", "kappa": 1e-3,
                                                                     "zeta": 0.01}


INVALID = [  # (constructor call, the field the message must name)
    (lambda: Fixation.compliant(0.0, 0.1, NU0), "kappa"),
    (lambda: Fixation.compliant(-1.0, 0.1, NU0), "kappa"),
    (lambda: Fixation.compliant(math.inf, 0.1, NU0), "kappa"),
    (lambda: Fixation.compliant(math.nan, 0.1, NU0), "kappa"),
    (lambda: Fixation.compliant(0.1, -0.01, NU0), "zeta"),
    (lambda: Fixation.compliant(0.1, math.inf, NU0), "zeta"),
    (lambda: Fixation.compliant(0.1, 0.01, 0.0), "nu0"),
    (lambda: Fixation.compliant(0.1, 0.01, math.nan), "nu0"),
    (lambda: Fixation.compliant(0.1, 0.01, NU0, -1e-6), "mu"),
    (lambda: Fixation.compliant(0.1, 0.01, NU0, math.inf), "mu"),
    (lambda: Fixation("compliant", kappa=0.1, nu0=NU0, inertia=1.0), "inertia"),
    (lambda: Fixation.free(0.0), "inertia"),
    (lambda: Fixation.free(-1.0), "inertia"),
    (lambda: Fixation.free(math.inf), "inertia"),
    (lambda: Fixation.free(1.0, -1e-6), "mu"),
    (lambda: Fixation("free", kappa=0.1, inertia=1.0), "kappa"),
    (lambda: Fixation("free", kappa=0.0, zeta=0.1, inertia=1.0), "zeta"),
    (lambda: Fixation("free", kappa=0.0, nu0=NU0, inertia=1.0), "nu0"),
    (lambda: Fixation("rigid", kappa=1.0), "kappa"),
    (lambda: Fixation("rigid", kappa=-math.inf), "kappa"),
    (lambda: Fixation("rigid", zeta=0.1), "zeta"),
    (lambda: Fixation("rigid", nu0=NU0), "nu0"),
    (lambda: Fixation("rigid", inertia=1.0), "inertia"),
    (lambda: Fixation("rigid", mu=1e-6), "mu"),
    (lambda: Fixation("spring"), "kind"),  # type: ignore[arg-type]
    (lambda: Fixation.compliant(0.1, 0.01, NU0).d(math.inf), "omega_check"),
    (lambda: Fixation.compliant(0.1, 0.01, NU0).d(-1.0), "omega_check"),
    (lambda: Fixation.free(1.0).d(math.nan), "omega_check"),
]


@pytest.mark.parametrize(("build", "field"), INVALID)
def test_each_invalid_combination_raises_a_value_error_naming_the_field(build, field: str) -> None:
    """kappa > 0 finite, zeta >= 0, nu0 > 0 for a spring-mass-dashpot (Eqs. 65, 66, 97); k = c = 0 and a mass
    for a free indenter (Eq. 57); kappa = inf and nothing else for a rigid one; mu >= 0 (Eq. 81); a finite
    omega_check >= 0 for the dynamic stiffness of a non-rigid fixation (Eq. 105).
    """
    with pytest.raises(ValueError, match=rf"\b{field}\b"):
        build()
