"""The envelope derivative of the simulated pull-off in the Gent–Schultz parameters (Sec. 3.4, Eqs. 4-11).

The pull-off is P*(theta) = min over the base offset d of the period-mean force P_m(d, theta), and at the minimiser d*
the mean force is stationary in d, so dP*/dtheta = dP_m/dtheta (d*, theta) at fixed d* (the envelope theorem),
whatever coordinate d is measured in. Each derivative is therefore a central difference in ln theta of two periodic
orbits at the fixed d*, warm-started from the orbit at d* (a few shooting periods each), instead of two re-traced
families. Its error: the central difference O(h^2) (h = :data:`ENVELOPE_STEP`) plus the orbits' error over h
(~1e-10/h). Used by the simulation's fit (:mod:`vibroadhesion.experiments.simulation_fit`), the finite-speed rows
(:mod:`vibroadhesion.experiments.speed_fit`) and the identifiability study.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from vibroadhesion import simulation
from vibroadhesion.core import groups
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import OrbitDiagnostics, SteadyState
from vibroadhesion.experiments.pulloff import GentSchultzParameters

#: Step h in ln theta of the envelope derivative (module docstring: O(h^2) + 1e-10/h, ~1e-6 relative).
ENVELOPE_STEP = 1e-3
#: Shooting periods allowed to an orbit warm-started next to a known one (3-6 suffice, as in a family).
WARM_ITERATIONS = 15

#: The most tensile orbit of a pair's family: (base offset d*, orbit there).
Extremum = tuple[float, SteadyState]


def pulloff_problem(params: GentSchultzParameters, frequency_hz: float, h1_um: float, *, radius: float,
                    reduced_modulus: float, base_offset: float = 0.0) -> Problem:
    """The rigidly fixed problem of one test (Eqs. 4-11): chi0 (Eq. 64), eta1 (Eq. 65), omega_check (Eq. 105)."""
    return Problem(GentSchultz(params.n), groups.chi0(params.w0, reduced_modulus, radius), h1_um * 1e-6 / radius,
                   float(groups.omega_check(frequency_hz, params.v0, radius)), base_offset=base_offset)


def envelope_log_derivatives(params: GentSchultzParameters, frequency_hz: float, h1_um: float, at: Extremum,
                             names: tuple[str, ...], *, radius: float, reduced_modulus: float,
                             step: float = ENVELOPE_STEP) -> np.ndarray:
    """d ln|P_cr| / d ln theta for theta in ``names`` at the pull-off orbit ``at`` (module docstring).

    Central differences in ln theta of the mean force Phat_m of two orbits at the fixed base offset d* of
    ``at``, warm-started from its state (envelope theorem), plus 1 for w0 (|P_cr^JKR| is proportional to w0,
    Eq. 70). Where one shifted orbit does not converge, the one-sided difference with the orbit of ``at``
    (error O(step), ~1e-3 of the derivative); NaN where neither does.
    """
    d_star, orbit = at
    if orbit.orbit is None:
        raise TypeError("the pull-off orbit has no orbit diagnostics")
    derivatives = np.empty(len(names))
    for k, name in enumerate(names):
        plus, minus = (_shifted_phat(params, name, sign * step, frequency_hz, h1_um, at, radius=radius,
                                     reduced_modulus=reduced_modulus) for sign in (1.0, -1.0))
        derivatives[k] = log_difference(plus, minus, orbit.orbit.phat_m, step) + (1.0 if name == "w0" else 0.0)
    return derivatives


def log_difference(plus: float, minus: float, center: float, step: float) -> float:
    """d ln|F|/d ln theta from F at ln theta +- ``step``: central, ln(plus/minus)/(2 step), error O(step^2).

    Where one of them is NaN, the one-sided difference with ``center`` (F at ln theta; error O(step)); NaN where
    both are, or where the two values compared differ in sign (no logarithm).
    """
    pair = ((plus, minus, 2.0 * step) if not (math.isnan(plus) or math.isnan(minus))
            else (plus, center, step) if math.isnan(minus) else (center, minus, step))
    ratio = pair[0] / pair[1]
    return math.log(ratio) / pair[2] if ratio > 0 else math.nan


def shifted(params: GentSchultzParameters, name: str, log_shift: float) -> GentSchultzParameters:
    """``params`` with ``name`` scaled by exp(``log_shift``) (a step in ln theta of Eq. 73's parameters)."""
    return replace(params, **{name: getattr(params, name) * math.exp(log_shift)})


def _shifted_phat(params: GentSchultzParameters, name: str, log_shift: float, frequency_hz: float, h1_um: float,
                  at: Extremum, *, radius: float, reduced_modulus: float) -> float:
    """Phat_m (Eq. 4') of the orbit at the fixed base offset of ``at`` with ``name`` scaled by exp(``log_shift``).

    Warm-started from the orbit of ``at`` with WARM_ITERATIONS periods, then with the shooting's default cap
    (a shooting that stalls next to the pull-off converges then); NaN if neither converges.
    """
    d_star, orbit = at
    problem = pulloff_problem(shifted(params, name, log_shift), frequency_hz, h1_um, radius=radius,
                              reduced_modulus=reduced_modulus, base_offset=d_star)
    state = start_state(orbit)
    found = simulation.steady_state(problem, initial_state=state, max_iterations=WARM_ITERATIONS)
    if not found.ok:
        found = simulation.steady_state(problem, initial_state=state)
    return found.orbit.phat_m if found.ok and found.orbit is not None else math.nan


def start_state(orbit: SteadyState) -> np.ndarray:
    """The state at tau = 0 of a simulated orbit (its diagnostics' ``start_state``)."""
    return diagnostics(orbit).start_state


def diagnostics(orbit: SteadyState) -> OrbitDiagnostics:
    """The orbit diagnostics of a simulated steady state (every simulated record has them)."""
    if orbit.orbit is None:
        raise TypeError("a simulated orbit has diagnostics")
    return orbit.orbit
