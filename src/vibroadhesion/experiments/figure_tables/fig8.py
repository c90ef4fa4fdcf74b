"""Fig. 8: dynamic contact stiffness (Eqs. 117-121) along the Fig. 6 solution."""

from __future__ import annotations

import pandas as pd

from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.models.stiffness import dynamic_stiffness

FIG8_COLUMNS = ["h1_um", "omega_check", "S_storage_rel", "S_loss_rel", "phase_rad"]


def fig8_table(fig6: pd.DataFrame, *, chi0: float, n: float) -> pd.DataFrame:
    """Dynamic contact stiffness (Eqs. 117–121) along the Fig. 6 solution: no new solve."""
    s = dynamic_stiffness(fig6["Abar"].to_numpy(), fig6["abar_m"].to_numpy(), chi0, fig6["omega_check"].to_numpy(),
                          GentSchultz(n))
    return pd.DataFrame({"h1_um": fig6["h1_um"], "omega_check": fig6["omega_check"], "S_storage_rel": s.S_storage_rel,
                         "S_loss_rel": s.S_loss_rel, "phase_rad": s.phase_rad})[FIG8_COLUMNS]
