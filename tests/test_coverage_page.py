"""The coverage page (book/coverage.md) against the study and the chapters, read as text.

- Every figure and table the study numbers ("Figure 2.x.y", "Table 2.x.y") is one row of the
  page, exactly once, and the page has no row for a number the study does not have.
- Every label the page cross-references ({numref}, {ref}) is defined in a chapter (a
  ``:name:`` option, a ``(label)=`` target, or the name given to ``display.table`` in a code
  cell) or on a page of ``book/``; every page it links with {doc} exists.
- Each row's status agrees with its evidence, by the page's own definitions: "reproduced"
  names only figures and tables that the chapter it names computes when it is built (a
  ``glue:figure``, or a table made by a code cell) and quotes nothing; "partly" names its
  difference and at least one computed item; a row that names a quoted table (its caption
  says "quoted") says so; "with the study's data" names a chapter that takes ``data_dir``.
- The counts the page states are those of its rows.

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
#: A row of the page's list-tables: its four cells, study item to status.
FULL_ROW = re.compile(
    r"^\* - (?P<item>(?:Figure|Table) 2\.\d+\.\d+)\s*\n  - (?P<what>.*?)\n  - (?P<where>.*?)"
    r"\n  - (?P<status>.*?)(?=\n\* - |\n```)",
    re.M | re.S,
)
STATUS = re.compile(r"^(reproduced|partly: \S|with the study's data: \S)")
CHAPTER = re.compile(r"chapter (\d)\b")
GLUE_FIGURE = re.compile(r"```\{glue:figure\}[^\n]*\n:name:\s*([\w-]+)")
STATIC_TABLE = re.compile(r":::\{table\}[^\n]*\n:name:\s*([\w-]+)")
#: A quoted table's caption that also holds the book's own values.
BESIDE = re.compile(r"the book's|this page's|this run's|beside")
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


def chapter_evidence(number: int) -> tuple[dict[str, str], bool]:
    """What chapter ``number`` holds under each label it defines, and whether it takes
    ``data_dir``: ``"figure"`` (a glued figure, computed), ``"table"`` (a table made by a
    code cell), ``"quoted table"`` (the same, its caption saying "quoted"), ``"quoted beside
    computed"`` (its caption quoting the study beside the book's own values) or
    ``"static"`` (a table typed into the text)."""
    (path,) = (ROOT / "notebooks").glob(f"{number:02d}-*.ipynb")
    kinds: dict[str, str] = {}
    takes_data = False
    for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
        source = "".join(cell["source"])
        tags = cell.get("metadata", {}).get("tags", [])
        if cell["cell_type"] == "markdown":
            kinds |= dict.fromkeys(GLUE_FIGURE.findall(source), "figure")
            kinds |= dict.fromkeys(STATIC_TABLE.findall(source), "static")
        elif "parameters" in tags:
            takes_data = "data_dir" in source
        elif "display.table(" in source or "_table(" in source:
            for label in STRING.findall(source):
                call = source[: source.index(label)].rsplit("_table(", 1)[-1]
                call = re.sub(r"\"\s*\n\s*(?:f|rf|r)?\"", "", call)  # one caption, not its pieces
                if "quoted" not in call:
                    kinds[label] = "table"
                elif BESIDE.search(call):
                    kinds[label] = "quoted beside computed"
                else:
                    kinds[label] = "quoted table"
    return kinds, takes_data


def page_rows_in_full() -> list[dict[str, str]]:
    text = PAGE.read_text(encoding="utf-8")
    return [m.groupdict() for m in FULL_ROW.finditer(text)]


def test_every_status_agrees_with_its_evidence() -> None:
    rows = page_rows_in_full()
    assert len(rows) == 49, f"read {len(rows)} rows of book/coverage.md, expected 49"
    wrong = []
    for row in rows:
        status = " ".join(row["status"].split())
        where = row["where"]
        if not STATUS.match(status):
            wrong.append(f"{row['item']}: status {status[:50]!r} is none of the page's words")
            continue
        chapters = CHAPTER.findall(where)
        labels = XREF.findall(where)
        if len(chapters) != 1 or not labels:
            wrong.append(f"{row['item']}: 'in the book' must name one chapter and its items")
            continue
        kinds, takes_data = chapter_evidence(int(chapters[0]))
        found = {label: kinds.get(label, "missing") for label in labels}
        missing = [label for label, kind in found.items() if kind == "missing"]
        computed = [
            label
            for label, kind in found.items()
            if kind in ("figure", "table", "quoted beside computed")
        ]
        quoted = [label for label, kind in found.items() if kind.startswith("quoted")]
        if status.startswith("reproduced") and quoted:
            wrong.append(f"{row['item']}: says reproduced but names quoted tables {quoted}")
        if missing:
            wrong.append(f"{row['item']}: chapter {chapters[0]} does not define {missing}")
        elif status.startswith("reproduced") and {"static"} & set(found.values()):
            wrong.append(
                f"{row['item']}: says reproduced, but names a table typed into the text, "
                f"not computed ({found})"
            )
        elif not computed:
            wrong.append(f"{row['item']}: names no figure or table its chapter computes ({found})")
        if quoted and "quoted" not in status:
            wrong.append(f"{row['item']}: names the quoted table(s) {quoted} and does not say so")
        if status.startswith("partly") and len(status.split(":", 1)[1].split()) < 4:
            wrong.append(f"{row['item']}: 'partly' must name the difference")
        if status.startswith("with the study's data") and not takes_data:
            wrong.append(f"{row['item']}: chapter {chapters[0]} takes no data_dir")
    assert not wrong, "book/coverage.md:\n" + "\n".join(wrong)


def test_the_page_s_counts_are_its_rows() -> None:
    text = PAGE.read_text(encoding="utf-8")
    stated = re.search(
        r"\*\*(\d+)\*\* are reproduced, \*\*(\d+)\*\* partly and \*\*(\d+)\*\* only with the "
        r"study's data",
        " ".join(text.split()),
    )
    assert stated, "book/coverage.md states no counts of reproduced, partly and data-only items"
    statuses = [" ".join(row["status"].split()) for row in page_rows_in_full()]
    counted = [
        sum(s.startswith(word) for s in statuses)
        for word in ("reproduced", "partly", "with the study's data")
    ]
    assert [int(n) for n in stated.groups()] == counted, (
        f"the page states {stated.groups()}, its rows count {counted}"
    )
