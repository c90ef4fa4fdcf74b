"""The steady-state problem (vibroadhesion.core.problem): its scales and its validation.

References: c_o = a_o/R = 2^(1/3) 3^(-2/3) chi0 (text below Eq. 86), etahat = eta1/c_o^2, omega_check c_o.
"""

from __future__ import annotations

import math

import pytest
from conftest import CHI0, ETA1, N_PUBLISHED

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz

LAW = GentSchultz(N_PUBLISHED)


def test_scales_follow_eq_86() -> None:
    problem = Problem(LAW, CHI0, ETA1, 1e5)
    c_o = 2 ** (1 / 3) * 3 ** (-2 / 3) * CHI0
    assert problem.c_o == pytest.approx(c_o, rel=1e-15)
    assert problem.etahat == pytest.approx(ETA1 / c_o**2, rel=1e-15)
    assert problem.speed_scale == pytest.approx(1e5 * c_o, rel=1e-15)
    assert problem.fixation == Fixation.rigid() and problem.base_offset == 0.0


@pytest.mark.parametrize(("changes", "field"), [({"chi0": 0.0}, "chi0"), ({"eta1": -1e-6}, "eta1"),
                                                ({"omega_check": math.inf}, "omega_check"),
                                                ({"omega_check": 0.0}, "omega_check"),
                                                ({"base_offset": math.nan}, "base_offset"),
                                                ({"force_amplitude": -1e-9}, "force_amplitude"),
                                                ({"force_amplitude": math.inf}, "force_amplitude")])
def test_invalid_problem_raises_naming_the_field(changes: dict[str, float], field: str) -> None:
    arguments = {"chi0": CHI0, "eta1": ETA1, "omega_check": 1e5} | changes
    with pytest.raises(ValueError, match=field):
        Problem(LAW, **arguments)
    with pytest.raises(TypeError):
        Problem(object(), CHI0, ETA1, 1e5)  # type: ignore[arg-type]


def test_force_rig_needs_a_fixation_that_yields() -> None:
    """Eq. (13): a rigid fixation carries F1 itself, so a forced rigid problem is rejected; a spring takes it."""
    with pytest.raises(ValueError, match="force_amplitude"):
        Problem(LAW, CHI0, 0.0, 1e5, force_amplitude=1e-9)
    forced = Problem(LAW, CHI0, 0.0, 1e5, Fixation.compliant(0.01, 0.0, 1e-5), force_amplitude=1e-9)
    assert forced.force_amplitude == 1e-9 and Problem(LAW, CHI0, ETA1, 1e5).force_amplitude == 0.0
