r"""The one-coordinate model's kernel for any vehicle (RK4 with located contact switches).

The beam deflects as :math:`\psi(x) z_b` (:mod:`~vbi_lib.models.one_coordinate`); the
vehicle is a :class:`~vbi_lib.vehicles.VehicleSystem` whose axle ``a`` is at
:math:`x_a = x_1 - \text{offset}_a`.  With :math:`\psi_a = \psi(x_a)` (zero off the bridge),
the road under axle ``a`` is :math:`r_a = \psi_a z_b + \bar\Delta_a` and

.. math::
    \tilde F_a &= P_a + k_a (r_a - e_a \cdot u) + c_a (\dot r_a - e_a \cdot \dot u), \qquad
        \dot r_a = \psi_a \dot z_b + \epsilon\, v \psi'_a z_b + \dot{\bar\Delta}_a \\
    M \ddot u + C \dot u + K u &= E^T (\mathbf{F}_c - \mathbf{P}), \qquad
    m^* \ddot z_b + c^* \dot z_b + k^* z_b = -\textstyle\sum_a \psi_a F_{c,a}

with the contact force :math:`F_{c,a} = \tilde F_a` for a bilateral contact and
:math:`\max(0, \tilde F_a)` for a tyre, :math:`P_a` the axle's static load.  One
axle with :math:`M = m_v`, :math:`K = C = 0`, :math:`E = 1` is the study's equations
(46)-(58).  States :math:`y = (u, \dot u, z_b, \dot z_b)`, classical RK4 on the node grid
(the road under every axle is linear within a step); a tyre's take-off or landing inside a
step is located and the step is split there (:mod:`~vbi_lib.models.axles`).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .axles import (
    ACCEPT_STEP,
    RETRY,
    locate_switch,
    log_event,
    track_axles,
    track_flight,
    unpack,
)
from .base import (
    P_COUNT,
    P_SPAN,
    P_SPEED,
    P_START,
    S_MIN_FORCE,
    downward_peak,
    start_summary,
    track_peak,
)

# the model's entries of the parameter vector, after the shared ones (as one_coordinate's)
_M_B, _K_B, _C_B = P_COUNT, P_COUNT + 1, P_COUNT + 2


@numba.njit(cache=True)
def kernel(x, road, axle_span, params, n_spans, coupled, convective, vec, n, n_axles, states,
           contact, summary, events, event_count):  # fmt: skip
    """Integrate one crossing of any vehicle (``vec``, :func:`~.axles.vehicle_vector`).

    ``states`` (n_nodes x (2n + 2)) and ``contact`` (n_nodes x n_axles, the contact forces
    pressing on the road) receive the histories when they have one row per node; with one
    row only the summary is kept.  ``events`` (rows: time, axle, +1 take-off or -1 landing,
    station) receives the tyres' switches while it has room; ``event_count[0]`` counts them.
    The helpers are closures over the kernel's arrays (numba inlines them), which keeps the
    inner loop as fast as a hand-written one.
    """
    _, Minv, K, C, E, W, kt, ct, off, unilateral, u0 = unpack(vec, n, n_axles)
    weight = W.sum()
    cpl = 1.0 if coupled else 0.0
    eps = 1.0 if convective else 0.0
    speed = params[P_SPEED]
    wave = math.pi / params[P_SPAN]
    m_b, k_b, c_b = params[_M_B], params[_K_B], params[_C_B]
    n_nodes = x.shape[0]
    m = 2 * n + 2
    record = states.shape[0] == n_nodes
    psi = np.empty(n_axles)
    dpsi = np.empty(n_axles)
    level = np.empty(n_axles)
    rate = np.empty(n_axles)
    dyn = np.empty(n_axles)
    force = np.empty(n_axles)
    gen = np.empty(n)
    start_gap = np.zeros(n_axles)
    end_gap = np.zeros(n_axles)
    slopes = np.empty((4, m))  # the four RK4 stages
    tmp = np.empty(m)
    y = np.zeros(m)
    trial = np.empty(m)
    flying = np.zeros(n_axles, dtype=np.bool_)

    def inputs(theta, k, shapes_known=False):
        """Shape values and the road under each axle at fraction ``theta`` of step ``k``.

        ``shapes_known``: ``psi`` and ``dpsi`` already hold the values at this point.
        """
        xa = x[k]
        xb = x[k + 1]
        if theta == 0.0:
            xf = xa
        elif theta == 1.0:
            xf = xb
        elif theta == 0.5:
            xf = 0.5 * (xa + xb)
        else:
            xf = xa + theta * (xb - xa)
        for a in range(n_axles):
            if shapes_known:
                pass
            elif axle_span[a, k] > 0:
                xi = xf - off[a] - params[P_START]
                psi[a] = math.sin(wave * xi)
                dpsi[a] = wave * math.cos(wave * xi)
            else:
                psi[a] = 0.0
                dpsi[a] = 0.0
            ra = road[a, k]
            rb = road[a, k + 1]
            if theta == 0.0:
                level[a] = ra
            elif theta == 1.0:
                level[a] = rb
            elif theta == 0.5:
                level[a] = 0.5 * (ra + rb)
            else:
                level[a] = ra + theta * (rb - ra)
            rate[a] = (rb - ra) / (xb - xa) * speed

    def dynamic(a, yy):
        """``P_a - W_a`` of axle ``a`` as if it touched (``inputs`` set)."""
        z = yy[2 * n]
        zd = yy[2 * n + 1]
        eu = 0.0
        ev = 0.0
        for i in range(n):
            eu += E[a, i] * yy[i]
            ev += E[a, i] * yy[n + i]
        r = cpl * psi[a] * z + level[a]
        rd = cpl * (psi[a] * zd + eps * speed * dpsi[a] * z) + rate[a]
        return kt[a] * (r - eu) + ct[a] * (rd - ev)

    def derivative(out, yy):
        """``dy/dt`` at the inputs set; ``dyn`` receives every ``P_a - W_a``."""
        for i in range(n):
            gen[i] = 0.0
        on_bridge = 0.0
        for a in range(n_axles):
            f = dynamic(a, yy)
            dyn[a] = f
            if flying[a]:
                f = -W[a]
            for i in range(n):
                gen[i] += E[a, i] * f
            on_bridge += psi[a] * (W[a] + f)
        for i in range(n):
            s = gen[i]
            for j in range(n):
                s -= C[i, j] * yy[n + j] + K[i, j] * yy[j]
            gen[i] = s
        for i in range(n):
            s = 0.0
            for j in range(n):
                s += Minv[i, j] * gen[j]
            out[i] = yy[n + i]
            out[n + i] = s
        out[2 * n] = yy[2 * n + 1]
        out[2 * n + 1] = (-c_b * yy[2 * n + 1] - k_b * yy[2 * n] - on_bridge) / m_b

    def rk4(y0, y1, th0, th1, k, k1_ready):
        """RK4 over step ``k`` from ``th0`` to ``th1`` (``slopes[0]`` holds f(th0) if ready).

        One loop over the four stages, so the right-hand side is compiled once.
        """
        h = (x[k + 1] - x[k]) / speed * (th1 - th0)
        mid = 0.5 * (th0 + th1)
        for stage in range(4):
            if stage == 0:
                if k1_ready:
                    continue
                for i in range(m):
                    tmp[i] = y0[i]
            else:
                scale = h if stage == 3 else 0.5 * h
                for i in range(m):
                    tmp[i] = y0[i] + scale * slopes[stage - 1, i]
            if stage != 2:
                inputs(th0 if stage == 0 else (mid if stage == 1 else th1), k)
            derivative(slopes[stage], tmp)
        for i in range(m):
            y1[i] = y0[i] + h * (slopes[0, i] + 2.0 * slopes[1, i] + 2.0 * slopes[2, i]
                                 + slopes[3, i]) / 6.0  # fmt: skip

    def peaks(y0, y1, h):
        """Every midspan's peak between two states ``h`` seconds apart (the whole run)."""
        for j in range(n_spans):
            sign = 1.0 if j % 2 == 0 else -1.0  # psi at midspan of span j + 1
            track_peak(summary, j + 1, downward_peak(
                sign * y0[2 * n], sign * y1[2 * n], sign * y0[2 * n + 1],
                sign * y1[2 * n + 1], h))  # fmt: skip

    for i in range(n):
        y[i] = u0[i]
    start_summary(summary, n_spans)
    if record:
        for i in range(m):
            states[0, i] = y[i]
    at_end = False  # psi, dpsi hold the values at the end of the previous step
    for k in range(n_nodes):
        last = k == n_nodes - 1
        step = k - 1 if last else k
        # the contact state at the node, with this step's road rate (right limit); the
        # shape values carry over from the previous step's end unless an axle changed span
        known = at_end
        if known and not last:
            for a in range(n_axles):
                known = known and axle_span[a, k] == axle_span[a, k - 1]
        inputs(1.0 if last else 0.0, step, known)
        derivative(slopes[0], y)
        fresh = True  # slopes[0] is the derivative at the (sub)step's start
        for a in range(n_axles):
            if unilateral[a]:
                p = W[a] + dyn[a]
                now = p < 0.0 if not flying[a] else p <= 0.0
                if now != flying[a]:
                    fresh = False
                    log_event(events, event_count, (x[k] - x[0]) / speed, a, now, x[k] - off[a])
                flying[a] = now
                start_gap[a] = -p if now else p
            force[a] = 0.0 if flying[a] else W[a] + dyn[a]
        if record:
            for a in range(n_axles):
                contact[k, a] = force[a]
        h = 0.0 if last else (x[k + 1] - x[k]) / speed
        track_axles(summary, force, W, off, x[k], axle_span, step, h, unilateral, weight)
        if last:
            break
        # one integrator call site for the whole step: phase 0 steps to the end of the
        # step; if a tyre's force changed sign, phase 1 brackets the switch of ``axle``
        # (Illinois, each trial a step from th0) and phase 2 takes the step to it.
        # start_gap / end_gap: each tyre's force at the (sub)step's start and at the trial's
        # end, signed to be positive while it keeps its contact state
        th0 = 0.0
        target = 1.0
        phase = 0
        axle = -1
        lo = glo = hi = ghi = 0.0
        side = 0
        tries = 0
        switches = 0
        while True:
            rk4(y, trial, th0, target, k, fresh)
            fresh = True
            for a in range(n_axles):  # the one place the tyres' end-of-trial forces are read
                if unilateral[a]:
                    p = W[a] + dynamic(a, trial)  # the inputs are at the target already
                    end_gap[a] = -p if flying[a] else p
            action, phase, axle, tries, lo, glo, hi, ghi, side, target = locate_switch(
                phase, axle, tries, switches, lo, glo, hi, ghi, side, th0, target,
                start_gap, end_gap, unilateral, n_axles)  # fmt: skip
            if action == RETRY:
                continue
            done = action == ACCEPT_STEP
            peaks(y, trial, h * (target - th0))
            track_flight(summary, flying, axle_span, k, h * (target - th0))
            for i in range(m):
                y[i] = trial[i]
            if done:
                break
            fresh = False
            for a in range(n_axles):  # switch every axle whose contact state changes here
                start_gap[a] = end_gap[a]
                if unilateral[a] and end_gap[a] <= 0.0:
                    flying[a] = not flying[a]
                    start_gap[a] = -end_gap[a]
                    log_event(events, event_count, (x[k] - x[0]) / speed + target * h, a,
                              flying[a], x[k] + target * (x[k + 1] - x[k]) - off[a])  # fmt: skip
                    if axle_span[a, k] > 0:  # its force passes through zero here
                        summary[S_MIN_FORCE] = min(summary[S_MIN_FORCE], 0.0)
            switches += 1
            axle = -1
            th0 = target
            target = 1.0
            phase = 0
            if th0 >= 1.0:
                inputs(1.0, k)  # leave the shape values at the step's end
                break
        at_end = True  # the last inputs were at the step's end
        if record:
            for i in range(m):
                states[k + 1, i] = y[i]


@numba.njit(cache=True, parallel=True)
def batch_kernel(offsets, x, road, axle_span, road_offsets, params, n_spans, coupled, convective,
                 vec, vec_offsets, dims, summaries):  # fmt: skip
    """Many crossings in parallel; crossing ``i`` uses nodes ``offsets[i]:offsets[i+1]``.

    ``road`` and ``axle_span`` hold each crossing's ``(n_axles, n_nodes)`` arrays flattened
    at ``road_offsets``; ``vec`` the vehicle vectors at ``vec_offsets``; ``dims[i]`` the
    vehicle's ``(n, n_axles)``.
    """
    for i in numba.prange(offsets.shape[0] - 1):
        a = offsets[i]
        b = offsets[i + 1]
        n = dims[i, 0]
        n_axles = dims[i, 1]
        shape = (n_axles, b - a)
        kernel(x[a:b], road[road_offsets[i] : road_offsets[i + 1]].reshape(shape),
               axle_span[road_offsets[i] : road_offsets[i + 1]].reshape(shape), params[i],
               n_spans[i], coupled[i], convective[i], vec[vec_offsets[i] : vec_offsets[i + 1]],
               n, n_axles, np.empty((1, 2 * n + 2)), np.empty((1, n_axles)),
               summaries[i], np.empty((0, 4)), np.zeros(1, dtype=np.int64))  # fmt: skip
