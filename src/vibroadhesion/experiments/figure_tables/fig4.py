"""Fig. 4: pull-off amplification against the base amplitude (Eqs. 71-72, 106, exact averaging)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from vibroadhesion.core import groups
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import Pulloff
from vibroadhesion.experiments.pulloff import GentSchultzParameters, Model, predict_pulloff, pulloff_mN
from vibroadhesion.models import exact_averaging

FIG4_COLUMNS = ["model", "frequency_hz", "h1_um", "Abar_cr", "J0", "ratio", "pulloff_mN"]


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
    :func:`vibroadhesion.models.exact_averaging.pulloff_at_critical_radius`; its J0 column is sqrt(w_eff/w0)).
    """
    geometry = {"radius": radius, "reduced_modulus": reduced_modulus}
    frames = []
    lead = predict_pulloff("leading", params["leading"], np.nan, h1_um, **geometry)
    frames.append(_fig4_frame("leading", np.nan, h1_um, lead, params["leading"].w0, radius))
    p = params["leading"]
    exact = exact_averaging.pulloff_at_critical_radius(np.asarray(h1_um) * 1e-6 / radius,
                                                       groups.chi0(p.w0, reduced_modulus, radius), GentSchultz(p.n))
    frames.append(_fig4_frame("exact_averaging", np.nan, h1_um, exact, p.w0, radius))
    for f in frequencies_hz:
        refined = predict_pulloff("refined", params["refined"], f, h1_um, **geometry)
        frames.append(_fig4_frame("refined", f, h1_um, refined, params["refined"].w0, radius))
    return pd.concat(frames, ignore_index=True)[FIG4_COLUMNS]


def _fig4_frame(model: str, frequency: float, h1_um: np.ndarray, pred: Pulloff, w0: float,
                radius: float) -> pd.DataFrame:
    """One curve of Fig. 4: the record's Abar_cr, sqrt(w_eff/w0), P_cr/P_cr^JKR and |P_cr| in mN (Eqs. 70-71)."""
    return pd.DataFrame(
        {"model": model, "frequency_hz": frequency, "h1_um": h1_um, "Abar_cr": pred.Abar_cr,
         "J0": pred.sqrt_w_eff_ratio, "ratio": pred.pulloff_ratio, "pulloff_mN": pulloff_mN(pred, w0, radius)}
    )
