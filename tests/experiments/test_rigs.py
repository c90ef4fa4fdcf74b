"""The rig comparison (vibroadhesion.experiments.rigs): drives, rows and the equivalence summary.

References: the closed forms of the drives (F1 = k h1 |1 - omega_bar^2 + 2 i zeta omega_bar| and F1 = k h1, Eqs. 13,
22, 65, 66), the identity of the base rig and the equal-amplitude force rig (their forcings of Eq. 20 differ by
a shift of time only: equal to 1e-12 at leading order, 1e-9 in the simulation, as in tests/simulation/
test_force_rig.py), and Appendix B's anti-resonance (the base rig's contact is not forced: w_eff = w0 exactly at
leading order, and the simulated steady state is the static one of Eq. 10 to the shooting's tolerance; the force
rig at F1 = k h1 drives it: w_eff > w0 and the pull-off grows).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from conftest import CHI0, N_PUBLISHED, NU0, RADIUS

from vibroadhesion import simulation
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.rigs import (
    RIGS,
    STATIC,
    drive,
    equivalence_summary,
    relative_difference,
    rig_comparison,
    static_row,
)

ETA1 = 20e-6 / RADIUS


def test_drives_are_the_closed_forms() -> None:
    spring = Fixation.compliant(1e-3, 0.01, NU0)
    omega_check = 17.85 / NU0
    modulus = abs(complex(1 - 17.85**2, 2 * 0.01 * 17.85))
    assert drive("base", ETA1, spring, omega_check) == (ETA1, 0.0)
    assert drive("force_equivalent", ETA1, spring, omega_check)[1] == pytest.approx(1e-3 * ETA1 * modulus, rel=1e-14)
    assert drive("force_spring", ETA1, spring, omega_check) == (0.0, 1e-3 * ETA1)
    with pytest.raises(ValueError, match="rig"):
        drive("pendulum", ETA1, spring, omega_check)


@pytest.fixture(scope="module")
def table() -> pd.DataFrame:
    spring = Fixation.compliant(1e-3, 0.01, NU0)
    undamped = Fixation.compliant(1e-3, 0.0, NU0)
    return rig_comparison([(spring, [17.85]), (undamped, [1.0])], [ETA1], CHI0, N_PUBLISHED)


def test_equal_amplitude_force_rig_is_the_base_rig(table: pd.DataFrame) -> None:
    """Leading order to 1e-12 and simulation (steady state and virtual pull-off) to 1e-9 at 200 Hz (omega_bar 17.85)."""
    summary = equivalence_summary(table)
    damped = summary[summary["zeta"] == 0.01].set_index("level")
    for column in ("max_rel_diff_w_eff_ratio", "max_rel_diff_pulloff_ratio", "max_rel_diff_delta_amplitude"):
        assert damped.loc["leading", column] < 1e-12, column
        assert damped.loc["simulation", column] < 1e-9, column
    rows = table[(table["zeta"] == 0.01) & (table["level"] == "simulation")]
    assert rows["status"].str.startswith("ok; pull-off pulloff").all() and len(rows) == len(RIGS)


def test_force_rig_drives_the_contact_at_the_base_rigs_anti_resonance(table: pd.DataFrame) -> None:
    """Hard case (Appendix B): zeta = 0, omega_bar = 1. Base rig: w_eff = w0 and pull-off ratio 1 exactly (leading);
    the equal-amplitude force rig needs F1 = 0; neither contact is forced, so the simulated rows are the static state
    and the JKR pull-off (static_row, against the shooting in the next test); the force rig at F1 = k h1 vibrates the
    contact: w_eff/w0 and the pull-off ratio above 1, simulated and leading (their contact-displacement amplitudes
    agree as tests/simulation/test_force_rig.py states).
    """
    anti = table[table["zeta"] == 0.0]
    by = {(r.rig, r.level): r for r in anti.itertuples()}
    assert by["base", "leading"].w_eff_ratio == 1.0 and by["base", "leading"].pulloff_ratio == 1.0
    assert by["force_equivalent", "leading"].drive_ratio == 0.0
    for rig in ("base", "force_equivalent"):
        static = by[rig, "simulation"]
        assert static.status == STATIC and static.pulloff_ratio == 1.0 and static.w_eff_ratio == 1.0
        assert static.abar_m == pytest.approx(by[rig, "leading"].abar_m, rel=1e-9)
    leading, simulated = by["force_spring", "leading"], by["force_spring", "simulation"]
    assert simulated.w_eff_ratio > 1.0 and simulated.pulloff_ratio > 1.0
    assert leading.w_eff_ratio > 1.0 and leading.pulloff_ratio > 1.0
    summary = equivalence_summary(table).set_index(["zeta", "level"])
    assert (summary.loc[(0.0, "simulation")].drop("omega_bar") == 0.0).all()


def test_static_row_is_the_shot_steady_state_of_the_unforced_base_rig() -> None:
    """The base rig at the undamped anti-resonance, shot in time (the full model, Eq. 8 with the base moving): its
    periodic state is static to rounding, at the static state's radius (Eq. 10, Appendix A) to 1e-9 (the shooting's
    tolerance), so static_row's closed form is the simulation's answer.
    """
    undamped = Fixation.compliant(1e-3, 0.0, NU0)
    problem = Problem(GentSchultz(N_PUBLISHED), CHI0, ETA1, 1.0 / NU0, undamped)
    shot, static = simulation.steady_state(problem), static_row(problem)
    assert shot.ok and float(shot.abar_m) == pytest.approx(static["abar_m"], rel=1e-9)
    assert float(shot.Abar) < 1e-12 and float(shot.w_eff_ratio) == pytest.approx(1.0, abs=1e-12)


def test_a_known_base_pulloff_is_taken_not_traced(table: pd.DataFrame) -> None:
    """base_pulloffs (the virtual pull-off job's rows in the pipeline) replace the base rig's traced pull-off only."""
    spring = Fixation.compliant(1e-3, 0.01, NU0)
    given = rig_comparison([(spring, [17.85])], [ETA1], CHI0, N_PUBLISHED, base_pulloffs={(17.85, ETA1): ("pulloff", 3.25)})
    traced = table[table["zeta"] == 0.01].reset_index(drop=True)
    base = int(np.flatnonzero((given["rig"] == "base") & (given["level"] == "simulation"))[0])
    assert given.at[base, "pulloff_ratio"] == 3.25 and given.at[base, "status"] == traced.at[base, "status"]
    pd.testing.assert_frame_equal(given.drop(index=base), traced.drop(index=base))


def test_relative_difference_is_zero_where_both_vanish_and_nan_where_one_is_missing() -> None:
    a, b = pd.Series([0.0, 1.0, 2.0, math.nan]), pd.Series([0.0, 1.0, 1.0, 1.0])
    assert np.allclose(relative_difference(a, b), [0.0, 0.0, 0.5, math.nan], rtol=0, atol=0, equal_nan=True)
