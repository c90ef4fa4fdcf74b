"""Pull-off force in physical units from each model level that gives one (Eqs. 70–72, 106).

* ``leading``: Abar_cr from Eq. (72), frequency independent;
* ``refined``: Abar_cr from Eq. (106), through omega_check = omega R / v0;
* ``exact_averaging``: the paper's criterion a_m = a_cr (Eqs. 60–61) with the exact
  high-frequency w_eff (:func:`vibroadhesion.models.exact_averaging.pulloff_at_critical_radius`);
* ``exact_averaging_force_minimum``: force-controlled detachment of the exact averaged model,
  the most tensile mean force over a_m (:func:`vibroadhesion.models.exact_averaging.pulloff_at_force_minimum`),
  which the simulated pull-off approaches as omega_check -> infinity.

The first three give P_cr = P_cr^JKR w_eff/w0 with |P_cr^JKR| = (3 pi / 2) R w0 (Eqs. 70–71); the
last gives P_cr = P_m at the minimum. The exact-averaging levels are frequency independent, so
v0 does not enter them either.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.core import groups
from vibroadhesion.core.jkr import pulloff_force
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import Pulloff
from vibroadhesion.models import exact_averaging
from vibroadhesion.models.leading_pulloff import pulloff_leading
from vibroadhesion.models.refined import pulloff_refined

Model = Literal["leading", "refined", "exact_averaging", "exact_averaging_force_minimum"]
MODELS: tuple[Model, ...] = ("leading", "refined", "exact_averaging", "exact_averaging_force_minimum")


@dataclass(frozen=True)
class GentSchultzParameters:
    """Parameters of the Gent–Schultz law, Eq. (73): w0 in J/m^2, n, v0 in m/s."""

    w0: float
    n: float
    v0: float


def predict_pulloff(
    model: Model,
    params: GentSchultzParameters,
    frequency_hz: ArrayLike,
    h1_um: ArrayLike,
    *,
    radius: float,
    reduced_modulus: float,
) -> Pulloff:
    """Pull-off of ``model`` at base amplitudes ``h1_um`` (um) and frequencies (Hz), broadcast (Eqs. 49, 71)."""
    law = GentSchultz(params.n)
    chi0 = groups.chi0(params.w0, reduced_modulus, radius)
    eta1 = groups.eta1(np.asarray(h1_um, dtype=float) * 1e-6, radius)
    if model == "refined":
        return pulloff_refined(eta1, chi0, groups.omega_check(frequency_hz, params.v0, radius), law)
    if model in MODELS:
        eta1_each = np.broadcast_arrays(eta1, np.asarray(frequency_hz, dtype=float))[0]
        return _frequency_independent(model, eta1_each, chi0, law)
    raise ValueError(f"unknown model {model!r}; expected one of {MODELS}")


def pulloff_mN(pulloff: Pulloff, w0: float, radius: float) -> NDArray[np.float64]:
    """|P_cr| in mN: P_cr/P_cr^JKR times |P_cr^JKR| = (3 pi/2) R w0 (Eqs. 70–71)."""
    return -pulloff_force(w0, radius) * pulloff.pulloff_ratio * 1e3


def _frequency_independent(model: Model, eta1: NDArray[np.float64], chi0: float, law: GentSchultz) -> Pulloff:
    """The pull-off of a level without omega, solved once per distinct eta1 and scattered back."""
    distinct, back = np.unique(eta1, return_inverse=True)
    detachment = {"leading": pulloff_leading,
                  "exact_averaging": exact_averaging.pulloff_at_critical_radius,
                  "exact_averaging_force_minimum": exact_averaging.pulloff_at_force_minimum}[model]
    return detachment(distinct, chi0, law).taken(np.reshape(back, eta1.shape))
