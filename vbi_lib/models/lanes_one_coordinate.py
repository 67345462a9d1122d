r"""Lane kernel of the study's two-degree-of-freedom model: many crossings per RK4 step.

The equations and the integrator are those of :mod:`~vbi_lib.models.one_coordinate`
(classical RK4 on the shared node grid, shape function and road linear within a step), with
the state-space product written out: with the suspension force

.. math:: F = k_v (r - u_v) + c_v (\dot r - \dot u_v) + \kappa z_b + \gamma \dot z_b,

(:math:`\kappa = k_v\psi + \epsilon c_v v \psi'`, :math:`\gamma = c_v\psi`, both zero when
decoupled; :math:`r, \dot r` the road here), :math:`\ddot u_v = F/m_v` and
:math:`\ddot z_b = (-k^* z_b - c^* \dot z_b - \psi (m_v g + F))/m^*`, which is
:math:`A z + B U + f` of (51)-(58) multiplied out.  :data:`~vbi_lib.models.lanes.LANES`
crossings advance together (see :mod:`~vbi_lib.models.lanes`); the sprung mass is the
study's :class:`~vbi_lib.Vehicle`.
"""

from __future__ import annotations

import math

import numba
import numpy as np

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
    finish,
    launch,
    next_nodes,
    refine_peaks,
    shared_table,
    sincos,
    start_summaries,
    start_walkers,
    track_force,
    track_lane_peaks,
)

# columns of the table of crossings, after the shared ones
T_MV, T_KV, T_CV, T_MB, T_KB, T_CB, T_COUPLED, T_CONVECTIVE = range(T_SHARED, T_SHARED + 8)
T_COUNT = T_SHARED + 8
# rows of a block's lane constants
(K_SPEED, K_START, K_SPAN, K_LENGTH, K_WAVE, K_KV, K_CV, K_KV_COUPLED, K_CV_COUPLED,
 K_CVV_CONVECTIVE, K_INV_MV, K_KB, K_CB, K_INV_MB, K_WEIGHT, K_INNER) = range(16)  # fmt: skip
K_COUNT = 16
# rows of a block's node buffer (CHUNK + 1 nodes: the chunk's steps and the node after)
B_X, B_E, B_ACTIVE, B_PSI, B_DPSI, B_PSI_MID, B_DPSI_MID = range(7)
B_COUNT = 7
NODES = CHUNK + 1
# rows of a block's state: u_v, u_v', z_b, z_b', the contact force at the last node, then
# the summary (layout of the base module) from row Z_SUMMARY
Z_U, Z_V, Z_Q, Z_QD, Z_LAST_FORCE, Z_LAST_X, Z_LAST_ON, Z_SUMMARY = range(8)
Z_COUNT = Z_SUMMARY + SUMMARY_SIZE + MARK_COUNT


@numba.njit(cache=True, inline="always")
def _at(row, r, lane):
    """Index of node ``r`` of a lane in row ``row`` of the flat node buffer."""
    return (row * NODES + r) * LANES + lane


@numba.njit(cache=True, error_model="numpy", fastmath=CONTRACT)
def _shapes(buf, const):
    """``psi`` and ``dpsi/dx`` at the chunk's nodes and midpoints near the bridge, all lanes.

    Rows where every lane is off the bridge are left alone: the steps mask the shape there.
    """
    for r in range(NODES):
        near = False
        for lane in range(LANES):
            xi = buf[_at(B_X, r, lane)] - const[K_START * LANES + lane]
            span = const[K_SPAN * LANES + lane]
            margin = 1e-6 * span  # rounding of stations at the bridge's ends
            near = near or (xi > -margin and xi < const[K_LENGTH * LANES + lane] + margin)
        if not near:
            continue
        for lane in range(LANES):
            wave = const[K_WAVE * LANES + lane]
            s, c = sincos(wave * (buf[_at(B_X, r, lane)] - const[K_START * LANES + lane]))
            buf[_at(B_PSI, r, lane)] = s
            buf[_at(B_DPSI, r, lane)] = wave * c
        if r < CHUNK:
            for lane in range(LANES):
                wave = const[K_WAVE * LANES + lane]
                middle = 0.5 * (buf[_at(B_X, r, lane)] + buf[_at(B_X, r + 1, lane)])
                s, c = sincos(wave * (middle - const[K_START * LANES + lane]))
                buf[_at(B_PSI_MID, r, lane)] = s
                buf[_at(B_DPSI_MID, r, lane)] = wave * c


@numba.njit(cache=True, inline="always", error_model="numpy", fastmath=CONTRACT)
def _force(kv, cv, e, rate, u, ud, kz, cz, q, qd):
    """Suspension force ``F`` [N] (the contact force is ``m_v g + F``)."""
    return kv * (e - u) + cv * (rate - ud) + kz * q + cz * qd


@numba.njit(cache=True, inline="always", error_model="numpy", fastmath=CONTRACT)
def _coupling(const, lane, psi, dpsi):
    """``kappa`` and ``gamma`` of the suspension force at a point (zero when decoupled)."""
    kz = const[K_KV_COUPLED * LANES + lane] * psi + const[K_CVV_CONVECTIVE * LANES + lane] * dpsi
    return kz, const[K_CV_COUPLED * LANES + lane] * psi


@numba.njit(cache=True, error_model="numpy", fastmath=CONTRACT)
def _steps(buf, const, state):
    """RK4 over the chunk's steps, every lane at once (no branch in the lane loop)."""
    for r in range(CHUNK):
        for lane in range(LANES):
            active = buf[_at(B_ACTIVE, r, lane)] > 0.0
            xa = buf[_at(B_X, r, lane)]
            xb = buf[_at(B_X, r + 1, lane)]
            ea = buf[_at(B_E, r, lane)]
            eb = buf[_at(B_E, r + 1, lane)]
            speed = const[K_SPEED * LANES + lane]
            dx = xb - xa
            h = dx / speed
            rate = (eb - ea) / dx * speed if active else 0.0
            middle = 0.5 * (xa + xb) - const[K_START * LANES + lane]
            on = active & (middle > 0.0) & (middle < const[K_LENGTH * LANES + lane])
            psa = buf[_at(B_PSI, r, lane)] if on else 0.0
            psm = buf[_at(B_PSI_MID, r, lane)] if on else 0.0
            psb = buf[_at(B_PSI, r + 1, lane)] if on else 0.0
            dpa = buf[_at(B_DPSI, r, lane)] if on else 0.0
            dpm = buf[_at(B_DPSI_MID, r, lane)] if on else 0.0
            dpb = buf[_at(B_DPSI, r + 1, lane)] if on else 0.0
            kv = const[K_KV * LANES + lane]
            cv = const[K_CV * LANES + lane]
            kza, cza = _coupling(const, lane, psa, dpa)
            kzm, czm = _coupling(const, lane, psm, dpm)
            kzb, czb = _coupling(const, lane, psb, dpb)
            kb = const[K_KB * LANES + lane]
            cb = const[K_CB * LANES + lane]
            inv_mv = const[K_INV_MV * LANES + lane]
            inv_mb = const[K_INV_MB * LANES + lane]
            weight = const[K_WEIGHT * LANES + lane]
            em = 0.5 * (ea + eb)
            half = 0.5 * h
            u = state[Z_U * LANES + lane]
            ud = state[Z_V * LANES + lane]
            q = state[Z_Q * LANES + lane]
            qd = state[Z_QD * LANES + lane]
            f1 = _force(kv, cv, ea, rate, u, ud, kza, cza, q, qd)
            a1 = f1 * inv_mv
            b1 = (-kb * q - cb * qd - psa * (f1 + weight)) * inv_mb
            u2 = u + half * ud
            ud2 = ud + half * a1
            q2 = q + half * qd
            qd2 = qd + half * b1
            f2 = _force(kv, cv, em, rate, u2, ud2, kzm, czm, q2, qd2)
            a2 = f2 * inv_mv
            b2 = (-kb * q2 - cb * qd2 - psm * (f2 + weight)) * inv_mb
            u3 = u + half * ud2
            ud3 = ud + half * a2
            q3 = q + half * qd2
            qd3 = qd + half * b2
            f3 = _force(kv, cv, em, rate, u3, ud3, kzm, czm, q3, qd3)
            a3 = f3 * inv_mv
            b3 = (-kb * q3 - cb * qd3 - psm * (f3 + weight)) * inv_mb
            u4 = u + h * ud3
            ud4 = ud + h * a3
            q4 = q + h * qd3
            qd4 = qd + h * b3
            f4 = _force(kv, cv, eb, rate, u4, ud4, kzb, czb, q4, qd4)
            a4 = f4 * inv_mv
            b4 = (-kb * q4 - cb * qd4 - psb * (f4 + weight)) * inv_mb
            sixth = h / 6.0
            u_new = u + sixth * (ud + 2.0 * ud2 + 2.0 * ud3 + ud4)
            ud_new = ud + sixth * (a1 + 2.0 * a2 + 2.0 * a3 + a4)
            q_new = q + sixth * (qd + 2.0 * qd2 + 2.0 * qd3 + qd4)
            qd_new = qd + sixth * (b1 + 2.0 * b2 + 2.0 * b3 + b4)
            # every midspan over the whole run: psi(mid_j) z_b = +z_b (span 1), -z_b (span 2)
            track_lane_peaks(state, Z_SUMMARY, lane, active, q, q_new, qd, qd_new, h)
            track_force(state, Z_SUMMARY, lane, on, weight + f1, xa, h)
            # the contact force at the step's end: the crossing's last node uses it
            f_end = _force(kv, cv, eb, rate, u_new, ud_new, kzb, czb, q_new, qd_new)
            i = Z_LAST_FORCE * LANES + lane
            state[i] = weight + f_end if active else state[i]
            i = Z_LAST_X * LANES + lane
            state[i] = xb if active else state[i]
            i = Z_LAST_ON * LANES + lane
            state[i] = (1.0 if on else 0.0) if active else state[i]
            state[Z_U * LANES + lane] = u_new
            state[Z_V * LANES + lane] = ud_new
            state[Z_Q * LANES + lane] = q_new
            state[Z_QD * LANES + lane] = qd_new
        refine_peaks(state, Z_SUMMARY, 1)  # one set: track_lane_peaks's


@numba.njit(cache=True, error_model="numpy")
def _block(lanes, px, pe, roads, table, summaries, widest):
    """Run the crossings ``lanes`` (``-1``: unused lane) to the end of their grids."""
    const = np.empty(K_COUNT * LANES)
    buf = np.empty(B_COUNT * NODES * LANES)  # shape rows off the bridge: masked, never read
    state = np.zeros(Z_COUNT * LANES)
    for lane in range(LANES):
        row = table[lanes[lane] if lanes[lane] >= 0 else lanes[0]]
        speed = row[T_SPEED]
        const[K_SPEED * LANES + lane] = speed
        const[K_START * LANES + lane] = row[T_START]
        const[K_SPAN * LANES + lane] = row[T_SPAN]
        const[K_LENGTH * LANES + lane] = row[T_LENGTH]
        const[K_INNER * LANES + lane] = row[T_INNER]
        const[K_WAVE * LANES + lane] = math.pi / row[T_SPAN]
        const[K_KV * LANES + lane] = row[T_KV]
        const[K_CV * LANES + lane] = row[T_CV]
        # kappa = k_v psi + c_v v psi' and gamma = c_v psi, their factors zero when decoupled
        coupled = 1.0 if row[T_COUPLED] > 0.0 else 0.0
        convective = 1.0 if row[T_CONVECTIVE] > 0.0 else 0.0
        const[K_KV_COUPLED * LANES + lane] = coupled * row[T_KV]
        const[K_CV_COUPLED * LANES + lane] = coupled * row[T_CV]
        const[K_CVV_CONVECTIVE * LANES + lane] = coupled * convective * (row[T_CV] * speed)
        const[K_INV_MV * LANES + lane] = 1.0 / row[T_MV]
        const[K_KB * LANES + lane] = row[T_KB]
        const[K_CB * LANES + lane] = row[T_CB]
        const[K_INV_MB * LANES + lane] = 1.0 / row[T_MB]
        const[K_WEIGHT * LANES + lane] = row[T_MV] * GRAVITY
        start_summaries(state, Z_SUMMARY, np.int64(row[T_SPANS]), lane)
    rows = buf.reshape((B_COUNT, NODES, LANES))
    walkers = start_walkers(lanes, px, pe, roads, table, rows[B_X], rows[B_E])
    for lane in range(LANES):
        state[Z_U * LANES + lane] = rows[B_E, 0, lane]  # at rest in static equilibrium
    while next_nodes(lanes, px, pe, roads, table, walkers, rows[B_X], rows[B_E],
                     rows[B_ACTIVE], CHUNK):  # fmt: skip
        _shapes(buf, const)
        _steps(buf, const, state)
        for lane in range(LANES):
            rows[B_X, 0, lane] = rows[B_X, CHUNK, lane]
            rows[B_E, 0, lane] = rows[B_E, CHUNK, lane]
    for lane in range(LANES):
        # the last node starts no step: its force uses the last step's coefficients
        on = state[Z_LAST_ON * LANES + lane] > 0.0
        force = state[Z_LAST_FORCE * LANES + lane]
        track_force(state, Z_SUMMARY, lane, on, force, state[Z_LAST_X * LANES + lane], 0.0)
    finish(lanes, state, Z_SUMMARY, walkers, summaries, widest)


@numba.njit(cache=True, parallel=True)
def _run(blocks, px, pe, roads, table, summaries, widest):
    for b in numba.prange(blocks.shape[0]):
        _block(blocks[b], px, pe, roads, table, summaries, widest)


@numba.njit(cache=True)
def _run_serial(blocks, px, pe, roads, table, summaries, widest):
    for b in range(blocks.shape[0]):
        _block(blocks[b], px, pe, roads, table, summaries, widest)


def run(batch, dt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:  # noqa: ANN001
    """Summaries ``(n, SUMMARY_SIZE)`` and largest steps ``(n,)`` [s] of a batch.

    ``batch`` is a :class:`~vbi_lib.models.batch.Batch` of the study's vehicles; ``dt`` the
    largest step of each crossing [s].
    """
    table = shared_table(batch, dt, T_COUNT)
    table[:, T_MV] = batch.column("vehicles", "mass")
    table[:, T_KV] = batch.column("vehicles", "stiffness")
    table[:, T_CV] = batch.column("vehicles", "damping")
    table[:, T_MB] = batch.column("bridges", "generalized_mass")
    table[:, T_KB] = batch.column("bridges", "generalized_stiffness")
    table[:, T_CB] = batch.column("bridges", "generalized_damping")
    table[:, T_COUPLED] = batch.coupled
    table[:, T_CONVECTIVE] = batch.convective
    return launch((_run, _run_serial), batch, table, None)
