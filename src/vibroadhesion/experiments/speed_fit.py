"""The withdrawal speed as fit input: the full model's pull-off of a test withdrawn at a finite speed (issue 15).

A row of ``data/pulloff.csv`` with a withdrawal speed V > 0 (column ``withdrawal_speed_um_s``, um/s) is predicted
by the time-domain withdrawal of the rigidly fixed indenter at that speed
(:func:`vibroadhesion.simulation.withdrawal.withdraw`, Eq. 11' there: the base offset ramped at V from the
vibrating steady state at the preloaded start offset of
:func:`vibroadhesion.experiments.speed_sweep.start_problem`), with its default method. The fitted quantity is the
dynamic pull-off read as a load cell averaging over a period records it: the most tensile one-period mean of the
contact force (Eq. 4'), |P| = -mean_force/|Phat_JKR| |P_cr^JKR| (Eq. 70). It is the reading whose V -> 0 limit is
the quasi-static value the rows without a speed are fitted to (the most tensile mean force of the family of
periodic steady states, :mod:`vibroadhesion.experiments.simulation_fit`; the difference falls as O(V),
:mod:`vibroadhesion.experiments.speed_sweep`). Rows at the same (frequency, h1, V) are solved once
(:class:`~vibroadhesion.experiments.simulation_fit._Families` keys them (f, h1, V)) and scattered to the replicates.

Status. ``pulloff`` (the period-mean force passed a tensile minimum before the contact was lost) is a pull-off.
``detached_before_mean_extremum`` (contact lost first: the instantaneous numbers, no steady-state counterpart),
``not_detached``, ``integration_failure`` and ``no_start_state`` (no steady state at the start offset) are not:
like a family without a pull-off, such a row keeps in the search the most tensile period mean it reached (NaN
without one) and is counted as zero force (residual -1) in the stated fit, named in ``row_status``.

Jacobian. No envelope theorem applies to a time-domain run, so d ln|P|/d ln theta is a central difference in
ln theta with step h = :data:`SPEED_STEP` of two withdrawals at the shifted parameters (one-sided with the
unshifted run where one of them has no reading). Its error, measured at 200 Hz, 20 um, V = 3 v0 (85 periods,
the fewest of the test conditions) on grids of 41 points over +-0.02 in ln w0, ln n and ln v0:

* truncation h^2 |d^3 ln P/d ln theta^3|/6: the second differences of ln P drift by at most 0.25 over 0.04
  (ln n; 0.02 for w0 and v0), so |d^3| <= 7 and the truncation is <= 1.2e-4 at h = 1e-2;
* the reading is a parabola through three period means, which jumps by up to 6e-6 in ln P where the period of
  the extremum moves to the next one (every ~0.015 in ln n, rarer in w0 and v0); a jump between the two runs
  costs jump/(2h) <= 3e-4 at h = 1e-2 (3e-3 at h = 1e-3: the larger step is the better one);
* the integration: :data:`FIT_RTOL` = 1e-9 leaves the reading within 2e-8 relative of a run at rtol 1e-11
  (measured at 200 and 400 Hz, 20 and 100 um, V = v0 and 3 v0), i.e. <= 2e-6 in the difference at h = 1e-2.

The bound is therefore 4.2e-4 absolute in d ln P/d ln theta (measured against the slope of a cubic fitted to
ln P on 17 points over +-0.04: 1.5e-4, 2e-5 and 9e-5 for w0, n, v0; tests/experiments/test_speed_fit.py). It
steers the search only: the fit is where the residuals, not the Jacobian, are least.

The asymptotic levels (leading, refined, exact averaging) are quasi-static models: :mod:`fitting` fits them to a
speed row as if V -> 0, and the fit page says so.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from vibroadhesion import simulation
from vibroadhesion.core.groups import PHAT_JKR
from vibroadhesion.experiments.envelope import log_difference, pulloff_problem, shifted
from vibroadhesion.experiments.pulloff import GentSchultzParameters, jkr_mN
from vibroadhesion.experiments.speed_sweep import start_problem
from vibroadhesion.simulation.withdrawal import withdraw

#: Integration tolerance of a fitted withdrawal (module docstring: reading within 2e-8 of rtol 1e-11).
FIT_RTOL = 1e-9
#: Step h in ln theta of the central differences (module docstring: error <= 4.2e-4 in d ln P/d ln theta).
SPEED_STEP = 1e-2


class SpeedPulloff(NamedTuple):
    """The dynamic pull-off of one test at a withdrawal speed (module docstring)."""

    status: str  # the withdrawal's status, or no_start_state
    force_mN: float  # -(most tensile one-period mean force) in mN: |P| where tensile; NaN without a reading
    periods: int  # periods integrated


def speed_pulloff(params: GentSchultzParameters, frequency_hz: float, h1_um: float, speed_um_s: float, *,
                  radius: float, reduced_modulus: float) -> SpeedPulloff:
    """The period-mean dynamic pull-off of a rigid test withdrawn at ``speed_um_s`` (Eqs. 4', 11', 70).

    V/v0 = ``speed_um_s`` 1e-6/v0 (Eq. 73's v0): v0 enters through it as well as through omega_check (Eq. 105).
    """
    problem = start_problem(pulloff_problem(params, frequency_hz, h1_um, radius=radius,
                                            reduced_modulus=reduced_modulus))
    steady = simulation.steady_state(problem)
    if not steady.ok or steady.orbit is None:
        return SpeedPulloff("no_start_state", math.nan, 0)
    run = withdraw(problem, speed_um_s * 1e-6 / params.v0, initial_state=steady.orbit.start_state, rtol=FIT_RTOL)
    return SpeedPulloff(run.status, -run.mean_force / abs(PHAT_JKR) * jkr_mN(params.w0, radius), run.periods)


def speed_log_derivative(params: GentSchultzParameters, frequency_hz: float, h1_um: float, speed_um_s: float,
                         name: str, center_mN: float, *, radius: float, reduced_modulus: float,
                         step: float = SPEED_STEP) -> float:
    """d ln|P|/d ln ``name`` of :func:`speed_pulloff` by central differences (module docstring, Eq. 70's w0 included).

    ``center_mN``: the reading at ``params`` (for the one-sided difference); NaN where neither shifted run has one.
    """
    plus, minus = (speed_pulloff(shifted(params, name, sign * step), frequency_hz, h1_um, speed_um_s, radius=radius,
                                 reduced_modulus=reduced_modulus).force_mN for sign in (1.0, -1.0))
    return log_difference(plus, minus, center_mN, step)

