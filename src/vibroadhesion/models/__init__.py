"""The asymptotic model levels, one module per level (or per part of a level).

Leading order (steady state Eqs. 43, 50–59; pull-off Eqs. 60–72), refined rigid (Eqs. 93–94, 106,
122–123), refined compliant (Eqs. 87, 90–96), dynamic stiffness (Eqs. 117–121), exact harmonic
balance (Eqs. 125–126) and the exact high-frequency averaging (the frozen-radius cycle, its table
per exponent, and its mean state and pull-off).

Layer 2: imports from :mod:`vibroadhesion.numerics` and :mod:`vibroadhesion.core`.
"""

__all__ = [
    "leading_order",
    "leading_pulloff",
    "refined",
    "compliant",
    "stiffness",
    "exact_harmonic_balance",
    "frozen_radius",
    "frozen_radius_table",
    "exact_averaging",
]
