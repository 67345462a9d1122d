"""The node grid of a crossing: where a model's kernel takes its steps.

The vehicle's position is that of its first axle.  Every profile sample under every axle,
every axle's arrival at the bridge ends and at the interior supports, and the end of the run
are nodes, so the road under each axle is a straight line within a step and the
coefficients switch only at nodes; a gap between two of those points longer than
``speed * dt`` is cut into equal steps no longer than that.  Points closer than
``1e-12 * max(1, |stop|)`` to the point before them are dropped, the road at a node is
``np.interp`` of the profile (averaged over the tyre's footprint,
:mod:`vbi_lib.vehicles.footprint`), and the span of a step is found from the supports.

One axle without a footprint (the study's sprung mass, and every crossing of the batch lane
kernels) has its grid built by a *walker*: a small state (:data:`WALK_INTS` integers and
:data:`WALK_FLOATS` floats) that :func:`walk` advances a few nodes at a time, reproducing
the set construction and ``np.interp`` operation for operation.  :func:`node_grid` runs it
to the end for one crossing (what :func:`vbi_lib.simulate` integrates over); the lane
kernels (:mod:`~vbi_lib.models.lanes`) run one walker per crossing and take a few dozen
nodes at a time, so a batch never holds its grids in memory and both paths step over the
same nodes.  Several axles, or a footprint, take the set construction written with numpy.
"""

from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np

from ..bridges import Bridge
from ..profiles import Profile
from ..ranges import MAX_NODES
from ..vehicles import VehicleSystem
from ..vehicles.footprint import footprint_average

# walker state: integers, then floats
W_SAMPLE, W_SUPPORT, W_STOP_TAKEN, W_PIECES, W_PIECE, W_INTERVAL, W_LEFT, W_SLOPED = range(8)
WALK_INTS = 8
W_PREVIOUS, W_GAP_START, W_GAP_END, W_WIDTH, W_WIDEST, W_SLOPE = range(6)
WALK_FLOATS = 6


@dataclass(frozen=True)
class Grid:
    """Nodes of one crossing: stations [m], road elevations [m] and the span of each step.

    ``x`` is the station of the vehicle's first axle.  ``span_of_step[k]`` is 0 off the
    bridge, else the span (1, 2, ...) the first axle is on from node ``k`` to node ``k + 1``;
    it has one entry per node (the last unused), so that batches slice nodes and steps with
    the same offsets.  ``elevation`` is the road under the first axle; ``road`` and
    ``axle_span``, shape ``(n_axles, n_nodes)``, give them for every axle (the road as its
    tyre sees it).  ``dt_max`` is the longest step [s].
    """

    x: np.ndarray
    elevation: np.ndarray
    span_of_step: np.ndarray
    dt_max: float
    road: np.ndarray
    axle_span: np.ndarray


# ---------------------------------------------------------------------------- the walker
@numba.njit(cache=True)
def walk_start(px, supports, stop, ints, floats):
    """Reset a walker to the start of the run (the profile's first station)."""
    ints[:] = 0
    floats[:] = 0.0
    first = px[0]
    # the first point of the merged list is px[0] (supports and stop lie at or after it)
    ints[W_SAMPLE] = 1
    if supports.shape[0] > 0 and supports[0] == first:
        ints[W_SUPPORT] = 1
    if stop == first:
        ints[W_STOP_TAKEN] = 1
    floats[W_PREVIOUS] = first
    floats[W_GAP_END] = first  # as if a gap had just ended there
    ints[W_LEFT] = 1
    ints[W_SLOPED] = -1  # no interval's slope worked out yet


@numba.njit(cache=True)
def walk(px, pe, supports, stop, step, tol, ints, floats, out_x, out_e, lane, first, last):
    """Give the walker's next nodes in ``out_x[first:last, lane]`` and ``out_e[...]``.

    Returns how many were given: fewer than asked once the run's last node is out.  The
    state is read once and written back once, so a caller can take a few nodes at a time.
    """
    n = px.shape[0]
    n_supports = supports.shape[0]
    i = ints[W_SAMPLE]
    j = ints[W_SUPPORT]
    stop_taken = ints[W_STOP_TAKEN]
    pieces = ints[W_PIECES]
    piece = ints[W_PIECE]
    k = ints[W_INTERVAL]
    left = ints[W_LEFT]
    previous = floats[W_PREVIOUS]
    a = floats[W_GAP_START]
    b = floats[W_GAP_END]
    width = floats[W_WIDTH]
    widest = floats[W_WIDEST]
    slope = floats[W_SLOPE]
    sloped = ints[W_SLOPED]
    row = first
    while row < last and left == 1:
        if piece >= pieces and i < n and previous == b and b == px[i - 1]:
            # a run of samples, each gap one piece, before the next support or the stop:
            # the general branch below, with the tests that cannot fail left out
            # (samples at or after the stop are never nodes, whether it is taken or not)
            limit = supports[j] if j < n_supports else np.inf
            limit = stop if stop < limit else limit
            while row < last and i < n:
                following = px[i]
                gap = following - b
                if not (following < limit and gap > tol and gap <= step):
                    break
                out_x[row, lane] = b
                out_e[row, lane] = pe[i - 1]
                row += 1
                widest = gap if gap > widest else widest
                k = i - 1
                a = b
                b = following
                previous = following
                i += 1
                pieces = 1
                piece = 1
            if row >= last:
                break
        if piece >= pieces:
            # the gap is done: the next point kept (more than tol after its predecessor)
            a = b
            found = False
            while True:
                best = np.inf
                if i < n and px[i] < stop:
                    best = px[i]
                if j < n_supports and supports[j] < best:
                    best = supports[j]
                if stop_taken == 0 and stop < best:
                    best = stop
                if best == np.inf:
                    break
                # one copy of equal points (np.union1d)
                if i < n and px[i] == best:
                    i += 1
                if j < n_supports and supports[j] == best:
                    j += 1
                if stop_taken == 0 and stop == best:
                    stop_taken = 1
                kept = best - previous > tol
                previous = best
                if kept:
                    found = True
                    break
            if found:
                b = best
                gap = b - a
                if gap <= step:
                    # gap / step <= 1, so ceil(gap / step - 1e-9) <= 1: one piece, as below
                    count = 1.0
                    width = gap
                else:
                    count = np.ceil(gap / step - 1e-9)
                    count = 1.0 if count < 1.0 else count
                    width = gap / count
                widest = width if width > widest else widest
                pieces = np.int64(count)
                piece = 0
                x = a
            else:
                left = 0  # the run's last point
                x = a
        else:
            x = a + piece * width
        piece += 1
        # np.interp(x, px, pe), numpy's operations (stations never decrease); the slope of
        # interval k is worked out when a node falls inside it (interval `sloped`)
        while k + 1 < n and px[k + 1] <= x:
            k += 1
        out_x[row, lane] = x
        if x == px[k] or k + 1 >= n:
            out_e[row, lane] = pe[k]
        else:
            if sloped != k:
                slope = (pe[k + 1] - pe[k]) / (px[k + 1] - px[k])
                sloped = k
            out_e[row, lane] = slope * (x - px[k]) + pe[k]
        row += 1
    ints[W_SAMPLE] = i
    ints[W_SUPPORT] = j
    ints[W_STOP_TAKEN] = stop_taken
    ints[W_PIECES] = pieces
    ints[W_PIECE] = piece
    ints[W_INTERVAL] = k
    ints[W_LEFT] = left
    ints[W_SLOPED] = sloped
    floats[W_PREVIOUS] = previous
    floats[W_GAP_START] = a
    floats[W_GAP_END] = b
    floats[W_WIDTH] = width
    floats[W_WIDEST] = widest
    floats[W_SLOPE] = slope
    return row - first


@numba.njit(cache=True)
def span_of(middle, edges):
    """The span (1, 2, ...) of a point ``middle`` from the bridge start, 0 off the bridge.

    ``edges`` are the supports from the bridge start; the count of supports at or before
    the point (``np.searchsorted(edges, middle, side="right")``).
    """
    if not (middle > 0.0 and middle < edges[edges.shape[0] - 1]):
        return 0
    span = 1
    while span < edges.shape[0] - 1 and edges[span] <= middle:
        span += 1
    return span


@numba.njit(cache=True)
def _walked_grid(px, pe, supports, edges, bridge_start, step, stop):
    """The one-axle grid, walked to its end: nodes, elevations, span of each step, widest."""
    tol = 1e-12 * max(1.0, abs(stop))
    ints = np.zeros(WALK_INTS, np.int64)
    floats = np.zeros(WALK_FLOATS)
    # each gap has at most gap / step + 1 pieces: a bound on the node count
    room = (stop - px[0]) / step
    bound = np.searchsorted(px, stop) + supports.shape[0] + 3 + np.int64(np.ceil(room))
    nodes = np.empty((2, bound))
    walk_start(px, supports, stop, ints, floats)
    count = walk(px, pe, supports, stop, step, tol, ints, floats, nodes[0:1].T, nodes[1:2].T, 0,
                 0, bound)  # fmt: skip
    if ints[W_LEFT] != 0:
        raise RuntimeError("the node grid outgrew its bound")
    x = nodes[0, :count].copy()
    elevation = nodes[1, :count].copy()
    span_of_step = np.zeros(count, np.int64)
    for k in range(count - 1):
        span_of_step[k] = span_of(0.5 * (x[k] + x[k + 1]) - bridge_start, edges)
    return x, elevation, span_of_step, floats[W_WIDEST]


def _pieces(
    bridge: Bridge,
    profile: Profile,
    speed: float,
    bridge_start: float,
    dt: float,
    stop: float,
    offsets: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The points every axle must step on, their gaps and the steps in each gap.

    Raises ``ValueError`` for more than :data:`~vbi_lib.ranges.MAX_NODES` nodes, counted
    before the grid is allocated.
    """
    first = profile.start + float(offsets.max())
    supports = bridge_start + np.array(bridge.supports)
    shifted = (profile.x[None, :] + offsets[:, None]).ravel()
    below = (supports[None, :] + offsets[:, None]).ravel()
    inside = shifted[(shifted > first) & (shifted < stop)]
    below = below[below >= first]
    points = np.union1d(np.concatenate(([first], inside, below)), [stop])
    points = points[points <= stop]
    gaps = np.diff(points)
    keep = np.concatenate(([True], gaps > 1e-12 * max(1.0, abs(stop))))
    points = points[keep]
    gaps = np.diff(points)
    pieces = np.maximum(1.0, np.ceil(gaps / (speed * dt) - 1e-9))
    nodes = float(pieces.sum()) + 1.0
    if not nodes <= MAX_NODES:  # before anything the size of the crossing is allocated
        raise ValueError(
            f"dt={dt!r} s at speed={speed!r} m/s over {stop - first:.4g} m asks for {nodes:.3g} "
            f"time steps; a crossing has at most {MAX_NODES:.0e} (about 3 GB): raise dt (or "
            "leave it to the model, dt=None), raise the speed, or shorten the road"
        )
    return points, gaps, pieces.astype(np.int64)


def _sets_grid(
    bridge: Bridge,
    profile: Profile,
    speed: float,
    bridge_start: float,
    dt: float,
    stop: float,
    offsets: np.ndarray,
    footprints: np.ndarray,
) -> Grid:
    """The grid of several axles (or a footprint), by set operations with numpy."""
    points, gaps, pieces = _pieces(bridge, profile, speed, bridge_start, dt, stop, offsets)
    starts = np.repeat(points[:-1], pieces)
    widths = np.repeat(gaps / pieces, pieces)
    within = np.arange(pieces.sum()) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    x = np.append(starts + within * widths, points[-1])
    seen: dict[float, np.ndarray] = {0.0: profile.elevation}
    span_edges = np.array(bridge.supports)
    road = np.empty((offsets.size, x.size))
    axle_span = np.zeros((offsets.size, x.size), dtype=np.int64)
    for a, (offset, footprint) in enumerate(zip(offsets, footprints, strict=True)):
        if footprint not in seen:
            seen[footprint] = footprint_average(profile.x, profile.elevation, footprint)
        road[a] = np.interp(x - offset, profile.x, seen[footprint])
        middle = 0.5 * (x[:-1] + x[1:]) - offset - bridge_start
        axle_span[a, :-1] = np.where(
            (middle > 0) & (middle < bridge.length),
            np.searchsorted(span_edges, middle, side="right"),
            0,
        )
    dt_max = float((widths.max() if widths.size else 0) / speed)
    return Grid(x, road[0], axle_span[0], dt_max, road, axle_span)


def node_grid(
    bridge: Bridge,
    profile: Profile,
    speed: float,
    bridge_start: float,
    dt: float,
    stop: float,
    vehicle: VehicleSystem | None = None,
) -> Grid:
    """Nodes from the first axle's start to ``stop``, subdivided to steps of ``speed * dt``.

    The first axle starts ``wheelbase`` after the profile's first station (the last axle on
    it).  Nodes: every profile sample under every axle, the bridge ends and supports under
    every axle.  A gap between two of those points longer than ``speed * dt`` is cut into
    equal steps no longer than that (``dt = inf``: never).  ``vehicle`` (a
    :class:`~vbi_lib.vehicles.VehicleSystem`) gives the axles' offsets and footprints;
    ``None`` is one axle with no footprint, whose grid the compiled walker builds.

    Raises
    ------
    ValueError
        More than :data:`~vbi_lib.ranges.MAX_NODES` nodes (counted before the grid is
        allocated).
    """
    offsets = np.zeros(1) if vehicle is None else vehicle.offsets
    footprints = np.zeros(1) if vehicle is None else vehicle.footprint
    if offsets.size > 1 or footprints[0] != 0.0:
        return _sets_grid(bridge, profile, speed, bridge_start, dt, stop, offsets, footprints)
    # the walker's allocation bound: samples, supports and ends, plus a step per speed * dt
    bound = profile.x.size + len(bridge.supports) + 3 + (stop - profile.start) / (speed * dt)
    if not bound <= MAX_NODES:  # near the limit: count the nodes exactly (refuses beyond)
        _pieces(bridge, profile, speed, bridge_start, dt, stop, offsets)
    edges = np.array(bridge.supports)
    supports = bridge_start + edges
    supports = supports[(supports >= profile.start) & (supports <= stop)]
    x, elevation, span_of_step, widest = _walked_grid(
        profile.x, profile.elevation, supports, edges, float(bridge_start), speed * dt,
        float(stop),
    )  # fmt: skip
    return Grid(x, elevation, span_of_step, float(widest / speed), elevation[None, :],
                span_of_step[None, :])  # fmt: skip
