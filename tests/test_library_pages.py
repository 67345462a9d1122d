"""The book's pages on the library (book/modules.md, ranges.md, performance.md, numerics.md)
and the README, the front door that links into them.

- The module map names every top-level module and package of ``vbi_lib`` (found by walking
  the package, so a module added or removed is followed).
- The performance page holds the markers ``benchmarks/run_all.py`` writes its table
  between, and ``run_all`` writes to that page (the README has no table to rewrite).
- The README is a front door of at most 10 KB: what vbi is, a picture, the two commands, an
  example, the live routes, and links into the book, every one of which exists.

The ranges page's table is compared with ``vbi_lib.ranges.RANGES`` in tests/test_inputs.py.
"""

from __future__ import annotations

import importlib.util
import pkgutil
import re

from conftest import ROOT

import vbi_lib

BOOK = ROOT / "book"
README = ROOT / "README.md"


def test_the_module_map_names_every_module_of_the_package() -> None:
    text = (BOOK / "modules.md").read_text(encoding="utf-8")
    first_cells = " ".join(
        line.split("|")[1] for line in text.splitlines() if line.startswith("| `")
    )
    listed = {name.split(".")[0].rstrip("*") for name in re.findall(r"`([\w.*]+)`", first_cells)}
    modules = {m.name for m in pkgutil.iter_modules(vbi_lib.__path__) if not m.name.startswith("_")}
    assert modules - listed == set(), f"book/modules.md does not list {sorted(modules - listed)}"
    assert listed - modules == set(), f"book/modules.md lists unknown {sorted(listed - modules)}"


def test_the_benchmarks_write_their_table_into_the_performance_page() -> None:
    spec = importlib.util.spec_from_file_location("run_all", ROOT / "benchmarks" / "run_all.py")
    run_all = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(run_all)
    assert run_all.PAGE == BOOK / "performance.md"
    text = run_all.PAGE.read_text(encoding="utf-8")
    assert text.count(run_all.START) == 1 and text.count(run_all.END) == 1
    assert run_all.START not in README.read_text(encoding="utf-8")
    rows = [r for r in run_all.table([{"what": "a", "target": "b", "measured": "c"}], "1", "2")
            .splitlines() if r.startswith("| a ")]  # fmt: skip
    assert rows == ["| a | b | c |"]


def test_the_readme_is_a_front_door() -> None:
    text = README.read_text(encoding="utf-8")
    assert len(text.encode("utf-8")) <= 10_000, f"README.md is {len(text.encode())} bytes"
    for must in ("make book", "make test", "make explore", "make lab", "vbi-report", "```python"):
        assert must in text, f"README.md lacks {must!r}"
    assert re.search(r"!\[[^\]]+\]\([^)]+\.(png|svg)\)", text), "README.md shows no picture"
    example = text.split("```python", 1)[1].split("```", 1)[0].strip().splitlines()
    assert len(example) <= 12, f"the README's example has {len(example)} lines"
    links = re.findall(r"\]\(((?!https?:)[^)#]+)", text)
    assert len(links) >= 8, "README.md links too little of the book"
    missing = [link for link in links if not (ROOT / link).exists()]
    assert not missing, f"README.md links files that do not exist: {missing}"
    for page in ("ranges.md", "performance.md", "numerics.md", "modules.md"):
        assert f"book/{page}" in text, f"README.md does not link book/{page}"
