"""Command-line entry points called by the Snakemake rules (``python -m vibroadhesion.pipeline.cli STEP ...``).

Each step reads artefacts, calls the package and writes artefacts atomically; a failure
prints one line to stderr and exits with status 1, leaving no output behind.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd

from vibroadhesion.pipeline import data, figures

from vibroadhesion.core import groups

from vibroadhesion.experiments import identifiability, validation, virtual_pulloff

from vibroadhesion.simulation import SpringFixation
from vibroadhesion.models.compliant import CompliantFixation
from vibroadhesion.numerics.continuation import ContinuationError
from vibroadhesion.pipeline.artefacts import save_figure, write_csv, write_json
from vibroadhesion.experiments.fitting import FitError, fit_gent_schultz, parameters_from_fit
from vibroadhesion.core.jkr import pulloff_force
from vibroadhesion.numerics.progress import ProgressBar
from vibroadhesion.experiments.pulloff import MODELS, GentSchultzParameters
from vibroadhesion.numerics.roots import NoRootError


def _fit(args: argparse.Namespace) -> None:
    setup = data.read_canonical_setup(args.setup)
    rows = data.read_canonical_pulloff(args.pulloff)
    published = GentSchultzParameters(setup.w0, setup.n, setup.v0)
    geometry = {"radius": setup.radius, "reduced_modulus": setup.reduced_modulus}
    fits = {model: fit_gent_schultz(rows, model, published, **geometry) for model in MODELS}
    summary = {
        "data_rows": len(rows),
        "status": "published parameters passed through (no measured rows)" if rows.empty else "fitted",
        "published": {"w0": setup.w0, "n": setup.n, "v0": setup.v0, "source": setup.sources["gent_schultz_published.w0"]},
        "figures_use": args.figures_use,
        "fits": fits,
    }
    write_json(summary, args.out)
    for model, fit in fits.items():
        p = fit["parameters"]
        print(f"{model}: {fit['status']}; w0 = {p['w0']['estimate']:.6g} J/m^2, n = {p['n']['estimate']:.6g}, "
              f"v0 = {p['v0']['estimate']:.6g} m/s; {fit['v0_note']}")


def _load_fit(path: str) -> dict:
    return json.loads(Path(path).read_text())


def _fig3_data(args: argparse.Namespace) -> None:
    fit = _load_fit(args.fit)
    n_fitted = parameters_from_fit(fit["fits"][fit["figures_use"]]).n
    abar = np.logspace(args.log10_abar_min, args.log10_abar_max, args.points)
    write_csv(figures.fig3_table([n_fitted, *args.panel_n], abar), args.out)


def _fig3_plot(args: argparse.Namespace) -> None:
    fit = _load_fit(args.fit)
    n_fitted = parameters_from_fit(fit["fits"][fit["figures_use"]]).n
    fig = figures.plot_fig3(pd.read_csv(args.csv), n_fitted, args.panel_n)
    save_figure(fig, args.pdf, args.png)


def _fig4_data(args: argparse.Namespace) -> None:
    setup = data.read_canonical_setup(args.setup)
    fit = _load_fit(args.fit)
    params = {model: parameters_from_fit(fit["fits"][model]) for model in MODELS}
    h1 = np.linspace(0.0, args.h1_max_um, args.points)
    table = figures.fig4_table(params, setup.frequencies_hz, h1, radius=setup.radius,
                               reduced_modulus=setup.reduced_modulus)
    write_csv(table, args.out)


def _fig4_plot(args: argparse.Namespace) -> None:
    setup = data.read_canonical_setup(args.setup)
    fit = _load_fit(args.fit)
    w0 = parameters_from_fit(fit["fits"]["leading"]).w0
    jkr_mN = float(-pulloff_force(w0, setup.radius)) * 1e3
    fig = figures.plot_fig4(pd.read_csv(args.csv), data.read_canonical_pulloff(args.pulloff), jkr_mN,
                            pd.read_csv(args.virtual))
    save_figure(fig, args.pdf, args.png)


def _rig_and_parameters(args: argparse.Namespace):
    """The ingested rig, the parameters of the fit the figures use, and chi0 at those parameters."""
    setup = data.read_canonical_setup(args.setup)
    fit = _load_fit(args.fit)
    params = parameters_from_fit(fit["fits"][fit["figures_use"]])
    return setup, params, groups.chi0(params.w0, setup.reduced_modulus, setup.radius)


def _experiment_omega_check(setup, params) -> dict[float, float]:
    return {f: float(groups.omega_check(f, params.v0, setup.radius)) for f in setup.frequencies_hz}


def _omega_grid(args: argparse.Namespace) -> np.ndarray:
    return np.logspace(args.log10_omega_min, args.log10_omega_max, args.points)


def _fig6_data(args: argparse.Namespace) -> None:
    setup, params, chi0 = _rig_and_parameters(args)
    table = figures.fig6_table(setup.amplitudes_um, _omega_grid(args), chi0=chi0, radius=setup.radius, n=params.n)
    write_csv(table, args.out)
    outside = table["A_over_am"] > figures.APPLICABILITY_LIMIT
    impossible = table["A_over_am"] > 1.0
    print(f"{len(table)} points solved; {int(outside.sum())} with A/a_m > {figures.APPLICABILITY_LIMIT} (outside the "
          f"asymptotic model), of which {int(impossible.sum())} with A/a_m > 1 (geometrically impossible)")


def _fig7_data(args: argparse.Namespace) -> None:
    setup, params, chi0 = _rig_and_parameters(args)
    write_csv(figures.fig7_table(setup.amplitudes_um, _omega_grid(args), chi0=chi0, radius=setup.radius, n=params.n), args.out)


def _fig8_data(args: argparse.Namespace) -> None:
    _, params, chi0 = _rig_and_parameters(args)
    write_csv(figures.fig8_table(pd.read_csv(args.fig6), chi0=chi0, n=params.n), args.out)


def _rig_and_fixation(args: argparse.Namespace):
    """:func:`_rig_and_parameters` and the assumed fixation entries of data/setup.yaml (all present)."""
    setup, params, chi0 = _rig_and_parameters(args)
    fixation = setup.fixation
    missing = {"natural_frequency", "stiffness_ratio_kappa", "weight_ratio_mu", "damping_ratio_zeta"} - set(fixation)
    if missing:
        raise ValueError(f"{args.setup}: the compliant fixation needs the entries {sorted(missing)} in data/setup.yaml")
    return setup, params, chi0, fixation


def _compliant_fixation(args: argparse.Namespace):
    """Fig. 5's base parameters (Sec. 3.5.3) from the rig, the fit and the assumed fixation of data/setup.yaml."""
    setup, params, chi0, fixation = _rig_and_fixation(args)
    omega0 = float(fixation["natural_frequency"])
    base = CompliantFixation(chi0=chi0, eta1=float(groups.eta1(args.h1_um * 1e-6, setup.radius)),
                             nu0=groups.nu0(params.v0, omega0, setup.radius), kappa=1.0,
                             mu=float(fixation["weight_ratio_mu"]), zeta=0.0)
    experiments = {f: 2.0 * np.pi * f / omega0 for f in setup.frequencies_hz}
    as_list = lambda v: [float(x) for x in np.atleast_1d(v)]  # noqa: E731
    return base, as_list(fixation["stiffness_ratio_kappa"]), as_list(fixation["damping_ratio_zeta"]), params.n, experiments


def _fig5_data(args: argparse.Namespace) -> None:
    base, kappas, zetas, n, experiments = _compliant_fixation(args)
    curves, markers, counts = figures.fig5_tables(base, kappas, zetas, n, experiments,
                                                  (args.omega_bar_min, args.omega_bar_max), args.count_points)
    write_csv(curves, args.out)
    write_csv(markers, args.markers)
    write_csv(counts, args.counts)
    for (kappa, zeta), rows in markers[markers["kind"] == "fold"].groupby(["kappa", "zeta"]):
        print(f"kappa = {kappa:g}, zeta = {zeta:g}: folds at omega_bar = " + ", ".join(f"{w:.6f}" for w in rows["omega_bar"]))
    several = counts[counts["solutions"] > 1]
    print(f"{len(curves)} points traced; {len(several)} of {len(counts)} grid frequencies with more than one solution")


def _fig5_plot(args: argparse.Namespace) -> None:
    fig = figures.plot_fig5(pd.read_csv(args.csv), pd.read_csv(args.markers), args.highlight_hz)
    save_figure(fig, args.pdf, args.png)


def _validate_rigid(args: argparse.Namespace) -> None:
    setup, params, chi0 = _rig_and_parameters(args)
    omega = validation.validation_frequencies((args.log10_omega_min, args.log10_omega_max),
                                              list(_experiment_omega_check(setup, params).values()))
    rows, progress = [], ProgressBar(len(omega), "frequencies")
    for w in omega:
        point = validation.rigid_point(args.h1_um, float(w), chi0=chi0, radius=setup.radius, n=params.n)
        rows.extend(point)
        simulated = next(r["status"] for r in point if r["model"] == "simulation")
        progress.advance(1, f"h1 = {args.h1_um:g} um, omega_check = {w:.6g}: simulation {simulated}")
    write_csv(pd.DataFrame(rows)[validation.RIGID_GRID_COLUMNS], args.out)


def _validate_compliant(args: argparse.Namespace) -> None:
    base, _, _, n, _ = _compliant_fixation(args)
    p = replace(base, kappa=args.kappa, zeta=args.zeta)
    table = validation.compliant_sweep(p, n, np.geomspace(args.omega_bar_min, args.omega_bar_max, args.points),
                                       ProgressBar(2 * args.points, "frequencies"))
    write_csv(table, args.out)
    sim = table[table["model"] == "simulation"]
    print(f"{len(sim)} simulated steady states ({int((sim['status'] != 'ok').sum())} not first time), "
          f"{int((~sim['stable'].astype(bool)).sum())} unstable or failed")


def _validate_compliant_plot(args: argparse.Namespace) -> None:
    sweep, fig5 = pd.read_csv(args.csv), pd.read_csv(args.fig5)
    omega = sweep["omega_bar"]
    curve = fig5[np.isclose(fig5["kappa"], args.kappa) & np.isclose(fig5["zeta"], args.zeta)
                 & fig5["omega_bar"].between(omega.min(), omega.max())]
    save_figure(figures.plot_compliant_sweep(sweep, curve), args.pdf, args.png)


def _virtual_pulloff(args: argparse.Namespace) -> None:
    spring = None
    if args.fixation == "rigid":
        setup, params, _ = _rig_and_parameters(args)
    else:
        if args.kappa is None or args.zeta is None:
            raise ValueError("the compliant virtual pull-off needs --kappa and --zeta")
        setup, params, _, fixation = _rig_and_fixation(args)  # weight and natural frequency: data/setup.yaml
        nu0 = groups.nu0(params.v0, float(fixation["natural_frequency"]), setup.radius)
        spring = SpringFixation(args.kappa, args.zeta, nu0, float(fixation["weight_ratio_mu"]))
    h1 = np.asarray(setup.amplitudes_um, dtype=float)
    table = virtual_pulloff.pulloff_table(params, args.frequency_hz, h1, radius=setup.radius,
                                          reduced_modulus=setup.reduced_modulus, fixation=spring,
                                          progress=ProgressBar(len(h1), "amplitudes"))
    write_csv(table, args.out)


def _virtual_pulloff_gather(args: argparse.Namespace) -> None:
    write_csv(pd.concat([pd.read_csv(p) for p in args.parts], ignore_index=True), args.out)


def _pulloff_sensitivity(args: argparse.Namespace) -> None:
    setup, params, _ = _rig_and_parameters(args)
    shifted = identifiability.perturbed(params, args.parameter, {"plus": 1, "minus": -1}[args.sign])
    h1 = np.asarray(setup.amplitudes_um, dtype=float)
    progress = ProgressBar(len(h1) * len(args.frequencies_hz), "amplitudes")
    tables = [virtual_pulloff.pulloff_table(shifted, f, h1, radius=setup.radius, reduced_modulus=setup.reduced_modulus,
                                            progress=progress, predictions=False) for f in args.frequencies_hz]
    write_csv(pd.concat(tables, ignore_index=True), args.out)


def _simulated_rigid_rows(virtual_csv: str) -> pd.DataFrame:
    """The simulated rigid-fixation pull-off rows of virtual_pulloff.csv, as fit input (``line`` = row number)."""
    table = pd.read_csv(virtual_csv)
    rows = table[(table["model"] == "simulation") & (table["fixation"] == "rigid")].reset_index(drop=True)
    return rows.assign(line=np.arange(len(rows)))


def _identifiability_fit(args: argparse.Namespace) -> None:
    setup, params, _ = _rig_and_parameters(args)
    start = time.perf_counter()
    row = identifiability.fit_level(_simulated_rigid_rows(args.virtual), args.model, params, radius=setup.radius,
                                    reduced_modulus=setup.reduced_modulus)
    write_csv(pd.DataFrame([row]).reindex(columns=identifiability.FIT_COLUMNS), args.out)
    print(f"{args.model}: {row['status']} in {time.perf_counter() - start:.1f} s; {row['note']}")


def _identifiability(args: argparse.Namespace) -> None:
    parts = {Path(p).stem: pd.read_csv(p) for p in args.sensitivity_parts}
    missing = [f"{n}_{s}" for n in identifiability.PARAMETERS for s in ("plus", "minus") if f"{n}_{s}" not in parts]
    if missing:
        raise ValueError(f"sensitivity runs missing: {', '.join(missing)}")
    sensitivity = identifiability.log_sensitivity(
        _simulated_rigid_rows(args.virtual), {n: parts[f"{n}_plus"] for n in identifiability.PARAMETERS},
        {n: parts[f"{n}_minus"] for n in identifiability.PARAMETERS})
    information = identifiability.information_table(sensitivity, args.noise)
    fits = pd.concat([pd.read_csv(p) for p in args.fits], ignore_index=True)
    write_csv(sensitivity, args.sensitivity_out)
    write_csv(information, args.information_out)
    write_csv(fits, args.fits_out)
    print(information.to_string(index=False))


def _validate_gather(args: argparse.Namespace) -> None:
    setup, params, _ = _rig_and_parameters(args)
    grid = pd.concat([pd.read_csv(p) for p in args.parts], ignore_index=True)
    grid = grid.sort_values(["h1_um", "omega_check"], kind="stable").reset_index(drop=True)
    errors = validation.relative_errors(grid)
    summary = validation.error_summary(errors, list(_experiment_omega_check(setup, params).values()))
    write_csv(grid, args.grid)
    write_csv(errors, args.errors)
    write_csv(summary, args.summary)
    print(summary.to_string(index=False))


def _validate_plot(args: argparse.Namespace) -> None:
    setup, params, _ = _rig_and_parameters(args)
    fig = figures.plot_validation_maps(pd.read_csv(args.grid), pd.read_csv(args.errors), _experiment_omega_check(setup, params))
    save_figure(fig, args.pdf, args.png)


def _rigid_fixation_plot(args: argparse.Namespace) -> None:
    setup, params, _ = _rig_and_parameters(args)
    marks = _experiment_omega_check(setup, params)
    table = pd.read_csv(args.csv)
    if args.step == "fig6-plot":
        fig = figures.plot_fig6(table, marks, pd.read_csv(args.validation))
    elif args.step == "fig7-plot":
        fig4 = pd.read_csv(args.fig4)
        fig = figures.plot_fig7(table, fig4[fig4["model"] == "leading"], marks, fig4[fig4["model"] == "exact_averaging"],
                                pd.read_csv(args.virtual))
    else:
        fig = figures.plot_fig8(table, marks)
    save_figure(fig, args.pdf, args.png)


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="python -m vibroadhesion.pipeline.cli", description=__doc__)
    steps = parser.add_subparsers(dest="step", required=True)

    p = steps.add_parser("fit", help="Gent–Schultz fit with every model level")
    p.add_argument("--setup", required=True)
    p.add_argument("--pulloff", required=True)
    p.add_argument("--figures-use", choices=MODELS, default="refined")
    p.add_argument("--out", required=True)
    p.set_defaults(run=_fit)

    for name, run, needs_csv in (("fig3-data", _fig3_data, False), ("fig3-plot", _fig3_plot, True)):
        p = steps.add_parser(name)
        p.add_argument("--fit", required=True)
        p.add_argument("--panel-n", type=float, nargs="+", required=True)
        if needs_csv:
            _plot_arguments(p)
        else:
            p.add_argument("--log10-abar-min", type=float, required=True)
            p.add_argument("--log10-abar-max", type=float, required=True)
            p.add_argument("--points", type=int, required=True)
            p.add_argument("--out", required=True)
        p.set_defaults(run=run)

    p = steps.add_parser("fig4-data")
    _rig_arguments(p)
    p.add_argument("--h1-max-um", type=float, required=True)
    p.add_argument("--points", type=int, required=True)
    p.add_argument("--out", required=True)
    p.set_defaults(run=_fig4_data)

    p = steps.add_parser("fig4-plot")
    _rig_arguments(p)
    p.add_argument("--pulloff", required=True)
    p.add_argument("--virtual", required=True, help="virtual_pulloff.csv: the simulated pull-off (not measurements)")
    _plot_arguments(p)
    p.set_defaults(run=_fig4_plot)

    p = steps.add_parser("fig5-data", help="compliant fixation: continuation of Eqs. (87), (90)")
    _compliant_sweep_arguments(p)
    p.add_argument("--count-points", type=int, required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--markers", required=True)
    p.add_argument("--counts", required=True)
    p.set_defaults(run=_fig5_data)
    p = steps.add_parser("fig5-plot")
    p.add_argument("--markers", required=True)
    p.add_argument("--highlight-hz", type=float, required=True)
    _plot_arguments(p)
    p.set_defaults(run=_fig5_plot)

    p = steps.add_parser("validate-rigid", help="all model levels against the simulation, one amplitude")
    _rig_arguments(p)
    p.add_argument("--h1-um", type=float, required=True)
    p.add_argument("--log10-omega-min", type=int, required=True)
    p.add_argument("--log10-omega-max", type=int, required=True)
    p.add_argument("--out", required=True)
    p.set_defaults(run=_validate_rigid)
    p = steps.add_parser("validate-compliant", help="Fig. 5 sweep up and down: simulation against the refined model")
    _compliant_sweep_arguments(p)
    _fixation_arguments(p)
    p.add_argument("--points", type=int, required=True)
    p.add_argument("--out", required=True)
    p.set_defaults(run=_validate_compliant)
    p = steps.add_parser("validate-compliant-plot")
    p.add_argument("--fig5", required=True, help="fig5.csv: the refined curve of the same (kappa, zeta)")
    _fixation_arguments(p)
    _plot_arguments(p)
    p.set_defaults(run=_validate_compliant_plot)
    p = steps.add_parser("virtual-pulloff", help="simulated pull-off experiment at one frequency, and the predictions")
    _rig_arguments(p)
    p.add_argument("--frequency-hz", type=float, required=True)
    p.add_argument("--fixation", choices=("rigid", "compliant"), required=True)
    p.add_argument("--kappa", type=float, help="compliant only: k/(E* R), Eq. (66)")
    p.add_argument("--zeta", type=float, help="compliant only: damping ratio, Eq. (65)")
    p.add_argument("--out", required=True)
    p.set_defaults(run=_virtual_pulloff)
    p = steps.add_parser("virtual-pulloff-gather")
    p.add_argument("--parts", nargs="+", required=True)
    p.add_argument("--out", required=True)
    p.set_defaults(run=_virtual_pulloff_gather)
    p = steps.add_parser("pulloff-sensitivity", help="simulated pull-off with one Gent-Schultz parameter scaled by exp(+-h)")
    _rig_arguments(p)
    p.add_argument("--parameter", choices=identifiability.PARAMETERS, required=True)
    p.add_argument("--sign", choices=("plus", "minus"), required=True)
    p.add_argument("--frequencies-hz", type=float, nargs="+", required=True)
    p.add_argument("--out", required=True)
    p.set_defaults(run=_pulloff_sensitivity)
    p = steps.add_parser("identifiability-fit", help="fit one model level to the simulated pull-off rows")
    _rig_arguments(p)
    p.add_argument("--virtual", required=True)
    p.add_argument("--model", choices=MODELS, required=True)
    p.add_argument("--out", required=True)
    p.set_defaults(run=_identifiability_fit)
    p = steps.add_parser("identifiability", help="sensitivity of the simulated pull-off, Cramer-Rao bounds, fits table")
    p.add_argument("--virtual", required=True)
    p.add_argument("--sensitivity-parts", nargs="+", required=True)
    p.add_argument("--fits", nargs="+", required=True)
    p.add_argument("--noise", type=float, nargs="+", required=True)
    p.add_argument("--sensitivity-out", required=True)
    p.add_argument("--information-out", required=True)
    p.add_argument("--fits-out", required=True)
    p.set_defaults(run=_identifiability)
    p = steps.add_parser("validate-gather")
    _rig_arguments(p)
    p.add_argument("--parts", nargs="+", required=True)
    p.add_argument("--grid", required=True)
    p.add_argument("--errors", required=True)
    p.add_argument("--summary", required=True)
    p.set_defaults(run=_validate_gather)
    p = steps.add_parser("validate-plot")
    _rig_arguments(p)
    p.add_argument("--grid", required=True)
    p.add_argument("--errors", required=True)
    p.add_argument("--pdf", required=True)
    p.add_argument("--png", required=True)
    p.set_defaults(run=_validate_plot)

    for name, run in (("fig6-data", _fig6_data), ("fig7-data", _fig7_data)):
        p = steps.add_parser(name)
        _rig_arguments(p)
        p.add_argument("--log10-omega-min", type=float, required=True)
        p.add_argument("--log10-omega-max", type=float, required=True)
        p.add_argument("--points", type=int, required=True)
        p.add_argument("--out", required=True)
        p.set_defaults(run=run)
    p = steps.add_parser("fig8-data")
    _rig_arguments(p)
    p.add_argument("--fig6", required=True)
    p.add_argument("--out", required=True)
    p.set_defaults(run=_fig8_data)
    for name in ("fig6-plot", "fig7-plot", "fig8-plot"):
        p = steps.add_parser(name)
        _rig_arguments(p)
        if name == "fig7-plot":
            p.add_argument("--fig4", required=True, help="fig4.csv: its leading-order rows are Fig. 7's asymptotes")
            p.add_argument("--virtual", required=True, help="virtual_pulloff.csv: the simulated pull-off")
        if name == "fig6-plot":
            p.add_argument("--validation", required=True, help="rigid_grid.csv: simulated points and exact averaging")
        _plot_arguments(p)
        p.set_defaults(run=_rigid_fixation_plot)
    return parser


def _plot_arguments(p: argparse.ArgumentParser) -> None:
    """The table a plot step draws and the two files it writes."""
    p.add_argument("--csv", required=True)
    p.add_argument("--pdf", required=True)
    p.add_argument("--png", required=True)


def _compliant_sweep_arguments(p: argparse.ArgumentParser) -> None:
    """Rig, base amplitude and omega_bar range of a compliant-fixation step."""
    _rig_arguments(p)
    p.add_argument("--h1-um", type=float, required=True)
    p.add_argument("--omega-bar-min", type=float, required=True)
    p.add_argument("--omega-bar-max", type=float, required=True)


def _fixation_arguments(p: argparse.ArgumentParser) -> None:
    """Stiffness and damping ratio (Eqs. 65, 66) of one compliant fixation."""
    p.add_argument("--kappa", type=float, required=True)
    p.add_argument("--zeta", type=float, required=True)


def _rig_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--setup", required=True)
    p.add_argument("--fit", required=True)


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        args.run(args)
    except (data.DataError, NoRootError, ContinuationError, FitError, ValueError) as exc:
        print(f"error: {args.step}: {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
