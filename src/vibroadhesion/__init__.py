"""Reference implementation of "An asymptotic model of vibroadhesion" (Argatov, Papangelo, Ciavarella).

Modules, one per idea: :mod:`~vibroadhesion.ratelaw` (Eq. 6, Eqs. 73–75),
:mod:`~vibroadhesion.integrals` (Eqs. 28, 29, 36), :mod:`~vibroadhesion.jkr` (Eqs. 4, 5, 60, 70),
:mod:`~vibroadhesion.groups` (Eqs. 64–66, 81, 86, 97, 105), :mod:`~vibroadhesion.roots`,
:mod:`~vibroadhesion.leading_order` (Eqs. 71–72), :mod:`~vibroadhesion.refined` (Eq. 106),
:mod:`~vibroadhesion.pulloff`, :mod:`~vibroadhesion.fitting`, :mod:`~vibroadhesion.data`.
"""

__version__ = "0.1.0"
