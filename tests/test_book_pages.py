"""What the built book's pages hold (the session's build, ``book_build`` in conftest).

- No page publishes noise: a Python traceback, an ANSI escape code, a kernel or Python
  warning, a progress bar.
- The pages reference no script, style or font outside the book, and the assets they load
  are in the build.
- The API reference has a page for every public module of ``vbi_lib``, found by walking the
  package, so a module added, moved or removed is followed.
- Each chapter's papermill ``parameters`` cell is folded.
- Equations are numbered per chapter, (3.1), (3.2), ... without a gap, and every reference
  to an equation reads a number of that form.
"""

from __future__ import annotations

import pkgutil
import re
import sys
from pathlib import Path

import pytest
from bs4 import BeautifulSoup
from conftest import ROOT, BookBuild

sys.path.insert(0, str(ROOT / "book" / "_ext"))
import vbi_book  # noqa: E402  (the book's Sphinx extension: book/_ext/vbi_book.py)

#: Noise in a cell's output, by name.
OUTPUT_NOISE = {
    "Python traceback": re.compile(r"Traceback \(most recent call last\)"),
    "kernel log line": re.compile(r"\[(IPKernelApp|KernelApp|NbConvertApp)\]|^\s*WARNING\b", re.M),
    "Python warning": re.compile(r"\b\w+Warning: "),
    "progress bar": re.compile(r"\d+%\|.*\|"),
}
#: An ANSI escape sequence anywhere in the page: raw, or as a character reference.
ANSI = re.compile(r"\x1b\[|&#0*27;\[|&#x0*1b;\[|\\u001b\[|\\x1b\[", re.I)

#: Noise whose cause lies outside the book's machinery (in the library or a chapter's
#: content), with that cause and its fix, and whether it appears on every build. An entry
#: that appears every time must still be found, so fixing its cause fails the test until the
#: entry is removed; one that depends on the machine's speed is tolerated either way.
KNOWN_NOISE: dict[tuple[str, str], tuple[str, bool]] = {}


def html_pages(html: Path) -> list[Path]:
    skip = {"_static", "_sources", "_images"}
    return sorted(p for p in html.rglob("*.html") if not skip & set(p.relative_to(html).parts))


def test_no_page_publishes_noise(book_build: BookBuild) -> None:
    html = book_build.require()
    found: dict[tuple[str, str], str] = {}
    for page in html_pages(html):
        name = page.relative_to(html).as_posix()
        source = page.read_text(encoding="utf-8")
        if ANSI.search(source):
            found[name, "ANSI escape code"] = ANSI.search(source).group(0)
        soup = BeautifulSoup(source, "html.parser")
        for output in soup.select("div.cell_output"):
            text = output.get_text()
            for kind, pattern in OUTPUT_NOISE.items():
                match = pattern.search(text)
                if match:
                    start = max(0, match.start() - 40)
                    found.setdefault((name, kind), text[start : match.end() + 80].strip())
    unexpected = {k: v for k, v in found.items() if k not in KNOWN_NOISE}
    fixed = [k for k, (_, every_build) in KNOWN_NOISE.items() if every_build and k not in found]
    assert not unexpected, "noise in the published pages:\n" + "\n".join(
        f"{page}: {kind}: {excerpt!r}" for (page, kind), excerpt in unexpected.items()
    )
    assert not fixed, f"known noise no longer found, remove it from KNOWN_NOISE: {fixed}"


def test_pages_load_nothing_from_outside(book_build: BookBuild) -> None:
    html = book_build.require()
    outside = []
    for page in html_pages(html):
        soup = BeautifulSoup(page.read_text(encoding="utf-8"), "html.parser")
        for tag, attribute in (("script", "src"), ("link", "href"), ("img", "src")):
            for element in soup.find_all(tag):
                url = element.get(attribute)
                if tag == "link" and "stylesheet" not in element.get("rel", []):
                    continue
                if not url:
                    continue
                if re.match(r"^([a-z]+:)?//", url):
                    outside.append(f"{page.relative_to(html)}: <{tag}> {url}")
                elif not url.startswith("data:"):
                    target = (page.parent / url.split("?")[0].split("#")[0]).resolve()
                    if not target.is_file():
                        outside.append(f"{page.relative_to(html)}: <{tag}> {url} is missing")
    assert not outside, "\n".join(outside)
    for asset in vbi_book.ASSETS:
        assert (html / "_static" / asset).is_file(), asset


def public_modules() -> list[str]:
    """Every public module of vbi_lib, walked from the package itself."""
    import vbi_lib

    found = ["vbi_lib"]
    for module in pkgutil.walk_packages(vbi_lib.__path__, "vbi_lib."):
        if not any(part.startswith("_") for part in module.name.split(".")):
            found.append(module.name)
    return sorted(found)


def test_api_reference_has_every_public_module(book_build: BookBuild) -> None:
    html = book_build.require()
    pages = {p.stem for p in (html / "book" / "api").glob("*.html")}
    missing = sorted(set(public_modules()) - pages)
    assert not missing, f"no API page for {missing}"
    stale = sorted(pages - set(public_modules()))
    assert not stale, f"API pages for modules that do not exist: {stale}"


def test_parameters_cell_is_folded(book_build: BookBuild) -> None:
    html = book_build.require()
    chapters = sorted((html / "notebooks").glob("*.html"))
    assert chapters
    for chapter in chapters:
        soup = BeautifulSoup(chapter.read_text(encoding="utf-8"), "html.parser")
        cells = soup.select("div.cell.tag_parameters")
        assert len(cells) == 1, f"{chapter.name}: {len(cells)} parameters cells"
        folded = cells[0].select_one("details")
        assert folded is not None, f"{chapter.name}: parameters cell not folded"
        assert "quick" in folded.get_text(), f"{chapter.name}: the fold hides no code"
        assert vbi_book.PARAMETERS_PROMPT in folded.summary.get_text()


def test_equations_are_numbered_per_chapter(book_build: BookBuild) -> None:
    html = book_build.require()
    chapters = sorted((html / "notebooks").glob("*.html"))
    assert chapters
    for chapter in chapters:
        number = vbi_book.chapter_number(f"notebooks/{chapter.stem}")
        soup = BeautifulSoup(chapter.read_text(encoding="utf-8"), "html.parser")
        shown = [span.get_text(strip=True).rstrip("#¶") for span in soup.select("span.eqno")]
        shown = [re.sub(r"[^\d.()]", "", text) for text in shown]
        expected = [f"({number}.{k})" for k in range(1, len(shown) + 1)]
        assert shown == expected, f"{chapter.name}: equation numbers {shown[:8]}..."
        for ref in soup.select("a.reference span.eqno, a.reference.internal"):
            text = ref.get_text(strip=True)
            if re.fullmatch(r"\(\d+(\.\d+)?\)", text):
                assert "." in text, f"{chapter.name}: an equation reference reads {text}"


@pytest.mark.parametrize("name", ["simulate", "Bridge", "Vehicle", "Profile"])
def test_package_names_resolve_to_where_they_are_defined(name: str) -> None:
    import importlib

    import vbi_lib

    if not hasattr(vbi_lib, name):
        pytest.skip(f"vbi_lib no longer exports {name}")
    canonical = vbi_book.canonical_name(f"vbi_lib.{name}")
    module, _, attribute = canonical.rpartition(".")
    assert module != "vbi_lib", "resolved to the package, not the defining module"
    assert getattr(importlib.import_module(module), attribute) is getattr(vbi_lib, name)


def test_missing_names_do_not_resolve() -> None:
    assert vbi_book.canonical_name("vbi_lib.no_such_function") is None
    assert vbi_book.canonical_name("vbi_lib.Bridge.no_such_attribute") is None
    assert vbi_book.canonical_name("no_such_package.x") is None
