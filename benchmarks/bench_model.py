"""Speed of the two-degree-of-freedom model: one crossing, its overhead, batches (issue 12).

Run: ``.venv/bin/python benchmarks/bench_model.py``.  Medians of repeated runs after a
warm-up (numba compiles on first use and caches to disk); comparisons are measured in the
same run, the candidates called in turns, and the load is printed.
"""

from __future__ import annotations

from pathlib import Path

import numba
import numpy as np
from _timing import alternating, load, median_time, report

import vbi_lib as vbi
from vbi_lib import study_data as sd
from vbi_lib import units as u
from vbi_lib.models import one_coordinate
from vbi_lib.models.base import SUMMARY_SIZE
from vbi_lib.models.grid import node_grid

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "seed-study"

#: Biggs (1964) / Yang and Yau (1997): L 25 m, EI 8.323e9 N m^2, 2303 kg/m, 5750 kg on
#: 1595 kN/m, on a flat road sampled every 5 cm.
BIGGS_BRIDGE = vbi.Bridge(25.0, 1, 8.323e9, 2303.0, damping_ratio=0.0)
BIGGS_TRUCK = vbi.Vehicle(5750.0, 1595e3, 0.0)
BIGGS_ROAD = vbi.Profile.flat(25.0, 0.05)
BIGGS_SPEEDS = np.linspace(60.0, 120.0, 1000) * u.kph


def table_2_13_1_crossing() -> None:
    bridge = vbi.Bridge(100 * u.ft, 1, 7.5e12 * u.lbf * u.inch**2, 4.6 * u.kip / u.ft / u.g)
    truck = vbi.Vehicle.from_frequency(100 * u.slinch, 4.0, 0.10)
    rng = np.random.default_rng(0)
    x = np.arange(0.0, 650 * u.ft + 1e-9, 1 * u.inch)
    road = vbi.Profile(x, np.cumsum(rng.normal(0.0, 2e-4, x.size)))
    seconds = median_time(lambda: vbi.simulate(bridge, truck, road, 720 * u.inch, 320 * u.ft), 50)
    report(
        "one crossing, Table 2.13.1 scenario (650 ft of profile at 1 in, 720 in/s)",
        "<= 2 ms",
        f"{seconds * 1e3:.2f} ms",
    )


def overhead_of_simulate() -> None:
    """``simulate`` against its compiled kernel alone, Biggs' case at 100 km/h."""
    speed = 100 * u.kph
    setup = one_coordinate.OneCoordinate(BIGGS_BRIDGE, BIGGS_TRUCK, speed, 0.0, coupled=True,
                                         convective=True, modes=None)  # fmt: skip
    grid = node_grid(BIGGS_BRIDGE, BIGGS_ROAD, speed, 0.0, setup.default_time_step()[0], 25.0)
    n = grid.x.size
    states, contact, summary = np.empty((n, 4)), np.empty(n), np.empty(SUMMARY_SIZE)

    def kernel() -> None:
        for _ in range(100):
            one_coordinate._kernel(grid.x, grid.elevation, grid.span_of_step, setup.params, 1,
                                   True, True, states, contact, summary)  # fmt: skip

    def simulate() -> None:
        for _ in range(100):
            vbi.simulate(BIGGS_BRIDGE, BIGGS_TRUCK, BIGGS_ROAD, speed, 0.0)

    times = alternating({"kernel": kernel, "simulate": simulate}, 15)
    kernel_ms, simulate_ms = times["kernel"] * 10, times["simulate"] * 10
    overhead = simulate_ms - kernel_ms
    report(
        f"`simulate` beyond its compiled kernel, Biggs' case ({n - 1} RK4 steps)",
        "<= 0.1 ms",
        f"{overhead:.3f} ms ({simulate_ms:.3f} ms in all, kernel {kernel_ms:.3f} ms)",
    )


def batch_against_loop() -> None:
    """1000 crossings of Biggs' case at 60-120 km/h: simulate_many, a loop, 1 and 2 threads."""
    threads = numba.get_num_threads()
    damped = vbi.Vehicle(BIGGS_TRUCK.mass, BIGGS_TRUCK.stiffness,
                         2 * 0.1 * np.sqrt(BIGGS_TRUCK.stiffness * BIGGS_TRUCK.mass))  # fmt: skip
    for truck, label in ((BIGGS_TRUCK, "Biggs' case"), (damped, "10 % damped truck")):

        def loop(truck: vbi.Vehicle = truck) -> None:
            for speed in BIGGS_SPEEDS:
                vbi.simulate(BIGGS_BRIDGE, truck, BIGGS_ROAD, speed, 0.0)

        def batch(truck: vbi.Vehicle = truck, count: int = threads) -> None:
            numba.set_num_threads(count)
            vbi.simulate_many(BIGGS_BRIDGE, truck, BIGGS_ROAD, BIGGS_SPEEDS, 0.0)

        def one_thread(truck: vbi.Vehicle = truck) -> None:
            batch(truck, 1)

        times = alternating({"loop": loop, "batch": batch, "one": one_thread}, 5)
        numba.set_num_threads(threads)
        report(
            f"1000 crossings at 60-120 km/h, {label}: `simulate_many` against a loop of `simulate`",
            ">= 20x" if truck is BIGGS_TRUCK else "",
            f"{times['batch'] * 1e3:.1f} ms against {times['loop'] * 1e3:.0f} ms "
            f"({times['loop'] / times['batch']:.0f}x)",
        )
        report(
            f"the same batch, 1 against {threads} numba threads",
            "",
            f"{times['one'] * 1e3:.1f} / {times['batch'] * 1e3:.1f} ms "
            f"({times['one'] / times['batch']:.2f}x)",
        )


def assessment_set() -> None:
    table, profiles = sd.read_assessment_set(DATA)
    bridges, vehicles, roads = sd.assessment_inputs(table, profiles, beam="study")

    def run() -> None:
        import warnings

        with warnings.catch_warnings():
            warnings.simplefilter("ignore", vbi.ContactLossWarning)
            vbi.simulate_many(bridges, vehicles, roads, sd.ASSESSMENT_SPEED,
                              sd.ASSESSMENT_BRIDGE_START)  # fmt: skip

    seconds = median_time(run, 7)
    report(
        f"the study's {len(table)}-scenario assessment set, 2-DOF model (`simulate_many`)",
        "<= 50 ms",
        f"{seconds * 1e3:.0f} ms",
    )


if __name__ == "__main__":
    print(f"{load()}; numba threads: {numba.get_num_threads()}", flush=True)
    table_2_13_1_crossing()
    overhead_of_simulate()
    batch_against_loop()
    if DATA.is_dir():
        assessment_set()
    else:
        print(f"no data at {DATA}: assessment-set benchmark skipped")
    print(f"at the end: {load()}")
