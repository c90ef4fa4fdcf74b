"""Leading-order asymptotic model (Sec. 3.1): the steady state for any fixation of the indenter.

The quasi-static pull-off estimate built on it (Sec. 3.2, Eqs. 60–72) is in
:mod:`vibroadhesion.models.leading_pulloff`.

Monotone J-integrals (Gent–Schultz law). With u = (Abar sin t)^n the integrands of J0 and -Jc1 are
S(u) = (2+u)/sqrt(1+u) and u/sqrt(1+u) (see :mod:`vibroadhesion.core.integrals`), whose
u-derivatives u/(2(1+u)^{3/2}) and (2+u)/(2(1+u)^{3/2}) are positive; u increases with Abar,
so J0 and |Jc1| are strictly increasing, from J0 = 1 and Jc1 = 0 at Abar = 0 to infinity. The
tests check the monotonicity on a dense grid for n in [0.05, 4].

Steady state for any fixation (Sec. 3.1). The paper prints the system (Eqs. 43, 50–54) but not its
closed form; derivation:

Harmonics. At leading order the indentation and force oscillate in phase with cos(omega t')
(Eqs. 47–48): delta_c = -sqrt(2 pi w0 a_m/E*) Jc1, P_c = -sqrt(8 pi E* w0 a_m^3) Jc1, and
delta_s = P_s = 0. Since sqrt(8 pi E* w0 a_m^3) = 2 E* a_m sqrt(2 pi w0 a_m/E*), P_c = K delta_c
with the contact stiffness K = 2 E* a_m (Eq. C.5). Eqs. (41)–(42) then give (Eqs. 50–51)

    Xi_c = (k - m omega^2 + K) delta_c,    Xi_s = -c omega delta_c,

and Eq. (43), Xi_c^2 + Xi_s^2 = [(k - m omega^2)^2 + c^2 omega^2] h1^2 (printed "Xi_c^2 + Xi_c^2", a
misprint: docs/errata.md), reads, with the complex dynamic stiffness of the fixation
D = k - m omega^2 + i c omega,

    |delta_c| |D + K| = |D| h1,                                                      (I)

the base-excited two-spring system of Appendix B (Eq. B.3, there with c = 0): the indenter is held
by the fixation D to the frame and by the contact spring K to the moving base.

Dimensionless form. With a_o = c_o R, c_o = 2^(1/3) 3^(-2/3) chi0 (Eq. 86), abar_m = a_m/a_o
and 2 pi w0/E* = a_o^3/R^2: |delta_c|/R = c_o^2 abar_m^(1/2) |Jc1| and K/(E* R) = 2 c_o abar_m.
With d = D/(E* R) (= kappa (1 - omega_bar^2 + 2 i zeta omega_bar) for a spring-mass-dashpot,
Eqs. 65–66), (I) divided by E* R^2 is

    c_o^2 abar_m^(1/2) |Jc1(Abar)| = eta1 |d| / |d + 2 c_o abar_m|.                   (II)

Mean balance. Eq. (15) times k, k (hhat - h0) + m g = P_m + k delta_m, with P_m, delta_m of
Eqs. (52)–(53). Divided by E* R^2 c_o^2, using P_m/(E* R^2) = c_o^3 [(4/3) abar_m^3 - 2 J0 abar_m^(3/2)]
and R delta_m/a_o^2 = abar_m^2 - J0 abar_m^(1/2) =: deltabar_m (Eq. 86):

    c_o [(4/3) abar_m^3 - 2 J0 abar_m^(3/2)] + kappa deltabar_m = mu/c_o^2 + kappa base_offset,   (III)

with base_offset = (hhat - h0) R/a_o^2; the load group of the right-hand side, times c_o^2,
is lambda = mu + kappa (hhat - h0)/R. With h0 = hhat, (III) is Eq. (87) term by term; with J0 = 1
and a_m/R = c_o abar_m it is Eq. (82). Limits: kappa -> inf (d -> inf) gives Eq. (55) from (II)
and deltabar_m = base_offset, Eq. (56); kappa = 0 with d = -m omega^2/(E* R) gives Eq. (57)–(58)
from (II) and P_m = m g, Eq. (59).

Force rig (Fig. 2, Eq. 13). With the base at h0 and F1 sin(omega t) on the indenter, the mean of Eq. (13)
is Eq. (15) (F0 = m g - k (h0 - hhat)), so (III) is unchanged, and its oscillating part is Eq. (20) with
the forcing F1 sin(omega t) in place of Eq. (22). Both together force Im[(F1 - h1 D) e^{i omega t}], and
(I) becomes |delta_c| |D + K| = |F1 - h1 D|; divided by E* R^2, with force = F1/(E* R^2),

    c_o^2 abar_m^(1/2) |Jc1(Abar)| = |force - eta1 d| / |d + 2 c_o abar_m|             (II')

(:meth:`Fixation.indentation_response`). So the force rig with F1 = h1 |D| is the base rig (the same
Abar, a_m, w_eff, P_m, and the same |delta_c| at every a_m); at the base rig's anti-resonance d = 0
(Appendix B, Eq. B.3) the base rig does not excite the contact while the force rig gives
|delta_c| = F1/(2 E* a_m): the whole force goes into the contact spring. The scan's end (below) holds
for (II') as for (II): the numerator does not depend on abar_m.
"""

from __future__ import annotations

import math
from functools import partial
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from vibroadhesion.core import groups
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.groups import contact_radius_ratio
from vibroadhesion.core.integrals import abar_for_abs_jc1, j_integrals
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.core.records import SteadyState, stacked
from vibroadhesion.numerics.roots import NoRootError
from vibroadhesion.numerics.scan import (
    Node,
    approach_pole,
    bracket_increasing_root,
    polish_sign_change,
    roots_on_nodes,
)


def indentation_amplitude(abar_m: ArrayLike, jc1: ArrayLike, chi0: float) -> NDArray[np.float64]:
    """|delta_c| / R = c_o^2 abar_m^(1/2) |Jc1| (Eq. 47 with 2 pi w0/E* = a_o^3/R^2; = Eq. 93)."""
    return contact_radius_ratio(chi0) ** 2 * np.sqrt(np.asarray(abar_m, dtype=float)) * np.abs(jc1)


def pm_over_abs_pjkr(abar_m: ArrayLike, j0: ArrayLike) -> NDArray[np.float64]:
    """P_m / |P_JKR| = (4/3) [(4/3) abar_m^3 - 2 J0 abar_m^(3/2)], tensile negative (Eqs. 52, 71).

    From Eq. (52) with sqrt(8 pi w0 E* a_m^3) = 2 E* a_o^(3/2) a_m^(3/2)/R and
    |P_JKR| = (3/2) pi w0 R = (3/4) E* a_o^3/R. It is -1 at the JKR pull-off, J0 = 1 and
    abar_m^(3/2) = 3/4.
    """
    abar_m = np.asarray(abar_m, dtype=float)
    return (4.0 / 3.0) * ((4.0 / 3.0) * abar_m**3 - 2.0 * np.asarray(j0) * abar_m**1.5)


def mean_indentation(abar_m: ArrayLike, j0: ArrayLike) -> NDArray[np.float64]:
    """deltabar_m = R delta_m / a_o^2 = abar_m^2 - J0 abar_m^(1/2) (Eqs. 53, 86)."""
    abar_m = np.asarray(abar_m, dtype=float)
    return abar_m**2 - np.asarray(j0) * np.sqrt(abar_m)


def internal_variables(
    abar_m: ArrayLike, eta1: float, fixation: Fixation, chi0: float, law: GentSchultz, omega_check: float,
    force: float = 0.0,
) -> NDArray[np.float64]:
    """Abar on the amplitude equation (II') at each abar_m, d of the fixation at ``omega_check`` (Eqs. 13, 43, 105).

    The root of |Jc1(Abar)| = target,

        target = |force - eta1 d| / (c_o^2 abar_m^(1/2) |d + 2 c_o abar_m|)

    (force = F1/(E* R^2) of the force rig, 0 for the base rig: then eta1 |d| in the numerator, (II)),
    unique because |Jc1| rises strictly from 0 to infinity (module docstring); solved for every abar_m at
    once (:func:`vibroadhesion.core.integrals.abar_for_abs_jc1`, to 1e-14 in ln Abar). A zero numerator
    (no excitation, or the base rig at its anti-resonance d = 0, Appendix B) gives Abar = 0 exactly; at
    the contact resonance the amplitude is unbounded and :class:`NoRootError` is raised.
    """
    abar_m = np.atleast_1d(np.asarray(abar_m, dtype=float))
    if not np.all((abar_m > 0) & np.isfinite(abar_m)):
        raise ValueError(f"abar_m must be positive numbers, got {abar_m[~((abar_m > 0) & np.isfinite(abar_m))]!r}")
    if eta1 < 0 or not math.isfinite(eta1):
        raise ValueError(f"eta1 must be finite and non-negative, got {eta1!r}")
    if force < 0 or not math.isfinite(force):
        raise ValueError(f"force must be finite and non-negative, got {force!r}")
    response = fixation.indentation_response(abar_m, chi0, omega_check, eta1, force)
    if np.any(np.isinf(response)):
        raise NoRootError(f"Eq. (43) at abar_m = {abar_m[np.isinf(response)][0]:.6g}: contact resonance "
                          "(d + 2 c_o abar_m = 0), amplitude unbounded")
    Abar = np.zeros_like(abar_m)
    excited = response > 0
    log_target = np.log(response[excited]) - np.log(indentation_amplitude(abar_m[excited], 1.0, chi0))
    Abar[excited] = abar_for_abs_jc1(log_target, law.n, f"Eq. (43) at eta1 = {eta1:.6g}, force = {force:.6g}")
    return Abar


def mean_balance_residual(
    abar_m: ArrayLike, j0: ArrayLike, fixation: Fixation, chi0: float, base_offset: float
) -> NDArray[np.float64]:
    """Eq. (III) of the module docstring, left minus right; for rigid fixation deltabar_m - base_offset (Eq. 56).

    Elementwise in ``abar_m`` and ``j0``.

    ``base_offset`` = (hhat - h0) R / a_o^2 (positive: base pushed towards the indenter); for a
    rigid fixation it is the imposed mean indentation. The weight mu is the fixation's (Eq. 81).
    """
    deltabar_m = mean_indentation(abar_m, j0)
    if fixation.is_rigid:
        return deltabar_m - base_offset
    c_o = contact_radius_ratio(chi0)
    force = 0.75 * pm_over_abs_pjkr(abar_m, j0)  # (4/3) abar_m^3 - 2 J0 abar_m^(3/2)
    load = load_group(fixation.mu, base_offset, fixation.kappa, chi0)
    return c_o * force + fixation.kappa * deltabar_m - load / c_o**2


def load_group(mu: float, base_offset: float, kappa: float, chi0: float) -> float:
    """lambda = mu + kappa (hhat - h0)/R = mu + kappa c_o^2 base_offset: right-hand side of (III) times c_o^2."""
    return mu + kappa * contact_radius_ratio(chi0) ** 2 * base_offset


#: Step of the scan in ln abar_m, and the bound on the refinement towards a contact resonance.
SCAN_STEP = 0.05
_RESONANCE_REFINEMENTS = 60


def steady_states(
    eta1: float,
    fixation: Fixation,
    chi0: float,
    law: GentSchultz,
    *,
    base_offset: float = 0.0,
    omega_check: float = math.inf,
    abar_m_min: float = 1e-4,
    force: float = 0.0,
) -> SteadyState:
    """All leading-order steady states with abar_m >= ``abar_m_min``, sorted by abar_m (Sec. 3.1).

    Solves the amplitude equation (II) and the mean balance (III) (derivation in the module
    docstring; Eqs. 43, 50–54; limits Eqs. 55–56 and 57–59; the force rig's (II'), Eq. 13, with
    ``force`` = F1/(E* R^2) > 0, eta1 = 0 for the force rig alone). Inputs: eta1 = h1/R, the fixation (with
    its weight mu = m g/(E* R^2), Eq. 81), chi0 (Eq. 64), the Gent–Schultz law, the base offset
    (hhat - h0) R/a_o^2 (load group ``load_group``) and omega_check = omega R/v0 (Eq. 105; the
    fixation's d at that frequency, and A/a_m; a rigid fixation admits omega_check = inf).

    Returns one record of level ``leading`` with one element per steady state, in increasing abar_m
    (:func:`steady_state_at`). Where there is none (e.g. a tensile load beyond pull-off) or the scan
    cannot be completed (:class:`NoRootError` inside, e.g. a residual that does not fall towards a
    contact resonance), the record has one element of status ``no_solution`` with NaN numbers and the
    reason in ``message``: the exception becomes a status here, at the level boundary.

    Method. For given abar_m, (II) fixes Abar uniquely (:func:`internal_variables`), so the
    solutions are the roots of the one-variable residual F(abar_m) of (III) along that curve
    (:func:`balance_state`). F is scanned on a grid of step ``SCAN_STEP`` in ln abar_m
    (:func:`scan_segments`); each sign change is polished by Brent's method, and each interior
    extremum of |F| without a sign change is maximised to catch two roots inside one cell
    (:mod:`vibroadhesion.numerics.scan`). Where d is real and negative, (II) has a pole at the contact resonance
    (:meth:`Fixation.contact_resonance`) where Abar and J0 -> infinity, so F -> -infinity: the
    scan is split there and refined geometrically towards it until F < 0 and decreasing.

    End of the scan (a proof, not a cut-off). Beyond abar_turn = max(0, -Re d/(2 c_o)) (0 for rigid
    fixation) the target of (II) decreases strictly with abar_m, since
    d ln|d + 2 c_o x|^2/dx = 4 c_o (Re d + 2 c_o x)/|d + 2 c_o x|^2 >= 0 there, so Abar and J0 do not
    increase. Then d/dx [(4/3) x^3 - 2 J0 x^(3/2)] >= x^(1/2) (4 x^(3/2) - 3 J0) and
    d/dx [x^2 - J0 x^(1/2)] >= x^(-1/2) (2 x^(3/2) - J0/2), both positive once x^(3/2) >= (3/4) J0,
    a condition that, x^(3/2)/J0 rising, persists. So F increases strictly beyond the first grid
    point past abar_turn where x^(3/2) >= (3/4) J0, and from there at most one root remains; it
    exists iff F < 0 there and is bracketed by doubling the step (:func:`monotone_tail_start`,
    :func:`in_monotone_tail`). Below ``abar_m_min`` (a_m far
    below the JKR scale a_o, where with vibration Abar -> infinity) roots are not sought.

    Multiplicity and stability. In the static limit (J0 = 1) (III) is, in s = abar_m^(1/2),
    (4/3) c_o s^6 + kappa s^4 - 2 c_o s^3 - kappa s - Lambda = 0 with one sign change in the
    coefficients of its derivative: one minimum, so one root for Lambda >= 0 and two or none for
    Lambda < 0 (JKR's stable branch and, at the smaller abar_m, its unstable one). With
    vibration, and near a contact resonance, there can be more, so all are returned. ``stable`` is
    True when F increases through the root: the mean force-plus-spring balance then restores a
    perturbed a_m (with the amplitude equation kept satisfied). For J0 = 1 this is the JKR
    criterion under a compliant machine, dP_m/da_m + k d delta_m/da_m > 0, which is dP_m/da_m > 0 under
    load control (kappa = 0) and d delta_m/da_m > 0 under displacement control (rigid).
    """
    _check_steady_state_inputs(law, chi0, base_offset, abar_m_min, omega_check)
    balance = MeanBalance(eta1, fixation, chi0, law, omega_check, base_offset, force)
    what = f"Eq. (54) with Eq. (43) at eta1 = {eta1:.6g}, force = {force:.6g}, {fixation}"
    try:
        roots = mean_balance_roots(balance, abar_m_min, what)
        if roots:
            return stacked([steady_state_at(abar_m, stable, balance, omega_check) for abar_m, stable in sorted(roots)])
    except NoRootError as error:
        return SteadyState.unsolved("leading", "no_solution", str(error), shape=(1,))
    return SteadyState.unsolved(
        "leading", "no_solution", f"{what}: no steady state with abar_m >= {abar_m_min:.3g} (base offset = "
        f"{base_offset:.6g}); a tensile load beyond the vibroadhesive pull-off has none", shape=(1,))


def mean_balance_roots(balance: MeanBalance, abar_m_min: float, what: str) -> list[tuple[float, bool]]:
    """Every root (abar_m, stable) >= ``abar_m_min`` of the mean balance (III) along (II) (Eqs. 43, 54), unsorted.

    The scan of :func:`steady_states` (method and end in its docstring): the segments of
    :func:`scan_segments`, each sign change and interior extremum polished, and the one root of the
    monotone tail bracketed by doubling. Raises :class:`NoRootError` where the scan cannot be completed.
    """
    fixation, chi0, omega_check = balance.fixation, balance.chi0, balance.omega_check
    # else Abar = 0, J0 = 1 throughout (no excitation, or the base rig at its anti-resonance d = 0)
    vibrating = (balance.eta1 > 0 and fixation.d(omega_check) != 0) or balance.force > 0
    resonance = fixation.contact_resonance(chi0, omega_check) if vibrating else None
    abar_turn = monotone_tail_start(fixation, chi0, omega_check) if vibrating else 0.0
    z_res = math.log(resonance) if resonance is not None and resonance > abar_m_min else None
    segments = scan_segments(balance, math.log(abar_m_min), z_res, abar_turn, what)
    residual = partial(balance_residual, balance=balance)
    tail_root_bracket = bracket_increasing_root(residual, *segments[-1][-1], SCAN_STEP, what)
    roots = [root for nodes in segments for root in roots_on_nodes(residual, nodes, what)]
    if tail_root_bracket is not None:
        roots.append(polish_sign_change(residual, *tail_root_bracket, True, what))
    return roots


def _check_steady_state_inputs(
    law: GentSchultz, chi0: float, base_offset: float, abar_m_min: float, omega_check: float
) -> None:
    """Reject inputs outside the domain of :func:`steady_states` (Eqs. 43, 54, 64, 105); the fixation checks itself.

    ValueError, or TypeError for a law other than Gent–Schultz (Eqs. 73–75).
    """
    if not isinstance(law, GentSchultz):
        raise TypeError("steady_states needs the Gent–Schultz law: the scan's end rests on its monotone J0 and |Jc1|")
    if not (math.isfinite(chi0) and chi0 > 0):
        raise ValueError(f"chi0 must be a positive number, got {chi0!r}")
    if not math.isfinite(base_offset):
        raise ValueError(f"need a finite base offset, got base_offset = {base_offset!r}")
    if not (math.isfinite(abar_m_min) and abar_m_min > 0):
        raise ValueError(f"abar_m_min must be a positive number, got {abar_m_min!r}")
    if not omega_check > 0:
        raise ValueError(f"omega_check must be positive, got {omega_check!r}")


class MeanBalance(NamedTuple):
    """Everything but abar_m in the mean balance (III) along the amplitude equation (II) (Eqs. 43, 54)."""

    eta1: float  # h1 / R
    fixation: Fixation
    chi0: float  # Eq. (64)
    law: GentSchultz
    omega_check: float  # omega R / v0, Eq. (105): the frequency of the fixation's d
    base_offset: float  # (hhat - h0) R / a_o^2
    force: float = 0.0  # F1 / (E* R^2) of the force rig, Eq. (13)


def balance_states(
    z: ArrayLike, balance: MeanBalance
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """(F, Abar, J0) at abar_m = e^z along the amplitude equation (II) (Eqs. 43, 54), elementwise in the 1-d ``z``.

    Abar solves (II) (Eq. 43, :func:`internal_variables`), J0 = J0(Abar) (Eq. 28) and F is the
    mean-balance residual (III) (Eq. 54, :func:`mean_balance_residual`).
    """
    abar_m = np.exp(np.asarray(z, dtype=float))
    Abar = internal_variables(abar_m, balance.eta1, balance.fixation, balance.chi0, balance.law, balance.omega_check,
                              balance.force)
    j0 = j_integrals(Abar, balance.law.n)[0]
    return mean_balance_residual(abar_m, j0, balance.fixation, balance.chi0, balance.base_offset), Abar, j0


def balance_state(z: float, balance: MeanBalance) -> tuple[float, float, float]:
    """(F, Abar, J0) at one abar_m = e^z (:func:`balance_states`; Eqs. 43, 54)."""
    f, Abar, j0 = balance_states(np.array([z]), balance)
    return float(f[0]), float(Abar[0]), float(j0[0])


def balance_residual(z: float, balance: MeanBalance) -> float:
    """F(e^z), the residual of the mean balance (III) along the amplitude equation (II) (Eqs. 43, 54)."""
    return balance_state(z, balance)[0]


def monotone_tail_start(fixation: Fixation, chi0: float, omega_check: float) -> float:
    """abar_turn = max(0, -Re d/(2 c_o)) with d at ``omega_check``, 0 for a rigid fixation (Eqs. 43, 86).

    Beyond it the target of the amplitude equation (II) decreases strictly with abar_m (proof in
    :func:`steady_states`).
    """
    if fixation.is_rigid:
        return 0.0
    return max(0.0, -fixation.d(omega_check).real / (2.0 * contact_radius_ratio(chi0)))


def in_monotone_tail(z: float, j0: float, abar_turn: float) -> bool:
    """abar_m = e^z > abar_turn and abar_m^(3/2) >= (3/4) J0 (Eqs. 43, 54).

    From here on the residual of the mean balance (III) increases strictly along (II) (proof in
    :func:`steady_states`).
    """
    return math.exp(z) > abar_turn and math.exp(1.5 * z) >= 0.75 * j0


def scan_segments(
    balance: MeanBalance, z_min: float, z_res: float | None, abar_turn: float, what: str
) -> list[list[Node]]:
    """Nodes (z, F), ascending, of each pole-free segment of the scan of F in z = ln abar_m (Eqs. 43, 54).

    F is the residual of the mean balance (III) along the amplitude equation (II).

    From ``z_min`` in steps of ``SCAN_STEP``; split at the contact resonance ``z_res`` (``None``: none above
    z_min) and refined towards it from both sides (:func:`vibroadhesion.numerics.scan.approach_pole`);
    ended at the first node in the monotone tail (:func:`in_monotone_tail`), which is the last node of the
    last segment.
    """
    residual = partial(balance_residual, balance=balance)
    segments: list[list[Node]] = []
    z = z_min
    if z_res is not None:
        grid = z_min + SCAN_STEP * np.arange(max(0, math.ceil((z_res - z_min) / SCAN_STEP) - 1))
        below = list(zip(grid.tolist(), balance_states(grid, balance)[0].tolist(), strict=True))
        to_pole = approach_pole(residual, z_res, -1.0, SCAN_STEP, _RESONANCE_REFINEMENTS, what)
        segments.append([node for node in below + to_pole if node[0] >= z_min])
        z = z_res + SCAN_STEP
    above: list[Node] = []
    if z_res is not None:
        above = approach_pole(residual, z_res, +1.0, SCAN_STEP, _RESONANCE_REFINEMENTS, what)[::-1]
    segments.append(above + nodes_to_monotone_tail(z, balance, abar_turn))
    return segments


#: Nodes of the scan solved at once (one vectorised solve of Eq. 43): at most this many lie past the end.
_SCAN_CHUNK = 64


def nodes_to_monotone_tail(z: float, balance: MeanBalance, abar_turn: float) -> list[Node]:
    """Nodes (z + k SCAN_STEP, F), k = 0, 1, ..., up to the first in the monotone tail (Eqs. 43, 54).

    F is the residual of the mean balance (III) along the amplitude equation (II), the end
    :func:`in_monotone_tail`; the nodes are solved _SCAN_CHUNK at a time (:func:`balance_states`).
    """
    nodes: list[Node] = []
    while True:
        zs = z + SCAN_STEP * np.arange(len(nodes), len(nodes) + _SCAN_CHUNK)
        f, _, j0 = balance_states(zs, balance)
        for node, node_j0 in zip(zip(zs.tolist(), f.tolist(), strict=True), j0.tolist(), strict=True):
            nodes.append(node)
            if in_monotone_tail(node[0], node_j0, abar_turn):
                return nodes


def steady_state_at(abar_m: float, stable: bool, balance: MeanBalance, omega_check: float) -> SteadyState:
    """The steady state at a root abar_m of the mean balance (Sec. 3.1): a record of level ``leading``, shape ().

    Abar (Eq. 43), w_eff/w0 = J0^2 (Eqs. 28, 49), A/a_m (Eq. 45, docs/errata.md E1; 0 for
    omega_check = inf), P_m/|P_JKR| (Eqs. 52, 71) and deltabar_m (Eqs. 53, 86); ``stable`` as in
    :func:`steady_states`.
    """
    _, Abar, j0 = balance_state(math.log(abar_m), balance)
    return SteadyState(
        level="leading",
        status=np.asarray("ok"),
        Abar=np.asarray(Abar),
        abar_m=np.asarray(abar_m),
        w_eff_ratio=np.asarray(j0**2),
        A_over_am=np.asarray(float(groups.A_over_am(Abar, abar_m, balance.chi0, omega_check))),
        pm_over_abs_pjkr=np.asarray(float(pm_over_abs_pjkr(abar_m, j0))),
        deltabar_m=np.asarray(float(mean_indentation(abar_m, j0))),
        stable=np.asarray(stable),
    )
