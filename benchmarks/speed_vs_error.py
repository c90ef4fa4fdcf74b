"""Speed against error of every model level at the paper's experimental conditions.

Usage: python benchmarks/speed_vs_error.py SETUP_JSON RIGID_ERRORS_CSV OUT_CSV OUT_TXT OUT_PNG

For each level of role ``validation_rigid`` of :mod:`vibroadhesion.core.levels` (leading order, refined, exact harmonic
balance, exact averaging, direct simulation) it times the solve of each point (h1 of data/setup.yaml
x the test frequencies, at the published parameters as the validation) on this machine, median of 3 per point, and takes the error of that level
against the simulation at the same points from the validation artefact (largest relative error over
Abar, abar_m, w_eff/w0, A/a_m and P_m/|P_JKR|). The simulation is the reference: its error is its
self-consistency between rtol 1e-12 and 1e-13, measured in results/benchmarks/simulate.txt, and is
listed as 0 here. Timings vary from run to run; the CSV is a benchmark, not a pipeline result. The
figure names each level by its registry label and marks it by the registry's cost class.
"""

import statistics
import sys
import time

import matplotlib.pyplot as plt
import pandas as pd

from vibroadhesion.core import groups, levels
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.benchmarking import machine_description
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.data import read_canonical_setup
from vibroadhesion.pipeline.figures import save_figure

#: The registry's functions this script resolves (vibroadhesion.core.levels): the rigid steady states.
LEVEL_FUNCTIONS = (("validation_rigid", "steady_state"),)
#: Marker of each cost class of the registry in the figure (the classes the timings are grouped into).
MARKERS: dict[levels.Cost, str] = {"algebraic": "o", "quadrature": "s", "simulation": "^"}


def main(setup_json: str, errors_csv: str, out_csv: str, out_txt: str, out_png: str) -> None:
    setup = read_canonical_setup(setup_json)
    p = {"w0": setup.w0, "n": setup.n, "v0": setup.v0}
    chi0 = groups.chi0(p["w0"], setup.reduced_modulus, setup.radius)
    law = GentSchultz(p["n"])
    tests = [float(groups.omega_check(f, p["v0"], setup.radius)) for f in setup.frequencies_hz]
    points = [(h * 1e-6 / setup.radius, w) for h in setup.amplitudes_um for w in tests]
    errors = pd.read_csv(errors_csv)
    at_tests = errors[errors["omega_check"].isin(tests)]
    rows = []
    for model in levels.names("validation_rigid"):
        level = levels.level(model).steady_state_function()
        times = []
        for eta1, w in points:
            runs = []
            for _ in range(3):
                start = time.perf_counter()
                level(eta1, w, chi0, law)
                runs.append(time.perf_counter() - start)
            times.append(statistics.median(runs))
        err = at_tests[at_tests["model"] == model]["relative_error"]
        rows.append({"model": model, "points": len(points), "seconds_per_point_median": statistics.median(times),
                     "seconds_per_point_max": max(times),
                     "max_relative_error_vs_simulation": 0.0 if model == "simulation" else float(err.max()),
                     "median_relative_error_vs_simulation": 0.0 if model == "simulation" else float(err.median())})
    table = pd.DataFrame(rows)
    write_csv(table, out_csv)
    text = (f"Speed against error at the experimental conditions ({len(points)} points: h1 = "
            f"{', '.join(f'{h:g}' for h in setup.amplitudes_um)} um x {', '.join(f'{f:g}' for f in setup.frequencies_hz)} Hz)\n"
            f"machine: {machine_description()}\n\n{table.to_string(index=False)}\n")
    with open(out_txt, "w", encoding="utf-8") as fh:
        fh.write(text)
    print(text)
    fig, ax = plt.subplots(figsize=(5.2, 3.8), layout="constrained")
    for k, r in table.iterrows():
        entry = levels.level(r["model"])
        if r["model"] == "simulation":  # the reference: no error of its own to plot, only its time
            ax.axvline(r["seconds_per_point_median"], color=f"C{k}", ls="--", lw=1.0,
                       label=f"{entry.label} [{entry.cost}]: the reference (its time)")
            continue
        ax.plot(r["seconds_per_point_median"], r["max_relative_error_vs_simulation"], MARKERS[entry.cost],
                color=f"C{k}", ms=8, label=f"{entry.label} [{entry.cost}]")
    ax.set(xscale="log", yscale="log", xlabel="time per solved point (s, median)",
           ylabel="largest relative error vs simulation", title="Speed against error at the test conditions")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)  # beside the points
    save_figure(fig, out_png.replace(".png", ".pdf"), out_png)


if __name__ == "__main__":
    main(*sys.argv[1:6])
