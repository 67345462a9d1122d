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


#: Where a reader is shown parameter files to copy: the front door, the book's pages (the
#: README's long sections moved to book/modules.md) and the examples' own README.
SHOWN_IN = [
    ROOT / "README.md",
    *sorted((ROOT / "book").glob("*.md")),
    ROOT / "examples" / "README.md",
]


def test_the_readme_examples_are_the_example_files() -> None:
    """Every YAML block of the README, the book's pages and the examples' README is an example
    file of the same title, as it is."""
    blocks = [
        part.split("```", 1)[0]
        for page in SHOWN_IN
        for part in page.read_text().split("```yaml\n")[1:]
    ]
    assert blocks, "neither the README nor the book shows a parameter file"
    by_title = {load_job(path).parameters.title: path for path in EXAMPLES if _readable(path)}
    for block in blocks:
        shown = read_parameters(yaml.safe_load(block), base_dir=ROOT / "examples")
        assert shown.title in by_title, f"no example file is titled {shown.title!r}"
        example = load_job(by_title[shown.title]).parameters
        assert (shown.bridge, shown.vehicle, shown.profile, shown.speeds, shown.sections,
                shown.effects, shown.direction) == (
            example.bridge, example.vehicle, example.profile, example.speeds, example.sections,
            example.effects, example.direction,
        )  # fmt: skip


def _readable(path: Path) -> bool:
    return "shared/data" not in path.read_text() or SHARED_DATA.is_dir()
