"""Pull-off force in physical units from each model level that gives one (Eqs. 70–72, 106).

* ``leading``: Abar_cr from Eq. (72), frequency independent;
* ``refined``: Abar_cr from Eq. (106), through omega_check = omega R / v0;
* ``exact_averaging``: the paper's criterion a_m = a_cr (Eqs. 60–61) with the exact
  high-frequency w_eff (:func:`vibroadhesion.models.exact_averaging.pulloff_at_critical_radius`);
* ``exact_averaging_force_minimum``: force-controlled detachment of the exact averaged model,
  the most tensile mean force over a_m (:func:`vibroadhesion.models.exact_averaging.pulloff_at_force_minimum`),
  which the simulated pull-off approaches as omega_check -> infinity.

* ``simulation``: the virtual pull-off of the full model (Eqs. 4-11, rigid fixation,
  :func:`vibroadhesion.experiments.virtual_pulloff.simulated_pulloff`), once per distinct (f, h1) pair.

The first three give P_cr = P_cr^JKR w_eff/w0 with |P_cr^JKR| = (3 pi / 2) R w0 (Eqs. 70–71); the
last gives P_cr = P_m at the minimum. The exact-averaging levels are frequency independent, so
v0 does not enter them either.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.core import groups, levels
from vibroadhesion.core.jkr import pulloff_force
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import Pulloff, stacked

#: The registry's functions this module resolves (vibroadhesion.core.levels): the pull-off of every fitted level.
LEVEL_FUNCTIONS = (("fit", "pulloff"),)


@dataclass(frozen=True)
class GentSchultzParameters:
    """Parameters of the Gent–Schultz law, Eq. (73): w0 in J/m^2, n, v0 in m/s."""

    w0: float
    n: float
    v0: float


def predict_pulloff(
    model: str,
    params: GentSchultzParameters,
    frequency_hz: ArrayLike,
    h1_um: ArrayLike,
    *,
    radius: float,
    reduced_modulus: float,
) -> Pulloff:
    """Pull-off of ``model`` (a level of role ``fit``) at base amplitudes ``h1_um`` (um) and frequencies (Hz).

    Broadcast over amplitudes and frequencies (Eqs. 49, 71). Every level is solved once per distinct
    condition and scattered back, so replicated rows cost nothing: per distinct (amplitude, omega_check)
    for the frequency-dependent levels, per distinct amplitude for the others.
    """
    if model not in levels.names("fit"):
        raise ValueError(f"unknown model {model!r}; expected one of {levels.names('fit')}")
    entry = levels.level(model)
    law = GentSchultz(params.n)
    chi0 = groups.chi0(params.w0, reduced_modulus, radius)
    eta1 = groups.eta1(np.asarray(h1_um, dtype=float) * 1e-6, radius)
    frequency = np.asarray(frequency_hz, dtype=float)
    omega = groups.omega_check(frequency, params.v0, radius) if entry.frequency_dependent else np.zeros_like(frequency)
    eta1_each, omega_each = np.broadcast_arrays(eta1, np.asarray(omega, dtype=float))
    distinct, back = np.unique(np.stack([eta1_each.ravel(), omega_each.ravel()], axis=1), axis=0, return_inverse=True)
    e, o = distinct[:, 0], distinct[:, 1]
    if entry.cost == "simulation":
        pulloff = stacked([replace(entry.pulloff_function()(Problem(law, chi0, float(ek), float(ok))),
                                   steady_states=None) for ek, ok in zip(e, o, strict=True)])
    elif entry.frequency_dependent:
        pulloff = entry.pulloff_function()(e, chi0, o, law)
    else:
        pulloff = entry.pulloff_function()(e, chi0, law)
    return pulloff.taken(np.reshape(back, eta1_each.shape))


def jkr_mN(w0: float, radius: float) -> float:
    """|P_cr^JKR| = (3 pi/2) R w0 in mN (Eq. 70): the force scale of the pull-off ratio (Eq. 71)."""
    return float(-pulloff_force(w0, radius)) * 1e3


def pulloff_mN(pulloff: Pulloff, w0: float, radius: float) -> NDArray[np.float64]:
    """|P_cr| in mN: P_cr/P_cr^JKR times |P_cr^JKR| = (3 pi/2) R w0 (Eqs. 70–71)."""
    return -pulloff_force(w0, radius) * pulloff.pulloff_ratio * 1e3
