"""The explorers in a real browser: the Voila app of ``make explore`` and JupyterLab.

Playwright's Python package drives Debian's chromium (``/usr/bin/chromium``; never a browser
download).  Each test starts its server on 127.0.0.1 and stops it (and its kernels) before it
ends.  Outside CI a machine without chromium skips these tests; CI must run them.
"""

from __future__ import annotations

import dataclasses
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from conftest import ROOT
from explorer_cases import direct_crossing

from vbi_lib.reports import printing
from vbi_lib.widgets import Scenario

CHROMIUM = Path("/usr/bin/chromium")
#: The same switches as the reports' PDF printer: headless, no sandbox, nothing fetched.
CHROMIUM_ARGS = list(printing.CHROMIUM_ARGS)
#: Seconds a page may take to show the explorers (kernel start, compiled code loaded).
LOAD_TIMEOUT = 180


@pytest.fixture(scope="module")
def browser() -> Iterator[object]:
    if not CHROMIUM.exists():
        if os.environ.get("CI") == "true":
            pytest.fail(
                f"CI must run the browser tests: {CHROMIUM} is missing "
                "(apt-get install -y chromium)"
            )
        pytest.skip(
            f"no {CHROMIUM}: install Debian's chromium (apt-get install -y chromium) "
            "to run the browser tests"
        )
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        chromium = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        try:
            yield chromium
        finally:
            chromium.close()


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


class Server:
    """A server process in its own process group; its output is read as it comes."""

    def __init__(self, command: list[str], env: dict[str, str] | None = None) -> None:
        self.lines: list[str] = []
        self.process = subprocess.Popen(
            command,
            cwd=ROOT,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            start_new_session=True,
            env=env,
        )
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        for line in self.process.stdout:
            self.lines.append(line)

    def wait_for_line(self, pattern: str, timeout: float = 120) -> re.Match:
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for line in list(self.lines):
                if match := re.search(pattern, line):
                    return match
            if self.process.poll() is not None:
                break
            time.sleep(0.1)
        pytest.fail(f"no line matching {pattern!r}; server said:\n{self.log()}")

    def wait_until_answering(self, url: str, timeout: float = 120) -> None:
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            try:
                with urllib.request.urlopen(url, timeout=5):
                    return
            except OSError:
                if self.process.poll() is not None:
                    break
                time.sleep(0.3)
        pytest.fail(f"{url} did not answer; server said:\n{self.log()}")

    def log(self) -> str:
        return "".join(self.lines)[-4000:]

    def stop(self) -> None:
        """SIGTERM to the group (the server shuts its kernels down), SIGKILL if it lingers."""
        if self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGTERM)
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(self.process.pid, signal.SIGKILL)
                self.process.wait(timeout=10)
        self._reader.join(timeout=10)


@contextmanager
def running(command: list[str], env: dict[str, str] | None = None) -> Iterator[Server]:
    server = Server(command, env)
    try:
        yield server
    finally:
        server.stop()


def expected_daf_text(speed_mph: float) -> str:
    """The readout's DAF for the explorer's default settings at ``speed_mph``, computed here."""
    values = {**dataclasses.asdict(Scenario()), "speed_mph": speed_mph}
    return f"DAF {direct_crossing(values).daf[0]:.3f}"


def nudge_speed_and_check(page: object) -> None:
    """Press the right arrow on the speed slider; the DAF readout must follow."""
    readout = page.locator(".vbi-readout").first
    page.wait_for_function(
        "document.querySelector('.vbi-readout') && "
        "document.querySelector('.vbi-readout').innerText.includes('DAF')",
        timeout=LOAD_TIMEOUT * 1000,
    )
    start = float(page.locator(".vbi-control-speed_mph .widget-readout").first.inner_text())
    assert expected_daf_text(start) in readout.inner_text()
    handle = page.locator(".vbi-control-speed_mph .noUi-handle").first
    handle.focus()
    handle.press("ArrowRight")
    target = expected_daf_text(start + 1.0)  # the slider's step is 1 mph
    page.wait_for_function(
        "t => document.querySelector('.vbi-readout').innerText.includes(t)",
        arg=target,
        timeout=60_000,
    )
    shown = page.locator(".vbi-control-speed_mph .widget-readout").first.inner_text()
    assert float(shown) == start + 1.0
    assert page.locator(".vbi-figure").first.is_visible()


def run_all_cells(page: object) -> None:
    """Run, Run All Cells from the menu bar, until a cell shows it ran (a click can be lost)."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    for _ in range(3):
        page.get_by_role("menuitem", name="Run", exact=True).click()
        page.get_by_role("menuitem", name="Run All Cells", exact=True).click()
        prompt = page.locator(".jp-InputPrompt", has_text=re.compile(r"\[(\*|\d+)\]")).first
        try:
            prompt.wait_for(timeout=30_000)
            return
        except PlaywrightTimeout:
            continue
    pytest.fail("JupyterLab did not run the notebook's cells")


def test_make_explore_serves_the_explorers_and_they_answer_the_keyboard(browser: object) -> None:
    port = free_port()
    with running(["make", "explore", f"PORT={port}"]) as server:
        url = server.wait_for_line(r"vbi explorers: (http://127\.0\.0\.1:\d+/)").group(1)
        assert url == f"http://127.0.0.1:{port}/"
        server.wait_until_answering(url)
        page = browser.new_page()
        try:
            page.goto(url, timeout=LOAD_TIMEOUT * 1000)
            nudge_speed_and_check(page)
            tabs = page.locator(".lm-TabBar-tabLabel, .p-TabBar-tabLabel").all_inner_texts()
            assert {"One crossing", "DAF against speed", "Frequency matching"} <= set(tabs)
        finally:
            page.close()


def test_jupyterlab_runs_the_explore_notebook(browser: object, tmp_path: Path) -> None:
    # a copy, so that JupyterLab's autosave can never write outputs into the repository
    shutil.copy(ROOT / "explore" / "explore.ipynb", tmp_path / "explore.ipynb")
    port, token = free_port(), "vbi-test-token"
    env = dict(os.environ)
    for name in (
        "JUPYTER_CONFIG_DIR",
        "JUPYTER_RUNTIME_DIR",
        "JUPYTERLAB_WORKSPACES_DIR",
        "JUPYTERLAB_SETTINGS_DIR",
    ):
        env[name] = str(tmp_path / name.lower())
    command = [
        str(Path(sys.executable).parent / "jupyter"),
        "lab",
        "--no-browser",
        "--ServerApp.ip=127.0.0.1",
        f"--ServerApp.port={port}",
        "--ServerApp.port_retries=0",
        f"--IdentityProvider.token={token}",
        f"--ServerApp.root_dir={tmp_path}",
        "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
        "--LabApp.extension_manager=readonly",
    ]
    if os.geteuid() == 0:  # containers and CI runners often run as root
        command.append("--allow-root")
    with running(command, env) as server:
        base = f"http://127.0.0.1:{port}"
        server.wait_until_answering(f"{base}/api/status?token={token}")
        page = browser.new_page()
        try:
            page.goto(f"{base}/lab/tree/explore.ipynb?token={token}", timeout=LOAD_TIMEOUT * 1000)
            page.locator(".jp-Notebook").first.wait_for(timeout=LOAD_TIMEOUT * 1000)
            # the status bar reads "Python 3 (ipykernel) | Idle" once the kernel is ready
            page.get_by_text(re.compile(r"\| Idle")).first.wait_for(timeout=LOAD_TIMEOUT * 1000)
            run_all_cells(page)
            nudge_speed_and_check(page)
        finally:
            page.close()
