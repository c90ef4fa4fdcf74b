"""The compiled period (vibroadhesion.simulation.kernel) against scipy's integrators.

References:
* the uncompiled :func:`vibroadhesion.simulation.model.contact_kernel` (itself checked against the
  dimensional JKR formulas in test_simulate.py) for the compiled right-hand side;
* :func:`scipy.integrate.solve_ivp` with DOP853 (the method whose coefficients and step control the
  kernel implements) for one period;
* the whole shooting with scipy's Fortran DOP853 at the tighter rtol 1e-13 for the steady states of
  the paper's 200 Hz test (omega_check of v0 = 44.5 um/s, R = 51.5 mm), rigid and compliant.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import CHI0, N_PUBLISHED, NU0, RADIUS, V0
from scipy.integrate import solve_ivp

from vibroadhesion import simulation as sim
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import omega_check
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.simulation import kernel
from vibroadhesion.simulation.integrators import Integrators, Period
from vibroadhesion.simulation.model import Model, absolute_start, contact_kernel
from vibroadhesion.simulation.scales import v_scale_estimate, x_scale

OMEGA_200HZ = float(omega_check(200.0, V0, RADIUS))
FIELDS = ("abar_m", "Abar", "w_eff_ratio", "pm_over_abs_pjkr")


def rigid(h1_um: float, omega: float = OMEGA_200HZ, n: float = N_PUBLISHED) -> Problem:
    return Problem(GentSchultz(n), CHI0, h1_um * 1e-6 / RADIUS, omega)


def static_period(problem: Problem) -> Period:
    model = Model(problem, 1e-3)
    start = absolute_start(model, None)
    return Period(model, start, v_scale_estimate(model, float(start[-1])), x_scale(model, start))


@pytest.mark.parametrize("abar, deltabar", [(1.3, 0.2), (1.3, -0.9), (2.7, 5.0), (0.8, -0.05), (1.0, 1.0)])
def test_compiled_rates_equal_the_contact_kernel(abar: float, deltabar: float) -> None:
    """The compiled rates are Eq. (6') of the Python kernel: the same double operations, so equal to
    1e-14 relative (log and exp of libm and of LLVM may differ in the last bits, amplified by 1/n < 2).
    """
    n, etahat, tau = 0.531, 0.7, 0.4
    problem = Problem(GentSchultz(n), CHI0, etahat * 1.0, 1e6)
    period = static_period(problem)
    k = period.kernel_constants.copy()
    k[4], k[5] = deltabar + etahat * math.sin(tau), etahat  # base_offset so that deltabar(tau) = deltabar
    k[0] = abar / k[2]  # b0 with u = 0: abar = b0 / speed_scale
    out = np.empty(kernel.FULL_SIZE)
    kernel.state_rates(tau, np.zeros(kernel.FULL_SIZE), out, k)
    x, x_a, _, p, w = contact_kernel(abar, deltabar, 1.0 / n, k[7])
    expected = [x * k[3], x_a * k[2], 0.0, 0.0, 0.0, w, p, p * math.cos(tau), p * math.sin(tau)]
    assert out.tolist() == pytest.approx(expected, rel=1e-14, abs=0.0)


@pytest.mark.parametrize("h1_um", [20.0, 100.0])
def test_compiled_period_equals_scipy_dop853(h1_um: float) -> None:
    """A period from the orbit's start. solve_ivp's DOP853 is the same method and step control, so it
    takes about the same number of steps at the same rtol: within 2 % (the error norms differ in the
    first steps from the initial step 1e-4, where the compiled run grows the step by the full factor 10
    and solve_ivp by 8.9-9.9, and rounding decides some acceptances; 299 against 296 steps measured at
    100 um, a count that moves when the orbit's start moves by rounding);
    at the tighter rtol 1e-13 it is the reference for the end state, which the kernel at 1e-12 meets to
    1e-10 in each component (relative, absolute for the O(1) scaled u: 100 rtol, where each run's
    global error is ~10 rtol per period). (From the static state the stiff first phase makes the
    period uncertain to ~1e-8 at rtol 1e-12, even for solve_ivp against itself at 1e-13.)
    """
    problem = rigid(h1_um)
    model = Model(problem, 1e-3)
    start = sim.steady_state(problem).orbit.start_state
    period = Period(model, start, v_scale_estimate(model, float(start[0])), 1.0)
    y0 = np.array(period.full_start())
    ours = kernel.integrate(period.kernel_constants, y0, 0.0, 2 * math.pi, 1e-12, 10_000, 1e-3)
    same = solve_ivp(period.full_rhs, (0.0, 2 * math.pi), y0, method="DOP853", rtol=1e-12, atol=1e-12)
    tight = solve_ivp(period.full_rhs, (0.0, 2 * math.pi), y0, method="DOP853", rtol=1e-13, atol=1e-13)
    assert ours.code == kernel.REACHED and same.success and tight.success
    assert abs(len(ours.taus) - len(same.t)) <= 0.02 * len(same.t)
    np.testing.assert_allclose(ours.y, tight.y[:, -1], rtol=1e-10, atol=1e-10)


def test_kernel_return_codes() -> None:
    """A step budget that is too small and a contact-loss threshold above abar(0) end the run with their codes."""
    period = static_period(rigid(20.0))
    y0 = np.array(period.core_start())
    budget = kernel.integrate(period.kernel_constants, y0, 0.0, 2 * math.pi, 1e-12, 3, 1e-3)
    assert budget.code == kernel.STEP_BUDGET and len(budget.taus) == 4
    lost = kernel.integrate(period.kernel_constants, y0, 0.0, 2 * math.pi, 1e-12, 10_000, 10.0)
    assert lost.code == kernel.CONTACT_LOST and len(lost.taus) == 2 and lost.tau == lost.taus[-1] > 0


@pytest.mark.parametrize("h1_um", [20.0, 60.0, 100.0])
def test_compiled_steady_state_equals_tighter_fortran_shooting(h1_um: float) -> None:
    """Reference: the shooting with scipy's Fortran DOP853 at rtol 1e-13 (Python right-hand side). The
    fixed point carries the period's global error (~10 rtol of the scaled state) divided by
    1 - multiplier (>= 0.11 here): below 1e-9 relative for a_m, Abar, w_eff/w0 and Pm.
    """
    problem = rigid(h1_um)
    ours = sim.steady_state(problem)
    ref = sim.steady_state(problem, integrator="fortran-dop853", rtol=1e-13)
    assert ours.status == ref.status == "ok"
    assert ours.orbit.integrator == "numba-dop853" and ref.orbit.integrator == "fortran-dop853"
    for field in FIELDS:
        assert float(getattr(ours, field)) == pytest.approx(float(getattr(ref, field)), rel=1e-9), field


@pytest.mark.parametrize("h1_um", [20.0, 100.0])
def test_compiled_compliant_steady_state_equals_tighter_fortran_shooting(h1_um: float) -> None:
    """The compliant fixation the validation simulates (kappa = 0.001, zeta = 0.01, data/setup.yaml) at
    200 Hz. Reference: the shooting with scipy's Fortran DOP853 at rtol 1e-13; the largest multiplier
    is <= 0.97 here, so the fixed point carries <= 30 times the period's ~10 rtol: 1e-9 relative.
    """
    problem = Problem(GentSchultz(N_PUBLISHED), CHI0, h1_um * 1e-6 / RADIUS, OMEGA_200HZ,
                      Fixation.compliant(0.001, 0.01, NU0))
    ours = sim.steady_state(problem)
    ref = sim.steady_state(problem, integrator="fortran-dop853", rtol=1e-13)
    assert ours.status == ref.status == "ok" and ours.orbit.integrator == "LSODA+numba-dop853"
    assert np.max(np.abs(ref.orbit.floquet_multipliers)) <= 0.97
    for field in FIELDS:
        assert float(getattr(ours, field)) == pytest.approx(float(getattr(ref, field)), rel=1e-9), field


def test_compiled_path_for_auto_and_the_transient_if_rigid_with_n_at_most_one() -> None:
    """The compiled DOP853 is the "auto" choice for every period near the orbit; the first period stays with
    LSODA for n > 1 and for the compliant fixation.
    """
    soft, hard = static_period(rigid(20.0)), static_period(rigid(20.0, n=4.0))
    spring = static_period(Problem(GentSchultz(N_PUBLISHED), CHI0, 20e-6 / RADIUS, OMEGA_200HZ,
                                   Fixation.compliant(0.001, 0.01, NU0)))
    auto, named = Integrators("auto", 1e-12), Integrators("fortran-dop853", 1e-12)
    assert auto.compiles(soft) and auto.compiles(soft, transient=True)
    assert auto.compiles(hard) and not auto.compiles(hard, transient=True)
    assert auto.compiles(spring) and not auto.compiles(spring, transient=True)
    assert not named.compiles(soft)
