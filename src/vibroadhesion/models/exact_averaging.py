"""Exact averaging in the high-frequency limit, rigid fixation: mean state, nominal point contact, pull-off.

Notation, the frozen contact radius and the drift-free cycle s(tau) = alpha + beta sin tau with
alpha = alpha*(beta) and Abar: :mod:`vibroadhesion.models.frozen_radius`. By Eqs. (18) and (16)-(17) the
effective work of adhesion is the mean of s squared, exactly, and at a mean radius abar_m
(beta = etahat/sqrt(abar_m))

    w_eff/w0 = alpha*^2,   Phat_m = mean Phat = (4/3) abar_m^3 - 2 alpha* abar_m^(3/2),
    base_offset = abar_m^2 - alpha* sqrt(abar_m).

alpha*(beta) and Abar(beta) are read from their table per exponent n
(:mod:`vibroadhesion.models.frozen_radius_table`, 1e-12 of the direct solve, which it falls back on outside
the table), so that a point costs about 0.5 ms instead of 25-40 ms.

Relation to the paper's first-harmonic (J-integral) model, Eqs. (25)–(29), (47), (49), (55). Its
leading order for rigid fixation imposes the same two conditions on s: the mean of s is abar_m^(3/2)
for the nominal point contact (Eqs. 53, 123 with J0 = mean s) and the first harmonic of s has
amplitude |Jc1| = etahat/sqrt(abar_m) = beta (Eq. 55; the delta_c of Eq. 47 is -sqrt(abar_m) Jc1).
It differs in how the two are linked: it assumes x = Abar cos tau' (a sinusoidal contact-front speed,
which has zero mean, so the drift condition is automatic), obtains s = sqrt(f(Abar cos tau')) -- which
has higher harmonics that the prescribed deltabar(tau) of Eq. (5) cannot balance -- and so replaces
alpha*(beta) by J0(Abar) on |Jc1(Abar)| = beta. The exact cycle keeps s affine in sin tau and lets the
speed x(tau) = X(s(tau)) take whatever (non-sinusoidal) shape makes the drift vanish. For small beta
(Eqs. 28, 29 expanded as in :func:`vibroadhesion.core.integrals.j_integrals_small_Abar`)

    J0 - 1 = pi W(2n) beta^2/(16 W(n+1)^2) + o(beta^2)   against   alpha* - 1 = beta^2/(2(1+n)),
    Abar_J = (pi beta/(2 W(n+1)))^(1/n)                  against   Abar   = (2 beta)^(1/n) W(1/n),

the same orders (both reduce to the static JKR state, with corrections O(beta^2) in w_eff and
Abar ~ beta^(1/n)) but different constants; the constants coincide for n = 1, where the law is linear
in x near x = 0 and a sinusoidal speed is exact. For large beta the J model gives J0/|Jc1| ->
W(n/2)/(2 W(n/2 + 1)) < 1, while the exact alpha*/beta -> 1 (w > 0 forces alpha* > beta).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import elementwise

from vibroadhesion.core import groups
from vibroadhesion.core.groups import PHAT_JKR
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import Pulloff, SteadyState
from vibroadhesion.models.frozen_radius import alpha_star
from vibroadhesion.models.frozen_radius_table import X_RANGE, is_tabulated, log_cycle_on_table, tabulated_cycle
from vibroadhesion.numerics.roots import NoRootError

Array = NDArray[np.float64]

# --- Rigid fixation: the mean state as a function of abar_m --------------------------------


class MeanState(NamedTuple):
    """High-frequency mean state at a given abar_m (rigid fixation), Eqs. (16)–(18) exact."""

    abar_m: Array
    base_offset: Array  # (hhat - h0) R/a_o^2 that holds this abar_m: abar_m^2 - alpha sqrt(abar_m)
    phat_m: Array  # Phat_m = (4/3) abar_m^3 - 2 alpha abar_m^(3/2)
    alpha: Array  # mean sqrt(w/w0); w_eff/w0 = alpha^2
    Abar: Array  # internal variable omega A/v0


def mean_state(abar_m: ArrayLike, eta1: ArrayLike, chi0: float, law: GentSchultz) -> MeanState:
    """Mean state at given abar_m for base amplitude eta1 = h1/R: beta = etahat/sqrt(abar_m), alpha = alpha*(beta).

    ``abar_m`` and ``eta1`` broadcast against each other. Parametrising by abar_m (instead of
    base_offset) makes a quasi-static sweep of h0 explicit: every abar_m > 0 has exactly one state
    (for n <= 4), while a given base_offset may have two or none.
    """
    abar_m, etahat = np.broadcast_arrays(np.asarray(abar_m, dtype=float),
                                         groups.etahat(np.asarray(eta1, dtype=float), chi0))
    if np.any(~(abar_m > 0)) or np.any(~np.isfinite(abar_m)):
        raise ValueError("abar_m must be positive and finite")
    cycle = tabulated_cycle(etahat / np.sqrt(abar_m), law)
    root = np.sqrt(abar_m)
    return MeanState(
        abar_m,
        abar_m**2 - cycle.alpha * root,
        (4.0 / 3.0) * abar_m**3 - 2.0 * cycle.alpha * abar_m * root,
        cycle.alpha,
        cycle.Abar,
    )


def _radius_where_alpha_is(etahat: Array, law: GentSchultz, c: float) -> Array:
    """abar_m solving alpha*(etahat/sqrt(abar_m)) = c abar_m^(3/2), vectorised over etahat > 0.

    On the table of alpha* (:func:`_log_beta_on_table`) where the root lies inside it, else by the
    bracketed search of :func:`_radius_by_bracketing` on the direct solve.
    """
    abar_m = np.full_like(etahat, np.nan)
    if is_tabulated(law):
        abar_m = np.exp(2.0 * (np.log(etahat) - _log_beta_on_table(etahat, law, c)))
    direct = np.isnan(abar_m)
    if np.any(direct):
        abar_m[direct] = _radius_by_bracketing(etahat[direct], law, c)
    return abar_m


#: Newton steps allowed on the table: the contraction bound (docstring below) reaches 1e-14 in x within
#: 33 steps from any start in the table (initial error < 18); quadratic convergence takes far fewer.
_NEWTON_STEPS = 40


def _log_beta_on_table(etahat: Array, law: GentSchultz, c: float) -> Array:
    """x = ln beta of the root of alpha*(beta) = c abar_m^(3/2), abar_m = (etahat/beta)^2; NaN off the table.

    The amplitude is an explicit function of beta: abar_m = (alpha*(beta)/c)^(2/3) and etahat = beta
    sqrt(abar_m), i.e. F(x) = x + (ln alpha*(e^x) - ln c)/3 - ln etahat = 0 (Eqs. 60-61 and 99, 123 with
    the exact w_eff = alpha*^2, Eq. 18). F' = 1 + s/3 with s = d ln alpha*/d ln beta, which runs from 0
    (alpha* - 1 ~ beta^2) to 1 (alpha* ~ beta) and stays in [0, 1] (measured on the whole table for
    n = 0.05-4), so F' lies in [1, 4/3], Newton's error contracts by at least 1/3 per step from any
    start and quadratically near the root. Steps are clipped to the table's range; a root at or beyond its ends,
    or one not converged to 1e-14 in x, is NaN (the caller solves it directly).
    """
    target = np.log(etahat)
    x = np.clip(target + math.log(c) / 3.0, *X_RANGE)
    converged = np.zeros(x.shape, dtype=bool)
    for _ in range(_NEWTON_STEPS):
        log_alpha, _, slope = log_cycle_on_table(x, law)
        step = (x + (log_alpha - math.log(c)) / 3.0 - target) / (1.0 + slope / 3.0)
        x = np.clip(x - step, *X_RANGE)
        converged = np.abs(step) <= 1e-14 * np.maximum(1.0, np.abs(x))
        if np.all(converged):
            break
    inside = converged & (x > X_RANGE[0]) & (x < X_RANGE[1])
    return np.where(inside, x, np.nan)


def _radius_by_bracketing(etahat: Array, law: GentSchultz, c: float) -> Array:
    """abar_m solving alpha*(etahat/sqrt(abar_m)) = c abar_m^(3/2) by Chandrupatla's method on the direct solve.

    Uniqueness: with u = sqrt(abar_m), d/du G(c u^3, etahat/u) = (1/u) mean[X'(s) (3 alpha - beta sin tau)]
    < 0 because X' < 0 and alpha > beta, so G(c u^3, etahat/u), which has the sign of
    alpha*(etahat/u) - c u^3, changes sign once: it is positive at u^4 = etahat/c (where c u^3 = beta
    < alpha*) and negative once c u^3 >= 1 + beta > alpha*.
    """
    lo = (etahat / c) ** 0.25
    hi = 1.01 * np.maximum(1.0, np.cbrt((1.0 + etahat) / c))
    res = elementwise.find_root(lambda u, e: _log_alpha_excess(u, e, law, c), (lo, hi), args=(etahat,))
    if not np.all(res.success):
        raise NoRootError(
            f"alpha*(etahat/sqrt(abar_m)) = {c:g} abar_m^(3/2): root search failed "
            f"for etahat = {etahat[~res.success][:5]}"
        )
    return res.x**2


def _log_alpha_excess(u: Array, etahat: Array, law: GentSchultz, c: float) -> Array:
    """ln alpha*(etahat/u) - ln(c u^3), u = sqrt(abar_m) (Eq. * of :mod:`vibroadhesion.models.frozen_radius`).

    Zero where the drift-free cycle meets the closure abar_m^(3/2) = alpha*/c (base_offset = 0,
    Eqs. 99, 123, for c = 1; a_m = a_cr, Eqs. 60–61, for c = 4/3).
    """
    return np.log(alpha_star(etahat / u, law)) - np.log(c * u**3)


def nominal_point_contact(eta1: ArrayLike, omega_check: ArrayLike, chi0: float, law: GentSchultz) -> SteadyState:
    """Exact high-frequency nominal point contact (Sec. 3.5.4), broadcast over eta1 and omega_check.

    The record of level ``exact_averaging``: base_offset = 0 gives alpha = abar_m^(3/2), so abar_m solves
    alpha*(etahat/sqrt(abar_m)) = abar_m^(3/2) (unique root, see :func:`_radius_by_bracketing`);
    Abar is the exact half peak-to-peak of the contact-radius oscillation, w_eff/w0 = alpha*^2,
    A/a_m = Abar/(omega_check c_o abar_m), P_m/|P_JKR| = Phat_m/(3/4) with Phat_m = (4/3 - 2) abar_m^3
    (negative: tensile) and deltabar_m = base_offset = 0. omega_check enters A/a_m only. Where the root
    search fails the status is ``no_solution`` (every number NaN).
    """
    eta1, omega_check = np.broadcast_arrays(np.asarray(eta1, dtype=float), np.asarray(omega_check, dtype=float))
    try:
        abar_m, Abar, alpha = _nominal_point_contact_state(eta1, chi0, law)
    except NoRootError as error:  # includes NoSteadyStateError
        return SteadyState.unsolved("exact_averaging", "no_solution", str(error), shape=eta1.shape)
    return SteadyState(
        "exact_averaging", np.full(eta1.shape, "ok"), Abar, abar_m, alpha**2,
        groups.A_over_am(Abar, abar_m, chi0, omega_check),
        ((4.0 / 3.0 - 2.0) * abar_m**3) / -PHAT_JKR, np.zeros(eta1.shape),
    )


def _nominal_point_contact_state(eta1: Array, chi0: float, law: GentSchultz) -> tuple[Array, Array, Array]:
    """(abar_m, Abar, alpha*) of the nominal point contact, alpha*(etahat/sqrt(abar_m)) = abar_m^(3/2)."""
    etahat = groups.etahat(eta1, chi0).ravel()
    flat_abar_m = np.ones_like(etahat)
    moving = etahat > 0
    if np.any(moving):
        flat_abar_m[moving] = _radius_where_alpha_is(etahat[moving], law, 1.0)
    cycle = tabulated_cycle(etahat / np.sqrt(flat_abar_m), law)
    abar_m, Abar, alpha = (v.reshape(eta1.shape) for v in (flat_abar_m, cycle.Abar, cycle.alpha))
    return abar_m, Abar, alpha


# --- Quasi-static pull-off in the high-frequency limit -------------------------------------


def pulloff_at_critical_radius(eta1: ArrayLike, chi0: float, law: GentSchultz) -> Pulloff:
    """Paper's criterion a_m = a_cr(w_eff) (Eqs. 60–61) with the exact w_eff, solved self-consistently.

    The record of level ``exact_averaging``: the mean state at detachment (abar_m, Abar_cr, alpha* =
    sqrt(w_eff/w0)) and P_cr/P_JKR^0 (positive for a tensile pull-off force).

    abar_cr = (9/16)^(1/3) (w_eff/w0)^(1/3) reads abar_m^(3/2) = (3/4) alpha*(etahat/sqrt(abar_m)) (unique
    root, :func:`_radius_by_bracketing` with c = 4/3); there Phat_m = (4/3)(9/16) alpha^2 - (3/2) alpha^2
    = -(3/4) alpha^2, so P_cr/P_JKR^0 = alpha^2 = w_eff/w0 (Eq. 71 with the exact w_eff). Where the root
    search fails (:class:`NoRootError`) the record says ``no_solution`` for every amplitude of the call,
    every number NaN, the reason in ``message``: the exception becomes a status here, at the level boundary.
    """
    eta1 = np.asarray(eta1, dtype=float)
    etahat = groups.etahat(eta1, chi0).ravel()
    abar_m = np.full_like(etahat, (9.0 / 16.0) ** (1.0 / 3.0))
    moving = etahat > 0
    try:
        if np.any(moving):
            abar_m[moving] = _radius_where_alpha_is(etahat[moving], law, 4.0 / 3.0)
        cycle = tabulated_cycle(etahat / np.sqrt(abar_m), law)
    except NoRootError as error:  # includes NoSteadyStateError
        return Pulloff.unsolved("exact_averaging", "no_solution", str(error), eta1.shape)
    shape = eta1.shape
    pulloff_ratio = (cycle.alpha**2).reshape(shape)
    return Pulloff.from_ratio("exact_averaging", "ok", pulloff_ratio, Abar_cr=cycle.Abar.reshape(shape),
                              sqrt_w_eff_ratio=cycle.alpha.reshape(shape), w_eff_ratio=pulloff_ratio,
                              abar_m=abar_m.reshape(shape))


#: Points of the coarse scan in ln abar_m that brackets the minimum of the mean force, and of each
#: of the nested scans that refine it (each shrinks the bracket by (points - 1)/2).
_SCAN_POINTS = 17
_REFINE_POINTS = 9
_REFINEMENTS = 3


def _smallest_mean_force(z: Array, eta1: Array, chi0: float, law: GentSchultz) -> tuple[Array, Array]:
    """Phat_m on the rows of nodes z = ln abar_m (one row per eta1, a column) and the index of its smallest value.

    Phat_m = (4/3) abar_m^3 - 2 alpha* abar_m^(3/2) (Eqs. 16–18, :func:`mean_state`). Raises
    :class:`NoRootError` when the smallest value of a row sits at an end of its scan.
    """
    force = mean_state(np.exp(z), eta1, chi0, law).phat_m
    k = np.argmin(force, axis=1)
    at_end = (k == 0) | (k == z.shape[1] - 1)
    if np.any(at_end):
        etahat = groups.etahat(eta1[:, 0], chi0)
        raise NoRootError(f"mean force has no interior minimum on the scan for etahat = {etahat[at_end][0]:.6g}")
    return force, k


def pulloff_at_force_minimum(eta1: ArrayLike, chi0: float, law: GentSchultz) -> Pulloff:
    """Force-controlled detachment: the minimum over abar_m of Phat_m(abar_m) at fixed etahat, vectorised over eta1.

    The record of level ``exact_averaging_force_minimum``: the mean state at the minimum and
    P_cr/P_JKR^0 = Phat_m/(-3/4) there.

    Under a slowly decreasing mean load the mean state is lost where d Phat_m/d abar_m = 0. The
    minimum is located on a scan of z = ln abar_m over [ln(0.05 m), ln(20 m)], m = max(1, sqrt(etahat))
    (the limits etahat -> 0, abar_m^(3/2) = 3/4, and etahat -> infinity, alpha ~ beta so Phat_m ~
    (4/3) abar_m^3 - 2 etahat abar_m with minimum at sqrt(etahat/2), both lie well inside), refined by
    nested scans between the neighbours of the smallest value (step 0.37 in z, then 0.094, 0.023,
    0.0058; each scan one vectorised call of :func:`mean_state` for all amplitudes), and placed at the
    vertex of the parabola through the smallest value and its neighbours. The vertex is off by O(h^2)
    in z for the last step h, so the force by O(h^4): 1.1e-9 relative at most over n = 0.05–4 and
    etahat = 1e-4–1e3 against Brent's method to 1e-12 in z (tested to 1e-8). Where a minimum sits at an
    end of a scan (:class:`NoRootError`) the record says ``no_solution`` for every amplitude of the call,
    every number NaN, the reason in ``message``: the exception becomes a status here, at the level boundary.
    """
    eta1 = np.asarray(eta1, dtype=float)
    try:
        state = _force_minimum_state(eta1, chi0, law)
    except NoRootError as error:  # includes NoSteadyStateError
        return Pulloff.unsolved("exact_averaging_force_minimum", "no_solution", str(error), eta1.shape)
    abar_m, alpha, Abar, pulloff_ratio = (np.reshape(v, eta1.shape) for v in (state.abar_m, state.alpha, state.Abar,
                                                                              state.phat_m / PHAT_JKR))
    return Pulloff.from_ratio("exact_averaging_force_minimum", "ok", pulloff_ratio, Abar_cr=Abar,
                              sqrt_w_eff_ratio=alpha, w_eff_ratio=alpha**2, abar_m=abar_m)


def _force_minimum_state(eta1: Array, chi0: float, law: GentSchultz) -> MeanState:
    """The mean state (Eqs. 16-18) at the minimum of Phat_m over abar_m, one per amplitude (flattened).

    The nested scans and the parabola vertex of :func:`pulloff_at_force_minimum`; raises
    :class:`NoRootError` when a minimum sits at an end of a scan.
    """
    column = eta1.reshape(-1, 1)
    etahat = groups.etahat(column, chi0)[:, 0]
    scale = np.maximum(1.0, np.sqrt(etahat))
    rows = np.arange(etahat.size)
    z = np.linspace(np.log(0.05 * scale), np.log(20.0 * scale), _SCAN_POINTS, axis=-1)
    force, k = _smallest_mean_force(z, column, chi0, law)
    for _ in range(_REFINEMENTS):
        z = np.linspace(z[rows, k - 1], z[rows, k + 1], _REFINE_POINTS, axis=-1)
        force, k = _smallest_mean_force(z, column, chi0, law)
    lower, middle, upper = force[rows, k - 1], force[rows, k], force[rows, k + 1]
    vertex = z[rows, k] - 0.5 * (z[:, 1] - z[:, 0]) * (upper - lower) / (upper - 2.0 * middle + lower)
    return mean_state(np.exp(vertex), column[:, 0], chi0, law)
