"""Pull-off force in physical units from either asymptotic level (Eqs. 70–72, 106).

The two model levels differ only in the equation that fixes Abar_cr: Eq. (72) (``leading``,
frequency independent) or Eq. (106) (``refined``, through omega_check = omega R / v0). Both
give P_cr = P_cr^JKR J0(Abar_cr)^2 with |P_cr^JKR| = (3 pi / 2) R w0 (Eqs. 70–71).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion import groups
from vibroadhesion.jkr import pulloff_force
from vibroadhesion.leading_order import pulloff_leading
from vibroadhesion.ratelaw import GentSchultz
from vibroadhesion.refined import pulloff_refined

Model = Literal["leading", "refined"]
MODELS: tuple[Model, ...] = ("leading", "refined")


@dataclass(frozen=True)
class GentSchultzParameters:
    """Parameters of the Gent–Schultz law, Eq. (73): w0 in J/m^2, n, v0 in m/s."""

    w0: float
    n: float
    v0: float


class PulloffPrediction(NamedTuple):
    abar_cr: NDArray[np.float64]
    j0: NDArray[np.float64]
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
    if model == "leading":
        est = pulloff_leading(np.broadcast_arrays(eta1, np.asarray(frequency_hz, dtype=float))[0], chi0, law)
    elif model == "refined":
        est = pulloff_refined(eta1, chi0, groups.omega_check(frequency_hz, params.v0, radius), law)
    else:
        raise ValueError(f"unknown model {model!r}; expected one of {MODELS}")
    magnitude_mN = -pulloff_force(params.w0, radius) * est.ratio * 1e3
    return PulloffPrediction(est.abar_cr, est.j0, est.ratio, magnitude_mN)
