"""Step of rule report_site: the rendered report as one folder, for Snakemake's report (``snakemake --report``).

Snakemake packs a folder marked ``report(directory(...), htmlindex=...)`` into its zip with every file at its
path relative to the index, so the links of the pages resolve there; a page marked on its own lands in a folder of
its own, away from the pages and figures it links. The folder holds the pages of results/report/ and the figures
their index shows as thumbnails, at their paths under results/, so the pages keep their bytes and their links.
"""

from __future__ import annotations

import shutil
from collections.abc import Iterable
from pathlib import Path


def report_site(files: Iterable[str | Path], out: str | Path, root: str | Path = "results") -> None:
    """Copy ``files`` (paths under ``root``) into the new folder ``out``, each at its path relative to ``root``.

    Raises ValueError, before anything is written, for a file outside ``root``.
    """
    sources = [Path(f) for f in files]
    outside = [str(f) for f in sources if not f.resolve().is_relative_to(Path(root).resolve())]
    if outside:
        raise ValueError(f"report site: files outside {root}: {', '.join(outside)}")
    for source in sources:
        target = Path(out) / source.resolve().relative_to(Path(root).resolve())
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, target)
