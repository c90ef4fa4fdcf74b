"""The two result records every model level returns: a steady state and a pull-off.

Every level -- leading order (Secs. 3.1-3.2), refined (Secs. 3.5-3.7, Eqs. 87-106, 122-123), exact
harmonic balance (Eqs. 125-126), exact high-frequency averaging and the direct simulation of
Eqs. (4)-(11) -- reports its periodic steady states as one :class:`SteadyState` and its pull-off as
one :class:`Pulloff`, with the same field names and units (``docs/notation.md``).

Fields are numpy arrays of one common shape (a scalar solve gives shape ``()``), so the vectorised
levels and the scalar ones return the same type. ``status`` is an array of strings of that shape;
the invariant "a status is never silently a number" is checked once, in ``__post_init__``: where
a status says the level has no solution, every number is NaN, and where it says ok, the defining
numbers are finite. A level turns its own exceptions (no root) into the status ``no_solution`` at
its boundary, once; it never returns a number for a point it did not solve.

Layer 1: imports only the standard library and numpy.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, fields, replace
from typing import Any, Literal, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

SteadyStatus = Literal["ok", "no_solution", "contact_loss", "not_converged", "integration_failure",
                       "speed_unresolved"]
PulloffStatus = Literal["ok", "pulloff", "no_solution", "contact_loss_before_extremum",
                        "no_steady_state_before_extremum", "budget_exceeded"]
#: Statuses of a withdrawal at a finite speed, in time (simulation.withdrawal) or by the slow flow (models.slow_flow).
WithdrawalStatus = Literal["pulloff", "detached_before_mean_extremum", "not_detached", "integration_failure"]

#: Statuses of a steady state that carry numbers ("speed_unresolved": an orbit that came within 1e-3
#: of the simulation's speed cap keeps them, flagged).
STEADY_WITH_NUMBERS = ("ok", "speed_unresolved")
#: Statuses of a pull-off that carry numbers: "pulloff" is the simulated experiment's "ok" (both are
#: CSV values of virtual_pulloff*.csv).
PULLOFF_FOUND = ("ok", "pulloff")


def _float_array(value: ArrayLike) -> FloatArray:
    """``value`` as a float64 array (a copy only where the dtype changes)."""
    return np.asarray(value, dtype=float)


def _shaped(value: ArrayLike, shape: tuple[int, ...]) -> FloatArray:
    """``value`` as a float64 array broadcast to ``shape`` (a read-only view)."""
    return np.broadcast_to(_float_array(value), shape)


def _check_invariant(record: Any, with_numbers: tuple[str, ...], numbers: tuple[str, ...],
                     defining: tuple[str, ...]) -> None:
    """Shapes agree with ``status``; NaN numbers without a solution, finite ``defining`` numbers with one.

    ``numbers`` are the float fields of ``record``; ``defining`` those that a solution always has.
    """
    status = record.status
    for name in numbers:
        value = getattr(record, name)
        if value.shape != status.shape:
            raise ValueError(f"{name} has shape {value.shape}, status has {status.shape}")
    solved = np.isin(status, with_numbers)
    for name in numbers:
        value = getattr(record, name)
        if not np.all(np.isnan(value[~solved])):
            raise ValueError(f"{name} is a number where the status says there is no solution: "
                             f"{sorted(set(status[~solved].tolist()))}")
    for name in defining:
        if not np.all(np.isfinite(getattr(record, name)[solved])):
            raise ValueError(f"{name} is not finite where the status says there is a solution")


@dataclass(frozen=True)
class OrbitDiagnostics:
    """What only the direct simulation knows about its periodic orbit (Eqs. 4-11, Floquet theory).

    Harmonic coefficients refer to tau = omega t with h - h0 = h1 sin tau; NaN (and ``stable`` False
    in the steady state) for an orbit that was not found, whose ``start_state`` is the last state tried.
    """

    start_state: FloatArray  # state at tau = 0 mod 2pi: (abar,) rigid, (xbar, dxbar/dtau, abar) compliant
    A1_over_am: float  # first-harmonic amplitude of a over a_m
    abar_c: float  # first-harmonic cosine coefficient of a / a_o
    abar_s: float  # first-harmonic sine coefficient of a / a_o
    phat_m: float  # mean of Phat = P R/(E* a_o^3) over the period (Eq. 4')
    phat_c: float
    phat_s: float
    deltabar_c: float  # first-harmonic coefficients of R delta/a_o^2
    deltabar_s: float
    peak_speed: float  # max |d abar/d tau| over the period
    peak_speed_in_range: bool | None  # inside the caller's speed range (None when none is given)
    floquet_multipliers: NDArray[np.inexact[Any]]
    periodicity_residual: float  # max_i |y_i(2pi) - y_i(0)| / scale_i
    iterations: int  # one-period integrations of the shooting
    integrator: str
    tau_contact_loss: float  # finite only for ``contact_loss``


@dataclass(frozen=True)
class SteadyState:
    """Periodic steady state(s) of one model level (Secs. 3.1, 3.5, 3.7, Eqs. 125-126, simulation).

    ``stable``: the leading order's mean-balance slope or the simulation's Floquet multipliers, None
    where the level does not say. ``orbit``: the simulation's diagnostics, None for the other levels.
    """

    level: str  # registry name = CSV value of ``model``
    status: NDArray[np.str_]  # SteadyStatus per element
    Abar: FloatArray  # internal variable omega A/v0, Eq. (45)
    abar_m: FloatArray  # a_m/a_o, Eq. (86)
    w_eff_ratio: FloatArray  # w_eff/w0, Eqs. (18), (49)
    A_over_am: FloatArray  # A/a_m, Eq. (98) corrected (docs/errata.md E1); may exceed 1 (reported, not hidden)
    pm_over_abs_pjkr: FloatArray  # P_m/|P_cr^JKR|, tensile negative, Eqs. (52), (71)
    deltabar_m: FloatArray  # R delta_m/a_o^2, Eq. (86); NaN where the level does not give it
    stable: NDArray[np.bool_] | None = None
    orbit: OrbitDiagnostics | None = None
    message: str = ""

    def __post_init__(self) -> None:
        """Arrays of one shape; NaN numbers without a solution; finite Abar, abar_m, w_eff_ratio with one."""
        numbers = tuple(f.name for f in fields(self) if f.name not in ("level", "status", "stable", "orbit",
                                                                        "message"))
        object.__setattr__(self, "status", np.asarray(self.status, dtype=str))
        for name in numbers:
            object.__setattr__(self, name, _float_array(getattr(self, name)))
        if self.stable is not None:
            object.__setattr__(self, "stable", np.asarray(self.stable, dtype=bool))
        _check_invariant(self, STEADY_WITH_NUMBERS, numbers, ("Abar", "abar_m", "w_eff_ratio"))

    @property
    def ok(self) -> NDArray[np.bool_]:
        """Where the level found a steady state (``ok``; a ``speed_unresolved`` orbit is not ok)."""
        return np.asarray(self.status == "ok")

    @classmethod
    def unsolved(cls, level: str, status: SteadyStatus, message: str = "", orbit: OrbitDiagnostics | None = None,
                 shape: tuple[int, ...] = ()) -> SteadyState:
        """A record without a solution: ``status`` and NaN numbers everywhere (``stable`` False with an orbit)."""
        nan = np.full(shape, math.nan)
        return cls(level, np.full(shape, status), *(nan,) * 6,
                   stable=None if orbit is None else np.full(shape, False), orbit=orbit, message=message)


@dataclass(frozen=True)
class Pulloff:
    """Pull-off of one model level, dimensionless (Secs. 3.2, 3.6; exact averaging; simulation).

    Numbers a level does not compute are NaN: ``abar_m`` where the level assumes a_m = a_cr,
    ``abar_cr`` (the criterion of Eq. 61 at the simulated w_eff) for the predictions, ``Abar_cr``
    for the simulation, ``base_offset`` for every level but the simulation.
    """

    level: str  # registry name = CSV value of ``model``
    status: NDArray[np.str_]  # PulloffStatus per element
    pulloff_ratio: FloatArray  # P_cr/P_cr^JKR > 0, Eq. (71)
    Abar_cr: FloatArray  # internal variable at detachment, Eqs. (72), (106)
    sqrt_w_eff_ratio: FloatArray  # J0(Abar_cr) (Eq. 71), or alpha* for exact averaging
    w_eff_ratio: FloatArray  # w_eff/w0 at detachment
    abar_cr: FloatArray  # a_cr/a_o of Eq. (61) at this w_eff
    abar_m: FloatArray  # a_m/a_o at detachment
    A_over_am: FloatArray  # A/a_m at detachment
    base_offset: FloatArray  # (hhat - h0) R/a_o^2 at detachment
    steady_states: int | None = None  # periodic orbits solved along the family (simulation)
    message: str = ""

    def __post_init__(self) -> None:
        """Arrays of one shape; NaN numbers without a pull-off; a finite ratio with one."""
        numbers = tuple(f.name for f in fields(self) if f.name not in ("level", "status", "steady_states", "message"))
        object.__setattr__(self, "status", np.asarray(self.status, dtype=str))
        for name in numbers:
            object.__setattr__(self, name, _float_array(getattr(self, name)))
        _check_invariant(self, PULLOFF_FOUND, numbers, ("pulloff_ratio",))

    @property
    def found(self) -> NDArray[np.bool_]:
        """Where the level found a pull-off (``ok``, or ``pulloff`` for the simulated experiment)."""
        return np.isin(self.status, PULLOFF_FOUND)

    def taken(self, index: NDArray[np.intp]) -> Pulloff:
        """The record at ``index`` (every array field indexed alike): scatters a solve on distinct inputs back."""
        arrays = {f.name: getattr(self, f.name)[index] for f in fields(self)
                  if f.name not in ("level", "steady_states", "message")}
        return replace(self, **arrays)

    @classmethod
    def unsolved(cls, level: str, status: PulloffStatus, message: str = "", shape: tuple[int, ...] = ()) -> Pulloff:
        """A record without a pull-off: ``status`` and NaN numbers everywhere."""
        nan = np.full(shape, math.nan)
        return cls(level, np.full(shape, status), *(nan,) * 8, message=message)

    @classmethod
    def from_ratio(cls, level: str, status: ArrayLike, pulloff_ratio: ArrayLike, *, Abar_cr: ArrayLike = math.nan,
                   sqrt_w_eff_ratio: ArrayLike = math.nan, w_eff_ratio: ArrayLike = math.nan,
                   abar_m: ArrayLike = math.nan) -> Pulloff:
        """A prediction (no simulated criterion, mean state or base offset: NaN), broadcast to the ratio's shape."""
        ratio = _float_array(pulloff_ratio)
        nan, shape = np.full(ratio.shape, math.nan), ratio.shape
        return cls(level, np.broadcast_to(np.asarray(status, dtype=str), shape), ratio, _shaped(Abar_cr, shape),
                   _shaped(sqrt_w_eff_ratio, shape), _shaped(w_eff_ratio, shape), nan, _shaped(abar_m, shape), nan, nan)


Record = TypeVar("Record", SteadyState, Pulloff)


def stacked(records: Sequence[Record]) -> Record:
    """One record whose elements are ``records`` (one level, each of shape ()), in their order.

    Several solutions of one level at one point (several roots of its equations) are the elements of
    one record; every array field is stacked along a new first axis, the messages are joined. A
    simulated orbit's diagnostics and a count of solved orbits belong to one element and are refused.
    """
    first = records[0]
    if any(record.level != first.level for record in records):
        raise ValueError(f"records of different levels: {sorted({record.level for record in records})}")
    if any(getattr(record, name, None) is not None for record in records for name in ("orbit", "steady_states")):
        raise ValueError("a simulated record (orbit diagnostics, orbits solved) cannot be stacked")
    if any((getattr(record, "stable", None) is None) != (getattr(first, "stable", None) is None) for record in records):
        raise ValueError("either every stacked steady state says whether it is stable or none does")
    arrays: dict[str, Any] = {f.name: np.stack([getattr(record, f.name) for record in records]) for f in fields(first)
                              if isinstance(getattr(first, f.name), np.ndarray)}
    arrays["message"] = "; ".join(record.message for record in records if record.message)
    return replace(first, **arrays)
