"""Timings of the reports, start-up included (plain script: run it, read the numbers).

    .venv/bin/python benchmarks/bench_reports.py

Runs the command line ``python -m vbi_lib.reports`` as a user would, in a fresh process each
time, and prints wall time and CPU time (that process and its children: the kernel and
chromium) for

* one report, HTML and PDF (target: at most 15 s wall);
* five parameter files in one command (one kernel) against five commands.

The parameter files are ``examples/generated-road.yaml`` with five seeds (no data needed);
when the study's data is beside the repository the issue's I-76 file is timed too.  One
untimed run first lets numba write its compiled kernels to disk, as any first use does.
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

from _timing import report

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "generated-road.yaml"
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


def main() -> None:
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
        wall, fastest, cpu = best([files[0], *out], work)
        report(
            f"one report, {kind}, `vbi-report` start-up included (`bench_reports.py`)",
            "<= 15 s",
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
