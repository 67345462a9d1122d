"""Sweeps that show their progress: many crossings in chunks, the figure redrawn between them.

A sweep runs :func:`vbi_lib.simulate_many` (compiled, parallel) on a chunk of crossings at a
time.  Between chunks the explorer may draw what is done (at most every ``interval``
seconds, so a fast sweep draws once), so a long sweep fills the figure progressively instead
of leaving the page unchanged until it ends.
"""

from __future__ import annotations

import time
import warnings
from collections.abc import Callable, Sequence
from dataclasses import fields

import numpy as np

from ..models import BatchResult, simulate_many
from ..validity import ContactLossWarning

__all__ = ["run_in_chunks"]

#: The per-crossing arrays of a batch result (all its fields but the model's name).
_FIELDS = tuple(f.name for f in fields(BatchResult) if f.name != "model")

#: Crossings per call of ``simulate_many``.
CHUNK = 64


def _padded(parts: Sequence[BatchResult], n: int, speeds: np.ndarray) -> BatchResult:
    """The chunks done so far, followed by NaN rows for the crossings still to run."""
    arrays = {}
    for name in _FIELDS:
        done = np.concatenate([getattr(p, name) for p in parts], axis=0)
        shape = (n, *done.shape[1:])
        full = np.full(shape, np.nan)
        full[: done.shape[0]] = done
        arrays[name] = full
    arrays["speed"] = np.asarray(speeds, dtype=float)
    return BatchResult(model=parts[0].model, **arrays)


def run_in_chunks(
    bridges: object,
    vehicles: object,
    profile: object,
    speeds: np.ndarray,
    bridge_start: float,
    options: dict[str, object],
    progress: Callable[[BatchResult, int], None] | None = None,
    interval: float = 0.25,
) -> BatchResult:
    """``simulate_many`` over ``len(speeds)`` crossings, reporting progress between chunks.

    Parameters
    ----------
    bridges, vehicles
        One bridge or vehicle, or one per crossing (lists the length of ``speeds``).
    profile, bridge_start
        The road and the station of the first support [m], shared by every crossing.
    speeds
        Speed of each crossing [m/s], shape ``(n,)``.
    options
        Keyword options of :func:`vbi_lib.simulate_many` (``model``, ``modes``, ``coupled``).
    progress
        Called as ``progress(partial, done)`` after a chunk when at least ``interval``
        seconds have passed since the last call (never after the last chunk); ``partial``
        has NaN rows for the crossings not yet run.

    Returns
    -------
    BatchResult
        Every crossing, in the order of ``speeds``.
    """
    speeds = np.asarray(speeds, dtype=float)
    n = speeds.size
    parts: list[BatchResult] = []
    last = time.perf_counter()
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        chunk = {
            "bridges": bridges[rows] if isinstance(bridges, list) else bridges,
            "vehicles": vehicles[rows] if isinstance(vehicles, list) else vehicles,
        }
        with warnings.catch_warnings():
            # the readout says in words which crossings lost contact
            warnings.simplefilter("ignore", ContactLossWarning)
            parts.append(
                simulate_many(
                    chunk["bridges"],
                    chunk["vehicles"],
                    profile,
                    speeds[rows],
                    bridge_start,
                    **options,
                )
            )
        done = rows.stop
        if progress is not None and done < n and time.perf_counter() - last >= interval:
            progress(_padded(parts, n, speeds), done)
            last = time.perf_counter()
    return _padded(parts, n, speeds)
