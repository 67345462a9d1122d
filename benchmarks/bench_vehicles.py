"""Speed of the general-vehicle kernels: a quarter car, the HS20 truck, the study's set on tyres.

Run: ``.venv/bin/python benchmarks/bench_vehicles.py``.  Prints the median of repeated runs
after a warm-up (numba compiles on first use and caches to disk).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
from _timing import median_time

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.study_data import assessment_inputs

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "seed-study"


def table_2_13_1_crossings() -> None:
    bridge = vbi.Bridge(100 * u.ft, 1, 7.5e12 * u.lbf * u.inch**2, 4.6 * u.kip / u.ft / u.g)
    sprung = vbi.Vehicle.from_frequency(100 * u.slinch, 4.0, 0.10)
    trucks = {
        "sprung mass": sprung,
        "quarter car": vbi.QuarterCar.from_vehicle(sprung, 0.1 * sprung.mass, 3.5e6, 4e3),
        "HS20, tyres": vbi.vehicles.hs20(),
        "HS20 rigid, tyres": vbi.vehicles.hs20(body="rigid"),
    }
    road = vbi.Profile.iso8608(700 * u.ft, 1 * u.inch, c10=64e-6, seed=1)
    for name, truck in trucks.items():
        for model, modes in (("one-coordinate", None), ("modal", 5)):
            seconds = median_time(
                lambda t=truck, m=model, n=modes: vbi.simulate(
                    bridge, t, road, 720 * u.inch, 320 * u.ft, model=m, modes=n
                ),
                10,
            )
            print(f"Table 2.13.1 beam, {name:18s} {model:14s}: {seconds * 1e3:.2f} ms")


def assessment_set_on_tyres(model: str, modes: int | None) -> tuple[float, int]:
    """The study's 239 crossings with each truck put on an axle (10 % of it) and a tyre."""
    import pandas as pd

    table = pd.read_csv(DATA / "scenarios-239.csv")
    profiles = {}
    for name in table.profile.unique():
        data = np.loadtxt(DATA / "profiles" / name, delimiter=",")
        profiles[name] = vbi.Profile(data[:, 0] * u.inch, (data[:, 1] - data[0, 1]) * u.inch)
    bridges, trucks, roads = assessment_inputs(table, profiles)
    cars = [vbi.QuarterCar.from_vehicle(t, 0.1 * t.mass, 3.5e6, 4e3) for t in trucks]

    def run() -> None:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", vbi.ContactLossWarning)
            vbi.simulate_many(bridges, cars, roads, 720 * u.inch, 3840 * u.inch, model=model,
                              modes=modes)  # fmt: skip

    return median_time(run, 3), len(table)


if __name__ == "__main__":
    table_2_13_1_crossings()
    if DATA.is_dir():
        for model, modes in (("one-coordinate", None), ("modal", 5)):
            seconds, n = assessment_set_on_tyres(model, modes)
            print(f"{n} crossings of the study's set as quarter cars, {model}: {seconds:.3f} s")
    else:
        print(f"no data at {DATA}: assessment-set benchmark skipped")
