"""Steps of the plot rules: draw a table written by a compute rule (no solve) and save PDF and PNG.

The only steps that import matplotlib (through :mod:`vibroadhesion.pipeline.figures` and its siblings).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import pandas as pd

from vibroadhesion.core.groups import omega_check
from vibroadhesion.experiments.pulloff import jkr_mN
from vibroadhesion.pipeline import dynamics_figures, error_maps, figures, page_figures
from vibroadhesion.pipeline.data import read_canonical_pulloff, read_canonical_setup
from vibroadhesion.pipeline.steps.inputs import experiment_omega_check, fitted, parameter_label, rig, setup_number

if TYPE_CHECKING:
    from matplotlib.figure import Figure

Path_ = str | Path


def _save_named(fig: Figure, setup_json: Path_, fit_json: Path_ | None, pdf: Path_, png: Path_) -> None:
    """Save ``fig`` with the name of its parameter set (:func:`parameter_label`) above its panels."""
    figures.save_figure(figures.name_parameter_set(fig, parameter_label(setup_json, fit_json)), pdf, png)


def fig3_plot(setup_json: Path_, fit_json: Path_ | None, csv: Path_, pdf: Path_, png: Path_,
              panel_n: Sequence[float]) -> None:
    """Fig. 3: J-integrals of the figure's n with their large-Abar asymptotes (Eqs. 28, 29, 36), and other n."""
    fig = figures.plot_fig3(pd.read_csv(csv), rig(setup_json, fit_json)[1]["n"], panel_n)
    _save_named(fig, setup_json, fit_json, pdf, png)


def fig4_plot(setup_json: Path_, fit_json: Path_, pulloff_csv: Path_, virtual_csv: Path_, csv: Path_, pdf: Path_,
              png: Path_) -> None:
    """Fig. 4: P_cr/P_JKR (Eqs. 71-72, 106) with the measured rows and the simulated rigid pull-off.

    The curves and the scale of the measured rows, |P_cr^JKR| = (3 pi/2) R w0 (Eq. 70), are those of one parameter
    set, the fit the figures use, which the figure names.
    """
    setup = read_canonical_setup(setup_json)
    params = fitted(fit_json)
    fig = figures.plot_fig4(pd.read_csv(csv), read_canonical_pulloff(pulloff_csv), jkr_mN(params["w0"], setup.radius),
                            pd.read_csv(virtual_csv))
    _save_named(fig, setup_json, fit_json, pdf, png)


def fig5_plot(setup_json: Path_, fit_json: Path_ | None, csv: Path_, markers_csv: Path_, pdf: Path_,
              png: Path_) -> None:
    """Fig. 5: A/a_m through resonance, the paper's dot at the frequency data/setup.yaml names."""
    highlight_hz = setup_number(read_canonical_setup(setup_json), "test_conditions.fig5_highlight_frequency")
    fig = figures.plot_fig5(pd.read_csv(csv), pd.read_csv(markers_csv), highlight_hz)
    _save_named(fig, setup_json, fit_json, pdf, png)


def _test_frequencies(setup_json: Path_, fit_json: Path_ | None) -> dict[float, float]:
    """omega_check (Eq. 105) of the rig's test frequencies at the figure's v0 (:func:`rig`: published unless a fit)."""
    setup, params, _ = rig(setup_json, fit_json)
    return experiment_omega_check(setup, params["v0"])


def fig6_plot(setup_json: Path_, fit_json: Path_ | None, csv: Path_, grid_csv: Path_, pdf: Path_, png: Path_) -> None:
    """Fig. 6 (Eqs. 122-123, 49, 98) with the simulated steady states and the exact averaging of the rigid grid."""
    fig = figures.plot_fig6(pd.read_csv(csv), _test_frequencies(setup_json, fit_json), pd.read_csv(grid_csv))
    _save_named(fig, setup_json, fit_json, pdf, png)


def fig7_plot(setup_json: Path_, fit_json: Path_ | None, pulloff_csv: Path_, csv: Path_, fig4_csv: Path_,
              virtual_csv: Path_, pdf: Path_, png: Path_) -> None:
    """Fig. 7 (Eq. 106) with Fig. 4's leading-order (Eq. 72) and exact-averaging rows, simulated and measured pull-off.

    The measured rows at omega_check = omega R/v0 (Eq. 105) and over |P_cr^JKR| = (3 pi/2) R w0 (Eq. 70) of the
    figure's parameter set (:func:`rig`), as Fig. 4 scales them.
    """
    fig4 = pd.read_csv(fig4_csv)
    setup, params, _ = rig(setup_json, fit_json)
    rows = read_canonical_pulloff(pulloff_csv)
    rows = rows.assign(omega_check=omega_check(rows["frequency_hz"], params["v0"], setup.radius))
    fig = figures.plot_fig7(pd.read_csv(csv), fig4[fig4["model"] == "leading"], _test_frequencies(setup_json, fit_json),
                            fig4[fig4["model"] == "exact_averaging"], pd.read_csv(virtual_csv), rows,
                            jkr_mN(params["w0"], setup.radius))
    _save_named(fig, setup_json, fit_json, pdf, png)


def fig8_plot(setup_json: Path_, fit_json: Path_ | None, csv: Path_, pdf: Path_, png: Path_) -> None:
    """Fig. 8: storage and loss contact stiffness and phase (Eqs. 117-121)."""
    _save_named(figures.plot_fig8(pd.read_csv(csv), _test_frequencies(setup_json, fit_json)), setup_json, fit_json,
                pdf, png)


def all_figures(inputs: Mapping[str, Path_], outputs: Mapping[str, Path_], panel_n: Sequence[float]) -> None:
    """The figures among Figs. 3-8 whose outputs are named, PDF and PNG each, in one process (one import).

    ``inputs`` and ``outputs`` by the names of the plot rules: the tables ``fig3`` ... ``fig8`` and
    ``fig5_markers``, ``setup``, ``fit`` (absent: the published parameters, :func:`rig`), ``pulloff`` (measured
    rows), ``virtual`` (simulated pull-off) and
    ``grid`` (simulated steady states); ``figN_pdf`` and ``figN_png`` of each figure to draw.
    """
    i, o = inputs, outputs
    if "fig3_png" in o:
        fig3_plot(i["setup"], i.get("fit"), i["fig3"], o["fig3_pdf"], o["fig3_png"], panel_n)
    if "fig4_png" in o:
        fig4_plot(i["setup"], i["fit"], i["pulloff"], i["virtual"], i["fig4"], o["fig4_pdf"], o["fig4_png"])
    if "fig5_png" in o:
        fig5_plot(i["setup"], i.get("fit"), i["fig5"], i["fig5_markers"], o["fig5_pdf"], o["fig5_png"])
    if "fig6_png" in o:
        fig6_plot(i["setup"], i.get("fit"), i["fig6"], i["grid"], o["fig6_pdf"], o["fig6_png"])
    if "fig7_png" in o:
        fig7_plot(i["setup"], i.get("fit"), i["pulloff"], i["fig7"], i["fig4"], i["virtual"], o["fig7_pdf"],
                  o["fig7_png"])
    if "fig8_png" in o:
        fig8_plot(i["setup"], i.get("fit"), i["fig8"], o["fig8_pdf"], o["fig8_png"])


def validation_plot(setup_json: Path_, fit_json: Path_ | None, grid_csv: Path_, errors_csv: Path_, pdf: Path_,
                    png: Path_) -> None:
    """Error maps of every model level against the simulation on the rigid grid."""
    fig = error_maps.plot_validation_maps(pd.read_csv(grid_csv), pd.read_csv(errors_csv),
                                          _test_frequencies(setup_json, fit_json))
    figures.save_figure(fig, pdf, png)


def compliant_sweep_plot(csv: Path_, curve_csv: Path_, pdf: Path_, png: Path_) -> None:
    """The simulated sweep up and down over the refined curve of the same compliant case (Eqs. 87, 90)."""
    figures.save_figure(page_figures.plot_compliant_sweep(pd.read_csv(csv), pd.read_csv(curve_csv)), pdf, png)


def withdrawal_plot(csv: Path_, pdf: Path_, png: Path_) -> None:
    """The speed sweep: simulated P/|P_JKR| (Eqs. 4', 70) against V/v0 with the quasi-static asymptote."""
    figures.save_figure(dynamics_figures.plot_speed_sweep(pd.read_csv(csv)), pdf, png)


def rigs_plot(csv: Path_, pdf: Path_, png: Path_) -> None:
    """The base and the force rig compared (Eq. 13, Appendix B; table of the rig-comparison rules)."""
    figures.save_figure(dynamics_figures.plot_rig_comparison(pd.read_csv(csv)), pdf, png)
