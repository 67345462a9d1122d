"""The built book in a real browser with the network blocked.

Every page of the session's book build (``book_build`` in conftest) is served from 127.0.0.1
by a server this module starts and stops, and opened in Debian's Chromium driven by
Playwright. Any request for a URL outside that server is blocked and recorded: the book must
render offline. On every page: no console error, no failed request, the math typeset by
MathJax (no raw TeX left) and no display equation wider than the text column (at the
1280 px window), and every saved ipywidgets view drawn as a widget (the explorers are static
ones, which compute in the page). A screenshot of
each page is kept in ``_build/screenshots/``.

Outside CI the test skips when Chromium or Playwright is missing; on CI (``CI=true``) it fails.
"""

from __future__ import annotations

import functools
import http.server
import os
import threading
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import pytest
from conftest import ROOT, BookBuild

from vbi_lib.reports import printing

if TYPE_CHECKING:
    from playwright.sync_api import Page, Route

CHROMIUM = Path("/usr/bin/chromium")
#: The same switches as the reports' PDF printer: headless, no sandbox, nothing fetched.
CHROMIUM_ARGS = list(printing.CHROMIUM_ARGS)
SCREENSHOTS = ROOT / "_build" / "screenshots"
WIDGET_VIEW = 'script[type="application/vnd.jupyter.widget-view+json"]'
#: Text of elements that show source on purpose (code, listings) is not checked for raw TeX.
RAW_TEX_CHECK = """() => {
  const skip = "PRE, CODE, SCRIPT, STYLE, TEXTAREA, MJX-CONTAINER";
  const walker = document.createTreeWalker(document.querySelector("main") || document.body,
                                           NodeFilter.SHOW_TEXT);
  const found = [];
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    if (node.parentElement.closest(skip)) continue;
    const text = node.textContent;
    for (const mark of ["$$", "\\\\begin{", "\\\\[", "\\\\(", "\\\\frac"]) {
      if (text.includes(mark)) found.push(text.trim().slice(0, 80));
    }
  }
  return found;
}"""


def _browser_missing() -> str | None:
    if not CHROMIUM.is_file():
        return f"no Chromium at {CHROMIUM} (apt-get install -y chromium)"
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        return "Playwright is not installed (make setup)"
    return None


@pytest.fixture(scope="module")
def book_server(book_build: BookBuild) -> Iterator[str]:
    """The built book served from 127.0.0.1 for this module's tests, then stopped."""
    html = book_build.require()
    handler = functools.partial(_QuietHandler, directory=str(html))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()
        thread.join(timeout=10)


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: object) -> None:  # noqa: A002
        pass


@dataclass
class PageReport:
    """What went wrong on one page."""

    path: str
    outside: list[str] = field(default_factory=list)
    failed: list[str] = field(default_factory=list)
    console: list[str] = field(default_factory=list)
    raw_tex: list[str] = field(default_factory=list)
    widgets: list[str] = field(default_factory=list)
    too_wide: list[str] = field(default_factory=list)

    def problems(self) -> list[str]:
        named = {
            "requests outside the book": self.outside,
            "failed requests": self.failed,
            "console errors": self.console,
            "raw TeX left": self.raw_tex,
            "widgets": self.widgets,
            "display equations wider than the text column": self.too_wide,
        }
        return [f"{self.path}: {name}: {items}" for name, items in named.items() if items]


#: Display equations whose typeset width runs past the text column (cut, or a scroll bar).
TOO_WIDE_CHECK = """() => [...document.querySelectorAll('div.math')]
    .filter(e => e.scrollWidth > e.clientWidth + 2)
    .map(e => `${e.id || '(no id)'}: ${e.scrollWidth - e.clientWidth} px too wide`)"""


def pages(html: Path) -> list[str]:
    """Every HTML page of the build, relative to its root (assets' folders left out)."""
    skip = {"_static", "_sources", "_images"}
    return sorted(
        p.relative_to(html).as_posix()
        for p in html.rglob("*.html")
        if not skip & set(p.relative_to(html).parts)
    )


def test_every_page_renders_offline(book_build: BookBuild, book_server: str) -> None:
    missing = _browser_missing()
    if missing:
        if os.environ.get("CI") == "true":
            pytest.fail(f"CI runs the browser tests: {missing}")
        pytest.skip(missing)
    from playwright.sync_api import TimeoutError as PlaywrightTimeout
    from playwright.sync_api import sync_playwright

    html = book_build.require()
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    reports: list[PageReport] = []
    math_pages = widget_pages = explorer_pages = 0
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(
            executable_path=str(CHROMIUM), args=CHROMIUM_ARGS, headless=True
        )
        try:
            context = browser.new_context(
                viewport={"width": 1280, "height": 900}, service_workers="block"
            )
            report = PageReport("")

            def route(route_: Route) -> None:
                url = route_.request.url
                if url.startswith(book_server):
                    route_.continue_()
                else:
                    report.outside.append(url)
                    route_.abort("blockedbyclient")

            context.route("**/*", route)
            page = context.new_page()
            page.on(
                "console",
                lambda m: report.console.append(m.text) if m.type == "error" else None,
            )
            page.on("pageerror", lambda e: report.console.append(f"uncaught: {e}"))
            page.on(
                "requestfailed",
                lambda r: (
                    report.failed.append(f"{r.url} ({r.failure})")
                    if r.url.startswith(book_server)
                    else None
                ),
            )
            page.on(
                "response",
                lambda r: (
                    report.failed.append(f"{r.url} (HTTP {r.status})") if r.status >= 400 else None
                ),
            )
            for path in pages(html):
                report = PageReport(path)
                reports.append(report)
                page.goto(book_server + path, wait_until="load")
                if page.locator(".math").count():
                    math_pages += 1
                    try:
                        page.wait_for_function(
                            "() => window.MathJax && MathJax.startup && MathJax.startup.promise",
                            timeout=10_000,
                        )
                        page.evaluate("() => MathJax.startup.promise")
                    except PlaywrightTimeout:
                        report.raw_tex.append("MathJax did not load")
                    untypeset = page.locator(".math:not(:has(mjx-container))").count()
                    if untypeset:
                        report.raw_tex.append(f"{untypeset} math elements not typeset")
                    report.raw_tex += page.evaluate(RAW_TEX_CHECK)
                    report.too_wide += page.evaluate(TOO_WIDE_CHECK)
                # the static explorers compute in the page (tests/widgets/test_static_explorers.py)
                explorer_pages += bool(page.locator("[data-vbi-explorer]").count())
                views = page.locator(WIDGET_VIEW).count()
                if views:
                    widget_pages += 1
                    _check_widgets(page, views, report, PlaywrightTimeout)
                page.wait_for_load_state("networkidle")
                name = path.removesuffix(".html").replace("/", "__") + ".png"
                page.screenshot(path=str(SCREENSHOTS / name), full_page=True)
        finally:
            browser.close()
    problems = [line for r in reports for line in r.problems()]
    assert not problems, "\n".join(problems)
    assert len(reports) > 10, f"only {len(reports)} pages found in {html}"
    assert math_pages, "no page with math: the MathJax check never ran"
    assert widget_pages or explorer_pages, "no page with an explorer: they are not in the book"


def _check_widgets(
    page: Page, views: int, report: PageReport, timeout_error: type[Exception]
) -> None:
    """Every saved view is drawn by the HTML manager from the page's saved widget state."""
    if not page.locator('script[type="application/vnd.jupyter.widget-state+json"]').count():
        report.widgets.append(f"{views} widget views but no saved widget state")
        return
    try:
        page.wait_for_function(
            f"() => document.querySelectorAll('.jupyter-widgets').length >= {views}",
            timeout=20_000,
        )
    except timeout_error:
        pass  # the views that did not appear are reported below
    # the manager draws each view beside its <script> tag, in the same cell output
    heights = page.evaluate(
        """(selector) => [...document.querySelectorAll(selector)].map((script) => {
             const box = script.parentElement.querySelector('.jupyter-widgets');
             return box ? box.getBoundingClientRect().height : 0;
           })""",
        WIDGET_VIEW,
    )
    empty = [i for i, height in enumerate(heights) if height <= 0]
    if empty:
        report.widgets.append(f"views {empty} of {views} not drawn")
