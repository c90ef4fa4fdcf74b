"""One period of the full model integrated in scaled variables: the right-hand sides, the integrator choice.

The one-period problem
----------------------
A period lasts 2 pi while the contact relaxes over omega_check c_o / |dx/dabar| periods, so the
steady state is found as a fixed point of the one-period map (:mod:`vibroadhesion.simulation.shooting`),
not by waiting. abar itself changes by only A ~ Abar/(omega_check c_o) per period (1e-7 of a_m at
omega_check = 1e9), so the integrated variable is the front displacement measured from the start
of the period,

    v = omega_check c_o (abar - abar(0)),   dv/dtau = x,

which is O(Abar) and carries full relative precision whatever omega_check is (scaled internally
by its observed half range, floored at a change of abar of 1e-14 abar, and xbar by
max(etahat, |xbar|, |xbar'|), so that one absolute tolerance fits all components). Along with this
core the full problem carries Psi = M - I of the one-period map (its variational equations,
:mod:`vibroadhesion.simulation.shooting`) and the quadratures of the orbit's means and harmonics
(:mod:`vibroadhesion.simulation.orbits`).

Integrators. "auto": a period with the compiled DOP853 of :mod:`vibroadhesion.simulation.kernel`
(a period costs ~100-300 steps of 12 right-hand sides; ~0.1-0.4 ms compiled, ~20 times less than
with the Python right-hand side), the first period from the static state too if rigid with n <= 1
(:class:`Integrators`); where the compiled run gives up, the retries below without the Fortran
DOP853 (the same method and step budget); otherwise, the first period with LSODA (ODEPACK), the periods near the
orbit, not stiff for omega_check >~ 1e3, with the Fortran DOP853 of :class:`scipy.integrate.ode`
(~25 us a step: the Python loop of solve_ivp would cost 4 times more), a period DOP853 gives up on
repeated with LSODA (ODEPACK's steps, switching to BDF where stiff: at n = 4 the periods near the
orbit need more than DOP853's 1e4 steps, and LSODA does them 3.6 times faster than Radau's Python
linear algebra, measured), and with Radau (analytic Jacobian) if LSODA gives up too. The extremes of
a and of Phi are located between accepted steps by Brent's method on re-integrated states.

Known limitation: for n > 1 in the quasi-static regime (omega_check c_o << etahat^(1/n - 1)) the
contact tracks Phi - 1 ~ x^n ~ 1e-9..1e-16, where the speed (Phi - 1)^(1/n) has a relative
rounding noise of 1e-16/|Phi - 1| and an unbounded derivative: no integrator meets the tolerance
and the result is ``integration_failure`` (after ~10^4 steps), not a number.
"""

from __future__ import annotations

import copy
import math
import warnings
from collections.abc import Callable, Sequence
from functools import partial
from typing import Literal, NamedTuple

import numpy as np
from scipy.integrate import BDF, DOP853, LSODA, RK45, Radau, ode

from vibroadhesion.simulation import kernel
from vibroadhesion.simulation.model import TWO_PI, Array, Model, contact_kernel

Integrator = Literal["auto", "fortran-dop853", "Radau", "BDF", "LSODA", "DOP853", "RK45"]
#: A right-hand side f(tau, y) of the scaled problem, and the Jacobian df/dy of one.
RightHandSide = Callable[[float, Array], list[float] | Array]
Jacobian = Callable[[float, Array], Array]
#: A number, or numbers at several points.
Values = float | Array
#: Called after every accepted step with (tau, y); True stops the integration.
StepCallback = Callable[[float, Array], bool]

_FORTRAN = "fortran-dop853"
_COMPILED = "numba-dop853"
_IVP_SOLVERS = {"Radau": Radau, "BDF": BDF, "LSODA": LSODA, "DOP853": DOP853, "RK45": RK45}
_IMPLICIT = ("Radau", "BDF", "LSODA")
#: "auto"'s retries, in order, of a call whose method gives up (module docstring, "Integrators").
_RETRIES = ("LSODA", "Radau")
#: Steps allowed per call: to the Fortran DOP853 (then "auto" repeats the call, _RETRIES) and
#: to the solve_ivp methods (then the integration has failed).
_FORTRAN_MAX_STEPS = 10_000
_IVP_MAX_STEPS = 10_000


#: Quadratures carried after the core and Psi: u, u cos, u sin, sqrt(w/w0), Phat, Phat cos,
#: Phat sin and, when compliant, xi, xi cos, xi sin.
_N_QUAD_RIGID = 7
_N_QUAD_COMPLIANT = 10


def compiled_rhs(constants: Array, size: int, tau: float, y: Array) -> Array:
    """The rates of Eqs. (3'), (6') of the core or of the full state (``size`` components) for scipy's integrators.

    :func:`vibroadhesion.simulation.kernel.state_rates` with the period's ``constants``, into a new array.
    """
    out = np.empty(size)
    kernel.state_rates(tau, y, out, constants)
    return out


class Period:
    """The one-period problem from a start state, in scaled variables.

    Scaled core: u = v/V (rigid) or (xi, eta, u) = (xbar/S, xbar'/S, v/V) (compliant), with
    v = speed_scale (abar - abar(0)); the map coordinate of abar is beta = speed_scale abar / V. The
    right-hand sides are the compiled ones of :mod:`vibroadhesion.simulation.kernel`.
    """

    def __init__(self, model: Model, start: Array, v_scale: float, x_scale: float):
        """The period of ``model`` from the absolute ``start`` with the scales V = ``v_scale``, S = ``x_scale``."""
        self.m = model
        self.start = np.asarray(start, dtype=float)
        self.b0 = model.speed_scale * float(self.start[-1])
        self.v_scale = v_scale
        self.x_scale = x_scale
        self.dim = model.dim
        self.n_var = self.dim * self.dim
        #: The constants of the compiled period (kernel.CONSTANTS).
        self.kernel_constants = np.array([
            self.b0, v_scale, 1.0 / model.speed_scale, 1.0 / v_scale, model.base_offset, model.etahat, model.inv_n,
            model.log_cap, 1.0 if model.variational else 0.0, 1.0 if model.compliant else 0.0,
            *self._spring_constants(), 0.0, *kernel.CONSTANT_EXCITATION])  # no withdrawal ramp: a periodic problem
        full_size = kernel.COMPLIANT_FULL_SIZE if model.compliant else kernel.FULL_SIZE
        self.core_rhs: RightHandSide = partial(compiled_rhs, self.kernel_constants, self.dim)
        self.full_rhs: RightHandSide = partial(compiled_rhs, self.kernel_constants, full_size)

    def _spring_constants(self) -> list[float]:
        """S, mu/(kappa c_o^2)/S, (c_o/kappa)/S, 1/omega_bar^2, 2 zeta omega_bar, c_o/kappa, fhat/S (Eqs. 3', 13).

        Zeros if rigid.
        """
        m = self.m
        if not m.compliant:
            return [0.0] * 7
        return [self.x_scale, m.force_offset / self.x_scale, m.compliance / self.x_scale, 1.0 / m.omega_bar**2,
                2.0 * m.zeta * m.omega_bar, m.compliance, m.force_drive / self.x_scale]

    # -- conversions

    def abar(self, u: float) -> float:
        """The contact radius at the scaled front displacement u, from V u = v = speed_scale (abar - a0) (Eq. 6')."""
        return (self.b0 + self.v_scale * u) / self.m.speed_scale

    def core_start(self) -> list[float]:
        """Scaled core at tau = 0: (xbar/S, xbar'/S, 0) or (0,) (v starts at 0)."""
        if self.m.compliant:
            return [self.start[0] / self.x_scale, self.start[1] / self.x_scale, 0.0]
        return [0.0]

    def full_start(self) -> list[float]:
        """Scaled core, Psi = 0 and the quadratures (all 0) at tau = 0 (shooting module, Psi(0) = 0)."""
        n_quad = _N_QUAD_COMPLIANT if self.m.compliant else _N_QUAD_RIGID
        return self.core_start() + [0.0] * (self.n_var + n_quad)

    def absolute(self, core: Sequence[float]) -> Array:
        """Absolute state (xbar, xbar', abar) or (abar,) from the scaled core."""
        if self.m.compliant:
            return np.array([core[0] * self.x_scale, core[1] * self.x_scale, self.abar(core[2])])
        return np.array([self.abar(core[0])])

    def contact_at(self, tau: float, core: Sequence[float]) -> tuple[float, float, tuple[float, ...]]:
        """(abar, deltabar, contact_kernel(...)) at a point of the period."""
        m = self.m
        abar = self.abar(core[-1])
        d = m.base_offset - m.etahat * math.sin(tau)
        if m.compliant:
            d += core[0] * self.x_scale
        return abar, d, contact_kernel(abar, d, m.inv_n, m.log_cap)

    def deltabar_rate(self, tau: Values, core: Sequence[Values]) -> Values:
        """d deltabar / d tau at a point (floats) or at points (arrays: ``core`` the components' arrays)."""
        rate = -self.m.etahat * np.cos(tau)
        return rate + core[1] * self.x_scale if self.m.compliant else rate

    # -- Jacobians (for the implicit integrators)

    def core_jacobian(self, tau: float, y: Array) -> Array:
        """Jacobian of the scaled core right-hand side (the J of the variational equations)."""
        abar, d, (_, x_a, x_d, _, _) = self.contact_at(tau, y.tolist()[: self.dim])
        j10, j11, j12, j20, j22 = self._jacobian_entries(abar, d, x_a, x_d)
        if not self.m.compliant:
            return np.array([[j22]])
        return np.array([[0.0, 1.0, 0.0], [j10, j11, j12], [j20, 0.0, j22]])

    def _jacobian_entries(self, abar: float, d: float, x_a: float, x_d: float) -> tuple[float, ...]:
        """Non-trivial entries (j10, j11, j12, j20, j22) of J in the scaled coordinates (xi, eta, beta).

        Unscaled, in (xbar, xbar', b): row xbar'' = [-(1 + (c_o/kappa) dPhat/ddeltabar), -2 zeta omega_bar,
        -(c_o/kappa) dPhat/dabar / speed_scale] / omega_bar^2 and row v' = [dx/ddeltabar, 0,
        dx/dabar / speed_scale]; the scaling multiplies entry (i, j) by scale_j / scale_i (scales S, S, V).
        """
        m = self.m
        j22 = x_a / m.speed_scale
        if not m.compliant:
            return 0.0, 0.0, 0.0, 0.0, j22
        inv_w2 = 1.0 / m.omega_bar**2
        return (
            (-1.0 - 2.0 * m.compliance * abar) * inv_w2,
            -2.0 * m.zeta / m.omega_bar,
            -m.compliance * (2.0 * d - 2.0 * abar * abar) * inv_w2 * self.v_scale / (m.speed_scale * self.x_scale),
            x_d * self.x_scale / self.v_scale,
            j22,
        )

    def full_jacobian(self, tau: float, y: Array) -> Array:
        """Block-diagonal part of the full Jacobian: J for the core, I (x) J for Psi.

        The one-way couplings of the core into Psi (second derivatives) and into the quadratures
        are left out: the implicit methods use the Jacobian only in the Newton iterations of
        their stages, which the driven components do not slow down.
        """
        core_j = self.core_jacobian(tau, y)
        size = len(self.full_start())
        jac = np.zeros((size, size))
        dim = self.dim
        jac[:dim, :dim] = core_j
        if self.m.compliant:
            jac[dim : dim + 9, dim : dim + 9] = np.kron(core_j, np.eye(3))
        return jac

    # -- right-hand sides


# --- Integration drivers --------------------------------------------------------------------------


class IntegrationError(RuntimeError):
    """An integrator gave up (step size underflow, step budget, stiffness detected)."""


def _fortran_solout(on_step: StepCallback, tau: float, y: Array) -> int:
    """``on_step`` in the convention of the Fortran DOP853's solout: -1 stops the integration."""
    return -1 if on_step(tau, y) else 0


def _integrate(
    fun: RightHandSide,
    jac: Jacobian,
    tau0: float,
    y0: Sequence[float],
    tau1: float,
    integrator: str,
    rtol: float,
    on_step: StepCallback | None = None,
) -> tuple[float, Array, bool]:
    """Integrate from tau0 to tau1; ``on_step(tau, y)`` after every accepted step may stop it.

    The state is scaled to O(1), so one absolute tolerance equal to ``rtol`` serves all
    components. ``jac`` is given to the implicit methods. Returns (tau reached, y there, stopped
    by on_step); raises :class:`IntegrationError` when the integrator gives up.
    """
    if integrator == _FORTRAN:
        solver = ode(fun).set_integrator("dop853", rtol=rtol, atol=rtol, nsteps=_FORTRAN_MAX_STEPS)
        if on_step is not None:
            solver.set_solout(partial(_fortran_solout, on_step))
        solver.set_initial_value(list(y0), tau0)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # failures are read from the return code
            y = solver.integrate(tau1)
        code = solver.get_return_code()
        if code < 0:
            raise IntegrationError(f"Fortran DOP853 return code {code}")
        return float(solver.t), np.array(y), code == 2
    solver_class = _IVP_SOLVERS[integrator]
    options = {"jac": jac} if integrator in _IMPLICIT else {}
    solver = solver_class(fun, tau0, np.array(y0, dtype=float), tau1, rtol=rtol, atol=rtol, **options)
    if on_step is not None and on_step(tau0, solver.y):
        return tau0, solver.y.copy(), True
    for _ in range(_IVP_MAX_STEPS):
        if solver.status != "running":
            break
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # LSODA's messages: failures are read from the status
            message = solver.step()
        if solver.status == "failed":
            raise IntegrationError(f"{integrator}: {message}")
        if on_step is not None and on_step(solver.t, solver.y):
            return float(solver.t), solver.y.copy(), True
    else:
        raise IntegrationError(f"{integrator}: more than {_IVP_MAX_STEPS} steps")
    return float(solver.t), solver.y.copy(), False


class Run(NamedTuple):
    """One integrated period: accepted steps (tau, scaled core) for the refinements."""

    period: Period
    lost_at: float  # tau of contact loss, NaN if none
    y_end: Array
    taus: Array  # accepted steps, the start first (the step of a contact loss left out)
    cores: Array  # (steps, dim): the scaled core at those steps
    u_range: tuple[float, float]


class Integrators:
    """Which integrator runs what.

    "auto": the transient from the static state (stiff while the base stroke forces the contact
    to grow: the front then slides along Phi ~ 0 at a huge closing speed) with LSODA,
    which switches to BDF there; the periods near the orbit, which are not stiff for
    omega_check >~ 1e3, with the Fortran DOP853; a run that DOP853 gives up on is repeated with
    LSODA, and with Radau if that gives up too (``_RETRIES``). A period near the orbit runs first with
    the compiled DOP853 of :mod:`vibroadhesion.simulation.kernel`, and with the methods above only if that gives up
    (then without the Fortran DOP853, the same method and step budget, which would give up too); so
    does a transient period of the rigid fixation with n <= 1 (within ~2e3 steps). Transients stay
    with LSODA for n > 1 (stiff first periods of 2e4 to more than 2e5 explicit steps) and for the
    compliant fixation (there the compiled DOP853's end state jumps by ~1e-9 between neighbouring
    starts as its step count changes, which spoils differences of transients such as the
    finite-difference monodromy). Any other name runs everything.
    """

    def __init__(self, integrator: Integrator, rtol: float):
        """Checks the name and ``rtol`` (in [1e-13, 1e-3]); records the methods that ran in ``used``."""
        if integrator != "auto" and integrator != _FORTRAN and integrator not in _IVP_SOLVERS:
            raise ValueError(f"unknown integrator {integrator!r}")
        if not (1e-13 <= rtol <= 1e-3):
            raise ValueError(f"rtol must lie in [1e-13, 1e-3], got {rtol}")
        self.auto = integrator == "auto"
        self.orbit = _FORTRAN if self.auto else integrator
        self.transient = "LSODA" if self.auto else integrator
        self.rtol = rtol
        self.used: list[str] = []

    def with_rtol(self, rtol: float) -> Integrators:
        """The same methods at another ``rtol`` (in [1e-13, 1e-3]), recording into the same ``used``."""
        if not (1e-13 <= rtol <= 1e-3):
            raise ValueError(f"rtol must lie in [1e-13, 1e-3], got {rtol}")
        other = copy.copy(self)
        other.rtol = rtol
        return other

    def compiles(self, period: Period, transient: bool = False) -> bool:
        """Whether ``period`` runs with the compiled DOP853 ("auto"; a transient only if rigid with n <= 1)."""
        return self.auto and (not transient or (period.m.variational and not period.m.compliant))

    def note(self, method: str) -> None:
        """Record that ``method`` ran."""
        if method not in self.used:
            self.used.append(method)

    def run(
        self,
        fun: RightHandSide,
        jac: Jacobian,
        tau0: float,
        y0: Sequence[float],
        tau1: float,
        on_step: StepCallback | None = None,
        transient: bool = False,
        compiled_gave_up: bool = False,
    ) -> tuple[float, Array, bool]:
        """:func:`_integrate` with the orbit's (or, ``transient``, the transient's) method; "auto" retries (_RETRIES).

        Returns (tau reached, y there, stopped by ``on_step``) and raises :class:`IntegrationError`
        when the (last) method gives up. ``compiled_gave_up``: the compiled DOP853 gave up on this call,
        so the Fortran DOP853, the same method with the same step budget, is skipped (at n = 4 it gave up
        on all 52 such periods of a virtual pull-off, 20 s of 63).
        """
        first = self.transient if transient else self.orbit
        methods = [first, *(m for m in _RETRIES if m != first)] if self.auto else [first]
        if compiled_gave_up and len(methods) > 1:
            methods = [m for m in methods if m != _FORTRAN]
        for method in methods[:-1]:
            try:
                result = _integrate(fun, jac, tau0, y0, tau1, method, self.rtol, on_step)
            except IntegrationError:
                continue
            self.note(method)
            return result
        result = _integrate(fun, jac, tau0, y0, tau1, methods[-1], self.rtol, on_step)
        self.note(methods[-1])
        return result

    def description(self) -> str:
        """The methods that ran, in order of first use, joined by "+" (e.g. "LSODA+fortran-dop853")."""
        return "+".join(self.used)


class _StepRecorder:
    """The ``on_step`` of a period: records accepted steps (tau, scaled core), stops at contact loss.

    Contact is lost when abar falls below ``contact_loss_abar`` (model docstring). One recorder
    serves a period's attempts: after a retry (LSODA, Radau), steps are appended only past the last
    one recorded.
    """

    def __init__(self, period: Period):
        self.period = period
        self.dim, self.loss = period.dim, period.m.contact_loss_abar
        self.steps: list[tuple[float, list[float]]] = []
        self.lost_at = math.nan

    def __call__(self, tau: float, y: Array) -> bool:
        core = y[: self.dim].tolist()
        if self.period.abar(core[-1]) < self.loss:
            self.lost_at = tau
            return True
        if not self.steps or tau > self.steps[-1][0]:
            self.steps.append((tau, core))
        return False


def _compiled_run(period: Period, integrators: Integrators, y0: Sequence[float], tau0: float, tau1: float,
                  loss_abar: float) -> kernel.KernelRun | None:
    """:func:`kernel.integrate` of ``period`` (Eq. 6'; None when it gives up: the caller takes the scipy path)."""
    result = kernel.integrate(period.kernel_constants, np.asarray(y0, dtype=float), tau0, tau1, integrators.rtol,
                              _FORTRAN_MAX_STEPS, loss_abar)
    if result.code < 0:
        return None
    integrators.note(_COMPILED)
    return result


def integrate_core(period: Period, integrators: Integrators, tau0: float, core0: Sequence[float],
                   tau1: float) -> list[float]:
    """The scaled core at ``tau1`` from ``core0`` at ``tau0`` (Eqs. 3', 6'; compiled if it can; no loss stop)."""
    if integrators.compiles(period):
        result = _compiled_run(period, integrators, core0, tau0, tau1, -math.inf)
        if result is not None:
            return result.y.tolist()
    return integrators.run(period.core_rhs, period.core_jacobian, tau0, core0, tau1,
                           compiled_gave_up=integrators.compiles(period))[1].tolist()


def run_period(period: Period, integrators: Integrators, full: bool, transient: bool = False) -> Run:
    """Integrate one period, stopping at contact loss; records accepted steps and the range of u."""
    y0 = period.full_start() if full else period.core_start()
    if integrators.compiles(period, transient):
        result = _compiled_run(period, integrators, y0, 0.0, TWO_PI, period.m.contact_loss_abar)
        if result is not None:
            kept = len(result.taus) - 1 if result.code == kernel.CONTACT_LOST else len(result.taus)
            lost_at = result.tau if kept < len(result.taus) else math.nan
            cores = result.cores[:kept]
            return Run(period, lost_at, result.y, result.taus[:kept], cores,
                       (float(cores[:, -1].min()), float(cores[:, -1].max())))
    recorder = _StepRecorder(period)
    fun, jac = (period.full_rhs, period.full_jacobian) if full else (period.core_rhs, period.core_jacobian)
    _, y_end, _ = integrators.run(fun, jac, 0.0, y0, TWO_PI, recorder, transient,
                                  compiled_gave_up=integrators.compiles(period, transient))
    cores = np.array([core for _, core in recorder.steps])
    return Run(period, recorder.lost_at, y_end, np.array([tau for tau, _ in recorder.steps]), cores,
               (float(cores[:, -1].min()), float(cores[:, -1].max())))
