"""Timings of the field-measurement tools (plain script: run it, read the numbers).

    .venv/bin/python benchmarks/bench_monitoring.py

Prints the median of repeated runs: the filter DAF of one event (cut-off given, and chosen
from a Welch estimate of the first frequency), a day of monitoring as one 2-D array of
events, and a load-test table.
"""

from __future__ import annotations

import warnings

import numpy as np
from _timing import median_time, report

from vbi_lib import monitoring as mon

FS = 200.0


def event(seed: int, duration: float = 1.2, f1: float = 4.0, seconds: float = 10.0) -> np.ndarray:
    """A half-sine pulse plus a decaying ring and noise, ``seconds`` long at ``FS``."""
    rng = np.random.default_rng(seed)
    t = np.arange(-2.0, seconds - 2.0, 1.0 / FS)
    pulse = np.where((t > 0) & (t < duration), np.sin(np.pi * t / duration), 0.0)
    ring = 0.2 * np.exp(-0.25 * np.abs(t - duration / 2)) * np.cos(2 * np.pi * f1 * t)
    return -(pulse + ring) + 0.01 * rng.standard_normal(t.size)


def main() -> None:
    one = event(0)
    print(f"one event: {one.size} samples ({one.size / FS:.0f} s at {FS:.0f} Hz)")
    t = median_time(lambda: mon.daf_from_record(one, FS, cutoff_hz=2.0), 50)
    print(f"  daf_from_record, cut-off given          {t * 1e3:8.2f} ms")
    t = median_time(lambda: mon.daf_from_record(one, FS, speed=25.0, span=30.0), 50)
    print(f"  daf_from_record, f1 by Welch, cut-off chosen {t * 1e3:8.2f} ms")
    report(
        "DAF of one 10 s record (2000 samples), cut-off chosen from the record", "",
        f"{t * 1e3:.1f} ms",
    )  # fmt: skip

    events = np.array([event(seed) for seed in range(1000)])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t = median_time(lambda: mon.daf_from_record(events, FS, speed=25.0, span=30.0), 3)
    print(f"1000 events (2-D array) -> RecordDAFs       {t:8.3f} s  ({t:.2f} ms per event)")

    line = np.sin(np.pi * np.linspace(0, 1, 2000))
    static = {f"G{g}": line for g in range(10)}
    dynamic = {v: {f"G{g}": [line * 1.1] * 5 for g in range(10)} for v in (10.0, 20.0, 30.0)}
    t = median_time(lambda: mon.daf_from_load_test(static, dynamic), 10)
    print(f"load test, 10 gauges x 3 speeds x 5 runs   {t * 1e3:8.2f} ms")


if __name__ == "__main__":
    main()
