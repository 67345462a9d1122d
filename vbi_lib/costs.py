"""Costs stated before they are spent: how long a mode search or a crossing will take.

Some allowed inputs are expensive: the exact modes of 50 spans x 200 modes, or a crossing
of millions of time steps with hundreds of modes.  Before such work starts the library
estimates its time and, past :data:`LONG` (about a minute), warns with a
:class:`~vbi_lib.validity.CostWarning` saying how long, why and what would cut it.

The estimates are deliberately simple and on the slow side (a warning is only useful
before the wait):

* **mode search** (:func:`mode_search_seconds`, :func:`vbi_lib.modes.beam_modes`): per mode
  about 9 Wittrick-Williams counts, 12 determinants and one SVD of the ``4N x 4N`` matrix
  of the support conditions, and the Gauss-Legendre quadrature of its mass normalisation;
  one of each is timed here, when the search starts, so that the estimate follows this
  machine and its load (on the project's shared 2-core machine 50 spans x 200 modes took
  29 s at a load of 9 and more than 90 s at 11: the BLAS threads thrash);
* **crossing** (:func:`crossing_seconds`, :func:`vbi_lib.simulate`): per time step,
  :data:`MODAL_NODE_MODE` seconds per mode and axle group of the modal kernel (about
  0.2 us measured at that load) or :data:`COORDINATE_NODE` per axle of the one-coordinate
  kernel (0.5 us), counted on the crossing's node grid before the kernel runs.
"""

from __future__ import annotations

import time
import warnings
from collections.abc import Callable, Sequence

import numpy as np

from .ranges import _caller_level
from .validity import CostWarning

__all__ = [
    "COORDINATE_NODE",
    "LONG",
    "MODAL_NODE_MODE",
    "PER_SPAN_MODE",
    "crossing_seconds",
    "mode_search_seconds",
    "warn_cost",
]

#: Work estimated to take longer than this is warned about [s].
LONG = 60.0
#: Seconds per span and mode of a search of fewer than 8 spans (not timed: seconds at most).
PER_SPAN_MODE = 2e-3
#: Seconds per time step, per mode and axle group, of the modal kernel.
MODAL_NODE_MODE = 0.25e-6
#: Seconds per time step and axle of the one-coordinate kernel.
COORDINATE_NODE = 0.6e-6


def _slowest(work: Callable[[], object], repeats: int = 2) -> float:
    """The slowest of ``repeats`` runs of ``work`` [s] (the load of a shared machine comes and
    goes; an estimate meant to warn should not be the luckiest)."""
    worst = 0.0
    for _ in range(repeats):
        start = time.perf_counter()
        work()
        worst = max(worst, time.perf_counter() - start)
    return worst


def mode_search_seconds(n_spans: int, modes: int, spans: Sequence[float] | None = None) -> float:
    """Estimated seconds to find ``modes`` exact modes of a beam of ``n_spans`` spans.

    A search makes, per mode, about 9 Wittrick-Williams counts and 12 determinants of the
    ``4N x 4N`` support conditions to isolate and refine the root, then one SVD for the
    mode's coefficients and the quadrature of its mass normalisation
    (:mod:`vbi_lib.continuous_beams`; counted on 20 and 50 spans).  For 8 spans or more one
    of each is timed here and now, on a wavenumber of the middle mode, the slower of two
    runs (under load the machine's BLAS threads make these vary tenfold); below, the search
    takes at most seconds and :data:`PER_SPAN_MODE` stands for all of it.

    >>> mode_search_seconds(2, 5) < 1.0
    True
    """
    if n_spans < 8:
        return modes * PER_SPAN_MODE * n_spans
    from .continuous_beams import _determinant, count_below, mode_coefficients

    lengths = np.asarray(spans if spans is not None else [1.0] * n_spans, dtype=float)
    k = np.pi * max(1.0, modes / 2) / float(lengths.sum())  # about the middle mode's
    coefficients = _slowest(lambda: mode_coefficients(lengths, k, 1.0))
    determinant = _slowest(lambda: _determinant(k, lengths))
    count = _slowest(lambda: count_below(k, lengths))
    return modes * (coefficients + 12 * determinant + 9 * count)


def crossing_seconds(model: str, nodes: int, modes: int | None, axles: int) -> float:
    """Estimated seconds of a crossing's kernel over ``nodes`` time steps.

    >>> round(crossing_seconds("modal", 1_000_000, 200, 3), 1)
    100.0
    """
    if model == "modal":
        return nodes * MODAL_NODE_MODE * (modes or 1) * (1 + (axles - 1) / 2)
    return nodes * COORDINATE_NODE * axles


def _duration(seconds: float) -> str:
    if seconds < 120:
        return f"{seconds:.0f} s"
    if seconds < 7200:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"


def warn_cost(seconds: float, what: str, cut: str) -> None:
    """Warn (:class:`~vbi_lib.validity.CostWarning`) when ``seconds`` pass :data:`LONG`.

    ``what`` says what is about to run and how the time was estimated, ``cut`` what would
    make it shorter.
    """
    if seconds > LONG:
        warnings.warn(
            f"{what} will take about {_duration(seconds)} on this machine; {cut}",
            CostWarning,
            stacklevel=_caller_level(),
        )


def warn_mode_search(spans: Sequence[float], modes: int) -> None:
    """The hook of :func:`vbi_lib.modes.beam_modes`: warn before a long mode search."""
    seconds = mode_search_seconds(len(spans), modes, spans)
    if seconds <= LONG:
        return
    size = 4 * len(spans)
    warn_cost(
        seconds,
        f"finding the exact modes of {len(spans)} spans, {modes} of them (about 12 "
        f"determinants and an SVD of {size}x{size} a mode, one of each timed now)",
        "fewer modes (modes=...) or fewer spans would cut it",
    )


def warn_crossing(model: str, nodes: int, modes: int | None, axles: int) -> None:
    """The hook of :func:`vbi_lib.simulate`: warn before a long crossing."""
    seconds = crossing_seconds(model, nodes, modes, axles)
    if seconds <= LONG:
        return
    shown = f", {modes} modes" if model == "modal" and modes else ""
    warn_cost(
        seconds,
        f"this crossing ({nodes:,} time steps{shown}, {axles} axle(s), model={model!r})",
        "a longer dt, fewer modes or a shorter road would cut it",
    )
