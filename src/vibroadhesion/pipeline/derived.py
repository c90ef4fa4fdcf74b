"""The values of the rig that follow from the given ones of data/setup.yaml, with their formulas.

Every entry of data/setup.yaml is given (its source says where from: the paper, or an assumption). A quantity that
follows from given ones is never typed in: each step computes it where it is used, from the values it reads
(:mod:`vibroadhesion.core.groups`), and the canonical copy results/data/setup.json shows it under
:data:`~vibroadhesion.pipeline.data.DERIVED_GROUP` with its formula and equation, at the published Gent–Schultz
parameters, so that an edit of R, E, nu, w0, v0, omega0 or the test frequencies shows there at once.
"""

from __future__ import annotations

from typing import Any

from vibroadhesion.core import groups
from vibroadhesion.pipeline.data import Setup

NATURAL_FREQUENCY = "fixation.natural_frequency"


def _entry(value: float | list[float], unit: str, formula: str, source: str) -> dict[str, Any]:
    """One derived value as the canonical copy shows it."""
    return {"value": value, "unit": unit, "formula": formula, "source": source}


def derived_values(setup: Setup) -> dict[str, dict[str, Any]]:
    """E* (Remark 2, Appendix A), chi0 (Eq. 64) and, with a compliant fixation, nu0 (Eq. 97) and omega_bar (Eq. 65).

    At the published w0 and v0 (``gent_schultz_published``); the figures at a fit compute them at the fit. The
    natural frequency omega0 = sqrt(k/m) (Eq. 65) is a property of the fixation, given: nu0 follows from it.
    """
    e_star = setup.reduced_modulus
    out = {
        "reduced_modulus": _entry(e_star, "Pa", "E* = storage_modulus_factor E / (1 - nu^2)",
                                  "Remark 2 and Appendix A (below Eq. A.5): E* = E/(1 - nu^2), with E amplified by "
                                  "the storage-modulus factor (Sec. 3.4)"),
        "chi0": _entry(groups.chi0(setup.w0, e_star, setup.radius), "1",
                       "chi0 = (9 pi w0 / (E* R))^(1/3), w0 of gent_schultz_published",
                       "Eq. (64); Sec. 3.5.3 prints chi0 = 2.589e-2 for the paper's rig"),
    }
    omega0 = setup.values.get(NATURAL_FREQUENCY)
    if isinstance(omega0, float):  # a number by the schema; absent where the file gives no compliant fixation
        out["nu0"] = _entry(groups.nu0(setup.v0, omega0, setup.radius), "1",
                            "nu0 = v0 / (omega0 R), v0 of gent_schultz_published, omega0 = fixation.natural_frequency",
                            "Eq. (97); Sec. 3.5.3 prints nu0 = 1.227e-5 for the paper's rig")
        out["omega_bar"] = _entry([groups.omega_bar(f, omega0) for f in setup.frequencies_hz], "1",
                                  "omega_bar = 2 pi f / omega0 at each of test_conditions.frequencies",
                                  "Eq. (65); Sec. 3.5.3 prints 17.85, 26.78 and 35.7 at 200, 300 and 400 Hz")
    return out
