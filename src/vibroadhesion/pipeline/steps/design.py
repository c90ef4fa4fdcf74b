"""Step of the design rule: which pull-off tests to add to the rig's (D-optimal), from the sensitivity jobs."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import pandas as pd

from vibroadhesion.experiments import design
from vibroadhesion.pipeline.artefacts import write_csv
from vibroadhesion.pipeline.steps.identifiability import rig_sensitivity


def experiment_design(virtual_csv: str | Path, sensitivity_parts: Sequence[str | Path], noise: Sequence[float],
                      added: Sequence[int], design_out: str | Path, candidates_out: str | Path) -> None:
    """design.csv and candidates.csv: which tests to add to the rig's (D-optimal), and every candidate's status.

    The current design is the rig's rows (:func:`~vibroadhesion.pipeline.steps.identifiability.rig_sensitivity`),
    the candidates every row of the parts and the static JKR test
    (:func:`vibroadhesion.experiments.design.candidate_table`).
    """
    candidates = design.candidate_table(pd.concat([pd.read_csv(p) for p in sensitivity_parts], ignore_index=True))
    table = design.design_table(rig_sensitivity(virtual_csv, sensitivity_parts), candidates, added, noise)
    write_csv(candidates, candidates_out)
    write_csv(table, design_out)
    print(table.to_string(index=False))
    print(design.v0_sentence(table))
