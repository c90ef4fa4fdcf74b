"""Virtual pull-off experiment: the simulated pull-off force of the rigidly or compliantly fixed indenter.

No measured pull-off forces behind the paper's Fig. 4 are published; this module generates the
simulated counterpart. The base is withdrawn quasi-statically: a family of periodic steady states
of the full model (:mod:`vibroadhesion.simulation`) with decreasing base_offset = (hhat - h0) R/a_o^2
(Eq. 11 with h0 growing), each orbit started from a prediction extrapolated from the previous two.
Along the family the mean contact force P_m first grows more tensile, passes an extremum and then
relaxes; the pull-off force is the most tensile mean force of the family, located by a bounded
Brent minimisation between the family's neighbours of the extremum.

Start. The family starts at the problem's base offset (0: the nominal point contact, Eq. 78) from the
static state, whose first period :func:`vibroadhesion.simulation.steady_state` integrates as the physical
transient. With deltabar(tau) = base_offset - etahat sin tau the first quarter period pulls the contact
by the whole stroke etahat = eta1/c_o^2, and a rigidly held JKR contact with work of adhesion w is lost
below its fixed-grip pull-off deltabar = -3 (Phi/16)^(2/3) = -0.4725 Phi^(2/3), Phi = w/w0 (the minimum of
Eq. 5' over abar). By the Gent–Schultz law (Eqs. 73–75) Phi = 1 + |x|^n at the opening speed x = adot/v0,
so holding a stroke etahat needs |x| >= ((etahat/0.4725)^(3/2) - 1)^(1/n): for h1 = 100 um (etahat = 7.90,
Phi >= 68) that is |x| >= 2.8e3 for the published n = 0.531, reached within the first period at 200 Hz, but
|x| >= 1e20 for n = 0.092 and 1e12 for n = 0.15 -- far beyond what the contact front does (the model caps
d abar/dtau at 1e6, |x| <= 1e6 omega_check c_o). Small n makes the adhesion nearly rate independent
(|x|^0.092 < 7 up to |x| = 1e9), so at omega_check = 1e8, n = 0.092, h1 = 100 um the contact is lost at
tau = 0.20 (deltabar = -1.6) of the first period, before any steady state exists: the family cannot start
there, whatever the later pull-off would be. For the rigid fixation the family then starts preloaded, at
base_offset = etahat (:func:`preloaded_offset`), where deltabar(tau) >= 0 keeps the contact for any rate
law, and is withdrawn from there; its mean force starts compressive, and only a tensile minimum of the
mean force is a pull-off (a compressive local minimum is passed, :func:`_tensile_extremum`). Such a
family may still lose contact on the way without a tensile extremum (n = 0.092 above: it does, after 16
orbits): the status says so.

Why the extremum, with a spring in series. With the fixation of Eq. (3') the mean of Eq. (3') over
a period gives xbar_m = mu/(kappa c_o^2) - sigma Phat_m, sigma = c_o/kappa, and the mean contact
displacement is deltabar_m = xbar_m + base_offset. Along the family, with the mean contact stiffness
S = dPhat_m/ddeltabar_m,

    d base_offset = (1 + sigma S) d deltabar_m,      dPhat_m/d base_offset = S / (1 + sigma S).

The mean force is extremal where S = 0, while the family continues in base_offset as long as
1 + sigma S > 0: it folds where S = -kappa/c_o, i.e. dP/ddelta = -k, the jump of a displacement-
controlled test through a spring. S decreases through 0 before it reaches -kappa/c_o, so the fold
comes after the force extremum, and the two coincide under force control (kappa -> 0); for the
rigid fixation (sigma = 0) there is no fold before the JKR fixed-grip limit. Under force control
the steady state is lost at the extremum, for either fixation: that is the pull-off reported.
Between the extremum and the fold the window is narrow for a soft spring (for kappa = 0.001 at
200 Hz, h1 = 20 um: 0.01 in base_offset after a withdrawal of 41): a step that lands beyond the fold
finds no steady state, and the step is then halved towards the last orbit (bisection between the
last orbit and the nearest failure) until an orbit past the extremum is found.

Step. Most of a base withdrawal goes into the spring: by the relation above, a contact displacement
step ``step`` needs a base step step (1 + sigma S). S is the secant stiffness of the family's last
two orbits, and 2 abar_m for the first step: at fixed J0 the leading-order mean relations (Eqs.
52–53) give dPhat_m/ddeltabar_m = 2 abar_m (4 abar_m^(3/2) - 3 J0)/(4 abar_m^(3/2) - J0) <= 2 abar_m,
the frozen-radius contact stiffness K = 2 E* a_m of Eq. (C.5). S is clipped to [0, 2 abar_m]. So
each step moves the contact by about ``step`` in deltabar_m, as in the rigid case, and the family
has a similar number of orbits whatever kappa is.

If the family ends (the simulation loses contact, or no steady state is found within the smallest
step) while P_m is still growing more tensile, there is no extremum to report: the status says so
and no number is returned. Where the shooting just fails to converge beyond the last orbit, the
transient from that orbit at the failed base_offset tells why: ``contact_loss_before_extremum`` if it
loses contact within END_TRANSIENT_PERIODS periods, ``no_steady_state_before_extremum`` otherwise. A family
that takes ``max_steps`` withdrawal steps without either ends as ``budget_exceeded`` (the virtual pull-off table
allows FAMILY_BUDGET).
(Example: the compliant family kappa = 0.001, omega_bar = 17.85, h1 = 20 um at omega_check = 1e4 ends at
base_offset = -26.146 with P_m still decreasing; its last orbit's Floquet multipliers, |lambda| <= 0.97,
show no fold, and the transient from it at -26.15 loses contact after 60 periods.) The paper's
detachment criterion a_m = a_cr (Eq. 60, with the simulated w_eff) is reported next to the
simulated mean radius at pull-off so that it can be checked.

Predictions next to the simulation (:func:`pulloff_table`). Rigid rows: Eq. (72) (``leading``),
Eq. (106) (``refined``), the exact high-frequency averaging with the paper's criterion a_m = a_cr
(``exact_averaging``) and its force-controlled detachment, the minimum of the mean force over a_m
(``exact_averaging_force_minimum``). Compliant rows: Eqs. (67)–(69) with (71) (``leading``,
:func:`vibroadhesion.models.leading_pulloff.pulloff_leading` with the spring's fixation) and Eq. (90) at
a_m = a_cr (``refined``, :func:`vibroadhesion.models.compliant.pulloff_by_scan`), both the smallest root
(the first reached as the base is withdrawn, :mod:`vibroadhesion.models.leading_pulloff`). There is no exact
averaging row for the compliant fixation: the exact averaging is a model of the rigidly fixed contact.

Results are in a_o units: P_m/|P_JKR| = Phat_m/(3/4), abar_cr = (9/16)^(1/3) (w_eff/w0)^(1/3) (Eq. 61).
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd
from scipy.optimize import minimize_scalar

from vibroadhesion import simulation
from vibroadhesion.core import groups, levels
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import PHAT_JKR, contact_radius_ratio
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import OrbitDiagnostics, Pulloff, PulloffStatus, SteadyState
from vibroadhesion.experiments.pulloff import GentSchultzParameters, jkr_mN, predict_pulloff
from vibroadhesion.models.compliant import pulloff_by_scan
from vibroadhesion.models.leading_pulloff import PULLOFF_SCAN, pulloff_closure, pulloff_leading
from vibroadhesion.numerics.progress import ProgressBar

#: Periods of the transient that tells how a family without an extremum ends (module docstring).
END_TRANSIENT_PERIODS = 200


#: Withdrawal steps (orbits along the family, failed ones included) that a family of the virtual pull-off table
#: (:func:`pulloff_table`) may take before it ends as ``budget_exceeded``. At the published parameters the rigid
#: families take 14-28 steps and the compliant ones 25-52 (results/simulation/published/, column steady_states, which
#: also counts the extremum's refinement), so 120 leaves twice the largest; a family at parameters far from any data
#: (e.g. w0 = 0.001 J/m^2, n = 0.98 at h1 = 100 um: a preloaded start at base_offset = etahat = 282, 0.2 per step
#: from the nominal contact) would otherwise walk its 400 default steps at up to 0.2 s each, for each of the 15 tests.
FAMILY_BUDGET = 120


def _ended(failure: str, solved: int) -> Pulloff:
    """The record of a family without a force extremum: why it ended, every number NaN.

    ``failure``: ``contact_loss``, ``budget_exceeded`` (its steps spent while P_m still grew more tensile: no
    statement about a steady state beyond) or a failed shooting (``no_steady_state_before_extremum``).
    """
    status: PulloffStatus = ("contact_loss_before_extremum" if failure == "contact_loss"
                             else "budget_exceeded" if failure == "budget_exceeded"
                             else "no_steady_state_before_extremum")
    nan = np.asarray(math.nan)
    return Pulloff("simulation", np.asarray(status), *(nan,) * 8, steady_states=solved)


def _orbit(state: SteadyState) -> OrbitDiagnostics:
    """The orbit diagnostics of a simulated steady state (every record of the simulation has them)."""
    if state.orbit is None:
        raise TypeError(f"a {state.level} steady state has no orbit diagnostics")
    return state.orbit


def _end_of_family(problem: Problem, last: SteadyState, failure: str) -> str:
    """Why the family ends: the shooting's own ``contact_loss``, or else what the transient says.

    The transient runs from the last orbit at the nearest failed base_offset over
    END_TRANSIENT_PERIODS periods (``contact_loss`` if it loses contact).
    """
    if failure == "contact_loss":
        return failure
    try:
        run = simulation.transient(problem, periods=END_TRANSIENT_PERIODS, initial_state=_orbit(last).start_state)
    except RuntimeError:
        return failure
    return "contact_loss" if run.status == "contact_loss" else failure


def simulated_pulloff(problem: Problem, *, step: float = 0.2, max_steps: int = 400, halvings: int = 6,
                      iterations: int = 15) -> Pulloff:
    """Pull-off from the family of steady states in base_offset (module docstring), from ``problem``'s base offset.

    The record of level ``simulation`` (scalar): status ``pulloff`` with P_cr/P_cr^JKR = -min P_m/|P_JKR|,
    the base offset, mean radius, w_eff/w0 and A/a_m of the most tensile orbit and the paper's
    criterion abar_cr (Eq. 61) at its w_eff; or why the family ended without an extremum, NaN.
    The keywords are those of :func:`traced_pulloff`.
    """
    return traced_pulloff(problem, step=step, max_steps=max_steps, halvings=halvings, iterations=iterations)[0]


def traced_pulloff(problem: Problem, *, warm: tuple[float, np.ndarray] | None = None, step: float = 0.2,
                   max_steps: int = 400, halvings: int = 6,
                   iterations: int = 15) -> tuple[Pulloff, tuple[float, SteadyState] | None]:
    """The pull-off record of :func:`simulated_pulloff` and its most tensile orbit (base_offset, orbit), or None.

    :func:`traced_family` with its orbit kept only where the family has a pull-off (the keywords are its).
    """
    record, reached = traced_family(problem, warm=warm, step=step, max_steps=max_steps, halvings=halvings,
                                    iterations=iterations)
    return record, reached if str(record.status) == "pulloff" else None


def traced_family(problem: Problem, *, warm: tuple[float, np.ndarray] | None = None, step: float = 0.2,
                  max_steps: int = 400, halvings: int = 6,
                  iterations: int = 15) -> tuple[Pulloff, tuple[float, SteadyState] | None]:
    """The pull-off record and the most tensile orbit (base_offset, orbit) the family reached; None without orbits.

    With a pull-off that orbit is the pull-off's. A family that ends without a force extremum (its record says
    why) still gives its most tensile orbit, the last before it ended while P_m grew more tensile: the minimum of
    P_m over the base offsets the family reached, attained at their end (the fit's search uses it, module
    docstring of :mod:`vibroadhesion.experiments.simulation_fit`).

    The family starts from the state of the module docstring ("Start"): at ``problem``'s base offset from
    the static state, preloaded to base_offset = etahat where that loses contact (rigid fixation), or, with
    ``warm`` = (base_offset, start_state), from a nearby orbit (a fit's previous pull-off): if the mean force
    does not first grow more tensile from there, the family is traced again from the cold start.

    ``step`` is the target change of the mean contact displacement deltabar_m per orbit; the base step
    is step (1 + sigma S) (module docstring). After a failed orbit the next steps go at most half-way
    to it; once the last orbit lies within step 2^-``halvings`` of the failure, the failed base_offset is tried
    again from the now close prediction (a shooting that failed from a poor start converges then), and the
    family is declared ended if it fails again.
    An orbit started from a predicted state gets ``iterations`` shooting periods (3–6 suffice along the
    families computed here; beyond the fold the shooting cannot converge, and the cap keeps those
    attempts cheap); the first, from the static state, the default of :func:`simulation.steady_state`.
    The extremum is located to 1e-4 step in base_offset, so the force to ~1e-8 relative (it is flat there).
    After ``max_steps`` withdrawal steps without an extremum or an end the record is ``budget_exceeded``.
    """
    fixation = problem.fixation
    sigma = 0.0 if fixation.is_rigid else contact_radius_ratio(problem.chi0) / fixation.kappa
    run = _Withdrawal(problem, iterations)
    d0, first = _first_orbit(run, warm)
    family: list[tuple[float, SteadyState]] = []
    failure: tuple[float, str] | None = None  # nearest base_offset known to have no steady state, and why
    orbit_k = first
    for _ in range(max_steps):
        if not orbit_k.ok:
            status = str(orbit_k.status)
            if not family:
                return _ended(status, run.solved), None
            if failure is not None and d0 == failure[0]:  # failed again from the close prediction: the end
                return (_ended(_end_of_family(run.problem_at(d0), family[-1][1], status), run.solved),
                        min(family, key=_phat))
            failure = (d0, status)
        else:
            family.append((d0, orbit_k))
            if failure is not None and d0 == failure[0]:  # the earlier failure was the shooting's, not the family's
                failure = None
            if warm is not None and len(family) == 2 and _phat(family[1]) >= _phat(family[0]):
                return traced_family(problem, step=step, max_steps=max_steps, halvings=halvings,
                                     iterations=iterations)  # the warm start lies beyond the extremum
            if _tensile_extremum([_phat(member) for member in family[-3:]]):
                break
        d0, state = _next_offset(family, failure, step, sigma, halvings)
        orbit_k = run.orbit(d0, state)
    else:
        return _ended("budget_exceeded", run.solved), min(family, key=_phat)
    d_best = run.most_tensile(family[-3:], step)
    return _pulloff_record(run.cache[d_best], d_best, run.solved), (d_best, run.cache[d_best])


def preloaded_offset(problem: Problem) -> float:
    """The compressive start base_offset = etahat, at which the rigidly fixed contact survives any rate law.

    With deltabar(tau) = base_offset - etahat sin tau >= 0 (Eq. 11 in the model's units), Eq. (5') gives
    Phi = (abar^2 - deltabar)^2/abar <= abar^3 wherever abar^2 > deltabar, so Phi < 1 (w < w0: the front
    closes, Eq. 6') whenever abar < 1: abar never falls below min(abar(0), 1) and the contact is kept
    whatever w0, n and v0 are (module docstring, "Start").
    """
    return max(problem.base_offset, problem.etahat)


def _first_orbit(run: _Withdrawal, warm: tuple[float, np.ndarray] | None) -> tuple[float, SteadyState]:
    """The family's first orbit and its base offset (module docstring, "Start").

    From ``warm`` (base_offset, state) when it converges there; else from the static state at the problem's
    base offset, and for the rigid fixation, where that first period loses contact, at :func:`preloaded_offset`.
    """
    if warm is not None:
        orbit = run.orbit(warm[0], warm[1])
        if orbit.ok:
            return warm[0], orbit
    d0 = run.problem.base_offset
    orbit = run.orbit(d0, None)
    if orbit.status == "contact_loss" and run.problem.fixation.is_rigid and preloaded_offset(run.problem) > d0:
        d0 = preloaded_offset(run.problem)
        orbit = run.orbit(d0, None)
    return d0, orbit


def _phat(member: tuple[float, SteadyState]) -> float:
    """Phat_m of a family member (base_offset, orbit)."""
    return _orbit(member[1]).phat_m


def _tensile_extremum(phat_m: list[float]) -> bool:
    """Do the last three mean forces of the family (in withdrawal order) bracket the pull-off?

    The middle one is below both neighbours and tensile (Phat_m < 0, Eq. 4'): a local minimum of the mean
    force while it is still compressive (which a family from the preloaded start can pass) is not a pull-off.
    """
    return len(phat_m) == 3 and phat_m[1] < min(phat_m[0], phat_m[2]) and phat_m[1] < 0.0


def _pulloff_record(at: SteadyState, d_best: float, solved: int) -> Pulloff:
    """The ``pulloff`` record of the most tensile orbit ``at`` of the family, at base offset ``d_best``."""
    w_eff_ratio = float(at.w_eff_ratio)
    sqrt_w_eff_ratio = math.sqrt(w_eff_ratio)
    return Pulloff("simulation", np.asarray("pulloff"), pulloff_ratio=np.asarray(float(_orbit(at).phat_m / PHAT_JKR)),
                   Abar_cr=np.asarray(math.nan), sqrt_w_eff_ratio=np.asarray(sqrt_w_eff_ratio),
                   w_eff_ratio=np.asarray(w_eff_ratio), abar_cr=np.asarray(float(pulloff_closure(sqrt_w_eff_ratio))),
                   abar_m=np.asarray(float(at.abar_m)), A_over_am=np.asarray(float(at.A_over_am)),
                   base_offset=np.asarray(float(d_best)), steady_states=solved)


class _Withdrawal:
    """One quasi-static withdrawal: the orbits solved at base offsets (base_offset), counted and cached."""

    def __init__(self, problem: Problem, iterations: int) -> None:
        """The withdrawal of ``problem``'s base (Eq. 11); ``iterations`` caps predicted shootings."""
        self.problem, self.iterations = problem, iterations
        self.solved = 0
        self.cache: dict[float, SteadyState] = {}

    def problem_at(self, d0: float) -> Problem:
        """The problem at base_offset = ``d0`` (Eq. 7 divided by a_o^2/R)."""
        return replace(self.problem, base_offset=d0)

    def orbit(self, d0: float, state: np.ndarray | None) -> SteadyState:
        """The periodic steady state at ``d0``: from the static state (``state`` None) or a predicted one."""
        self.solved += 1
        if state is None:
            return simulation.steady_state(self.problem_at(d0), initial_state=None)
        return simulation.steady_state(self.problem_at(d0), initial_state=state, max_iterations=self.iterations)

    def mean_force(self, d: float, bracket: list[tuple[float, SteadyState]]) -> float:
        """Phat_m of the orbit at ``d`` (solved once, from the bracket's interpolation); inf where none converges."""
        if d not in self.cache:
            self.cache[d] = self.orbit(d, _interpolated_state(bracket, d))
        return self.cached_force(d)

    def most_tensile(self, bracket: list[tuple[float, SteadyState]], step: float) -> float:
        """The base offset of the most tensile orbit inside ``bracket`` (hi, mid, lo): bounded Brent to 1e-4 step.

        Every evaluation is cached (:attr:`cache`), so the answer is the most tensile orbit found.
        """
        (hi, _), (mid, middle), (lo, _) = bracket
        self.cache = {mid: middle}
        minimize_scalar(self.mean_force, bounds=(lo, hi), args=(bracket,), method="bounded",
                        options={"xatol": 1e-4 * step})
        return min(self.cache, key=self.cached_force)

    def cached_force(self, d: float) -> float:
        """Phat_m of the cached orbit at ``d``; inf where it did not converge (never the most tensile)."""
        return _orbit(self.cache[d]).phat_m if self.cache[d].ok else math.inf


def _next_offset(family: list[tuple[float, SteadyState]], failure: tuple[float, str] | None,
                 step: float, sigma: float, halvings: int) -> tuple[float, np.ndarray]:
    """The next base offset and its predicted start state (module docstring: base step step (1 + sigma S)).

    S = dPhat_m/ddeltabar_m from the last two orbits (2 abar_m, the static JKR stiffness of Eq. 4',
    from one), clipped to [0, 2 abar_m]. After a failure the step goes at most half-way to it, and the
    failed offset itself once the family lies within step 2^-halvings of it.
    """
    d_last, last = family[-1]
    if len(family) >= 2:
        previous = family[-2][1]
        stiffness = (_orbit(last).phat_m - _orbit(previous).phat_m) / float(last.deltabar_m - previous.deltabar_m)
    else:
        stiffness = 2.0 * float(last.abar_m)
    stiffness = min(max(stiffness, 0.0), 2.0 * float(last.abar_m))
    d0 = d_last - step * (1.0 + sigma * stiffness)
    if failure is not None:
        gap = d_last - failure[0]
        d0 = failure[0] if gap <= step * 2.0**-halvings else max(d0, d_last - 0.5 * gap)
    return d0, _predicted_state(family, d0, sigma * stiffness)


def _predicted_state(family: list[tuple[float, SteadyState]], d0: float,
                     sigma_stiffness: float) -> np.ndarray:
    """Start state for the orbit at ``d0``, extrapolated from the family.

    Linear extrapolation from the last two orbits of the family; from one orbit, its state with the
    spring's mean shifted by d xbar_m = -sigma S/(1 + sigma S) d base_offset.
    """
    d_last, last = family[-1]
    if len(family) >= 2:
        d_prev, previous = family[-2]
        start, previous_start = _orbit(last).start_state, _orbit(previous).start_state
        return start + (start - previous_start) * (d0 - d_last) / (d_last - d_prev)
    state = _orbit(last).start_state.copy()
    if state.size == 3:
        state[0] -= sigma_stiffness / (1.0 + sigma_stiffness) * (d0 - d_last)
    return state


def _interpolated_state(bracket: list[tuple[float, SteadyState]], d0: float) -> np.ndarray:
    """Start state inside the bracket of the extremum: piecewise-linear in base_offset between its orbits."""
    ds = np.array([d for d, _ in bracket])[::-1]  # ascending
    states = np.array([_orbit(o).start_state for _, o in bracket])[::-1]
    return np.array([np.interp(d0, ds, states[:, i]) for i in range(states.shape[1])])


def _refined_compliant_pulloff(omega_bar: float, fixation: Fixation, chi0: float, eta1: float,
                               law: GentSchultz) -> Pulloff:
    """Eq. (71) at the smallest root of Eq. (90) with a_m = a_cr (the first reached as the base is withdrawn).

    The record of level ``refined`` (scalar): the first element of the roots' record, ``no_solution`` where
    the scan finds none.
    """
    return pulloff_by_scan(omega_bar, fixation, chi0, eta1, law, PULLOFF_SCAN).taken(np.asarray(0))


def _record_rows(pulloff: Pulloff, h1_um: np.ndarray) -> list[dict[str, Any]]:
    """Rows of :func:`pulloff_table` from one record, one per amplitude; NaN where the level gives no number."""
    rows: list[dict[str, Any]] = [
        {"model": pulloff.level, "h1_um": h, "status": str(status), "pulloff_ratio": pulloff_ratio,
         "abar_m": abar_m, "abar_cr": abar_cr}
        for h, status, pulloff_ratio, abar_m, abar_cr in zip(
            h1_um, *(np.ravel(v) for v in (pulloff.status, pulloff.pulloff_ratio, pulloff.abar_m, pulloff.abar_cr)),
            strict=True)
    ]
    if pulloff.steady_states is not None:
        for row in rows:
            row["steady_states"] = pulloff.steady_states
    return rows


COLUMNS = ["fixation", "kappa", "zeta", "frequency_hz", "h1_um", "model", "status", "pulloff_ratio", "pulloff_mN",
           "abar_m", "abar_cr", "steady_states"]


def pulloff_table(params: GentSchultzParameters, frequency_hz: float, h1_um: np.ndarray, *, radius: float,
                  reduced_modulus: float, fixation: Fixation = Fixation.rigid(),
                  progress: ProgressBar | None = None, predictions: bool = True) -> pd.DataFrame:
    """Rows of results/simulation/virtual_pulloff/{fixation}_{frequency}Hz.csv.

    The simulated (virtual) experiment and, unless ``predictions`` is false, the predictions of the
    module docstring, for the rigid (the default) or the compliant fixation. ``progress`` advances
    once per amplitude with the steady states solved for it. Each family takes at most :data:`FAMILY_BUDGET`
    withdrawal steps (status ``budget_exceeded`` beyond).
    """
    law = GentSchultz(params.n)
    chi0 = groups.chi0(params.w0, reduced_modulus, radius)
    omega_check = float(groups.omega_check(frequency_hz, params.v0, radius))
    h1_um = np.asarray(h1_um, dtype=float)
    eta1 = h1_um * 1e-6 / radius
    rows = []
    for h1, e in zip(h1_um, eta1, strict=True):
        result = simulated_pulloff(Problem(law, chi0, float(e), omega_check, fixation), max_steps=FAMILY_BUDGET)
        rows += _record_rows(result, np.asarray([h1]))
        if progress is not None:
            progress.advance(result.steady_states or 0, f"{frequency_hz:g} Hz, h1 = {h1:g} um: {result.status}, "
                                                        f"P/P_JKR = {float(result.pulloff_ratio):.6g}")
    if predictions:
        rows += _predicted_rows(params, frequency_hz, h1_um, fixation, radius=radius, reduced_modulus=reduced_modulus)
    table = pd.DataFrame(rows).assign(frequency_hz=frequency_hz, **fixation.csv_constants)
    table["pulloff_mN"] = table["pulloff_ratio"] * jkr_mN(params.w0, radius)
    return table.reindex(columns=COLUMNS)


def _predicted_rows(params: GentSchultzParameters, frequency_hz: float, h1_um: np.ndarray,
                    fixation: Fixation, *, radius: float,
                    reduced_modulus: float) -> list[dict[str, Any]]:
    """The prediction rows of :func:`pulloff_table` (module docstring), one per model and amplitude."""
    if fixation.is_rigid:
        return [row for model in levels.names("virtual_pulloff", fixation.kind) if model != "simulation"
                for row in _record_rows(predict_pulloff(model, params, frequency_hz, h1_um, radius=radius,
                                                        reduced_modulus=reduced_modulus), h1_um)]
    law = GentSchultz(params.n)
    chi0 = groups.chi0(params.w0, reduced_modulus, radius)
    eta1 = h1_um * 1e-6 / radius
    omega_check = float(groups.omega_check(frequency_hz, params.v0, radius))
    return [row for model in levels.names("virtual_pulloff", fixation.kind) if model != "simulation"
            for h, e in zip(h1_um, eta1, strict=True)
            for row in _record_rows(_compliant_prediction(model, fixation, chi0, float(e), omega_check, law),
                                    np.asarray([h]))]


def _compliant_prediction(model: str, fixation: Fixation, chi0: float, eta1: float, omega_check: float,
                          law: GentSchultz) -> Pulloff:
    """The pull-off ``model`` predicts for the spring fixation (module docstring): a scalar record.

    ``leading``: Eqs. (67)–(69) with (71); ``refined``: Eq. (90) at a_m = a_cr with (71).
    """
    if model == "leading":
        return pulloff_leading(eta1, chi0, law, fixation, omega_check)
    if model == "refined":
        return _refined_compliant_pulloff(fixation.omega_bar(omega_check), fixation, chi0, eta1, law)
    raise ValueError(f"no compliant pull-off prediction for model level {model!r}")


def published_pulloffs(table: pd.DataFrame, frequency_hz: float) -> dict[float, tuple[str, float]]:
    """{h1_um: (status, P_cr/|P_JKR|)} of the simulated rows of a virtual pull-off table at one frequency.

    ``table``: the CSV of the virtual pull-off rules (columns model, frequency_hz, h1_um, status, pulloff_ratio), whose
    ``simulation`` rows are :func:`simulated_pulloff`'s; read where a later experiment needs the same families
    (the withdrawal's V -> 0 value, the base rig of the rig comparison) instead of tracing them again.
    """
    rows = table[(table["model"] == "simulation") & (table["frequency_hz"] == frequency_hz)]
    return {float(h1): (str(status), float(ratio))
            for h1, status, ratio in zip(rows["h1_um"], rows["status"], rows["pulloff_ratio"], strict=True)}
