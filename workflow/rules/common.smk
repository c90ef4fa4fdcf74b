# Helpers shared by the rules.
import sys
from pathlib import Path

# Run every step with the interpreter that runs Snakemake (the project's virtual environment),
# whether or not that environment is activated in the shell.
PYTHON = sys.executable

FIGURES = ["fig3", "fig4", "fig5", "fig6", "fig7", "fig8"]


def code(*modules):
    """Package sources a rule depends on, plus the lock: editing any of them reruns the rule.

    Snakemake does not track imported code by itself; listing the files as inputs makes a
    change of their content trigger a rerun of exactly the rules that use them.
    """
    return [str(next(Path("src/vibroadhesion").glob(f"*/{m}.py"))) for m in modules] + ["environment.lock"]


NUMERICS = [
    "ratelaw",
    "integrals",
    "roots",
    "scan",
    "groups",
    "jkr",
    "leading_order",
    "leading_pulloff",
    "refined",
    "pulloff",
]
#: The simulation sub-package, module by module (model -> integrators -> orbits -> shooting).
SIMULATION = ["model", "integrators", "orbits", "shooting"]
