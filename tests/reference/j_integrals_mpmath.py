"""Write j_integrals_mpmath.csv: the 30-digit mpmath J-integrals at every (n, Abar) that tests/core/test_integrals.py
checks the package's rule against (its ``stored_points``).

Source: ``tests/mpmath_reference.j_integrals_mp_computed``, the definitions Eqs. (28), (29), (36) of Argatov,
Papangelo & Ciavarella with the Gent–Schultz law of Eqs. (73)–(75), integrated by mpmath's tanh-sinh quadrature at 30 significant
digits (guard digits for the cancellation in Jc1), independently of the package. The points are the grids of
``test_integrals._abar_grid`` (fixed and seeded log-uniform Abar per n), its ``HARD_CASES`` and its probes near
Abar = 2. Stored because the quadrature takes about a minute and a quarter for them all (``mpmath_reference.
j_integrals_mp`` reads a stored point, computes any other); ``test_integrals.test_stored_reference_is_the_mpmath_
quadrature`` recomputes a sample of the rows and checks that the stored points are the tests' points.

Run from the repository root: ``.venv/bin/python tests/reference/j_integrals_mpmath.py`` (deterministic: the same file).
"""

from __future__ import annotations

import csv
import sys
from pathlib import Path

import mpmath as mp

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE.parent), str(HERE.parent / "core")]

from mpmath_reference import STORED, j_integrals_mp_computed  # noqa: E402
from test_integrals import stored_points  # noqa: E402

#: Columns of the stored table: one row per (n, Abar), the integrals as 45-significant-digit decimal strings (the
#: quadrature works at 40 digits and more; the large-Abar remainders, 1e-12 of J0 = 2.5e23 at n = 4, Abar = 1e12,
#: need them all).
COLUMNS = ["n", "Abar", "J0", "Jc1", "J1"]


def main() -> None:
    """Compute every point of ``stored_points()`` and write the table (same points, same bytes)."""
    with STORED.open("w", newline="") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(COLUMNS)
        for n, abar in stored_points():
            values = j_integrals_mp_computed(abar, n)
            writer.writerow([repr(n), repr(abar), *(mp.nstr(v, 45, strip_zeros=False) for v in values)])


if __name__ == "__main__":
    main()
