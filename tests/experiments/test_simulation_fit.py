"""The full model as a fit level (vibroadhesion.experiments.simulation_fit) on simulated pull-off rows.

References: the parameters the rows are simulated with (a correct fit recovers them from noise-free rows);
the derivative of the pull-off by central differences of whole re-traced families (today's sensitivity
rule, :mod:`vibroadhesion.experiments.identifiability`), against which the envelope derivative is checked.
"""

from __future__ import annotations

import io
import math
import time
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
from conftest import N_PUBLISHED, RADIUS, REDUCED_MODULUS, V0, W0

from vibroadhesion.experiments import fitting, simulation_fit
from vibroadhesion.experiments.fitting import fit_gent_schultz
from vibroadhesion.experiments.pulloff import GentSchultzParameters, jkr_mN, predict_pulloff
from vibroadhesion.experiments.envelope import envelope_log_derivatives, pulloff_problem
from vibroadhesion.experiments.virtual_pulloff import simulated_pulloff, traced_pulloff
from vibroadhesion.numerics.progress import Heartbeat

GEOMETRY = {"radius": RADIUS, "reduced_modulus": REDUCED_MODULUS}
PUBLISHED = GentSchultzParameters(W0, N_PUBLISHED, V0)  # Fig. 4 caption


def _simulated_mN(params: GentSchultzParameters, frequency_hz: float, h1_um: float) -> float:
    record = simulated_pulloff(pulloff_problem(params, frequency_hz, h1_um, **GEOMETRY))
    return float(record.pulloff_ratio) * jkr_mN(params.w0, RADIUS)


def _rows(params: GentSchultzParameters, frequencies: list[float], amplitudes: list[float]) -> pd.DataFrame:
    pairs = [(f, h) for f in frequencies for h in amplitudes]
    return pd.DataFrame({"frequency_hz": [f for f, _ in pairs], "h1_um": [h for _, h in pairs],
                         "pulloff_mN": [_simulated_mN(params, f, h) for f, h in pairs], "source": "simulated",
                         "line": np.arange(2, 2 + len(pairs))})


def _estimate(summary: dict, name: str) -> float:
    return summary["parameters"][name]["estimate"]


@pytest.mark.parametrize("frequency_hz, h1_um", [(200.0, 20.0), (400.0, 100.0)])
def test_envelope_derivative_equals_central_differences_of_whole_families(frequency_hz: float, h1_um: float) -> None:
    """d ln P_cr / d ln theta (w0, n, v0) from two orbits at the fixed pull-off offset against central differences
    (same step h = 1e-3 in ln theta) of families re-traced at theta e^(+-h). Tolerance 3e-5: the two
    differences have different O(h^2) truncation errors (measured at h = 1e-2: up to 1e-3, so 1e-5 at h = 1e-3),
    the families' pull-offs carry ~1e-8 relative error (1e-8/2h = 5e-6), and the envelope's offset is located to
    2e-5, which leaves P_m'' 2e-5 dd*/dtheta = O(1e-5) (measured differences: 1.3e-7 at 20 um, 9.7e-6 at 100 um).
    """
    at = traced_pulloff(pulloff_problem(PUBLISHED, frequency_hz, h1_um, **GEOMETRY))[1]
    assert at is not None
    names = ("w0", "n", "v0")
    envelope = envelope_log_derivatives(PUBLISHED, frequency_hz, h1_um, at, names, **GEOMETRY)
    h = 1e-3
    families = []
    for name in names:
        plus, minus = (_simulated_mN(replace(PUBLISHED, **{name: getattr(PUBLISHED, name) * math.exp(s * h)}),
                                     frequency_hz, h1_um) for s in (1, -1))
        families.append(math.log(plus / minus) / (2 * h))
    assert np.all(np.abs(envelope - np.array(families)) < 3e-5), (envelope, families)


def test_rows_at_a_single_frequency_fit_w0_and_n_and_say_v0_is_not_identifiable() -> None:
    """Rows simulated at 200 Hz, h1 = 20, 40, 60 um with the published parameters: w0 and n recovered to 1e-6
    (the search stops at 1e-8 in ln theta; the rows carry the pull-off's 1e-8 error), v0 kept and named. Every
    traced family beats the progress line (interval 0 here: every beat prints)."""
    rows = _rows(PUBLISHED, [200.0], [20.0, 40.0, 60.0])
    log = io.StringIO()
    summary = fit_gent_schultz(rows, "simulation", PUBLISHED, **GEOMETRY,
                               progress=Heartbeat("fit simulation", 0.0, stream=log))
    lines = log.getvalue().splitlines()
    assert len(lines) == summary["families_traced"] and lines[0].startswith("fit simulation: ")
    assert "1/3 (f, h1) pairs traced at GentSchultzParameters(" in lines[0]
    assert summary["status"] == "fitted" and summary["free_parameters"] == ["w0", "n"]
    assert summary["v0_identifiable"] is False
    assert summary["v0_note"] == "v0 not identifiable: the rows span 1 frequency (at least 2 needed)"
    assert summary["parameters"]["v0"]["estimate"] == V0 and summary["parameters"]["v0"]["std_error"] is None
    assert abs(_estimate(summary, "w0") / W0 - 1) < 1e-6 and abs(_estimate(summary, "n") / N_PUBLISHED - 1) < 1e-6
    assert [row["status"] for row in summary["row_status"]] == ["pulloff"] * 3


def test_a_row_whose_family_ends_in_contact_loss_is_reported_and_counted_as_zero_force() -> None:
    """n = 0.15 at 200 Hz: h1 = 5, 10, 20 um have simulated pull-offs (20 um only from the preloaded start), the
    family at 40 um loses contact before a force extremum. A 40 um row (300 mN) appears with that status, the
    note names it, and its residual is the whole observed force (zero predicted force), not dropped; the other
    rows still give back w0 and n (to 1e-6): the row without a pull-off has no gradient."""
    truth = replace(PUBLISHED, n=0.15)
    rows = _rows(truth, [200.0], [5.0, 10.0, 20.0])
    rows = pd.concat([rows, pd.DataFrame({"frequency_hz": [200.0], "h1_um": [40.0], "pulloff_mN": [300.0],
                                          "source": "typed", "line": [9]})], ignore_index=True)
    summary = fit_gent_schultz(rows, "simulation", truth, **GEOMETRY)
    status = {row["line"]: row["status"] for row in summary["row_status"]}
    assert status == {2: "pulloff", 3: "pulloff", 4: "pulloff", 9: "contact_loss_before_extremum"}
    assert "line 9 (200 Hz, 40 um): contact_loss_before_extremum" in summary["note"]
    assert {r["line"]: r["residual"] for r in summary["residuals_mN"]}[9] == pytest.approx(-300.0, rel=1e-12)
    assert abs(_estimate(summary, "w0") / truth.w0 - 1) < 1e-6 and abs(_estimate(summary, "n") / truth.n - 1) < 1e-6


def test_full_model_fit_recovers_the_published_parameters_from_a_distant_start() -> None:
    """Target of issue 13: the 15 rigid rows (200/300/400 Hz x 20..100 um) simulated with the published w0, n, v0
    (Fig. 4 caption), noise-free, fitted from w0 +50 %, n -40 %: converges, and recovers w0 and n to 1e-3
    relative (measured 1e-11: the search stops at 1e-8 in ln theta). The wall time is printed: target 60 s,
    measured 5.4 s on the shared 2-core machine with the compiled steady state (83-88 s before it)."""
    rows = _rows(PUBLISHED, [200.0, 300.0, 400.0], [20.0, 40.0, 60.0, 80.0, 100.0])
    start = replace(PUBLISHED, w0=1.5 * W0, n=0.6 * N_PUBLISHED)
    began = time.perf_counter()
    summary = fit_gent_schultz(rows, "simulation", start, **GEOMETRY)
    print(f"full-model fit of 15 rows: {time.perf_counter() - began:.1f} s, {summary['families_traced']} families")
    assert summary["status"] == "fitted"
    assert abs(_estimate(summary, "w0") / W0 - 1) < 1e-3 and abs(_estimate(summary, "n") / N_PUBLISHED - 1) < 1e-3
    assert all(row["status"] == "pulloff" for row in summary["row_status"])


def test_true_n_03_is_recovered_from_a_start_where_two_of_three_families_lose_contact() -> None:
    """The n = 0.3 set of issue 13 (w0, v0 published) on three of its rows (200 Hz 20 and 40 um, 300 Hz 40 um),
    simulated, fitted from w0 +50 %, n -40 % (n = 0.18): there the 40 um families lose contact before a force
    extremum (residual -1, no gradient), yet the search reaches the truth (1e-6, as the tests above) with every
    row a pull-off at the fit. (At n = 0.3, 8 of the benchmark's 15 rows, 60-100 um at 200 and 300 Hz and 80-100 um
    at 400 Hz, have no simulated pull-off at the truth itself, benchmarks/simulation_fit.py --sets; fitted in 4-9 s
    on the shared 2-core machine.)"""
    truth = replace(PUBLISHED, n=0.3)
    rows = pd.concat([_rows(truth, [200.0], [20.0, 40.0]), _rows(truth, [300.0], [40.0])], ignore_index=True)
    rows["line"] = [2, 3, 4]
    start = replace(truth, w0=1.5 * truth.w0, n=0.6 * truth.n)
    assert [str(simulated_pulloff(pulloff_problem(start, f, 40.0, **GEOMETRY)).status) for f in (200.0, 300.0)] \
        == ["contact_loss_before_extremum"] * 2
    summary = fit_gent_schultz(rows, "simulation", start, **GEOMETRY)
    assert summary["status"] == "fitted" and summary["free_parameters"] == ["w0", "n"]
    assert abs(_estimate(summary, "w0") / truth.w0 - 1) < 1e-6 and abs(_estimate(summary, "n") / truth.n - 1) < 1e-6
    assert [row["status"] for row in summary["row_status"]] == ["pulloff"] * 3


@pytest.mark.parametrize("pairs, start", [
    ([(200.0, 40.0), (300.0, 40.0), (400.0, 20.0)], "w0 +50 %, n -40 %"),
    ([(300.0, 40.0), (400.0, 40.0), (400.0, 60.0)], "published")])
def test_true_n_03_is_recovered_from_starts_where_the_search_used_to_stall(
        pairs: list[tuple[float, float]], start: str) -> None:
    """Issue 13 (start weakness): three of the n = 0.3 rows that have a simulated pull-off at the truth, noise-free,
    fitted from w0 +50 %, n -40 % and from the fit's usual start (the published parameters). With residual -1 and a
    zero gradient for families without a pull-off both searches stalled where 1 and 0 of the 3 families have one
    (``failed``: too few pairs with a pull-off); with P*, the most tensile force each family reaches (module
    docstring), they converge to the truth: 1e-6 relative (the search stops at 1e-8 in ln theta, the rows carry
    the pull-off's 1e-8 error; measured 1e-10), every row a pull-off at the fit."""
    truth = replace(PUBLISHED, n=0.3)
    rows = pd.concat([_rows(truth, [f], [h]) for f, h in pairs], ignore_index=True)
    rows["line"] = [2, 3, 4]
    begin = replace(truth, w0=1.5 * truth.w0, n=0.6 * truth.n) if start.startswith("w0") else PUBLISHED
    summary = fit_gent_schultz(rows, "simulation", begin, **GEOMETRY)
    assert summary["status"] == "fitted" and summary["free_parameters"] == ["w0", "n"]
    assert abs(_estimate(summary, "w0") / truth.w0 - 1) < 1e-6 and abs(_estimate(summary, "n") / truth.n - 1) < 1e-6
    assert [row["status"] for row in summary["row_status"]] == ["pulloff"] * 3


def test_a_fit_that_ends_on_the_box_says_at_bound(monkeypatch: pytest.MonkeyPatch) -> None:
    """Rows simulated with n = 0.531 at 200 Hz, h1 = 20, 40, 60 um, fitted in a box that stops n at 0.5: n ends
    on its bound (status ``at_bound``, no standard error for n, the note says the rows need n outside the box)."""
    monkeypatch.setitem(fitting.BOUNDS, "n", (0.05, 0.5))
    rows = _rows(PUBLISHED, [200.0], [20.0, 40.0, 60.0])
    summary = fit_gent_schultz(rows, "simulation", PUBLISHED, **GEOMETRY)
    assert summary["status"] == "at_bound" and summary["at_bound"] == ["n"]
    assert _estimate(summary, "n") == pytest.approx(0.5, rel=1e-6)
    assert summary["parameters"]["n"]["std_error"] is None and summary["parameters"]["w0"]["std_error"] > 0
    assert "n ends on its bound" in summary["note"]


def test_predict_pulloff_of_the_simulation_level_is_the_virtual_pulloff_once_per_pair() -> None:
    """predict_pulloff("simulation") equals simulated_pulloff of each (f, h1) pair bit for bit; a repeated pair is
    solved once and scattered back (same bits)."""
    pulloff = predict_pulloff("simulation", PUBLISHED, [200.0, 300.0, 200.0], [20.0, 20.0, 20.0], **GEOMETRY)
    assert pulloff.pulloff_ratio[0] == pulloff.pulloff_ratio[2]
    for k, f in ((0, 200.0), (1, 300.0)):
        reference = simulated_pulloff(pulloff_problem(PUBLISHED, f, 20.0, **GEOMETRY))
        assert pulloff.pulloff_ratio[k] == float(reference.pulloff_ratio) and pulloff.status[k] == "pulloff"


def test_a_static_jkr_row_enters_the_simulation_fit_by_eq70() -> None:
    """A static test (h1 = 0, frequency empty: NaN) has the pull-off |P_cr^JKR| = (3 pi/2) R w0 (Eq. 70), no
    simulation; with two vibrated rows at 200 Hz the fit recovers the published w0 and n (1e-6) and lists the row as
    ``static_jkr`` with the JKR force."""
    jkr = 1.5 * math.pi * RADIUS * W0 * 1e3
    static = pd.DataFrame({"frequency_hz": [math.nan], "h1_um": [0.0], "pulloff_mN": [jkr], "source": "hand",
                           "line": [9]})
    rows = pd.concat([_rows(PUBLISHED, [200.0], [20.0, 60.0]), static], ignore_index=True)
    summary = fit_gent_schultz(rows, "simulation", replace(PUBLISHED, w0=0.3), **GEOMETRY)
    assert abs(_estimate(summary, "w0") / W0 - 1) < 1e-6 and abs(_estimate(summary, "n") / N_PUBLISHED - 1) < 1e-6
    static_row = next(row for row in summary["row_status"] if row["line"] == 9)
    assert static_row["status"] == "static_jkr" and static_row["model_mN"] == pytest.approx(jkr, rel=1e-6)


def test_the_v0_column_at_the_fit_is_never_a_silent_zero() -> None:
    """The 3-parameter Jacobian after the (w0, n) search (parameters through exp(ln), one ulp off) against the one
    computed alone at the published parameters, 15 rows: the same to the envelope's 3e-5 (test above). Its
    (200 Hz, 100 um) v0 entry (-0.19) once came out 0: the warm orbit at v0 e^(+h) stalled for 15 shooting
    periods next to the pull-off; it is now solved again with the default cap, or the pair's derivative is
    one-sided, or the fit fails -- never 0."""
    rows = _rows(PUBLISHED, [200.0], [60.0, 100.0])
    pairs = sorted(set(simulation_fit._pair_keys(rows)))
    after_search = simulation_fit._Families(pairs, GEOMETRY)
    simulation_fit._Objective(rows, PUBLISHED, ("w0", "n"), after_search).jacobian(np.log([W0, N_PUBLISHED]))
    log_all = np.log([W0, N_PUBLISHED, V0])
    jac = simulation_fit._Objective(rows, PUBLISHED, ("w0", "n", "v0"), after_search).jacobian(log_all)
    alone = simulation_fit._Objective(rows, PUBLISHED, ("w0", "n", "v0"),
                                      simulation_fit._Families(pairs, GEOMETRY)).jacobian(log_all)
    assert np.all(np.abs(jac - alone) < 3e-5) and np.all(jac[:, 2] < -1e-3), (jac, alone)


def test_rows_simulated_at_other_parameters_with_1_percent_scatter_give_them_back_within_their_intervals() -> None:
    """Reference: the parameters the rows are simulated at, w0 = 0.30 J/m^2, n = 0.70 (inside the box, away from the
    published set the search may start from), 200/300/400 Hz x 20, 60 um, each force times 1 + 0.01 eps (seed 5). The
    fit is ``fitted``, determines w0 and n, and their 95 % profile-likelihood intervals hold the truth."""
    truth = GentSchultzParameters(0.30, 0.70, V0)
    rows = _rows(truth, [200.0, 300.0, 400.0], [20.0, 60.0])
    rows["pulloff_mN"] *= 1.0 + 0.01 * np.random.default_rng(5).standard_normal(len(rows))
    summary = fit_gent_schultz(rows, "simulation", PUBLISHED, **GEOMETRY, starts=[replace(truth, w0=0.25, n=0.6)])
    assert summary["status"] == "fitted" and set(summary["determined"]) >= {"w0", "n"}, summary["note"]
    for name in ("w0", "n"):
        lower, upper = summary["parameters"][name]["interval"]
        assert lower <= getattr(truth, name) <= upper, (name, lower, upper)
