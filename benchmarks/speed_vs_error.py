"""Speed against error of every model level at the paper's experimental conditions.

Usage: python benchmarks/speed_vs_error.py SETUP_JSON RIGID_ERRORS_CSV OUT_CSV OUT_TXT OUT_PNG

For each level of role ``validation_rigid`` of :mod:`vibroadhesion.core.levels` (leading order, refined, exact harmonic
balance, exact averaging, direct simulation) it times the solve of each point (h1 of data/setup.yaml
x the test frequencies, at the published parameters as the validation) on this machine, REPEATS times per point with
the levels in turn (so that the load of a shared machine hits them alike), and takes the error of that level
against the simulation at the same points from the validation artefact (largest relative error over
Abar, abar_m, w_eff/w0, A/a_m and P_m/|P_JKR|). The simulation is the reference: its error is its
self-consistency between rtol 1e-12 and 1e-13, measured in results/benchmarks/simulate.txt, and is
listed as 0 here. A level's time per point is the median over the points of each point's fastest run
(``seconds_per_point_min``) and of its median run (``seconds_per_point_median``; ``seconds_per_point_max``: the
slowest point's median); the text states the machine's load before and after. Timings vary from run to run; the
CSV is a benchmark, not a pipeline result. The figure names each level by its registry label and marks it by the
registry's cost class.
"""

import statistics
import sys
from functools import partial

import pandas as pd

from vibroadhesion.core import groups, levels
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.experiments.benchmarking import load_average, load_note, machine_description, timed_in_turn
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.data import read_canonical_setup
from vibroadhesion.pipeline.figures import save_figure
from vibroadhesion.pipeline.page_figures import plot_speed_vs_error

#: The registry's functions this script resolves (vibroadhesion.core.levels): the rigid steady states.
LEVEL_FUNCTIONS = (("validation_rigid", "steady_state"),)
#: Runs of each level per point.
REPEATS = 5


def format_rows(table):
    """The table as text a page shows without wrapping: short headers, times in ms, errors in %."""
    lines = [f"{'level':<16}{'points':>7}{'ms/point: fastest':>19}{'median':>9}{'slowest':>9}{'max error %':>13}"
             f"{'median error %':>16}"]
    for r in table.itertuples():
        lines.append(f"{r.model:<16}{r.points:>7}{1e3 * r.seconds_per_point_min:>19.3f}"
                     f"{1e3 * r.seconds_per_point_median:>9.3f}{1e3 * r.seconds_per_point_max:>9.3f}"
                     f"{100 * r.max_relative_error_vs_simulation:>13.3g}"
                     f"{100 * r.median_relative_error_vs_simulation:>16.3g}")
    return "\n".join(lines) + "\n"


def main(setup_json: str, errors_csv: str, out_csv: str, out_txt: str, out_png: str) -> None:
    setup = read_canonical_setup(setup_json)
    p = {"w0": setup.w0, "n": setup.n, "v0": setup.v0}
    chi0 = groups.chi0(p["w0"], setup.reduced_modulus, setup.radius)
    law = GentSchultz(p["n"])
    tests = [float(groups.omega_check(f, p["v0"], setup.radius)) for f in setup.frequencies_hz]
    points = [(h * 1e-6 / setup.radius, w) for h in setup.amplitudes_um for w in tests]
    errors = pd.read_csv(errors_csv)
    at_tests = errors[errors["omega_check"].isin(tests)]
    models = levels.names("validation_rigid")
    before = load_average()
    runs = {model: [] for model in models}  # per model, per point: the seconds of each repeat
    for eta1, w in points:
        calls = {m: partial(levels.level(m).steady_state_function(), eta1, w, chi0, law) for m in models}
        for model, seconds in timed_in_turn(calls, REPEATS).items():
            runs[model].append(seconds)
    load = load_note(before)
    rows = []
    for model in models:
        err = at_tests[at_tests["model"] == model]["relative_error"]
        medians = [statistics.median(seconds) for seconds in runs[model]]
        rows.append({"model": model, "points": len(points),
                     "seconds_per_point_min": statistics.median(min(seconds) for seconds in runs[model]),
                     "seconds_per_point_median": statistics.median(medians), "seconds_per_point_max": max(medians),
                     "max_relative_error_vs_simulation": 0.0 if model == "simulation" else float(err.max()),
                     "median_relative_error_vs_simulation": 0.0 if model == "simulation" else float(err.median())})
    table = pd.DataFrame(rows)
    write_csv(table, out_csv)
    text = (f"Speed against error at the experimental conditions ({len(points)} points: h1 = "
            f"{', '.join(f'{h:g}' for h in setup.amplitudes_um)} um x {', '.join(f'{f:g}' for f in setup.frequencies_hz)} Hz)\n"
            f"machine: {machine_description()}\n{load}\neach point solved {REPEATS} times per level, the levels in "
            "turn; seconds per point: the median over the points of the fastest and of the median run\n\n"
            f"{format_rows(table)}")
    with open(out_txt, "w", encoding="utf-8") as fh:
        fh.write(text)
    print(text)
    fig = plot_speed_vs_error(table, REPEATS)
    save_figure(fig, out_png.replace(".png", ".pdf"), out_png)


if __name__ == "__main__":
    main(*sys.argv[1:6])
