r"""What the batch kernels share: crossings on the SIMD lanes of the CPU.

:func:`vbi_lib.simulate_many` hands the crossings of the study's sprung mass
(:class:`~vbi_lib.Vehicle`) on bridges of one or two spans to a model's *lane kernel*
(:mod:`~vbi_lib.models.lanes_one_coordinate`, :mod:`~vbi_lib.models.lanes_modal`), which
advances :data:`LANES` crossings together, one time step at a time (other vehicles, and
bridges of more spans, take the models' own kernels, :meth:`CrossingModel.integrate_many
<vbi_lib.models.base.CrossingModel.integrate_many>`):

* the state of a block is a structure of arrays, ``(n_states, LANES)``, lane index innermost
  and contiguous, and every step is a loop over the lanes with no branch (masks select), so
  the compiler packs the lanes into vector registers.  The hot loops index flat arrays as
  ``field * LANES + lane`` with ``LANES`` a compile-time constant, so the compiler can see
  that two fields never overlap, and call only helpers that take numbers;
* each crossing has its own node grid, taken :data:`CHUNK` nodes at a time from its walker
  (:func:`~vbi_lib.models.grid.walk`, the code that builds :func:`vbi_lib.simulate`'s grid),
  and its own steps; a crossing that has finished idles behind a mask until its block is done,
  so crossings are sorted by their expected number of steps before they are cut into blocks;
* sines, cosines and exponentials of the shape functions come from :func:`sincos` and
  :func:`exp_parts`, branch-free polynomials the compiler packs too (the C library's
  ``sin`` and ``exp`` would be called once per lane);
* the peak refinement inside a step (three divisions and a square root) is needed only
  where a midspan rate changes sign: the step loop keeps the end values and marks those
  steps, and :func:`refine_peaks` refines them afterwards with the base module's code;
* numba's ``prange`` shares the blocks among threads, one block at a time;
* the arithmetic may fuse a multiply and an add (:data:`CONTRACT`): each lane goes through
  the same packed code whatever block it is in, so a crossing's result does not depend on
  the batch, the chunking or the number of threads.

Results equal :func:`vbi_lib.simulate`'s to rounding (the tests hold them to 1e-10): the
lanes evaluate the same equations on the same nodes with the same peak refinement and
contact checks, in a different order of floating-point operations.
"""

from __future__ import annotations

import math
from decimal import Decimal

import numba
import numpy as np

from .base import (
    S_BRIDGE_TIME,
    S_FLIGHT_TIME,
    S_MAX_AT,
    S_MAX_FORCE,
    S_MIN_FORCE,
    S_PEAK,
    S_TENSION_TIME,
    SUMMARY_SIZE,
    hermite_min,
)
from .grid import W_WIDEST, WALK_FLOATS, WALK_INTS, walk, walk_start

#: Crossings advanced together in one block (the lane index runs innermost).
LANES = 16
#: Steps taken from each crossing's grid walker at a time.
CHUNK = 64
#: Floating-point freedom of the lane loops: a * b + c may be one fused multiply-add (one
#: rounding instead of two); nothing else (no reassociation, infinities and NaN kept).
CONTRACT = {"contract"}

# the first columns of every lane kernel's table of crossings (a model appends its own);
# T_LENGTH: the bridge's length, T_INNER: its interior support from its start (one span:
# +inf); T_WALK: crossings of one class (>= 0) have the same grid, -1 a grid of their own
T_STOP, T_STEP, T_TOL, T_START, T_SPAN, T_SPANS, T_SPEED, T_WALK, T_LENGTH, T_INNER = range(10)
T_SHARED = 10

# pi/2 in two parts: a 33-bit head (n * head is exact for n < 2**20) and the rest;
# sin(fl(pi)) is pi - fl(pi) to double precision
PIO2_HEAD = math.floor(math.pi / 2 * 2.0**32) / 2.0**32
PIO2_TAIL = (math.pi / 2 - PIO2_HEAD) + math.sin(math.pi) / 2
TWO_OVER_PI = 2.0 / math.pi
# Taylor coefficients from the highest: (-1)^k / (2k+1)! (k = 8..1) and (-1)^k / (2k)! (k = 8..2)
SINE_TERMS = tuple((-1.0) ** k / math.factorial(2 * k + 1) for k in range(8, 0, -1))
COSINE_TERMS = tuple((-1.0) ** k / math.factorial(2 * k) for k in range(8, 1, -1))


@numba.njit(cache=True, inline="always", error_model="numpy", fastmath=CONTRACT)
def sincos(theta):
    """``sin(theta), cos(theta)`` without branches, within about 1 ulp for ``|theta| < 1e6``.

    The argument is reduced by multiples of pi/2 (Cody and Waite's two-part constant), the
    reduced sine and cosine are Taylor polynomials on ``[-pi/4, pi/4]`` (truncation below
    1e-18), and the quadrant picks and signs them with selects.
    """
    n = np.floor(theta * TWO_OVER_PI + 0.5)
    r = (theta - n * PIO2_HEAD) - n * PIO2_TAIL
    z = r * r
    sine_poly = 0.0
    for term in SINE_TERMS:
        sine_poly = sine_poly * z + term
    cosine_poly = 0.0
    for term in COSINE_TERMS:
        cosine_poly = cosine_poly * z + term
    s = r + r * z * sine_poly
    c = 1.0 - 0.5 * z + z * z * cosine_poly
    quadrant = n - 4.0 * np.floor(0.25 * n)
    odd = (quadrant == 1.0) | (quadrant == 3.0)
    sine = c if odd else s
    cosine = s if odd else c
    sine = -sine if quadrant >= 2.0 else sine
    cosine = -cosine if (quadrant == 1.0) | (quadrant == 2.0) else cosine
    return sine, cosine


# ln 2 in two parts (as pi/2 above); the tail from ln 2 to 36 digits
LN2_HEAD = math.floor(math.log(2.0) * 2.0**32) / 2.0**32
LN2_TAIL = float(Decimal("0.693147180559945309417232121458176568") - Decimal(LN2_HEAD))
# Taylor coefficients of exp from the highest, 1/13! .. 1/0!
EXP_TERMS = tuple(1.0 / math.factorial(k) for k in range(13, -1, -1))


@numba.njit(cache=True, inline="always", error_model="numpy", fastmath=CONTRACT)
def exp_parts(x):
    """``exp(x)`` as ``(p, n)`` with ``exp(x) = p * 2**n``, without branches.

    ``x`` is clamped to [-708, 709] (the normal range); ``n = round(x / ln 2)``, and ``p`` is
    the Taylor polynomial of the reduced argument (``|r| <= ln 2 / 2``, truncation below 1e-17).
    The caller makes ``2**n`` from :func:`power_of_two_bits` in a separate loop, so that
    both loops stay packed.
    """
    x = min(max(x, -708.0), 709.0)
    n = np.floor(x * (1.0 / math.log(2.0)) + 0.5)
    r = (x - n * LN2_HEAD) - n * LN2_TAIL
    p = 0.0
    for term in EXP_TERMS:
        p = p * r + term
    return p, n


@numba.njit(cache=True, inline="always")
def power_of_two_bits(n):
    """The bits of the double ``2**n`` (``n`` a whole number in [-1022, 1023]) as an int64."""
    return (np.int64(n) + 1023) << 52


# ---------------------------------------------------------------------------- summaries
@numba.njit(cache=True)
def start_summaries(state, first, n_spans, lane):
    """Reset a lane's summary (``state[(first + S_*) * LANES + lane]``), as ``start_summary``."""
    state[(first + S_PEAK) * LANES + lane] = -np.inf
    state[(first + S_PEAK + 1) * LANES + lane] = -np.inf if n_spans > 1 else np.nan
    state[(first + S_MAX_FORCE) * LANES + lane] = -np.inf
    state[(first + S_MAX_AT) * LANES + lane] = np.nan
    state[(first + S_MIN_FORCE) * LANES + lane] = np.inf
    state[(first + S_TENSION_TIME) * LANES + lane] = 0.0
    state[(first + S_BRIDGE_TIME) * LANES + lane] = 0.0
    state[(first + S_FLIGHT_TIME) * LANES + lane] = 0.0  # the sprung mass never leaves


# rows of a lane kernel's state after the summary: a step whose midspan rate changes sign,
# kept for the refinement of its peak; one set of MARK_SET rows per span (span 2's after span 1's)
MARK_TURN, MARK_M0, MARK_M1, MARK_V0, MARK_V1, MARK_H, MARK_SPAN = range(7)
MARK_SET = 7
MARK_COUNT = 2 * MARK_SET


@numba.njit(cache=True, inline="always")
def track_lane_peak(state, first, lane, on, span_index, m0, m1, v0, v1, h):
    """Account a step's midspan displacements ``m0, m1`` and rates ``v0, v1``, masked by ``on``.

    The larger downward end value is kept at once; a step where the rate changes sign is
    marked in the rows after the summary (``first + SUMMARY_SIZE + P_*``) for
    :func:`refine_peaks`, which finds the extreme inside it.  ``span_index`` is 0 for span 1,
    1 for span 2; each span has its own marked step, so that a kernel tracks both midspans
    at every step (the span DAF reads the whole run).
    """
    # (both rates zero, as at rest on the approach: no extreme inside the step)
    turn = on & (v0 * v1 <= 0.0) & ((v0 != 0.0) | (v1 != 0.0))
    peak = -m0 if -m0 >= -m1 else -m1
    i1 = (first + S_PEAK) * LANES + lane
    i2 = (first + S_PEAK + 1) * LANES + lane
    p1 = state[i1]
    p2 = state[i2]
    keep = on & (not turn)
    state[i1] = peak if keep & (span_index == 0.0) & (peak > p1) else p1
    state[i2] = peak if keep & (span_index == 1.0) & (peak > p2) else p2
    pending = first + SUMMARY_SIZE + (MARK_SET if span_index == 1.0 else 0)
    state[(pending + MARK_TURN) * LANES + lane] = 1.0 if turn else 0.0
    state[(pending + MARK_M0) * LANES + lane] = m0
    state[(pending + MARK_M1) * LANES + lane] = m1
    state[(pending + MARK_V0) * LANES + lane] = v0
    state[(pending + MARK_V1) * LANES + lane] = v1
    state[(pending + MARK_H) * LANES + lane] = h
    state[(pending + MARK_SPAN) * LANES + lane] = span_index


@numba.njit(cache=True, inline="always")
def track_lane_peaks(state, first, lane, on, m0, m1, v0, v1, h):
    """:func:`track_lane_peak` of span 1 with ``m0, m1, v0, v1`` and of span 2 with their
    negatives (the one-coordinate beam's midspans, ``+z_b`` and ``-z_b``): both turn in the
    same steps, so one marked step serves both (``MARK_SPAN`` 2)."""
    # (both rates zero, as at rest on the approach: no extreme inside the step)
    turn = on & (v0 * v1 <= 0.0) & ((v0 != 0.0) | (v1 != 0.0))
    keep = on & (not turn)
    down = -m0 if -m0 >= -m1 else -m1
    up = m0 if m0 >= m1 else m1
    i1 = (first + S_PEAK) * LANES + lane
    i2 = (first + S_PEAK + 1) * LANES + lane
    p1 = state[i1]
    p2 = state[i2]
    state[i1] = down if keep & (down > p1) else p1
    state[i2] = up if keep & (up > p2) else p2
    pending = first + SUMMARY_SIZE
    state[(pending + MARK_TURN) * LANES + lane] = 1.0 if turn else 0.0
    state[(pending + MARK_M0) * LANES + lane] = m0
    state[(pending + MARK_M1) * LANES + lane] = m1
    state[(pending + MARK_V0) * LANES + lane] = v0
    state[(pending + MARK_V1) * LANES + lane] = v1
    state[(pending + MARK_H) * LANES + lane] = h
    state[(pending + MARK_SPAN) * LANES + lane] = 2.0


@numba.njit(cache=True, inline="always")
def refine_peaks(state, first, sets=2):
    """The peaks of the steps :func:`track_lane_peak` marked: the cubic Hermite's extreme inside.

    As ``downward_peak`` of the base module, whose functions it calls; few steps are marked
    (a midspan rate changes sign about twice a period), so this loop is rarely busy.
    ``sets``: the marked-step sets in use (1: :func:`track_lane_peaks` only).
    """
    for span in range(sets):
        pending = first + SUMMARY_SIZE + span * MARK_SET
        marked = False  # a packed test of the lanes first: most steps mark none
        for lane in range(LANES):
            marked = marked | (state[(pending + MARK_TURN) * LANES + lane] > 0.0)
        if not marked:
            continue
        for lane in range(LANES):
            if state[(pending + MARK_TURN) * LANES + lane] > 0.0:
                m0 = state[(pending + MARK_M0) * LANES + lane]
                m1 = state[(pending + MARK_M1) * LANES + lane]
                v0 = state[(pending + MARK_V0) * LANES + lane]
                v1 = state[(pending + MARK_V1) * LANES + lane]
                h = state[(pending + MARK_H) * LANES + lane]
                pair = state[(pending + MARK_SPAN) * LANES + lane] == 2.0
                i = (first + S_PEAK + span) * LANES
                peak = -hermite_min(m0, m1, v0, v1, h)
                if peak > state[i + lane]:
                    state[i + lane] = peak
                if pair:  # track_lane_peaks: span 2 is the negative of span 1
                    i = (first + S_PEAK + 1) * LANES
                    peak = -hermite_min(-m0, -m1, -v0, -v1, h)
                    if peak > state[i + lane]:
                        state[i + lane] = peak


@numba.njit(cache=True, inline="always")
def track_force(state, first, lane, on, force, x, h):
    """Account a lane's contact force ``force`` [N] at ``x`` held ``h`` s, masked by ``on``.

    As ``track_contact`` of the base module: extremes, station of the largest, time on the
    bridge and time in tension.
    """
    i_max = (first + S_MAX_FORCE) * LANES + lane
    i_at = (first + S_MAX_AT) * LANES + lane
    i_min = (first + S_MIN_FORCE) * LANES + lane
    i_bridge = (first + S_BRIDGE_TIME) * LANES + lane
    i_tension = (first + S_TENSION_TIME) * LANES + lane
    largest = state[i_max]
    higher = on & (force > largest)
    state[i_max] = force if higher else largest
    state[i_at] = x if higher else state[i_at]
    smallest = state[i_min]
    state[i_min] = force if on & (force < smallest) else smallest
    state[i_bridge] += h if on else 0.0
    state[i_tension] += h if on & (force < 0.0) else 0.0


@numba.njit(cache=True)
def finish(lanes, state, first, walkers, summaries, widest):
    """Copy each used lane's summary and widest step [m] to the batch's outputs."""
    floats, share = walkers[1], walkers[3]
    for lane in range(LANES):
        i = lanes[lane]
        if i >= 0:
            for k in range(SUMMARY_SIZE):
                summaries[i, k] = state[(first + k) * LANES + lane]
            walker = share[lane] if share[lane] >= 0 else lane
            widest[i] = floats[walker, W_WIDEST]


# ---------------------------------------------------------------------------- grids
@numba.njit(cache=True)
def support_stations(row):
    """Stations of a crossing's supports (a row of the table), as :func:`node_grid` has them:
    ``bridge_start + bridge.supports``."""
    n_spans = np.int64(row[T_SPANS])
    out = np.empty(n_spans + 1)
    out[0] = row[T_START] + 0.0
    if n_spans > 1:
        out[1] = row[T_START] + row[T_INNER]
    out[n_spans] = row[T_START] + row[T_LENGTH]
    return out


@numba.njit(cache=True)
def start_walkers(lanes, px, pe, roads, table, x, e):
    """Each lane's walker at its first node (row 0 of ``x``, ``e``); unused lanes copy lane 0.

    ``px``, ``pe`` are the batch's roads end to end (stations, elevations) and ``roads[i]``
    the slice of crossing ``i``'s road.  Returns the walkers' integer and float states, the
    lanes' supports and, for each lane, the earlier lane of the same grid class whose nodes
    it copies (``-1``: it walks its own grid).
    """
    ints = np.zeros((LANES, WALK_INTS), np.int64)
    floats = np.zeros((LANES, WALK_FLOATS))
    supports = np.zeros((LANES, 3))  # 1 or 2 spans
    share = np.full(LANES, -1, np.int64)
    for lane in range(LANES):
        if lanes[lane] >= 0 and table[lanes[lane], T_WALK] >= 0.0:
            for other in range(lane):
                if lanes[other] >= 0 and table[lanes[other], T_WALK] == table[lanes[lane], T_WALK]:
                    share[lane] = other
                    break
    for lane in range(LANES):
        i = lanes[lane] if lanes[lane] >= 0 else lanes[0]
        row = table[i]
        n_spans = np.int64(row[T_SPANS])
        supports[lane, : n_spans + 1] = support_stations(row)
        road_x = px[roads[i, 0] : roads[i, 1]]
        road_e = pe[roads[i, 0] : roads[i, 1]]
        walk_start(road_x, supports[lane, : n_spans + 1], row[T_STOP], ints[lane], floats[lane])
        x[0, lane] = road_x[0]
        e[0, lane] = road_e[0]
        if lanes[lane] >= 0:
            walk(road_x, road_e, supports[lane, : n_spans + 1], row[T_STOP], row[T_STEP],
                 row[T_TOL], ints[lane], floats[lane], x, e, lane, 0, 1)  # fmt: skip
    return ints, floats, supports, share


@numba.njit(cache=True)
def next_nodes(lanes, px, pe, roads, table, walkers, x, e, active, steps):
    """Rows ``1..steps`` of ``x``, ``e`` from each lane's walker (row 0: the last node given).

    ``walkers`` is what :func:`start_walkers` returned.
    A lane of a grid class copies the nodes of the first lane of its class (``share``); a
    lane past its last node repeats it and ``active[r, lane]`` is 0 for its steps.  Returns
    whether any lane took a step.
    """
    ints, floats, supports, share = walkers
    busy = False
    given = np.zeros(LANES, np.int64)
    for lane in range(LANES):
        i = lanes[lane]
        if i >= 0 and share[lane] >= 0:
            source = share[lane]
            given[lane] = given[source]
            for r in range(1, steps + 1):
                x[r, lane] = x[r, source]
                e[r, lane] = e[r, source]
        elif i >= 0:
            row = table[i]
            n_spans = np.int64(row[T_SPANS])
            lo, hi = roads[i, 0], roads[i, 1]
            given[lane] = walk(px[lo:hi], pe[lo:hi], supports[lane, : n_spans + 1],
                               row[T_STOP], row[T_STEP], row[T_TOL], ints[lane], floats[lane],
                               x, e, lane, 1, steps + 1)  # fmt: skip
        for r in range(1 + given[lane], steps + 1):
            x[r, lane] = x[r - 1, lane]
            e[r, lane] = e[r - 1, lane]
        for r in range(steps):
            active[r, lane] = 1.0 if r < given[lane] else 0.0
        busy = busy or given[lane] > 0
    return busy


# ---------------------------------------------------------------------------- blocks
def plan_blocks(expected_steps: np.ndarray, groups: np.ndarray | None = None) -> np.ndarray:
    """Crossing indices of each block, ``(n_blocks, LANES)``, ``-1`` on unused lanes.

    Crossings are sorted by ``groups`` (a block never mixes two groups) and then by their
    expected number of steps, so the crossings of a block finish at about the same step.
    """
    n = expected_steps.size
    groups = np.zeros(n, np.int64) if groups is None else groups
    order = np.lexsort((expected_steps, groups))
    rows = []
    sorted_groups = groups[order]
    bounds = np.flatnonzero(np.diff(sorted_groups)) + 1
    for part in np.split(order, bounds):
        pad = (-part.size) % LANES
        rows.append(np.concatenate((part, np.full(pad, -1, np.int64))).reshape(-1, LANES))
    return np.ascontiguousarray(np.concatenate(rows))


def expected_steps(
    profiles: tuple, profile: np.ndarray, stop: np.ndarray, step: np.ndarray
) -> np.ndarray:
    """About how many steps each crossing's grid has: its samples, plus the length / step."""
    first = np.array([road.x[0] for road in profiles])[profile]
    density = np.array([(road.x.size - 1) / (road.x[-1] - road.x[0]) for road in profiles])
    return (stop - first) * (density[profile] + 1.0 / step)


def shared_table(batch, dt: np.ndarray, columns: int) -> np.ndarray:  # noqa: ANN001
    """The table of crossings with the shared columns ``T_*`` filled (``columns`` in all)."""
    bridges = batch.bridges
    table = np.empty((len(batch), columns))
    stop = batch.bridge_start + batch.column("bridges", "length")
    table[:, T_STOP] = stop
    table[:, T_STEP] = batch.speed * dt
    table[:, T_TOL] = 1e-12 * np.maximum(1.0, np.abs(stop))
    table[:, T_START] = batch.bridge_start
    table[:, T_SPAN] = batch.column("bridges", "span")
    table[:, T_SPANS] = np.array([x.n_spans for x in bridges], dtype=float)[batch.bridge]
    table[:, T_LENGTH] = batch.column("bridges", "length")
    inner = [x.supports[1] if x.n_spans > 1 else np.inf for x in bridges]
    table[:, T_INNER] = np.array(inner)[batch.bridge]
    table[:, T_SPEED] = batch.speed
    # a grid whose every gap is no longer than the step has one piece per gap: crossings of
    # one road, bridge position and stop then have the same nodes, whatever their steps
    widest_gap = np.array([np.diff(road.x).max() for road in batch.profiles])[batch.profile]
    one_piece = widest_gap + table[:, T_TOL] <= table[:, T_STEP]
    table[:, T_WALK] = -1.0
    if one_piece.any():
        rows = np.flatnonzero(one_piece)
        keys = (batch.profile, table[:, T_START], table[:, T_INNER], table[:, T_SPANS], stop)
        _, classes = batch.groups(*(key[rows] for key in keys))
        table[rows, T_WALK] = classes
    return table


#: Batches of fewer blocks than this many per thread run without a parallel region: waking
#: numba's threads costs more than it saves (milliseconds on a busy machine).
BLOCKS_PER_THREAD = 2


def launch(kernels, batch, table: np.ndarray, groups: np.ndarray | None, *extra):  # noqa: ANN001, ANN002
    """Run a lane kernel over a batch; return the summaries and the largest steps [s].

    ``kernels`` is the kernel's ``(prange, serial)`` pair; the serial one runs batches of
    fewer than :data:`BLOCKS_PER_THREAD` blocks per numba thread.

    ``kernel(blocks, px, pe, roads, table, *extra, summaries, widest)`` (``px``, ``pe``:
    the roads end to end, ``roads``: each crossing's slice of them) runs the blocks of
    :func:`plan_blocks` (``prange``, one block handed out at a time since blocks differ in
    length) and fills, for each crossing, its summary row and the widest step of its grid [m].
    """
    n = len(batch)
    offsets = np.zeros(len(batch.profiles) + 1, np.int64)
    offsets[1:] = np.cumsum([road.x.size for road in batch.profiles])
    px = np.concatenate([road.x for road in batch.profiles])
    pe = np.concatenate([road.elevation for road in batch.profiles])
    step = np.where(table[:, T_WALK] >= 0, np.inf, table[:, T_STEP])  # one piece per gap
    steps = expected_steps(batch.profiles, batch.profile, table[:, T_STOP], step)
    blocks = plan_blocks(steps, groups)
    summaries = np.full((n, SUMMARY_SIZE), np.nan)
    widest = np.zeros(n)
    roads = np.stack((offsets[batch.profile], offsets[batch.profile + 1]), axis=1)
    threaded, serial = kernels
    if blocks.shape[0] < BLOCKS_PER_THREAD * numba.get_num_threads():
        serial(blocks, px, pe, roads, table, *extra, summaries, widest)
    else:
        with numba.parallel_chunksize(1):
            threaded(blocks, px, pe, roads, table, *extra, summaries, widest)
    return summaries, widest / batch.speed
