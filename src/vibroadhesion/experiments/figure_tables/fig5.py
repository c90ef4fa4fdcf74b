"""Fig. 5: passage through resonance of a compliantly fixed indenter.

Refined model (Eqs. 87, 90-96), traced by continuation.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from vibroadhesion.core.fixation import Fixation
from vibroadhesion.core.ratelaw import GentSchultz
from vibroadhesion.models.compliant import static_abar_0
from vibroadhesion.models.response_curve import OPEN_ENDS, ResponseCurve, trace_response_curve

FIG5_COLUMNS = ["chi0", "eta1", "nu0", "zeta", "kappa", "mu", "branch", "omega_bar", "Abar", "abar_m", "A_over_am"]
FIG5_MARKER_COLUMNS = ["kind", "frequency_hz", *FIG5_COLUMNS]
FIG5_COUNT_COLUMNS = ["zeta", "kappa", "omega_bar", "solutions"]


def _fig5_rows(branch: Sequence[str], x: np.ndarray, curve: ResponseCurve) -> pd.DataFrame:
    """Rows of fig5.csv at points x = (ln omega_bar, ln abar_m, ln Abar) of ``curve`` (Eqs. 87, 90, 98 corrected)."""
    p = curve.fixation
    return pd.DataFrame({"chi0": curve.chi0, "eta1": curve.eta1, "nu0": p.nu0, "zeta": p.zeta, "kappa": p.kappa,
                         "mu": p.mu,
                         "branch": branch, "omega_bar": np.exp(x[:, 0]), "Abar": np.exp(x[:, 2]),
                         "abar_m": np.exp(x[:, 1]), "A_over_am": curve.A_over_am(x)})[FIG5_COLUMNS]


def fig5_tables(
    fixations: Sequence[Fixation], chi0: float, eta1: float, n: float,
    experiment_omega_bar: Mapping[float, float], omega_bar_range: tuple[float, float], count_points: int,
) -> tuple[pd.DataFrame, pd.DataFrame, pd.DataFrame]:
    """Fig. 5 for every compliant fixation (kappa, zeta, nu0, mu) at chi0 (Eq. 64) and eta1 = h1/R (Eq. 65).

    The traced curves, the markers (folds, test frequencies), and the number of solutions on a log grid of
    omega_bar.

    ``branch`` names the monotone segment of the curve in trace order: "lower-k"/"upper-k" for the
    two pieces below/above the exact anti-resonance (zeta = 0), "full-k" otherwise, and "<piece>_reverse-k"
    for a part traced back (:func:`vibroadhesion.models.response_curve.trace_response_curve`); k counts the
    folds passed. A piece that cannot be continued (``OPEN_ENDS``: it runs to unbounded amplitude, or the
    corrector fails) has a marker of that ``kind`` at its last point. The exact anti-resonance point (Abar = 0
    at omega_bar = 1, zeta = 0) is a row with branch "anti-resonance". The markers of the test frequencies are
    the solutions on the traced curve there (:meth:`vibroadhesion.models.response_curve.ResponseCurve.
    steady_states_at`), by increasing Abar.
    """
    law = GentSchultz(n)
    curves, markers, counts = [], [], []
    grid = np.geomspace(*omega_bar_range, count_points)
    for p in fixations:
        curve = trace_response_curve(p, chi0, eta1, law, omega_bar_range)
        for name, piece, end in zip(curve.names, curve.pieces, curve.ends, strict=True):
            turns = np.sign(piece.tangents[1:, 0]) != np.sign(piece.tangents[:-1, 0])
            segment = np.concatenate([[0], np.cumsum(turns)])
            curves.append(_fig5_rows([f"{name}-{k}" for k in segment], piece.points, curve))
            if end in OPEN_ENDS:  # the piece could not be continued: its last point, with why
                markers.append(_fig5_rows([f"{name}-{segment[-1]}"], piece.points[-1:], curve)
                               .assign(kind=end, frequency_hz=np.nan))
        if "lower" in curve.names:  # split at the exact anti-resonance: Abar = 0 there
            anti = np.array([[0.0, np.log(static_abar_0(p, chi0)), -np.inf]])
            curves.append(_fig5_rows(["anti-resonance"], anti, curve))
        markers.append(_fig5_rows(["fold"] * len(curve.folds), curve.folds, curve)
                       .assign(kind="fold", frequency_hz=np.nan))
        for f, omega_bar in sorted(experiment_omega_bar.items()):
            states = curve.steady_states_at(omega_bar, law)
            solved = states.ok
            solutions = np.column_stack([np.full(np.count_nonzero(solved), np.log(omega_bar)),
                                         np.log(states.abar_m[solved]), np.log(states.Abar[solved])])
            markers.append(_fig5_rows(["experiment"] * len(solutions), solutions, curve)
                           .assign(kind="experiment", frequency_hz=f))
        counts.append(pd.DataFrame({"zeta": p.zeta, "kappa": p.kappa, "omega_bar": grid,
                                    "solutions": [curve.count_at(w) for w in grid]}))
    return (pd.concat(curves, ignore_index=True), pd.concat(markers, ignore_index=True)[FIG5_MARKER_COLUMNS],
            pd.concat(counts, ignore_index=True)[FIG5_COUNT_COLUMNS])
