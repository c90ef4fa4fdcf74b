"""Base- and force-excitation rigs compared (Figs. 1, 2; Eqs. 11, 13; Appendix B made quantitative).

Both rigs force the same equation for the contact, Eq. (20): the base rig (Fig. 1) with
-h1 [(k - m omega^2) sin(omega t) + c omega cos(omega t)] (Eq. 22), the force rig (Fig. 2) with F1 sin(omega t)
(Eq. 13; its mean part F0 is Eq. 15's). A harmonic forcing of the same frequency and modulus is the
same forcing shifted in time, so the force rig with

    F1 = h1 |k - m omega^2 + i c omega| = k h1 |1 - omega_bar^2 + 2 i zeta omega_bar|          (Eqs. 22, 65)

has the base rig's periodic steady states, phase aside: the same contact-displacement amplitude at every
mean contact radius, the same a_m, w_eff and mean force, and so the same pull-off, in the full model
(the simulation) and at every order of the asymptotics (at leading order, Eq. 43 becomes
|delta_c| |D + 2 E* a_m| = |F1 - h1 D|: :meth:`vibroadhesion.core.fixation.Fixation.indentation_response`).
At equal contact-displacement amplitude the rigs therefore differ only in the drive they need,
F1/(k h1) = |1 - omega_bar^2 + 2 i zeta omega_bar|: 317 at 200 Hz for omega0 = 70.4 rad/s, 2 zeta at the
fixation's resonance, and 0 at the undamped anti-resonance omega = sqrt(k/m), where the base rig leaves the
contact spring undeformed for any h1 (Eq. B.3) while a force rig still drives it, |delta_c| = F1/(2 E* a_m).

The study (:func:`rig_comparison`) evaluates, for the stroke eta1 = h1/R at each omega_bar, three rigs
(:data:`RIGS`): ``base`` (h1), ``force_equivalent`` (F1 = k h1 |D|, the equal-amplitude force rig) and
``force_spring`` (F1 = k h1, the force the spring of the base rig would pass on with the mass at rest: the
force rig where the base rig does nothing), each at the leading order (Eqs. 43, 54, 67-71 with (II') of
:mod:`vibroadhesion.models.leading_order`) and simulated (:func:`vibroadhesion.simulation.steady_state` and the
virtual pull-off of :mod:`vibroadhesion.experiments.virtual_pulloff`). Failures are statuses, never numbers.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from vibroadhesion import simulation
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import contact_radius_ratio
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.virtual_pulloff import simulated_pulloff
from vibroadhesion.models.leading_order import steady_states
from vibroadhesion.models.leading_pulloff import pulloff_leading
from vibroadhesion.numerics.progress import ProgressBar

#: The rigs of the comparison (module docstring), in the row order of the table.
RIGS = ("base", "force_equivalent", "force_spring")
#: The numbers of a row, NaN where the level has none or failed.
NUMBERS = ("abar_m", "Abar", "w_eff_ratio", "A_over_am", "delta_amplitude", "pulloff_ratio")
#: The status of the simulated row of a contact that is not forced (:func:`static_row`).
STATIC = "static: the contact is not forced (Eq. B.3), the static state (Eq. 10) and the JKR pull-off (Eq. 71)"


def drive(rig: str, eta1: float, fixation: Fixation, omega_check: float) -> tuple[float, float]:
    """(eta1, force = F1/(E* R^2)) of ``rig`` at the stroke eta1 = h1/R (module docstring; Eqs. 13, 22, 65, 66).

    base: (eta1, 0); force_equivalent: (0, eta1 |d|), d = kappa (1 - omega_bar^2 + 2 i zeta omega_bar), i.e.
    F1 = h1 |k - m omega^2 + i c omega|; force_spring: (0, kappa eta1), i.e. F1 = k h1.
    """
    if rig == "base":
        return eta1, 0.0
    if rig == "force_equivalent":
        return 0.0, eta1 * abs(fixation.d(omega_check))
    if rig == "force_spring":
        return 0.0, fixation.kappa * eta1
    raise ValueError(f"rig must be one of {RIGS}, got {rig!r}")


def leading_row(rig: str, eta1: float, fixation: Fixation, chi0: float, law: GentSchultz,
                omega_check: float) -> dict[str, Any]:
    """The leading order of ``rig`` (Eqs. 13, 43, 54, 67-71): its first stable steady state and its pull-off.

    The steady state is the stable one of smallest a_m (the branch a loading from the static contact
    reaches, Eq. 82); ``delta_amplitude`` = R |delta_c|/a_o^2 from (II'). NaN with the status where none.
    """
    base_eta1, force = drive(rig, eta1, fixation, omega_check)
    states = steady_states(base_eta1, fixation, chi0, law, omega_check=omega_check, force=force)
    pulloff = pulloff_leading(base_eta1, chi0, law, fixation, omega_check, force=force)
    stable = np.flatnonzero(states.ok & np.asarray(states.stable, dtype=bool))
    row = {"level": "leading", "status": "ok" if stable.size else str(states.status.flat[0]),
           **dict.fromkeys(NUMBERS, math.nan), "pulloff_ratio": float(pulloff.pulloff_ratio)}
    if stable.size:
        k = int(stable[0])
        abar_m = float(states.abar_m[k])
        response = float(fixation.indentation_response(abar_m, chi0, omega_check, base_eta1, force))
        row |= {"abar_m": abar_m, "Abar": float(states.Abar[k]), "w_eff_ratio": float(states.w_eff_ratio[k]),
                "A_over_am": float(states.A_over_am[k]), "delta_amplitude": response / contact_radius_ratio(chi0)**2}
    return row


def simulated_row(rig: str, eta1: float, fixation: Fixation, chi0: float, law: GentSchultz,
                  omega_check: float, known: tuple[str, float] | None = None) -> dict[str, Any]:
    """The SIMULATED steady state of ``rig`` at the nominal point contact and its virtual pull-off (Eqs. 3', 13).

    ``delta_amplitude`` is the modulus of the first harmonic of deltabar; the status joins the steady
    state's and the pull-off's. ``known`` = (status, P_cr/|P_JKR|) of this virtual pull-off where it was traced
    already (the same family: :func:`rig_comparison`), which is then not traced again. A rig whose contact is not
    forced at any a_m (|force - eta1 d| = 0: the base rig at the undamped anti-resonance, Eq. B.3, and the
    equal-amplitude force rig there, F1 = 0) has the forcing term of Eq. (8) constant (Eq. 9 with c = 0,
    m omega^2 = k): :func:`static_row`.
    """
    base_eta1, force = drive(rig, eta1, fixation, omega_check)
    problem = Problem(law, chi0, base_eta1, omega_check, fixation, force_amplitude=force)
    if fixation.indentation_response(1.0, chi0, omega_check, base_eta1, force) == 0:
        return static_row(problem)
    row: dict[str, Any] = {"level": "simulation", **dict.fromkeys(NUMBERS, math.nan)}
    state = simulation.steady_state(problem)
    if known is None:
        pulloff = simulated_pulloff(problem)
        known = (str(pulloff.status), float(pulloff.pulloff_ratio))
    row |= {"status": f"{state.status}; pull-off {known[0]}", "pulloff_ratio": known[1]}
    if state.ok and state.orbit is not None:
        row |= {"abar_m": float(state.abar_m), "Abar": float(state.Abar), "w_eff_ratio": float(state.w_eff_ratio),
                "A_over_am": float(state.A_over_am),
                "delta_amplitude": math.hypot(state.orbit.deltabar_c, state.orbit.deltabar_s)}
    return row


def static_row(problem: Problem) -> dict[str, Any]:
    """The full model's steady state and pull-off of a contact that is not forced (Eqs. 8-10, A.4-A.7, 70, 71).

    With the forcing term of Eq. (8) constant the static equilibrium of Eq. (10) (Appendix A,
    :func:`vibroadhesion.simulation.static_state`) is the steady state: abar_m = a_0/a_o, no amplitude, w_eff = w0.
    Withdrawn quasi-statically the contact passes through static JKR states (Eqs. A.4, A.5, w = w0), whose most
    tensile force is P_cr^JKR (Eqs. 70, 71): pull-off ratio 1. Closed form, not shot (the shooting of an unforced
    undamped contact is ill-conditioned: with F1 = 0 it ended in integration_failure after 4-18 s, and the virtual
    pull-off of such a family, whose free oscillation never decays, did not finish in 100 s).
    """
    static = simulation.static_state(problem)
    return {"level": "simulation", "status": STATIC, "abar_m": static.abar_0, "Abar": 0.0, "w_eff_ratio": 1.0,
            "A_over_am": 0.0, "delta_amplitude": 0.0, "pulloff_ratio": 1.0}


def rig_comparison(cases: Sequence[tuple[Fixation, Sequence[float]]], eta1: Sequence[float], chi0: float, n: float,
                   progress: ProgressBar | None = None,
                   base_pulloffs: Mapping[tuple[float, float], tuple[str, float]] | None = None) -> pd.DataFrame:
    """Rows (zeta, omega_bar, eta1, rig, level, drive) of the comparison (module docstring).

    ``cases``: (compliant fixation, its omega_bar values); omega_check = omega_bar/nu0 (Eqs. 97, 105).
    ``drive_ratio`` = F1/(k h1) of the force rigs (NaN for the base rig), ``force`` = F1/(E* R^2).
    ``progress`` advances once per (omega_bar, eta1, rig). ``base_pulloffs``: (omega_bar, eta1) -> (status,
    P_cr/|P_JKR|) of the base rig's simulated virtual pull-off where it is known (the virtual pull-off of the
    compliant fixation at the rig's test conditions, :mod:`vibroadhesion.experiments.virtual_pulloff`: the same
    family), taken instead of tracing it again.
    """
    law, rows = GentSchultz(n), []
    for fixation, omega_bars in cases:
        for omega_bar in omega_bars:
            omega_check = omega_bar / fixation.nu0
            for e in eta1:
                for rig in RIGS:
                    base_eta1, force = drive(rig, e, fixation, omega_check)
                    key = {"kappa": fixation.kappa, "zeta": fixation.zeta, "omega_bar": omega_bar, "eta1": e,
                           "rig": rig, "force": force,
                           "drive_ratio": math.nan if rig == "base" else force / (fixation.kappa * e)}
                    known = (base_pulloffs or {}).get((omega_bar, e)) if rig == "base" else None
                    rows += [key | leading_row(rig, e, fixation, chi0, law, omega_check),
                             key | simulated_row(rig, e, fixation, chi0, law, omega_check, known)]
                    if progress is not None:
                        progress.advance(1, f"omega_bar = {omega_bar:.4g}, eta1 = {e:.3g}, {rig}")
    return pd.DataFrame(rows)


def equivalence_summary(table: pd.DataFrame) -> pd.DataFrame:
    """Per (zeta, omega_bar, level): the largest relative difference of the equal-amplitude force rig from the base rig.

    Over the strokes, in w_eff/w0, the pull-off ratio and the contact-displacement amplitude: 0 in exact
    arithmetic (module docstring), so these are the numerical differences of two independent computations, except
    where neither rig forces the contact (:func:`static_row` on both sides: 0 by construction).
    """
    keys = ["zeta", "omega_bar", "eta1", "level"]
    base = table[table["rig"] == "base"].set_index(keys)
    force = table[table["rig"] == "force_equivalent"].set_index(keys)
    differences = pd.DataFrame({f"max_rel_diff_{name}": relative_difference(force[name], base[name])
                                for name in ("w_eff_ratio", "pulloff_ratio", "delta_amplitude")})
    return differences.groupby(level=["zeta", "omega_bar", "level"]).max().reset_index()


def relative_difference(a: pd.Series, b: pd.Series) -> pd.Series:
    """|a - b| / max(|a|, |b|): 0 where both are 0 (the undamped anti-resonance: no amplitude), NaN where one is."""
    scale = np.maximum(a.abs(), b.abs())
    return ((a - b).abs() / scale.where(scale > 0, 1.0)).mask(scale == 0, 0.0)
