r"""What every model's kernel does with a general vehicle's axles, written once.

A :class:`~vbi_lib.vehicles.VehicleSystem` reaches a compiled kernel as one flat vector
(:func:`vehicle_vector`, unpacked by :func:`unpack`), so a batch of different vehicles is a
concatenation.  The helpers here account the contact forces of the axles on the bridge in
the summary vector (the worst axle's force over its static load, the time in tension of
bilateral contacts and in flight of unilateral ones), mark the spans the vehicle occupies
and solve the small dense systems of an implicit step.

Events of unilateral contacts
-----------------------------
A tyre in contact takes off when its force :math:`P_a` would turn tensile and lands when
:math:`P_a` (computed from the state as if it touched) turns compressive again.  The contact
force :math:`\max(0, P_a)` is continuous there, so the motion is smooth on either side and
only the switch must be found: each kernel steps to the end of a step, and if some
:math:`P_a` changed sign it locates the first root by the Illinois variant of regula falsi,
each trial being the kernel's own integrator from the step's start to the trial time, steps
to that time, switches the axle and continues (:data:`MAX_EVENTS` per step at most).
"""

from __future__ import annotations

import numba
import numpy as np

from ..vehicles import VehicleSystem
from .base import (
    S_BRIDGE_TIME,
    S_FLIGHT_TIME,
    S_MAX_AT,
    S_MAX_FORCE,
    S_MIN_FORCE,
    S_TENSION_TIME,
)

#: Most contact switches located within one step (further ones wait for the next step).
MAX_EVENTS = 8
#: Relative width of the bracket at which an event's time is accepted.
EVENT_TOLERANCE = 1e-13


def vehicle_vector(system: VehicleSystem, u0: np.ndarray) -> np.ndarray:
    """The vehicle as one flat vector for the kernels (layout of :func:`unpack`)."""
    return np.concatenate((_matrices(system), u0))


def _matrices(system: VehicleSystem) -> np.ndarray:
    """Every part of :func:`vehicle_vector` but the initial state (computed once a system)."""
    cached = system.__dict__.get("_kernel_matrices")
    if cached is None:
        parts = (
            system.mass,
            system.mass_inverse,
            system.stiffness,
            system.damping,
            system.contact,
            system.static_loads,
            system.contact_stiffness,
            system.contact_damping,
            system.offsets,
            system.unilateral.astype(float),
        )
        cached = np.concatenate([np.ravel(p) for p in parts])
        system.__dict__["_kernel_matrices"] = cached
    return cached


def vector_size(n: int, n_axles: int) -> int:
    """Length of :func:`vehicle_vector` for ``n`` dofs and ``n_axles`` axles."""
    return 4 * n * n + n_axles * n + 5 * n_axles + n


@numba.njit(cache=True)
def unpack(vec, n, n_axles):
    """Views of ``M, M^-1, K, C, E, W, k, c, offsets``, the unilateral flags and ``u0``."""
    i = 0
    blocks = []
    for _ in range(4):
        blocks.append(vec[i : i + n * n].reshape((n, n)))
        i += n * n
    E = vec[i : i + n_axles * n].reshape((n_axles, n))
    i += n_axles * n
    W = vec[i : i + n_axles]
    kt = vec[i + n_axles : i + 2 * n_axles]
    ct = vec[i + 2 * n_axles : i + 3 * n_axles]
    off = vec[i + 3 * n_axles : i + 4 * n_axles]
    unilateral = vec[i + 4 * n_axles : i + 5 * n_axles] > 0.5
    u0 = vec[i + 5 * n_axles : i + 5 * n_axles + n]
    return blocks[0], blocks[1], blocks[2], blocks[3], E, W, kt, ct, off, unilateral, u0


@numba.njit(cache=True, inline="always")
def occupied(axle_span, k, n_spans, spans):
    """``spans[j]`` = whether some axle is on span ``j + 1`` during step ``k``; any at all."""
    anything = False
    for j in range(n_spans):
        spans[j] = False
    for a in range(axle_span.shape[0]):
        s = axle_span[a, k]
        if s > 0:
            spans[s - 1] = True
            anything = True
    return anything


@numba.njit(cache=True, inline="always")
def track_axles(summary, force, W, off, x_front, axle_span, k, h, unilateral, weight):
    """Account the axle contact forces at a node held for ``h`` seconds (axles on the bridge).

    The worst axle counts: ``P_a / W_a`` is stored times the vehicle's ``weight``, so that
    one axle's entries are its force; the time in tension counts bilateral axles only.
    """
    on_bridge = False
    tension = False
    for a in range(force.shape[0]):
        if axle_span[a, k] <= 0:
            continue
        on_bridge = True
        ratio = force[a] / W[a]
        if ratio * weight > summary[S_MAX_FORCE]:
            summary[S_MAX_FORCE] = ratio * weight
            summary[S_MAX_AT] = x_front - off[a]
        if ratio * weight < summary[S_MIN_FORCE]:
            summary[S_MIN_FORCE] = ratio * weight
        if force[a] < 0.0 and not unilateral[a]:
            tension = True
    if on_bridge:
        summary[S_BRIDGE_TIME] += h
        if tension:
            summary[S_TENSION_TIME] += h


@numba.njit(cache=True, inline="always")
def track_flight(summary, flying, axle_span, k, h):
    """Add ``h`` seconds of flight if a tyre on the bridge is off the road."""
    for a in range(flying.shape[0]):
        if flying[a] and axle_span[a, k] > 0:
            summary[S_FLIGHT_TIME] += h
            return


@numba.njit(cache=True, inline="always")
def log_event(events, count, time, axle, took_off, station):
    """Append a take-off (``took_off``) or landing of ``axle`` to ``events`` (if room)."""
    i = count[0]
    if i < events.shape[0]:
        events[i, 0] = time
        events[i, 1] = axle
        events[i, 2] = 1.0 if took_off else -1.0
        events[i, 3] = station
    count[0] = i + 1


@numba.njit(cache=True, inline="always")
def illinois_step(lo, glo, hi, ghi, t, gt, side):
    """One update of the Illinois bracket on ``g`` (``g(lo) >= 0 > g(hi)``).

    Returns the new ``(lo, glo, hi, ghi, side)``; the retained end's value is halved when
    the same end is kept twice, which keeps regula falsi superlinear.
    """
    if gt >= 0.0:
        lo = t
        glo = gt
        if side == 1:
            ghi *= 0.5
        side = 1
    else:
        hi = t
        ghi = gt
        if side == -1:
            glo *= 0.5
        side = -1
    return lo, glo, hi, ghi, side


@numba.njit(cache=True, inline="always")
def next_trial(lo, glo, hi, ghi):
    """Regula falsi point of the bracket, bisection if it falls outside."""
    t = 0.5 * (lo + hi)
    if glo - ghi > 0.0:
        candidate = lo + (hi - lo) * glo / (glo - ghi)
        if lo < candidate < hi:
            t = candidate
    return t


#: What :func:`locate_switch` tells the kernel to do with its trial step.
RETRY, ACCEPT, ACCEPT_STEP = 0, 1, 2


@numba.njit(cache=True, inline="always")
def locate_switch(phase, axle, tries, switches, lo, glo, hi, ghi, side, th0, target,
                  start_gap, end_gap, unilateral, n_axles):  # fmt: skip
    """One decision of the event location, after a trial from ``th0`` to ``target``.

    Both general kernels share it.  Phase 0 stepped to the step's end; if a tyre's force
    changed sign there (``end_gap < 0``), phase 1 brackets that axle's switch with Illinois
    trials from ``th0``, and phase 2 takes the step to the located switch (any earlier
    switch of another axle restarts the search).  Returns ``(action, phase, axle, tries, lo,
    glo, hi, ghi, side, target)``: ``RETRY`` (integrate again from ``th0`` to ``target``),
    ``ACCEPT`` (keep the trial: a switch is reached) or ``ACCEPT_STEP`` (keep it: the
    step is done with no switch).
    """
    if phase == 1:
        tries += 1
        gt = end_gap[axle]
        if gt == 0.0:
            hi = target
        else:
            lo, glo, hi, ghi, side = illinois_step(lo, glo, hi, ghi, target, gt, side)
        if gt == 0.0 or hi - lo <= EVENT_TOLERANCE or tries >= 200:
            phase = 2
            target = hi
        else:
            target = next_trial(lo, glo, hi, ghi)
        return RETRY, phase, axle, tries, lo, glo, hi, ghi, side, target
    found = -1
    if switches < MAX_EVENTS and target > th0:
        for a in range(n_axles):
            if found < 0 and unilateral[a] and a != axle and end_gap[a] < 0.0:
                found = a
    if found >= 0:
        axle = found
        lo, glo, hi, ghi, side, tries = th0, start_gap[axle], target, end_gap[axle], 0, 0
        phase = 2 if glo <= 0.0 else 1
        target = th0 if glo <= 0.0 else next_trial(lo, glo, hi, ghi)
        return RETRY, phase, axle, tries, lo, glo, hi, ghi, side, target
    action = ACCEPT_STEP if phase == 0 else ACCEPT
    return action, phase, axle, tries, lo, glo, hi, ghi, side, target


@numba.njit(cache=True)
def solve_in_place(a, b, m, cols):
    """Solve the leading ``m x m`` block of ``a`` against ``b[:m, :cols]`` in place.

    Gaussian elimination with partial pivoting; ``a`` is overwritten and ``b`` receives the
    solution (the systems are small: a vehicle's dofs, or its axles).
    """
    for col in range(m):
        pivot = col
        best = abs(a[col, col])
        for r in range(col + 1, m):
            if abs(a[r, col]) > best:
                best = abs(a[r, col])
                pivot = r
        if pivot != col:
            for c in range(m):
                tmp = a[col, c]
                a[col, c] = a[pivot, c]
                a[pivot, c] = tmp
            for c in range(cols):
                tmp = b[col, c]
                b[col, c] = b[pivot, c]
                b[pivot, c] = tmp
        for r in range(col + 1, m):
            f = a[r, col] / a[col, col]
            if f != 0.0:
                for c in range(col, m):
                    a[r, c] -= f * a[col, c]
                for c in range(cols):
                    b[r, c] -= f * b[col, c]
    for c in range(cols):
        for r in range(m - 1, -1, -1):
            s = b[r, c]
            for j in range(r + 1, m):
                s -= a[r, j] * b[j, c]
            b[r, c] = s / a[r, r]


def event_log(n_nodes: int) -> tuple[np.ndarray, np.ndarray]:
    """Room for the tyres' take-offs and landings of one crossing, and their counter."""
    return np.empty((2 * n_nodes + 16, 4)), np.zeros(1, dtype=np.int64)


def logged_events(events: np.ndarray, count: np.ndarray) -> np.ndarray:
    """The events a kernel logged, ``(n_events, 4)``: time, axle, +1/-1, station."""
    if count[0] > events.shape[0]:
        raise RuntimeError(f"{count[0]} contact events overflowed the log of {events.shape[0]}")
    return events[: count[0]].copy()


def largest_over_positions(deflection, first: float, last: float, count: int = 801) -> float:
    """Largest value of ``deflection(x)`` (vectorised in ``x``) for ``x`` in ``[first, last]``.

    A sampled search, then a bounded refinement around the best sample (the static
    influence of axles is smooth between the stations where an axle reaches a support).
    """
    from scipy.optimize import minimize_scalar

    xs = np.linspace(first, last, count)
    values = deflection(xs)
    i = int(np.argmax(values))
    lo, hi = xs[max(i - 1, 0)], xs[min(i + 1, count - 1)]
    best = minimize_scalar(
        lambda s: -float(deflection(np.array([s]))[0]),
        bounds=(lo, hi),
        method="bounded",
        options={"xatol": 1e-10 * max(1.0, abs(last - first))},
    )
    return float(max(values[i], -best.fun))
