"""Parameters and kernels of the model, on which every model level builds.

The Gent–Schultz rate law (Eqs. 6, 73–75), the J-integrals (Eqs. 28, 29, 36), JKR contact
(Eqs. 4, 5, 60, 70), the dimensionless groups (Eqs. 64–66, 81, 86, 97, 105), the fixation of the
indenter (:class:`vibroadhesion.core.fixation.Fixation`), the steady-state problem
(:class:`vibroadhesion.core.problem.Problem`), the two result records every model level returns
(:mod:`~vibroadhesion.core.records`) and the registry of model levels (:mod:`~vibroadhesion.core.levels`).

Layer 1: imports only from :mod:`vibroadhesion.numerics`.
"""

__all__ = ["ratelaw", "integrals", "jkr", "groups", "fixation", "problem", "records", "levels"]
