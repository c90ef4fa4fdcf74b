"""Which tests to add (vibroadhesion.experiments.design): D-optimal augmentation of a pull-off design.

References: closed forms (the matrix determinant lemma det(A + s s^T) = det(A) (1 + s^T A^-1 s) for one
added row; the Fisher information of the static row (1, 0, 0) is e1 e1^T / sigma^2, Eq. 70), and an
exhaustive search over all sets written here, independently of the module's.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pandas as pd
import pytest

from vibroadhesion.experiments import design
from vibroadhesion.experiments.identifiability import IDENTIFIABLE_RELATIVE_SE, SENSITIVITY_COLUMNS

S_COLUMNS = SENSITIVITY_COLUMNS[-3:]


def _brute_force(current: np.ndarray, candidates: np.ndarray, count: int) -> tuple[int, ...]:
    """The set of ``count`` candidates with the largest det(S^T S), by np.linalg.det of every set."""
    return max(itertools.combinations(range(len(candidates)), count),
               key=lambda c: np.linalg.det(np.vstack([current, candidates[list(c)]]).T @
                                           np.vstack([current, candidates[list(c)]])))


def test_one_added_row_is_the_largest_mahalanobis_norm_and_raises_det_by_the_lemma() -> None:
    """Current design diag(1, 1, 0.1): A = diag(1, 1, 0.01). The added row s maximising det(A + s s^T) maximises
    s^T A^-1 s: (0, 0, 0.5) gives 1 + 25 = 26, beating (1, 1, 0) (3) and (0.3, 0.3, 0.3) (1 + 0.18 + 9 = 10.18).
    det = 0.01 * 26 = 0.26 exactly (up to rounding, 1e-12)."""
    current = np.diag([1.0, 1.0, 0.1])
    candidates = np.array([[1.0, 1.0, 0.0], [0.3, 0.3, 0.3], [0.0, 0.0, 0.5]])
    assert design.d_optimal(current, candidates, 1) == [2]
    assert design.log_det_information(np.vstack([current, candidates[[2]]])) == pytest.approx(math.log(0.26), abs=1e-12)
    # Two rows: (0, 0, 0.5) and (0.3, 0.3, 0.3) or (1, 1, 0)? det by hand: A + both outer products.
    by_hand = {pair: np.linalg.det(np.diag([1.0, 1.0, 0.01]) + sum(np.outer(candidates[i], candidates[i]) for i in pair))
               for pair in itertools.combinations(range(3), 2)}
    assert tuple(design.d_optimal(current, candidates, 2)) == max(by_hand, key=by_hand.__getitem__)


@pytest.mark.parametrize("seed, count", [(28, 2), (28, 3), (29, 2), (34, 3), (39, 3)])
def test_greedy_and_exchange_equal_exhaustive_search_where_greedy_alone_does_not(seed: int, count: int) -> None:
    """Random 10-candidate cases (current design weak in its third direction) in which greedy addition alone
    misses the optimum: the exchange passes reach the set of the brute-force search, and so does
    ``d_optimal`` (exhaustive here)."""
    rng = np.random.default_rng(seed)
    current = rng.normal(size=(3, 3)) * np.array([1.0, 1.0, 0.05])
    candidates = rng.normal(size=(10, 3))
    best = list(_brute_force(current, candidates, count))
    greedy: list[int] = []
    for _ in range(count):
        greedy.append(design._best_addition(current, candidates, greedy))
    assert sorted(greedy) != best  # the case needs the exchange
    assert design.greedy_exchange(current, candidates, count) == best
    assert design.d_optimal(current, candidates, count) == best


def _simulated(rows: list[tuple[float, float, str, tuple[float, float, float] | None]]) -> pd.DataFrame:
    """Sensitivity rows (frequency, h1, status, S row or None for no derivative)."""
    return pd.DataFrame([{"frequency_hz": f, "h1_um": h, "status": status, "pulloff_mN": 1.0 if s else math.nan,
                          **dict(zip(S_COLUMNS, s or (math.nan,) * 3, strict=True))} for f, h, status, s in rows])


def test_static_test_adds_exactly_one_over_sigma_squared_to_w0_and_a_contact_loss_candidate_is_excluded() -> None:
    """Current S = diag(2, 0.5, 0.1) (three rows): Fisher information diag(4, 0.25, 0.01)/sigma^2. The candidates are a
    row whose family lost contact (no derivative) and the static JKR test (1, 0, 0), so the one added test is the
    static one: the information becomes diag(5, 0.25, 0.01)/sigma^2 and the standard errors sigma (1/sqrt 5, 2, 10)
    (1e-14). The lost row is listed with its status, not usable."""
    current = _simulated([(200.0, 20.0, "pulloff", (2.0, 0.0, 0.0)), (200.0, 60.0, "pulloff", (0.0, 0.5, 0.0)),
                          (300.0, 60.0, "pulloff", (0.0, 0.0, 0.1))])
    lost = _simulated([(1.0, 120.0, "contact_loss_before_extremum", None)])
    candidates = design.candidate_table(lost)
    assert candidates["status"].tolist() == ["contact_loss_before_extremum", design.STATIC_STATUS]
    assert candidates["usable"].tolist() == [False, True]
    assert candidates[S_COLUMNS].iloc[0].isna().all()
    static = candidates[S_COLUMNS].to_numpy(float)[1]
    s = current[S_COLUMNS].to_numpy(float)
    added = np.vstack([s, static])
    sigma = 0.01
    assert np.array_equal((added.T @ added - s.T @ s) / sigma**2, np.diag([1 / sigma**2, 0.0, 0.0]))
    table = design.design_table(current, candidates, [1], [sigma]).set_index("design")
    after = table.loc["current + 1 test"]
    assert after["added"] == "static JKR test (h1 = 0)" and after["rows"] == 4
    expected = sigma * np.array([1 / math.sqrt(5.0), 2.0, 10.0])
    assert np.allclose(after[["w0_relative_se", "n_relative_se", "v0_relative_se"]].to_numpy(float), expected,
                       rtol=1e-14, atol=0)
    before = table.loc["current"]
    assert before["w0_relative_se"] == pytest.approx(sigma / 2.0, rel=1e-14)


def test_the_sentence_says_where_v0_becomes_identifiable_from_the_numbers() -> None:
    """v0 relative SE 10 sigma from the current rows; one added row (0, 0, 1) at 30 Hz gives sigma/sqrt(1.01):
    at sigma = 0.1 v0 goes from 100 % (not identifiable) to 9.95 %, identifiable, at 30 Hz."""
    current = _simulated([(200.0, 20.0, "pulloff", (2.0, 0.0, 0.0)), (200.0, 60.0, "pulloff", (0.0, 0.5, 0.0)),
                          (300.0, 60.0, "pulloff", (0.0, 0.0, 0.1))])
    candidates = design.candidate_table(_simulated([(30.0, 120.0, "pulloff", (0.0, 0.0, 1.0))]))
    table = design.design_table(current, candidates, [1], [0.1])
    assert 0.1 * 10 >= IDENTIFIABLE_RELATIVE_SE > 0.1 / math.sqrt(1.01)
    text = design.v0_sentence(table)
    assert "fix v0 to 100 % (not identifiable" in text
    assert "v0 becomes identifiable with 1 added test(s), at 30 Hz (30 Hz, h1 = 120 um): 9.95 %" in text
