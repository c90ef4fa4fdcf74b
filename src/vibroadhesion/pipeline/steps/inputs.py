"""Readers of the artefacts most steps start from: the ingested rig and the Gent–Schultz fit."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Literal

import numpy as np

from vibroadhesion.core import groups
from vibroadhesion.core.fixation import Fixation
from vibroadhesion.pipeline.data import Setup, SetupValue, read_canonical_setup

#: Which fixations of data/setup.yaml a step needs (:func:`setup_fixations`).
FixationCase = Literal["rigid", "compliant", "fig5"]


def fitted(fit_json: str | Path, model: str | None = None) -> dict[str, float]:
    """w0, n, v0 of ``model``'s fit (default: the fit the figures use, ``figures_use``) in SI units."""
    fit = json.loads(Path(fit_json).read_text())
    parameters = fit["fits"][model or fit["figures_use"]]["parameters"]
    return {name: parameters[name]["estimate"] for name in ("w0", "n", "v0")}


def published(setup: Setup) -> dict[str, float]:
    """w0, n, v0 of data/setup.yaml's ``gent_schultz_published`` (the paper's Fig. 4 caption) in SI units."""
    return {"w0": setup.w0, "n": setup.n, "v0": setup.v0}


def parameter_label(setup_json: str | Path, fit_json: str | Path | None = None, math: bool = True) -> str:
    """The parameter set a figure uses, named on it: the fit the figures use, or the published set (:func:`rig`).

    In matplotlib's mathtext (``math``) for a figure, else plain text (w0, n, v0) for a heading of the report.
    """
    w0, n, v0 = ("$w_0$", "$n$", "$v_0$") if math else ("w0", "n", "v0")
    if fit_json is None:
        which, p = "published parameters", published(read_canonical_setup(setup_json))
    else:
        fit = json.loads(Path(fit_json).read_text())
        which = "published parameters" if fit["data_rows"] == 0 else f"{fit['figures_use']} fit"
        p = fitted(fit_json)
    return f"{which}: {w0} = {p['w0']:.3g} J/m², {n} = {p['n']:.3g}, {v0} = {p['v0'] * 1e6:.3g} µm/s"


def rig(setup_json: str | Path, fit_json: str | Path | None = None) -> tuple[Setup, dict[str, float], float]:
    """The ingested rig, one parameter set and chi0 at it (Eq. 64).

    The parameter set is the fit the figures use when ``fit_json`` is given (the steps behind Figs. 4 and 7,
    which show measured rows), else the published set of data/setup.yaml (the paper's figures, the validation
    and the identifiability study, which a data edit must not rerun).
    """
    setup = read_canonical_setup(setup_json)
    params = published(setup) if fit_json is None else fitted(fit_json)
    return setup, params, groups.chi0(params["w0"], setup.reduced_modulus, setup.radius)


def experiment_omega_check(setup: Setup, v0: float) -> dict[float, float]:
    """omega_check = omega R / v0 (Eq. 105) at each test frequency of the rig."""
    return {f: float(groups.omega_check(f, v0, setup.radius)) for f in setup.frequencies_hz}


def setup_entry(setup: Setup, key: str) -> SetupValue:
    """The value of an optional entry ``"group.entry"`` of data/setup.yaml (e.g. of the assumed compliant fixation).

    A ValueError names it when the file does not give it.
    """
    if key not in setup.values:
        raise ValueError(f"this step needs the entry {key} in data/setup.yaml (with value, unit and source)")
    return setup.values[key]


def setup_number(setup: Setup, key: str) -> float:
    """The single number of an optional entry ``"group.entry"`` (:func:`setup_entry`); a list is a ValueError."""
    value = setup_entry(setup, key)
    if isinstance(value, tuple):
        raise ValueError(f"the entry {key} in data/setup.yaml must be one number, not a list")
    return value


def setup_floats(setup: Setup, key: str) -> list[float]:
    """The numbers of an optional entry ``"group.entry"`` (:func:`setup_entry`), one or a list, as a list."""
    return [float(x) for x in np.atleast_1d(setup_entry(setup, key))]


def setup_fixations(setup: Setup, v0: float, case: FixationCase) -> list[Fixation]:
    """The fixations of data/setup.yaml's group ``fixation`` (Eqs. 65, 66, 81, 97): the one place they are built.

    ``"rigid"``: the rigid fixation. ``"compliant"``: the simulated compliant case
    (``simulated_stiffness_ratio_kappa``, ``simulated_damping_ratio_zeta``) of the validation sweep and the
    virtual pull-off. ``"fig5"``: every (kappa, zeta) of ``stiffness_ratio_kappa`` x ``damping_ratio_zeta``,
    kappa outermost (Fig. 5). nu0 = v0/(omega0 R) with omega0 = ``natural_frequency`` and the fitted ``v0``,
    mu = ``weight_ratio_mu``. A ValueError names a missing entry or an unknown case.
    """
    if case == "rigid":
        return [Fixation.rigid()]
    if case not in ("compliant", "fig5"):
        raise ValueError(f"case must be 'rigid', 'compliant' or 'fig5', got {case!r}")
    nu0 = groups.nu0(v0, setup_number(setup, "fixation.natural_frequency"), setup.radius)
    mu = setup_number(setup, "fixation.weight_ratio_mu")
    if case == "compliant":
        pairs = [(setup_number(setup, "fixation.simulated_stiffness_ratio_kappa"),
                  setup_number(setup, "fixation.simulated_damping_ratio_zeta"))]
    else:
        pairs = [(kappa, zeta) for kappa in setup_floats(setup, "fixation.stiffness_ratio_kappa")
                 for zeta in setup_floats(setup, "fixation.damping_ratio_zeta")]
    return [Fixation.compliant(kappa, zeta, nu0, mu) for kappa, zeta in pairs]
