"""The book builds from scratch with warnings as errors and every cell executed afresh."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from conftest import ROOT


def test_book_builds_with_warnings_as_errors(tmp_path: Path) -> None:
    jupyter_book = Path(sys.executable).parent / "jupyter-book"
    command = [
        str(jupyter_book),
        "build",
        str(ROOT),
        "--path-output",
        str(tmp_path),
        "-W",
        "--keep-going",
    ]
    env = dict(os.environ, VBI_QUICK="1", MPLBACKEND="Agg")
    result = subprocess.run(
        command, capture_output=True, text=True, timeout=2400, env=env, cwd=ROOT
    )
    log = result.stdout[-6000:] + result.stderr[-6000:]
    assert result.returncode == 0, f"book build failed:\n{log}"
    html = tmp_path / "_build" / "html"
    assert (html / "index.html").is_file()
    assert (html / "notebooks" / "01-what-is-dynamic-amplification.html").is_file()
