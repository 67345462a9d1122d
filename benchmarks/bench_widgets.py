"""How fast an explorer answers a slider (issue 15: one crossing <= 100 ms median, as seen).

Run: ``.venv/bin/python benchmarks/bench_widgets.py``.  Three measurements of the crossing
explorer's update when the speed slider moves, from the inside out:

1. in this process (the explorer's ``update``: one crossing, the lines' new data, one Agg
   draw and the PNG), with the study's sprung mass and with the quarter car;
2. in a real Jupyter kernel (``jupyter_client``), the control set as a message from the page
   would set it, the widget messages sent on the kernel's sockets;
3. in Chromium on the Voila app of ``make explore``: from the key press on the slider to the
   moment both the new figure and the new DAF readout are on the page (timed inside the
   page with ``performance.now()``), so the browser's round trip and rendering count.

The sweeps are timed in this process: a 36-speed sweep and a 13 x 15 frequency map.
Prints medians after a warm-up (compiled code loads on first use).
"""

from __future__ import annotations

import os
import re
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


if __name__ == "__main__":
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
