"""The "auto" integrators' retry of a period the Fortran DOP853 gives up on (simulation.integrators, _RETRIES).

At n = 4 the periods near the orbit need more than DOP853's 1e4 steps; they are repeated with LSODA (then
Radau). Reference: the same virtual pull-off with Radau as the only retry, the chain before LSODA was added.
"""

from __future__ import annotations

from conftest import CHI0, RADIUS

from vibroadhesion.core.problem import Problem
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.virtual_pulloff import simulated_pulloff
from vibroadhesion.simulation import integrators

OMEGA_CHECK_200HZ = 2 * 3.141592653589793 * 200.0 * 0.0515 / 44.5e-6  # omega R / v0, Eq. (105), Fig. 4 caption


def test_lsoda_retry_gives_the_radau_retry_pulloff_at_n_4(monkeypatch) -> None:
    """n = 4, 200 Hz, h1 = 20 um: the pull-off with the LSODA retry equals the one with Radau retries to 1e-7
    relative (each locates the extremum to ~1e-8, virtual_pulloff docstring; both integrate to the same rtol).
    """
    problem = Problem(GentSchultz(4.0), CHI0, 20e-6 / RADIUS, OMEGA_CHECK_200HZ)
    auto = simulated_pulloff(problem)
    monkeypatch.setattr(integrators, "_RETRIES", ("Radau",))
    radau = simulated_pulloff(problem)
    assert auto.status == radau.status == "pulloff"
    assert abs(float(auto.pulloff_ratio) / float(radau.pulloff_ratio) - 1) < 1e-7


def test_a_period_the_compiled_dop853_gave_up_on_skips_the_fortran_dop853(monkeypatch) -> None:
    """After the compiled DOP853 gave up, "auto" goes on with LSODA (then Radau), not the same method again;
    otherwise (and for a named integrator) the chain is unchanged.
    """
    tried: list[str] = []

    def give_up(fun, jac, tau0, y0, tau1, method, rtol, on_step=None):
        tried.append(method)
        raise integrators.IntegrationError(method)

    monkeypatch.setattr(integrators, "_integrate", give_up)
    for gave_up, chain in ((True, ["LSODA", "Radau"]), (False, ["fortran-dop853", "LSODA", "Radau"])):
        tried.clear()
        try:
            integrators.Integrators("auto", 1e-12).run(None, None, 0.0, [0.0], 1.0, compiled_gave_up=gave_up)
        except integrators.IntegrationError:
            pass
        assert tried == chain
    tried.clear()
    try:
        integrators.Integrators("fortran-dop853", 1e-12).run(None, None, 0.0, [0.0], 1.0, compiled_gave_up=True)
    except integrators.IntegrationError:
        pass
    assert tried == ["fortran-dop853"]
