"""Speed of the two-degree-of-freedom model (issue: one crossing <= 2 ms, 239 crossings <= 0.5 s).

Run: ``.venv/bin/python benchmarks/bench_model.py``.  Prints the median of repeated runs after
a warm-up (numba compiles on first use and caches to disk).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from _timing import median_time

import vbi_lib as vbi
from vbi_lib import study_data as sd
from vbi_lib import units as u

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "seed-study"


def table_2_13_1_crossing() -> float:
    bridge = vbi.Bridge(100 * u.ft, 1, 7.5e12 * u.lbf * u.inch**2, 4.6 * u.kip / u.ft / u.g)
    truck = vbi.Vehicle(100 * u.slinch, 63165.5 * u.lbf / u.inch, 0.0)
    truck = vbi.Vehicle.from_frequency(truck.mass, truck.frequency_hz, 0.10)
    rng = np.random.default_rng(0)
    x = np.arange(0.0, 650 * u.ft + 1e-9, 1 * u.inch)
    road = vbi.Profile(x, np.cumsum(rng.normal(0.0, 2e-4, x.size)))
    return median_time(lambda: vbi.simulate(bridge, truck, road, 720 * u.inch, 320 * u.ft), 50)


def assessment_set() -> tuple[float, int]:
    table, profiles = sd.read_assessment_set(DATA)
    bridges, vehicles, roads = sd.assessment_inputs(table, profiles, beam="study")

    def run() -> None:
        vbi.simulate_many(bridges, vehicles, roads, sd.ASSESSMENT_SPEED, sd.ASSESSMENT_BRIDGE_START)

    return median_time(run, 5), len(table)


if __name__ == "__main__":
    one = table_2_13_1_crossing()
    print(f"one crossing, Table 2.13.1 scenario (650 ft at 1 in, 720 in/s): {one * 1e3:.2f} ms")
    if DATA.is_dir():
        seconds, n = assessment_set()
        print(f"{n} crossings of the study's assessment set (simulate_many): {seconds:.3f} s")
    else:
        print(f"no data at {DATA}: assessment-set benchmark skipped")
