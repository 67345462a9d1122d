"""Speed of continuous bridges: their exact modes, a crossing, its sections and envelopes.

Run: ``.venv/bin/python benchmarks/bench_bridges.py``.  Prints the median of repeated runs
after a warm-up (numba compiles on first use and caches to disk).  The modes are cached per
bridge (``beam_modes`` is memoised), so the mode timing clears the cache on every call.
"""

from __future__ import annotations

from _timing import median_time

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.beam_statics import static_envelope
from vbi_lib.continuous_beams import _wavenumbers
from vbi_lib.modes import beam_modes

SPANS = [60 * u.ft, 80 * u.ft, 80 * u.ft, 60 * u.ft]
BRIDGE = vbi.Bridge.continuous(SPANS, EI=7.5e12 * u.lbf * u.inch**2,
                               mass_per_length=4.6 * u.kip / u.ft / u.g)  # fmt: skip
TRUCK = vbi.Vehicle.from_frequency(100 * u.slinch, 4.0, 0.10)
ROAD = vbi.Profile.iso8608(100.0 + BRIDGE.length + 1.0, 1 * u.inch, c10=16e-6, seed=1)
SECTIONS = [0.4 * SPANS[0], SPANS[0], SPANS[0] + SPANS[1] / 2, SPANS[0] + SPANS[1]]


def modes(count: int) -> float:
    def compute() -> None:
        beam_modes.cache_clear()
        _wavenumbers.cache_clear()
        beam_modes(BRIDGE, count)

    return median_time(compute, 5)


if __name__ == "__main__":
    for count in (5, 20, 60):
        print(f"exact modes of four unequal spans, {count:2d} modes: {modes(count) * 1e3:.1f} ms")
    for count in (5, 20):
        seconds = median_time(
            lambda c=count: vbi.simulate(
                BRIDGE, TRUCK, ROAD, 720 * u.inch, 100.0, model="modal", modes=c
            ),
            10,
        )
        print(f"one crossing of four spans at 720 in/s, {count:2d} modes: {seconds * 1e3:.1f} ms")
    run = vbi.simulate(BRIDGE, TRUCK, ROAD, 720 * u.inch, 100.0, model="modal", modes=10)
    seconds = median_time(lambda: run.sections(SECTIONS), 5)
    print(f"sections (4 sections, 3 effects, static envelope) of that crossing: {seconds:.3f} s")
    hs20 = ([8 * u.kip, 32 * u.kip, 32 * u.kip], [0.0, 14 * u.ft, 28 * u.ft])
    seconds = median_time(lambda: static_envelope(SPANS, BRIDGE.EI, SECTIONS, *hs20), 5)
    print(f"static envelope of an HS20 truck at 4 sections: {seconds:.3f} s")
