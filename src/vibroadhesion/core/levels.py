"""The model levels of the package, one entry each: adding a level is one entry here and its module.

Every list of levels -- the rows of the rigid validation grid, the predictions next to the virtual
pull-off, the fits, the columns of the report, the fit jobs of the Snakemake rules -- is a call of
:func:`names` with a role, in the canonical order of :data:`LEVELS`, which is the row order of every
artefact: rigid_grid.csv and speed_vs_error.csv (``validation_rigid``: simulation, leading, refined,
exact_hb, exact_averaging), virtual_pulloff*.csv (``virtual_pulloff``, of the levels that support the
fixation: the simulated rows first, then level by level), fits.csv (``fit``). Fig. 4 (``fig4``) draws
the frequency-independent curves first, then one curve per test frequency: :func:`fig4_names`.

Each level says which kinds of fixation of the indenter (:class:`vibroadhesion.core.fixation.Fixation`)
its model covers (``fixations``): the exact harmonic balance and the exact averaging are models of the
rigidly fixed contact; the leading order covers every fixation (Sec. 3.1), the refined model and the
simulation the rigid and the spring-mass-dashpot ones (Secs. 3.5-3.7). :func:`names` with a fixation
keeps the levels that support it.

Functions are referenced as ``"module:function"`` strings and imported on first use, so this module
imports the standard library only and Snakemake reads it at DAG time. Signatures, at the rigidly
fixed nominal point contact (Eqs. 4-11, 78) and its pull-off:

* ``steady_state(eta1, omega_check, chi0, law) -> SteadyState``;
* ``pulloff(eta1, chi0, law) -> Pulloff``, or ``pulloff(eta1, chi0, omega_check, law)`` for a
  frequency-dependent level; the simulation's pull-off is the virtual experiment,
  ``simulated_pulloff(problem)`` (:class:`vibroadhesion.core.problem.Problem`).

A module that resolves the functions of a role declares it in ``LEVEL_FUNCTIONS`` (pairs of role
and ``"steady_state"``/``"pulloff"``): the modules :func:`modules` names are then part of its code
for the Snakemake rules (:mod:`vibroadhesion.pipeline.imports`), although no import statement names
them.

Layer 1: imports only the standard library.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

if TYPE_CHECKING:
    from vibroadhesion.core.fixation import FixationKind

Cost = Literal["algebraic", "quadrature", "simulation"]
Role = Literal["validation_rigid", "virtual_pulloff", "fit", "fig4"]
Function = Literal["steady_state", "pulloff"]


@dataclass(frozen=True)
class ModelLevel:
    """One model level: its CSV name, label, functions, fixations, whether omega enters it, cost class and roles.

    ``frequency_dependent`` False: the level does not depend on omega R/v0 (Eq. 105), so v0 cannot be
    identified from it. ``cost`` (measured at the 15 test points, results/benchmarks/speed_vs_error.csv):
    ``algebraic`` ~0.25 ms per point, ``quadrature`` ~0.5 ms (exact averaging, tabulated) to ~10 ms,
    ``simulation`` ~30 ms and more; the speed-against-error figure marks each level by its class and names
    it by its ``label`` (benchmarks/speed_vs_error.py; the CSVs keep ``name``).
    ``fit``: the level is fitted to the measured rows, and its fit may supply the parameters of the figures
    (``fit.figures_use`` of the config names one of them).
    """

    name: str  # CSV value of ``model``; never renamed (artefacts)
    label: str  # for humans: figure legends
    steady_state: str | None  # "module:function", or None
    pulloff: str | None  # "module:function", or None
    fixations: frozenset[FixationKind]  # the kinds of fixation the level's model covers
    frequency_dependent: bool
    cost: Cost
    roles: frozenset[Role]

    def steady_state_function(self) -> Callable[..., Any]:
        """The level's steady-state function, imported on first use."""
        return _resolve(self.steady_state, self.name, "steady_state")

    def pulloff_function(self) -> Callable[..., Any]:
        """The level's pull-off function, imported on first use."""
        return _resolve(self.pulloff, self.name, "pulloff")


_VALIDATION_AND_VIRTUAL_PULLOFF: frozenset[Role] = frozenset({"validation_rigid", "virtual_pulloff"})
_RIGID: frozenset[FixationKind] = frozenset({"rigid"})
_RIGID_AND_COMPLIANT: frozenset[FixationKind] = frozenset({"rigid", "compliant"})

#: The levels in canonical order (the row order of every artefact, module docstring).
LEVELS: tuple[ModelLevel, ...] = (
    ModelLevel("simulation", "simulation of the full model (Eqs. 4-11)",
               "vibroadhesion.experiments.validation:simulated_nominal_point_contact",
               "vibroadhesion.experiments.virtual_pulloff:simulated_pulloff", _RIGID_AND_COMPLIANT, True,
               "simulation", _VALIDATION_AND_VIRTUAL_PULLOFF | {"fit"}),
    ModelLevel("leading", "leading order, Eqs. (55), (71)-(72)",
               "vibroadhesion.models.refined:leading_nominal_point_contact",
               "vibroadhesion.models.leading_pulloff:pulloff_leading", frozenset({"rigid", "compliant", "free"}),
               False, "algebraic", _VALIDATION_AND_VIRTUAL_PULLOFF | {"fit", "fig4"}),
    ModelLevel("refined", "refined, Eqs. (106), (122)-(123)",
               "vibroadhesion.models.refined:nominal_point_contact",
               "vibroadhesion.models.refined:pulloff_refined", _RIGID_AND_COMPLIANT, True, "algebraic",
               _VALIDATION_AND_VIRTUAL_PULLOFF | {"fit", "fig4"}),
    ModelLevel("exact_hb", "exact harmonic balance, Eqs. (125)-(126)",
               "vibroadhesion.models.exact_harmonic_balance:rigid_fixation", None, _RIGID, True, "quadrature",
               frozenset({"validation_rigid"})),
    ModelLevel("exact_averaging", "exact high-frequency averaging, a_m = a_cr",
               "vibroadhesion.models.exact_averaging:nominal_point_contact",
               "vibroadhesion.models.exact_averaging:pulloff_at_critical_radius", _RIGID, False, "quadrature",
               frozenset({"validation_rigid", "virtual_pulloff", "fit", "fig4"})),
    ModelLevel("exact_averaging_force_minimum", "exact averaging, force-controlled detachment", None,
               "vibroadhesion.models.exact_averaging:pulloff_at_force_minimum", _RIGID, False, "quadrature",
               frozenset({"virtual_pulloff", "fit"})),
)


def level(name: str) -> ModelLevel:
    """The level called ``name``; a ValueError names the known levels."""
    for entry in LEVELS:
        if entry.name == name:
            return entry
    raise ValueError(f"unknown model level {name!r}; expected one of {[entry.name for entry in LEVELS]}")


def names(role: Role, fixation: FixationKind | None = None) -> tuple[str, ...]:
    """The levels that take part in ``role``, in canonical order; with ``fixation``, those that support it."""
    return tuple(entry.name for entry in LEVELS
                 if role in entry.roles and (fixation is None or fixation in entry.fixations))


def fig4_names() -> tuple[str, ...]:
    """Fig. 4's curves in row order: the frequency-independent levels, then the frequency-dependent ones."""
    return tuple(sorted(names("fig4"), key=lambda name: level(name).frequency_dependent))


def modules(role: Role, function: Function) -> tuple[str, ...]:
    """The modules that implement ``function`` of the levels of ``role`` (sorted, without duplicates)."""
    references = (getattr(level(name), function) for name in names(role))
    return tuple(sorted({reference.split(":")[0] for reference in references if reference is not None}))


def _resolve(reference: str | None, name: str, function: Function) -> Callable[..., Any]:
    """The function of a ``"module:function"`` reference; a ValueError when the level has none."""
    if reference is None:
        raise ValueError(f"model level {name!r} has no {function} function")
    module, attribute = reference.split(":")
    found: Callable[..., Any] = getattr(importlib.import_module(module), attribute)
    return found
