"""Running reports: parameter files in, HTML, PDF and the results as data out, nothing else.

Everything that can be checked is checked before anything runs: every parameter file (read,
checked and its road assembled, :func:`load_job`), the output folder and the file names in it
(:func:`check_output`) and, for PDFs, the browser.  The reports then run in one Jupyter kernel
shared by all of them (started once, its namespace reset between reports): the template
notebook gets the file's parameters in a cell injected after its ``parameters`` cell, as
papermill does, and its code cells are executed one by one.  Each executed notebook becomes
self-contained HTML without its code (no script or style is fetched from the network), and
Debian's chromium prints that HTML to PDF.  Beside them go ``NAME.json`` and ``NAME.csv``,
the results as data (:mod:`.results_file`).

All work happens in a temporary folder (the kernel's temporary files too); chromium's
profile and temporary files live in a short folder of their own (:func:`short_folder`), so
that its socket paths fit the 108 bytes a Unix socket allows whatever the length of
``TMPDIR``.  The output folder receives the finished files at the very end, each written
beside its final name and renamed.  The temporary folders are removed and the kernel and
chromium are stopped whatever happens: an error, ``KeyboardInterrupt`` (SIGINT) or
:class:`Terminated` (SIGTERM, and SIGHUP when the terminal or ssh session closes, once
:func:`signals_raise` is in force).
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import shutil
import signal
import tempfile
import threading
import time
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .inputs import prepare
from .kernel import Kernel, ReportFailed
from .parameter_file import read_parameter_file
from .parameters import ParameterError, ReportParameters, read_parameters
from .printing import Printer, find_chromium

__all__ = [
    "OutputError",
    "ReportFailed",
    "ReportFiles",
    "ReportJob",
    "Terminated",
    "check_output",
    "find_chromium",
    "load_job",
    "short_folder",
    "signals_raise",
    "write_reports",
]

HERE = Path(__file__).resolve().parent.parent
TEMPLATE = HERE / "templates" / "bridge_report.ipynb"
HTML_TEMPLATES = HERE / "templates"
#: Seconds any one cell of the report may run.
CELL_TIMEOUT = 600.0


class OutputError(ValueError):
    """The output folder or a file name in it cannot be written (checked before running)."""


class Terminated(BaseException):  # noqa: N818 (a signal, like KeyboardInterrupt)
    """SIGTERM or SIGHUP arrived (see :func:`signals_raise`); ``args[0]`` is its name."""

    @property
    def signal_name(self) -> str:
        """``"SIGTERM"`` or ``"SIGHUP"``."""
        return str(self.args[0]) if self.args else "SIGTERM"


#: Signals that end a run, and clean up, as :class:`Terminated` (SIGINT: KeyboardInterrupt).
TERMINATING = tuple(getattr(signal, n) for n in ("SIGTERM", "SIGHUP") if hasattr(signal, n))


@contextlib.contextmanager
def signals_raise() -> Iterator[None]:
    """While in force, SIGTERM and SIGHUP raise :class:`Terminated` (SIGINT raises
    KeyboardInterrupt).

    So ``finally`` blocks run on all three: the kernel and chromium are stopped and the
    temporary folders removed.  SIGHUP is what a closing terminal or ssh session sends.
    Only in the main thread (elsewhere it does nothing).
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def terminate(signum: int, frame: object) -> None:
        raise Terminated(signal.Signals(signum).name)

    previous = {signum: signal.signal(signum, terminate) for signum in TERMINATING}
    previous_int = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
        signal.signal(signal.SIGINT, previous_int)


@contextlib.contextmanager
def _signals_held() -> Iterator[None]:
    """SIGINT, SIGTERM and SIGHUP wait until the block ends (so clean-up is not cut short)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, *TERMINATING})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


#: A folder whose path is at most this long is short enough for chromium's sockets.
SHORT_PATH = 40


def short_folder(work: Path) -> Path:
    """A new folder with a short path for chromium's profile and temporary files.

    Inside ``work`` when its path is short; else in the first of ``/tmp``, ``/var/tmp`` and
    ``/dev/shm`` that can be written (named ``vbi-PID-...``, removed with the run).
    """
    if len(str(work)) <= SHORT_PATH:
        folder = work / "c"
        folder.mkdir()
        return folder
    for base in ("/tmp", "/var/tmp", "/dev/shm"):  # noqa: S108 (a private mkdtemp folder)
        if os.path.isdir(base) and os.access(base, os.W_OK | os.X_OK):
            return Path(tempfile.mkdtemp(prefix=f"vbi-{os.getpid()}-", dir=base))
    folder = work / "c"  # nowhere short: chromium may fail, and says why
    folder.mkdir()
    return folder


# ---------------------------------------------------------------------------- jobs
@dataclass(frozen=True)
class ReportJob:
    """One report to run: its checked parameters, as given, and where they came from.

    Attributes
    ----------
    name
        Stem of the output files (``NAME.html``, ``NAME.pdf``, ``NAME.json``, ``NAME.csv``).
    values
        The parameters as given (what the template receives).
    parameters
        The same, checked (:func:`~vbi_lib.reports.parameters.read_parameters`).
    source
        The parameter file's ``name``, ``sha256`` and ``folder`` (relative profile paths are
        read from there).
    warnings
        Sentences on inputs that look like a slip (the ``warnings`` of
        :class:`~vbi_lib.reports.inputs.ReportInputs`).
    """

    name: str
    values: dict[str, Any]
    parameters: ReportParameters = field(repr=False)
    source: dict[str, str]
    warnings: tuple[str, ...] = ()

    @classmethod
    def from_mapping(
        cls, values: Mapping[str, Any], name: str = "report", base_dir: str | Path = "."
    ) -> ReportJob:
        """A job from parameters given in Python (checked now, road assembled now)."""
        folder = Path(base_dir).resolve()
        parameters = read_parameters(values, base_dir=folder)
        inputs = prepare(parameters)
        return cls(_name(name), dict(values), parameters, {"folder": str(folder)},
                   inputs.warnings)  # fmt: skip


def _name(stem: str) -> str:
    if not stem or stem.startswith(".") or any(c in stem for c in "/\\\0"):
        raise OutputError(f"name={stem!r} cannot name a report file; use letters and digits")
    return stem


def load_job(path: str | Path) -> ReportJob:
    """Read, check and prepare one parameter file (YAML); the report is named after its stem.

    Raises
    ------
    ParameterError
        The file cannot be read, is not YAML, or holds a parameter that cannot be used; the
        message starts with the file's name.
    """
    path = Path(path)
    values, data = read_parameter_file(path)
    try:
        parameters = read_parameters(values, base_dir=path.parent.resolve())
        inputs = prepare(parameters)
    except ParameterError as error:
        raise ParameterError(error.key, error.value, "", message=f"{path}: {error}") from None
    source = {
        "name": path.name,
        "sha256": hashlib.sha256(data).hexdigest(),
        "folder": str(path.parent.resolve()),
    }
    return ReportJob(_name(path.stem), dict(values), parameters, source, inputs.warnings)


# ---------------------------------------------------------------------------- output
@dataclass(frozen=True)
class ReportFiles:
    """The files one report wrote: its HTML, its PDF (unless turned off) and its results as
    data (``NAME.json`` and ``NAME.csv``), and the warnings on its inputs."""

    html: Path
    pdf: Path | None
    json: Path | None = None
    csv: Path | None = None
    warnings: tuple[str, ...] = ()


def check_output(output_dir: str | Path, names: Sequence[str], pdf: bool) -> Path:
    """Check that the reports' files can be written in ``output_dir``; nothing is created.

    Raises
    ------
    OutputError
        The folder is a file, cannot be created or written, a target name is a folder, two
        reports share a name, or a PDF is asked for and chromium is missing.
    """
    folder = Path(output_dir).expanduser()
    if folder.exists() and not folder.is_dir():
        raise OutputError(f"--output-dir={str(output_dir)!r} is a file; give a folder")
    existing = folder
    while not existing.exists():
        existing = existing.parent
    if not existing.is_dir() or not os.access(existing, os.W_OK | os.X_OK):
        raise OutputError(f"--output-dir={str(output_dir)!r} cannot be written ({existing})")
    seen: set[str] = set()
    for name in names:
        if name in seen:
            raise OutputError(
                f"two parameter files are named {name!r}: their reports would overwrite each "
                "other; rename one"
            )
        seen.add(name)
        for suffix in (".html", ".json", ".csv", ".pdf") if pdf else (".html", ".json", ".csv"):
            target = folder / f"{name}{suffix}"
            if target.is_dir():
                raise OutputError(f"{target} is a folder; the report cannot be written there")
    if pdf and find_chromium() is None:
        raise OutputError(
            "printing the PDF needs Debian's chromium (apt-get install -y chromium) or "
            "VBI_CHROMIUM naming it; install it, or ask for HTML only (--no-pdf)"
        )
    return folder


def _execute(kernel: Kernel, job: ReportJob, timeout: float) -> Any:
    """The template run with ``job``'s parameters, as an executed notebook."""
    from papermill.iorw import load_notebook_node
    from papermill.parameterize import parameterize_notebook

    notebook = load_notebook_node(str(TEMPLATE))
    results = str(work_out(kernel) / f"{job.name}.json")
    parameters = {**job.values, "source": job.source, "results_file": results}
    notebook = parameterize_notebook(notebook, parameters, kernel_name="python3", language="python")
    kernel.run("%reset -f", timeout)
    for index, cell in enumerate(notebook.cells):
        if cell.cell_type != "code":
            continue
        try:
            cell.outputs = kernel.run(cell.source, timeout)
        except ReportFailed as error:
            raise ReportFailed(f"{job.source.get('name', job.name)}: {error}") from None
        cell.execution_count = index
    return notebook


def work_out(kernel: Kernel) -> Path:
    """The run's folder of finished files (beside the kernel's work folder)."""
    return kernel.work / "out"


def _html(notebook: Any, job: ReportJob) -> str:
    from nbconvert import HTMLExporter

    exporter = HTMLExporter(
        extra_template_basedirs=[str(HTML_TEMPLATES)],
        template_name="report_html",
        exclude_input=True,
        exclude_input_prompt=True,
        exclude_output_prompt=True,
    )
    page = "letter" if job.parameters.units == "US" else "A4"
    html, _ = exporter.from_notebook_node(
        notebook, resources={"metadata": {"name": job.parameters.title}, "vbi_page_size": page}
    )
    return html


def _commit(files: list[tuple[Path, Path]], folder: Path) -> None:
    """Move finished files into ``folder``: all written beside their names, then renamed."""
    made = [] if folder.exists() else [folder]
    folder.mkdir(parents=True, exist_ok=True)
    staged: list[tuple[str, Path]] = []
    try:
        for source, target in files:
            handle, partial = tempfile.mkstemp(prefix=f".{target.name}.", dir=folder)
            os.close(handle)
            staged.append((partial, target))
            shutil.copyfile(source, partial)
            os.chmod(partial, 0o644)
        for partial, target in staged:
            os.replace(partial, target)
        staged.clear()
    finally:
        for partial, _ in staged:
            with contextlib.suppress(OSError):
                os.unlink(partial)
        if staged:
            for directory in made:
                with contextlib.suppress(OSError):
                    directory.rmdir()


def write_reports(
    sources: Sequence[str | Path | ReportJob],
    output_dir: str | Path,
    *,
    pdf: bool = True,
    timeout: float = CELL_TIMEOUT,
) -> list[ReportFiles]:
    """Run reports through one kernel and write ``NAME.html`` (and ``NAME.pdf``) for each.

    Parameters
    ----------
    sources
        Parameter files (YAML), or jobs made with :meth:`ReportJob.from_mapping`.
    output_dir
        Folder of the reports (created if missing).
    pdf
        Also print each report to PDF with chromium.
    timeout
        Seconds any one cell may run.

    Returns
    -------
    list of ReportFiles
        In the order of ``sources``: ``NAME.html``, ``NAME.pdf``, ``NAME.json`` and
        ``NAME.csv`` in ``output_dir``.

    Raises
    ------
    ParameterError
        A parameter file that cannot be used (nothing has run).
    OutputError
        The output cannot be written (nothing has run).
    ReportFailed
        A report failed while running; nothing is written.
    """
    work = Path(tempfile.mkdtemp(prefix="vbi-report-"))
    kernel = None
    printers: list[Printer] = []
    short: Path | None = None
    try:
        (work / "tmp").mkdir()
        (work / "out").mkdir()
        names = [s.name if isinstance(s, ReportJob) else _name(Path(s).stem) for s in sources]
        folder = check_output(output_dir, names, pdf)
        jobs = [s if isinstance(s, ReportJob) else load_job(s) for s in sources]
        kernel = Kernel(work)
        kernel.start()
        threading.Thread(target=_preload, daemon=True).start()
        if pdf:
            short = short_folder(work)
        kernel.ready()
        files: list[tuple[Path, Path]] = []
        results = []
        for job in jobs:
            notebook = _execute(kernel, job, timeout)
            html = work / "out" / f"{job.name}.html"
            html.write_text(_html(notebook, job), encoding="utf-8")
            files.append((html, folder / html.name))
            data = [work / "out" / f"{job.name}{suffix}" for suffix in (".json", ".csv")]
            for made in data:
                if not made.is_file():
                    raise ReportFailed(f"{job.name}: the report wrote no {made.name}")
                files.append((made, folder / made.name))
            target_pdf = None
            if pdf:
                printers.append(Printer(html, html.with_suffix(".pdf"), short))
                target_pdf = folder / f"{job.name}.pdf"
                files.append((html.with_suffix(".pdf"), target_pdf))
            results.append(ReportFiles(folder / html.name, target_pdf, folder / data[0].name,
                                       folder / data[1].name, job.warnings))  # fmt: skip
        kernel.stop()
        kernel = None
        for printer in printers:
            printer.wait()
        _commit(files, folder)
        return results
    finally:
        with _signals_held():
            for printer in printers:
                printer.stop()
            if kernel is not None:
                kernel.stop()
            for folder_ in (work, short):
                if folder_ is not None:
                    shutil.rmtree(folder_, ignore_errors=True)
                    _wait_gone(folder_)


def _preload() -> None:
    """Import what writing the HTML needs while the kernel works (the GIL is free then)."""
    with contextlib.suppress(Exception):
        import nbconvert  # noqa: F401
        import papermill.parameterize  # noqa: F401


def _wait_gone(work: Path) -> None:
    """Remove ``work`` again if a process still writing there re-created files (rare)."""
    for _ in range(20):
        if not work.exists():
            return
        time.sleep(0.05)
        shutil.rmtree(work, ignore_errors=True)
