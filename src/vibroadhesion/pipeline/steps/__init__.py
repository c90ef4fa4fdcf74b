"""The steps the Snakemake rules run, one small module per area, each importing only what it needs.

A rule runs ``workflow/scripts/<rule>.py`` through Snakemake's ``script:`` directive; that adapter
calls one function of a module here inside :func:`logged`, with the rule's input, output, params
and wildcards. Each rule's code dependency is the import closure of its adapter
(:mod:`vibroadhesion.pipeline.imports`), so a module that a step does not import cannot rerun it.
Plot steps alone import matplotlib (:mod:`vibroadhesion.pipeline.figures`).
"""

from __future__ import annotations

import sys
import traceback
from collections.abc import Iterator
from contextlib import contextmanager, redirect_stderr, redirect_stdout
from pathlib import Path

#: Failures a step reports in one line: bad data (``ValueError``, e.g. ``DataError``), no root or
#: no continuation (``ArithmeticError``), a failed fit (``RuntimeError``, e.g. ``FitError``).
EXPECTED_FAILURES = (ValueError, ArithmeticError, RuntimeError)


@contextmanager
def logged(log: str | Path, step: str) -> Iterator[None]:
    """Send the step's output to ``log``.

    On an expected failure write one line to the log and to the terminal (``error: <step>: <message>``) and exit
    with status 1. Any other exception (a bug) goes to the log with its traceback and propagates (Python prints it
    on the terminal too).

    The writers are atomic (:mod:`vibroadhesion.pipeline.artefacts`), so a failed step leaves no
    partial output; Snakemake removes the complete outputs of a failed job.
    """
    with open(log, "w", encoding="utf-8") as stream, redirect_stdout(stream), redirect_stderr(stream):
        try:
            yield
        except EXPECTED_FAILURES as exc:
            line = f"error: {step}: {exc}"
            print(line, file=stream)
            print(line, file=sys.__stderr__)
            raise SystemExit(1) from None
        except Exception:
            traceback.print_exc(file=stream)
            raise
