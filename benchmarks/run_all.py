"""Run every benchmark script, one process each, and rewrite the book's Performance table.

``make benchmarks`` runs this.  Each script prints its results and records the rows it
reports (:func:`_timing.report`); the table between the ``benchmarks:start`` and
``benchmarks:end`` markers of the book's page ``book/performance.md`` is replaced by those
rows, with the date and the load before and after, so the page says what this machine
measured and under what load.
"""

from __future__ import annotations

import datetime
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
#: The book's page that holds the table.
PAGE = HERE.parent / "book" / "performance.md"
START, END = "<!-- benchmarks:start -->", "<!-- benchmarks:end -->"
#: The scripts, in the order of the table.
SCRIPTS = [
    "bench_model",
    "bench_modal",
    "bench_vehicles",
    "bench_bridges",
    "bench_studies",
    "bench_profiles",
    "bench_monitoring",
    "bench_reports",
    "bench_widgets",
]


def load() -> str:
    return " / ".join(f"{x:.1f}" for x in os.getloadavg())


def table(rows: list[dict[str, str]], before: str, after: str) -> str:
    when = datetime.date.today().isoformat()
    lines = [
        START,
        f"Measured by `make benchmarks` on {when}, {os.cpu_count()} cores, after numba's first "
        "compilation (cached on disk); medians of repeated runs. The machine is shared: load "
        f"average (1 / 5 / 15 min) {before} at the start, {after} at the end. Comparisons "
        "(batch against loop, threads, workers) are measured in turns in the same run.",
        "",
        "| what | target | measured |",
        "|---|---|---|",
    ]
    lines += [f"| {r['what']} | {r['target']} | {r['measured']} |" for r in rows]
    return "\n".join(lines + [END])


def main() -> None:
    before = load()
    rows: list[dict[str, str]] = []
    with tempfile.TemporaryDirectory() as folder:
        for name in SCRIPTS:
            print(f"== {name}.py", flush=True)
            record = Path(folder) / f"{name}.jsonl"
            env = os.environ | {"VBI_BENCH_ROWS": str(record)}
            subprocess.run([sys.executable, str(HERE / f"{name}.py")], check=True,
                           cwd=HERE.parent, env=env)  # fmt: skip
            if record.exists():
                rows += [json.loads(line) for line in record.read_text().splitlines()]
    text = PAGE.read_text()
    if START not in text or END not in text:
        raise SystemExit(f"{PAGE} has no {START} ... {END} markers; table not written")
    head, rest = text.split(START, 1)
    _, tail = rest.split(END, 1)
    PAGE.write_text(head + table(rows, before, load()) + tail)
    print(f"{PAGE.relative_to(HERE.parent)}: Performance table rewritten ({len(rows)} rows)")


if __name__ == "__main__":
    main()
