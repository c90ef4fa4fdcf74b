"""Virtual pull-off experiment: the simulated pull-off force of the rigidly fixed indenter.

No measured pull-off forces behind the paper's Fig. 4 are published; this module generates the
simulated counterpart. The base is withdrawn quasi-statically: a family of periodic steady states
of the full model (:mod:`vibroadhesion.simulate`) with decreasing deltabar0 = (hhat - h0) R/a_o^2
(Eq. 11 with h0 growing), each orbit started from the previous one. Along the family the mean
contact force P_m first grows more tensile, passes an extremum and then relaxes; under force
control the steady state stops existing at that extremum, so the pull-off force is the most
tensile mean force of the family. It is located by a bounded Brent minimisation between the
family's neighbours of the extremum.

If the family ends (the simulation loses contact, or a steady state cannot be found) while P_m is
still growing more tensile, there is no extremum to report: the status says so and no number is
returned. The paper's detachment criterion a_m = a_cr (Eq. 60, with the simulated w_eff) is
reported next to the simulated mean radius at pull-off so that it can be checked.

Results are in a_o units: P_m/|P_JKR| = Phat_m/(3/4), abar_cr = (9/16)^(1/3) (w_eff/w0)^(1/3) (Eq. 61).
"""

from __future__ import annotations

import math
from typing import Literal, NamedTuple

import numpy as np
from scipy.optimize import minimize_scalar

import pandas as pd

from vibroadhesion import exact_averaging, groups, simulate
from vibroadhesion.groups import PHAT_JKR
from vibroadhesion.jkr import pulloff_force
from vibroadhesion.progress import ProgressBar
from vibroadhesion.pulloff import GentSchultzParameters, predict_pulloff
from vibroadhesion.ratelaw import GentSchultz
from vibroadhesion.refined import pulloff_closure

Status = Literal["pulloff", "contact_loss_before_extremum", "no_steady_state_before_extremum"]


class VirtualPulloff(NamedTuple):
    status: Status
    ratio: float  # P_cr / P_cr^JKR = -min P_m / |P_JKR| (positive), NaN without an extremum
    deltabar0: float  # base offset (hhat - h0) R/a_o^2 at pull-off
    abar_m: float  # simulated mean contact radius at pull-off, a_m/a_o
    abar_cr: float  # the paper's criterion (Eq. 61) with the simulated w_eff there
    w_eff_ratio: float
    a_over_am: float
    steady_states: int  # periodic orbits solved along the family


def rigid_virtual_pulloff(eta1: float, omega_check: float, chi0: float, law: GentSchultz, *,
                          step: float = 0.2, max_steps: int = 400) -> VirtualPulloff:
    """Pull-off of the rigidly fixed indenter from the family of steady states in deltabar0 (module docstring)."""
    solved = 0

    def orbit(d0: float, state):
        nonlocal solved
        solved += 1
        return simulate.steady_state(simulate.BaseExcitation(law, chi0, eta1, omega_check, deltabar0=d0),
                                     initial_state=state)

    family: list[tuple[float, simulate.SteadyState]] = []
    state = None
    for k in range(max_steps):
        d0 = -step * k
        orbit_k = orbit(d0, state)
        if orbit_k.status != "converged":
            ended = "contact_loss_before_extremum" if orbit_k.status == "contact_loss" else "no_steady_state_before_extremum"
            return VirtualPulloff(ended, *(math.nan,) * 6, solved)
        family.append((d0, orbit_k))
        state = orbit_k.start_state
        if len(family) >= 3 and family[-1][1].phat_m > family[-2][1].phat_m:
            break
    else:
        return VirtualPulloff("no_steady_state_before_extremum", *(math.nan,) * 6, solved)
    (hi, _), (mid, middle), (lo, _) = family[-3:]
    cache: dict[float, simulate.SteadyState] = {mid: middle}

    def mean_force(d0: float) -> float:
        if d0 not in cache:
            cache[d0] = orbit(d0, middle.start_state)
        return cache[d0].phat_m if cache[d0].status == "converged" else math.inf

    minimize_scalar(mean_force, bounds=(lo, hi), method="bounded", options={"xatol": 1e-6 * step})
    d_best = min(cache, key=mean_force)  # every evaluation is cached: the most tensile orbit found
    at = cache[d_best]
    return VirtualPulloff("pulloff", float(at.phat_m / PHAT_JKR), float(d_best), float(at.abar_m),
                          float(pulloff_closure(math.sqrt(at.w_eff_ratio))), float(at.w_eff_ratio),
                          float(at.a_over_am), solved)


COLUMNS = ["fixation", "frequency_hz", "h1_um", "model", "status", "pulloff_ratio", "pulloff_mN", "abar_m", "abar_cr",
           "steady_states"]


def pulloff_table(params: GentSchultzParameters, frequency_hz: float, h1_um: np.ndarray, *, radius: float,
                  reduced_modulus: float) -> pd.DataFrame:
    """results/validation/virtual_pulloff.csv rows at one frequency: the simulated (virtual) experiment
    and the predictions of Eq. (72) (leading), Eq. (106) (refined) and the exact averaging (a_m = a_cr)."""
    law = GentSchultz(params.n)
    chi0 = groups.chi0(params.w0, reduced_modulus, radius)
    omega_check = float(groups.omega_check(frequency_hz, params.v0, radius))
    jkr_mN = float(-pulloff_force(params.w0, radius)) * 1e3
    rows, progress = [], ProgressBar(len(h1_um), "amplitudes")
    for h1 in np.asarray(h1_um, dtype=float):
        result = rigid_virtual_pulloff(h1 * 1e-6 / radius, omega_check, chi0, law)
        rows.append({"model": "simulation", "h1_um": h1, "status": result.status, "pulloff_ratio": result.ratio,
                     "abar_m": result.abar_m, "abar_cr": result.abar_cr, "steady_states": result.steady_states})
        progress.advance(result.steady_states, f"{frequency_hz:g} Hz, h1 = {h1:g} um: {result.status}, "
                                               f"P/P_JKR = {result.ratio:.6g}")
    geometry = {"radius": radius, "reduced_modulus": reduced_modulus}
    for model in ("leading", "refined"):
        pred = predict_pulloff(model, params, frequency_hz, h1_um, **geometry)
        rows += [{"model": model, "h1_um": h, "status": "ok", "pulloff_ratio": r} for h, r in zip(h1_um, pred.ratio)]
    exact = exact_averaging.pulloff_at_critical_radius(np.asarray(h1_um) * 1e-6 / radius, chi0, law)
    rows += [{"model": "exact_averaging", "h1_um": h, "status": "ok", "pulloff_ratio": r, "abar_m": a}
             for h, r, a in zip(h1_um, exact.ratio, exact.abar_m)]
    table = pd.DataFrame(rows).assign(fixation="rigid", frequency_hz=frequency_hz)
    table["pulloff_mN"] = table["pulloff_ratio"] * jkr_mN
    return table.reindex(columns=COLUMNS)
