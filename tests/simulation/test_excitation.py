"""The excitation schedule of a withdrawal (vibroadhesion.simulation.excitation), against independent references.

* s(tau) and ds/dtau in the compiled kernel: the closed form of the piecewise linear schedule;
* switched off at tau = 0 from the vibrating steady state: the rate-dependent JKR pull-off (h1 = 0) of the
  same start radius, the scalar ODE for a(T) integrated with mpmath (tests/mpmath_reference.py), and after the
  transient the one from the static contact;
* ramped to zero over the first two periods: between the h1 = 0 pull-offs from the start radius +- 2 A;
* a schedule that is constant at s = 1 (or switches outside the withdrawal): today's withdrawal to the bit;
* the force rig's drive switched off: the unforced problem's withdrawal.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from conftest import CHI0, N_PUBLISHED, NU0, OMEGA_BAR_200HZ, RADIUS
from mpmath_reference import rate_dependent_jkr_pulloff_mp

from vibroadhesion import simulation as sim
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.simulation import kernel
from vibroadhesion.simulation.excitation import ExcitationSchedule
from vibroadhesion.simulation.integrators import Period
from vibroadhesion.simulation.model import Model
from vibroadhesion.simulation.scales import v_scale_estimate
from vibroadhesion.simulation.withdrawal import withdraw

#: h1 = 20 um at omega_check = 1e6 preloaded at base_offset 4, withdrawn at V = 0.05 v0 (~4000 periods): far
#: enough from the pull-off (-0.56) that the start's memory has faded to 2e-8 there (measured with mpmath).
BASE_OFFSET, SPEED = 4.0, 0.05
VIBRATING = Problem(GentSchultz(N_PUBLISHED), CHI0, 20e-6 / RADIUS, 1e6, base_offset=BASE_OFFSET)
#: DOP853 at rtol 1e-11 over ~2e5 steps against mpmath at tol 1e-16 (as tests/simulation/test_withdrawal.py).
INTEGRATION = 1e-8


#: Where the schedule's s0, s1, tau_a, tau_b sit in the kernel's constants.
SCHEDULE = [kernel.CONSTANTS.index(f"excitation_{name}") for name in ("s0", "s1", "tau_a", "tau_b")]


def schedule_constants(s0: float, s1: float, tau_a: float, tau_b: float) -> np.ndarray:
    k = np.zeros(len(kernel.CONSTANTS))
    k[SCHEDULE] = s0, s1, tau_a, tau_b
    return k


@pytest.fixture(scope="module")
def vibrating_start() -> tuple[float, float]:
    """(abar(0), A) of the periodic steady state at BASE_OFFSET: its start radius and radius half-amplitude."""
    steady = sim.steady_state(VIBRATING)
    assert steady.status == "ok" and steady.orbit is not None
    return float(steady.orbit.start_state[0]), float(steady.A_over_am) * float(steady.abar_m)


@pytest.fixture(scope="module")
def references(vibrating_start: tuple[float, float]) -> dict[str, float]:
    """The h1 = 0 pull-offs (mpmath) from the static contact and from the start radius a0, a0 - 2A, a0 + 2A."""
    a0, amplitude = vibrating_start
    group = SPEED / VIBRATING.c_o
    starts = {"static": None, "a0": a0, "a0-2A": a0 - 2 * amplitude, "a0+2A": a0 + 2 * amplitude}
    return {key: float(rate_dependent_jkr_pulloff_mp(BASE_OFFSET, group, N_PUBLISHED, start_radius=start)[0])
            for key, start in starts.items()}


def test_schedule_levels_and_rates_are_the_piecewise_linear_s() -> None:
    taus = np.array([0.0, 0.999, 1.0, 2.0, 2.5, 3.0, 10.0])
    level, rate = kernel.excitation_factors(taus, schedule_constants(0.2, 1.4, 1.0, 3.0))
    # s0 = 0.2 before 1, 0.2 + 0.6 (tau - 1) on [1, 3), 1.4 from 3 on
    assert level == pytest.approx([0.2, 0.2, 0.2, 0.8, 1.1, 1.4, 1.4], rel=1e-15)
    assert rate.tolist() == pytest.approx([0.0, 0.0, 0.6, 0.6, 0.6, 0.0, 0.0], rel=1e-15)
    switch = kernel.excitation_factors(np.array([1.999, 2.0, 5.0]), schedule_constants(1.0, 0.0, 2.0, 2.0))
    assert switch[0].tolist() == [1.0, 0.0, 0.0] and switch[1].tolist() == [0.0, 0.0, 0.0]  # off from tau_off on
    steady = kernel.excitation_factors(taus, schedule_constants(*kernel.CONSTANT_EXCITATION))
    assert steady[0].tolist() == [1.0] * 7 and steady[1].tolist() == [0.0] * 7


def test_integration_steps_onto_a_switch_inside_its_interval() -> None:
    """No step straddles a switch: the switch time is an accepted step of the compiled DOP853 of a period."""
    assert ExcitationSchedule().kernel_constants(0.0) == list(kernel.CONSTANT_EXCITATION)
    model = Model(VIBRATING, 1e-3)
    start = np.array([sim.static_state(VIBRATING).abar_0])
    period = Period(model, start, v_scale_estimate(model, float(start[0])), 1.0)
    constants = period.kernel_constants.copy()
    constants[SCHEDULE] = ExcitationSchedule.switched_off(2.5).kernel_constants(0.0)
    run = kernel.integrate(constants, np.array(period.full_start()), 0.0, 2 * math.pi, 1e-11, 10_000, -math.inf)
    assert run.code == kernel.REACHED and 2.5 in run.taus.tolist()


@pytest.mark.parametrize(("s0", "s1", "tau_a", "tau_b"), [(-0.1, 1.0, 0.0, 1.0), (1.0, math.nan, 0.0, 1.0),
                                                          (1.0, 0.0, 2.0, 1.0), (1.0, 0.0, -1.0, 1.0),
                                                          (1.0, 0.0, 1.0, math.inf), (math.inf, 1.0, 0.0, 0.0)])
def test_invalid_schedule_raises(s0: float, s1: float, tau_a: float, tau_b: float) -> None:
    with pytest.raises(ValueError):
        ExcitationSchedule(s0, s1, tau_a, tau_b)


def test_switched_off_from_the_vibrating_state_is_the_rate_dependent_jkr_pulloff(
        vibrating_start: tuple[float, float], references: dict[str, float]) -> None:
    a0, _ = vibrating_start
    off = withdraw(VIBRATING, SPEED, initial_state=[a0], excitation=ExcitationSchedule.switched_off(0.0))
    assert off.status == "pulloff"
    # from tau = 0 on this is the h1 = 0 problem from the radius a0 (measured 1e-15)
    assert off.force == pytest.approx(references["a0"], rel=INTEGRATION)
    # and, the transient over, the rate-dependent JKR pull-off from the static contact: the start's memory is
    # the difference of the two mpmath pull-offs (1.8e-8)
    memory = abs(references["a0"] / references["static"] - 1)
    assert memory < 1e-7
    assert off.force == pytest.approx(references["static"], rel=INTEGRATION + memory)


def test_ramped_to_zero_before_the_pulloff_is_the_rate_dependent_jkr_pulloff(
        vibrating_start: tuple[float, float], references: dict[str, float]) -> None:
    """s from 1 to 0 over the first two periods. The radius then lies within a0 +- 2A (it oscillates by 2A over a
    period and relaxes over ~1e4 radians), and from there on the h1 = 0 flow is order preserving with dP/da =
    2 (d - a^2) < 0: the pull-off lies between the mpmath pull-offs from a0 -+ 2A (measured 9e-11 from the one
    from a0), widened by the integration error.
    """
    a0, _ = vibrating_start
    ramp = withdraw(VIBRATING, SPEED, initial_state=[a0], excitation=ExcitationSchedule(1.0, 0.0, 0.0, 4 * math.pi))
    assert ramp.status == "pulloff" and ramp.tau > 4 * math.pi
    low, high = sorted((references["a0-2A"], references["a0+2A"]))
    assert low * (1 + INTEGRATION) <= ramp.force <= high * (1 - INTEGRATION)
    memory = max(abs(references[key] / references["static"] - 1) for key in ("a0-2A", "a0+2A"))
    assert ramp.force == pytest.approx(references["static"], rel=INTEGRATION + memory)


def test_constant_schedule_is_todays_withdrawal_to_the_bit(vibrating_start: tuple[float, float]) -> None:
    """s = 1 throughout, written three ways, and a switch-on at tau = 0: the default's record, every float equal."""
    a0, _ = vibrating_start
    default = withdraw(VIBRATING, 1.0, initial_state=[a0])
    for schedule in (ExcitationSchedule(1.0, 1.0, 3.0, 7.0), ExcitationSchedule.switched_off(1e9),
                     ExcitationSchedule.switched_on(0.0)):
        assert withdraw(VIBRATING, 1.0, initial_state=[a0], excitation=schedule) == default, schedule
    assert default.status == "pulloff"


def test_force_rig_drive_switched_off_is_the_unforced_withdrawal() -> None:
    """s scales the force rig's drive too (Eq. 13, fhat s(tau)): the forced problem switched off at tau = 0 is the
    unforced one from the same start (its x scale differs, so to the integration error, 1e-8).
    """
    fixation = Fixation.compliant(0.001, 0.01, NU0)
    omega_bar = OMEGA_BAR_200HZ
    drive = fixation.kappa * 20e-6 / RADIUS * abs(complex(1.0 - omega_bar**2, 2.0 * fixation.zeta * omega_bar))
    forced = Problem(GentSchultz(N_PUBLISHED), CHI0, 0.0, omega_bar / NU0, fixation, force_amplitude=drive)
    steady = sim.steady_state(forced)
    assert steady.status == "ok" and steady.orbit is not None
    start = list(steady.orbit.start_state)
    off = withdraw(forced, 10.0, initial_state=start, excitation=ExcitationSchedule.switched_off(0.0))
    unforced = withdraw(replace(forced, force_amplitude=0.0), 10.0, initial_state=start)
    assert off.status == unforced.status and off.status in ("pulloff", "detached_before_mean_extremum")
    assert off.force == pytest.approx(unforced.force, rel=INTEGRATION)
    assert off.tau == pytest.approx(unforced.tau, rel=1e-6)  # a quadratic minimum's location: ~sqrt of the error
