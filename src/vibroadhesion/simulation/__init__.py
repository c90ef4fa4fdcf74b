"""The full model, Eqs. (4)–(6), integrated in time: periodic steady states by shooting, transients.

Floquet multipliers and contact loss are reported with every steady state.

Modules, each importing only from those before it:

* :mod:`~vibroadhesion.simulation.model`: the nondimensional model (derivation), the constants of a
  :class:`vibroadhesion.core.problem.Problem`, the contact kernel and the static state;
* :mod:`~vibroadhesion.simulation.kernel`: the right-hand sides and DOP853 compiled with numba;
* :mod:`~vibroadhesion.simulation.excitation`: the excitation switched on or off or ramped during a withdrawal;
* :mod:`~vibroadhesion.simulation.integrators`: one period in scaled variables (right-hand sides,
  Jacobians) and the choice between the compiled DOP853, the Fortran DOP853 and
  :func:`scipy.integrate.solve_ivp`;
* :mod:`~vibroadhesion.simulation.orbits`: a period as a :class:`~vibroadhesion.core.records.SteadyState`
  with its :class:`~vibroadhesion.core.records.OrbitDiagnostics` (means, harmonics, extremes), the
  frozen-contact start of the shooting, and :func:`transient`;
* :mod:`~vibroadhesion.simulation.shooting`: :func:`steady_state`, the periodic orbit as a fixed
  point of the one-period map (rigid and compliant fixation).

Layer 3: imports from the layers below (numerics, core, models).
"""

from vibroadhesion.simulation.model import (
    NoStaticContactError,
    StaticState,
    static_state,
)
from vibroadhesion.simulation.orbits import Transient, transient
from vibroadhesion.simulation.shooting import steady_state

__all__ = [
    "NoStaticContactError",
    "StaticState",
    "Transient",
    "static_state",
    "steady_state",
    "transient",
]
