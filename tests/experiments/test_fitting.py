"""Least-squares fit of the Gent–Schultz parameters (vibroadhesion.experiments.fitting) on synthetic rows.

Reference: the parameters chosen here. Rows are generated from them with the forward model
(:func:`vibroadhesion.experiments.pulloff.predict_pulloff`, whose equations are checked against mpmath in
test_pulloff.py); a correct fit recovers them exactly without noise, and with 1 % Gaussian
noise its reported standard errors must cover them at the nominal rate (2 SE ~ 95 %).
"""

from __future__ import annotations

import io

import numpy as np
import pandas as pd
import pytest
from conftest import AMPLITUDES_UM, LinearResiduals, FREQUENCIES_HZ, N_PUBLISHED, RADIUS, REDUCED_MODULUS, V0, W0

from vibroadhesion.core.records import Pulloff
from vibroadhesion.experiments import fit_summary, fitting
from vibroadhesion.experiments.fit_summary import start_from_fit
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters, predict_pulloff, pulloff_mN
from vibroadhesion.numerics.progress import Heartbeat

GEOMETRY = {"radius": RADIUS, "reduced_modulus": REDUCED_MODULUS}
TRUE = GentSchultzParameters(w0=0.30, n=0.70, v0=20e-6)
PUBLISHED = GentSchultzParameters(w0=W0, n=N_PUBLISHED, v0=V0)  # Fig. 4 caption; also the start point


def _rows(frequencies, model: str, *, noise: float = 0.0, seed: int = 0, params=TRUE,
          relative: bool = True) -> pd.DataFrame:
    """Synthetic rows; noise is Gaussian, relative to each force or (relative=False) to the median force."""
    f = np.repeat(np.asarray(frequencies, dtype=float), len(AMPLITUDES_UM))
    h1 = np.tile(AMPLITUDES_UM, len(frequencies))
    force = pulloff_mN(predict_pulloff(model, params, f, h1, **GEOMETRY), params.w0, RADIUS)
    if noise:
        eps = np.random.default_rng(seed).standard_normal(force.size)
        force = force * (1.0 + noise * eps) if relative else force + noise * float(np.median(force)) * eps
    return pd.DataFrame({"frequency_hz": f, "h1_um": h1, "pulloff_mN": force, "source": "synthetic",
                         "line": np.arange(2, 2 + f.size)})


def _estimates(summary) -> dict[str, float]:
    return {k: summary["parameters"][k]["estimate"] for k in ("w0", "n", "v0")}


def test_leading_fit_recovers_true_w0_n_from_noise_free_rows_to_1e6() -> None:
    """Reference: w0 = 0.30, n = 0.70 used to generate the rows (200/300/400 Hz, h1 = 20..100 um); 1e-6 relative."""
    rows = _rows(FREQUENCIES_HZ, "leading")
    summary = fit_gent_schultz(rows, "leading", PUBLISHED, **GEOMETRY)
    assert summary["status"] == "fitted"
    assert summary["free_parameters"] == ["w0", "n"]
    est = _estimates(summary)
    assert abs(est["w0"] / TRUE.w0 - 1) < 1e-6, est
    assert abs(est["n"] / TRUE.n - 1) < 1e-6, est
    assert est["v0"] == PUBLISHED.v0  # the leading model does not depend on v0
    assert summary["v0_identifiable"] is False
    assert summary["rms_relative_residual"] < 1e-6
    assert start_from_fit(summary, PUBLISHED) == GentSchultzParameters(est["w0"], est["n"], PUBLISHED.v0)


def test_a_start_keeps_what_a_level_determined_and_the_published_value_elsewhere() -> None:
    """A cheaper level's n that the rows leave open is no start value: the full model's search starts at the published n."""
    summary = fit_gent_schultz(_rows(FREQUENCIES_HZ, "leading"), "leading", PUBLISHED, **GEOMETRY)
    open_n = summary | {"status": "not_identifiable", "determined": ["w0"]}
    assert start_from_fit(open_n, PUBLISHED) == GentSchultzParameters(_estimates(summary)["w0"], PUBLISHED.n,
                                                                      PUBLISHED.v0)
    assert start_from_fit(summary | {"status": "poor_fit"}, PUBLISHED) is None
    assert start_from_fit(summary | {"determined": []}, PUBLISHED) is None


def test_refined_fit_recovers_true_w0_n_v0_from_noise_free_low_frequency_rows_to_1e6() -> None:
    """Reference: w0 = 0.30, n = 0.70, v0 = 20 um/s; rows at 0.2, 1, 5 Hz where omega_check = 3e3..8e4 and the
    frequency term of Eq. (106) changes the force by up to 50 %, so v0 is identifiable; 1e-6 relative.
    """
    rows = _rows([0.2, 1.0, 5.0], "refined")
    lead = pulloff_mN(predict_pulloff("leading", TRUE, rows["frequency_hz"], rows["h1_um"], **GEOMETRY), TRUE.w0, RADIUS)
    assert np.max(np.abs(rows["pulloff_mN"] / lead - 1)) > 0.1  # v0 matters for these rows
    summary = fit_gent_schultz(rows, "refined", PUBLISHED, **GEOMETRY)
    assert summary["status"] == "fitted"
    assert summary["v0_identifiable"] is True, summary["v0_note"]
    assert summary["free_parameters"] == ["w0", "n", "v0"]
    est = _estimates(summary)
    for name in ("w0", "n", "v0"):
        assert abs(est[name] / getattr(TRUE, name) - 1) < 1e-6, (name, est)


def _coverage(relative: bool) -> tuple[dict[str, int], dict[str, list[float]]]:
    hits = {"w0": 0, "n": 0}
    z_scores: dict[str, list[float]] = {"w0": [], "n": []}
    for seed in range(20):
        rows = _rows(FREQUENCIES_HZ, "leading", noise=0.01, seed=seed, relative=relative)
        summary = fit_gent_schultz(rows, "leading", PUBLISHED, **GEOMETRY)
        assert summary["status"] == "fitted"
        for name in hits:
            entry = summary["parameters"][name]
            assert entry["std_error"] is not None and entry["std_error"] > 0
            z = (entry["estimate"] - getattr(TRUE, name)) / entry["std_error"]
            z_scores[name].append(round(z, 2))
            hits[name] += abs(z) <= 2
    return hits, z_scores


def test_leading_fit_standard_errors_cover_truth_in_15_of_20_noisy_fits() -> None:
    """Reference: the true (w0, n). With 1 % Gaussian relative noise (seeds 0..19) the true value must lie
    within 2 reported standard errors in >= 15 of 20 fits for each parameter (nominal coverage ~93 % for
    t with 13 degrees of freedom; 15/20 then fails with probability ~1.5 %).
    """
    hits, z_scores = _coverage(relative=True)
    assert all(h >= 15 for h in hits.values()), f"coverage {hits} of 20; z-scores {z_scores}"


def test_refined_fit_on_one_frequency_keeps_published_v0() -> None:
    """With one frequency v0 cannot be separated from w0, n (Sec. 3.4 / fitting docstring): v0_identifiable is
    False, a note says why, and v0 is the published value exactly.
    """
    rows = _rows([300], "refined")
    log = io.StringIO()
    summary = fit_gent_schultz(rows, "refined", PUBLISHED, **GEOMETRY, progress=Heartbeat("fit refined", 0.0, stream=log))
    assert log.getvalue().startswith("fit refined: ") and "rms relative residual" in log.getvalue()  # each evaluation
    assert summary["v0_identifiable"] is False
    assert "frequency" in summary["v0_note"] and "not identifiable" in summary["v0_note"]
    assert summary["parameters"]["v0"]["estimate"] == PUBLISHED.v0
    assert summary["parameters"]["v0"]["std_error"] is None
    assert "v0" not in summary.get("free_parameters", [])


@pytest.mark.parametrize("model", ["leading", "refined"])
def test_zero_rows_returns_published_parameters(model: str) -> None:
    """No data: nothing to fit, the published parameters (Fig. 4 caption) are returned unchanged."""
    rows = _rows([300], model).iloc[:0]
    summary = fit_gent_schultz(rows, model, PUBLISHED, **GEOMETRY)
    assert summary["status"] == "published"
    assert summary["rows"] == 0
    assert _estimates(summary) == {"w0": PUBLISHED.w0, "n": PUBLISHED.n, "v0": PUBLISHED.v0}
    assert start_from_fit(summary, PUBLISHED) is None  # nothing determined: no start of its own


# ----------------------------------------------------------------------------- statuses, rows, static tests


def _table(rows: list[tuple[float, float, float]]) -> pd.DataFrame:
    f, h1, force = (np.array(c, dtype=float) for c in zip(*rows, strict=True))
    return pd.DataFrame({"frequency_hz": f, "h1_um": h1, "pulloff_mN": force, "source": "hand",
                         "line": np.arange(2, 2 + f.size)})


def test_replicated_conditions_are_solved_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """predict_pulloff hands the level each distinct (amplitude, omega_check) once and scatters the answer back:
    4 rows, 3 conditions."""
    from vibroadhesion.models import refined

    seen = []

    def counting(eta1, chi0, omega_check, law):
        seen.append(np.size(eta1))
        return original(eta1, chi0, omega_check, law)

    original = refined.pulloff_refined
    monkeypatch.setattr(refined, "pulloff_refined", counting)
    f, h1 = np.array([300.0, 200.0, 300.0, 300.0]), np.array([40.0, 40.0, 40.0, 60.0])
    ratio = predict_pulloff("refined", TRUE, f, h1, **GEOMETRY).pulloff_ratio
    assert seen == [3]
    assert ratio[0] == ratio[2] and ratio[0] != ratio[1] and ratio[0] != ratio[3]


@pytest.mark.parametrize("model", ["leading", "refined"])
def test_replicated_rows_give_the_estimates_of_the_rows_once(model: str) -> None:
    """Least squares with every residual twice has the same minimiser. The search stops on a relative cost change
    below ftol = 1e-12, which places it within ~sqrt(ftol) = 1e-6 (relative, in ln theta) of the minimum along a
    flat direction: agreement to 1e-6 (measured 1e-8); a wrong weighting of replicates moves the noisy fit by ~1 %."""
    rows = _rows(FREQUENCIES_HZ, model, noise=0.01, seed=3)
    once = _estimates(fit_gent_schultz(rows, model, PUBLISHED, **GEOMETRY))
    twice = _estimates(fit_gent_schultz(pd.concat([rows, rows], ignore_index=True), model, PUBLISHED, **GEOMETRY))
    assert all(abs(twice[k] / once[k] - 1) < 1e-6 for k in once), (once, twice)


@pytest.mark.parametrize("model", ["leading", "refined", "exact_averaging", "exact_averaging_force_minimum"])
def test_four_plausible_rows_end_in_a_status_not_an_exception(model: str) -> None:
    """The rows of issue 13 that ended in 'Singular matrix' (uncaught LinAlgError): every level ends in a status."""
    rows = _table([(200, 20, 130), (200, 60, 700), (300, 40, 420), (400, 100, 1300)])
    summary = fit_gent_schultz(rows, model, PUBLISHED, **GEOMETRY)
    assert summary["status"] in ("fitted", "poor_fit", "at_bound", "not_identifiable", "failed"), summary
    statuses = {k: summary["parameters"][k]["status"] for k in ("w0", "n", "v0")}
    if summary["status"] != "failed":  # the level's status is the first of its parameters' that holds
        assert (summary["status"] == "fitted") == all(s in ("fitted", "published") for s in statuses.values())
    for entry in summary["parameters"].values():  # no interval is shown for a parameter the rows do not determine
        assert (entry["status"] == "fitted") == (entry["interval"] is not None and None not in entry["interval"]
                                                 and entry["std_error"] is not None)
    if summary["status"] != "fitted":
        assert summary["note"] or summary["goodness_of_fit"]["rejected"]


def test_one_condition_replicated_cannot_separate_w0_and_n() -> None:
    """Three replicates of one (f, h1): the leading force depends on (w0, n) through one number, so J has rank 1 < 2:
    not_identifiable, no standard errors."""
    rows = _rows([300.0], "leading").iloc[[1, 1, 1]].reset_index(drop=True)
    summary = fit_gent_schultz(rows, "leading", PUBLISHED, **GEOMETRY)
    assert summary["status"] == "not_identifiable", summary
    assert "lower rank" in summary["note"]
    assert all(summary["parameters"][k]["std_error"] is None for k in ("w0", "n"))


def test_two_rows_keep_the_published_values_and_say_so() -> None:
    summary = fit_gent_schultz(_rows([300.0], "leading").iloc[:2], "leading", PUBLISHED, **GEOMETRY)
    assert summary["status"] == "not_identifiable" and "2 rows" in summary["note"]
    assert _estimates(summary) == {"w0": PUBLISHED.w0, "n": PUBLISHED.n, "v0": PUBLISHED.v0}


def test_a_model_without_solution_fails_that_level_with_its_reason(monkeypatch: pytest.MonkeyPatch) -> None:
    """A level whose pull-off has no solution at a trial point ends as 'failed' with the reason, published values
    kept and no standard errors; the exception does not escape (the other levels go on)."""
    rows = _rows(FREQUENCIES_HZ, "leading")

    def no_solution(model, params, frequency_hz, h1_um, **geometry):
        return Pulloff.unsolved(model, "no_solution", "no root of Eq. (72)", shape=np.shape(h1_um))

    monkeypatch.setattr(fitting, "predict_pulloff", no_solution)
    summary = fit_gent_schultz(rows, "leading", PUBLISHED, **GEOMETRY)
    assert summary["status"] == "failed" and "no solution" in summary["note"], summary
    assert _estimates(summary) == {"w0": PUBLISHED.w0, "n": PUBLISHED.n, "v0": PUBLISHED.v0}


def test_static_jkr_rows_pin_w0_by_eq70() -> None:
    """h1 = 0: no vibration, the pull-off is |P_JKR| = (3 pi/2) R w0 (Eq. 70) at every level. Static rows alone
    give w0 = |P|/((3 pi/2) R) but no n (not_identifiable); with the vibrated rows of TRUE both are recovered (1e-6)."""
    jkr_mN = 1.5 * np.pi * RADIUS * TRUE.w0 * 1e3
    static = _table([(0.0, 0.0, jkr_mN)] * 3)
    alone = fit_gent_schultz(static, "leading", PUBLISHED, **GEOMETRY)
    assert alone["status"] == "not_identifiable"
    rows = pd.concat([static.iloc[:1], _rows([300.0], "leading").iloc[[0, 4]]], ignore_index=True)
    est = _estimates(fit_gent_schultz(rows, "leading", PUBLISHED, **GEOMETRY))
    assert abs(est["w0"] / TRUE.w0 - 1) < 1e-6 and abs(est["n"] / TRUE.n - 1) < 1e-6, est


def test_static_rows_are_not_a_frequency_for_v0() -> None:
    """A static row has no excitation: with vibrated rows at one frequency, v0 stays not identifiable."""
    rows = pd.concat([_table([(0.0, 0.0, 70.0)]), _rows([300.0], "refined")], ignore_index=True)
    summary = fit_gent_schultz(rows, "refined", PUBLISHED, **GEOMETRY)
    assert summary["v0_identifiable"] is False and "1 frequency" in summary["v0_note"], summary["v0_note"]


@pytest.mark.parametrize("model", ["leading", "simulation"])
def test_a_row_whose_force_is_not_a_positive_number_fails_the_level_and_names_it(model: str) -> None:
    """A NaN force (a simulated row whose family has no pull-off) and a zero force: each level ends as 'failed'
    naming the lines, published values kept, before any model evaluation. Rows with NaN once escaped as scipy's
    uncaught ValueError ('array must not contain infs or NaNs') from the simulation fit."""
    rows = _rows([300.0], "leading")
    rows.loc[1, "pulloff_mN"] = np.nan
    rows.loc[3, "pulloff_mN"] = 0.0
    summary = fit_gent_schultz(rows, model, PUBLISHED, **GEOMETRY)
    assert summary["status"] == "failed" and summary["note"].startswith("line(s) 3, 5: "), summary["note"]
    assert _estimates(summary) == {"w0": PUBLISHED.w0, "n": PUBLISHED.n, "v0": PUBLISHED.v0}


@pytest.mark.parametrize(("n", "scale", "status"), [(3.99, 1e-3, "at_bound"), (3.5, 1e-3, "not_identifiable"),
                                                     (1.0, 1.0, "fitted")])
def test_a_parameter_whose_bound_lies_within_two_standard_errors_is_at_bound(n: float, scale: float,
                                                                             status: str) -> None:
    """A search that stops by its xtol just inside the box (n = 3.99, ln-distance 2.5e-3 from the bound 4) with rows
    that hardly constrain n (its Jacobian column 1e-3 against w0's 1: relative SE of n ~ 7 at s = 1.7e-2) reports n
    ``at_bound`` without a standard error, and w0's standard error with n held: s/|J_w0| w0 in closed form. The same
    rows with the search ending 13 % from the bound (n = 3.5: more than 1 %) leave n ``not_identifiable`` (its
    relative SE ~ 7 > 0.5: not determined by these rows), and rows that constrain n (column ~1: relative SE ~ 1e-2)
    at n = 1 leave it ``fitted``. The residual model is linear in ln theta (fit_statistics' closed-form case)."""
    jac = np.array([[1.0, scale], [1.0, -scale], [1.0, 2.0 * scale]])
    residuals = np.array([1e-2, -1e-2, 1e-2])
    params = GentSchultzParameters(w0=0.3, n=n, v0=V0)
    lo, hi = np.log([fit_summary.BOUNDS[k] for k in ("w0", "n")]).T
    x = np.log([params.w0, params.n])
    fit = fit_summary.fit_record(params, _Result(x, jac), residuals, ("w0", "n"), (lo, hi), LinearResiduals(residuals, jac, x))
    rows = pd.DataFrame({"line": [2, 3, 4], "pulloff_mN": [100.0, 110.0, 120.0], "frequency_hz": [200.0, 300.0, 400.0],
                         "h1_um": [20.0, 40.0, 60.0]})
    summary = fit_summary.fitted_summary(rows, fit, ("w0", "n"), "")
    s = np.sqrt(residuals @ residuals / (3 - 2))
    assert summary["parameters"]["n"]["status"] == status
    if status == "at_bound":
        assert summary["at_bound"] == ["n"] and summary["parameters"]["n"]["std_error"] is None
        assert summary["parameters"]["w0"]["std_error"] == pytest.approx(s / np.sqrt(3.0) * 0.3, rel=1e-12)
        assert "within 1 % and 2 standard errors" in summary["note"]
    else:
        assert summary["at_bound"] == [] and summary["parameters"]["n"]["std_error"] > 0


class _Result:
    """The fields of scipy's OptimizeResult that fit_record reads."""

    def __init__(self, x: np.ndarray, jac: np.ndarray) -> None:
        self.x, self.jac, self.nfev, self.message = x, jac, 1, "test"
