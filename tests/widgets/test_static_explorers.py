"""The static book's explorers in Chromium, offline: they compute what vbi_lib computes.

The session's book build (``book_build`` in conftest) is served from 127.0.0.1 and every request
outside it is aborted.  On every page with an explorer (``[data-vbi-explorer]``) a key press on
``input[name=speed]`` must change the readout, the readout must equal ``vbi.simulate`` of the
explorer's ``settings()``, no request may leave the book and the console must hold no error.
On the chapter that holds the three, the controls must be honest: typed values refused with a
message (the display keeps the controls' value), percent boxes taking percent, the loss of
contact said in words, the link (the URL's hash) carrying the setting, the reset button, and
the report parameter file that vbi-report takes.

The DAF compared is the library's ``crossing.daf`` (whole run, each span over its own static;
the modal model by mode acceleration), which ``test_js_port`` also checks against a reference
built in the test from the library's histories.
"""

from __future__ import annotations

import json
import math
import os
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import test_book_browser as book_browser
import yaml
from conftest import BookBuild

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.reports import prepare, read_parameters

book_server = book_browser.book_server  # the built book on 127.0.0.1 (module scope)
#: The page's explorers have all computed (their readouts show a result).
READY = (
    "() => window.vbiExplorers && window.vbiExplorers.length && "
    "window.vbiExplorers.every(e => e.result)"
)


def library_crossing(settings: dict[str, Any]) -> vbi.Crossing:
    """``vbi.simulate`` of an explorer's ``settings()`` (the contract's SI JSON)."""
    b, v, road = settings["bridge"], settings["vehicle"], settings["road"]
    bridge = vbi.Bridge.continuous(b["spans"], EI=b["EI"], mass_per_length=b["mass_per_length"],
                                   damping_ratio=b["damping_ratio"])  # fmt: skip
    truck = vbi.Vehicle(v["mass"], v["stiffness"], v["damping"])
    profile = vbi.Profile(np.array(road["x"]), np.array(road["elevation"]))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        warnings.simplefilter("ignore", vbi.OutsideValidityWarning)
        return vbi.simulate(bridge, truck, profile, settings["speed"], settings["bridge_start"],
                            model=settings["model"], modes=settings["modes"],
                            coupled=settings["coupled"])  # fmt: skip


def expected_dafs(settings: dict[str, Any]) -> list[float]:
    return [float(d) for d in library_crossing(settings).daf]


def _browser_or_skip() -> None:
    missing = book_browser._browser_missing()
    if missing:
        if os.environ.get("CI") == "true":
            pytest.fail(f"CI runs the browser tests: {missing}")
        pytest.skip(missing)


class Offline:
    """One Chromium context on the served book: outside requests aborted, errors recorded."""

    def __init__(self, playwright: Any, server: str) -> None:
        self.server = server
        self.outside: list[str] = []
        self.errors: list[str] = []
        self.browser = playwright.chromium.launch(
            executable_path=str(book_browser.CHROMIUM), args=book_browser.CHROMIUM_ARGS
        )
        self.context = self.browser.new_context(
            viewport={"width": 1280, "height": 900}, service_workers="block", accept_downloads=True
        )
        self.context.route("**/*", self._route)

    def _route(self, route: Any) -> None:
        if route.request.url.startswith(self.server):
            route.continue_()
        else:
            self.outside.append(route.request.url)
            route.abort("blockedbyclient")

    def page(self, path: str) -> Any:
        page = self.context.new_page()
        page.on(
            "console",
            lambda m: self.errors.append(f"{path}: {m.text}") if m.type == "error" else None,
        )
        page.on("pageerror", lambda e: self.errors.append(f"{path}: uncaught {e}"))
        page.goto(self.server + path, wait_until="load")
        page.wait_for_function(READY, timeout=60_000)
        return page

    def close(self) -> None:
        self.browser.close()


def explorer_pages(html: Path) -> list[str]:
    """The pages that hold a static explorer's root (not those that only name it: the API)."""
    root = '<div class="vbi-page-explorer" data-vbi-explorer='
    return [p for p in book_browser.pages(html) if root in (html / p).read_text()]


def readout(page: Any, i: int) -> tuple[str, list[float]]:
    text, value = page.evaluate(
        """(i) => { const r = document.querySelectorAll('[data-vbi-explorer]')[i]
                    .querySelector('[data-vbi-readout=daf]');
                    return [r.textContent, r.dataset.value]; }""",
        i,
    )
    return text, [math.nan if d is None else d for d in json.loads(value)]


def _close(a: list[float], b: list[float], rtol: float = 1e-9) -> bool:
    return len(a) == len(b) and all(
        (math.isnan(x) and math.isnan(y)) or abs(x - y) <= rtol * max(abs(x), abs(y))
        for x, y in zip(a, b, strict=True)
    )


def daf_words(dafs: list[float]) -> str:
    """The readout's words for these DAFs (as vbi_lib.widgets.readouts.daf_text writes them)."""
    if len(dafs) == 1:
        return f"DAF {dafs[0]:.3f}"
    return "DAF " + ", ".join(f"{d:.3f} (span {j + 1})" for j, d in enumerate(dafs))


# ---------------------------------------------------------------------------- every page
def test_every_explorer_answers_a_key_press_as_the_library_computes(
    book_build: BookBuild, book_server: str
) -> None:
    _browser_or_skip()
    from playwright.sync_api import sync_playwright

    html = book_build.require()
    found = explorer_pages(html)
    assert found, "no page of the book holds a static explorer"
    checked = 0
    with sync_playwright() as playwright:
        offline = Offline(playwright, book_server)
        try:
            for path in found:
                page = offline.page(path)
                count = page.locator("[data-vbi-explorer]").count()
                for i in range(count):
                    root = page.locator("[data-vbi-explorer]").nth(i)
                    before = readout(page, i)
                    speed = root.locator("input[name=speed]").first
                    speed.focus()
                    speed.press("ArrowRight")
                    page.wait_for_function(
                        """([i, before]) => document.querySelectorAll('[data-vbi-explorer]')[i]
                             .querySelector('[data-vbi-readout=daf]').dataset.value !== before""",
                        arg=[i, json.dumps([None if math.isnan(d) else d for d in before[1]])],
                        timeout=10_000,
                    )
                    text, shown = readout(page, i)
                    assert shown != before[1], f"{path} explorer {i}: the readout did not change"
                    settings = page.evaluate(f"window.vbiExplorers[{i}].settings()")
                    expected = expected_dafs(settings)
                    assert _close(shown, expected), f"{path} explorer {i}: {shown} != {expected}"
                    assert text == daf_words(expected), f"{path} explorer {i}: {text!r}"
                    checked += 1
                page.close()
        finally:
            offline.close()
    assert checked >= 3, f"only {checked} explorers checked"
    assert not offline.outside, f"requests outside the book: {sorted(set(offline.outside))}"
    assert not offline.errors, "console errors:\n" + "\n".join(offline.errors)


def test_the_explorers_weigh_little(book_build: BookBuild) -> None:
    """What the static explorers add to the book (the issue allows 1 MB): their scripts, uPlot,
    and the chapter's specification of the controls."""
    html = book_build.require()
    files = [*(html / "_static" / "vbi-explorers").iterdir(),
             *(html / "_static" / "vendor" / "uplot").iterdir()]  # fmt: skip
    assert sum(f.stat().st_size for f in files) < 200_000, [
        (f.name, f.stat().st_size) for f in files
    ]


# ---------------------------------------------------------------------------- honest controls
@pytest.fixture(scope="module")
def chapter(book_build: BookBuild, book_server: str) -> Any:
    _browser_or_skip()
    from playwright.sync_api import sync_playwright

    html = book_build.require()
    path = next(p for p in explorer_pages(html) if "07-your-own-bridge" in p)
    with sync_playwright() as playwright:
        offline = Offline(playwright, book_server)
        try:
            yield offline, path
        finally:
            offline.close()
    assert not offline.outside, f"requests outside the book: {sorted(set(offline.outside))}"
    assert not offline.errors, "console errors:\n" + "\n".join(offline.errors)


def _type(page: Any, name: str, text: str) -> None:
    box = page.locator(f"[data-vbi-explorer=crossing] input.vbi-typed[name={name}]")
    box.fill(text)
    box.press("Enter")


def _notice(page: Any) -> str:
    return page.locator("[data-vbi-explorer=crossing] [data-vbi-notice]").inner_text()


def test_bad_typed_values_are_refused_with_a_message_and_the_display_kept(chapter: Any) -> None:
    offline, path = chapter
    page = offline.page(path)
    start = readout(page, 0)
    for text, said in [
        ("abc", 'speed="abc" is not a number; the explorer keeps 41 mph'),
        ("1e9", "speed=1e9 mph is outside 5 to 100 mph; the explorer keeps 41 mph"),
        ("0", "speed=0 mph is outside 5 to 100 mph"),
        ("NaN", 'speed="NaN" is not a number'),
    ]:
        _type(page, "speed", text)
        page.wait_for_timeout(100)
        assert said in _notice(page), (text, _notice(page))
        assert readout(page, 0) == start
        box = page.locator("[data-vbi-explorer=crossing] input.vbi-typed[name=speed]")
        assert box.input_value() == "41"
        assert (
            page.locator("[data-vbi-explorer=crossing] input[type=range][name=speed]").input_value()
            == "41"
        )
    page.close()


def test_a_percent_box_takes_percent_and_the_setting_follows(chapter: Any) -> None:
    offline, path = chapter
    page = offline.page(path)
    _type(page, "bridge_damping", "2")
    page.wait_for_function(
        READY + " && window.vbiExplorers[0].settings().bridge.damping_ratio === 0.02"
    )
    settings = page.evaluate("window.vbiExplorers[0].settings()")
    assert settings["bridge"]["damping_ratio"] == pytest.approx(0.02)
    assert _close(readout(page, 0)[1], expected_dafs(settings))
    _type(page, "truck_damping", "15")
    page.wait_for_timeout(200)
    assert page.evaluate("window.vbiExplorers[0].settings()")["vehicle"][
        "damping"
    ] == pytest.approx(2 * 0.15 * settings["vehicle"]["mass"] * 2 * math.pi * 3.5, rel=1e-12)
    page.close()


def test_the_link_carries_the_setting_and_reset_restores_the_start(chapter: Any) -> None:
    offline, path = chapter
    page = offline.page(path)
    start = readout(page, 0)
    _type(page, "span", "120")
    page.locator("[data-vbi-explorer=crossing] input[name=n_spans][value='2']").check()
    page.wait_for_timeout(200)
    link = page.evaluate("window.location.hash")
    assert "crossing.span=120" in link and "crossing.n_spans=2" in link, link
    shared = offline.page(path + link)  # a reader opens the shared link
    settings = shared.evaluate("window.vbiExplorers[0].settings()")
    assert settings["bridge"]["spans"] == [120 * u.ft, 120 * u.ft]
    assert _close(readout(shared, 0)[1], expected_dafs(settings))
    shared.close()
    bad = offline.page(path + "#crossing.speed=900&crossing.road=gravel")
    words = bad.locator("[data-vbi-explorer=crossing] [data-vbi-notice]").inner_text()
    assert (
        "speed=900 mph is outside 5 to 100 mph" in words and 'road="gravel" is not offered' in words
    )
    assert readout(bad, 0) == start  # the refused values left the start setting
    bad.close()
    page.locator("[data-vbi-explorer=crossing] button.vbi-reset").click()
    page.wait_for_timeout(200)
    assert readout(page, 0) == start and "=" not in page.evaluate("window.location.hash")
    page.close()


def test_a_loss_of_contact_is_said_in_words_beside_the_daf(chapter: Any) -> None:
    offline, path = chapter
    page = offline.page(path)
    page.locator("[data-vbi-explorer=crossing] input[name=iso_class][value=E]").check()
    _type(page, "speed", "80")
    page.wait_for_timeout(300)
    contact = page.locator("[data-vbi-explorer=crossing] [data-vbi-readout=contact]").inner_text()
    settings = page.evaluate("window.vbiExplorers[0].settings()")
    crossing = library_crossing(settings)
    assert crossing.lost_contact, "pick a setting that loses contact"
    assert "the tyre would leave the road" in contact and "outside the model's validity" in contact
    assert f"{crossing.min_contact_force_ratio:.2f} × the weight" in contact
    page.close()


def test_the_page_writes_a_report_parameter_file_vbi_report_takes(
    chapter: Any, tmp_path: Path
) -> None:
    offline, path = chapter
    page = offline.page(path)
    page.locator("[data-vbi-explorer=crossing] button.vbi-report").click()
    link = page.locator("[data-vbi-explorer=crossing] a.vbi-download").first
    with page.expect_download() as download:
        link.click()
    target = tmp_path / download.value.suggested_filename
    download.value.save_as(target)
    inputs = prepare(read_parameters(yaml.safe_load(target.read_text()), base_dir=tmp_path))
    settings = page.evaluate("window.vbiExplorers[0].settings()")
    assert inputs.bridge.EI == pytest.approx(settings["bridge"]["EI"], rel=1e-9)
    assert inputs.vehicle.stiffness == pytest.approx(settings["vehicle"]["stiffness"], rel=1e-9)
    assert inputs.speeds == pytest.approx((settings["speed"],), rel=1e-9)
    page.close()
