"""Identifiability of the Gent–Schultz parameters from (simulated) pull-off rows.

References: closed forms (a power law, whose log-sensitivities are its exponents; diagonal and
appended-row Fisher matrices, whose Cramer-Rao bounds are explicit); the exact high-frequency
limit of the simulation (the exact-averaging force minimum, to 1e-4), under which a fit of that
level must recover the simulation's parameters to within the first-order bias its own model error
implies; the simulation's frequency dependence for the v0 column.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from conftest import FREQUENCIES_HZ, N_PUBLISHED, RADIUS, REDUCED_MODULUS, V0, W0

from vibroadhesion.experiments import identifiability, virtual_pulloff
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters, predict_pulloff, pulloff_mN

GEOMETRY = {"radius": RADIUS, "reduced_modulus": REDUCED_MODULUS}
PUBLISHED = GentSchultzParameters(w0=W0, n=N_PUBLISHED, v0=V0)  # Fig. 4 caption


def _simulated(params: GentSchultzParameters, frequencies, h1_um) -> pd.DataFrame:
    """Simulated (virtual) pull-off rows, as fit input."""
    tables = [virtual_pulloff.pulloff_table(params, f, np.asarray(h1_um, dtype=float), **GEOMETRY) for f in frequencies]
    rows = pd.concat(tables, ignore_index=True)
    rows = rows[rows["model"] == "simulation"].reset_index(drop=True)
    assert (rows["status"] == "pulloff").all(), rows
    return rows.assign(line=np.arange(len(rows)))


def test_log_sensitivity_of_a_power_law_is_its_exponents() -> None:
    """P = w0^0.3 n^1.7 v0^-0.2 (times a per-row constant): ln P is linear in ln theta, so central
    differences are exact: 1e-12.
    """
    exponents = {"w0": 0.3, "n": 1.7, "v0": -0.2}
    key = pd.DataFrame({"frequency_hz": [200.0, 400.0], "h1_um": [20.0, 100.0], "status": "pulloff"})
    constant = np.array([150.0, 1400.0])

    def rows(params: GentSchultzParameters) -> pd.DataFrame:
        force = constant * math.prod(getattr(params, k) ** e for k, e in exponents.items())
        return key.assign(pulloff_mN=force)

    plus = {k: rows(identifiability.perturbed(PUBLISHED, k, 1)) for k in exponents}
    minus = {k: rows(identifiability.perturbed(PUBLISHED, k, -1)) for k in exponents}
    table = identifiability.log_sensitivity(rows(PUBLISHED), plus, minus)
    for k, e in exponents.items():
        assert np.allclose(table[f"dlnP_dln{k}"], e, rtol=0, atol=1e-12)


def test_cramer_rao_errors_of_explicit_designs() -> None:
    """S = diag(1, 2, 4): standard errors sigma (1, 1/2, 1/4), no correlation; with the static JKR
    row (1, 0, 0) appended, the w0 error drops to sigma/sqrt(2). Exact to 1e-14.
    """
    sensitivity = pd.DataFrame({"dlnP_dlnw0": [1.0, 0, 0], "dlnP_dlnn": [0, 2.0, 0], "dlnP_dlnv0": [0, 0, 4.0]})
    table = identifiability.information_table(sensitivity, [0.01]).set_index("design")
    alone, static = table.loc["virtual experiment"], table.loc["virtual experiment + static JKR pull-off"]
    assert np.allclose([alone["w0_relative_se"], alone["n_relative_se"], alone["v0_relative_se"]], [0.01, 0.005, 0.0025],
                       rtol=1e-14)
    assert alone["corr_w0_n"] == 0.0 and alone["corr_n_v0"] == 0.0
    assert static["w0_relative_se"] == pytest.approx(0.01 / math.sqrt(2), rel=1e-14)
    assert static["v0_relative_se"] == pytest.approx(0.0025, rel=1e-14)


def test_failed_sensitivity_run_is_an_error_not_a_number() -> None:
    key = pd.DataFrame({"frequency_hz": [200.0], "h1_um": [100.0], "pulloff_mN": [1.0], "status": ["pulloff"]})
    lost = key.assign(status="contact_loss_before_extremum", pulloff_mN=math.nan)
    runs = {k: key for k in identifiability.PARAMETERS}
    with pytest.raises(ValueError, match=r"run n\+: no simulated pull-off at 200 Hz, h1 = 100 um"):
        identifiability.log_sensitivity(key, {**runs, "n": lost}, runs)


def test_simulated_v0_sensitivity_equals_minus_the_frequency_derivative() -> None:
    """h1 = 80, 100 um: d ln P/d ln v0 by central differences of the simulation at 300 Hz against
    -d ln P/d ln omega from the parabola through the simulated 200/300/400 Hz rows (v0 enters only via
    omega R/v0). Both are O(h^2) / interpolation estimates of the same derivative: 5 %.
    """
    h1 = [80.0, 100.0]
    base = _simulated(PUBLISHED, FREQUENCIES_HZ, h1)
    at_300 = base[base["frequency_hz"] == 300.0]
    plus = {k: at_300 for k in ("w0", "n")} | {"v0": _simulated(identifiability.perturbed(PUBLISHED, "v0", 1), [300.0], h1)}
    minus = {k: at_300 for k in ("w0", "n")} | {"v0": _simulated(identifiability.perturbed(PUBLISHED, "v0", -1), [300.0], h1)}
    sensitivity = identifiability.log_sensitivity(at_300, plus, minus)
    reference = identifiability.frequency_derivative(base, at_hz=300.0)
    assert np.all(reference["minus_dlnP_dlnomega"] < -0.05)  # a real frequency effect at these amplitudes
    assert np.allclose(sensitivity["dlnP_dlnv0"], reference["minus_dlnP_dlnomega"], rtol=0.05)


def test_exact_averaging_fit_recovers_simulation_parameters_within_its_model_error_at_high_frequency() -> None:
    """Noise-free virtual rows at omega_check = 1e9 (v0 = 64.7 nm/s, 200 Hz), h1 = 20, 60, 100 um, where the
    simulated pull-off equals the exact-averaging force minimum to its own accuracy. The fit of that
    level must land within twice the first-order bias its measured model error e implies,
    |d ln theta_j| <= sum_i |pinv(J)_ji| max|e_i| (J = d residual/d ln theta at the truth), and that
    bound must itself be small (< 1 %), so the test can fail.
    """
    truth = GentSchultzParameters(w0=W0, n=N_PUBLISHED, v0=2 * math.pi * 200.0 * RADIUS / 1e9)
    rows = _simulated(truth, [200.0], [20.0, 60.0, 100.0])
    model = "exact_averaging_force_minimum"

    def relative_residual(w0: float, n: float) -> np.ndarray:
        p = GentSchultzParameters(w0, n, truth.v0)
        pulloff = predict_pulloff(model, p, rows["frequency_hz"], rows["h1_um"], **GEOMETRY)
        return pulloff_mN(pulloff, w0, RADIUS) / rows["pulloff_mN"] - 1

    model_error = np.max(np.abs(relative_residual(truth.w0, truth.n)))
    h = 1e-4
    jac = np.column_stack([
        (relative_residual(truth.w0 * math.exp(h), truth.n) - relative_residual(truth.w0 * math.exp(-h), truth.n)) / (2 * h),
        (relative_residual(truth.w0, truth.n * math.exp(h)) - relative_residual(truth.w0, truth.n * math.exp(-h))) / (2 * h),
    ])
    bound = np.abs(np.linalg.pinv(jac)).sum(axis=1) * model_error
    assert model_error < 1e-3 and np.all(bound < 1e-2), (model_error, bound)

    fit = fit_gent_schultz(rows, model, PUBLISHED, **GEOMETRY)
    assert fit["status"] == "fitted" and fit["v0_identifiable"] is False
    recovered = np.log([fit["parameters"]["w0"]["estimate"] / truth.w0, fit["parameters"]["n"]["estimate"] / truth.n])
    assert np.all(np.abs(recovered) <= 2 * bound + 1e-6), (recovered, bound)


def test_refined_fit_of_simulated_rows_says_v0_is_not_identifiable() -> None:
    """Simulated rows at 200/300/400 Hz, h1 = 60, 100 um: the frequency effect (up to 10 %) is real but
    the refined model cannot resolve v0 from it; the fit says so and keeps the start value of v0.
    """
    rows = _simulated(PUBLISHED, FREQUENCIES_HZ, [60.0, 100.0])
    fit = fit_gent_schultz(rows, "refined", PUBLISHED, **GEOMETRY)
    assert fit["v0_identifiable"] is False
    assert fit["v0_note"].startswith("v0 not identifiable")
    assert fit["parameters"]["v0"]["estimate"] == PUBLISHED.v0 and fit["parameters"]["v0"]["std_error"] is None


def test_recommendation_picks_the_smallest_misfit_and_trusts_only_unbiased_parameters() -> None:
    """Synthetic tables: level B misfits least; its w0 bias (1 %) is inside the 4 % Cramer-Rao error, its n bias
    (-80 %) is not; v0 (SE 80 %) is not identifiable. A failed level is never recommended.
    """
    nan = math.nan
    fits = pd.DataFrame([
        {"model": "A", "status": "fitted", "rms_relative_residual": 0.20, "max_relative_residual": 0.3,
         "w0_relative_bias": 0.5, "n_relative_bias": 0.1, "v0_relative_bias": nan},
        {"model": "B", "status": "fitted", "rms_relative_residual": 0.05, "max_relative_residual": 0.13,
         "w0_relative_bias": 0.01, "n_relative_bias": -0.8, "v0_relative_bias": nan},
        {"model": "C", "status": "failed", "rms_relative_residual": nan, "max_relative_residual": nan,
         "w0_relative_bias": nan, "n_relative_bias": nan, "v0_relative_bias": nan},
    ])
    sensitivity = pd.DataFrame({"dlnP_dlnw0": [1.0, 0, 0], "dlnP_dlnn": [0, 25.0, 0], "dlnP_dlnv0": [0, 0, 0.05],
                                "h1_um": [20.0, 100.0, 60.0]})
    information = identifiability.information_table(sensitivity.iloc[:, :3], [0.04])
    text = identifiability.recommendation(fits, information, sensitivity, 0.04)
    assert text.startswith("Fit real data with **B**")
    assert "Trust its **w0** (bias +1.0 %" in text
    assert "Do not trust its n: bias -80 %" in text and "at h1 = 100 um" in text
    assert "v0 is not identifiable" in text and "C" not in text.split("against")[1].split(".")[0]
