"""Timings of the reports, start-up included, and of the static envelopes they stand on.

    .venv/bin/python benchmarks/bench_reports.py

Runs the command line ``python -m vbi_lib.reports`` as a user would, in a fresh process each
time, and prints wall time and CPU time (that process and its children: the kernel and
chromium) for

* one report of the study's case, HTML and PDF (``examples/generated-road.yaml``; target:
  at most 15 s wall);
* the three-span HS20 report, HTML and PDF (``examples/three-spans-hs20.yaml``: the rear
  spacing searched, both directions; target: at most 20 s wall);
* five parameter files in one command (one kernel) against five commands;

and, in this process, the whole-field static envelope of the HS20 over three spans (301
stations, both directions, both faces of each pier; target: under 1 s) against the
sampled-and-refined search it replaced.  One untimed run first lets numba write its
compiled kernels to disk, as any first use does.  The machine's load is printed: on a
shared machine the wall time is the CPU time stretched by it.
"""

from __future__ import annotations

import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _timing import alternating, report

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "generated-road.yaml"
THREE_SPANS = ROOT / "examples" / "three-spans-hs20.yaml"
I76 = ROOT / "examples" / "i76-span3.yaml"
REPEATS = 3


def run(arguments: list[str], cwd: Path) -> tuple[float, float]:
    """Wall and CPU time [s] of one command-line run (CPU of the process and its children)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(
        [sys.executable, "-m", "vbi_lib.reports", *arguments],
        cwd=cwd,
        capture_output=True,
        text=True,
    )
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise SystemExit(f"vbi-report failed: {done.stderr.strip()}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def best(arguments: list[str], cwd: Path) -> tuple[float, float, float]:
    """Median and best wall time, and median CPU time, over :data:`REPEATS` runs."""
    times = [run(arguments, cwd) for _ in range(REPEATS)]
    walls = [t[0] for t in times]
    return statistics.median(walls), min(walls), statistics.median(t[1] for t in times)


def envelopes() -> None:
    """The whole-field static envelope of the HS20 over three spans, both directions and
    faces, exact; against the sampled search on the same stations (one face, one way)."""
    import numpy as np

    from vbi_lib import units as u
    from vbi_lib.beam_statics import continuous_statics, envelope, field_envelope
    from vbi_lib.continuous_beams import support_stations

    spans = [90 * u.ft, 120 * u.ft, 90 * u.ft]
    ei = 2.8e13 * u.lbf * u.inch**2
    loads = [8 * u.kip, 32 * u.kip, 32 * u.kip]
    offsets = [0.0, 14 * u.ft, 28 * u.ft]
    exact = field_envelope(spans, ei, loads, offsets, count=301, direction="both")
    supports = support_stations(spans)
    few = np.linspace(0.0, supports[-1], 11)

    def sampled() -> None:
        def influence(a: np.ndarray) -> np.ndarray:
            statics = continuous_statics(few[None, :], a[:, None], spans, ei)
            return np.stack([-statics.deflection, statics.moment, statics.shear])

        envelope(influence, supports, few, np.array(loads), np.array(offsets))

    times = alternating(
        {
            "field": lambda: field_envelope(spans, ei, loads, offsets, count=301),
            "sampled": sampled,
        },
        5,
    )
    per_station = times["sampled"] / few.size
    report(
        f"whole-field static envelope, HS20 on three spans: {exact.sections.size} stations "
        "(each pier twice), both directions, exact (`bench_reports.py`)",
        "< 1 s",
        f"{times['field'] * 1e3:.0f} ms; the sampled search it replaced: "
        f"{per_station * 1e3:.0f} ms a station, {per_station * 301:.0f} s for 301 stations "
        "one way",
    )


def main() -> None:
    envelopes()
    pdf = [] if shutil.which("chromium") or os.environ.get("VBI_CHROMIUM") else ["--no-pdf"]
    kind = "HTML and PDF" if not pdf else "HTML only (no chromium here)"
    with tempfile.TemporaryDirectory() as folder:
        work = Path(folder)
        text = EXAMPLE.read_text()
        files = []
        for seed in range(1, 6):
            path = work / f"road-{seed}.yaml"
            path.write_text(text.replace("seed: 1 ", f"seed: {seed} "))
            files.append(path.name)
        out = ["--output-dir", "out", *pdf]
        run([files[0], *out], work)  # compiled kernels on disk, as after any first use
        run([str(THREE_SPANS), *out], work)
        wall, fastest, cpu = best([files[0], *out], work)
        report(
            f"one report, {kind}, `vbi-report` start-up included (`bench_reports.py`)",
            "<= 15 s",
            f"{wall:.1f} s wall (best {fastest:.1f} s), {cpu:.1f} s CPU "
            f"(command, kernel and chromium)",
        )
        wall, fastest, cpu = best([str(THREE_SPANS), *out], work)
        report(
            f"three-span HS20 report (governing rear spacing, both directions), {kind}, "
            "start-up included (`bench_reports.py`)",
            "<= 20 s",
            f"{wall:.1f} s wall (best {fastest:.1f} s), {cpu:.1f} s CPU "
            f"(command, kernel and chromium)",
        )
        if I76.is_file() and (ROOT.parent / "shared" / "data").is_dir():
            wall, cpu = run([str(I76), *out], work)
            print(f"  I-76 span 3: wall {wall:5.1f} s, CPU {cpu:5.1f} s")
        wall, cpu = run([*files, *out], work)
        separate = [run([name, *out], work) for name in files]
        wall5 = sum(t[0] for t in separate)
        cpu5 = sum(t[1] for t in separate)
        report(
            "five parameter files in one command (one kernel) / five commands",
            "",
            f"CPU {cpu:.0f} s / {cpu5:.0f} s; wall {wall:.0f} s / {wall5:.0f} s",
        )
    load = os.getloadavg()[0]
    print(f"(load average {load:.1f} on {os.cpu_count()} cores while measuring)")


if __name__ == "__main__":
    main()
