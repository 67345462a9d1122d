"""Study runner throughput and memory: python benchmarks/bench_studies.py [--quick].

1. 100 000 crossings of 100 ft spans on ISO 8608 roads sampled every 1 in (200 ft approach)
   with the default executor (the local process pool), pool start-up timed apart.
2. Throughput of one and two worker processes, measured in turns in the same run (the
   machine is shared: the load is printed), and of this process alone.
3. Peak memory (this process and its workers) as the study grows: results are streamed
   chunk by chunk and no time history is kept, so it should stay flat.
"""

from __future__ import annotations

import concurrent.futures as cf
import multiprocessing
import sys
import threading
import time

import psutil
from _timing import alternating, load, report

import vbi_lib as vbi
from vbi_lib import studies
from vbi_lib import units as u
from vbi_lib.studies.chunks import init_worker  # one numba thread per worker, as the pool


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


def count(n: int) -> str:
    """A whole number with thin groups of three digits: 100 000."""
    return f"{n:,}".replace(",", " ")


def timed(table, executor, **kwargs) -> float:  # noqa: ANN001
    start = time.perf_counter()
    studies.run(table, executor, progress=False, **kwargs)
    return time.perf_counter() - start


def main() -> None:
    import warnings

    warnings.simplefilter("ignore", vbi.ContactLossWarning)  # the tables say which crossings
    quick = "--quick" in sys.argv
    print(f"{load()} (other work shares the cores)", flush=True)
    n_big = 2000 if quick else 100_000

    # 1. the headline: a hundred thousand crossings with the default executor
    table = scenarios(n_big)
    start = time.perf_counter()
    studies.default_executor()
    studies.run(scenarios(8, seed=99), studies.default_executor(), progress=False)
    warm = time.perf_counter() - start
    seconds = timed(table, None)
    report(
        f"{count(n_big)} crossings of 100 ft spans at 1 in spacing, default executor "
        "(`studies.run`)",
        "<= 30 s",
        f"{seconds:.1f} s ({n_big / seconds:.0f} crossings/s); {seconds + warm:.1f} s with "
        "pool start-up",
    )

    # 2. one worker against two, in turns in the same run, on the study of a hundred
    # thousand crossings (a short study would time mostly the start and the last chunk);
    # this process alone
    n = 1000 if quick else n_big
    rounds = 3
    table = scenarios(n, seed=1)
    context = multiprocessing.get_context("spawn")
    pools = {
        workers: cf.ProcessPoolExecutor(workers, mp_context=context, initializer=init_worker)
        for workers in (1, 2)
    }
    try:
        for workers, pool in pools.items():  # start the workers and load the compiled code
            studies.run(scenarios(4 * workers, seed=98), pool, progress=False, chunk_size=1)
        before = children_cpu()
        runs = {w: (lambda p=p: timed(table, p)) for w, p in pools.items()}
        times = alternating(runs, rounds)
        per_cpu = 2 * (1 + rounds) * n / (children_cpu() - before)  # (warm-up + rounds) x 2
    finally:
        for pool in pools.values():
            pool.shutdown()
    rates = {workers: n / seconds for workers, seconds in times.items()}
    report(
        "study throughput with 1 and 2 worker processes (in turns, same run)",
        ">= 1.8x",
        f"{rates[1]:.0f} / {rates[2]:.0f} crossings/s ({rates[2] / rates[1]:.2f}x); "
        f"{per_cpu:.0f} crossings per worker CPU-second",
    )
    serial = n / min(timed(table, "serial") for _ in range(3))
    print(f"this process alone ('serial', numba threads): {serial:.0f} crossings/s (best of 3)",
          flush=True)  # fmt: skip

    # 3. memory as the study grows
    peaks = {}
    for n in (500, 1000, 2000) if quick else (2500, 5000, 10_000, 20_000):
        table = scenarios(n, seed=2)
        with PeakMemory() as memory:
            seconds = timed(table, studies.default_executor())
        peaks[n] = memory.peak / 2**20
        print(f"{n:6d} crossings: {seconds:5.1f} s, peak memory (parent + workers) "
              f"{peaks[n]:5.0f} MiB", flush=True)  # fmt: skip
    low, high = min(peaks), max(peaks)
    report(
        f"peak memory of a study at {count(low)} / {count(high)} crossings",
        "flat",
        f"{peaks[low]:.0f} / {peaks[high]:.0f} MiB (parent and workers)",
    )
    studies.shutdown_default_executor()
    print(f"at the end: {load()}")


if __name__ == "__main__":
    main()
