"""The Jupyter kernel the reports of one run share, and how a cell's outputs are kept.

One IPython kernel is started in the run's temporary folder (its connection file and
``TMPDIR`` there, its own session so that a terminal's Ctrl-C reaches only the runner), warmed
up at once (imports, compiled code, fonts) and stopped, killed if need be, whatever happens.
Cells are executed with the kernel client's ``execute_interactive``: outputs are kept as
notebook outputs, stderr is left out of the report, an error stops the report.
"""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
from pathlib import Path

__all__ = ["WARM_UP", "Kernel", "ReportFailed"]


class ReportFailed(RuntimeError):
    """A report failed while running (a cell raised, the kernel died, chromium failed)."""


#: What the kernel runs first (imports, compiled code, fonts), while the parent imports too.
WARM_UP = """
import io
import matplotlib.pyplot as plt
import vbi_lib.reports.render
from vbi_lib.reports.analysis import warm_up
warm_up()
figure = plt.figure()
figure.savefig(io.BytesIO(), format="svg")
plt.close(figure)
"""


class Kernel:
    """One IPython kernel for all the reports of a run, in the work folder."""

    def __init__(self, work: Path) -> None:
        from jupyter_client import KernelManager

        self.work = work
        self.km = KernelManager(kernel_name="python3", connection_file=str(work / "kernel.json"))
        self.kc = None
        self.log = None

    def start(self) -> None:
        env = dict(os.environ, TMPDIR=str(self.work / "tmp"), PYDEVD_DISABLE_FILE_VALIDATION="1")
        # the reports' matrix products are small (time steps x a few modes): OpenBLAS's
        # threads only cost, several times over on a shared machine
        env.setdefault("OPENBLAS_NUM_THREADS", "1")
        env.pop("JPY_PARENT_PID", None)
        self.log = open(self.work / "kernel.log", "wb")  # noqa: SIM115 (closed in stop)
        self.km.start_kernel(
            cwd=str(self.work), env=env, stdout=subprocess.DEVNULL, stderr=self.log
        )
        self.kc = self.km.blocking_client()
        self.kc.start_channels()
        # warm up at once: imports and compiled code loading are most of a first report's time
        self.kc.execute(WARM_UP, silent=True)

    def ready(self, timeout: float = 120.0) -> None:
        """Wait until the kernel answers (it was started by :meth:`start`)."""
        try:
            self.kc.wait_for_ready(timeout=timeout)
        except RuntimeError as error:
            raise ReportFailed(f"the Jupyter kernel did not start: {error}") from None

    def run(self, code: str, timeout: float) -> list[dict]:
        """Execute ``code``; its outputs as notebook outputs (stderr left out)."""
        import nbformat

        outputs: list = []

        def keep(message: dict) -> None:
            kind = message["header"]["msg_type"]
            if kind == "stream" and message["content"].get("name") == "stderr":
                return
            if kind in ("stream", "display_data", "execute_result", "error"):
                outputs.append(nbformat.v4.output_from_msg(message))
            elif kind == "clear_output":
                outputs.clear()

        try:
            reply = self.kc.execute_interactive(
                code, timeout=timeout, output_hook=keep, allow_stdin=False, store_history=False
            )
        except TimeoutError:
            raise ReportFailed(f"a report cell ran longer than {timeout:.0f} s") from None
        content = reply["content"]
        if content["status"] != "ok":
            name, value = content.get("ename", "Error"), content.get("evalue", "")
            raise ReportFailed(f"{name}: {value}")
        return outputs

    def stop(self) -> None:
        with contextlib.suppress(Exception):
            if self.kc is not None:
                self.kc.stop_channels()
        with contextlib.suppress(Exception):
            if self.km.has_kernel:
                self.km.shutdown_kernel(now=True)
        process = getattr(getattr(self.km, "provisioner", None), "process", None)
        if process is not None and process.poll() is None:
            with contextlib.suppress(Exception):
                os.killpg(process.pid, signal.SIGKILL)
                process.wait(5)
        if self.log is not None:
            self.log.close()
