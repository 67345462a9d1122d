"""Every chapter runs with papermill in its quick mode; a broken notebook names itself."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT, SHARED_DATA

NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))

#: Extra papermill parameters a chapter takes when the shared data is present.
DATA_PARAMETERS = {
    "04-how-good-is-the-simple-model": {"data_dir": str(SHARED_DATA / "seed-study")},
    "05-road-profiles-and-roughness": {"data_dir": str(SHARED_DATA)},
    "08-beyond-the-study": {"data_dir": str(SHARED_DATA / "seed-study")},
}


def test_there_are_notebooks() -> None:
    assert NOTEBOOKS, "no notebooks found"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_is_clean(path: Path) -> None:
    """Stored without outputs and with a papermill ``parameters`` cell holding ``quick``."""
    notebook = json.loads(path.read_text())
    cells = notebook["cells"]
    assert not any(c.get("outputs") for c in cells if c["cell_type"] == "code"), "has outputs"
    tagged = [c for c in cells if "parameters" in c.get("metadata", {}).get("tags", [])]
    assert len(tagged) == 1, "needs exactly one cell tagged 'parameters'"
    assert "quick" in "".join(tagged[0]["source"])
    assert notebook["metadata"]["kernelspec"]["name"] == "python3"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_has_its_key_points_once(path: Path) -> None:
    """One "Key points" box at the end, not a heading of that name above it as well."""
    cells = json.loads(path.read_text())["cells"]
    text = "".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")
    assert text.count("Key points") == 1, "'Key points' must appear once"
    last = "".join(cells[-1]["source"])
    assert "```{admonition} Key points" in last, "the chapter must end with its key points"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_runs_quick(path: Path, tmp_path: Path) -> None:
    command = [
        sys.executable,
        "-m",
        "papermill",
        str(path),
        str(tmp_path / path.name),
        "-p",
        "quick",
        "True",
        "--cwd",
        str(path.parent),
        "-k",
        "python3",
        "--execution-timeout",
        "900",
    ]
    for name, value in DATA_PARAMETERS.get(path.stem, {}).items():
        if SHARED_DATA.is_dir():
            command += ["-p", name, value]
    env = dict(os.environ, VBI_QUICK="1", MPLBACKEND="Agg")
    # papermill occasionally hangs after the last cell: a hard timeout names the notebook
    result = subprocess.run(command, capture_output=True, text=True, timeout=1200, env=env)
    assert result.returncode == 0, f"{path.name} failed:\n{result.stderr[-4000:]}"
