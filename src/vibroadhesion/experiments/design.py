"""Which pull-off tests to run next: a D-optimal augmentation of the rig's design (issue 13, item 4).

The rig's tests (the virtual pull-off rows at the test conditions of data/setup.yaml) have the
sensitivity rows S_i = d ln P_i / d ln theta (theta = w0, n, v0) of the full model
(:func:`vibroadhesion.experiments.identifiability.envelope_sensitivity`). With relative scatter sigma
per test the covariance of ln theta is at best sigma^2 (S^T S)^-1 (Cramer-Rao), so the tests to add
are those that maximise det(S^T S) of the current rows plus the added ones (D-optimal: the smallest
volume of the confidence ellipsoid, whatever sigma).

Candidates: every simulated (frequency, amplitude) pair of the candidate grid with its status (a
family that ends without a pull-off, or without a derivative, is listed and excluded), and the static
JKR test h1 = 0, |P_cr^JKR| = (3 pi/2) R w0 (Eq. 70), whose row is exactly (1, 0, 0) whatever the
frequency. A test may repeat one of the rig's conditions (a replicate); the added tests are distinct.

Search (:func:`d_optimal`): exhaustive over all sets of distinct candidates while there are at most
EXHAUSTIVE_LIMIT of them (a stack of 3 x 3 determinants: 26,235 sets for 3 of 55 candidates, a few ms);
beyond, greedy (add the candidate that raises det most, one at a time) and exchange passes (replace an
added test by any other candidate while det grows: Fedorov's exchange), which end at a design no single
exchange improves -- a local optimum, the global one on the tested cases.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence

import numpy as np
import pandas as pd

from vibroadhesion.experiments.identifiability import (
    IDENTIFIABLE_RELATIVE_SE,
    PARAMETERS,
    SENSITIVITY_COLUMNS,
    standard_errors,
)

#: The static JKR test's sensitivity row: |P_cr^JKR| is proportional to w0 and independent of n, v0 (Eq. 70).
STATIC_ROW = (1.0, 0.0, 0.0)
#: The status of the static JKR candidate (no simulation: Eq. 70 is exact).
STATIC_STATUS = "static_jkr"
#: Exhaustive search up to this many sets of added tests (beyond: greedy and exchange).
EXHAUSTIVE_LIMIT = 200_000
#: An exchange must raise ln det(S^T S) by more than this to be taken (the rows carry ~1e-5 relative error).
MIN_GAIN = 1e-9

_S_COLUMNS = SENSITIVITY_COLUMNS[-3:]
CANDIDATE_COLUMNS = [*SENSITIVITY_COLUMNS, "usable"]
DESIGN_COLUMNS = ["design", "added", "added_frequencies", "rows", "log_det_information", "relative_noise",
                  *(f"{n}_relative_se" for n in PARAMETERS), *(f"{n}_identifiable" for n in PARAMETERS)]


def candidate_table(simulated: pd.DataFrame) -> pd.DataFrame:
    """The candidate tests: the simulated rows (SENSITIVITY_COLUMNS) and the static JKR test (Eq. 70).

    ``usable`` is true where the row has a sensitivity (status ``pulloff``, or the static test); the
    others keep their status and no numbers. The static test has no frequency (empty) and no force.
    """
    static = pd.DataFrame([{"frequency_hz": math.nan, "h1_um": 0.0, "status": STATIC_STATUS,
                            **dict(zip(_S_COLUMNS, STATIC_ROW, strict=True))}])
    table = pd.concat([simulated[SENSITIVITY_COLUMNS], static], ignore_index=True)
    table["usable"] = np.all(np.isfinite(table[_S_COLUMNS].to_numpy(float)), axis=1)
    return table.reindex(columns=CANDIDATE_COLUMNS)


def log_det_information(rows: np.ndarray) -> float:
    """ln det(S^T S) of the sensitivity rows ``rows`` (the D-criterion: Fisher information at sigma = 1).

    -inf where S^T S is singular.
    """
    sign, value = np.linalg.slogdet(rows.T @ rows)
    return float(value) if sign > 0 else -math.inf


def d_optimal(current: np.ndarray, candidates: np.ndarray, count: int) -> list[int]:
    """Indices (sorted) of ``count`` distinct rows of ``candidates`` that maximise det(S^T S) with ``current``.

    Exhaustive where cheap, else greedy and exchange (module docstring).
    """
    if not 0 < count <= len(candidates):
        raise ValueError(f"need 1 to {len(candidates)} added tests, got {count}")
    if math.comb(len(candidates), count) <= EXHAUSTIVE_LIMIT:
        return exhaustive(current, candidates, count)
    return greedy_exchange(current, candidates, count)


def exhaustive(current: np.ndarray, candidates: np.ndarray, count: int) -> list[int]:
    """The ``count`` distinct candidate rows with the largest det(S^T S) with ``current`` (the first on a tie)."""
    sets = np.array(list(itertools.combinations(range(len(candidates)), count)), dtype=int)
    outer = np.einsum("ki,kj->kij", candidates, candidates)
    sign, value = np.linalg.slogdet(current.T @ current + outer[sets].sum(axis=1))
    return [int(i) for i in sets[int(np.argmax(np.where(sign > 0, value, -np.inf)))]]


def greedy_exchange(current: np.ndarray, candidates: np.ndarray, count: int) -> list[int]:
    """Greedy choice of ``count`` candidate rows, then exchange passes until none raises ln det by MIN_GAIN."""
    chosen: list[int] = []
    for _ in range(count):
        chosen.append(_best_addition(current, candidates, chosen))
    improved = True
    while improved:
        improved = False
        for position in range(count):
            rest = chosen[:position] + chosen[position + 1:]
            best = _best_addition(current, candidates, rest)
            gain = _log_det_with(current, candidates, rest + [best]) - _log_det_with(current, candidates, chosen)
            if gain > MIN_GAIN:
                chosen[position], improved = best, True
    return sorted(chosen)


def _best_addition(current: np.ndarray, candidates: np.ndarray, chosen: list[int]) -> int:
    """The unchosen candidate whose addition to ``current`` and ``chosen`` gives the largest det(S^T S)."""
    free = [j for j in range(len(candidates)) if j not in chosen]
    values = [_log_det_with(current, candidates, chosen + [j]) for j in free]
    return free[int(np.argmax(values))]


def _log_det_with(current: np.ndarray, candidates: np.ndarray, chosen: list[int]) -> float:
    """ln det(S^T S) of ``current`` plus the ``chosen`` candidate rows."""
    return log_det_information(np.vstack([current, candidates[chosen]]))


def describe(test: pd.Series) -> str:
    """A candidate test in words: "30 Hz, h1 = 120 um", or the static JKR test."""
    if test["status"] == STATIC_STATUS:
        return "static JKR test (h1 = 0)"
    return f"{test['frequency_hz']:g} Hz, h1 = {test['h1_um']:g} um"


def design_table(current: pd.DataFrame, candidates: pd.DataFrame, added: Sequence[int],
                 noises: Sequence[float]) -> pd.DataFrame:
    """Expected relative standard errors of w0, n, v0 for the current design and each D-optimal augmentation.

    ``current``: the rig's sensitivity rows (rows without a derivative are left out, as in
    :func:`~vibroadhesion.experiments.identifiability.information_table`); ``candidates``: the table of
    :func:`candidate_table`; ``added``: how many tests to add (e.g. 1, 2, 3). One row per design and
    relative scatter sigma, standard errors sigma sqrt(diag((S^T S)^-1)) (Cramer-Rao). An augmentation by more tests
    than there are usable candidates (where few simulated families found a pull-off) has no row.
    """
    s = current[_S_COLUMNS].to_numpy(float)
    s = s[np.all(np.isfinite(s), axis=1)]
    usable = candidates[candidates["usable"]].reset_index(drop=True)
    pool = usable[_S_COLUMNS].to_numpy(float)
    designs = [("current", usable.iloc[[]])]
    designs += [(f"current + {k} test{'s' if k > 1 else ''}", usable.iloc[d_optimal(s, pool, k)]) for k in added
                if k <= len(pool)]  # more tests than usable candidates (no simulated pull-off among them): none
    rows = []
    for name, tests in designs:
        matrix = np.vstack([s, tests[_S_COLUMNS].to_numpy(float)])
        frequencies = sorted({f for f in tests["frequency_hz"] if np.isfinite(f)})
        for noise in noises:
            se, _ = standard_errors(matrix, noise)
            rows.append({"design": name, "added": "; ".join(describe(t) for _, t in tests.iterrows()),
                         "added_frequencies": ", ".join(f"{f:g} Hz" for f in frequencies), "rows": len(matrix),
                         "log_det_information": log_det_information(matrix), "relative_noise": noise,
                         **{f"{n}_relative_se": float(v) for n, v in zip(PARAMETERS, se, strict=True)},
                         **{f"{n}_identifiable": bool(v < IDENTIFIABLE_RELATIVE_SE)
                            for n, v in zip(PARAMETERS, se, strict=True)}})
    return pd.DataFrame(rows).reindex(columns=DESIGN_COLUMNS)


def v0_sentence(design: pd.DataFrame) -> str:
    """Whether v0 becomes identifiable (relative SE below IDENTIFIABLE_RELATIVE_SE) and with tests at which frequencies.

    One sentence per relative scatter of ``design`` (:func:`design_table`), computed from its numbers.
    """
    limit = f"{100 * IDENTIFIABLE_RELATIVE_SE:g} %"
    text = []
    for noise, rows in design.groupby("relative_noise", sort=True):
        now = rows[rows["design"] == "current"].iloc[0]
        head = (f"At {100 * noise:g} % scatter the rig's {now['rows']} tests fix v0 to "
                f"{100 * now['v0_relative_se']:.3g} % "
                f"({'identifiable' if now['v0_identifiable'] else 'not identifiable'}: the limit is {limit})")
        gained = rows[(rows["design"] != "current") & rows["v0_identifiable"]]
        if now["v0_identifiable"]:
            text.append(head + ".")
        elif gained.empty:
            best = rows.iloc[-1]
            text.append(f"{head}; v0 stays not identifiable with the best {best['rows'] - now['rows']} added tests "
                        f"({best['added']}: {100 * best['v0_relative_se']:.3g} %).")
        else:
            first = gained.iloc[0]
            frequencies = first["added_frequencies"]
            where = f"at {frequencies}" if isinstance(frequencies, str) and frequencies else "none vibrated"
            text.append(f"{head}; v0 becomes identifiable with {first['rows'] - now['rows']} added test(s), {where} "
                        f"({first['added']}): {100 * first['v0_relative_se']:.3g} %.")
    return " ".join(text)
