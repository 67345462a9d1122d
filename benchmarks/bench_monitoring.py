"""Timings of the field-measurement tools (plain script: run it, read the numbers).

    .venv/bin/python benchmarks/bench_monitoring.py

Prints the median of repeated runs: the filter DAF of one event (cut-off given, and chosen
from a Welch estimate of the first frequency), the influence-line fit of one strain event
(speed given, and searched from 1 to 60 m/s), a crawl run lined up with a record, a day of
monitoring as one 2-D array of events, and a load-test table.
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


AXLES = mon.Axles(spacings=(4.3, 1.3), loads=(0.25, 1.0, 1.0))


def strain_event(seed: int, seconds: float = 10.0) -> np.ndarray:
    """Midspan moment of a three-axle truck at 25 m/s on a 30 m span, a 4 Hz ring, noise."""
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, seconds, 1.0 / FS)
    static = mon.influence_line(25.0 * (t - 1.5), 15.0, 30.0, axles=AXLES)
    ring = 0.15 * static.max() * np.exp(-0.5 * np.abs(t - 2.3)) * np.cos(2 * np.pi * 4 * t)
    return static + ring + 0.005 * static.max() * rng.standard_normal(t.size)


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

    strain = strain_event(0)
    print(f"one strain event: {strain.size} samples, three axles on a 30 m span")
    known = {"span": 30.0, "response": "strain", "axles": AXLES}
    t = median_time(lambda: mon.daf_from_record(strain, FS, speed=25.0, **known), 20)
    print(f"  influence-line fit, speed given          {t * 1e3:8.2f} ms")
    t = median_time(lambda: mon.daf_from_record(strain, FS, **known), 5)
    print(f"  influence-line fit, speed searched       {t * 1e3:8.2f} ms")
    crawl_time = np.arange(0.0, 80.0, 1 / 50.0)
    crawl = mon.influence_line(0.5 * (crawl_time - 5.0), 15.0, 30.0, axles=AXLES)
    crawl_known = {"crawl": crawl, "crawl_sample_rate_hz": 50.0, "crawl_speed": 0.5}
    t = median_time(lambda: mon.daf_from_record(strain, FS, speed=25.0, **crawl_known), 20)
    print(f"  crawl run lined up, speed given          {t * 1e3:8.2f} ms")

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
