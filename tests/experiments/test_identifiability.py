"""Identifiability of the Gent–Schultz parameters from (simulated) pull-off rows.

References: closed forms (a power law, whose log-sensitivities are its exponents; diagonal and
appended-row Fisher matrices, whose Cramer-Rao bounds are explicit); the exact high-frequency
limit of the simulation (the exact-averaging force minimum, to 1e-4), under which a fit of that
level must recover the simulation's parameters to within the first-order bias its own model error
implies; the simulation's frequency dependence for the v0 column.
"""

from __future__ import annotations

import math
from dataclasses import replace

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


@pytest.mark.parametrize("rows", [[[1.0, 2.0, 3.0], [1.0, 0.0, 0.0]],
                                  [[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [1.0, 0.0, 0.0]],
                                  [[1.2484315, 1.5098986, -0.4253193], [1.0, 0.0, 0.0]]],
                         ids=["two-rows", "dependent-rows", "one-row-plus-static"])
def test_rank_deficient_design_determines_no_parameter(rows: list[list[float]]) -> None:
    """Two rows, or three of rank 2, cannot determine three parameters: infinite standard errors and NaN
    correlations, with no warning (the last case is the 1 Hz row plus the static row, whose S^T S numpy inverts on
    one CPU with a negative variance and refuses on another: the rank decides, not the inversion).
    """
    se, corr = identifiability.standard_errors(np.array(rows), 0.01)
    assert np.all(np.isinf(se)) and np.all(np.isnan(corr))


def _family_difference(name: str, frequency_hz: float, h1_um: float, step: float) -> float:
    """d ln P / d ln ``name`` by central differences of the virtual pull-off re-traced at ``name`` e^(+-step)."""
    forces = []
    for sign in (1, -1):
        shifted = replace(PUBLISHED, **{name: getattr(PUBLISHED, name) * math.exp(sign * step)})
        table = identifiability.envelope_sensitivity(shifted, frequency_hz, [h1_um], **GEOMETRY)
        forces.append(float(table["pulloff_mN"].iloc[0]))
    return math.log(forces[0] / forces[1]) / (2 * step)


@pytest.mark.parametrize("frequency_hz, h1_um", [(200.0, 100.0), (30.0, 60.0)])
def test_envelope_sensitivity_equals_central_differences_of_re_traced_families(frequency_hz: float,
                                                                               h1_um: float) -> None:
    """The sensitivity rows (envelope theorem at the detachment point) against central differences of whole
    families re-traced with each parameter scaled by e^(+-h), h = 0.02 and 0.01 (the old rule's way, smaller steps).
    A central difference errs by c h^2 + O(h^4), so D(h/2) errs by about |D(h) - D(h/2)|/3 (Richardson); the
    families' pull-offs carry ~1e-8 relative error (2e-8/2h = 1e-6 at h/2), the envelope derivative O(1e-5)
    (:mod:`vibroadhesion.experiments.simulation_fit`). Tolerance: twice the Richardson estimate + 2e-5.
    """
    table = identifiability.envelope_sensitivity(PUBLISHED, frequency_hz, [h1_um], **GEOMETRY)
    assert table["status"].tolist() == ["pulloff"]
    for name in identifiability.PARAMETERS:
        coarse, fine = (_family_difference(name, frequency_hz, h1_um, h) for h in (0.02, 0.01))
        tolerance = 2 * abs(coarse - fine) / 3 + 2e-5
        assert abs(table[f"dlnP_dln{name}"].iloc[0] - fine) < tolerance, (name, table, coarse, fine)


def test_a_row_whose_family_loses_contact_keeps_its_status_and_has_no_derivative() -> None:
    """1 Hz (omega_check = 7.3e3), h1 = 60 um: the family loses contact before a tensile extremum; 20 um has a
    pull-off. The lost row has its status, no force and no derivative (NaN), and the Cramer-Rao table leaves it out."""
    table = identifiability.envelope_sensitivity(PUBLISHED, 1.0, [20.0, 60.0], **GEOMETRY)
    assert table["status"].tolist() == ["pulloff", "contact_loss_before_extremum"]
    lost = table.iloc[1]
    assert math.isnan(lost["pulloff_mN"]) and all(math.isnan(lost[f"dlnP_dln{n}"]) for n in identifiability.PARAMETERS)
    assert np.isfinite(table.iloc[0][[f"dlnP_dln{n}" for n in identifiability.PARAMETERS]].to_numpy(float)).all()
    explicit = pd.DataFrame({"dlnP_dlnw0": [1.0, 0, 0], "dlnP_dlnn": [0, 2.0, 0], "dlnP_dlnv0": [0, 0, 4.0]})
    with_lost = identifiability.information_table(pd.concat([explicit, table.iloc[[1]]]), [0.01])
    assert with_lost["rows"].tolist() == [3, 4]  # the lost row is left out, the static row added
    assert with_lost["v0_relative_se"].iloc[0] == pytest.approx(0.0025, rel=1e-14)
    alone = identifiability.information_table(table, [0.01]).iloc[0]  # one row cannot determine three parameters
    assert alone["rows"] == 1 and math.isinf(alone["v0_relative_se"]) and not alone["v0_identifiable"]


def test_simulated_v0_sensitivity_equals_minus_the_frequency_derivative() -> None:
    """h1 = 80, 100 um: d ln P/d ln v0 by the envelope theorem at 300 Hz against -d ln P/d ln omega from the
    parabola through the simulated 200/300/400 Hz rows (v0 enters only via omega R/v0). The parabola's
    interpolation error dominates: 5 %.
    """
    h1 = [80.0, 100.0]
    base = _simulated(PUBLISHED, FREQUENCIES_HZ, h1)
    sensitivity = identifiability.envelope_sensitivity(PUBLISHED, 300.0, h1, **GEOMETRY)
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
    # 3 rows for 2 parameters leave one degree of freedom: t_1(0.975) = 12.7 times the 1e-3 residual floor; w0 is
    # determined, n's interval need not close inside the box (then: not determined by these rows)
    assert fit["parameters"]["w0"]["status"] == "fitted" and fit["v0_identifiable"] is False
    assert fit["status"] in ("fitted", "not_identifiable")
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
