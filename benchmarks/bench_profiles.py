"""Timings of road generation and roughness metrics (plain script: run it, read the numbers).

Targets (issue 4): IRI of one mile sampled every 25 mm under 50 ms; a 650 ft ISO 8608 road at
1 in spacing under 50 ms.

    python benchmarks/bench_profiles.py
"""

from __future__ import annotations

import time

from _timing import report

import vbi_lib as vbi
from vbi_lib import units as u


def best_of(function, repeat: int = 20) -> float:
    """Smallest wall time of ``repeat`` calls [s] (after one warm-up call)."""
    function()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    mile = vbi.Profile.iso8608(1 * u.mile, 0.025, c10=256e-6, seed=1)
    start = time.perf_counter()
    vbi.iri(mile)
    first = time.perf_counter() - start
    seconds = best_of(lambda: vbi.iri(mile))
    print(
        f"IRI, one mile every 25 mm ({mile.x.size} samples): "
        f"{seconds * 1e3:.2f} ms (first call {first * 1e3:.0f} ms)"
    )
    report(
        "IRI of one mile sampled every 25 mm",
        "<= 50 ms",
        f"{seconds * 1e3:.1f} ms (first call {first * 1e3:.0f} ms: compiled code loaded)",
    )
    print(
        f"IRI per 100 m segment, same road: "
        f"{best_of(lambda: vbi.iri(mile, segment_length=100.0)) * 1e3:.2f} ms"
    )

    def study_road() -> vbi.Profile:
        return vbi.Profile.iso8608(650 * u.ft, 1 * u.inch, c10=300e-6, waviness=2, seed=1)

    seconds = best_of(study_road)
    print(f"ISO 8608 road, 650 ft every 1 in ({study_road().x.size} samples): "
          f"{seconds * 1e3:.2f} ms")  # fmt: skip
    report("a 650 ft ISO 8608 road at 1 in spacing", "<= 50 ms", f"{seconds * 1e3:.2f} ms")
    seconds = best_of(lambda: vbi.Profile.iso8608(1 * u.mile, 0.025, c10=256e-6, seed=1))
    print(f"ISO 8608 road, one mile every 25 mm: {seconds * 1e3:.2f} ms")
    road = study_road()
    print(f"ISO 8608 fit of that road: {best_of(lambda: vbi.fit_iso8608(road)) * 1e3:.2f} ms")
    truck = vbi.Vehicle.from_frequency(200 * u.slinch, 2.8, 0.2)
    seconds = best_of(
        lambda: vbi.contact_force_amplification(road, truck, 720 * u.inch, 320 * u.ft, 100 * u.ft)
    )
    print(f"contact-force amplification, 650 ft road, 100 ft span: {seconds * 1e3:.2f} ms")


if __name__ == "__main__":
    main()
