"""Costs stated before they are spent: how long a mode search or a crossing will take.

Some allowed inputs are expensive: the exact modes of 50 spans x 200 modes, or a crossing
of millions of time steps with hundreds of modes.  Before such work starts the library
estimates its time and, past :data:`LONG` (about a minute), warns with a
:class:`~vbi_lib.validity.CostWarning` saying how long, why and what would cut it.

The estimates are deliberately simple and on the slow side (a warning is only useful
before the wait):

* **mode search** (:func:`mode_search_seconds`, :func:`vbi_lib.modes.beam_modes`): per mode
  one singular value decomposition of the ``4N x 4N`` matrix of the support conditions
  (the null vector gives the mode's coefficients), timed here on a matrix of that size
  so that the estimate follows this machine and its load, plus about :data:`PER_SPAN_MODE`
  seconds per span and mode for the Wittrick-Williams counts and the Gauss-Legendre
  quadrature of the mass normalisation (Python loops; measured on the project's 2-core
  machine at a load of 9: 50 spans x 200 modes took 28.6 s, 26 s of it in the SVDs);
* **crossing** (:func:`crossing_seconds`, :func:`vbi_lib.simulate`): per time step,
  :data:`MODAL_NODE_MODE` seconds per mode and axle group of the modal kernel (about
  0.2 us measured at that load) or :data:`COORDINATE_NODE` per axle of the one-coordinate
  kernel (0.5 us), counted on the crossing's node grid before the kernel runs.
"""

from __future__ import annotations

import time
import warnings
from functools import lru_cache

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
#: Seconds per span and mode of a mode search besides its SVD (counts and quadrature).
PER_SPAN_MODE = 7e-4
#: Seconds per time step, per mode and axle group, of the modal kernel.
MODAL_NODE_MODE = 0.25e-6
#: Seconds per time step and axle of the one-coordinate kernel.
COORDINATE_NODE = 0.6e-6


@lru_cache(maxsize=64)
def _svd_seconds(size: int) -> float:
    """Seconds one SVD of a ``size x size`` matrix takes here and now (best of two)."""
    matrix = np.random.default_rng(0).standard_normal((size, size))
    best = np.inf
    for _ in range(2):
        start = time.perf_counter()
        np.linalg.svd(matrix)
        best = min(best, time.perf_counter() - start)
    return float(best)


def mode_search_seconds(n_spans: int, modes: int) -> float:
    """Estimated seconds to find ``modes`` exact modes of a beam of ``n_spans`` spans.

    ``modes * (t_svd(4 n_spans) + PER_SPAN_MODE * n_spans)``, with ``t_svd`` timed here on
    a matrix of that size (only for 16 spans or more: below, a search takes seconds).

    >>> mode_search_seconds(2, 5) < 1.0
    True
    """
    svd = _svd_seconds(4 * n_spans) if n_spans >= 16 else 0.0
    return modes * (svd + PER_SPAN_MODE * n_spans)


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


def warn_mode_search(n_spans: int, modes: int) -> None:
    """The hook of :func:`vbi_lib.modes.beam_modes`: warn before a long mode search."""
    seconds = mode_search_seconds(n_spans, modes)
    if seconds <= LONG:
        return
    warn_cost(
        seconds,
        f"finding the exact modes of {n_spans} spans, {modes} of them (estimated from one "
        f"{4 * n_spans}x{4 * n_spans} SVD timed now, one per mode)",
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
