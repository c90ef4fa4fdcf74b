"""Reference implementation of "An asymptotic model of vibroadhesion" (Argatov, Papangelo, Ciavarella).

Sub-packages, one layer each, in the direction the data flows (a module imports only from its own
layer and the layers listed before it; ``tests/test_layers.py`` enforces it):

* :mod:`vibroadhesion.numerics`: roots, continuation, progress (no physics);
* :mod:`vibroadhesion.core`: rate law, J-integrals, JKR, dimensionless groups, the result records and
  the registry of model levels;
* :mod:`vibroadhesion.models`: the asymptotic model levels of the paper;
* :mod:`vibroadhesion.simulation`: the full model in time (ground truth);
* :mod:`vibroadhesion.experiments`: pull-off, fit, virtual pull-off, validation, identifiability;
* :mod:`vibroadhesion.pipeline`: files, figures, report and the steps the Snakemake rules run.
"""

__version__ = "0.1.0"
__all__ = ["core", "experiments", "models", "numerics", "pipeline", "simulation"]
