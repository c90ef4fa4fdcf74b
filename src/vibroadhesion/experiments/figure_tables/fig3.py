"""Fig. 3: the J-integrals of the Gent–Schultz law (Eqs. 28, 29, 36, 77) on a grid of Abar."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from vibroadhesion.core.integrals import j_integrals

FIG3_COLUMNS = ["n", "Abar", "J0", "Jc1", "J1"]


def fig3_table(exponents: Sequence[float], Abar: np.ndarray) -> pd.DataFrame:
    """J0, Jc1, J1 (Eqs. 28, 29, 36 for the Gent–Schultz law, Eq. 77) on ``Abar`` for each n."""
    frames = []
    for n in sorted(set(float(n) for n in exponents)):
        j0, jc1, j1 = j_integrals(Abar, n)
        frames.append(pd.DataFrame({"n": n, "Abar": Abar, "J0": j0, "Jc1": jc1, "J1": j1}))
    return pd.concat(frames, ignore_index=True)[FIG3_COLUMNS]
