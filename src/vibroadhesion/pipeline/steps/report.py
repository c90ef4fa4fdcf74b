"""Steps of the report rules.

One page (notebook executed by papermill, exported to HTML by nbconvert, in one process) and the index of a target's
pages.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import nbconvert
import papermill

from vibroadhesion.pipeline.atomic import atomic_path


def page(notebook: str | Path, executed: str | Path, html: str | Path, parameters: Mapping[str, str]) -> None:
    """Execute ``notebook`` and write the executed notebook and its HTML page.

    ``parameters`` (artefact paths) are injected after the notebook's ``parameters`` cell; the
    kernel is a fresh one, run from the working directory.
    """
    with atomic_path(executed) as tmp:
        nb = papermill.execute_notebook(str(notebook), str(tmp), parameters=dict(parameters), kernel_name="python3",
                                        cwd=".", progress_bar=False)
    body, _ = nbconvert.HTMLExporter().from_notebook_node(nb)
    with atomic_path(html) as tmp:
        tmp.write_text(body, encoding="utf-8")
