r"""Lane kernel of the many-mode model: many crossings per Newmark step.

The equations, the average-acceleration rule and its reduction to one scalar equation for
the suspension force are those of :mod:`~vbi_lib.models.modal`; here
:data:`~vbi_lib.models.lanes.LANES` crossings advance together (see
:mod:`~vbi_lib.models.lanes`).  A step is a sequence of loops over the lanes, inside loops
over the modes where the modes take part, and each loop writes one flat array: ``z``, the
per-lane values (vehicle, sums over the modes, summary), or ``y``, the per-mode values laid
out mode by mode.  A block holds crossings of one number of modes, on bridges of one or two
spans of any lengths: each mode is evaluated in its general form
:math:`a \sin ks + b \cos ks + c e^{-ks} + d e^{-k(L_j - s)}` in the span of the node
(:func:`vbi_lib.modes.shape_values`), each lane with its own coefficients.  The sprung mass
is the study's :class:`~vbi_lib.Vehicle`.
"""

from __future__ import annotations

from functools import lru_cache

import numba
import numpy as np

from ..bridges import Bridge
from ..modes import beam_modes, shape_values
from ..units import g as GRAVITY
from .base import SUMMARY_SIZE
from .lanes import (
    CHUNK,
    CONTRACT,
    LANES,
    MARK_COUNT,
    T_INNER,
    T_LENGTH,
    T_SHARED,
    T_SPAN,
    T_SPANS,
    T_SPEED,
    T_START,
    exp_parts,
    finish,
    launch,
    next_nodes,
    power_of_two_bits,
    refine_peaks,
    shared_table,
    sincos,
    start_summaries,
    start_walkers,
    track_force,
    track_lane_peak,
)
from .statics import influence_pieces

# columns of the table of crossings, after the shared ones, then the influence pieces
T_MV, T_KV, T_CV, T_COUPLED, T_CONVECTIVE, T_DESIGN = range(T_SHARED, T_SHARED + 6)
T_PIECES = T_SHARED + 6
# the exact influence line of each midspan (mode acceleration), per span j of two: the
# breaks b0..b3, the inverse widths of the three pieces, then each piece's cubic c0..c3
I_BREAK, I_WIDTH, I_CUBIC = 0, 4, 7
I_COUNT = 19
T_COUNT = T_PIECES + 2 * I_COUNT
# per design (bridge and number of modes) and mode: wavenumber, 2 zeta omega, omega^2,
# phi at the two midspans, then the coefficients (a, b, c, d) in span 1 and in span 2, then
# whether the mode has exponential parts (c or d above rounding, see EXP_NEGLIGIBLE)
M_KAPPA, M_TWO_ZW, M_W2, M_MID1, M_MID2, M_COEF = range(6)
M_EXP = M_COEF + 8
# phi at the two midspans over omega^2: the series' static part of the mode acceleration
M_G1, M_G2 = M_EXP + 1, M_EXP + 2
M_COUNT = M_EXP + 3
#: Exponential parts with ``|c|, |d|`` at most this times ``max(|a|, |b|)`` of their span are
#: left out (the sine modes of a simply supported span carry ``c, d`` of rounding size only);
#: exp(-ks) <= 1, so the shape changes by at most this fraction of its amplitude.
EXP_NEGLIGIBLE = 1e-14
# per-lane constants, then the per-mode constants from row K_COUNT on (mode-major)
(K_SPEED, K_START, K_SPAN, K_LENGTH, K_KV, K_CV, K_MV, K_WEIGHT, K_CPL, K_EPS_SPEED,
 K_CV_EPS_SPEED, K_INNER) = range(12)  # fmt: skip
K_PIECES = 12  # the influence pieces, laid out as the table's (I_* per span)
K_COUNT = K_PIECES + 2 * I_COUNT
# rows of the scratch of the shapes: s from the span's left support, L_j - s, span 2 or not,
# and the polynomial parts of exp(-k s) and exp(-k (L_j - s))
S_S, S_REST, S_SECOND, S_E0, S_E1 = range(5)
S_COUNT = 5
# z: per-lane values, the summary from Z_SUMMARY (and the marked turning step after it)
# (the node's midspan values: the series M, its rate V and the series' static part S of each
# midspan; the previous node's P*: mode-acceleration value, series rate, correction, step)
(Z_UV, Z_VV, Z_LAST_FORCE, Z_LAST_X, Z_LAST_ON, Z_H, Z_RATE, Z_ON, Z_ACTIVE, Z_UB,
 Z_UBD, Z_FORCE, Z_NUM, Z_DEN, Z_SV, Z_M1, Z_M2, Z_V1, Z_V2, Z_S1, Z_S2, Z_PM1, Z_PM2,
 Z_PV1, Z_PV2, Z_PC1, Z_PC2, Z_PH, Z_SUMMARY) = range(29)  # fmt: skip
Z_COUNT = Z_SUMMARY + SUMMARY_SIZE + MARK_COUNT
# y: per-mode values, mode-major
Y, V, YT, VT, R, INV_DD = range(6)
Y_COUNT = 6
# nodes: station, elevation, step active, as (rows, LANES) blocks
N_X, N_E, N_ACTIVE = range(3)


# index helpers: unsigned, so that numba adds no wraparound test for negative indices
# (which would stop the compiler from seeing that consecutive lanes are consecutive)
@numba.njit(cache=True, inline="always")
def _k(row, lane):
    return np.uint64(row * LANES + lane)


@numba.njit(cache=True, inline="always")
def _m(n, field, lane):
    """Index of a per-mode constant in ``const``."""
    return np.uint64((K_COUNT + n * M_COUNT + field) * LANES + lane)


@numba.njit(cache=True, inline="always")
def _y(n, field, lane):
    return np.uint64((n * Y_COUNT + field) * LANES + lane)


@numba.njit(cache=True, inline="always")
def _node(field, rows, r, lane):
    return np.uint64((field * rows + r) * LANES + lane)


@numba.njit(cache=True, inline="always")
def _shape(n_modes, r, n, which, lane):
    """Index of ``phi`` (``which`` 0) or ``dphi`` (1) of mode ``n`` at node ``r``."""
    return np.uint64(((r * n_modes + n) * 2 + which) * LANES + lane)


@numba.njit(cache=True, error_model="numpy", fastmath=CONTRACT)
def _shapes(nodes, shapes, rows, n_modes, const, scratch, bits, scales):
    """Mode shapes and slopes at the chunk's nodes near the bridge, all lanes.

    As :func:`vbi_lib.modes.shape_values`: the node's span (the second from beyond the
    interior support), ``s`` from its left support and ``L_j - s`` to its right one, then
    ``a sin ks + b cos ks + c exp(-ks) + d exp(-k (L_j - s))`` and its slope.  ``scratch``
    (:data:`S_COUNT` rows of LANES floats) and ``bits`` (2 LANES int64, seen as floats by
    ``scales``) carry values from one lane loop to the next so that each loop stays packed.

    Rows with every lane off the bridge are left alone (the steps mask them); stations are
    clamped to a hair beyond either end of the bridge (rounding of the support stations),
    which keeps the exponentials finite on lanes off the bridge.
    """
    for r in range(rows):
        near = False
        for lane in range(LANES):
            xi = nodes[_node(N_X, rows, r, lane)] - const[_k(K_START, lane)]
            margin = 1e-6 * const[_k(K_SPAN, lane)]  # rounding of stations at the ends
            near = near or (xi > -margin and xi < const[_k(K_LENGTH, lane)] + margin)
        if not near:
            continue
        for lane in range(LANES):
            length = const[_k(K_LENGTH, lane)]
            inner = const[_k(K_INNER, lane)]
            margin = 1e-6 * const[_k(K_SPAN, lane)]
            xi = nodes[_node(N_X, rows, r, lane)] - const[_k(K_START, lane)]
            xi = min(max(xi, -margin), length + margin)
            second = xi > inner
            left = inner if second else 0.0
            right = length if second else min(inner, length)
            scratch[_k(S_S, lane)] = xi - left
            scratch[_k(S_REST, lane)] = right - xi
            scratch[_k(S_SECOND, lane)] = 1.0 if second else 0.0
        for n in range(n_modes):
            needs = False  # a lane whose mode n has exponential parts
            for lane in range(LANES):
                needs = needs or const[_m(n, M_EXP, lane)] > 0.0
            if not needs:  # sines and cosines only (a simply supported span's modes)
                for lane in range(LANES):
                    k = const[_m(n, M_KAPPA, lane)]
                    first = M_COEF + 4 if scratch[_k(S_SECOND, lane)] > 0.0 else M_COEF
                    a = const[_m(n, first, lane)]
                    b = const[_m(n, first + 1, lane)]
                    sine, cosine = sincos(k * scratch[_k(S_S, lane)])
                    shapes[_shape(n_modes, r, n, 0, lane)] = a * sine + b * cosine
                    shapes[_shape(n_modes, r, n, 1, lane)] = k * (a * cosine - b * sine)
                continue
            # the two exponentials, packed: polynomial parts, then 2**n from its bits
            for lane in range(LANES):
                k = const[_m(n, M_KAPPA, lane)]
                p0, n0 = exp_parts(-k * scratch[_k(S_S, lane)])
                p1, n1 = exp_parts(-k * scratch[_k(S_REST, lane)])
                scratch[_k(S_E0, lane)] = p0
                scratch[_k(S_E1, lane)] = p1
                bits[lane] = power_of_two_bits(n0)
                bits[LANES + lane] = power_of_two_bits(n1)
            for lane in range(LANES):
                k = const[_m(n, M_KAPPA, lane)]
                first = M_COEF + 4 if scratch[_k(S_SECOND, lane)] > 0.0 else M_COEF
                a = const[_m(n, first, lane)]
                b = const[_m(n, first + 1, lane)]
                c = const[_m(n, first + 2, lane)]
                d = const[_m(n, first + 3, lane)]
                sine, cosine = sincos(k * scratch[_k(S_S, lane)])
                e0 = scratch[_k(S_E0, lane)] * scales[lane]  # exp(-k s)
                e1 = scratch[_k(S_E1, lane)] * scales[LANES + lane]  # exp(-k (L_j - s))
                shapes[_shape(n_modes, r, n, 0, lane)] = a * sine + b * cosine + c * e0 + d * e1
                shapes[_shape(n_modes, r, n, 1, lane)] = k * (
                    a * cosine - b * sine - c * e0 + d * e1
                )


@numba.njit(cache=True, error_model="numpy", fastmath=CONTRACT)
def _step(r, rows, nodes, shapes, const, y, z, n_modes):
    """One average-acceleration step ``r -> r + 1`` of every lane (see ``modal._kernel``)."""
    for lane in range(LANES):
        active = nodes[_node(N_ACTIVE, rows, r, lane)] > 0.0
        xa = nodes[_node(N_X, rows, r, lane)]
        xb = nodes[_node(N_X, rows, r + 1, lane)]
        ea = nodes[_node(N_E, rows, r, lane)]
        eb = nodes[_node(N_E, rows, r + 1, lane)]
        speed = const[_k(K_SPEED, lane)]
        dx = xb - xa
        middle = 0.5 * (xa + xb) - const[_k(K_START, lane)]
        on = active & (middle > 0.0) & (middle < const[_k(K_LENGTH, lane)])
        z[_k(Z_ACTIVE, lane)] = 1.0 if active else 0.0
        z[_k(Z_H, lane)] = dx / speed
        z[_k(Z_RATE, lane)] = (eb - ea) / dx * speed if active else 0.0
        z[_k(Z_ON, lane)] = 1.0 if on else 0.0
        z[_k(Z_UB, lane)] = 0.0
        z[_k(Z_UBD, lane)] = 0.0
        for f in range(Z_M1, Z_S2 + 1):
            z[_k(f, lane)] = 0.0
    # ---- the state at the start of the step: sums over the modes
    for n in range(n_modes):
        for lane in range(LANES):
            on = z[_k(Z_ON, lane)] > 0.0
            pa = shapes[_shape(n_modes, r, n, 0, lane)] if on else 0.0
            dpa = shapes[_shape(n_modes, r, n, 1, lane)] if on else 0.0
            q = y[_y(n, Y, lane)]
            qd = y[_y(n, V, lane)]
            z[_k(Z_UB, lane)] += pa * q
            z[_k(Z_UBD, lane)] += pa * qd + const[_k(K_EPS_SPEED, lane)] * dpa * q
            z[_k(Z_M1, lane)] += const[_m(n, M_MID1, lane)] * q
            z[_k(Z_M2, lane)] += const[_m(n, M_MID2, lane)] * q
            z[_k(Z_V1, lane)] += const[_m(n, M_MID1, lane)] * qd
            z[_k(Z_V2, lane)] += const[_m(n, M_MID2, lane)] * qd
            z[_k(Z_S1, lane)] += const[_m(n, M_G1, lane)] * pa
            z[_k(Z_S2, lane)] += const[_m(n, M_G2, lane)] * pa
    # ---- the suspension force at the start (right limit), from the equations
    for lane in range(LANES):
        cpl = const[_k(K_CPL, lane)]
        kv = const[_k(K_KV, lane)]
        cv = const[_k(K_CV, lane)]
        uv = z[_k(Z_UV, lane)]
        vv = z[_k(Z_VV, lane)]
        ea = nodes[_node(N_E, rows, r, lane)]
        rate = z[_k(Z_RATE, lane)]
        force = kv * (cpl * z[_k(Z_UB, lane)] + ea - uv) + cv * (
            cpl * z[_k(Z_UBD, lane)] + rate - vv
        )
        z[_k(Z_FORCE, lane)] = force
        h = z[_k(Z_H, lane)]
        on = z[_k(Z_ON, lane)] > 0.0
        xa = nodes[_node(N_X, rows, r, lane)]
        track_force(z, Z_SUMMARY, lane, on, const[_k(K_WEIGHT, lane)] + force, xa, h)
        beta = 0.25 * h * h
        gamma = 0.5 * h
        av = force / const[_k(K_MV, lane)]
        z[_k(Z_UV, lane)] = uv + h * vv + beta * av  # predictors
        z[_k(Z_VV, lane)] = vv + gamma * av
        z[_k(Z_SV, lane)] = kv * beta + cv * gamma
    # ---- the step that ended at this node, at both midspans
    for lane in range(LANES):
        on = z[_k(Z_ON, lane)] > 0.0
        xa = nodes[_node(N_X, rows, r, lane)]
        _close_step(z, const, lane, xa, on, const[_k(K_WEIGHT, lane)] + z[_k(Z_FORCE, lane)])
        z[_k(Z_PH, lane)] = z[_k(Z_H, lane)] if z[_k(Z_ACTIVE, lane)] > 0.0 else 0.0
    refine_peaks(z, Z_SUMMARY)
    # ---- predictors of the modes, and the sums the end of the step needs
    for lane in range(LANES):
        z[_k(Z_UB, lane)] = 0.0
        z[_k(Z_UBD, lane)] = 0.0
    for n in range(n_modes):
        for lane in range(LANES):
            on = z[_k(Z_ON, lane)] > 0.0
            pa = shapes[_shape(n_modes, r, n, 0, lane)] if on else 0.0
            pb = shapes[_shape(n_modes, r + 1, n, 0, lane)] if on else 0.0
            dpb = shapes[_shape(n_modes, r + 1, n, 1, lane)] if on else 0.0
            h = z[_k(Z_H, lane)]
            q = y[_y(n, Y, lane)]
            qd = y[_y(n, V, lane)]
            acc = (-const[_m(n, M_TWO_ZW, lane)] * qd - const[_m(n, M_W2, lane)] * q
                   - pa * (const[_k(K_WEIGHT, lane)] + z[_k(Z_FORCE, lane)]))  # fmt: skip
            qt = q + h * qd + 0.25 * h * h * acc
            qdt = qd + 0.5 * h * acc
            y[_y(n, YT, lane)] = qt
            y[_y(n, VT, lane)] = qdt
            z[_k(Z_UB, lane)] += pb * qt
            z[_k(Z_UBD, lane)] += pb * qdt + const[_k(K_EPS_SPEED, lane)] * dpb * qt
    # ---- the implicit equations at the end of the step reduce to one for F
    for lane in range(LANES):
        cpl = const[_k(K_CPL, lane)]
        kv = const[_k(K_KV, lane)]
        cv = const[_k(K_CV, lane)]
        uvt = z[_k(Z_UV, lane)]
        vvt = z[_k(Z_VV, lane)]
        eb = nodes[_node(N_E, rows, r + 1, lane)]
        rate = z[_k(Z_RATE, lane)]
        z[_k(Z_NUM, lane)] = kv * (cpl * z[_k(Z_UB, lane)] + eb - uvt) + cv * (
            cpl * z[_k(Z_UBD, lane)] + rate - vvt
        )
        z[_k(Z_DEN, lane)] = 1.0 + z[_k(Z_SV, lane)] / const[_k(K_MV, lane)]
    for n in range(n_modes):
        for lane in range(LANES):
            on = z[_k(Z_ON, lane)] > 0.0
            pb = shapes[_shape(n_modes, r + 1, n, 0, lane)] if on else 0.0
            dpb = shapes[_shape(n_modes, r + 1, n, 1, lane)] if on else 0.0
            h = z[_k(Z_H, lane)]
            beta = 0.25 * h * h
            two_zw = const[_m(n, M_TWO_ZW, lane)]
            w2 = const[_m(n, M_W2, lane)]
            inv_dd = 1.0 / (1.0 + two_zw * 0.5 * h + w2 * beta)
            rr = (
                -two_zw * y[_y(n, VT, lane)]
                - w2 * y[_y(n, YT, lane)]
                - pb * const[_k(K_WEIGHT, lane)]
            )
            g = const[_k(K_CPL, lane)] * (
                z[_k(Z_SV, lane)] * pb + const[_k(K_CV_EPS_SPEED, lane)] * beta * dpb
            )
            y[_y(n, INV_DD, lane)] = inv_dd
            y[_y(n, R, lane)] = rr
            z[_k(Z_DEN, lane)] += g * pb * inv_dd
            z[_k(Z_NUM, lane)] += g * rr * inv_dd
    for lane in range(LANES):
        h = z[_k(Z_H, lane)]
        force = z[_k(Z_NUM, lane)] / z[_k(Z_DEN, lane)]
        z[_k(Z_FORCE, lane)] = force
        av = force / const[_k(K_MV, lane)]
        z[_k(Z_UV, lane)] += 0.25 * h * h * av
        z[_k(Z_VV, lane)] += 0.5 * h * av
    # ---- the modes at the end of the step
    for n in range(n_modes):
        for lane in range(LANES):
            on = z[_k(Z_ON, lane)] > 0.0
            pb = shapes[_shape(n_modes, r + 1, n, 0, lane)] if on else 0.0
            h = z[_k(Z_H, lane)]
            acc = (y[_y(n, R, lane)] - pb * z[_k(Z_FORCE, lane)]) * y[_y(n, INV_DD, lane)]
            q = y[_y(n, YT, lane)] + 0.25 * h * h * acc
            qd = y[_y(n, VT, lane)] + 0.5 * h * acc
            y[_y(n, Y, lane)] = q
            y[_y(n, V, lane)] = qd
    for lane in range(LANES):
        # the contact force at the step's end: the crossing's last node uses it
        active = z[_k(Z_ACTIVE, lane)] > 0.0
        i = _k(Z_LAST_FORCE, lane)
        z[i] = const[_k(K_WEIGHT, lane)] + z[_k(Z_FORCE, lane)] if active else z[i]
        i = _k(Z_LAST_X, lane)
        z[i] = nodes[_node(N_X, rows, r + 1, lane)] if active else z[i]
        i = _k(Z_LAST_ON, lane)
        z[i] = z[_k(Z_ON, lane)] if active else z[i]


@numba.njit(cache=True, inline="always", error_model="numpy", fastmath=CONTRACT)
def _influence(const, lane, j, s):
    """The exact downward deflection of midspan ``j`` under a unit load at ``s`` [m/N]."""
    base = K_PIECES + j * I_COUNT
    # every piece evaluated, then the one holding s picked: no gather, so the lanes stay packed
    values = 0.0
    for k in range(3):
        u = (s - const[_k(base + I_BREAK + k, lane)]) * const[_k(base + I_WIDTH + k, lane)]
        c = base + I_CUBIC + 4 * k
        value = ((const[_k(c + 3, lane)] * u + const[_k(c + 2, lane)]) * u
                 + const[_k(c + 1, lane)]) * u + const[_k(c, lane)]  # fmt: skip
        start = const[_k(base + I_BREAK + k, lane)]
        values = value if (k == 0) | (s >= start) else values
    return values


@numba.njit(cache=True, inline="always", error_model="numpy", fastmath=CONTRACT)
def _close_step(z, const, lane, x, on, contact):
    """Track the step that ends at this node, at both midspans (the whole run).

    The headline midspan displacement is the mode-acceleration one (``modal``'s
    ``midspan_history``): the series plus ``F_c (sum_n phi_n(m_j) phi_n(x) / omega_n^2 -
    eta_j(x))``, ``F_c`` the contact force (the step's from this node on; zero off the bridge).
    The previous node's values (``Z_P*``) and this node's give the step's peak, the series'
    rates exact and the correction's its secant; then this node's values become the
    previous ones.  ``Z_PH`` 0: no step to close (the first node).
    """
    s = x - const[_k(K_START, lane)]
    force = contact if on else 0.0
    c1 = force * (z[_k(Z_S1, lane)] - (_influence(const, lane, 0, s) if on else 0.0))
    c2 = force * (z[_k(Z_S2, lane)] - (_influence(const, lane, 1, s) if on else 0.0))
    m1 = z[_k(Z_M1, lane)] + c1
    m2 = z[_k(Z_M2, lane)] + c2
    h = z[_k(Z_PH, lane)]
    closing = h > 0.0
    hh = h if closing else 1.0
    r1 = (c1 - z[_k(Z_PC1, lane)]) / hh
    r2 = (c2 - z[_k(Z_PC2, lane)]) / hh
    track_lane_peak(z, Z_SUMMARY, lane, closing, 0.0, z[_k(Z_PM1, lane)], m1,
               z[_k(Z_PV1, lane)] + r1, z[_k(Z_V1, lane)] + r1, hh)  # fmt: skip
    track_lane_peak(z, Z_SUMMARY, lane, closing, 1.0, z[_k(Z_PM2, lane)], m2,
               z[_k(Z_PV2, lane)] + r2, z[_k(Z_V2, lane)] + r2, hh)  # fmt: skip
    z[_k(Z_PM1, lane)] = m1
    z[_k(Z_PM2, lane)] = m2
    z[_k(Z_PV1, lane)] = z[_k(Z_V1, lane)]
    z[_k(Z_PV2, lane)] = z[_k(Z_V2, lane)]
    z[_k(Z_PC1, lane)] = c1
    z[_k(Z_PC2, lane)] = c2


@numba.njit(cache=True, error_model="numpy", fastmath=CONTRACT)
def _close_last(y, z, const, n_modes):
    """Close each lane's last step at its last node (every axle at or past the bridge's
    end, where the correction vanishes): the series alone, from the final modes."""
    for lane in range(LANES):
        for f in range(Z_M1, Z_S2 + 1):
            z[_k(f, lane)] = 0.0
    for n in range(n_modes):
        for lane in range(LANES):
            q = y[_y(n, Y, lane)]
            qd = y[_y(n, V, lane)]
            z[_k(Z_M1, lane)] += const[_m(n, M_MID1, lane)] * q
            z[_k(Z_M2, lane)] += const[_m(n, M_MID2, lane)] * q
            z[_k(Z_V1, lane)] += const[_m(n, M_MID1, lane)] * qd
            z[_k(Z_V2, lane)] += const[_m(n, M_MID2, lane)] * qd
    for lane in range(LANES):
        _close_step(z, const, lane, 0.0, False, 0.0)
        z[_k(Z_PH, lane)] = 0.0
    refine_peaks(z, Z_SUMMARY)


@numba.njit(cache=True, error_model="numpy")
def _block(lanes, px, pe, roads, table, counts, designs, summaries, widest):
    """Run the crossings ``lanes`` (``-1``: unused lane; one number of modes) to their ends."""
    n_modes = counts[np.int64(table[lanes[0], T_DESIGN])]
    chunk = max(8, min(CHUNK, 1024 // n_modes))
    rows = chunk + 1
    const = np.zeros((K_COUNT + n_modes * M_COUNT) * LANES)
    z = np.zeros(Z_COUNT * LANES)
    y = np.zeros(n_modes * Y_COUNT * LANES)
    for lane in range(LANES):
        row = table[lanes[lane] if lanes[lane] >= 0 else lanes[0]]
        speed = row[T_SPEED]
        const[_k(K_SPEED, lane)] = speed
        const[_k(K_START, lane)] = row[T_START]
        const[_k(K_SPAN, lane)] = row[T_SPAN]
        const[_k(K_LENGTH, lane)] = row[T_LENGTH]
        const[_k(K_INNER, lane)] = row[T_INNER]
        const[_k(K_KV, lane)] = row[T_KV]
        const[_k(K_CV, lane)] = row[T_CV]
        const[_k(K_MV, lane)] = row[T_MV]
        const[_k(K_WEIGHT, lane)] = row[T_MV] * GRAVITY
        const[_k(K_CPL, lane)] = row[T_COUPLED]
        eps = row[T_CONVECTIVE]
        const[_k(K_EPS_SPEED, lane)] = eps * speed
        const[_k(K_CV_EPS_SPEED, lane)] = row[T_CV] * eps * speed
        for f in range(2 * I_COUNT):
            const[_k(K_PIECES + f, lane)] = row[T_PIECES + f]
        design = np.int64(row[T_DESIGN])
        for n in range(n_modes):
            for f in range(M_COUNT):
                const[_m(n, f, lane)] = designs[design, f, n]
        start_summaries(z, Z_SUMMARY, np.int64(row[T_SPANS]), lane)
    scratch = np.empty(S_COUNT * LANES)
    bits = np.empty(2 * LANES, np.int64)
    nodes = np.empty(3 * rows * LANES)
    shapes = np.empty(rows * n_modes * 2 * LANES)  # rows off the bridge: masked, never read
    grid = nodes.reshape((3, rows, LANES))
    walkers = start_walkers(lanes, px, pe, roads, table, grid[N_X], grid[N_E])
    for lane in range(LANES):
        z[_k(Z_UV, lane)] = grid[N_E, 0, lane]  # at rest in static equilibrium
    while next_nodes(lanes, px, pe, roads, table, walkers, grid[N_X], grid[N_E],
                     grid[N_ACTIVE], chunk):  # fmt: skip
        _shapes(nodes, shapes, rows, n_modes, const, scratch, bits, bits.view(np.float64))
        for r in range(chunk):
            _step(r, rows, nodes, shapes, const, y, z, n_modes)
        for lane in range(LANES):
            grid[N_X, 0, lane] = grid[N_X, chunk, lane]
            grid[N_E, 0, lane] = grid[N_E, chunk, lane]
    _close_last(y, z, const, n_modes)
    for lane in range(LANES):
        # the last node: the force at the end of the last step
        track_force(z, Z_SUMMARY, lane, z[_k(Z_LAST_ON, lane)] > 0.0,
                    z[_k(Z_LAST_FORCE, lane)], z[_k(Z_LAST_X, lane)], 0.0)  # fmt: skip
    finish(lanes, z, Z_SUMMARY, walkers, summaries, widest)


@numba.njit(cache=True, parallel=True)
def _run(blocks, px, pe, roads, table, counts, designs, summaries, widest):
    for b in numba.prange(blocks.shape[0]):
        _block(blocks[b], px, pe, roads, table, counts, designs, summaries, widest)


@numba.njit(cache=True)
def _run_serial(blocks, px, pe, roads, table, counts, designs, summaries, widest):
    for b in range(blocks.shape[0]):
        _block(blocks[b], px, pe, roads, table, counts, designs, summaries, widest)


@lru_cache(maxsize=1024)
def _pieces_row(bridge: Bridge) -> np.ndarray:
    """The table's influence columns of a bridge: the exact influence line of each midspan
    in cubic pieces (:func:`~vbi_lib.models.statics.influence_pieces`) padded to three
    pieces a span; a one-span bridge's second span is zero."""
    row = np.zeros(2 * I_COUNT)
    breaks, cubics = influence_pieces(bridge)
    for j in range(bridge.n_spans):
        part = row[j * I_COUNT : (j + 1) * I_COUNT]
        b = np.full(4, breaks[j, -1])
        b[: breaks.shape[1]] = breaks[j]
        part[I_BREAK : I_BREAK + 4] = b
        width = np.diff(b)
        part[I_WIDTH : I_WIDTH + 3] = np.divide(1.0, width, out=np.zeros(3), where=width > 0)
        part[I_CUBIC : I_CUBIC + 4 * cubics.shape[1]] = cubics[j].ravel()
    row.setflags(write=False)
    return row


def run(batch, dt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:  # noqa: ANN001
    """Summaries ``(n, SUMMARY_SIZE)`` and largest steps ``(n,)`` [s] of a batch.

    ``batch`` is a :class:`~vbi_lib.models.batch.Batch` of the study's vehicles with
    ``batch.modes`` the number of modes of each crossing; ``dt`` the largest step [s].
    """
    table = shared_table(batch, dt, T_COUNT)
    table[:, T_MV] = batch.column("vehicles", "mass")
    table[:, T_KV] = batch.column("vehicles", "stiffness")
    table[:, T_CV] = batch.column("vehicles", "damping")
    table[:, T_COUPLED] = batch.coupled
    table[:, T_CONVECTIVE] = batch.convective
    # one design per bridge and number of modes
    first, inverse = batch.groups(batch.bridge, batch.modes)
    table[:, T_DESIGN] = inverse
    counts = batch.modes[first]
    width = int(counts.max())
    designs = np.zeros((first.size, M_COUNT, width))
    for d, count in enumerate(counts):
        bridge = batch.bridges[batch.bridge[first[d]]]
        basis = beam_modes(bridge, int(count))
        designs[d, M_KAPPA, :count] = basis.wavenumber
        # as the model's kernel has them: zeta the bridge's, phi at the midspans
        zeta = np.full(count, bridge.damping_ratio)
        designs[d, M_TWO_ZW, :count] = 2.0 * zeta * basis.omega
        designs[d, M_W2, :count] = basis.omega * basis.omega
        mid = np.empty((bridge.n_spans, count))  # phi at each midspan, compiled
        slope, curvature = np.empty(count), np.empty(count)
        supports = np.array(bridge.supports)
        for j, station in enumerate(bridge.midspans):
            shape_values(station, supports, basis.wavenumber, basis.coefficients, mid[j], slope,
                         curvature)  # fmt: skip
        designs[d, M_MID1, :count] = mid[0]
        for j in range(bridge.n_spans):
            designs[d, M_COEF + 4 * j : M_COEF + 4 * j + 4, :count] = basis.coefficients[:, j].T
            if j > 0:
                designs[d, M_MID2, :count] = mid[j]
        coef = np.abs(basis.coefficients)  # (N, n_spans, 4)
        size = np.maximum(coef[:, :, 0], coef[:, :, 1])
        exps = (np.maximum(coef[:, :, 2], coef[:, :, 3]) > EXP_NEGLIGIBLE * size).any(axis=1)
        designs[d, M_EXP, :count] = exps
        designs[d, M_G1, :count] = mid[0] / basis.omega**2
        designs[d, M_G2, :count] = (mid[1] if bridge.n_spans > 1 else 0.0) / basis.omega**2
    pieces = np.array([_pieces_row(bridge) for bridge in batch.bridges])
    table[:, T_PIECES:] = pieces[batch.bridge]
    # a block holds one number of modes
    return launch((_run, _run_serial), batch, table, batch.modes, counts, designs)
