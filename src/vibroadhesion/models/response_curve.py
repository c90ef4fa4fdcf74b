"""The response curve of the compliantly fixed indenter through resonance, Fig. 5 (Eqs. 87, 90-96).

The solutions of Eqs. (87) and (90) (:func:`vibroadhesion.models.compliant.residual`, in x = (ln omega_bar,
ln abar_m, ln Abar)) form a curve in omega_bar, traced by pseudo-arclength continuation
(:mod:`vibroadhesion.numerics.continuation`) from the ends of the range, through its folds.

The notch (zeta = 0, Appendix B). At omega_bar = 1 the right-hand side of Eq. (90) vanishes and Abar = 0
exactly: in x that point is at ln Abar = -infinity. The curve splits into a piece below and a piece above
omega_bar = 1, each traced towards the notch until A/a_m < NOTCH_FLOOR, or until |ln omega_bar| < NOTCH_GAP:
nearer, the Jacobian's central differences (step 1e-7 in ln omega_bar) would straddle omega_bar = 1, where
ln|1 - omega_bar^2| of Eq. (90) is singular. For large n the notch piece approaches as Abar ~ |1 - omega_bar^2|
(Eq. 96's p_check_s, not Jc1 ~ Abar^n, balances the forcing), so at n = 4 it reaches the singular line while
A/a_m is still ~1e-6: the corrector failed there before NOTCH_GAP (Eq. 90 was differenced across the notch).

Edges of the exponent range: unbounded amplitude. Where the rate law's dissipation cannot bound the
response (zeta = 0 and n = 0.05: J0, Jc1, J1 grow only like Abar^(n/2)), a piece runs to Abar -> infinity at
an almost fixed omega_bar (5.32 for kappa = 0.001, h1 = 20 um), and Eq. (90) becomes the cancellation of terms
growing like Abar: the residual's rounding (the J-integrals' 1e-13 times the cancellation factor, 2e4 in
d/d ln omega_bar at A/a_m = 4.7e3) exceeds the corrector's tolerance 1e-12 and the corrector failed. A piece is
ended at A/a_m > AMPLITUDE_CEILING (1000 times the refined model's range A/a_m <= 0.1), "unbounded_amplitude".
At n = 4 (zeta = 0) the resonance peak grows in Abar and abar_m together (J0 ~ Abar^(n/2) makes the mean
contact radius grow with the amplitude, abar_m ~ J0^(2/3), so A/a_m stays ~ 3e-5): the same cancellation stops
the corrector (kappa = 0.01: near omega_bar = 16 at abar_m = 81, J0 = 489; kappa = 0.001: Newton at the end of
the range, omega_bar = 50, at abar_m = 80), "corrector_failed". No ceiling on abar_m separates this from
the damped peaks, which reach abar_m = 53 (zeta = 0.01, kappa = 0.001): the status says where it stopped.

A piece that does not end where it was going (the notch, or the other end of the range) leaves part of
the curve untraced; that part is traced back from where the piece was going (:func:`trace_response_curve`).
A corrector failure ends a piece with "corrector_failed" where it happened, its points kept. How each
piece ends is in :attr:`ResponseCurve.ends`: a piece that cannot be continued is reported, never hidden.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial

import numpy as np
from numpy.typing import NDArray

from vibroadhesion.core import groups
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.ratelaw import RateLaw
from vibroadhesion.core.records import SteadyState, stacked
from vibroadhesion.models.compliant import newton_at_frequency, residual, solutions_by_scan
from vibroadhesion.numerics.continuation import (
    ContinuationError,
    ContinuationSettings,
    Curve,
    crossings,
    locate_folds,
    trace,
)
from vibroadhesion.numerics.roots import NoRootError

Array = NDArray[np.float64]

#: A/a_m below which a branch approaching the anti-resonance notch (zeta = 0) is ended.
NOTCH_FLOOR = 1e-12
#: |ln omega_bar| below which a branch approaching the notch is ended: ten central-difference steps of the
#: Jacobian (ContinuationSettings.fd_step = 1e-7) from omega_bar = 1, where Eq. (90) in logarithms is singular.
NOTCH_GAP = 1e-6
#: A/a_m above which a branch is ended as running to unbounded amplitude: 1000 times the refined model's
#: range A/a_m <= 0.1, where Eq. (90) is a cancellation of terms growing like Abar (module docstring, "Edges").
AMPLITUDE_CEILING = 100.0
#: |ln omega_bar| at which a piece is traced back out of the notch (zeta = 0, :func:`trace_response_curve`).
NOTCH_START = 1e-3
#: How a piece of the curve ends when it reaches neither the end of the range nor the notch (reported).
OPEN_ENDS = ("unbounded_amplitude", "corrector_failed")


def _A_over_am(x: Array, fixation: Fixation, chi0: float) -> Array:
    """A/a_m at points x = (ln omega_bar, ln abar_m, ln Abar) (corrected Eq. 98, omega_check = omega_bar/nu0)."""
    return groups.A_over_am(np.exp(x[:, 2]), np.exp(x[:, 1]), chi0, np.exp(x[:, 0]) / fixation.nu0)


@dataclass(frozen=True)
class ResponseCurve:
    """The traced solution curve: pieces (split at the exact anti-resonance), how each ends, and the folds."""

    fixation: Fixation
    chi0: float  # Eq. (64)
    eta1: float  # h1 / R, Eq. (65)
    pieces: tuple[Curve, ...]  # points x = (ln omega_bar, ln abar_m, ln Abar) in trace order
    names: tuple[str, ...]  # one per piece: "lower"/"upper" (zeta = 0) or "full", "<name>_reverse" traced back
    ends: tuple[str, ...]  # one per piece: "range_end", "notch", or one of OPEN_ENDS
    folds: Array  # (k, 3) fold points in x

    def A_over_am(self, x: Array) -> Array:
        """A/a_m along points x (corrected Eq. 98)."""
        return _A_over_am(x, self.fixation, self.chi0)

    def count_at(self, omega_bar: float) -> int:
        """Number of solutions on the traced curve at ``omega_bar`` (crossings of the curve)."""
        return sum(len(crossings(piece, math.log(omega_bar))) for piece in self.pieces)

    def steady_states_at(self, omega_bar: float, law: RateLaw) -> SteadyState:
        """Every solution on the traced curve at ``omega_bar``, polished by Newton: one record of level ``refined``.

        One element per crossing of the curve (:func:`newton_at_frequency`), the solutions by increasing
        Abar, then any crossing where Newton did not converge (``not_converged``); no crossing (outside the
        traced range) gives one element of status ``no_solution``.
        """
        s = math.log(omega_bar)
        case = (self.fixation, self.chi0, self.eta1, law)
        states = [newton_at_frequency(omega_bar, *case, (math.exp(g[1]), math.exp(g[2])))
                  for piece in self.pieces for g in crossings(piece, s)]
        if not states:
            return SteadyState.unsolved("refined", "no_solution", f"the traced curve does not reach omega_bar = "
                                        f"{omega_bar:.6g}", shape=(1,))
        return stacked(sorted(states, key=_solutions_first_by_Abar))


def _solutions_first_by_Abar(state: SteadyState) -> tuple[bool, float]:
    """Sort key of the elements of a record: the solutions by increasing Abar, then the unsolved ones."""
    return not bool(state.ok), float(state.Abar)


def _start(omega_bar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw) -> Array:
    """The one solution x = (ln omega_bar, ln abar_m, ln Abar) of Eqs. (87), (90) at an end of the range."""
    roots = solutions_by_scan(omega_bar, fixation, chi0, eta1, law, np.linspace(-60.0, 60.0, 2401))
    found = int(np.count_nonzero(roots.ok))
    if found != 1:
        raise NoRootError(
            f"Eqs. (87), (90): expected one solution at the end omega_bar = {omega_bar:.6g} to start from, "
            f"found {found}"
        )
    return np.array([math.log(omega_bar), math.log(float(roots.abar_m[0])), math.log(float(roots.Abar[0]))])


def _notch_start(log_omega_bar: float, fixation: Fixation, chi0: float, eta1: float, law: RateLaw) -> Array:
    """The solution of Eqs. (87), (90) with the smallest Abar at ``log_omega_bar`` near the notch (zeta = 0).

    Next to omega_bar = 1 the branch leaving the anti-resonance has Abar -> 0 (Appendix B); for small n
    Abar is tiny there (Jc1 ~ Abar^n carries Eq. 90), hence the scan down to ln Abar = -700.
    """
    roots = solutions_by_scan(math.exp(log_omega_bar), fixation, chi0, eta1, law, np.linspace(-700.0, 60.0, 7601))
    if not bool(roots.ok[0]):
        raise NoRootError(str(roots.message[0]))
    return np.array([log_omega_bar, math.log(float(roots.abar_m[0])), math.log(float(roots.Abar[0]))])


def _piece_end(x: Array, fixation: Fixation, chi0: float, bounds: tuple[float, float], notch: bool) -> str:
    """How a piece of the curve ends at x, "" while it goes on (module docstring).

    "unbounded_amplitude" above AMPLITUDE_CEILING, "range_end" outside ``bounds`` of ln omega_bar, and for
    a piece going to the notch (``notch``) "notch" (:func:`_into_notch`).
    """
    if _A_over_am(x[None, :], fixation, chi0)[0] > AMPLITUDE_CEILING:
        return "unbounded_amplitude"
    if not bounds[0] <= x[0] <= bounds[1]:
        return "range_end"
    return "notch" if notch and _into_notch(x, fixation, chi0) else ""


def _piece_ended(x: Array, fixation: Fixation, chi0: float, bounds: tuple[float, float], notch: bool) -> bool:
    """The stop of :func:`trace`: has the piece ended at x (:func:`_piece_end`)?"""
    return _piece_end(x, fixation, chi0, bounds, notch) != ""


def _trace_piece(res: Callable[[Array], Array], start: Array, direction: float, notch: bool, fixation: Fixation,
                 chi0: float, bounds: tuple[float, float], settings: ContinuationSettings) -> tuple[Curve, str]:
    """One piece of Eqs. (87), (90) from ``start`` along ln omega_bar's ``direction``, and how it ends.

    A corrector failure ends the piece where it happened, "corrector_failed" (never a jump, never lost).
    """
    stop = partial(_piece_ended, fixation=fixation, chi0=chi0, bounds=bounds, notch=notch)
    try:
        curve = trace(res, start, np.array([direction, 0.0, 0.0]), stop, settings)
    except ContinuationError as error:
        if error.partial is None:
            raise
        return error.partial, "corrector_failed"
    return curve, _piece_end(curve.points[-1], fixation, chi0, bounds, notch)


def trace_response_curve(
    fixation: Fixation, chi0: float, eta1: float, law: RateLaw, omega_bar_range: tuple[float, float] = (0.1, 50.0),
    settings: ContinuationSettings = ContinuationSettings(),
) -> ResponseCurve:
    """Trace Eqs. (87), (90) over ``omega_bar_range`` by pseudo-arclength continuation (Fig. 5).

    One piece from the low end to the high end when zeta > 0; two pieces when zeta = 0, each from
    one end towards omega_bar = 1, ended in the notch (:func:`_into_notch`; the exact solution Abar = 0 at
    omega_bar = 1 is added by the caller). A piece that does not reach where it was going (the notch, or
    the high end) leaves part of the curve untraced: that part is traced back from there (from the high
    end, or next to the notch, :func:`_notch_start`), the piece ``<name>_reverse``. How each piece ends
    (:func:`_piece_end`) is in ``ends``. Folds are located on every piece.
    """
    lo, hi = (math.log(v) for v in omega_bar_range)
    res = partial(residual, fixation=fixation, chi0=chi0, eta1=eta1, law=law)
    split = fixation.zeta == 0.0 and lo < 0.0 < hi  # the exact anti-resonance Abar = 0 at omega_bar = 1 (App. B)
    plan = [("lower", lo, 1.0), ("upper", hi, -1.0)] if split else [("full", lo, 1.0)]
    pieces, names, ends = [], [], []
    for name, s0, sign in plan:
        curve, end = _trace_piece(res, _start(math.exp(s0), fixation, chi0, eta1, law), sign, split, fixation, chi0,
                                  (lo, hi), settings)
        traced = [(name, curve, end)]
        if end != "notch" if split else curve.points[-1][0] < hi:  # the rest, traced back from where it was going
            back = (_notch_start(-sign * NOTCH_START, fixation, chi0, eta1, law) if split
                    else _start(math.exp(hi), fixation, chi0, eta1, law))
            traced.append((f"{name}_reverse", *_trace_piece(res, back, -sign, False, fixation, chi0, (lo, hi),
                                                             settings)))
        for label, piece, how in traced:
            clipped, how = _clip(piece, how, fixation, chi0, eta1, law, (lo, hi))
            pieces.append(clipped)
            names.append(label)
            ends.append(how)
    folds = np.concatenate([locate_folds(res, c, settings) for c in pieces])
    return ResponseCurve(fixation, chi0, eta1, tuple(pieces), tuple(names), tuple(ends), folds)


def _into_notch(x: Array, fixation: Fixation, chi0: float) -> bool:
    """A/a_m < NOTCH_FLOOR or |ln omega_bar| < NOTCH_GAP at x = (ln omega_bar, ln abar_m, ln Abar) (Eq. 98 corrected).

    A branch approaching the anti-resonance omega_bar = 1, where Eq. (90) has the exact solution
    Abar = 0 for zeta = 0 (Appendix B). Within NOTCH_GAP of it the central differences of the Jacobian
    (step 1e-7 in ln omega_bar) would straddle omega_bar = 1, where ln|1 - omega_bar^2| is singular.
    """
    return bool(_A_over_am(x[None, :], fixation, chi0)[0] < NOTCH_FLOOR or abs(x[0]) < NOTCH_GAP)


def _clip(curve: Curve, end: str, fixation: Fixation, chi0: float, eta1: float, law: RateLaw,
          bounds: tuple[float, float]) -> tuple[Curve, str]:
    """Replace a last point beyond the range ``bounds`` of ln omega_bar by the solution at its end (Eqs. 87, 90).

    Newton at the end of the range from the last point, else from the chord between the last two points
    at the end (a long last step on a steep piece); if neither converges, the piece ends at its last point
    inside the range, "corrector_failed" (``end`` otherwise).
    """
    lo, hi = bounds
    last = curve.points[-1]
    if lo <= last[0] <= hi:
        return curve, end
    edge = hi if last[0] > hi else lo
    chord = crossings(Curve(curve.points[-2:], curve.tangents[-2:], curve.residuals[-2:]), edge)
    for guess in [last, *chord]:
        state = newton_at_frequency(math.exp(edge), fixation, chi0, eta1, law, (math.exp(guess[1]), math.exp(guess[2])))
        if state.ok:
            points = curve.points.copy()
            points[-1] = [edge, math.log(float(state.abar_m)), math.log(float(state.Abar))]
            return Curve(points, curve.tangents, curve.residuals), end
    return Curve(curve.points[:-1], curve.tangents[:-1], curve.residuals[:-1]), "corrector_failed"
