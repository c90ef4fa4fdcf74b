"""Fig. 4: pull-off amplification against the base amplitude (Eqs. 71-72, 106, exact averaging)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from vibroadhesion.core import groups
from vibroadhesion.core.jkr import pulloff_force
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters, Model, PulloffPrediction, predict_pulloff
from vibroadhesion.models import exact_averaging

FIG4_COLUMNS = ["model", "frequency_hz", "h1_um", "Abar_cr", "sqrt_w_eff_ratio", "pulloff_ratio", "pulloff_mN"]


def fig4_table(
    params: Mapping[Model, GentSchultzParameters],
    frequencies_hz: Sequence[float],
    h1_um: np.ndarray,
    *,
    radius: float,
    reduced_modulus: float,
) -> pd.DataFrame:
    """Fig. 4's table: pull-off against amplitude for every model level.

    Leading-order curve (Eqs. 71–72, no frequency), refined curves (Eq. 106) per frequency, and the
    exact-averaging curve (the exact high-frequency limit with the paper's criterion a_m = a_cr,
    :func:`vibroadhesion.models.exact_averaging.pulloff_at_critical_radius`). Column ``sqrt_w_eff_ratio`` is
    sqrt(w_eff/w0) at detachment: J0(Abar_cr) for the J-integral levels, alpha* for exact averaging.
    """
    geometry = {"radius": radius, "reduced_modulus": reduced_modulus}
    frames = []
    lead = predict_pulloff("leading", params["leading"], np.nan, h1_um, **geometry)
    frames.append(_fig4_frame("leading", np.nan, h1_um, lead))
    p = params["leading"]
    exact = exact_averaging.pulloff_at_critical_radius(np.asarray(h1_um) * 1e-6 / radius,
                                                       groups.chi0(p.w0, reduced_modulus, radius), GentSchultz(p.n))
    frames.append(_fig4_frame("exact_averaging", np.nan, h1_um, PulloffPrediction(
        exact.abar, exact.alpha, exact.ratio, -pulloff_force(p.w0, radius) * exact.ratio * 1e3)))
    for f in frequencies_hz:
        refined = predict_pulloff("refined", params["refined"], f, h1_um, **geometry)
        frames.append(_fig4_frame("refined", f, h1_um, refined))
    return pd.concat(frames, ignore_index=True)[FIG4_COLUMNS]


def _fig4_frame(model: str, frequency: float, h1_um: np.ndarray, pred: PulloffPrediction) -> pd.DataFrame:
    return pd.DataFrame(
        {"model": model, "frequency_hz": frequency, "h1_um": h1_um, "Abar_cr": pred.abar_cr,
         "sqrt_w_eff_ratio": pred.j0, "pulloff_ratio": pred.ratio, "pulloff_mN": pred.pulloff_mN}
    )
