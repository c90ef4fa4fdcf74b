"""Readers of the artefacts most steps start from: the ingested rig and the Gent–Schultz fit."""

from __future__ import annotations

import json
from pathlib import Path

from vibroadhesion.core import groups
from vibroadhesion.pipeline.data import Setup, SetupValue, read_canonical_setup


def fitted(fit_json: str | Path, model: str | None = None) -> dict[str, float]:
    """w0, n, v0 of ``model``'s fit (default: the fit the figures use, ``figures_use``) in SI units."""
    fit = json.loads(Path(fit_json).read_text())
    parameters = fit["fits"][model or fit["figures_use"]]["parameters"]
    return {name: parameters[name]["estimate"] for name in ("w0", "n", "v0")}


def rig(setup_json: str | Path, fit_json: str | Path) -> tuple[Setup, dict[str, float], float]:
    """The ingested rig, the parameters of the fit the figures use, and chi0 at them (Eq. 64)."""
    setup = read_canonical_setup(setup_json)
    params = fitted(fit_json)
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
