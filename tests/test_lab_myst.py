"""The chapters read right in JupyterLab: jupyterlab-myst renders their MyST.

JupyterLab runs on 127.0.0.1 on a copy of chapter 3 (so that its autosave never writes into
the repository), Debian's Chromium opens it, and the page is checked: the extension says it
is active, the chapter's exercises are rendered as exercises, its equations are typeset and
its cross-references to equations are numbers, and none of that markup is left raw.

jupyterlab-myst does not implement myst-nb's glue (``{glue:text}``, ``glue:figure``;
jupyter-book/jupyterlab-myst issue 40): in Lab a glued number shows its key, which the book
says on *How to use this book*. The server is stopped by the test that started it.
"""

from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest
from conftest import ROOT

CHROMIUM = Path("/usr/bin/chromium")
CHAPTER = ROOT / "notebooks" / "03-the-two-degree-of-freedom-model.ipynb"
LOAD_TIMEOUT = 180  # seconds: JupyterLab's start and its first page


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def test_jupyterlab_renders_the_chapters_myst(tmp_path: Path) -> None:
    if not CHROMIUM.exists():
        if os.environ.get("CI") == "true":
            pytest.fail(f"CI must run the browser tests: {CHROMIUM} is missing")
        pytest.skip(f"no {CHROMIUM}: apt-get install -y chromium")
    from playwright.sync_api import sync_playwright

    from vbi_lib.reports import printing

    shutil.copy(CHAPTER, tmp_path / CHAPTER.name)
    env = dict(os.environ)
    for name in ("JUPYTER_CONFIG_DIR", "JUPYTER_RUNTIME_DIR", "JUPYTERLAB_WORKSPACES_DIR"):
        env[name] = str(tmp_path / name.lower())
    settings = tmp_path / "settings"
    (settings / "@jupyterlab" / "notebook-extension").mkdir(parents=True)
    # every cell drawn at once (no windowing), so that the whole chapter can be read
    (settings / "@jupyterlab" / "notebook-extension" / "tracker.jupyterlab-settings").write_text(
        '{"windowingMode": "none"}'
    )
    env["JUPYTERLAB_SETTINGS_DIR"] = str(settings)
    port, token = _free_port(), "vbi-test-token"
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
    log = tmp_path / "lab.log"
    with log.open("w") as out:
        server = subprocess.Popen(command, env=env, stdout=out, stderr=subprocess.STDOUT,
                                  start_new_session=True)  # fmt: skip
    try:
        base = f"http://127.0.0.1:{port}"
        end = time.monotonic() + LOAD_TIMEOUT
        while True:
            try:
                with urllib.request.urlopen(f"{base}/api/status?token={token}", timeout=5):
                    break
            except OSError:
                if server.poll() is not None or time.monotonic() > end:
                    pytest.fail(f"JupyterLab did not answer:\n{log.read_text()[-3000:]}")
                time.sleep(0.5)
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(
                executable_path=str(CHROMIUM), args=list(printing.CHROMIUM_ARGS)
            )
            try:
                page = browser.new_page(viewport={"width": 1300, "height": 1000})
                console: list[str] = []
                page.on("console", lambda message: console.append(message.text))
                page.goto(f"{base}/lab/tree/{CHAPTER.name}?token={token}",
                          timeout=LOAD_TIMEOUT * 1000)  # fmt: skip
                page.locator(".jp-Notebook").first.wait_for(timeout=LOAD_TIMEOUT * 1000)
                page.get_by_text("Exercise 1", exact=True).first.wait_for(
                    timeout=LOAD_TIMEOUT * 1000
                )
                page.locator(
                    ".jp-MarkdownCell mjx-container, .jp-MarkdownCell .katex"
                ).first.wait_for(timeout=60_000)
                markdown = " ".join(page.locator(".jp-MarkdownCell").all_inner_texts())
            finally:
                browser.close()
    finally:
        if server.poll() is None:
            os.killpg(server.pid, signal.SIGTERM)
            try:
                server.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(server.pid, signal.SIGKILL)
                server.wait(timeout=10)
    assert any("jupyterlab-myst is activated" in line for line in console), console[-20:]
    for raw in (":::{exercise}", ":::{solution-start}", "{eq}`", "{numref}`", "{doc}`", "$$"):
        assert raw not in markdown, f"JupyterLab shows {raw!r} raw in chapter 3"
    assert "Exercise 2" in markdown and "(study 46)" in markdown
