"""Every model level against the direct simulation of the full model (rigid nominal point contact).

For each base amplitude h1 and frequency omega_check the steady state of the rigidly fixed
nominal point contact (h0 = hhat, Eq. 78) is computed by every level of role ``validation_rigid``
of :mod:`vibroadhesion.core.levels`, in its order:

* ``simulation``: periodic orbit of Eqs. (4), (5) with w = w0 f(adot/v0), shooting on the
  one-period map (:mod:`vibroadhesion.simulation`), the ground truth;
* ``leading``: Eq. (55) with abar_m^(3/2) = J0 (Eqs. 99, 123), frequency independent (the
  omega_check -> infinity limit of the refined model); A/a_m from its Abar at the given omega_check;
* ``refined``: Eqs. (122)–(123);
* ``exact_hb``: harmonic balance with the exact JKR relations, Eqs. (125)–(126)
  (:mod:`vibroadhesion.models.exact_harmonic_balance`);
* ``exact_averaging``: the exact high-frequency limit (:mod:`vibroadhesion.models.exact_averaging`).

Every row carries a ``status``: ``ok`` for a solution, the simulation's own status
(``contact_loss``, ``not_converged``, ...) or ``no_solution`` when a model level has no steady
state there. Numbers of rows without a solution are NaN, never a fill-in value.

Mean force of the J-integral levels: Eq. (52), P_m/|P_JKR| = (4/3) [(4/3) abar_m^3 - 2 J0 abar_m^(3/2)]
(:func:`vibroadhesion.models.leading_order.pm_over_abs_pjkr`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import pandas as pd

from vibroadhesion import simulation
from vibroadhesion.core import levels
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import SteadyState
from vibroadhesion.models.refined import APPLICABILITY_LIMIT  # applied as a user would: to the refined A/a_m
from vibroadhesion.models.response_curve import trace_response_curve
from vibroadhesion.numerics.progress import ProgressBar

#: The registry's functions this module resolves (vibroadhesion.core.levels): the rigid steady states.
LEVEL_FUNCTIONS = (("validation_rigid", "steady_state"),)

QUANTITIES = ("Abar", "abar_m", "w_eff_ratio", "A_over_am", "pm_over_abs_pjkr")
RIGID_GRID_COLUMNS = ["h1_um", "omega_check", "model", "status", *QUANTITIES]
ERROR_COLUMNS = ["h1_um", "omega_check", "model", "quantity", "relative_error", "refined_A_over_am", "applicable"]

#: The error a level must stay below to be "trusted" (issue: where each level's error is below 5 %).
TRUSTED_ERROR = 0.05


def simulated_nominal_point_contact(eta1: float, omega_check: float, chi0: float, law: GentSchultz) -> SteadyState:
    """The direct simulation's periodic steady state of the rigidly fixed nominal point contact (Eqs. 4-11, 78)."""
    return simulation.steady_state(Problem(law, chi0, eta1, omega_check))


def _row_numbers(state: SteadyState) -> dict[str, float]:
    """QUANTITIES of a record; NaN unless its status is ``ok``."""
    values = (state.Abar, state.abar_m, state.w_eff_ratio, state.A_over_am, state.pm_over_abs_pjkr)
    if not state.ok:
        return dict.fromkeys(QUANTITIES, math.nan)
    return {quantity: float(value) for quantity, value in zip(QUANTITIES, values, strict=True)}


def rigid_point(h1_um: float, omega_check: float, *, chi0: float, radius: float, n: float) -> list[dict[str, Any]]:
    """Every level of role ``validation_rigid`` at one (h1, omega_check): rows of :data:`RIGID_GRID_COLUMNS`."""
    law = GentSchultz(n)
    rows = []
    for model in levels.names("validation_rigid"):
        state = levels.level(model).steady_state_function()(h1_um * 1e-6 / radius, omega_check, chi0, law)
        rows.append({"h1_um": h1_um, "omega_check": omega_check, "model": model, "status": str(state.status),
                     **_row_numbers(state)})
    return rows


def rigid_grid(h1_um: float, omega_checks: Sequence[float], *, chi0: float, radius: float, n: float) -> pd.DataFrame:
    """All model levels along one amplitude's frequency grid (one Snakemake job per amplitude)."""
    rows = [row for w in omega_checks for row in rigid_point(h1_um, float(w), chi0=chi0, radius=radius, n=n)]
    return pd.DataFrame(rows)[RIGID_GRID_COLUMNS]


def validation_frequencies(decades: tuple[int, int], experiment_omega_check: Sequence[float]) -> np.ndarray:
    """Every whole decade of omega_check in ``decades`` plus the experiments' omega_check, sorted."""
    decade_grid = 10.0 ** np.arange(decades[0], decades[1] + 1)
    return np.unique(np.concatenate([decade_grid, np.asarray(experiment_omega_check)]))


def relative_errors(grid: pd.DataFrame) -> pd.DataFrame:
    """|model/simulation - 1| for every quantity, where both have a solution.

    ``applicable`` marks the points the paper's rule admits (refined A/a_m <= 0.1); points where
    the simulation has no steady state (contact loss) or the model has none are left out.
    """
    sim = grid[grid["model"] == "simulation"].set_index(["h1_um", "omega_check"])
    refined = grid[grid["model"] == "refined"].set_index(["h1_um", "omega_check"])["A_over_am"]
    frames = []
    for model in levels.names("validation_rigid"):
        if model == "simulation":  # the reference
            continue
        rows = grid[grid["model"] == model].set_index(["h1_um", "omega_check"])
        both = (rows["status"] == "ok") & (sim["status"] == "ok")
        for quantity in QUANTITIES:
            err = (rows.loc[both, quantity] / sim.loc[both, quantity] - 1.0).abs()
            frames.append(pd.DataFrame({"model": model, "quantity": quantity, "relative_error": err,
                                        "refined_A_over_am": refined.loc[err.index]}).reset_index())
    errors = pd.concat(frames, ignore_index=True)
    errors["applicable"] = errors["refined_A_over_am"] <= APPLICABILITY_LIMIT
    ordered = errors.sort_values(["model", "quantity", "h1_um", "omega_check"], kind="stable")
    return ordered[ERROR_COLUMNS].reset_index(drop=True)


def error_summary(errors: pd.DataFrame, experiment_omega_check: Sequence[float]) -> pd.DataFrame:
    """Largest relative error of each level, inside and outside the applicability region.

    Over the whole grid and at the experiments' frequencies, and the share of points below
    TRUSTED_ERROR. No row where no level was compared (the simulation found no steady state on the grid); the
    columns are there all the same.
    """
    rows = []
    for model, e in errors.groupby("model", sort=False):
        worst = e.groupby(["h1_um", "omega_check", "applicable"])["relative_error"].max().reset_index()
        at_exp = worst["omega_check"].isin(np.asarray(experiment_omega_check))
        rows.append({
            "model": model,
            "max_error_applicable": worst.loc[worst["applicable"], "relative_error"].max(),
            "max_error_outside": worst.loc[~worst["applicable"], "relative_error"].max(),
            "max_error_experiments_applicable": worst.loc[at_exp & worst["applicable"], "relative_error"].max(),
            "max_error_experiments_outside": worst.loc[at_exp & ~worst["applicable"], "relative_error"].max(),
            "points": len(worst),
            "points_below_5pct": int((worst["relative_error"] < TRUSTED_ERROR).sum()),
        })
    return pd.DataFrame(rows, columns=SUMMARY_COLUMNS)


#: Columns of :func:`error_summary` (results/validation/rigid_error_summary.csv).
SUMMARY_COLUMNS = ["model", "max_error_applicable", "max_error_outside", "max_error_experiments_applicable",
                   "max_error_experiments_outside", "points", "points_below_5pct"]


# --- Compliant fixation: the Fig. 5 sweep, up and down in frequency ----------------------------

SWEEP_COLUMNS = ["direction", "omega_bar", "model", "solution_index", "status", "Abar", "abar_m", "A_over_am", "stable",
                 "max_floquet_multiplier"]


def compliant_sweep(fixation: Fixation, chi0: float, eta1: float, n: float, omega_bar: Sequence[float],
                    progress: ProgressBar | None = None) -> pd.DataFrame:
    """Simulated steady states along ``omega_bar`` swept up, then down, next to the refined model.

    The compliant ``fixation`` at chi0 (Eq. 64) and eta1 = h1/R (Eq. 65), omega_check = omega_bar/nu0 (Eq. 105).

    Each orbit is started from the previous one (a slow sweep, so a fold of the response shows as
    a jump and a hysteresis loop), next to every solution of the refined model (Eqs. 87, 90) on its
    traced curve at the same frequency.

    A start from the previous orbit that does not converge is retried from the static state
    (Eq. 82); the row says which (``status``). ``stable`` and the largest |Floquet multiplier| come
    from the monodromy matrix of the simulated orbit; the refined rows carry the index of their
    solution in order of increasing Abar as ``solution_index`` and no stability (the averaged model does
    not provide one). ``progress`` advances once per simulated frequency.
    """
    law = GentSchultz(n)
    curve = trace_response_curve(fixation, chi0, eta1, law, (min(omega_bar), max(omega_bar)))
    rows = []
    for direction, grid in (("up", list(omega_bar)), ("down", list(omega_bar)[::-1])):
        state = None
        for w in grid:
            problem = Problem(law, chi0, eta1, w / fixation.nu0, fixation)
            sim = simulation.steady_state(problem, initial_state=state)
            status, solved = "ok", 1
            if not sim.ok and state is not None:
                sim = simulation.steady_state(problem)
                status, solved = "ok, restarted from the static state", 2
            if progress is not None:
                progress.advance(solved, f"sweep {direction}, omega_bar = {w:.6g}: {sim.status}")
            if sim.ok and sim.orbit is not None:
                state = sim.orbit.start_state
                rows.append({"direction": direction, "omega_bar": w, "model": "simulation", "solution_index": 0,
                             "status": status, "Abar": float(sim.Abar), "abar_m": float(sim.abar_m),
                             "A_over_am": float(sim.A_over_am), "stable": bool(sim.stable),
                             "max_floquet_multiplier": float(np.max(np.abs(sim.orbit.floquet_multipliers)))})
            else:
                rows.append({"direction": direction, "omega_bar": w, "model": "simulation", "solution_index": 0,
                             "status": str(sim.status), "Abar": math.nan, "abar_m": math.nan, "A_over_am": math.nan,
                             "stable": False, "max_floquet_multiplier": math.nan})
            if direction == "up":
                refined = curve.steady_states_at(w, law)
                rows += [{"direction": "-", "omega_bar": w, "model": refined.level, "solution_index": k,
                          "status": str(status), "Abar": float(Abar), "abar_m": float(abar_m),
                          "A_over_am": float(A_over_am), "stable": math.nan, "max_floquet_multiplier": math.nan}
                         for k, (status, Abar, abar_m, A_over_am) in enumerate(
                             zip(refined.status, refined.Abar, refined.abar_m, refined.A_over_am, strict=True))]
    return pd.DataFrame(rows)[SWEEP_COLUMNS]
