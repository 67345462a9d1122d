"""Study runner throughput and memory: python benchmarks/bench_studies.py [--quick].

1. 10 000 crossings of 100 ft spans on ISO 8608 roads sampled every 1 in (200 ft approach)
   with the default executor (the local process pool), pool start-up timed apart.
2. Throughput of one and two worker processes, and of this process alone.
3. Peak memory (this process and its workers) as the study grows: results are streamed
   chunk by chunk and no time history is kept, so it should stay flat.
"""

from __future__ import annotations

import concurrent.futures as cf
import multiprocessing
import os
import sys
import threading
import time

import psutil

from vbi_lib import studies
from vbi_lib import units as u


def scenarios(n: int, seed: int = 0):  # noqa: ANN201
    """``n`` crossings: the four Table 2.15.3 bridges, four trucks, random roads and speeds."""
    return studies.monte_carlo(
        studies.parametric_bridges(),
        studies.parametric_trucks(),
        n,
        speed_range=(40 * u.mph, 75 * u.mph),
        c10_range=(16e-6, 300e-6),
        offset_range=(0.0, 20 * u.ft),
        approach=200 * u.ft,
        spacing=1 * u.inch,
        n_profiles=max(1, n // 25),
        seed=seed,
    )


class PeakMemory:
    """Largest resident memory of this process plus its children, sampled every 20 ms."""

    def __enter__(self) -> PeakMemory:
        self.peak = 0
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._watch, daemon=True)
        self._thread.start()
        return self

    def _watch(self) -> None:
        me = psutil.Process()
        while not self._stop.is_set():
            total = me.memory_info().rss
            for child in me.children(recursive=True):
                try:
                    total += child.memory_info().rss
                except psutil.Error:
                    pass
            self.peak = max(self.peak, total)
            time.sleep(0.02)

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        self._thread.join()


def children_cpu() -> float:
    """CPU seconds (user + system) used so far by this process's live children."""
    total = 0.0
    for child in psutil.Process().children(recursive=True):
        try:
            times = child.cpu_times()
            total += times.user + times.system
        except psutil.Error:
            pass
    return total


def timed(table, executor, **kwargs) -> float:  # noqa: ANN001
    start = time.perf_counter()
    studies.run(table, executor, progress=False, **kwargs)
    return time.perf_counter() - start


def main() -> None:
    quick = "--quick" in sys.argv
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"{os.cpu_count()} cores, load average {load} (other work shares the cores)")
    n_big = 1000 if quick else 10_000

    # 1. the headline: 10 000 crossings with the default executor
    table = scenarios(n_big)
    start = time.perf_counter()
    studies.default_executor()
    studies.run(scenarios(8, seed=99), studies.default_executor(), progress=False)
    warm = time.perf_counter() - start
    seconds = timed(table, None)
    print(f"default pool start-up (spawn, import, compile cache): {warm:.1f} s")
    print(
        f"{n_big} crossings, 100 ft spans, 1 in spacing, default executor: {seconds:.1f} s "
        f"({n_big / seconds:.0f} crossings/s); with start-up {seconds + warm:.1f} s"
    )

    # 2. scaling from one worker to two, and this process alone
    n = 400 if quick else 2000
    table = scenarios(n, seed=1)
    context = multiprocessing.get_context("spawn")
    rates = {}
    for workers in (1, 2):
        with cf.ProcessPoolExecutor(
            workers, mp_context=context, initializer=studies._init_worker
        ) as pool:
            studies.run(scenarios(4 * workers, seed=98), pool, progress=False, chunk_size=1)
            before = children_cpu()
            rates[workers] = n / min(timed(table, pool) for _ in range(3))
            per_cpu = 3 * n / (children_cpu() - before)
        print(
            f"{workers} worker(s): {rates[workers]:.0f} crossings/s (best of 3); "
            f"{per_cpu:.0f} crossings per worker CPU-second"
        )
    print(f"speed-up 1 -> 2 workers: {rates[2] / rates[1]:.2f}x")
    serial = n / min(timed(table, "serial") for _ in range(3))
    print(f"this process alone ('serial', numba threads): {serial:.0f} crossings/s (best of 3)")

    # 3. memory as the study grows
    for n in (500, 1000, 2000) if quick else (2500, 5000, 10_000, 20_000):
        table = scenarios(n, seed=2)
        with PeakMemory() as memory:
            seconds = timed(table, studies.default_executor())
        print(
            f"{n:6d} crossings: {seconds:5.1f} s, peak memory (parent + workers) "
            f"{memory.peak / 2**20:5.0f} MiB"
        )


if __name__ == "__main__":
    main()
