"""Printing a report's HTML to PDF with Debian's chromium, headless, in the background.

Chromium runs with switches that fetch nothing and skip first-run work, with its profile and
temporary files in a short folder of the run's and in its own session, so it can be killed
whole.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import signal
import subprocess
import tempfile
from pathlib import Path

from .kernel import ReportFailed

__all__ = ["CHROMIUM_ARGS", "PRINT_TIMEOUT", "Printer", "find_chromium"]

#: Seconds chromium may take to print one report.
PRINT_TIMEOUT = 120.0
#: Chromium's switches: headless, no sandbox (containers), nothing fetched, no first-run work.
CHROMIUM_ARGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--disable-default-apps",
    "--no-default-browser-check",
    "--mute-audio",
    "--no-pdf-header-footer",
)


def find_chromium() -> str | None:
    """Debian's chromium (``VBI_CHROMIUM`` overrides the path), or ``None``."""
    return os.environ.get("VBI_CHROMIUM") or shutil.which("chromium")


class Printer:
    """Chromium printing one report's HTML to PDF, in the background (its own profile folder).

    ``folder`` holds chromium's profile and temporary files; its path must be short (the
    Unix sockets chromium makes there allow 108 bytes; see
    :func:`vbi_lib.reports.running.short_folder`).  Printing one report overlaps with the
    kernel running the next; :meth:`wait` collects it.
    """

    def __init__(self, html: Path, pdf: Path, folder: Path) -> None:
        self.html, self.pdf = html, pdf
        own = Path(tempfile.mkdtemp(prefix="p", dir=folder))
        (own / "t").mkdir()
        command = [
            find_chromium() or "chromium",
            *CHROMIUM_ARGS,
            f"--user-data-dir={own / 'u'}",
            f"--print-to-pdf={pdf}",
            html.as_uri(),
        ]
        self.errors = open(own / "log", "wb")  # noqa: SIM115
        self.process = subprocess.Popen(
            command,
            stdout=subprocess.DEVNULL,
            stderr=self.errors,
            env=dict(os.environ, TMPDIR=str(own / "t")),
            start_new_session=True,
        )

    def wait(self, timeout: float = PRINT_TIMEOUT) -> None:
        """Wait for the PDF; ``ReportFailed`` if chromium fails or takes too long."""
        try:
            self.process.wait(timeout)
        except subprocess.TimeoutExpired:
            raise ReportFailed(
                f"chromium did not print {self.html.name} in {timeout:.0f} s"
            ) from None
        finally:
            self.stop()
        if self.process.returncode != 0 or not self.pdf.is_file() or not self.pdf.stat().st_size:
            log = Path(self.errors.name).read_text(errors="replace").splitlines()
            lines = [line for line in log if line.strip()]
            detail = lines[-1] if lines else f"exit status {self.process.returncode}"
            raise ReportFailed(f"chromium could not print {self.html.name} to PDF: {detail}")

    def stop(self) -> None:
        """Kill chromium (all its processes) if it still runs."""
        if self.process.poll() is None:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(self.process.pid, signal.SIGKILL)
            self.process.wait()
        self.errors.close()
