"""Figs. 6 and 7: rigidly fixed indenter, refined model.

Nominal point contact (Eqs. 122-123, 49, corrected 98) and the pull-off estimate (Eq. 106).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.models.refined import nominal_point_contact, pulloff_refined

FIG6_COLUMNS = ["h1_um", "omega_check", "Abar", "abar_m", "w_eff_ratio", "A_over_am"]
FIG7_COLUMNS = ["h1_um", "omega_check", "Abar_cr", "pulloff_ratio", "A_over_am"]


def fig6_table(
    h1_um: Sequence[float], omega_check: np.ndarray, *, chi0: float, radius: float, n: float
) -> pd.DataFrame:
    """Nominal point contact of a rigidly fixed indenter (Eqs. 122–123, 49, corrected 98)."""
    h1 = np.asarray(h1_um, dtype=float)[:, None]
    sol = nominal_point_contact(h1 * 1e-6 / radius, omega_check[None, :], chi0, GentSchultz(n))
    return pd.DataFrame(
        {"h1_um": np.broadcast_to(h1, sol.Abar.shape).ravel(),
         "omega_check": np.broadcast_to(omega_check, sol.Abar.shape).ravel(),
         "Abar": sol.Abar.ravel(), "abar_m": sol.abar_m.ravel(), "w_eff_ratio": sol.w_eff_ratio.ravel(),
         "A_over_am": sol.A_over_am.ravel()}
    )[FIG6_COLUMNS]


def fig7_table(
    h1_um: Sequence[float], omega_check: np.ndarray, *, chi0: float, radius: float, n: float
) -> pd.DataFrame:
    """Refined pull-off estimate against omega_check (Eq. 106) for each amplitude, with A/a_m at detachment."""
    h1 = np.asarray(h1_um, dtype=float)[:, None]
    est = pulloff_refined(h1 * 1e-6 / radius, chi0, omega_check[None, :], GentSchultz(n))
    return pd.DataFrame(
        {"h1_um": np.broadcast_to(h1, est.Abar_cr.shape).ravel(),
         "omega_check": np.broadcast_to(omega_check, est.Abar_cr.shape).ravel(),
         "Abar_cr": est.Abar_cr.ravel(), "pulloff_ratio": est.pulloff_ratio.ravel(), "A_over_am": est.A_over_am.ravel()}
    )[FIG7_COLUMNS]
