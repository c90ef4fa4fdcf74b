"""The fixations a step builds from data/setup.yaml (vibroadhesion.pipeline.steps.inputs.setup_fixations).

Reference: the group ``fixation`` of the shipped data/setup.yaml, read back from ``Setup.values``, and
nu0 = v0/(omega0 R) (Eq. 97), which with the published v0 is the paper's nu0 = 1.227e-5 (Sec. 3.5.3) to 1e-3.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import NU0, RADIUS, V0

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.pipeline.data import load_setup
from vibroadhesion.pipeline.steps.inputs import setup_fixations

SETUP = load_setup(Path(__file__).resolve().parents[2] / "data" / "setup.yaml")


def test_rigid_case_is_the_rigid_fixation() -> None:
    assert setup_fixations(SETUP, V0, "rigid") == [Fixation.rigid()]


def test_compliant_case_is_the_simulated_spring_of_setup_yaml() -> None:
    (fixation,) = setup_fixations(SETUP, V0, "compliant")
    values = SETUP.values
    assert fixation.kind == "compliant"
    assert (fixation.kappa, fixation.zeta, fixation.mu) == (values["fixation.simulated_stiffness_ratio_kappa"],
                                                            values["fixation.simulated_damping_ratio_zeta"],
                                                            values["fixation.weight_ratio_mu"])
    assert fixation.nu0 == V0 / (values["fixation.natural_frequency"] * RADIUS)
    assert fixation.nu0 == pytest.approx(NU0, rel=1e-3)


def test_fig5_case_is_every_kappa_zeta_pair_kappa_outermost() -> None:
    fixations = setup_fixations(SETUP, V0, "fig5")
    kappas, zetas = SETUP.values["fixation.stiffness_ratio_kappa"], SETUP.values["fixation.damping_ratio_zeta"]
    assert isinstance(kappas, tuple) and isinstance(zetas, tuple)
    assert [(f.kappa, f.zeta) for f in fixations] == [(k, z) for k in kappas for z in zetas]
    assert len({(f.nu0, f.mu) for f in fixations}) == 1


def test_unknown_case_raises() -> None:
    with pytest.raises(ValueError, match="case"):
        setup_fixations(SETUP, V0, "free")  # type: ignore[arg-type]
