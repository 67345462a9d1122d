"""Shared fixtures: where the study's data lives (beside the repository, never inside it)."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHARED_DATA = ROOT.parent / "shared" / "data"


@pytest.fixture(scope="session")
def shared_data() -> Path:
    """``../shared/data``; tests that need it are skipped when it is absent, except on CI."""
    import os

    if not SHARED_DATA.is_dir():
        if os.environ.get("CI") == "true":
            raise RuntimeError(f"CI needs the study's data at {SHARED_DATA}")
        pytest.skip(f"no shared data at {SHARED_DATA}")
    return SHARED_DATA
