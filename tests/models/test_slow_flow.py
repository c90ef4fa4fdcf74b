"""The averaged slow flow of a withdrawal (vibroadhesion.models.slow_flow), against independent references.

* the period-mean front speed G(alpha, beta) against an mpmath quadrature of the Gent–Schultz inverse law;
* h1 = 0: the slow flow is the scalar ODE of the rate-dependent JKR pull-off (no averaging left), integrated
  with mpmath in tests/mpmath_reference.py without the package;
* V -> 0: the exact averaging's quasi-static force minimum, approached at a measured rate O(V);
* the time-domain withdrawal of the full model where both apply (200 Hz, h1 = 20 um, rigid);
* its own integration error against a tighter run, and its statuses.
"""

from __future__ import annotations

import math
from dataclasses import replace

import mpmath as mp
import pytest
from conftest import CHI0, N_PUBLISHED, RADIUS, V0
from mpmath_reference import rate_dependent_jkr_pulloff_mp

from vibroadhesion import simulation as sim
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import omega_check
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.models.exact_averaging import pulloff_at_force_minimum
from vibroadhesion.models.frozen_radius import alpha_star, mean_front_speed
from vibroadhesion.models.slow_flow import withdraw_slowly
from vibroadhesion.simulation.withdrawal import withdraw

LAW = GentSchultz(N_PUBLISHED)
OMEGA_200HZ = float(omega_check(200.0, V0, RADIUS))


def _preloaded(h1_um: float) -> Problem:
    """The rigid 200 Hz test at h1, preloaded at base_offset = etahat (the sweep's start)."""
    problem = Problem(LAW, CHI0, h1_um * 1e-6 / RADIUS, OMEGA_200HZ)
    return replace(problem, base_offset=problem.etahat)


def _mean_speed_mp(alpha: float, beta: float) -> float:
    """(1/pi) int_{-pi/2}^{pi/2} X(alpha + beta sin theta) d theta, X the inverse Gent–Schultz law (Eqs. 73-74)."""
    p = 1 / mp.mpf(N_PUBLISHED)

    def speed(theta: mp.mpf) -> mp.mpf:
        s = alpha + beta * mp.sin(theta)
        return -((s * s - 1) ** p) if s > 1 else (1 / (s * s) - 1) ** p

    with mp.workdps(30):
        kink = [mp.asin((1 - alpha) / beta)] if abs((1 - alpha) / beta) < 1 else []
        return float(mp.quad(speed, [-mp.pi / 2, *kink, mp.pi / 2]) / mp.pi)


@pytest.mark.parametrize(("alpha", "beta"), [(1.05, 0.1), (1.3, 0.1), (1.2, 0.5), (1.9, 1.58), (2.8, 1.58),
                                             (8.3, 7.9), (0.95, 0.02)])
def test_mean_front_speed_is_the_mpmath_quadrature(alpha: float, beta: float) -> None:
    # the quadrature of frozen_radius (1e-14 against mpmath for the drift condition) and 96-point Gauss-Legendre
    # on one branch; measured 3e-15 relative at worst
    assert float(mean_front_speed(alpha, beta, LAW)) == pytest.approx(_mean_speed_mp(alpha, beta), rel=1e-12)


def test_mean_front_speed_vanishes_on_the_drift_free_cycle() -> None:
    for beta in (0.1, 1.58, 7.9):
        alpha = float(alpha_star(beta, LAW))
        # alpha* to 1e-15 relative; G's slope in alpha is O(1)-O(1e4) here, each half integral O(1)-O(1e4)
        assert abs(float(mean_front_speed(alpha, beta, LAW))) < 1e-10 * max(1.0, beta**4)


@pytest.mark.parametrize("speed_ratio", [0.05, 0.5])
def test_h1_zero_is_the_rate_dependent_jkr_pulloff(speed_ratio: float) -> None:
    problem = Problem(LAW, CHI0, 0.0, 1e6, base_offset=0.5)
    run = withdraw_slowly(problem, speed_ratio)
    force, offset = rate_dependent_jkr_pulloff_mp(0.5, speed_ratio / problem.c_o, N_PUBLISHED)
    assert run.status == "pulloff"
    # LSODA at rtol 1e-7 (SLOW_FLOW_RTOL): measured 1.4e-7 (V = 0.05 v0) and 1.2e-7 (0.5 v0), about its rtol;
    # mpmath's at tol 1e-16
    assert run.mean_force == pytest.approx(float(force), rel=5e-7)
    assert run.force == run.mean_force  # no vibration: the peak is the mean
    assert run.mean_base_offset == pytest.approx(float(offset), abs=1e-3)  # sqrt of the force's error


def test_slow_flow_tends_to_the_force_minimum_at_rate_v() -> None:
    problem = _preloaded(20.0)
    limit = float(pulloff_at_force_minimum(problem.eta1, problem.chi0, LAW).pulloff_ratio)
    deviation = {v: -withdraw_slowly(problem, v).mean_force / 0.75 / limit - 1.0 for v in (1e-3, 1e-2)}
    assert all(d > 0.0 for d in deviation.values())  # a finite speed pulls harder
    # O(V): measured 8.24e-5 and 8.31e-4, a ratio of 10.1 for the speed ratio 10
    assert deviation[1e-2] / deviation[1e-3] == pytest.approx(10.0, rel=0.05)
    assert deviation[1e-3] < 1e-4


def test_integration_error_against_a_tighter_run() -> None:
    for h1, speed in ((20.0, 0.1), (100.0, 1.0)):
        run, tight = withdraw_slowly(_preloaded(h1), speed), withdraw_slowly(_preloaded(h1), speed, rtol=1e-10)
        assert run.status == tight.status == "pulloff"
        # measured 5.4e-9 (20 um, 0.1 v0) and 3.4e-9 (100 um, v0); 1.4e-7 at worst over 20-100 um, 1e-3 to 1 v0
        assert run.mean_force == pytest.approx(tight.mean_force, rel=3e-7)
        assert run.force == pytest.approx(tight.force, rel=3e-7)


@pytest.mark.parametrize(("speed_ratio", "bound"), [(0.3, 3e-3), (1.0, 5e-3)])
def test_agrees_with_the_time_domain_at_20um(speed_ratio: float, bound: float) -> None:
    """200 Hz, 20 um, rigid: the slow flow against the full model withdrawn in time from the same start offset.

    The slow flow is the omega R/v0 -> infinity limit: its quasi-static error against the simulation is ~1e-4 at
    20 um (README), and at a finite speed the difference grows with V (measured in the README's table).
    """
    problem = _preloaded(20.0)
    orbit = sim.steady_state(problem).orbit
    assert orbit is not None
    timed = withdraw(problem, speed_ratio, initial_state=orbit.start_state, rtol=1e-9)
    slow = withdraw_slowly(problem, speed_ratio)
    assert timed.status == slow.status == "pulloff"
    assert abs(slow.mean_force / timed.mean_force - 1.0) < bound
    assert abs(slow.force / timed.force - 1.0) < 2.0 * bound


def test_statuses() -> None:
    compliant = replace(_preloaded(20.0), fixation=Fixation.compliant(0.001, 0.01, 1.227e-5))
    with pytest.raises(ValueError, match="rigid"):
        withdraw_slowly(compliant, 1.0)
    with pytest.raises(ValueError):
        withdraw_slowly(_preloaded(20.0), 0.0)
    # a start offset below the family's force minimum has no start state: a failure status, no number
    below = withdraw_slowly(replace(_preloaded(20.0), base_offset=-50.0), 1.0)
    assert below.status == "integration_failure" and math.isnan(below.mean_force)
    # the runaway ends the flow after both minima: detached, the pull-off before it
    run = withdraw_slowly(_preloaded(20.0), 0.1)
    assert run.status == "pulloff" and run.slow_time < run.slow_time_detached
