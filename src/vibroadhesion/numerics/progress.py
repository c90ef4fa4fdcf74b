"""Progress of the long rules, written to their logs: a text bar per finished item, or a heartbeat line.

A Snakemake log is a file, not a terminal, so the bar is redrawn on a new line for each finished
item (no carriage returns) and flushed at once: ``tail -f`` on the log, or the log of a cluster
job, shows how far the job is, how many periodic steady states it has solved and the time so far.
A search whose number of steps is not known beforehand (a least-squares fit) beats a
:class:`Heartbeat` instead: a line at most every few seconds, saying where it is.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
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


class Heartbeat:
    """``<label>: 12 s  <note>``, printed by :meth:`beat` when ``interval`` seconds passed since the last line."""

    def __init__(self, label: str, interval: float = 10.0, *, stream: TextIO | None = None,
                 clock: Callable[[], float] = time.perf_counter) -> None:
        """A heartbeat named ``label`` on ``stream`` (stdout when None), its clock started now."""
        self.label, self.interval = label, interval
        self._stream, self._clock = stream, clock
        self._start = self._last = clock()

    def beat(self, note: str) -> None:
        """Print ``note`` with the time so far if ``interval`` seconds passed since the last printed line."""
        now = self._clock()
        if now - self._last >= self.interval:
            self._last = now
            print(f"{self.label}: {now - self._start:.0f} s  {note}", file=self._stream or sys.stdout, flush=True)
