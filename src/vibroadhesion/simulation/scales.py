"""Scales of the one-period problem: the natural sizes of v and xbar, and the periodicity test built on them.

The integrated core of :mod:`vibroadhesion.simulation.integrators` is scaled so that one absolute
tolerance fits all components: v = omega_check c_o (abar - abar(0)) by its half range over a period
(estimated before the first run, observed after it), xbar and xbar' by max(etahat, |xbar|, |xbar'|).
With those scales every core component is O(1), and a run returns to its start "to rounding" when each
component's residual is within a few rtol of its own range (Eqs. 3', 6').
"""

from __future__ import annotations

import numpy as np

from vibroadhesion.simulation.integrators import Integrators, Run
from vibroadhesion.simulation.model import SPEED_CAP, TWO_PI, Array, Model

#: A residual below this many rtol (scaled state) is periodic to the local accuracy of the
#: integration: the orbit is accepted even where the map is too ill-conditioned to pin it down
#: better (e.g. an undamped spring whose contact does not move).
_PERIODIC_RESIDUAL_FACTOR = 10.0


def v_scale_estimate(model: Model, abar: float) -> float:
    """A guess of the half range of v = speed_scale (abar - abar(0)) over a period.

    The smaller of the frozen-contact value (abar fixed, v' = x(Phi(abar, deltabar(tau))), the
    limit omega_check -> infinity) and the quasi-static one (v follows the JKR compliance,
    speed_scale etahat; etahat plus the force rig's frozen response, Eq. 13); only used to scale the first
    integration, later ones use the observed range.
    """
    tau = np.linspace(0.0, TWO_PI, 257)
    amplitude = model.etahat + model.force_response(abar)
    d = model.base_offset - amplitude * np.sin(tau)
    gap = np.maximum(abar * abar - d, 1e-150)
    law = model.problem.law
    x = np.clip(law.speed(gap * gap / abar), -SPEED_CAP * model.speed_scale, SPEED_CAP * model.speed_scale)
    u = np.concatenate([[0.0], np.cumsum(0.5 * (x[1:] + x[:-1]) * np.diff(tau))])
    frozen = 0.5 * float(u.max() - u.min())
    return max(min(frozen, model.speed_scale * amplitude), _v_scale_floor(model, abar))


def _v_scale_floor(model: Model, abar: float) -> float:
    """Smallest scale of v: a change of abar below the resolution of abar itself."""
    return 1e-14 * model.speed_scale * abar


def x_scale(model: Model, start: Array) -> float:
    """S = max(etahat, fhat/max(1, omega_bar^2), |xbar|, |xbar'|) of the compliant start (floored), 1 if rigid.

    fhat/max(1, omega_bar^2) is the response of the spring and mass to the force rig's drive (Eq. 13) away from
    their resonance; the floor is 1e-280.
    """
    if not model.compliant:
        return 1.0
    drive = model.force_drive / max(1.0, model.omega_bar**2)
    return max(model.etahat, drive, abs(float(start[0])), abs(float(start[1])), 1e-280)


def observed_v_scale(run: Run) -> float:
    """Half range of v over the run (the natural scale of the next run), floored."""
    lo, hi = run.u_range
    half = 0.5 * (hi - lo) * run.period.v_scale
    return max(half, _v_scale_floor(run.period.m, float(run.period.start[-1])))


def periodic_to_rounding(run: Run, integrators: Integrators) -> bool:
    """Whether the run returns to its start to the accuracy of the integration (Eqs. 3', 6').

    Each scaled core component within _PERIODIC_RESIDUAL_FACTOR rtol of its own range
    (:func:`scaled_core_ranges`: absolute for a component whose scaled range is O(1), relative to the
    component's size where it is larger), where the abar component also passes when its drift is below the
    resolution of abar itself (a contact that does not move: its scaled range is then meaningless).
    """
    period = run.period
    residual = np.abs(run.y_end[: period.dim] - np.array(period.core_start()))
    tolerance = _PERIODIC_RESIDUAL_FACTOR * integrators.rtol * scaled_core_ranges(run)
    abar_drift = residual[-1] * period.v_scale / period.m.speed_scale
    abar_ok = residual[-1] <= tolerance[-1] or abar_drift <= 4.0 * np.finfo(float).eps * float(period.start[-1])
    return bool(abar_ok and np.all(residual[:-1] <= tolerance[:-1]))


def scaled_core_ranges(run: Run) -> Array:
    """Largest magnitude of each scaled core component over the accepted steps, floored at 1 (Eqs. 3', 6').

    DOP853 (rtol = atol) keeps the error of a component within ~rtol (1 + |y|): the sizes the periodicity
    check and the noise of the fixed point scale their tolerances with, component by component, so that a
    component whose scale is far off (a huge scaled range) cannot loosen the tolerance of the others. With
    the scales fitted (S, V of :class:`Period`) every range is O(1) and the tolerances are absolute.
    """
    return np.asarray(np.maximum(1.0, np.max(np.abs(run.cores), axis=0)), dtype=float)
