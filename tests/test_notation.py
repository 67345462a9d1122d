"""One symbol per quantity: the pages, their figures and tables, and the library's docstrings
against the notation page (``book/notation.md``), which is the reference.

- Every symbol written in math on a page (a chapter's text, equations, figure labels and
  table headers built in its code, the book's own pages) is declared in one of the notation
  page's symbol tables.
- No page, label, header or docstring writes a symbol the page's table "Symbols kept apart"
  sets aside (the study's R for the contact force, W for a weight, n for a mode, ...). Each
  row of that table has a detector here, and the test fails when a row has none, so the
  page stays the reference.
- Every restated equation of the study shows the study's number beside it: an equation
  labelled ``study-46`` carries "(study 46)" (or a group holding 46, "(study 46-48)").

Static checks of the sources; no build needed.
"""

from __future__ import annotations

import ast
import json
import re
from collections.abc import Iterator

import pytest
from conftest import ROOT

NOTATION = ROOT / "book" / "notation.md"
CHAPTERS = sorted((ROOT / "notebooks").glob("*.ipynb"))
#: The book's own pages checked for declared symbols (the notation page declares them; the
#: page on writing chapters shows markup with placeholder symbols).
PAGES = sorted(
    p for p in (ROOT / "book").glob("*.md") if p.name not in {"notation.md", "writing-chapters.md"}
)
#: The pages held to the symbols kept apart: every page but the notation page itself.
ALIAS_PAGES = sorted(p for p in (ROOT / "book").glob("*.md") if p.name != "notation.md")
LIBRARY = sorted((ROOT / "vbi_lib").rglob("*.py"))

# ---------------------------------------------------------------------------- math atoms
#: LaTeX commands that are operators, functions, spacing or layout, not symbols.
NOT_SYMBOLS = set(
    r"""\sin \cos \tan \sinh \cosh \tanh \exp \log \ln \pi \times \max \min \frac \dfrac \tfrac
    \sqrt \left \right \big \Big \bigl \bigr \bigg \quad \qquad \cdot \cdots \dots \ldots \le
    \ge \leq \geq \ll \gg \approx \sim \propto \equiv \ne \neq \pm \mp \in \mid \to \sum \int
    \infty \partial \textstyle \displaystyle \phantom \lvert \rvert \vert \prime \hat \cases
    \lim \colon \circ \forall \hline \tag \label \nonumber \lesssim \gtrsim \Rightarrow
    \rightarrow \underbrace \overbrace""".split()
)
#: Upper-case words that are one symbol each.
WORDS = ("DAF", "IM", "IRI", "EI", "MAE", "FE")
TOKEN = re.compile(
    r"(\\bar\s*\{?\s*\\?[A-Za-z]+\}?|\\[A-Za-z]+|" + "|".join(WORDS) + r"|[A-Za-z])"
    r"(_\{[^{}]*\}|_\\?[A-Za-z0-9]+)?(\^\*|'{1,4})?"
)


def _clean(math: str) -> str:
    m = math.replace("{{", "{").replace("}}", "}")  # f-strings in code cells
    m = re.sub(r"\\(text|operatorname)\s*\{[^{}]*\}", " ", m)
    m = re.sub(r"(?<!_)\\mathrm\s*\{[a-z]{2,}\}", " ", m)  # a word in roman: "odd"
    m = re.sub(r"\\(mathrm|mathbf|boldsymbol|mathsf|mathit)\s*\{([^{}]*)\}", r"\2", m)
    m = re.sub(r"\\(mathrm|mathbf|boldsymbol|mathsf)\s+(\\?[A-Za-z])", r"\2", m)
    m = re.sub(r"\\begin\{[a-z*]+\}|\\end\{[a-z*]+\}", " ", m)
    m = re.sub(r"\\d?dot\s*\{([^{}]*)\}", r" \1", m)  # a rate is the symbol's own
    m = re.sub(r"\\d?dot\s*", " ", m)
    m = re.sub(r"\be\^", " ", m)  # Euler's number
    m = re.sub(r"_\\(max|min)\b", r"_{\1}", m)
    m = re.sub(r"\^\{?(T|\\mathsf\{T\}|\\top|-?[\d.]+)\}?", " ", m)  # powers, transposes
    return re.sub(r"\\[,;! ]", " ", m)


def atoms(math: str) -> set[str]:
    """The symbols of a piece of LaTeX: ``F_c / P`` gives ``{"F_{c}", "P"}``."""
    found = set()
    for token in TOKEN.finditer(_clean(math)):
        base, sub, mark = token.group(1), token.group(2) or "", token.group(3) or ""
        base = re.sub(r"\\bar\s*\{?\s*(\\?[A-Za-z]+)\}?", r"\\bar \1", base)
        if base in NOT_SYMBOLS:
            continue
        if sub.startswith("_") and not sub.startswith("_{"):
            sub = "_{" + sub[1:] + "}"
        if sub.startswith("_{"):
            inner = sub[2:-1].strip()
            sub = "_{" + inner + "}" if inner else ""
        found.add(base + sub + ("^*" if mark == "^*" else ""))
    return found


def _tables(text: str, header: str) -> Iterator[list[str]]:
    """The rows (cells) of every pipe table of ``text`` whose header row starts ``header``."""
    inside = False
    for line in text.splitlines():
        if line.startswith(header):
            inside = True
            continue
        if inside and line.startswith("|"):
            if not set(line) <= set("|-: "):
                yield [cell.strip() for cell in line.strip().strip("|").split("|")]
        else:
            inside = False


def declared_symbols() -> set[str]:
    """Every symbol of the first column of the notation page's symbol tables."""
    symbols = set()
    for row in _tables(NOTATION.read_text(encoding="utf-8"), "| symbol | meaning |"):
        for math in re.findall(r"\$([^$]+)\$", row[0]):
            symbols |= atoms(math)
    return symbols


def math_of(text: str) -> list[str]:
    """The inline and display math of Markdown (code spans left out)."""
    text = re.sub(r"`[^`\n]*`", " ", text)
    text = re.sub(
        r"\$\$(.*?)\$\$", lambda m: "$" + m.group(1).replace("$", " ") + "$", text, flags=re.S
    )
    return re.findall(r"\$([^$]+)\$", text)


def strings_of(source: str) -> list[str]:
    """The string literals of Python code (f-strings' literal parts), magics left out."""
    code = "\n".join(
        line for line in source.splitlines() if not line.lstrip().startswith(("%", "!"))
    )
    try:
        tree = ast.parse(code)
    except SyntaxError:
        return [source]
    return [
        n.value for n in ast.walk(tree) if isinstance(n, ast.Constant) and isinstance(n.value, str)
    ]


def chapter_texts() -> Iterator[tuple[str, str, str]]:
    """``(where, kind, text)`` of every chapter cell: markdown, or a code cell's strings."""
    for path in CHAPTERS:
        for k, cell in enumerate(json.loads(path.read_text(encoding="utf-8"))["cells"]):
            source = "".join(cell["source"])
            where = f"{path.stem}, cell {k}"
            if cell["cell_type"] == "markdown":
                yield where, "markdown", source
            elif cell["cell_type"] == "code":
                for text in strings_of(source):
                    yield where, "code", text


def library_texts() -> Iterator[tuple[str, str]]:
    """``(where, text)`` of every string literal (docstrings included) of the library."""
    for path in LIBRARY:
        for text in strings_of(path.read_text(encoding="utf-8")):
            yield str(path.relative_to(ROOT)), text


def test_the_atoms_of_a_formula() -> None:
    assert atoms(r"F_c / P") == {"F_{c}", "P"}
    assert atoms(r"\mathrm{DAF}_d = A_v + \frac{48}{\pi^4}\, \eta") == {"DAF_{d}", "A_{v}", r"\eta"}
    assert atoms(r"m^* \ddot z_b + c^* \dot z_b") == {"m^*", "z_{b}", "c^*"}
    assert atoms(r"\mathbf{A}_{\text{off}} z_1") == {"A", "z_{1}"}
    assert atoms(r"P L^3 / (48 EI)") == {"P", "L", "EI"}


def test_every_symbol_on_a_page_is_declared_on_the_notation_page() -> None:
    declared = declared_symbols()
    assert len(declared) > 100, "the notation page's symbol tables were not read"
    undeclared: dict[str, str] = {}
    for where, kind, text in chapter_texts():
        pieces = math_of(text)
        for math in pieces:
            for symbol in atoms(math) - declared:
                undeclared.setdefault(symbol, f"{where} ({kind}): ${math.strip()[:60]}$")
    for page in PAGES:
        for math in math_of(page.read_text(encoding="utf-8")):
            for symbol in atoms(math) - declared:
                undeclared.setdefault(symbol, f"{page.name}: ${math.strip()[:60]}$")
    assert not undeclared, "symbols the notation page does not declare:\n" + "\n".join(
        f"  {s}: {w}" for s, w in sorted(undeclared.items())
    )


# ------------------------------------------------------------------ symbols kept apart
#: One detector per row of the notation page's table "Symbols kept apart", keyed by the
#: row's first two cells, and whether it applies to the library's docstrings too.
DETECTORS: dict[tuple[str, str], tuple[re.Pattern[str], bool]] = {
    ("$R$", "the contact force (the study)"): (
        re.compile(
            r"\$R\$|\$R = |\bR = m_v|\bmin R\b|\bR ?/ ?(?:W|weight)\b|contact force \$?R\b"
            r"|\bR_a\b|\$R_a|:math:`R_?a?\b(?!\^)"
        ),
        True,
    ),
    ("$R$", "a response (the study's $R_{dyn}$, $R_{sta}$)"): (
        re.compile(r"R_\{?(?:dyn|sta)\b|R_\\mathrm\{(?:dyn|sta)"),
        True,
    ),
    ("$W$", "a vehicle's weight"): (
        re.compile(r"(?<![\w.])\d+(?:\.\d+)? W\b(?![\w(=-])|(?:F_c|R) ?/ ?W\b|\bover W\b"),
        True,
    ),
    ("$r$", "the inertia ratio (the study)"): (re.compile(r"\br = m_b|\$r\$ = "), True),
    ("$n$", "the number of a mode"): (
        re.compile(r"n\^2 ?\\pi|mode \$n\$|\$\\phi_n|\\omega_n\b|\$q_n"),
        False,
    ),
    ("$w$", "the waviness (ISO 8608)"): (re.compile(r"\$w\$|\$w = |\bw = \d|\(w = \d"), False),
    ("$s$", "an axle spacing"): (
        re.compile(r"axle spacing \$?s\b|\bs f_?1 ?/ ?v|\$s f_1|\bs = .{0,40}spacing"),
        False,
    ),
    ("$\\varphi$", "a road's random phases"): (re.compile(r"\\varphi"), True),
    ("$\\lambda$", "a beam mode's wavenumber"): (
        re.compile(r"\\lambda_[kn]\b|\\lambda L\b"),
        False,
    ),
}


def kept_apart() -> list[tuple[str, str]]:
    rows = _tables(NOTATION.read_text(encoding="utf-8"), "| elsewhere | for |")
    return [(row[0], row[1]) for row in rows]


def test_every_symbol_kept_apart_has_a_detector() -> None:
    rows = kept_apart()
    assert rows, "book/notation.md has no table 'Symbols kept apart' (| elsewhere | for | ...)"
    assert set(rows) == set(DETECTORS), (
        "the notation page's 'Symbols kept apart' and this test's DETECTORS differ: "
        f"rows without a detector {sorted(set(rows) - set(DETECTORS))}, detectors without a "
        f"row {sorted(set(DETECTORS) - set(rows))}"
    )


@pytest.mark.parametrize("row", list(DETECTORS), ids=lambda r: f"{r[0]} for {r[1][:20]}")
def test_no_page_or_docstring_writes_a_symbol_kept_apart(row: tuple[str, str]) -> None:
    pattern, in_library = DETECTORS[row]
    found = []
    for where, _, text in chapter_texts():
        found += [f"{where}: ...{m.group(0)}..." for m in pattern.finditer(text)]
    for page in ALIAS_PAGES:
        found += [f"{page.name}: ...{m.group(0)}..." for m in pattern.finditer(page.read_text())]
    if in_library:
        for where, text in library_texts():
            found += [f"{where}: ...{m.group(0)}..." for m in pattern.finditer(text)]
    assert not found, f"{row[0]} for {row[1]} (this book writes otherwise):\n" + "\n".join(found)


def test_the_detectors_find_what_they_are_for() -> None:
    examples = {
        ("$R$", "the contact force (the study)"): "smallest axle force 0.27 of min R/W",
        ("$R$", "a response (the study's $R_{dyn}$, $R_{sta}$)"): "$R_{dyn}$",
        ("$W$", "a vehicle's weight"): "smallest axle force 0.27 W",
        ("$r$", "the inertia ratio (the study)"): "$r$ = the ratio",
        ("$n$", "the number of a mode"): r"ratio $12/(n^2\pi^2)$",
        ("$w$", "the waviness (ISO 8608)"): "class B (w = 2)",
        ("$s$", "an axle spacing"): "s f1 / v = 1.5",
        ("$\\varphi$", "a road's random phases"): r"$\varphi_i$",
        ("$\\lambda$", "a beam mode's wavenumber"): r"$\lambda_k L$",
    }
    for row, (pattern, _) in DETECTORS.items():
        assert pattern.search(examples[row]), row
    clean = "the contact force $F_c / P$, $R^2$ = 0.95, waviness $W$ = 2, a span of 100 W-beams"
    assert not any(pattern.search(clean) for pattern, _ in DETECTORS.values())


# ---------------------------------------------------------------- the study's numbers
LABELLED = re.compile(r"\$\$(?P<math>.*?)\$\$\s*\((?P<label>[\w-]+)\)", re.S)
TAG = re.compile(r"\(study (?P<numbers>[\d,\s\u2013-]+)\)")


def _numbers(tag: str) -> set[int]:
    found = set()
    for part in re.split(r",\s*", tag.strip()):
        ends = [int(x) for x in re.split(r"[\u2013-]", part) if x.strip()]
        found |= set(range(ends[0], ends[-1] + 1))
    return found


def test_every_restated_equation_shows_the_study_s_number() -> None:
    missing = []
    for path in CHAPTERS:
        for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
            if cell["cell_type"] != "markdown":
                continue
            for match in LABELLED.finditer("".join(cell["source"])):
                label = re.fullmatch(r"study-(\d+)(?:-\d+)*", match["label"])
                if not label:
                    continue
                tags = [_numbers(t["numbers"]) for t in TAG.finditer(match["math"])]
                if not any(int(label.group(1)) in numbers for numbers in tags):
                    missing.append(f"{path.stem}: ({match['label']})")
    assert not missing, "equations labelled with a study number but not showing it:\n" + "\n".join(
        missing
    )
