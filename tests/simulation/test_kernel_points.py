"""The compiled helpers of the orbit analysis and of the start (vibroadhesion.simulation.kernel), and the first period.

References:
* closed forms: the frozen mean speed for n = 1 in the opening range (x = 1 - Phi, a trigonometric
  polynomial of degree 2, which the 512-point periodic trapezoid rule integrates exactly) and at the
  cap; abar (Phi - 1) = gap^2 - abar;
* a central difference of Phi(abar(tau), deltabar(tau)) along the rates of Eq. (6') for dPhi/dtau;
* :func:`scipy.integrate.solve_ivp` (DOP853, rtol 1e-13) for the re-integration inside a step;
* the first period at the full rtol for the looser first period of the shooting.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import CHI0, N_PUBLISHED, RADIUS, V0
from scipy.integrate import solve_ivp

from vibroadhesion import simulation as sim
from vibroadhesion.core.groups import omega_check
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.simulation import kernel, shooting
from vibroadhesion.simulation.integrators import Integrators, Period, run_period
from vibroadhesion.simulation.model import Model, absolute_start, contact_kernel
from vibroadhesion.simulation.scales import v_scale_estimate, x_scale

OMEGA_200HZ = float(omega_check(200.0, V0, RADIUS))
SINES = np.sin(np.linspace(0.0, 2 * math.pi, 512, endpoint=False))


def orbit_period(h1_um: float) -> Period:
    problem = Problem(GentSchultz(N_PUBLISHED), CHI0, h1_um * 1e-6 / RADIUS, OMEGA_200HZ)
    model = Model(problem, 1e-3)
    start = sim.steady_state(problem).orbit.start_state
    return Period(model, start, v_scale_estimate(model, float(start[0])), 1.0)


def test_frozen_mean_speed_closed_forms() -> None:
    """n = 1, abar = 1, deltabar = -1 - 0.5 sin tau: Phi = (2 + 0.5 sin tau)^2 in [2.25, 6.25] (opening), so
    x = 1 - Phi and <x> = 1 - (4 + 0.125) = -3.125 (exact for the rule up to rounding: 1e-14); where
    abar^2 <= deltabar all period the contact closes at the cap.
    """
    assert kernel.frozen_mean_speed(1.0, -1.0, 0.5, SINES, 1.0, 1e30) == pytest.approx(-3.125, rel=1e-14)
    assert kernel.frozen_mean_speed(1.0, 5.0, 0.1, SINES, 1.0 / N_PUBLISHED, 7.0) == 7.0
    # A huge opening speed is clipped at -cap: Phi - 1 = 2.25 - 1 at every point with n = 0.01.
    assert kernel.frozen_mean_speed(1.0, -0.5, 0.0, SINES, 100.0, 1e6) == -1e6


def test_point_values_turning_and_phi_rate() -> None:
    """TURNING is gap^2 - abar (closed form); PHI_RATE is dPhi/dtau, against a central difference
    (step 1e-6: truncation ~1e-12, rounding ~1e-10 of Phi) of Phi(abar + abar' h, deltabar(tau + h)).
    """
    period = orbit_period(100.0)
    k, m = period.kernel_constants, period.m
    taus = np.array([0.3, 1.7, 4.0])
    cores = np.array([[0.2], [-0.1], [0.05]])
    turning = kernel.point_values(kernel.TURNING, taus, cores, k)
    rate = kernel.point_values(kernel.PHI_RATE, taus, cores, k)
    for tau, core, g_turn, g_rate in zip(taus, cores, turning, rate, strict=True):
        abar, d, (x, *_) = period.contact_at(float(tau), core.tolist())
        assert g_turn == pytest.approx((abar * abar - d) ** 2 - abar, rel=1e-13)
        h = 1e-6

        def phi(t: float, abar: float = abar, x: float = x, tau: float = float(tau)) -> float:
            a = abar + x / m.speed_scale * (t - tau)
            return (a * a - (m.base_offset - m.etahat * math.sin(t))) ** 2 / a

        assert g_rate == pytest.approx((phi(tau + h) - phi(tau - h)) / (2 * h), rel=1e-8)


def test_point_in_step_equals_solve_ivp() -> None:
    """From an accepted step's start to a point inside it: the core agrees with solve_ivp's DOP853 at
    rtol 1e-13 to 1e-12 (one short step at rtol 1e-12), and g there is point_values of that core.
    """
    period = orbit_period(20.0)
    k = period.kernel_constants
    run = run_period(period, Integrators("auto", 1e-12), full=False)
    tau_k, tau_end = float(run.taus[10]), float(run.taus[11])
    tau = 0.5 * (tau_k + tau_end)
    core = np.empty(1)
    code, g = kernel.point_in_step(kernel.PHI_RATE, k, tau_k, run.cores[10], tau, 1e-12, 10_000, core)
    reference = solve_ivp(period.core_rhs, (tau_k, tau), run.cores[10], method="DOP853", rtol=1e-13, atol=1e-13)
    assert code == kernel.REACHED
    np.testing.assert_allclose(core, reference.y[:, -1], rtol=1e-12, atol=1e-12)
    assert g == kernel.point_values(kernel.PHI_RATE, np.array([tau]), core[None, :], k)[0]
    same = np.empty(1)
    assert kernel.point_in_step(kernel.TURNING, k, tau_k, run.cores[10], tau_k, 1e-12, 10_000, same)[0] == 0
    assert same[0] == run.cores[10][0]


def test_with_rtol_shares_the_record_and_checks_the_range() -> None:
    integrators = Integrators("auto", 1e-12)
    looser = integrators.with_rtol(1e-9)
    looser.note("numba-dop853")
    assert looser.rtol == 1e-9 and integrators.rtol == 1e-12 and integrators.used == ["numba-dop853"]
    with pytest.raises(ValueError):
        integrators.with_rtol(1e-2)


@pytest.mark.parametrize("h1_um, omega, kept", [(20.0, OMEGA_200HZ, True), (100.0, OMEGA_200HZ, True),
                                                 (100.0, 1e5, False)])
def test_first_period_looser_where_it_decides_the_same(h1_um: float, omega: float, kept: bool) -> None:
    """Where the contact is kept, the first period from the static state runs at rtol 1e-9 and its end
    state agrees with the full-rtol one to its stated margin (1e-5 of the scale; measured <= 8.7e-8);
    where the contact is lost (h1 = 100 um at omega_check 1e5) it is repeated at rtol and equal to it.
    """
    problem = Problem(GentSchultz(N_PUBLISHED), CHI0, h1_um * 1e-6 / RADIUS, omega)
    model = Model(problem, 1e-3)
    start = absolute_start(model, None)
    v_scale = v_scale_estimate(model, float(start[0]))
    first = shooting._first_period(model, start, v_scale, Integrators("auto", 1e-12))
    full = run_period(Period(model, start, v_scale, x_scale(model, start)), Integrators("auto", 1e-12), full=False,
                      transient=True)
    assert math.isnan(first.lost_at) == math.isnan(full.lost_at) == kept
    if kept:
        assert len(first.taus) < len(full.taus)
        assert abs(float(first.y_end[0] - full.y_end[0])) <= 1e-5 * max(1.0, float(np.max(np.abs(full.cores))))
    else:
        assert first.lost_at == full.lost_at and np.array_equal(first.y_end, full.y_end)


def test_point_values_agree_with_the_contact_kernel_speed() -> None:
    """The PHI_RATE value uses x of Eq. (6'): with deltabar' = 0 (etahat cos tau = 0 at tau = pi/2) it is
    Phi_a x / speed_scale, Phi_a = gap (3 abar^2 + deltabar)/abar^2 (closed form of the derivative).
    """
    period = orbit_period(20.0)
    k, m = period.kernel_constants, period.m
    tau, core = math.pi / 2, np.array([0.1])
    abar = period.abar(0.1)
    d = m.base_offset - m.etahat
    x = contact_kernel(abar, d, m.inv_n, m.log_cap)[0]
    gap = abar * abar - d
    expected = gap * (3 * abar * abar + d) / (abar * abar) * x / m.speed_scale
    value = kernel.point_values(kernel.PHI_RATE, np.array([tau]), core[None, :], k)[0]
    assert value == pytest.approx(expected, rel=1e-12)
