"""The numbers behind each figure.

One module per figure (or pair of figures sharing a solve), so a rule that computes one figure's table depends on
the model code of that figure only.

A ``figN_table`` function computes the numbers of Fig. N from model parameters and returns the
DataFrame the pipeline writes as ``results/figN/figN.csv``; the drawings are in
:mod:`vibroadhesion.pipeline.figures` and never recompute with a solver.
"""

from vibroadhesion.models.refined import APPLICABILITY_LIMIT

__all__ = ["APPLICABILITY_LIMIT"]
