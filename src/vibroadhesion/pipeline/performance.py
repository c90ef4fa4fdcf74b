"""docs/performance.md: what each job and each method costs, as tables written from one run's artefacts.

The numbers are those of the run in ``results/`` (its ``benchmark:`` files and the speed-against-error and
J-integral benchmarks of the ``validation`` target), so the document holds today's numbers only and is rewritten
by ``benchmarks/performance_table.py`` after a run; history is in git.
"""

from __future__ import annotations

import re
from pathlib import Path

import pandas as pd

from vibroadhesion.pipeline.report import rule_timings

#: The artefacts the document is written from, relative to ``results/``.
RULE_TIMINGS = "benchmarks/rules"
SPEED_VS_ERROR = "benchmarks/speed_vs_error.csv"
J_INTEGRALS = "benchmarks/j_integrals.csv"
J_INTEGRALS_TEXT = "benchmarks/j_integrals.txt"

INTRO = """# Performance

Written by `benchmarks/performance_table.py` from the artefacts of one `snakemake -c2 all validation` run.

Machine: {machine}; {load}.

Rerun the script after a run to refresh the numbers. Timings of a loaded machine move by 10–20 %: compare two
versions side by side in one session (`benchmarks/pipeline_time.py A B`: cold and no-op runs of two checkouts in
turn, minimum and median of repeats), never against an older copy of this file. The accuracy of each method does not
depend on the machine and is stated in [findings.md](findings.md#accuracy-of-the-numerics).
"""


def _markdown(frame: pd.DataFrame) -> str:
    """A pipe table of ``frame`` (its cells already formatted as text)."""
    lines = ["| " + " | ".join(frame.columns) + " |", "| " + " | ".join("---" for _ in frame.columns) + " |"]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in frame.itertuples(index=False)]
    return "\n".join(lines) + "\n"


def machine_and_load(results: Path) -> tuple[str, str]:
    """The machine and its load at the start, as the J-integral benchmark recorded them (its first two lines).

    The machine is what follows "on" in the first line, without the count of repeats; the load what follows the
    colon of the second.
    """
    first, second = (results / J_INTEGRALS_TEXT).read_text(encoding="utf-8").splitlines()[:2]
    machine = re.sub(r", \d+ repeats in turn$", "", first.split(" on ", 1)[-1])
    return machine, second.split(": ", 1)[-1]


def rules_table(results: Path) -> pd.DataFrame:
    """Wall time, CPU time and peak memory of every job with a ``benchmark:`` file, longest CPU time first."""
    table = rule_timings(sorted((results / RULE_TIMINGS).glob("*.tsv")))
    table = table.sort_values(["cpu_s", "rule"], ascending=[False, True])
    return pd.DataFrame({"job": [f"`{rule}`" for rule in table["rule"]],
                         "wall time (s)": [f"{v:.1f}" for v in table["wall_s"]],
                         "CPU time (s)": [f"{v:.1f}" for v in table["cpu_s"]],
                         "peak memory (MB)": [f"{v:.0f}" for v in table["max_rss_MB"]]})


def levels_table(results: Path) -> pd.DataFrame:
    """Per model level: milliseconds per point (fastest and median run) and the error against the simulation."""
    table = pd.read_csv(results / SPEED_VS_ERROR)
    return pd.DataFrame({"level": [f"`{m}`" for m in table["model"]],
                         "ms per point, fastest": [f"{1e3 * v:.2f}" for v in table["seconds_per_point_min"]],
                         "ms per point, median": [f"{1e3 * v:.2f}" for v in table["seconds_per_point_median"]],
                         "max error (%)": [f"{100 * v:.1f}" for v in table["max_relative_error_vs_simulation"]],
                         "median error (%)": [f"{100 * v:.1f}" for v in table["median_relative_error_vs_simulation"]]})


def j_integrals_table(results: Path) -> pd.DataFrame:
    """Evaluations per second and the largest relative error against mpmath, per method and exponent n."""
    table = pd.read_csv(results / J_INTEGRALS)
    return pd.DataFrame({"method": table["method"], "n": [f"{v:g}" for v in table["n"]],
                         "evaluations/s (median)": [f"{v:.3g}" for v in table["evaluations_per_s_median_time"]],
                         "max relative error": [f"{v:.1e}" for v in table["max_relative_error"]],
                         "speed-up (median)": [f"{v:.3g}" for v in table["speedup_vs_quad_median"]]})


def performance_markdown(results: str | Path) -> str:
    """The whole of docs/performance.md, from the artefacts under ``results``."""
    root = Path(results)
    machine, load = machine_and_load(root)
    return "\n".join([
        INTRO.format(machine=machine, load=load),
        "## Jobs\n\nEach job of the run with a Snakemake `benchmark:` file (one run, interpreter start-up included).\n",
        _markdown(rules_table(root)),
        "## Model levels: speed against error\n\nAt the rig's 15 test conditions, each point solved 5 times per "
        "level, the levels in turn (`results/benchmarks/speed_vs_error.csv`).\n",
        _markdown(levels_table(root)),
        "## J-integrals\n\nThe fixed 72-node rule against `scipy.integrate.quad` (epsrel 1e-12), both against the "
        "30-digit mpmath reference (`results/benchmarks/j_integrals.csv`).\n",
        _markdown(j_integrals_table(root)),
    ])
