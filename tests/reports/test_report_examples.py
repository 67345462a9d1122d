"""The example parameter files are valid, and their README documents every key there is."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
import yaml
from conftest import ROOT, SHARED_DATA

from vbi_lib.reports import SCHEMA, load_job, read_parameters

EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))


def keys(schema: dict, prefix: str = "") -> list[str]:
    found = []
    for name, value in schema.items():
        if isinstance(value, dict):
            found += keys(value, f"{name}.")
        else:
            found.append(prefix + name)
    return found


def test_there_are_examples() -> None:
    assert {p.name for p in EXAMPLES} >= {"generated-road.yaml", "i76-span3.yaml"}


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_example_is_a_valid_report(path: Path) -> None:
    if "shared/data" in path.read_text() and not SHARED_DATA.is_dir():
        if os.environ.get("CI") == "true":
            raise RuntimeError(f"CI needs the study's data at {SHARED_DATA}")
        pytest.skip(f"{path.name} reads the study's data, absent at {SHARED_DATA}")
    job = load_job(path)
    assert job.name == path.stem


def test_every_key_is_documented() -> None:
    text = (ROOT / "examples" / "README.md").read_text()
    missing = [key for key in keys(SCHEMA) if f"| `{key}` |" not in text]
    assert not missing, f"examples/README.md does not document {missing}"


def test_the_readme_example_is_the_example_file() -> None:
    readme = (ROOT / "README.md").read_text()
    block = readme.split("```yaml\n", 1)[1].split("```", 1)[0]
    shown = read_parameters(yaml.safe_load(block))
    example = load_job(ROOT / "examples" / "generated-road.yaml").parameters
    assert shown.profile.file is None  # it runs on a generated road: no file needed
    assert (shown.bridge, shown.vehicle, shown.profile, shown.speeds, shown.title) == (
        example.bridge,
        example.vehicle,
        example.profile,
        example.speeds,
        example.title,
    )
