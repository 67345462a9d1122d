"""When a worker process of a study dies: what happened, and a pool to go on with.

A process pool breaks when one of its workers dies (``kill -9``, the out-of-memory killer, a
crash in compiled code): every chunk it held fails with ``BrokenProcessPool`` and the pool
takes no more work.  :func:`vbi_lib.studies.run` then runs each of those chunks once more,
one at a time, in a new pool of the same settings (:func:`replacement`); a chunk whose
worker dies again keeps NaN results and the reason (:func:`death_reason`) in ``error``.
Every finished row is kept.

The message says what happened: a worker died, with its exit status (signal 9, SIGKILL, is
what the out-of-memory killer sends).  It speaks of the ``if __name__ == "__main__":`` guard
only when the study runs from a script, in spawned workers, and the script has no such guard
(:func:`missing_guard`): then every worker dies as it starts, re-running the script.
"""

from __future__ import annotations

import concurrent.futures as cf
import signal
import sys
from typing import Any

from .._files import read_text

__all__ = [
    "death_reason",
    "exit_statuses",
    "lost_worker",
    "missing_guard",
    "processes",
    "replacement",
]

#: What the workers' exit statuses say, for a status of ``-signal``.
_SIGNALS = {
    signal.SIGKILL: "killed by signal 9 (SIGKILL), which is what the out-of-memory killer sends",
    signal.SIGSEGV: "crashed (signal 11, SIGSEGV: a fault in compiled code)",
    signal.SIGBUS: "crashed (signal 7, SIGBUS)",
    signal.SIGABRT: "aborted (signal 6, SIGABRT)",
}


def processes(pool: cf.Executor) -> dict[int, Any]:
    """The worker processes of a process pool by pid (empty for other executors)."""
    found = getattr(pool, "_processes", None)
    return dict(found) if isinstance(found, dict) else {}


def exit_statuses(workers: dict[int, Any]) -> list[str]:
    """How the workers that died ended, in words (those the pool stopped itself left out)."""
    out = []
    for pid, process in workers.items():
        code = getattr(process, "exitcode", None)
        if code is None or code == 0 or code == -signal.SIGTERM:
            continue  # alive, or stopped by the pool once it was broken
        if code < 0:
            words = _SIGNALS.get(-code, f"killed by signal {-code}")
        else:
            words = f"exited with status {code}"
        out.append(f"worker {pid} {words}")
    return out


def death_reason(statuses: list[str], again: bool) -> str:
    """The ``error`` of a chunk whose worker died (``again``: on its second run, alone)."""
    how = "; ".join(statuses) if statuses else "a worker process died"
    when = (
        "its worker process died while running it, and again when it ran alone"
        if again
        else "its worker process died while running it"
    )
    return (
        f"WorkerDied: {when} ({how}): perhaps out of memory; run the study with a smaller "
        "chunk_size or fewer workers, or find the row that needs the memory"
    )


def lost_worker(exc: BaseException) -> str | None:
    """The ``error`` of a chunk that a Dask cluster gave up on after its workers died
    (``KilledWorker``), else ``None``."""
    if type(exc).__name__ != "KilledWorker":
        return None
    return (
        f"WorkerDied: the cluster's workers died each time they ran it ({exc}): perhaps out of "
        "memory; run the study with a smaller chunk_size, or find the row that needs the memory"
    )


def missing_guard(pool: cf.Executor) -> str | None:
    """The script that runs the study, when spawned workers re-run it for want of an
    ``if __name__ == "__main__":`` guard (its source names no ``__main__``); else ``None``."""
    context = getattr(pool, "_mp_context", None)
    method = context.get_start_method() if context is not None else None
    if method == "fork":
        return None  # forked workers do not import the script
    main = sys.modules.get("__main__")
    script = getattr(main, "__file__", None)
    if not script:
        return None  # interactive or a notebook: workers do not re-run it
    try:
        text = read_text(script, "script", max_bytes=10 * 2**20)
    except (OSError, ValueError):
        return None
    return None if "__main__" in text else script


def replacement(pool: cf.Executor) -> cf.Executor:
    """A new process pool with the settings of the broken ``pool``: its number of workers,
    start method, initializer and its arguments."""
    return cf.ProcessPoolExecutor(
        max_workers=getattr(pool, "_max_workers", None),
        mp_context=getattr(pool, "_mp_context", None),
        initializer=getattr(pool, "_initializer", None),
        initargs=getattr(pool, "_initargs", ()),
    )
