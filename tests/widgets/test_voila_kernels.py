"""``make explore`` in Chromium: kernels of closed pages are culled, nothing comes from a CDN.

Voila starts a kernel (some 450 MB) for every page load and cannot shut it down when the tab
closes (its shutdown request is refused, voila#1458); ``make explore`` culls kernels that are
idle with no page connected (issue 25).  Here the cull timings are shortened
(``EXPLORE_IDLE``, ``EXPLORE_CULL``), one page stays open throughout, ten more are
loaded until their explorers answer and closed, and once the cull interval has passed at most
one kernel is left: the open page's, which still answers its slider.  ``EXPLORE_OPTIONS``
passes the app's theme, which the page shows.  Every request for a
URL outside the app is blocked and must not happen (Voila's template links Font Awesome from
a CDN; the vbi template drops the links).
"""

from __future__ import annotations

import time

import psutil
import test_explorer_browser as live
from test_explorer_browser import LOAD_TIMEOUT, free_port, nudge_speed_and_check, running

browser = live.browser  # the module-scoped Chromium of the live explorers' browser tests

#: Seconds a kernel may stay idle with no page before it is culled, and the cull interval.
IDLE, INTERVAL = 4, 2
LOADS = 10


def kernels(pid: int) -> list[psutil.Process]:
    """The kernels the server started (its ipykernel descendants)."""
    try:
        children = psutil.Process(pid).children(recursive=True)
    except psutil.NoSuchProcess:
        return []
    found = []
    for child in children:
        try:
            if any("ipykernel" in part for part in child.cmdline()):
                found.append(child)
        except psutil.Error:
            continue
    return found


def wait_for_daf(page: object) -> None:
    page.wait_for_function(
        "document.querySelector('.vbi-readout') && "
        "document.querySelector('.vbi-readout').innerText.includes('DAF')",
        timeout=LOAD_TIMEOUT * 1000,
    )


def test_closed_pages_leave_no_kernel_behind_and_nothing_comes_from_a_cdn(browser: object) -> None:
    port = free_port()
    command = [
        *("make", "explore", f"PORT={port}", f"EXPLORE_IDLE={IDLE}", f"EXPLORE_CULL={INTERVAL}"),
        "EXPLORE_OPTIONS=--VoilaConfiguration.theme=dark",
    ]
    outside: list[str] = []
    with running(command) as server:
        url = server.wait_for_line(r"vbi explorers: (http://127\.0\.0\.1:\d+/)").group(1)
        server.wait_until_answering(url)
        context = browser.new_context()

        def route(route_: object) -> None:
            if route_.request.url.startswith(url):
                route_.continue_()
            else:
                outside.append(route_.request.url)
                route_.abort("blockedbyclient")

        context.route("**/*", route)
        try:
            keeper = context.new_page()
            keeper.goto(url, timeout=LOAD_TIMEOUT * 1000)
            wait_for_daf(keeper)
            theme = keeper.evaluate("document.body.dataset.jpThemeName")
            assert theme == "JupyterLab Dark", f"EXPLORE_OPTIONS did not reach Voila: {theme}"
            most = 0
            for _ in range(LOADS):
                page = context.new_page()
                page.goto(url, timeout=LOAD_TIMEOUT * 1000)
                wait_for_daf(page)
                most = max(most, len(kernels(server.process.pid)))
                page.close()
            # the closed pages' kernels go once idle for IDLE s, checked every INTERVAL s
            end = time.monotonic() + IDLE + 3 * INTERVAL + 30
            left = kernels(server.process.pid)
            while len(left) > 1 and time.monotonic() < end:
                time.sleep(1)
                left = kernels(server.process.pid)
            assert len(left) <= 1, (
                f"{len(left)} kernels left after {LOADS} loads and closes (at most {most} at "
                f"once); the server said:\n{server.log()}"
            )
            # the open page's kernel was not culled: its explorer still answers
            nudge_speed_and_check(keeper)
        finally:
            context.close()
    assert not outside, f"requests outside the app: {sorted(set(outside))}"
