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
  ``integration_failure``; ``no_start_state`` when the steady state at the start does not converge;
  ``skipped_within_tolerance``, the stopping rule below),
  ``method``: ``time_domain`` (integrated in time, the periods integrated) or ``slow_flow`` (the averaged slow flow of
  :mod:`vibroadhesion.models.slow_flow`, rigid fixation only: the exact high-frequency averaging with the base
  offset slow; ``periods`` = the periods the withdrawal spans, ``steps`` = the slow flow's steps). A slow-flow row's
  ``quasi_static_ratio`` is its own V -> 0 limit, the exact averaging's force minimum
  (:func:`vibroadhesion.models.exact_averaging.pulloff_at_force_minimum`), and its ``relative_deviation`` is
  measured from that: the speed effect the averaging predicts (its own quasi-static error against the
  simulation, ~1e-4 at 20 um and 10-22 % at 100 um, cancels in the ratio to first order). The slow flow does not
  depend on the frequency (omega_check -> infinity at fixed etahat and V/v0): it is integrated once per amplitude
  and speed (:func:`slow_flow_rows`, slow times) and placed at each frequency (:func:`at_frequency`).

Stopping rule (:class:`StopRule`, config ``withdrawal.stop``). The slowest speeds cost the most (the periods grow as
1/V: at the compliant fixation 69 % of the full sweep's steps were at V = v0, and 98 % of those at 40-100 um, where
V = 3 v0 was already within 0.6 % of the quasi-static value; at the rigid one 70 % at 0.3 v0). The speeds of a test
therefore run from the fastest down, and the first speed at or below ``not_above`` whose period-mean pull-off is
within ``within`` of the quasi-static value ends it: the slower speeds get a row of status
``skipped_within_tolerance`` and no numbers. Nothing that :func:`quasi_static_limits` reports is lost when
``within`` is at most its smallest tolerance, since the deviation falls monotonically as V -> 0 (O(V); every test
of the full sweep, pinned on the artefacts by tests/test_headline_open_questions.py). ``not_above`` keeps the
speeds where another method is compared with the time domain (rigid: 1 v0, the slow flow's largest speed).

Rows are labelled ``source`` = ``simulated`` (time domain) or ``averaged`` (slow flow). :func:`quasi_static_limits`
gives, per test, the largest speed below which every speed keeps the period-mean pull-off within 1 % (5 %) of its
quasi-static value, interpolated in log V between the neighbouring speeds: at each speed the time domain where it
ran, the slow flow elsewhere; its ``method_*`` columns say which method the neighbouring rows came from.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import Any, NamedTuple

import numpy as np
import pandas as pd

from vibroadhesion import simulation
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import PHAT_JKR
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.virtual_pulloff import preloaded_offset, published_pulloffs
from vibroadhesion.models.exact_averaging import pulloff_at_force_minimum
from vibroadhesion.models.slow_flow import withdraw_slowly
from vibroadhesion.simulation.withdrawal import withdraw

COLUMNS = ["source", "fixation", "frequency_hz", "h1_um", "V_over_v0", "V_um_s", "method", "status",
           "peak_pulloff_ratio", "mean_pulloff_ratio", "quasi_static_ratio", "relative_deviation", "base_offset",
           "tau_pulloff", "tau_detached", "periods", "steps"]
#: Integration tolerance of the sweep: against rtol 1e-12 the pull-off force (peak and period mean) agrees within
#: 1.0e-6 relative in the 63 withdrawals the sweep runs at 200 and 400 Hz (compliant) and 400 Hz (rigid), with the
#: same statuses, at 0.65 of the CPU time of rtol 1e-9 (1.1e-7; benchmarks/withdrawal_rtol.py). The sweep's numbers
#: are read to 1e-4 (deviations from the quasi-static value, the slow flow's difference), so 1e-6 is ample.
#: tests/simulation/test_withdrawal.py bounds it by 2e-6 at 200 Hz.
SWEEP_RTOL = 1e-7
#: Tolerances of the quasi-static estimate reported by :func:`quasi_static_limits`.
TOLERANCES = (0.01, 0.05)
#: Status of a speed not integrated because a faster one was already within the stopping rule's deviation.
SKIPPED = "skipped_within_tolerance"


class StopRule(NamedTuple):
    """The stopping rule of a test's speeds, run from the fastest down (module docstring, "Stopping rule").

    The first speed at or below ``not_above`` (V/v0) within ``within`` (relative deviation from the quasi-static
    pull-off) ends the test.
    """

    within: float
    not_above: float = math.inf

    @classmethod
    def from_config(cls, stop: Mapping[str, float | None]) -> StopRule | None:
        """The rule of config ``withdrawal.stop`` of one fixation: None if ``within`` is null (every speed runs)."""
        within, not_above = stop["within"], stop["not_above"]
        return None if within is None else cls(float(within), math.inf if not_above is None else float(not_above))


def start_problem(problem: Problem) -> Problem:
    """The problem at the withdrawal's start offset (module docstring): etahat if rigid, 0 if compliant (Eq. 78)."""
    return replace(problem, base_offset=preloaded_offset(problem) if problem.fixation.is_rigid else 0.0)


def quasi_static_ratios(virtual_pulloff: pd.DataFrame, frequency_hz: float) -> dict[float, float]:
    """{h1: P_cr/|P_JKR|} of the simulated family of steady states (Eq. 4' mean force, Eq. 70) at one frequency.

    Read from the published virtual pull-off table
    (:func:`vibroadhesion.experiments.virtual_pulloff.published_pulloffs`): NaN where the family has no tensile
    extremum (status other than ``pulloff``).
    """
    return {h1: ratio if status == "pulloff" else math.nan
            for h1, (status, ratio) in published_pulloffs(virtual_pulloff, frequency_hz).items()}


def speed_rows(problem: Problem, speed_ratios: Sequence[float], v0_um_s: float, quasi_static: float,
               stop: StopRule | None = None) -> list[dict[str, Any]]:
    """Rows of :data:`COLUMNS` (without the test's identifying columns) for one test at each V/v0 (Eq. 11').

    ``quasi_static``: the family's P_cr/|P_JKR| (:func:`quasi_static_ratios`), the V -> 0 value. The speeds run
    from the fastest down; with ``stop`` the first speed it accepts ends the test, and the slower speeds get rows of
    status :data:`SKIPPED` (module docstring, "Stopping rule"). Rows in the order of ``speed_ratios``.
    """
    start = start_problem(problem)
    steady = simulation.steady_state(start)
    rows, done = {}, False
    for ratio in sorted(speed_ratios, reverse=True):
        row: dict[str, Any] = {"V_over_v0": ratio, "V_um_s": ratio * v0_um_s, "method": "time_domain",
                               "quasi_static_ratio": quasi_static}
        if done or not steady.ok or steady.orbit is None:
            rows[ratio] = {**row, "status": SKIPPED if done else "no_start_state"}
            continue
        run = withdraw(start, ratio, initial_state=steady.orbit.start_state, rtol=SWEEP_RTOL)
        mean = -run.mean_force / abs(PHAT_JKR)
        deviation = mean / quasi_static - 1.0
        rows[ratio] = {**row, "status": run.status, "peak_pulloff_ratio": -run.force / abs(PHAT_JKR),
                       "mean_pulloff_ratio": mean, "relative_deviation": deviation, "base_offset": run.base_offset,
                       "tau_pulloff": run.tau, "tau_detached": run.tau_detached, "periods": run.periods,
                       "steps": run.steps}
        done = (stop is not None and ratio <= stop.not_above and run.status == "pulloff"
                and abs(deviation) <= stop.within)
    return [rows[ratio] for ratio in speed_ratios]


def sweep_table(problems: Sequence[tuple[float, Problem]], speed_ratios: Sequence[float], *, fixation_name: str,
                frequency_hz: float, v0_um_s: float, quasi_static: dict[float, float],
                stop: StopRule | None = None) -> pd.DataFrame:
    """The speed sweep of the tests ``problems`` = [(h1 in um, problem)] at one frequency and fixation (simulated).

    ``quasi_static``: {h1: the family's P_cr/|P_JKR|} (:func:`quasi_static_ratios`); ``stop``: the stopping rule
    of :func:`speed_rows`.
    """
    rows = [{**row, "h1_um": h1} for h1, problem in problems
            for row in speed_rows(problem, speed_ratios, v0_um_s, quasi_static[h1], stop)]
    table = pd.DataFrame(rows).assign(source="simulated", fixation=fixation_name, frequency_hz=frequency_hz)
    return table.reindex(columns=COLUMNS).astype({"periods": "Int64", "steps": "Int64"})  # counts; none if not run


#: Columns of the frequency-free slow-flow table (:func:`slow_flow_rows`): slow times T = v0 t/a_o.
SLOW_COLUMNS = ["h1_um", "V_over_v0", "V_um_s", "status", "peak_pulloff_ratio", "mean_pulloff_ratio",
                "quasi_static_ratio", "relative_deviation", "base_offset", "slow_time_pulloff", "slow_time_detached",
                "steps"]


def slow_flow_rows(problems: Sequence[tuple[float, Problem]], speed_ratios: Sequence[float],
                   v0_um_s: float) -> pd.DataFrame:
    """The slow flow (rigid) of the tests [(h1, problem)] at each V/v0, from the rigid start (:func:`start_problem`).

    Rows of :data:`SLOW_COLUMNS`; ``quasi_static_ratio`` is the exact averaging's force minimum (module docstring).
    """
    rows = []
    for h1, problem in problems:
        start = start_problem(problem)
        limit = float(pulloff_at_force_minimum(problem.eta1, problem.chi0, problem.law).pulloff_ratio)
        for ratio in speed_ratios:
            run = withdraw_slowly(start, ratio)
            mean = -run.mean_force / abs(PHAT_JKR)
            rows.append({"h1_um": h1, "V_over_v0": ratio, "V_um_s": ratio * v0_um_s, "status": run.status,
                         "peak_pulloff_ratio": -run.force / abs(PHAT_JKR), "mean_pulloff_ratio": mean,
                         "quasi_static_ratio": limit, "relative_deviation": mean / limit - 1.0,
                         "base_offset": run.base_offset, "slow_time_pulloff": run.slow_time,
                         "slow_time_detached": run.slow_time_detached, "steps": run.steps})
    return pd.DataFrame(rows).reindex(columns=SLOW_COLUMNS)


def at_frequency(slow: pd.DataFrame, omega_check: float, c_o: float, *, fixation_name: str,
                 frequency_hz: float) -> pd.DataFrame:
    """The slow-flow rows as rows of :data:`COLUMNS` at one frequency: tau = omega_check c_o T (Eqs. 86, 105).

    ``periods`` = the periods up to detachment (or to the end of the flow), what a time domain would integrate.
    """
    to_tau = omega_check * c_o
    end = slow["slow_time_detached"].fillna(slow["slow_time_pulloff"]) * to_tau
    table = slow.assign(source="averaged", fixation=fixation_name, frequency_hz=frequency_hz, method="slow_flow",
                        tau_pulloff=slow["slow_time_pulloff"] * to_tau,
                        tau_detached=slow["slow_time_detached"] * to_tau,
                        periods=np.ceil(end / (2.0 * math.pi)).astype("Int64"))
    return table.reindex(columns=COLUMNS)


def _limit(speeds: np.ndarray, deviation: np.ndarray, tolerance: float) -> tuple[float, str, slice]:
    """Largest V/v0 below which every speed is within ``tolerance`` (log-interpolated), a note, the rows used."""
    inside = np.abs(deviation) <= tolerance
    if not inside[0]:
        return math.nan, f"not within {100 * tolerance:g} % even at the slowest speed {speeds[0]:g} v0", slice(0, 1)
    if inside.all():
        return math.nan, f"within {100 * tolerance:g} % up to the fastest speed {speeds[-1]:g} v0", slice(None)
    k = int(np.argmin(inside))  # first speed outside
    lo, hi = np.log(speeds[k - 1]), np.log(speeds[k])
    d_lo, d_hi = math.log(abs(deviation[k - 1]) or 1e-300), math.log(abs(deviation[k]))
    at = lo + (math.log(tolerance) - d_lo) * (hi - lo) / (d_hi - d_lo)
    return float(np.exp(at)), "log-interpolated between neighbouring speeds", slice(k - 1, k + 1)


def _one_row_per_speed(test: pd.DataFrame) -> pd.DataFrame:
    """The rows of one test with a deviation, one per speed: the time domain where it ran, else the slow flow."""
    test = test.dropna(subset=["relative_deviation"])
    ranked = test.assign(rank=(test["method"] != "time_domain").astype(int))
    return ranked.sort_values(["V_over_v0", "rank"], kind="stable").drop_duplicates("V_over_v0")


def quasi_static_limits(table: pd.DataFrame) -> pd.DataFrame:
    """Per test: the V/v0 below which the quasi-static estimate is within 1 % and 5 % (module docstring)."""
    rows = []
    for (fixation, frequency, h1), test in table.groupby(["fixation", "frequency_hz", "h1_um"], sort=True):
        test = _one_row_per_speed(test)
        row: dict[str, Any] = {"source": "/".join(sorted(set(test["source"]))), "fixation": fixation,
                               "frequency_hz": frequency, "h1_um": h1}
        for tolerance in TOLERANCES:
            speed, note, used = (_limit(test["V_over_v0"].to_numpy(), test["relative_deviation"].to_numpy(), tolerance)
                                 if len(test) else (math.nan, "no speed", slice(0, 0)))
            row[f"V_over_v0_within_{round(100 * tolerance)}pct"] = speed
            row[f"note_{round(100 * tolerance)}pct"] = note
            row[f"method_{round(100 * tolerance)}pct"] = "/".join(dict.fromkeys(test["method"].iloc[used]))
        rows.append(row)
    return pd.DataFrame(rows)


def rig_problems(chi0: float, law_n: float, omega_check: float, radius: float, h1_um: Sequence[float],
                 fixation: Fixation) -> list[tuple[float, Problem]]:
    """[(h1, problem)] of the rig's amplitudes at one frequency (Eqs. 64, 65, 105)."""
    return [(float(h1), Problem(GentSchultz(law_n), chi0, float(h1) * 1e-6 / radius, omega_check, fixation))
            for h1 in h1_um]


def method_agreement(table: pd.DataFrame) -> pd.DataFrame:
    """Where a test ran both methods at one speed: the slow flow's pull-off (mean, peak) against the time domain's.

    Speeds the stopping rule skipped (status :data:`SKIPPED`) did not run in the time domain.

    ``*_difference`` = slow flow/time domain - 1 (rows of :data:`COLUMNS`; bounded below by the exact averaging's own
    quasi-static error against the simulation, module docstring).
    """
    keys = ["fixation", "frequency_hz", "h1_um", "V_over_v0"]
    values = ["status", "mean_pulloff_ratio", "peak_pulloff_ratio", "periods"]
    ran = table[table["status"] != SKIPPED]
    timed, slow = (ran[ran["method"] == method][keys + values] for method in ("time_domain", "slow_flow"))
    both = timed.merge(slow, on=keys, suffixes=("_time_domain", "_slow_flow"))
    for value in ("mean_pulloff_ratio", "peak_pulloff_ratio"):
        both[f"{value}_difference"] = both[f"{value}_slow_flow"] / both[f"{value}_time_domain"] - 1.0
    return both.reset_index(drop=True)
