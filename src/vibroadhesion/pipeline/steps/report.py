"""Step of the report rules: the pages of one index, rendered in one process with one kernel.

Each page is a notebook executed by papermill and exported to HTML by nbconvert. Starting a Jupyter
kernel, and importing pandas and matplotlib in it, costs about as much as executing a page, so the
pages of one index share a kernel: before each page its namespace is reset to that of a fresh kernel
(``InteractiveShell.reset(new_session=True)``: user variables gone, execution count back to 1), so
a page cannot read what an earlier one defined and its executed notebook is the same as in a kernel
of its own. Modules imported by an earlier page stay imported, as in any Python session.

Same inputs, same bytes: the executed notebooks carry no time of the run and no path of its temporary files
(:func:`without_run_record`), and the kernel talks to this process over IPC sockets in a private temporary
directory, not over TCP (for which ipykernel warns, on every start, that the traffic is not encrypted).
"""

from __future__ import annotations

import re
import tempfile
import time
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import nbconvert
import nbformat
import papermill
from jupyter_client.manager import KernelManager

from vibroadhesion.pipeline.atomic import atomic_path
from vibroadhesion.pipeline.pages import index_artefacts, page_title_and_index, write_index

#: The tag (and, here, the cell id) of the cell in which papermill injects a page's parameters.
INJECTED = "injected-parameters"

#: nbconvert templates of the pages: ``offline`` is JupyterLab's page without the scripts it fetches from a CDN.
TEMPLATES = Path(__file__).resolve().parents[1] / "templates"

#: The keys of papermill's metadata, of the notebook and of each cell, that record when the run happened or where it
#: wrote its temporary file (:func:`without_run_record`).
RUN_RECORD = ("start_time", "end_time", "duration", "output_path")

#: The code that gives a running IPython kernel the namespace of a fresh one.
RESET = "get_ipython().reset(new_session=True, aggressive=False)"

#: Run once in each kernel (:func:`shared_kernel`): the plain-text form a pandas Styler gets beside its HTML table in
#: the executed notebook is the text of its data (IPython's ``for_type_by_name``), not Python's default repr, whose
#: memory address differs from run to run. The namespace reset keeps the kernel's display formatters.
STYLER_TEXT = """\
def _styler_text(styler, printer, cycle):
    printer.text(styler.data.to_string())
get_ipython().display_formatter.formatters["text/plain"].for_type_by_name(
    "pandas.io.formats.style", "Styler", _styler_text)
del _styler_text
"""


@dataclass(frozen=True)
class Page:
    """One report page: the notebook, where its executed copy and its HTML go, and its papermill parameters."""

    notebook: Path
    executed: Path
    html: Path
    parameters: Mapping[str, str]


@contextmanager
def shared_kernel(timeout: float = 60.0) -> Iterator[KernelManager]:
    """A python3 kernel started in the working directory, shut down on exit.

    Its channels are IPC sockets (jupyter_client's ``transport = "ipc"``) named by ``ip`` in a temporary directory
    of this process: no TCP port is opened, and two report jobs started side by side cannot pick the same socket.
    Its display formatters give pandas Stylers a plain-text form without a memory address (:data:`STYLER_TEXT`).
    """
    with tempfile.TemporaryDirectory(prefix="kernel-") as sockets:
        manager = KernelManager(kernel_name="python3", transport="ipc", ip=str(Path(sockets) / "ipc"))
        manager.start_kernel(cwd=".")
        try:
            client = manager.client()
            client.start_channels()
            client.wait_for_ready(timeout=timeout)
            client.stop_channels()
            run_silently(manager, STYLER_TEXT, timeout)
            yield manager
        finally:
            manager.shutdown_kernel(now=True)


def reset_namespace(manager: KernelManager, timeout: float = 60.0) -> None:
    """Give the kernel of ``manager`` the namespace of a fresh kernel (:data:`RESET`), or raise RuntimeError."""
    run_silently(manager, RESET, timeout)


def run_silently(manager: KernelManager, code: str, timeout: float = 60.0) -> None:
    """Run ``code`` in the kernel of ``manager`` outside the history and execution count, or raise RuntimeError."""
    client = manager.client()
    client.start_channels()
    try:
        client.execute(code, silent=True, store_history=False)
        reply = client.get_shell_msg(timeout=timeout)
    finally:
        client.stop_channels()
    if reply["content"]["status"] != "ok":
        raise RuntimeError(f"kernel code failed: {reply['content'].get('evalue', reply['content']['status'])}")


def render_page(page: Page, manager: KernelManager, exporter: nbconvert.HTMLExporter | None = None) -> None:
    """Execute ``page.notebook`` in the kernel of ``manager`` and write the executed notebook and its HTML page.

    The page shows the outputs only (text, tables, figures): the code stays in the notebook, which remains the
    source and stays executable; the executed notebook keeps both.

    ``page.parameters`` (artefact paths) are injected after the notebook's ``parameters`` cell, in a cell
    whose id papermill draws at random: it is given a fixed one, so that the same inputs give the same page. The
    executed notebook is written once, when it is complete (papermill's save after every cell went to a temporary
    file that a failure deletes anyway: 0.2-0.3 s a job). The
    page carries its title (:data:`~vibroadhesion.pipeline.pages.PAGES`) and a link back to its index, and loads
    nothing from the network (template ``offline``: no MathJax, no require.js; the pages have no math or widgets).
    ``exporter`` (:func:`html_exporter`) may be shared by the pages of a job: its templates load once. The executed
    notebook records no time and no temporary path (nbclient's ``record_timing`` off, :func:`without_run_record`).
    """
    with atomic_path(page.executed) as tmp:
        nb = papermill.execute_notebook(str(page.notebook), str(tmp), parameters=dict(page.parameters),
                                        kernel_name="python3", cwd=".", progress_bar=False, km=manager,
                                        request_save_on_cell_execute=False, record_timing=False)
        without_run_record(nb)
        for cell in nb.cells:
            if INJECTED in cell.metadata.get("tags", ()):
                cell.id = INJECTED
        nbformat.write(nb, tmp)
    title, index = page_title_and_index(page.notebook.stem)
    resources = {"metadata": {"name": f"Vibroadhesion: {title}"}}
    body, _ = (exporter or html_exporter()).from_notebook_node(nb, resources=resources)
    with atomic_path(page.html) as tmp:
        tmp.write_text(with_index_link(body, index), encoding="utf-8")


def without_run_record(nb: nbformat.NotebookNode) -> None:
    """Remove from the executed notebook ``nb`` what differs between two runs of the same page.

    That is the times and the temporary output path papermill records in its metadata of the notebook and of each
    cell (:data:`RUN_RECORD`). Its parameters, input path, cell statuses and any exception stay.
    """
    for metadata in (nb.metadata, *(cell.metadata for cell in nb.cells)):
        for key in RUN_RECORD:
            metadata.get("papermill", {}).pop(key, None)


def html_exporter() -> nbconvert.HTMLExporter:
    """The exporter of the pages: outputs only, template ``offline``."""
    return nbconvert.HTMLExporter(exclude_input=True, exclude_input_prompt=True, exclude_output_prompt=True,
                                  template_name="offline", extra_template_basedirs=[str(TEMPLATES)])


def with_index_link(body: str, index: str) -> str:
    """The HTML page ``body`` with a link back to its index (``index.html`` or ``validation_index.html``) at the top."""
    link = f'<p style="margin: 1em 2em"><a href="{index}.html">&larr; back to the report index</a></p>'
    return re.sub(r"(<body[^>]*>)", lambda match: match.group(1) + link, body, count=1)


def render(parameters: Mapping[str, Mapping[str, str]], executed: Sequence[str | Path], html: Sequence[str | Path],
           indexes: Sequence[str | Path] = ()) -> None:
    """Render pages in one kernel, each from a fresh namespace, then write the index pages named in ``indexes``.

    ``parameters`` maps each page (the stem of ``notebooks/<page>.ipynb``) to its papermill parameters, in the
    order of ``executed`` and ``html``, the paths of its executed notebook and of its HTML page. The findings on an
    index come from the artefacts its pages read (:func:`vibroadhesion.pipeline.front_page.findings`).
    """
    if not len(parameters) == len(executed) == len(html):
        raise ValueError(f"{len(parameters)} pages, {len(executed)} executed notebooks, {len(html)} HTML pages")
    pages = [Page(Path(f"notebooks/{stem}.ipynb"), Path(nb), Path(page), values)
             for (stem, values), nb, page in zip(parameters.items(), executed, html, strict=True)]
    exporter = html_exporter()
    with shared_kernel() as manager:
        for page in pages:
            reset_namespace(manager)
            render_page(page, manager, exporter)
    if indexes:  # the findings' imports (pandas, the refined model) only in the job that writes an index
        from vibroadhesion.pipeline.front_page import findings

        for index in indexes:
            as_of = time.time_ns()  # before the findings read the artefacts (pages.findings_outdated)
            write_index(index, findings=findings(index_artefacts(parameters)), as_of_ns=as_of)
