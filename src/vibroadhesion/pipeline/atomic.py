"""Atomic output files: write beside the target, move into place only when the writing succeeded.

The one implementation behind every writer of the pipeline (:mod:`vibroadhesion.pipeline.artefacts`
for results, :mod:`vibroadhesion.pipeline.data` for the canonical inputs). It imports the standard
library only, so a step that writes no figure does not pay for matplotlib.

Permissions: the temporary file is created by ``os.open(name, O_CREAT | O_EXCL, 0o666)``, so the
kernel applies the process umask at creation, exactly as for any file the user creates (Python's
``open(path, "w")`` asks for 0o666 too): the output gets mode ``0o666 & ~umask`` and a folder's
default ACL applies as usual. ``tempfile.mkstemp`` would create it 0o600, and restoring the mode
afterwards needs the umask, which a process can only read by setting it (``os.umask`` twice): a
window in which a file created by another thread gets the wrong mode, or, read once at import, a
value that misses a later change of the umask. Letting the kernel apply the umask needs neither.
"""

from __future__ import annotations

import errno
import os
import secrets
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

_CREATE_NEW = os.O_WRONLY | os.O_CREAT | os.O_EXCL


def create_beside(path: Path) -> Path:
    """Create a new empty file with a fresh hidden name in ``path``'s folder and return its path.

    The name is ``.<name>.<random hex><suffix>`` (the suffix kept for writers that infer the
    format from it); its mode is ``0o666 & ~umask``. ``O_EXCL`` makes the creation fail rather
    than reuse or follow an existing name, and another name is drawn, as ``tempfile`` does.
    """
    for _ in range(tempfile.TMP_MAX):
        candidate = path.with_name(f".{path.name}.{secrets.token_hex(4)}{path.suffix}")
        try:
            os.close(os.open(candidate, _CREATE_NEW, 0o666))
        except FileExistsError:
            continue
        return candidate
    raise FileExistsError(errno.EEXIST, "no unused temporary name", str(path.parent))


@contextmanager
def atomic_path(path: str | Path) -> Iterator[Path]:
    """Yield a new empty file beside ``path``; move it onto ``path`` only if the block succeeds.

    The folder is created if missing. On an exception in the block (or a failed move) the
    temporary file is removed and ``path`` is left as it was.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = create_beside(path)
    try:
        yield tmp
        os.replace(tmp, path)
    finally:
        tmp.unlink(missing_ok=True)
