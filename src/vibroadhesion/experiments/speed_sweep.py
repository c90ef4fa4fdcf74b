"""Simulated pull-off against withdrawal speed (issue 15): the time-domain withdrawal next to the quasi-static family.

For one test (frequency, base amplitude h1, fixation) the base is withdrawn at speeds V = ``speed_ratio`` v0
(:func:`vibroadhesion.simulation.withdrawal.withdraw`, Eq. 11' there) from the vibrating steady state at
a compressive start: for the rigid fixation base_offset = etahat (the preloaded start of
:func:`vibroadhesion.experiments.virtual_pulloff.preloaded_offset`, where the contact survives any rate
law), for the compliant one the nominal point contact (base_offset = 0, Eq. 78), the start of the
quasi-static family there. Each row gives

* ``peak_pulloff_ratio``: the most tensile load-cell force over the withdrawal, over |P_JKR| (Eq. 70):
  what an instrument sampling faster than the excitation records;
* ``mean_pulloff_ratio``: the most tensile one-period mean of the load-cell force, over |P_JKR|: what a
  load cell averaging over a period records, and the quantity whose V -> 0 limit is the quasi-static
  family value ``quasi_static_ratio`` (the most tensile mean force of the periodic steady states,
  :func:`vibroadhesion.experiments.virtual_pulloff.simulated_pulloff`); measured at 200 Hz, 20 um,
  rigid, the difference falls as O(V) (tests/simulation/test_withdrawal.py);
* ``relative_deviation`` = mean_pulloff_ratio/quasi_static_ratio - 1;
* the status of the withdrawal (``pulloff``, ``detached_before_mean_extremum``: the contact was lost before
  the period-mean force passed its extremum, the numbers being the instantaneous ones; ``not_detached``,
  ``integration_failure``; ``no_start_state`` when the steady state at the start does not converge),
  ``method`` = ``time_domain`` (every point here is integrated in time) and the periods integrated.

All of it is simulated (``source`` = ``simulated``). :func:`quasi_static_limits` gives, per test, the
largest speed below which every simulated speed keeps the period-mean pull-off within 1 % (5 %) of the
quasi-static value, interpolated in log V between the neighbouring simulated speeds.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd

from vibroadhesion import simulation
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import PHAT_JKR
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.virtual_pulloff import preloaded_offset, simulated_pulloff
from vibroadhesion.simulation.withdrawal import withdraw

COLUMNS = ["source", "fixation", "frequency_hz", "h1_um", "V_over_v0", "V_um_s", "method", "status",
           "peak_pulloff_ratio", "mean_pulloff_ratio", "quasi_static_ratio", "relative_deviation", "base_offset",
           "tau_pulloff", "tau_detached", "periods", "steps"]
#: Integration tolerance of the sweep: against rtol 1e-13 the pull-off force (peak and period mean) agrees to
#: 3e-11 relative at 400 Hz, 100 um, rigid, V = v0, and to 1e-8 at 200 Hz, 20 um, compliant, V = 3 v0 (measured;
#: tests/simulation/test_withdrawal.py bounds it by 1e-6 at 200 Hz), at a third of the steps of rtol 1e-13.
SWEEP_RTOL = 1e-9
#: Tolerances of the quasi-static estimate reported by :func:`quasi_static_limits`.
TOLERANCES = (0.01, 0.05)


def start_problem(problem: Problem) -> Problem:
    """The problem at the withdrawal's start offset (module docstring): etahat if rigid, 0 if compliant (Eq. 78)."""
    return replace(problem, base_offset=preloaded_offset(problem) if problem.fixation.is_rigid else 0.0)


def _quasi_static_ratio(problem: Problem) -> float:
    """P_cr/|P_JKR| of the family of steady states (Eq. 4' mean force, Eq. 70), NaN without a tensile extremum."""
    family = simulated_pulloff(replace(problem, base_offset=0.0))
    return float(family.pulloff_ratio) if str(family.status) == "pulloff" else math.nan


def speed_rows(problem: Problem, speed_ratios: Sequence[float], v0_um_s: float) -> list[dict[str, Any]]:
    """Rows of :data:`COLUMNS` (without the test's identifying columns) for one test at each V/v0 (Eq. 11')."""
    start = start_problem(problem)
    steady = simulation.steady_state(start)
    quasi_static = _quasi_static_ratio(problem)
    rows = []
    for ratio in speed_ratios:
        row: dict[str, Any] = {"V_over_v0": ratio, "V_um_s": ratio * v0_um_s, "method": "time_domain",
                               "quasi_static_ratio": quasi_static}
        if not steady.ok or steady.orbit is None:
            rows.append({**row, "status": "no_start_state"})
            continue
        run = withdraw(start, ratio, initial_state=steady.orbit.start_state, rtol=SWEEP_RTOL)
        mean = -run.mean_force / abs(PHAT_JKR)
        rows.append({**row, "status": run.status, "peak_pulloff_ratio": -run.force / abs(PHAT_JKR),
                     "mean_pulloff_ratio": mean, "relative_deviation": mean / quasi_static - 1.0,
                     "base_offset": run.base_offset, "tau_pulloff": run.tau, "tau_detached": run.tau_detached,
                     "periods": run.periods, "steps": run.steps})
    return rows


def sweep_table(problems: Sequence[tuple[float, Problem]], speed_ratios: Sequence[float], *, fixation_name: str,
                frequency_hz: float, v0_um_s: float) -> pd.DataFrame:
    """The speed sweep of the tests ``problems`` = [(h1 in um, problem)] at one frequency and fixation (simulated)."""
    rows = [{**row, "h1_um": h1} for h1, problem in problems for row in speed_rows(problem, speed_ratios, v0_um_s)]
    table = pd.DataFrame(rows).assign(source="simulated", fixation=fixation_name, frequency_hz=frequency_hz)
    return table.reindex(columns=COLUMNS)


def _limit(speeds: np.ndarray, deviation: np.ndarray, tolerance: float) -> tuple[float, str]:
    """Largest V/v0 below which every simulated speed is within ``tolerance`` (log-interpolated), and a note."""
    inside = np.abs(deviation) <= tolerance
    if not inside[0]:
        return math.nan, f"not within {100 * tolerance:g} % even at the slowest simulated speed {speeds[0]:g} v0"
    if inside.all():
        return math.nan, f"within {100 * tolerance:g} % up to the fastest simulated speed {speeds[-1]:g} v0"
    k = int(np.argmin(inside))  # first speed outside
    lo, hi = np.log(speeds[k - 1]), np.log(speeds[k])
    d_lo, d_hi = math.log(abs(deviation[k - 1]) or 1e-300), math.log(abs(deviation[k]))
    at = lo + (math.log(tolerance) - d_lo) * (hi - lo) / (d_hi - d_lo)
    return float(np.exp(at)), "log-interpolated between simulated speeds"


def quasi_static_limits(table: pd.DataFrame) -> pd.DataFrame:
    """Per test: the V/v0 below which the quasi-static estimate is within 1 % and 5 % (module docstring)."""
    rows = []
    for (fixation, frequency, h1), test in table.groupby(["fixation", "frequency_hz", "h1_um"], sort=True):
        test = test.dropna(subset=["relative_deviation"]).sort_values("V_over_v0")
        row: dict[str, Any] = {"source": "simulated", "fixation": fixation, "frequency_hz": frequency, "h1_um": h1}
        for tolerance in TOLERANCES:
            speed, note = (_limit(test["V_over_v0"].to_numpy(), test["relative_deviation"].to_numpy(), tolerance)
                           if len(test) else (math.nan, "no simulated speed"))
            row[f"V_over_v0_within_{round(100 * tolerance)}pct"] = speed
            row[f"note_{round(100 * tolerance)}pct"] = note
        rows.append(row)
    return pd.DataFrame(rows)


def rig_problems(chi0: float, law_n: float, omega_check: float, radius: float, h1_um: Sequence[float],
                 fixation: Fixation) -> list[tuple[float, Problem]]:
    """[(h1, problem)] of the rig's amplitudes at one frequency (Eqs. 64, 65, 105)."""
    return [(float(h1), Problem(GentSchultz(law_n), chi0, float(h1) * 1e-6 / radius, omega_check, fixation))
            for h1 in h1_um]
