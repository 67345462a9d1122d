"""The coverage page (book/coverage.md) against the study and the chapters, read as text.

- Every figure and table the study numbers ("Figure 2.x.y", "Table 2.x.y") is one row of the
  page, exactly once, and the page has no row for a number the study does not have.
- Every label the page cross-references ({numref}, {ref}) is defined in a chapter (a
  ``:name:`` option, a ``(label)=`` target, or the name given to ``display.table`` in a code
  cell) or on a page of ``book/``; every page it links with {doc} exists.

The study's text is read from ``../shared/seed`` beside the repository (never copied in);
the test skips without it, except on CI.
"""

from __future__ import annotations

import json
import os
import re

import pytest
from conftest import ROOT

PAGE = ROOT / "book" / "coverage.md"
STUDY = ROOT.parent / "shared" / "seed" / "estimating-dynamic-amplification.md"

#: A numbered item of the study, e.g. "Figure 2.13.4" or "Table 2.15.1".
ITEM = re.compile(r"\b(Figure|Table) (2\.\d+\.\d+)\b")
#: A row of one of the page's list-tables: its first cell is the study's number.
ROW = re.compile(r"^\* - (Figure|Table) (2\.\d+\.\d+)\s*$", re.M)
#: A cross-reference: {numref}`label`, {numref}`text <label>`, the same with {ref}.
XREF = re.compile(r"\{(?:numref|ref)\}`(?:[^`<]*<)?([\w-]+)>?`")
DOC = re.compile(r"\{doc\}`(?:[^`<]*<)?([^`>]+)>?`")
#: Where a chapter or a page defines a label.
NAME_OPTION = re.compile(r"^\s*:name:\s*([\w-]+)\s*$", re.M)
TARGET = re.compile(r"^\(([\w-]+)\)=\s*$", re.M)
STRING = re.compile(r"""["']([a-z0-9]+(?:-[a-z0-9]+)+)["']""")


@pytest.fixture(scope="module")
def study_text() -> str:
    if not STUDY.is_file():
        if os.environ.get("CI") == "true":
            raise RuntimeError(f"CI needs the study's text at {STUDY}")
        pytest.skip(f"no study text at {STUDY}")
    return STUDY.read_text(encoding="utf-8")


def page_rows(text: str) -> list[str]:
    return [f"{kind} {number}" for kind, number in ROW.findall(text)]


def defined_labels() -> set[str]:
    """Every label defined in the chapters' sources and the book's pages (static text)."""
    labels: set[str] = set()
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
            source = "".join(cell["source"])
            if cell["cell_type"] == "markdown":
                labels |= set(NAME_OPTION.findall(source)) | set(TARGET.findall(source))
            elif cell["cell_type"] == "code":
                # display.table(frame, caption, name, ...): the label is a string argument
                for call in source.split("display.table(")[1:]:
                    labels |= set(STRING.findall(call.split("\n)")[0]))
    for path in sorted((ROOT / "book").glob("*.md")):
        source = path.read_text(encoding="utf-8")
        labels |= set(NAME_OPTION.findall(source)) | set(TARGET.findall(source))
    return labels


def test_every_item_of_the_study_is_one_row(study_text: str) -> None:
    items = {f"{kind} {number}" for kind, number in ITEM.findall(study_text)}
    assert len(items) == 49, f"the study numbers 49 figures and tables, found {len(items)}"
    rows = page_rows(PAGE.read_text(encoding="utf-8"))
    missing = sorted(items - set(rows))
    repeated = sorted({row for row in rows if rows.count(row) > 1})
    unknown = sorted(set(rows) - items)
    assert not missing, f"book/coverage.md has no row for {missing}"
    assert not repeated, f"book/coverage.md has more than one row for {repeated}"
    assert not unknown, f"book/coverage.md has rows for items the study lacks: {unknown}"


def test_every_cross_reference_is_defined() -> None:
    text = PAGE.read_text(encoding="utf-8")
    used = set(XREF.findall(text))
    assert used, "book/coverage.md cross-references no label"
    undefined = sorted(used - defined_labels())
    assert not undefined, f"book/coverage.md references labels no chapter defines: {undefined}"
    for target in DOC.findall(text):
        page = (PAGE.parent / target.strip()).resolve()
        found = [page.with_suffix(s) for s in (".md", ".ipynb") if page.with_suffix(s).is_file()]
        assert found, f"book/coverage.md links {{doc}}`{target}`, which is no page of the book"


def test_the_page_is_in_the_table_of_contents() -> None:
    toc = (ROOT / "_toc.yml").read_text(encoding="utf-8")
    assert re.search(r"^\s*- file: book/coverage\s*$", toc, re.M), "_toc.yml lacks book/coverage"
