"""Report rendering: the pages of one index share a kernel, yet each starts from a fresh namespace.

Checked on small notebooks written here, executed in a real kernel (a few seconds), and on the built report: each
page rendered again is the same file.
"""

import ast
import re
from pathlib import Path

import nbformat
import pytest
from papermill.exceptions import PapermillExecutionError

from vibroadhesion.pipeline.pages import PAGES, VALIDATION_PAGES
from vibroadhesion.pipeline.steps.report import INJECTED, RUN_RECORD, Page, render_page, reset_namespace, shared_kernel


def _notebook(path: Path, *sources: str) -> Path:
    """A notebook with a ``parameters`` cell (``value = 0``) followed by code cells ``sources``."""
    nb = nbformat.v4.new_notebook()
    parameters = nbformat.v4.new_code_cell("value = 0")
    parameters.metadata["tags"] = ["parameters"]
    nb.cells = [parameters, *(nbformat.v4.new_code_cell(s) for s in sources)]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, path)
    return path


def _page(tmp_path: Path, stem: str, *sources: str, value: str = "1") -> Page:
    notebook = _notebook(tmp_path / f"{stem}.ipynb", *sources)
    return Page(notebook, tmp_path / f"{stem}.executed.ipynb", tmp_path / f"{stem}.html", {"value": value})


def test_a_page_cannot_read_what_an_earlier_page_of_the_same_kernel_defined(tmp_path: Path) -> None:
    first = _page(tmp_path, "first", "leaked = int(value) + 1", "print(leaked)")
    second = _page(tmp_path, "second", "print(leaked)")
    with shared_kernel() as manager:
        reset_namespace(manager)
        render_page(first, manager)
        reset_namespace(manager)
        with pytest.raises(PapermillExecutionError, match="NameError"):
            render_page(second, manager)
    printed = nbformat.read(first.executed, as_version=4).cells[-1].outputs[0]["text"]
    assert printed == "2\n"  # value = 1 injected, leaked = 2


def test_pages_in_a_shared_kernel_equal_pages_in_kernels_of_their_own(tmp_path: Path) -> None:
    """Same executed cells, outputs and execution counts (1, 2, ...), and the same HTML bytes."""
    pages = [_page(tmp_path, stem, "import math", "math.sqrt(float(value))", value=v) for stem, v in (("a", "4"), ("b", "9"))]
    with shared_kernel() as manager:
        for page in pages:
            reset_namespace(manager)
            render_page(page, manager)
    shared = [(p.html.read_bytes(), nbformat.read(p.executed, as_version=4)) for p in pages]
    for page, (html, nb) in zip(pages, shared, strict=True):
        with shared_kernel() as manager:
            render_page(page, manager)
        alone = nbformat.read(page.executed, as_version=4)
        assert page.html.read_bytes() == html
        assert [c.get("execution_count") for c in nb.cells] == [c.get("execution_count") for c in alone.cells]
        assert [c.get("outputs") for c in nb.cells] == [c.get("outputs") for c in alone.cells]
    assert [c.execution_count for c in shared[1][1].cells] == [1, 2, 3, 4]
    assert shared[1][1].cells[-1].outputs[0]["data"]["text/plain"] == "3.0"


def test_a_page_rendered_twice_gives_the_same_bytes_and_the_kernel_no_warning(
        tmp_path: Path, capfd: pytest.CaptureFixture[str]) -> None:
    """Same inputs, same bytes: the executed notebook records no time and no temporary path (papermill's start and end
    times, durations and output path; nbclient's execution times) and a table's plain-text form no memory address,
    so a page rendered twice is the same notebook and the same HTML file; the kernel runs over IPC, so ipykernel
    prints no warning about unencrypted TCP."""
    page = _page(tmp_path, "twice", "import pandas as pd", "pd.DataFrame({'x': [1.5]}).style.set_uuid('t')")
    renders = []
    for _ in range(2):
        with shared_kernel() as manager:
            reset_namespace(manager)
            render_page(page, manager)
        renders.append((page.executed.read_bytes(), page.html.read_bytes()))
    assert renders[0] == renders[1]
    nb = nbformat.read(page.executed, as_version=4)
    recorded = [nb.metadata["papermill"], *(cell.metadata.get("papermill", {}) for cell in nb.cells)]
    assert not [key for metadata in recorded for key in metadata if key in RUN_RECORD]
    assert not [cell.metadata["execution"] for cell in nb.cells if "execution" in cell.metadata]
    assert nb.metadata["papermill"]["input_path"] == str(page.notebook)  # what stays: the source and the parameters
    assert nb.metadata["papermill"]["parameters"] == {"value": "1"}
    assert nb.cells[-1].outputs[0]["data"]["text/plain"] == "     x\n0  1.5"  # the Styler's data as text
    output = capfd.readouterr()
    assert "without encryption" not in output.err + output.out, output.err[-2000:]


def test_a_page_shows_outputs_and_no_code(tmp_path: Path) -> None:
    """Readers see what a cell prints, not the cell: no source, no In/Out prompts; the executed notebook keeps both."""
    page = _page(tmp_path, "shown", "marker_variable = 6 * 7", "print(marker_variable)")
    with shared_kernel() as manager:
        reset_namespace(manager)
        render_page(page, manager)
    html = page.html.read_text(encoding="utf-8")
    assert "42" in html
    assert "marker_variable" not in html and "In&nbsp;[" not in html
    assert "marker_variable" in page.executed.read_text(encoding="utf-8")



def test_a_page_has_its_title_and_a_link_back_to_its_index(tmp_path: Path) -> None:
    """The title of pipeline.pages (not the notebook's file name) and a link to the index that lists the page."""
    page = _page(tmp_path, "identifiability", "print(6 * 7)")
    with shared_kernel() as manager:
        render_page(page, manager)
    html = page.html.read_text(encoding="utf-8")
    title = dict(VALIDATION_PAGES)["identifiability"]
    assert f"<title>Vibroadhesion: {title}</title>" in html.replace("&amp;", "&")
    assert '<a href="validation_index.html">&larr; back to the report index</a>' in html
    assert html.index("back to the report index") < html.index("<pre>42")
    assert re.findall(r"<script[^>]*src=\"http[^\"]*\"", html) == [] and "cdnjs" not in html  # offline: nothing fetched


def _recorded_parameters(executed: Path) -> dict[str, str]:
    """The papermill parameters an executed notebook records in its injected cell (``name = "value"`` lines)."""
    (cell,) = [c for c in nbformat.read(executed, as_version=4).cells if c.get("id") == INJECTED]
    return {node.targets[0].id: ast.literal_eval(node.value) for node in ast.parse(cell.source).body
            if isinstance(node, ast.Assign)}


def test_every_built_page_renders_again_to_the_same_bytes(pipeline_results: Path, tmp_path: Path,
                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    """Same inputs, same bytes: each page of the built report, rendered again from the artefacts its executed
    notebook names, is the same HTML file and the same executed notebook. Catches a random id in a page, such as the
    uuid a pandas Styler draws for its table unless given one (the identifiability page's design and
    excluded-candidates tables did), and a memory address in a table's plain-text form."""
    monkeypatch.chdir(pipeline_results.parent)  # the artefact paths are relative to the repository copy
    built = sorted((pipeline_results / "report" / "notebooks").glob("*.ipynb"))
    assert {p.stem for p in built} == {stem for stem, _ in PAGES + VALIDATION_PAGES}
    pages = [Page(Path("notebooks") / p.name, tmp_path / p.name, tmp_path / f"{p.stem}.html", _recorded_parameters(p))
             for p in built]
    with shared_kernel() as manager:
        for page in pages:
            reset_namespace(manager)
            render_page(page, manager)
    for page in pages:
        assert page.html.read_bytes() == (pipeline_results / "report" / page.html.name).read_bytes(), page.html.name
        assert page.executed.read_bytes() == (pipeline_results / "report" / "notebooks" / page.executed.name
                                              ).read_bytes(), page.executed.name
