"""How fast an explorer answers a slider (issue 15: one crossing <= 100 ms median, as seen).

Run: ``.venv/bin/python benchmarks/bench_widgets.py`` (``--static``: the static book's
explorers only).  Three measurements of the crossing
explorer's update when the speed slider moves, from the inside out:

1. in this process (the explorer's ``update``: one crossing, the lines' new data, one Agg
   draw and the PNG), with the study's sprung mass and with the quarter car;
2. in a real Jupyter kernel (``jupyter_client``), the control set as a message from the page
   would set it, the widget messages sent on the kernel's sockets;
3. in Chromium on the Voila app of ``make explore``: from the key press on the slider to the
   moment both the new figure and the new DAF readout are on the page (timed inside the
   page with ``performance.now()``), so the browser's round trip and rendering count.

The sweeps are timed in this process: a 36-speed sweep and a 13 x 15 frequency map.

The static book's explorers (issue 25: within a frame, 16 ms, for the default crossing) are
timed in Chromium on the built book (``_build/html``, ``make book``; ``VBI_BOOK_HTML`` names
another build): from the key press on ``input[name=speed]`` to the end of the redraw (the
explorer's ``vbi-drawn`` event: the port's crossing, uPlot's two plots and the readout; the
recomputation waits for the next frame), and the work alone (the crossing and the redraw);
and the port's crossing alone in Node.
Prints medians after a warm-up (compiled code loads on first use).
"""

from __future__ import annotations

import functools
import http.server
import json
import os
import re
import shutil
import signal
import socket
import statistics
import subprocess
import sys
import threading
import time
import urllib.request
from pathlib import Path

from _timing import median_time, report

from vbi_lib.reports.printing import CHROMIUM_ARGS

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = Path("/usr/bin/chromium")
PRESSES = 30


def slider_moves(vehicle_type: str) -> tuple[float, float]:
    """Median time of a speed-slider move of the crossing explorer, and the share of full
    redraws, with the given truck model."""
    from vbi_lib.widgets import CrossingExplorer

    explorer = CrossingExplorer(vehicle_type=vehicle_type)
    # up and down the slider, 1 mph a step: the axes rescale now and then, as they do in use
    speeds = iter([41.0 + k for k in range(16)] * 2 + [56.0 - k for k in range(16)] * 2)

    def move() -> None:
        explorer.controls["speed_mph"].value = next(speeds)

    one = median_time(move, PRESSES)
    return one, explorer.view.full_draws / explorer.view.renders


def in_process() -> tuple[float, float, float, float, float]:
    from vbi_lib.widgets import FrequencyExplorer, SpeedExplorer

    one, full = slider_moves("sprung-mass")
    quarter, _ = slider_moves("quarter-car")
    sweep = SpeedExplorer()
    damping = iter([0.10, 0.11] * 100)
    speed = median_time(lambda: sweep.set(truck_damping=next(damping)), 5)
    heat = FrequencyExplorer()
    frequency = median_time(heat.update, 5)
    return one, full, quarter, speed, frequency


KERNEL_CODE = f"""
import statistics, time
from vbi_lib.widgets import CrossingExplorer
explorer = CrossingExplorer()
control = explorer.controls["speed_mph"]
times = []
for k in range({PRESSES + 1}):
    start = time.perf_counter()
    control.set_state({{"value": 41.0 + min(k, {PRESSES} - k)}})  # as the page would send it
    times.append(time.perf_counter() - start)
print("MEDIAN", statistics.median(times[1:]))
"""


def in_kernel() -> float:
    from jupyter_client.manager import start_new_kernel

    manager, client = start_new_kernel(kernel_name="python3", cwd=str(ROOT))
    try:
        out: list[str] = []

        def collect(message: dict) -> None:
            if message["msg_type"] == "stream":
                out.append(message["content"]["text"])
            elif message["msg_type"] == "error":
                out.append("\n".join(message["content"]["traceback"]))

        client.execute_interactive(KERNEL_CODE, output_hook=collect, timeout=600)
        text = "".join(out)
        match = re.search(r"MEDIAN ([0-9.eE+-]+)", text)
        if not match:
            raise RuntimeError(f"the kernel did not report a time:\n{text[-2000:]}")
        return float(match.group(1))
    finally:
        client.stop_channels()
        manager.shutdown_kernel(now=True)


PAGE_TIMER = """
() => {
  const readout = document.querySelector('.vbi-readout').parentElement;
  const image = document.querySelector('.vbi-figure');
  const handle = document.querySelector('.vbi-control-speed_mph .noUi-handle');
  window.vbiTimes = [];
  let pressed = null, readoutAt = null, imageAt = null;
  const done = () => {
    if (pressed !== null && readoutAt !== null && imageAt !== null) {
      window.vbiTimes.push(Math.max(readoutAt, imageAt) - pressed);
      pressed = readoutAt = imageAt = null;
    }
  };
  handle.addEventListener('keydown', () => { pressed = performance.now(); }, true);
  new MutationObserver(() => { if (pressed !== null) { readoutAt = performance.now(); done(); } })
    .observe(readout, {subtree: true, childList: true, characterData: true});
  new MutationObserver(() => { if (pressed !== null) { imageAt = performance.now(); done(); } })
    .observe(image, {attributes: true, attributeFilter: ['src']});
}
"""


def in_browser() -> float | None:
    if not CHROMIUM.exists():
        print(f"no {CHROMIUM}: the browser measurement is skipped (apt-get install -y chromium)")
        return None
    from playwright.sync_api import sync_playwright

    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    server = subprocess.Popen(
        ["make", "explore", f"PORT={port}"],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        start_new_session=True,
    )
    threading.Thread(target=lambda: server.stdout.read(), daemon=True).start()
    url = f"http://127.0.0.1:{port}/"
    try:
        for _ in range(600):
            try:
                urllib.request.urlopen(url, timeout=5).close()
                break
            except OSError:
                time.sleep(0.2)
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(
                executable_path=str(CHROMIUM), args=list(CHROMIUM_ARGS)
            )
            page = browser.new_page()
            page.goto(url, timeout=300_000)
            page.wait_for_function(
                "document.querySelector('.vbi-readout') && "
                "document.querySelector('.vbi-readout').innerText.includes('DAF')",
                timeout=300_000,
            )
            page.evaluate(PAGE_TIMER)
            handle = page.locator(".vbi-control-speed_mph .noUi-handle").first
            handle.focus()
            for k in range(PRESSES + 1):
                handle.press("ArrowRight" if k < PRESSES // 2 else "ArrowLeft")
                page.wait_for_function(f"window.vbiTimes.length >= {k + 1}", timeout=60_000)
            times = page.evaluate("window.vbiTimes")
            browser.close()
        return statistics.median(times[1:]) / 1e3
    finally:
        os.killpg(server.pid, signal.SIGTERM)
        server.wait(timeout=30)


STATIC_TIMER = """
() => {
  const root = document.querySelector('[data-vbi-explorer=crossing]');
  const slider = root.querySelector('input[type=range][name=speed]');
  window.vbiPress = { pressed: null, total: [], work: [] };
  slider.addEventListener('keydown', () => { window.vbiPress.pressed = performance.now(); }, true);
  root.addEventListener('vbi-drawn', (event) => {
    const press = window.vbiPress;
    if (press.pressed === null) return;
    press.total.push(event.detail.drawn - press.pressed);
    press.work.push(event.detail.compute + (event.detail.drawn - event.detail.computed));
    press.pressed = null;
  });
}
"""

NODE_TIMER = """
const m = require(process.argv[1]);
const d = JSON.parse(process.argv[2]);
for (const modes of [1, 10]) {
  const { setting } = m.scenarioSetting({ ...d, modes });
  for (let i = 0; i < 20; i++) m.simulate(setting);
  const times = [];
  for (let i = 0; i < 50; i++) {
    const t = process.hrtime.bigint();
    m.simulate(setting);
    times.push(Number(process.hrtime.bigint() - t) / 1e6);
  }
  times.sort((a, b) => a - b);
  console.log(JSON.stringify({ modes, ms: times[25] }));
}
"""


def static_in_node() -> dict[int, float]:
    """Median time of the port's default crossing in Node [ms], one-coordinate and 10 modes."""
    node = shutil.which("node")
    if node is None:
        return {}
    from dataclasses import asdict

    from vbi_lib.widgets import Scenario

    model = ROOT / "book" / "_static" / "vbi-explorers" / "vbi-model.js"
    out = subprocess.run([node, "-e", NODE_TIMER, str(model), json.dumps(asdict(Scenario()))],
                         capture_output=True, text=True, check=True)  # fmt: skip
    return {row["modes"]: row["ms"] for row in map(json.loads, out.stdout.split())}


def static_in_browser() -> tuple[float, float] | None:
    """Median key press to redraw, and the work alone, of the static crossing explorer [s]."""
    html = Path(os.environ.get("VBI_BOOK_HTML", ROOT / "_build" / "html"))
    page_path = "notebooks/07-your-own-bridge.html"
    if not CHROMIUM.exists() or not (html / page_path).is_file():
        print(f"no {html / page_path} or no chromium: the static explorer is not timed (make book)")
        return None
    from playwright.sync_api import sync_playwright

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args: object) -> None:
            pass

    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(Quiet, directory=str(html))
    )
    threading.Thread(target=server.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{server.server_address[1]}/"
    try:
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(
                executable_path=str(CHROMIUM), args=list(CHROMIUM_ARGS)
            )
            page = browser.new_page()
            page.route("**/*", lambda r: r.continue_() if r.request.url.startswith(base)
                       else r.abort("blockedbyclient"))  # fmt: skip
            page.goto(base + page_path)
            page.wait_for_function(
                "window.vbiExplorers && window.vbiExplorers.every(e => e.result)", timeout=60_000
            )
            page.evaluate(STATIC_TIMER)
            slider = page.locator("[data-vbi-explorer=crossing] input[type=range][name=speed]")
            slider.focus()
            for k in range(PRESSES + 1):
                slider.press("ArrowRight" if k < PRESSES // 2 else "ArrowLeft")
                page.wait_for_function(f"window.vbiPress.total.length >= {k + 1}", timeout=10_000)
            times = page.evaluate("window.vbiPress")
            browser.close()
    finally:
        server.shutdown()
    return statistics.median(times["total"][1:]) / 1e3, statistics.median(times["work"][1:]) / 1e3


if __name__ == "__main__":
    static = static_in_browser()
    node = static_in_node()
    if static is not None:
        total, work = static
        report(
            "static book's crossing explorer: speed slider key press to redraw in Chromium "
            "(the work alone: port + uPlot + readout)",
            "<= 16 ms (one frame)",
            f"{total * 1e3:.1f} ms ({work * 1e3:.1f} ms)",
        )
    if node:
        report(
            "the page's port, one default crossing in Node: one-coordinate / 10 modes",
            "-",
            f"{node[1]:.2f} / {node[10]:.2f} ms",
        )
    if "--static" in sys.argv:  # the static book's explorers only
        sys.exit(0)
    one, full, quarter, speed, frequency = in_process()
    print(
        f"crossing explorer, one slider move, in this process (Agg + PNG): {one * 1e3:.1f} ms "
        f"({full:.0%} of the updates redrew the whole figure)"
    )
    print(f"the same with the quarter car: {quarter * 1e3:.1f} ms")
    kernel = in_kernel()
    print(f"crossing explorer, one slider move, in a Jupyter kernel: {kernel * 1e3:.1f} ms")
    seen = in_browser()
    browser = "no chromium here" if seen is None else f"{seen * 1e3:.0f} ms median of {PRESSES}"
    report(
        "crossing explorer: speed slider moved, key press to new figure and DAF in Chromium "
        "(`make explore`)",
        "<= 100 ms median",
        f"{browser}; {kernel * 1e3:.0f} ms in the kernel",
    )
    report(
        "crossing explorer, one slider move in this process (Agg + PNG): sprung mass / quarter car",
        "<= 100 ms",
        f"{one * 1e3:.0f} / {quarter * 1e3:.0f} ms",
    )
    report(
        "speed explorer (36 speeds) / frequency map (13 x 15), one update",
        "progressive",
        f"{speed:.2f} s / {frequency:.2f} s",
    )
    sys.exit(0)
