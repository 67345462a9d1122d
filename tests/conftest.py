"""Shared fixtures: where the study's data lives (beside the repository, never inside it), and
the book built once per test session (shared by the book's build, content and browser tests)."""

from __future__ import annotations

import os
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHARED_DATA = ROOT.parent / "shared" / "data"


@pytest.fixture(scope="session")
def shared_data() -> Path:
    """``../shared/data``; tests that need it are skipped when it is absent, except on CI."""
    if not SHARED_DATA.is_dir():
        if os.environ.get("CI") == "true":
            raise RuntimeError(f"CI needs the study's data at {SHARED_DATA}")
        pytest.skip(f"no shared data at {SHARED_DATA}")
    return SHARED_DATA


@dataclass(frozen=True)
class BookBuild:
    """One ``jupyter-book build`` of the whole book into a temporary folder."""

    returncode: int
    log: str
    html: Path

    def require(self) -> Path:
        """The HTML folder; fails the calling test if the build failed."""
        if self.returncode != 0:
            pytest.fail(f"the book did not build (see test_book):\n{self.log[-3000:]}")
        return self.html


@pytest.fixture(scope="session")
def book_build(tmp_path_factory: pytest.TempPathFactory) -> BookBuild:
    """The book built from scratch, every cell executed afresh, warnings as errors.

    Built once per session, in quick mode (``VBI_QUICK=1``), into a temporary folder, so the
    tests never touch the developer's ``_build/html``.
    """
    out = tmp_path_factory.mktemp("book")
    command = [
        str(Path(sys.executable).parent / "jupyter-book"),
        "build",
        str(ROOT),
        "--path-output",
        str(out),
        "-W",
        "--keep-going",
    ]
    env = dict(os.environ, VBI_QUICK="1", MPLBACKEND="Agg")
    # ipykernel stops capturing what subprocesses write to stderr when it sees this variable;
    # without it the chapters' kernels behave as in `make book`, and their noise is tested
    env.pop("PYTEST_CURRENT_TEST", None)
    result = subprocess.run(
        command, capture_output=True, text=True, timeout=2400, env=env, cwd=ROOT
    )
    log = result.stdout[-6000:] + result.stderr[-6000:]
    return BookBuild(result.returncode, log, out / "_build" / "html")
