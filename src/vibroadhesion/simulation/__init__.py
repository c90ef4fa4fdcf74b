"""The full model, Eqs. (4)–(6), integrated in time: periodic steady states by shooting, transients,
Floquet multipliers, contact loss reported.

Layer 3: imports from the layers below (numerics, core, models).
"""

__all__ = ["simulate"]
