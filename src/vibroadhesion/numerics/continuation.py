"""Pseudo-arclength continuation of a one-parameter family of solutions of F(x) = 0.

F maps R^(N+1) to R^N; its zero set is (generically) a curve. Following it by arclength
instead of by the parameter lets the trace pass through folds (turning points of the
parameter), where natural-parameter continuation would have to jump (Keller 1977; Allgower &
Georg, *Introduction to Numerical Continuation Methods*, 2003, Ch. 2 and 9).

Each step: tangent t_k (unit null vector of the Jacobian F'(x_k), oriented to continue in the
same direction), Euler predictor x_k + h t_k, Newton corrector on

    F(x) = 0,   t_k . (x - x_k) = h                                   (the pseudo-arclength condition)

(chord iteration with the Jacobian of the previous point, which the tangent needed anyway),
and step control: halve on failure, grow by 1.5 while the tangent turns by less than 8 degrees.
A fold of the parameter x[0] is a sign change of the tangent's first component; it is located
to machine precision by a bracketed root of that component along the curve (:func:`locate_folds`).

The Jacobian is taken by central differences from one vectorised call of F on the 2(N+1)
perturbed points (``residual`` must accept an (m, N+1) array and return (m, N)). Failure of the
corrector at the smallest step raises :class:`ContinuationError`, which carries the curve traced so
far: the trace never jumps.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

Array = NDArray[np.float64]
Residual = Callable[[Array], Array]


class ContinuationError(ArithmeticError):
    """The corrector did not converge even at the smallest allowed step.

    ``partial`` is the curve traced up to the failure (None where no step was taken), so that a caller
    can report where the trace ended instead of losing it.
    """

    def __init__(self, message: str, partial: Curve | None = None) -> None:
        """The failure ``message`` and the points traced before it."""
        super().__init__(message)
        self.partial = partial


@dataclass(frozen=True)
class ContinuationSettings:
    """Step control and tolerances (in the units of x; the callers use logarithmic variables)."""

    initial_step: float = 0.02
    min_step: float = 1e-8
    max_step: float = 0.25
    tolerance: float = 1e-12  # max-norm of F at an accepted point
    max_newton: int = 25
    max_points: int = 20000
    fd_step: float = 1e-7


@dataclass(frozen=True)
class Curve:
    """Points on the solution curve in trace order, their unit tangents and their residuals."""

    points: Array  # (m, N+1)
    tangents: Array  # (m, N+1)
    residuals: Array  # (m,) max-norm of F at each point


def _as_curve(points: list[Array], tangents: list[Array], norms: list[float]) -> Curve:
    """The :class:`Curve` of the points, tangents and residual norms accepted so far."""
    return Curve(np.array(points), np.array(tangents), np.array(norms))


def jacobian(residual: Residual, x: Array, fd_step: float) -> Array:
    """F'(x), (N, N+1), by central differences with one vectorised call of ``residual``."""
    m = x.size
    h = fd_step * np.maximum(1.0, np.abs(x))
    shifted = np.concatenate([x + np.diag(h), x - np.diag(h)])
    values = residual(shifted)
    return ((values[:m] - values[m:]) / (2.0 * h[:, None])).T


def tangent(jac: Array, previous: Array) -> Array:
    """Unit null vector of ``jac`` oriented along ``previous`` (bordered solve, Allgower–Georg 2.1)."""
    bordered = np.vstack([jac, previous])
    rhs = np.zeros(jac.shape[1])
    rhs[-1] = 1.0
    t = np.linalg.solve(bordered, rhs)
    return t / np.linalg.norm(t)


def correct(
    residual: Residual, predictor: Array, normal: Array, jac: Array, settings: ContinuationSettings
) -> tuple[Array, float] | None:
    """Chord-Newton on F(x) = 0 within the hyperplane normal . (x - predictor) = 0; None if not converged.

    ``jac`` is F' at a nearby point (the previous point of the curve): the bordered matrix is
    factored once per step, which converges linearly at a rate of the step length.
    """
    bordered = np.vstack([jac, normal])
    x = predictor.copy()
    for _ in range(settings.max_newton):
        with np.errstate(over="ignore", invalid="ignore"):  # a diverging iterate: non-finite F, rejected below
            f = residual(x[None, :])[0]
        if not np.all(np.isfinite(f)):
            return None
        norm = float(np.max(np.abs(f)))
        if norm < settings.tolerance:
            return x, norm
        x = x + np.linalg.solve(bordered, -np.concatenate([f, [normal @ (x - predictor)]]))
    return None


def trace(
    residual: Residual,
    start: Array,
    direction: Array,
    stop: Callable[[Array], bool],
    settings: ContinuationSettings = ContinuationSettings(),
) -> Curve:
    """Follow the curve from the solution ``start`` along ``direction`` until ``stop(x)`` is true.

    The last point is the first one for which ``stop`` holds (callers clip to their range).
    """
    x = np.asarray(start, dtype=float)
    jac = jacobian(residual, x, settings.fd_step)
    t = tangent(jac, np.asarray(direction, dtype=float))
    points, tangents, norms = [x], [t], [float(np.max(np.abs(residual(x[None, :])[0])))]
    h = settings.initial_step
    while not stop(x):
        if len(points) >= settings.max_points:
            raise ContinuationError(f"continuation stopped after {settings.max_points} points without reaching the end")
        accepted = None
        while accepted is None:
            predictor = x + h * t
            accepted = correct(residual, predictor, t, jac, settings)
            if accepted is None:
                h *= 0.5
                if h < settings.min_step:
                    raise ContinuationError(f"corrector failed at step {h:.3g} from x = {x.tolist()}",
                                            _as_curve(points, tangents, norms))
        x_new, norm = accepted
        jac_new = jacobian(residual, x_new, settings.fd_step)
        t_new = tangent(jac_new, t)
        if t_new @ t < 0.5:  # tangent turned by more than 60 degrees: the step jumped a sharp bend
            h *= 0.5
            if h < settings.min_step:
                raise ContinuationError(f"cannot resolve a sharp turn of the curve at x = {x.tolist()}",
                                        _as_curve(points, tangents, norms))
            continue
        x, t, jac = x_new, t_new, jac_new
        points.append(x)
        tangents.append(t)
        norms.append(norm)
        h = min(settings.max_step, 1.5 * h) if t_new @ tangents[-2] > 0.99 else h
    return _as_curve(points, tangents, norms)


def _corrected_at(
    sigma: float, residual: Residual, x0: Array, t0: Array, jac0: Array, settings: ContinuationSettings
) -> tuple[Array, Array]:
    """The point corrected from the predictor x0 + sigma t0 (arclength sigma from x0 along t0) and its tangent.

    Same corrector and tangent as a step of :func:`trace`, with the chord Jacobian ``jac0`` of x0.
    """
    result = correct(residual, x0 + sigma * t0, t0, jac0, settings)
    if result is None:
        raise ContinuationError(f"corrector failed while locating the fold near x = {x0.tolist()}")
    x = result[0]
    return x, tangent(jacobian(residual, x, settings.fd_step), t0)


def _tangent_parameter_component(
    sigma: float, residual: Residual, x0: Array, t0: Array, jac0: Array, settings: ContinuationSettings
) -> float:
    """t[0] of the corrected point at arclength sigma: zero at a fold of the parameter x[0]."""
    return _corrected_at(sigma, residual, x0, t0, jac0, settings)[1][0]


def locate_folds(residual: Residual, curve: Curve, settings: ContinuationSettings = ContinuationSettings()) -> Array:
    """Points where the parameter x[0] turns (tangent[0] = 0), one per sign change along ``curve``.

    Between two points with opposite signs of t[0] the fold is the root of sigma -> t[0] of the
    corrected point at arclength sigma, found by Brent's method to 1e-13 in sigma.
    """
    folds = []
    signs = np.sign(curve.tangents[:, 0])
    for k in np.flatnonzero(signs[:-1] * signs[1:] < 0):
        x0, t0 = curve.points[k], curve.tangents[k]
        span = float(t0 @ (curve.points[k + 1] - x0))
        args = (residual, x0, t0, jacobian(residual, x0, settings.fd_step), settings)
        sigma = brentq(_tangent_parameter_component, 0.0, span, args=args, xtol=1e-13)
        folds.append(_corrected_at(sigma, *args)[0])
    return np.array(folds).reshape(-1, curve.points.shape[1])


def crossings(curve: Curve, parameter: float) -> list[Array]:
    """Points of ``curve`` linearly interpolated where x[0] = ``parameter``, one per crossing.

    A point lying exactly on the parameter is returned once (not once per adjacent interval).
    """
    d = curve.points[:, 0] - parameter
    guesses = [curve.points[k] for k in np.flatnonzero(d == 0)]
    for k in np.flatnonzero(d[:-1] * d[1:] < 0):
        a, b = curve.points[k], curve.points[k + 1]
        guesses.append(a + d[k] / (d[k] - d[k + 1]) * (b - a))
    return guesses
