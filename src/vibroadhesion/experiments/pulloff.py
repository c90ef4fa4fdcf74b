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
from typing import Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.core import groups
from vibroadhesion.core.jkr import pulloff_force
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.models import exact_averaging
from vibroadhesion.models.leading_order import PulloffEstimate, pulloff_leading
from vibroadhesion.models.refined import pulloff_refined

Model = Literal["leading", "refined", "exact_averaging", "exact_averaging_force_minimum"]
MODELS: tuple[Model, ...] = ("leading", "refined", "exact_averaging", "exact_averaging_force_minimum")


@dataclass(frozen=True)
class GentSchultzParameters:
    """Parameters of the Gent–Schultz law, Eq. (73): w0 in J/m^2, n, v0 in m/s."""

    w0: float
    n: float
    v0: float


class PulloffPrediction(NamedTuple):
    """Pull-off of one model level at each (frequency, amplitude), broadcast (Eqs. 49, 71)."""

    abar_cr: NDArray[np.float64]  # internal variable Abar at detachment
    j0: NDArray[np.float64]  # sqrt(w_eff/w0) there (J0(Abar_cr) for the J-integral levels, Eq. 49)
    ratio: NDArray[np.float64]  # P_cr / P_cr^JKR, Eq. (71)
    pulloff_mN: NDArray[np.float64]  # |P_cr| in mN


def predict_pulloff(
    model: Model,
    params: GentSchultzParameters,
    frequency_hz: ArrayLike,
    h1_um: ArrayLike,
    *,
    radius: float,
    reduced_modulus: float,
) -> PulloffPrediction:
    """Pull-off estimate of ``model`` at base amplitudes ``h1_um`` (um) and frequencies (Hz), broadcast."""
    law = GentSchultz(params.n)
    chi0 = groups.chi0(params.w0, reduced_modulus, radius)
    eta1 = groups.eta1(np.asarray(h1_um, dtype=float) * 1e-6, radius)
    if model == "refined":
        est = pulloff_refined(eta1, chi0, groups.omega_check(frequency_hz, params.v0, radius), law)
    elif model in MODELS:
        eta1_each = np.broadcast_arrays(eta1, np.asarray(frequency_hz, dtype=float))[0]
        est = _frequency_independent(model, eta1_each, chi0, law)
    else:
        raise ValueError(f"unknown model {model!r}; expected one of {MODELS}")
    magnitude_mN = -pulloff_force(params.w0, radius) * est.ratio * 1e3
    return PulloffPrediction(est.abar_cr, est.j0, est.ratio, magnitude_mN)


def _frequency_independent(model: Model, eta1: NDArray[np.float64], chi0: float, law: GentSchultz) -> PulloffEstimate:
    """Abar_cr, sqrt(w_eff/w0) and P_cr/P_cr^JKR of the levels without omega, solved once per distinct eta1."""
    distinct, back = np.unique(eta1, return_inverse=True)
    if model == "leading":
        est = pulloff_leading(distinct, chi0, law)
    else:
        detachment = {"exact_averaging": exact_averaging.pulloff_at_critical_radius,
                      "exact_averaging_force_minimum": exact_averaging.pulloff_at_force_minimum}[model]
        state = detachment(distinct, chi0, law)
        est = PulloffEstimate(state.abar, state.alpha, state.ratio)
    return PulloffEstimate(*(np.asarray(v)[back].reshape(eta1.shape) for v in est))
