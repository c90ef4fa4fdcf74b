"""Dynamic contact stiffness of the rigidly fixed contact (Sec. 3.7, Eqs. 114–121).

The complex stiffness S* = S' + i S'' is the ratio of the complex force and indentation
oscillations (Eq. 114). From Eq. (117), with r_delta = delta_s/delta_c and r_P = P_s/P_c,

    S'  / (P_c/delta_c) = (1 + r_P r_delta) / (1 + r_delta^2)                       Eq. (118)
    S'' / (P_c/delta_c) = (r_delta - r_P)   / (1 + r_delta^2)

and P_c/delta_c = 2 E* a_m (Eq. 119), so both are returned relative to 2 E* a_m. The ratios
follow from Eqs. (93)–(96):

    r_delta = -6^(2/3) Abar abar_m^(1/2) (1 - J1/(4 abar_m^(3/2))) / (omega_check chi0 Jc1)   Eq. (120)
    r_P     = -6^(2/3) Abar abar_m^(1/2) (1 - 3J1/(4 abar_m^(3/2))) / (omega_check chi0 Jc1)  Eq. (121)

The phase is arg S* = phi_P + phi_delta (Eq. 114). Limits (tested): omega_check -> infinity
gives S'/(2E* a_m) -> 1, the flat-punch stiffness of Greenwood and Johnson; omega_check -> 0
gives (1 - J1/(4 abar_m^(3/2)))^-1 (1 - 3J1/(4 abar_m^(3/2))), which is 1/3 as Abar -> 0.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.core.integrals import j_integrals_for_law
from vibroadhesion.core.ratelaw import RateLaw

Array = NDArray[np.float64]


class DynamicStiffness(NamedTuple):
    """Dynamic contact stiffness S* = S' + i S'' relative to 2 E* a_m, and its phase (Eqs. 117–121)."""

    S_storage_rel: Array  # S' / (2 E* a_m)
    S_loss_rel: Array  # S'' / (2 E* a_m)
    phase_rad: Array  # arg S* = atan2(S'', S')


def dynamic_stiffness(
    Abar: ArrayLike, abar_m: ArrayLike, chi0: float, omega_check: ArrayLike, law: RateLaw
) -> DynamicStiffness:
    """Storage and loss stiffness relative to 2 E* a_m and the phase, Eqs. (117)–(121).

    ``Abar`` must be positive: at zero amplitude the ratio of Eq. (120) is 0/0 and its limit
    depends on how the amplitude vanishes.
    """
    Abar = np.asarray(Abar, dtype=float)
    abar_m = np.asarray(abar_m, dtype=float)
    if np.any(Abar <= 0):
        raise ValueError("the dynamic stiffness needs Abar > 0 (Eq. 120 is 0/0 at zero amplitude)")
    _, jc1, j1 = j_integrals_for_law(Abar, law)
    common = -(6.0 ** (2 / 3)) * Abar * np.sqrt(abar_m) / (np.asarray(omega_check, dtype=float) * chi0 * jc1)
    q = j1 / (4.0 * abar_m**1.5)
    r_delta, r_p = common * (1.0 - q), common * (1.0 - 3.0 * q)
    denominator = 1.0 + r_delta**2
    storage = (1.0 + r_p * r_delta) / denominator
    loss = (r_delta - r_p) / denominator
    return DynamicStiffness(storage, loss, np.arctan2(loss, storage))
