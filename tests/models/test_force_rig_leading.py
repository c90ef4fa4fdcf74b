"""Leading order of the force-excitation rig (Fig. 2, Eq. 13; (II') of vibroadhesion.models.leading_order).

Independent references, written here from the printed equations in dimensional form with E* = R = 1,
w0 = chi0^3/(9 pi) (Eq. 64) and a_o = (2 pi w0)^(1/3) (Eq. 86), with 30-digit mpmath J-integrals:

* the base rig's leading order itself: Eq. (13) with F1 = h1 |k - m omega^2 + i c omega| forces Eq. (20) with
  the amplitude of Eq. (22), so every leading-order number of the two rigs is the same (to 1e-12: the two
  paths round differently);
* Appendix B's anti-resonance (zeta = 0, omega = sqrt(k/m), D = 0): Eq. (43) with the force F1 on the right,
  |Xi| = F1, Xi = (D + 2 E* a_m) delta_c (Eqs. 41-42, 47-48), is 2 E* a_m |delta_c| = F1, with delta_c of
  Eq. (47) and the mean balance Eq. (54) (h0 = hhat, mu = 0): solved in Abar; at a_m = a_cr (Eq. 61) it is
  (chi0^3/3) J0 |Jc1| = F1/(E* R^2), whose root gives P_cr/P_JKR = J0^2 (Eq. 71);
* the free indenter (Sec. 3.1.3) under F1 sin(omega t): Eq. (57) becomes |Xi_c| = F1 with Xi_c of Eq. (58)
  (corrected, docs/errata.md), and Eq. (59) P_m = m g holds as printed (the force has zero mean).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from conftest import CHI0, ETA1, N_PUBLISHED
from mpmath_reference import j_integrals_mp
from test_leading_order_steady_state import A_O, W0, thirty_digits  # noqa: F401 (the autouse fixture: 30 digits)

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.models.leading_order import steady_states
from vibroadhesion.models.leading_pulloff import pulloff_leading

LAW = GentSchultz(N_PUBLISHED)
FIELDS = ("Abar", "abar_m", "w_eff_ratio", "A_over_am", "pm_over_abs_pjkr", "deltabar_m")

@pytest.mark.parametrize(("kappa", "zeta", "omega_bar"), [(1e-3, 0.01, 17.85), (1e-2, 0.05, 5.0), (0.1, 0.2, 1.5),
                                                          (1e-3, 0.0, 17.85)])
def test_force_rig_with_f1_equal_h1_times_dynamic_stiffness_is_the_base_rig(kappa, zeta, omega_bar) -> None:
    """Reference: the base rig's leading order (Eqs. 43, 54, 67-71) at h1; the force rig at F1 = h1 |D| (module
    docstring). Every steady state (three on the folded curve at kappa = 1e-3) and the pull-off agree to 1e-12.
    """
    fixation = Fixation.compliant(kappa, zeta, 1.0)  # nu0 = 1: omega_check = omega_bar
    force = ETA1 * abs(fixation.d(omega_bar))
    base = steady_states(ETA1, fixation, CHI0, LAW, omega_check=omega_bar)
    forced = steady_states(0.0, fixation, CHI0, LAW, omega_check=omega_bar, force=force)
    assert base.ok.all() and forced.ok.all() and base.abar_m.shape == forced.abar_m.shape
    for field in FIELDS:
        assert np.allclose(getattr(forced, field), getattr(base, field), rtol=1e-12, atol=0), field
    assert np.array_equal(forced.stable, base.stable)
    base_pulloff = pulloff_leading(ETA1, CHI0, LAW, fixation, omega_bar)
    forced_pulloff = pulloff_leading(0.0, CHI0, LAW, fixation, omega_bar, force=force)
    assert float(forced_pulloff.pulloff_ratio) == pytest.approx(float(base_pulloff.pulloff_ratio), rel=1e-12)


def _anti_resonance_mean_radius(Abar: float) -> mp.mpf:
    """a_m of Eq. (54) with k - m omega^2 = 0 and c = 0, h0 = hhat, mu = 0: (4/3) a^3 + k a^2 = J0 (...) (E* = R = 1).

    Eq. (54) times k: 0 = -(sqrt(8 pi w0 a^3) + k sqrt(2 pi w0 a)) J0 + (4/3) a^3 + k a^2, solved by bisection.
    """
    j0 = j_integrals_mp(Abar, N_PUBLISHED)[0]
    kappa = mp.mpf(KAPPA)

    def balance(a: mp.mpf) -> mp.mpf:
        return (mp.mpf(4) / 3 * a**3 + kappa * a**2) - (mp.sqrt(8 * mp.pi * W0 * a**3) + kappa * mp.sqrt(2 * mp.pi * W0 * a)) * j0

    return mp.findroot(balance, (A_O * 0.5, A_O * 20), solver="bisect", tol=mp.mpf(10) ** -28)


KAPPA = 1e-3


def test_force_rig_at_the_base_rigs_anti_resonance_solves_eq_43_with_f1() -> None:
    """Hard case (Appendix B): d = 0. The base rig gives Abar = 0 and the static state; the force rig gives the root
    of 2 a_m sqrt(2 pi w0 a_m) |Jc1(Abar)| = F1 along Eq. (54) (module docstring), to 1e-9 in Abar and a_m.
    """
    fixation = Fixation.compliant(KAPPA, 0.0, 1.0)
    force = 1e-2 * KAPPA * ETA1
    base = steady_states(ETA1, fixation, CHI0, LAW, omega_check=1.0)
    assert base.Abar.tolist() == [0.0] and base.w_eff_ratio.tolist() == [1.0]
    forced = steady_states(0.0, fixation, CHI0, LAW, omega_check=1.0, force=force)
    assert forced.ok.all() and forced.Abar.size == 1 and float(forced.w_eff_ratio[0]) > 1.0

    def residual(Abar: float) -> mp.mpf:
        am = _anti_resonance_mean_radius(Abar)
        return 2 * am * mp.sqrt(2 * mp.pi * W0 * am) * abs(j_integrals_mp(Abar, N_PUBLISHED)[1]) - force

    Abar = float(forced.Abar[0])
    assert residual(Abar * (1 - 1e-9)) < 0 < residual(Abar * (1 + 1e-9))
    assert float(forced.abar_m[0]) == pytest.approx(float(_anti_resonance_mean_radius(Abar) / A_O), rel=1e-9)


@pytest.mark.parametrize("force", [1e-7, 1e-5, 1e-3])
def test_force_rig_pulloff_at_the_anti_resonance_solves_chi0_cubed_j0_jc1_over_3_equal_force(force: float) -> None:
    """Reference: (chi0^3/3) J0 |Jc1| = F1/(E* R^2) at a_m = a_cr (module docstring), 30-digit J's: Abar_cr to 1e-9,
    and P_cr/P_JKR = J0(Abar_cr)^2 (Eq. 71) to 1e-9; where the base rig's pull-off is the static JKR one.
    """
    fixation = Fixation.compliant(KAPPA, 0.0, 1.0)
    estimate = pulloff_leading(0.0, CHI0, LAW, fixation, 1.0, force=force)
    Abar = float(estimate.Abar_cr)

    def residual(a: float) -> mp.mpf:
        j0, jc1, _ = j_integrals_mp(a, N_PUBLISHED)
        return mp.mpf(CHI0) ** 3 / 3 * j0 * abs(jc1) - force

    assert residual(Abar * (1 - 1e-9)) < 0 < residual(Abar * (1 + 1e-9))
    assert float(estimate.pulloff_ratio) == pytest.approx(float(j_integrals_mp(Abar, N_PUBLISHED)[0] ** 2), rel=1e-9)
    assert float(pulloff_leading(ETA1, CHI0, LAW, fixation, 1.0).pulloff_ratio) == 1.0


@pytest.mark.parametrize("beta", [0.01, 0.3])
def test_free_indenter_under_a_harmonic_force_equals_eqs_57_59_with_f1(beta: float) -> None:
    """Reference: |Xi_c| = F1 with Xi_c = (m omega^2 - 2 E* a_m) sqrt(2 pi w0 a_m) Jc1 (Eq. 58 corrected) and
    Eq. (59) with m g = 0, i.e. a_m^(3/2) = (3/4) sqrt(8 pi w0) J0: one equation in Abar, roots to 1e-9, and
    P_m = m g = 0 (Eq. 52 is a cancellation of terms (8/3) J0 abar_m^(3/2) with abar_m solved to ~1e-10: to 1e-8 of
    them). beta = m omega^2/(E* R); at beta = 0.3 the contact resonance lies above.
    """
    force = 1e-2 * ETA1 * beta

    def mean_radius(Abar: float) -> mp.mpf:
        return (mp.mpf(3) / 4 * mp.sqrt(8 * mp.pi * W0) * j_integrals_mp(Abar, N_PUBLISHED)[0]) ** (mp.mpf(2) / 3)

    def residual(Abar: float) -> mp.mpf:
        am, jc1 = mean_radius(Abar), j_integrals_mp(Abar, N_PUBLISHED)[1]
        return abs((beta - 2 * am) * mp.sqrt(2 * mp.pi * W0 * am) * jc1) - force

    record = steady_states(0.0, Fixation.free(beta), CHI0, LAW, omega_check=1.0, force=force)
    assert record.ok.all()
    for Abar, abar_m, pm, w in zip(record.Abar, record.abar_m, record.pm_over_abs_pjkr, record.w_eff_ratio,
                                   strict=True):
        assert residual(float(Abar) * (1 - 1e-9)) * residual(float(Abar) * (1 + 1e-9)) < 0
        assert float(abar_m) == pytest.approx(float(mean_radius(float(Abar)) / A_O), rel=1e-9)
        assert abs(float(pm)) < 1e-8 * (8 / 3) * math.sqrt(float(w)) * float(abar_m) ** 1.5


def test_negative_or_non_finite_force_raises() -> None:
    fixation = Fixation.compliant(KAPPA, 0.0, 1.0)
    for force in (-1e-9, math.inf):
        with pytest.raises(ValueError, match="force"):
            steady_states(0.0, fixation, CHI0, LAW, omega_check=1.0, force=force)
