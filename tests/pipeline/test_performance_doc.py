"""docs/performance.md is what ``benchmarks/performance_table.py`` writes from a run: the same tables, jobs and levels.

The timings differ from run to run (the machine's load), so the committed document is compared with one written from
the session's pipeline build in everything but its numbers.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import ROOT

from vibroadhesion.pipeline.performance import performance_markdown

pytestmark = pytest.mark.pipeline

NUMBER = re.compile(r"\b\d[\d.e+\-]*\b")


def _without_numbers(text: str) -> list[str]:
    """The document's lines with every number replaced by ``#`` and the machine line left out."""
    return [NUMBER.sub("#", line) for line in text.splitlines() if not line.startswith("Machine: ")]


def test_committed_document_has_the_tables_a_run_writes(pipeline_results: Path) -> None:
    written = _without_numbers(performance_markdown(pipeline_results))
    committed = _without_numbers((ROOT / "docs" / "performance.md").read_text(encoding="utf-8"))
    assert sorted(committed) == sorted(written)


def test_jobs_are_ordered_by_cpu_time(pipeline_results: Path) -> None:
    """The jobs table lists the longest CPU time first."""
    text = performance_markdown(pipeline_results).split("## Jobs", 1)[1].split("##", 1)[0]
    cpu = [float(row.split("|")[3]) for row in text.splitlines() if row.startswith("| `")]
    assert len(cpu) >= 10 and cpu == sorted(cpu, reverse=True)
