"""Progress of the long validation rules, written to their logs as one text bar per finished item.

A Snakemake log is a file, not a terminal, so the bar is redrawn on a new line for each finished
item (no carriage returns) and flushed at once: ``tail -f`` on the log, or the log of a cluster
job, shows how far the job is, how many periodic steady states it has solved and the time so far.
"""

from __future__ import annotations

import sys
import time
from typing import TextIO

BAR_WIDTH = 30


class ProgressBar:
    """``[#########.....................]  3/10 items  57 steady states  12.3 s  <note>``."""

    def __init__(self, total: int, unit: str, *, stream: TextIO | None = None) -> None:
        """A bar for ``total`` items of ``unit``, printed on ``stream`` (stdout when None), its clock started now."""
        if total < 1:
            raise ValueError(f"a progress bar needs at least one item, got total = {total}")
        self.total, self.unit = total, unit
        self.done = 0
        self.steady_states = 0
        self._stream = stream
        self._start = time.perf_counter()

    def advance(self, steady_states: int, note: str = "") -> None:
        """One item finished, having solved ``steady_states`` periodic steady states; redraw the bar."""
        self.done += 1
        self.steady_states += steady_states
        filled = round(BAR_WIDTH * self.done / self.total)
        line = (f"[{'#' * filled}{'.' * (BAR_WIDTH - filled)}] {self.done:>{len(str(self.total))}}/{self.total} "
                f"{self.unit}  {self.steady_states} steady states  {time.perf_counter() - self._start:.1f} s")
        print(f"{line}  {note}" if note else line, file=self._stream or sys.stdout, flush=True)
