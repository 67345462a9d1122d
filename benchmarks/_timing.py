"""Timing helpers shared by the benchmark scripts (run as ``python benchmarks/bench_*.py``).

The machine is shared: other work comes and goes while a benchmark runs.  So a comparison
(batch against loop, one thread against two, one worker against two) is measured in one
run, the candidates called in turns (:func:`alternating`), and every script states the load
(:func:`load`).  :func:`report` prints a result and, when ``run_all.py`` asks for it, records
it as a row of the Performance table (book/performance.md).
"""

from __future__ import annotations

import json
import os
import statistics
import time
from collections.abc import Callable

#: File ``run_all.py`` collects the rows in (one JSON object per line).
ROWS_FILE = os.environ.get("VBI_BENCH_ROWS")


def median_time(function: Callable[[], object], repeats: int) -> float:
    """Median wall time of ``repeats`` calls [s], after one warm-up call (numba compiles)."""
    function()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def alternating(functions: dict[str, Callable[[], object]], repeats: int) -> dict[str, float]:
    """Median wall time [s] of each function, the functions called in turns.

    After one warm-up call each, the functions run one after the other, ``repeats`` rounds,
    so a change of load on a shared machine falls on all of them alike; ratios of the
    medians compare them in the same conditions.
    """
    for function in functions.values():
        function()
    times: dict[str, list[float]] = {name: [] for name in functions}
    for _ in range(repeats):
        for name, function in functions.items():
            start = time.perf_counter()
            function()
            times[name].append(time.perf_counter() - start)
    return {name: statistics.median(values) for name, values in times.items()}


def load() -> str:
    """The load average now (1, 5 and 15 minutes) and the number of cores."""
    one, five, fifteen = os.getloadavg()
    return f"load average {one:.1f} / {five:.1f} / {fifteen:.1f} on {os.cpu_count()} cores"


def report(what: str, target: str, measured: str) -> None:
    """Print a result; under ``run_all.py``, record it as a row of the Performance table."""
    print(f"{what}: {measured}" + (f"  (target {target})" if target else ""), flush=True)
    if ROWS_FILE:
        with open(ROWS_FILE, "a") as rows:
            rows.write(json.dumps({"what": what, "target": target, "measured": measured}) + "\n")
