"""Leading-order pull-off estimate (Sec. 3.2, Eqs. 60–72) for any fixation of the indenter.

The steady state it rests on, the amplitude equation (II) with the transmissibility T of (I), is
derived in the docstring of :mod:`vibroadhesion.models.leading_order` (Eqs. 43, 50–59).

Detachment is assumed when the mean contact radius reaches the JKR
critical value for the effective work of adhesion, a_m = a_cr (Eqs. 60–61), i.e.
abar_cr = a_cr/a_o = (9/16)^(1/3) J0^(2/3) (Eq. 61 over Eq. 86), and then

    P_cr / P_cr^JKR = J0(Abar_cr)^2.                                               Eq. (71)

For rigid fixation Eq. (55) at a_m = a_cr reads

    J0(Abar)^(1/3) |Jc1(Abar)| = 3 eta1 / chi0^2,                                  Eq. (72)

which fixes Abar_cr independently of the frequency. For any fixation the amplitude equation (II)
holds at a_m = a_cr; with c_o^2 abar_cr^(1/2) = (chi0^2/3) J0^(1/3) and 2 c_o abar_cr = chi0 J0^(2/3)
(c_o^3 = 2 chi0^3/9) it is

    (chi0^2/3) J0^(1/3) |Jc1| |d + chi0 J0^(2/3)| = eta1 |d|.                       (IV)

For the spring-mass-dashpot, d = kappa (1 - omega_bar^2 + 2 i zeta omega_bar), (IV) divided by kappa
is |xi_c + i xi_s| = eta1 |1 - omega_bar^2 + 2 i zeta omega_bar| with xi_c = (chi0^2/3) J0^(1/3)
(1 - omega_bar^2) Jc1 + (chi0^3/(3 kappa)) J0 Jc1 and xi_s = -(2 chi0^2/3) zeta omega_bar J0^(1/3) Jc1:
Eqs. (67)–(69) as printed (they follow from Eqs. 43, 47–48, 50–51 and 62–63 divided by k R, with
k - m omega^2 = k (1 - omega_bar^2) and c omega/k = 2 zeta omega_bar; docs/errata.md, checked).
As d -> infinity (kappa -> infinity, rigid) (IV) becomes Eq. (72).

Roots of (IV) (:func:`critical_internal_variables`). In z = ln Abar, g(z) = ln[(chi0^2/3) J0^(1/3) |Jc1|] -
ln[eta1 T(abar_cr)] with the transmissibility T(a) = |d|/|d + 2 c_o a| (Eq. I). g -> -infinity as
Abar -> 0 (the left term -> -infinity, T(abar_cr(0)) = |d|/|d + chi0| > 0) and g -> +infinity as
Abar -> infinity (J0 |Jc1| -> infinity while T J0^(2/3) stays bounded). Below the fixation's resonance
(Re d >= 0, omega_bar <= 1) T decreases with a_cr, hence with Abar, so g increases strictly and the
root is unique (as for Eq. 72). Above it (Re d < 0) T rises towards the contact resonance
a = -Re d/(2 c_o) (a pole when zeta = 0, where g -> -infinity on both sides) and there can be three
or more roots. d = 0 (zeta = 0, omega_bar = 1, the anti-resonance of Appendix B) gives Abar_cr = 0
exactly: no oscillation, the static JKR pull-off, ratio 1.

Force rig (Eq. 13; (II') of :mod:`vibroadhesion.models.leading_order`): eta1 |d| becomes |force - eta1 d|
with force = F1/(E* R^2), so (IV) reads (chi0^2/3) J0^(1/3) |Jc1| |d + chi0 J0^(2/3)| = |force - eta1 d|
and g has T replaced by that response (:meth:`Fixation.indentation_response`); the numerator is a
constant, so the limits of g and the root order above hold as they are. At the base rig's
anti-resonance d = 0 it is (chi0^3/3) J0 |Jc1| = force, whose left-hand side rises strictly from 0 to
infinity: one root, the force rig's pull-off where the base rig has none.

Which root is the pull-off. The withdrawal lowers the mean contact radius. With F(a_m) = a_m -
a_cr(Abar(a_m)), Abar(a_m) the unique solution of (II) at a_m
(:func:`vibroadhesion.models.leading_order.internal_variables`), the contact holds while F > 0 and
detaches where F first vanishes as a_m decreases; roots in a_m and roots of (IV) in Abar are in the
same order (a_cr increases with Abar). F < 0 as a_m -> 0 (T -> 1,
so Abar and a_cr -> infinity) and F > 0 as a_m -> infinity (T -> 0). Further roots come from T rising
towards the contact resonance, where the amplified oscillation makes F < 0 again; a withdrawal
that starts attached below them reaches the smallest root first, and that root is reported as the
pull-off. (A start above the contact resonance would meet the resonance first; this estimate does
not cover it, and :func:`critical_internal_variables` returns every root for a caller who needs the others.)


Uniqueness of Eq. (72) (Gent–Schultz law). J0 and |Jc1| are strictly increasing in Abar
(:mod:`vibroadhesion.models.leading_order`), so the left-hand side of Eq. (72) rises strictly from 0
(Abar = 0) to infinity, and Eq. (72) has exactly one root for every eta1 > 0.
"""

from __future__ import annotations

import math
from functools import partial

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.integrals import j_integrals_for_law
from vibroadhesion.core.ratelaw import RateLaw
from vibroadhesion.core.records import Pulloff
from vibroadhesion.models.leading_order import indentation_amplitude
from vibroadhesion.numerics.roots import NoRootError, solve_log_increasing, solve_log_increasing_many


def pulloff_from_internal_variable(level: str, Abar_cr: NDArray[np.float64], law: RateLaw) -> Pulloff:
    """The pull-off record at Abar_cr: J0 there (Eq. 28) and the ratio J0^2 (Eq. 71).

    A NaN Abar_cr (no root) gives the status ``no_solution`` and NaN numbers.
    """
    found = ~np.isnan(Abar_cr)
    j0 = np.where(found, j_integrals_for_law(np.where(found, Abar_cr, 0.0), law)[0], np.nan)
    pulloff_ratio = j0**2
    return Pulloff.from_ratio(level, np.where(found, "ok", "no_solution"), pulloff_ratio, Abar_cr=Abar_cr,
                              sqrt_w_eff_ratio=j0, w_eff_ratio=pulloff_ratio)


def pulloff_lhs_leading(Abar: ArrayLike, law: RateLaw) -> NDArray[np.float64]:
    """Left-hand side of Eq. (72), J0^(1/3) |Jc1|."""
    j0, jc1, _ = j_integrals_for_law(Abar, law)
    return np.cbrt(j0) * np.abs(jc1)


def pulloff_closure(j0: ArrayLike) -> NDArray[np.float64]:
    """abar_m = a_cr / a_o = (9/16)^(1/3) J0^(2/3): detachment at the JKR critical radius (Eqs. 61, 86)."""
    return (9.0 / 16.0) ** (1.0 / 3.0) * np.cbrt(j0) ** 2


def critical_internal_variable_leading(eta1: float, chi0: float, law: RateLaw, fixation: Fixation = Fixation.rigid(),
                          omega_check: float = math.inf, force: float = 0.0) -> float:
    """Abar_cr for one amplitude ratio eta1 = h1/R >= 0 and force F1/(E* R^2) >= 0 of the force rig (both 0 give 0).

    Rigid fixation (the default): the unique root of Eq. (72). Any other fixation, with its d at
    ``omega_check`` = omega R/v0 (Eq. 105): the smallest root of Eqs. (67)–(69), (IV) of the module
    docstring (:func:`critical_internal_variables`), the first reached as the base is withdrawn (module docstring).
    """
    for name, value in (("eta1", eta1), ("force", force)):
        if value < 0 or not np.isfinite(value):
            raise ValueError(f"{name} must be finite and non-negative, got {value}")
    if eta1 == 0 and force == 0:
        return 0.0
    if not fixation.is_rigid:
        return critical_internal_variables(eta1, fixation, chi0, law, omega_check, force=force)[0]
    log_target = np.log(3.0 * eta1 / chi0**2)
    return solve_log_increasing(
        lambda z: float(np.log(pulloff_lhs_leading(np.exp(z), law))) - log_target,
        what=f"Eq. (72) at eta1 = {eta1:.6g}",
    )


def pulloff_leading(eta1: ArrayLike, chi0: float, law: RateLaw, fixation: Fixation = Fixation.rigid(),
                    omega_check: float = math.inf, force: float = 0.0) -> Pulloff:
    """Leading-order pull-off, vectorised over eta1 (Eqs. 67–72): the record of level ``leading``.

    Eqs. (71)–(72) for rigid fixation (the default), Eqs. (67)–(69) and (71) for any other, with its d
    at ``omega_check`` (:func:`critical_internal_variable_leading`); ``force`` = F1/(E* R^2) adds the force rig
    (Eq. 13, module docstring). An amplitude without a root has the status ``no_solution``.
    """
    eta1 = np.asarray(eta1, dtype=float)
    if fixation.is_rigid and force == 0 and np.all(np.isfinite(eta1) & (eta1 > 0)):
        Abar = critical_internal_variables_rigid(eta1, chi0, law)
    else:
        Abar = np.vectorize(lambda e: critical_internal_variable_or_nan(e, chi0, law, fixation, omega_check, force),
                            otypes=[float])(eta1)
    return pulloff_from_internal_variable("leading", Abar, law)


def _log_pulloff_lhs(log_Abar: NDArray[np.float64], law: RateLaw) -> NDArray[np.float64]:
    """ln of the left-hand side of Eq. (72) at Abar = e^z (-inf where it vanishes: increasing all the same)."""
    with np.errstate(divide="ignore"):
        return np.log(pulloff_lhs_leading(np.exp(log_Abar), law))


def critical_internal_variables_rigid(eta1: NDArray[np.float64], chi0: float, law: RateLaw) -> NDArray[np.float64]:
    """Abar_cr of Eq. (72) for every amplitude ratio eta1 > 0 at once (rigid fixation).

    The roots of the increasing J0^(1/3)|Jc1| = 3 eta1/chi0^2
    (:func:`~vibroadhesion.numerics.roots.solve_log_increasing_many`), the same roots as
    :func:`critical_internal_variable_leading` point by point; NaN where one has no root.
    """
    try:
        return solve_log_increasing_many(partial(_log_pulloff_lhs, law=law), np.log(3.0 * eta1 / chi0**2),
                                         what="Eq. (72)")
    except NoRootError:
        return np.array([critical_internal_variable_or_nan(e, chi0, law, Fixation.rigid(), math.inf)
                         for e in eta1.ravel()]).reshape(eta1.shape)


def critical_internal_variable_or_nan(eta1: float, chi0: float, law: RateLaw, fixation: Fixation,
                                      omega_check: float, force: float = 0.0) -> float:
    """:func:`critical_internal_variable_leading`, NaN where it has no root (the level boundary of Eqs. 13, 67–72)."""
    try:
        return critical_internal_variable_leading(eta1, chi0, law, fixation, omega_check, force)
    except NoRootError:
        return math.nan


#: Grid in z = ln Abar on which Eqs. (67)-(69) are scanned for sign changes (:func:`critical_internal_variables`).
PULLOFF_SCAN = np.linspace(-40.0, 40.0, 1601)


def critical_internal_variables(eta1: float, fixation: Fixation, chi0: float, law: RateLaw, omega_check: float,
                   log_Abar: NDArray[np.float64] = PULLOFF_SCAN, force: float = 0.0) -> list[float]:
    """Every root Abar of the amplitude equation at a_m = a_cr, Eqs. (67)–(69), ascending; d at ``omega_check``.

    g(z) = ln[c_o^2 abar_cr^(1/2) |Jc1|] - ln[eta1 T(abar_cr)] with abar_cr = :func:`pulloff_closure` (J0),
    i.e. (IV) of the module docstring in logarithms, is evaluated on the grid ``log_Abar``; each sign
    change is polished by Brent's method (roots closer than the grid spacing can be missed). A contact
    resonance is no sign change (g -> -infinity on both sides). d = 0 (anti-resonance) gives [0.0] for the base
    rig alone; ``force`` = F1/(E* R^2) adds the force rig (Eq. 13, module docstring).
    Raises :class:`NoRootError` when g is not negative at the left end of the grid (the smallest root
    could lie below it) or when there is no sign change.
    """
    if not (eta1 >= 0 and force >= 0 and eta1 + force > 0 and math.isfinite(eta1 + force)):
        raise ValueError(f"eta1 and force must be non-negative numbers, not both 0, got {eta1!r}, {force!r}")
    if fixation.d(omega_check) == 0 and force == 0:
        return [0.0]
    values = critical_log_excess(np.asarray(log_Abar, dtype=float), eta1, fixation, chi0, law, omega_check, force)
    what = f"Eqs. (67)-(69) at eta1 = {eta1:.6g}, force = {force:.6g}, {fixation}"
    if not values[0] < 0:
        raise NoRootError(f"{what}: the left-hand side reaches the target below Abar = {math.exp(log_Abar[0]):.3g}")
    crossings = np.flatnonzero(np.sign(values[:-1]) * np.sign(values[1:]) < 0)
    if crossings.size == 0:
        raise NoRootError(f"{what}: no root for Abar up to {math.exp(log_Abar[-1]):.3g}")
    excess = partial(critical_log_excess, eta1=eta1, fixation=fixation, chi0=chi0, law=law, omega_check=omega_check,
                     force=force)
    return [math.exp(brentq(lambda z: float(excess(np.array([z]))[0]),
                            log_Abar[k], log_Abar[k + 1], xtol=1e-14, rtol=4 * np.finfo(float).eps))
            for k in crossings]


def critical_log_excess(
    log_Abar: NDArray[np.float64], eta1: float, fixation: Fixation, chi0: float, law: RateLaw, omega_check: float,
    force: float = 0.0,
) -> NDArray[np.float64]:
    """g(z) = ln[c_o^2 abar_cr^(1/2) |Jc1|] - ln[eta1 T(abar_cr)], z = ln Abar (Eqs. 67–69, 72).

    With the force rig's ``force`` = F1/(E* R^2) (Eq. 13), eta1 T is |force - eta1 d|/|d + 2 c_o abar_cr|
    (:meth:`Fixation.indentation_response`).

    (IV) of the module docstring in logarithms, i.e. half the logarithm of the printed Eq. (67) (with
    Eqs. 68–69) over eta1^2; for a rigid fixation (T = 1) ln of the left-hand side of Eq. (72) over its
    right-hand side.

    abar_cr = :func:`pulloff_closure` (J0) (Eqs. 61, 86). Vectorised over ``log_Abar`` (1-d).
    """
    j0, jc1, _ = j_integrals_for_law(np.exp(log_Abar), law)
    abar_cr = pulloff_closure(j0)
    response = fixation.indentation_response(abar_cr, chi0, omega_check, eta1, force)
    return np.log(indentation_amplitude(abar_cr, jc1, chi0)) - np.log(response)

