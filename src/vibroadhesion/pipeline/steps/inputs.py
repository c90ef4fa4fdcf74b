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
    """w0, n, v0 of ``model``'s fit in SI units.

    Default: the set the figures use (``figures_use``: a level's fit, or ``published``).
    """
    fit = json.loads(Path(fit_json).read_text())
    used = model or fit["figures_use"]
    if used == "published":
        return {name: fit["published"][name] for name in ("w0", "n", "v0")}
    parameters = fit["fits"][used]["parameters"]
    return {name: parameters[name]["estimate"] for name in ("w0", "n", "v0")}


def published(setup: Setup) -> dict[str, float]:
    """w0, n, v0 of data/setup.yaml's ``gent_schultz_published`` (the paper's Fig. 4 caption) in SI units."""
    return {"w0": setup.w0, "n": setup.n, "v0": setup.v0}


def parameter_label(setup_json: str | Path, fit_json: str | Path | None = None, math: bool = True) -> str:
    """The parameter set a figure uses, named on it.

    The fit the figures use with each fitted parameter's interval, or the published set (:func:`rig`); where rows
    were fitted but the preferred level's fit is not used, why (e.g. the fit is poor). In matplotlib's mathtext
    (``math``) for a figure, on two lines; else plain text (w0, n, v0) on one line, for a heading of the report.
    """
    if fit_json is None:
        p = published(read_canonical_setup(setup_json))
        return f"published parameters: {_values(p, {}, math)}"
    fit = json.loads(Path(fit_json).read_text())
    p, used, newline = fitted(fit_json), fit["figures_use"], "\n" if math else " "
    if used == "published":
        why = f" ({fit['figures_reason']}):{newline}" if fit["data_rows"] else ": "
        return f"published parameters{why}{_values(p, {}, math)}"
    entries = fit["fits"][used]["parameters"]
    intervals = {name: entries[name]["interval"] for name in p if entries[name]["status"] == "fitted"}
    why = f" ({fit['figures_reason']})" if used != fit["figures_preferred"] else ""
    return (f"{used} fit of {fit['data_rows']} measured rows{why}, {fit['settings']['confidence']:.0%} intervals:"
            f"{newline}{_values(p, intervals, math)}")


#: How a parameter is named and scaled on a figure: mathtext symbol, plain name, unit, factor from SI.
_SHOWN = {"w0": ("$w_0$", "w0", "J/m²", 1.0), "n": ("$n$", "n", "", 1.0), "v0": ("$v_0$", "v0", "µm/s", 1e6)}


def _values(p: dict[str, float], intervals: dict[str, list[float]], math: bool = True) -> str:
    """"w0 = 0.236 J/m², n = 0.531, v0 = 44.5 µm/s", with [lower, upper] after each parameter in ``intervals``."""
    parts = []
    for name, (symbol, plain, unit, factor) in _SHOWN.items():
        bounds = intervals.get(name)
        interval = f" [{bounds[0] * factor:.3g}, {bounds[1] * factor:.3g}]" if bounds else ""
        parts.append(f"{symbol if math else plain} = {p[name] * factor:.3g}{interval}{' ' + unit if unit else ''}")
    return ", ".join(parts)


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
