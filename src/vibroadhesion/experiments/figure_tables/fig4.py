"""Fig. 4: pull-off amplification against the base amplitude (Eqs. 71-72, 106, exact averaging)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from vibroadhesion.core import levels
from vibroadhesion.core.records import Pulloff
from vibroadhesion.experiments.pulloff import GentSchultzParameters, predict_pulloff, pulloff_mN

FIG4_COLUMNS = ["model", "frequency_hz", "h1_um", "Abar_cr", "sqrt_w_eff_ratio", "pulloff_ratio", "pulloff_mN",
                "A_over_am"]


def fig4_table(
    params: GentSchultzParameters,
    frequencies_hz: Sequence[float],
    h1_um: np.ndarray,
    *,
    radius: float,
    reduced_modulus: float,
) -> pd.DataFrame:
    """Fig. 4's table: pull-off against amplitude for every level of role ``fig4``, all at one parameter set.

    One set (the fit the figures use), so that the curves differ by their model only and the measured rows
    can be scaled by the one |P_cr^JKR| = (3 pi/2) R w0 of that set (Eq. 70).

    In the registry's Fig. 4 order (:func:`vibroadhesion.core.levels.fig4_names`): the frequency-independent
    curves (leading order, Eqs. 71–72; the exact high-frequency limit with the paper's criterion
    a_m = a_cr, :func:`vibroadhesion.models.exact_averaging.pulloff_at_critical_radius`) with frequency NaN,
    then the frequency-dependent ones (refined, Eq. 106) at each test frequency. Column ``sqrt_w_eff_ratio``
    is sqrt(w_eff/w0) at detachment: J0(Abar_cr) for the J-integral levels, alpha* for exact averaging. Column
    ``A_over_am`` is A/a_m at detachment where the level has a frequency (refined: the applicability of the
    asymptotic model at that test condition, A/a_m <= 0.1), NaN for the omega_check -> infinity levels.
    """
    frames = []
    for model in levels.fig4_names():
        frequencies = frequencies_hz if levels.level(model).frequency_dependent else [np.nan]
        for f in frequencies:
            pred = predict_pulloff(model, params, f, h1_um, radius=radius, reduced_modulus=reduced_modulus)
            frames.append(_fig4_frame(model, f, h1_um, pred, params.w0, radius))
    return pd.concat(frames, ignore_index=True)[FIG4_COLUMNS]


def _fig4_frame(model: str, frequency: float, h1_um: np.ndarray, pred: Pulloff, w0: float,
                radius: float) -> pd.DataFrame:
    """One curve of Fig. 4: the record's Abar_cr, sqrt(w_eff/w0), P_cr/P_cr^JKR, |P_cr| in mN (Eqs. 70-71), A/a_m."""
    return pd.DataFrame(
        {"model": model, "frequency_hz": frequency, "h1_um": h1_um, "Abar_cr": pred.Abar_cr,
         "sqrt_w_eff_ratio": pred.sqrt_w_eff_ratio, "pulloff_ratio": pred.pulloff_ratio,
         "pulloff_mN": pulloff_mN(pred, w0, radius), "A_over_am": pred.A_over_am}
    )
