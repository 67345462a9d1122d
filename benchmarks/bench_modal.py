"""Speed of the many-mode model: one crossing with N modes, the 239-scenario set (issue 12).

Run: ``.venv/bin/python benchmarks/bench_modal.py``.  Prints the median of repeated runs after
a warm-up (numba compiles on first use and caches to disk) and the load.
"""

from __future__ import annotations

from pathlib import Path

from _timing import load, median_time, report

import vbi_lib as vbi
from vbi_lib import study_data as sd
from vbi_lib import units as u

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "seed-study"


def table_2_13_1_crossings() -> None:
    bridge = vbi.Bridge(100 * u.ft, 2, 7.5e12 * u.lbf * u.inch**2, 4.6 * u.kip / u.ft / u.g)
    truck = vbi.Vehicle.from_frequency(100 * u.slinch, 4.0, 0.10)
    road = vbi.Profile.iso8608(650 * u.ft, 1 * u.inch, c10=300e-6, waviness=2.0, seed=1)
    for modes in (1, 5, 20, 100):
        seconds = median_time(
            lambda m=modes: vbi.simulate(
                bridge, truck, road, 720 * u.inch, 320 * u.ft, model="modal", modes=m
            ),
            20,
        )
        print(f"one crossing, Table 2.13.1 two-span beam, {modes:3d} modes: {seconds * 1e3:.2f} ms")


def assessment_set(modes: int) -> tuple[float, int]:
    table, profiles = sd.read_assessment_set(DATA)
    bridges, trucks, roads = sd.assessment_inputs(table, profiles, beam="exact")
    speed, start = sd.ASSESSMENT_SPEED, sd.ASSESSMENT_BRIDGE_START

    def run() -> None:
        import warnings

        with warnings.catch_warnings():
            warnings.simplefilter("ignore", vbi.ContactLossWarning)
            vbi.simulate_many(bridges, trucks, roads, speed, start, model="modal", modes=modes)

    return median_time(run, 7), len(table)


if __name__ == "__main__":
    import numba

    print(f"{load()}; numba threads: {numba.get_num_threads()}", flush=True)
    table_2_13_1_crossings()
    if DATA.is_dir():
        seconds = {}
        for modes in (1, 5, 15):
            seconds[modes], n = assessment_set(modes)
            print(f"{n} crossings of the study's assessment set, {modes:2d} modes: "
                  f"{seconds[modes] * 1e3:.0f} ms", flush=True)  # fmt: skip
        report(
            f'the {n} scenarios with 5 modes (`simulate_many(model="modal")`)',
            "<= 150 ms",
            f"{seconds[5] * 1e3:.0f} ms (1 mode: {seconds[1] * 1e3:.0f} ms, "
            f"15 modes: {seconds[15] * 1e3:.0f} ms)",
        )
    else:
        print(f"no data at {DATA}: assessment-set benchmark skipped")
    print(f"at the end: {load()}")
