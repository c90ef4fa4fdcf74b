"""Step of rule report_site: the rendered report as one folder, for Snakemake's report (``snakemake --report``).

Snakemake packs a folder marked ``report(directory(...), htmlindex=...)`` into its zip with every file at its
path relative to the index, so the links of the pages resolve there; a page marked on its own lands in a folder of
its own, away from the pages and figures it links. The folder holds the pages of results/report/ and the figures
their index shows as thumbnails, at their paths under results/, so the pages keep their links.

An index's job may run before the artefacts of another target it reports on (the figure index before the
validation); the Snakefile's onsuccess reads its findings again at the end of the run
(:func:`vibroadhesion.pipeline.front_page.refresh_findings`). This step, which runs after every report job, reads
them again in its copies of the indexes in the same way, and their links to the pages beside them, so the folder
shows what the run built.
"""

from __future__ import annotations

import shutil
from collections.abc import Iterable, Mapping
from pathlib import Path

from vibroadhesion.pipeline.pages import refresh_indexes


def report_site(files: Iterable[str | Path], out: str | Path, indexes: Mapping[str, Mapping[str, Mapping[str, str]]],
                root: str | Path = "results") -> None:
    """Copy ``files`` (paths under ``root``) into the new folder ``out``, and read the findings of its indexes again.

    Each file goes to its path relative to ``root``. ``indexes`` maps each index (a path under ``root``) to the
    papermill parameters of its pages, as :func:`~vibroadhesion.pipeline.front_page.refresh_findings` takes them.
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
    if indexes:  # the findings' imports (pandas, the refined model) only where there are indexes
        from vibroadhesion.pipeline.front_page import refresh_findings

        copies = {Path(out) / Path(index).relative_to(root): pages for index, pages in indexes.items()}
        refresh_findings({str(copy): pages for copy, pages in copies.items()})
        for copy in copies:  # the links that depend on which pages exist beside the index (all of them, here)
            refresh_indexes({}, copy.parent, [copy.stem])
