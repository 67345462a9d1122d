r"""The many-mode model's kernel for any vehicle (Newmark average acceleration, located switches).

The beam deflects in ``N`` exact modes, :math:`u_b = \sum_n \phi_n q_n`
(:mod:`~vbi_lib.models.modal`); the vehicle is a :class:`~vbi_lib.vehicles.VehicleSystem`.
With the dynamic contact forces :math:`F_a = P_a - W_a` (:math:`F_a = -W_a` for a tyre in
flight, whose force is zero):

.. math::
    M \ddot u + C \dot u + K u = E^T F, \qquad
    \ddot q_n + 2 \zeta_b \omega_n \dot q_n + \omega_n^2 q_n
        = -\textstyle\sum_a \phi_n(x_a) (W_a + F_a).

The average-acceleration rule writes every end-of-step acceleration as a predictor plus
:math:`\beta = h^2/4` (displacement) or :math:`\gamma = h/2` (velocity) times itself; the
vehicle's accelerations then follow from :math:`F` through
:math:`S = M + \gamma C + \beta K`, the modes' from :math:`F` mode by mode, and the contact
laws close the step as one small dense system in the axle forces (size ``n_axles``; a tyre
in flight contributes the row :math:`F_a = -W_a`).  For one axle and one degree of freedom
this is the scalar equation of the study's sprung mass.  The accelerations at the start of
each step are recomputed from the equations of motion (right limits at the road's slope
jumps), and a tyre's take-off or landing inside a step is located and the step split there
(:mod:`~vbi_lib.models.axles`).
"""

from __future__ import annotations

import numba
import numpy as np

from ..modes import shape_values
from .axles import (
    ACCEPT_STEP,
    RETRY,
    locate_switch,
    log_event,
    solve_in_place,
    track_axles,
    track_flight,
    unpack,
)
from .base import P_SPEED, P_START, S_MIN_FORCE, start_summary


@numba.njit(cache=True)
def kernel(x, road, axle_span, params, supports, kappa, coef, omega, zeta, phi_mid, coupled,
           convective, vec, n, n_axles, q_hist, qd_hist, vehicle_hist, contact, summary,
           events, event_count):  # fmt: skip
    """Newmark average acceleration on any vehicle and N modes over the nodes ``x``.

    History arrays (``q_hist``, ``qd_hist`` n_nodes x N; ``vehicle_hist`` n_nodes x 2n, the
    vehicle's displacements then velocities; ``contact`` n_nodes x n_axles) are filled when
    they have one row per node; ``summary`` gets the peaks and the contact checks;
    ``events`` and ``event_count`` the tyres' switches (as the one-coordinate kernel's).
    """
    M, Minv, K, C, E, W, kt, ct, off, unilateral, u0 = unpack(vec, n, n_axles)
    weight = W.sum()
    n_nodes = x.shape[0]
    n_modes = omega.shape[0]
    n_spans = phi_mid.shape[0]
    record = q_hist.shape[0] == n_nodes
    speed = params[P_SPEED]
    start = params[P_START]
    eps = 1.0 if convective else 0.0
    cpl = 1.0 if coupled else 0.0
    two_zw = 2.0 * zeta * omega
    w2 = omega * omega
    # state at the start of the current (sub)step, and a trial end state
    u = u0.copy()
    v = np.zeros(n)
    q = np.zeros(n_modes)
    qd = np.zeros(n_modes)
    u1 = np.empty(n)
    v1 = np.empty(n)
    q1 = np.empty(n_modes)
    qd1 = np.empty(n_modes)
    flying = np.zeros(n_axles, dtype=np.bool_)
    # shapes and road under the axles at the (sub)step's start, end and a probe point
    phi0 = np.zeros((n_axles, n_modes))
    dphi0 = np.zeros((n_axles, n_modes))
    phit = np.zeros((n_axles, n_modes))
    dphit = np.zeros((n_axles, n_modes))
    ddphi = np.empty(n_modes)
    level0 = np.empty(n_axles)
    levelt = np.empty(n_axles)
    rate = np.empty(n_axles)
    # workspace of a step
    force = np.empty(n_axles)
    pressing = np.empty(n_axles)
    av = np.empty(n)
    aq = np.empty(n_modes)
    ut = np.empty(n)
    vt = np.empty(n)
    qt = np.empty(n_modes)
    qdt = np.empty(n_modes)
    S = np.empty((n, n))
    G = np.empty((n, n_axles + 1))
    dd = np.empty(n_modes)
    rt = np.empty(n_modes)
    gmat = np.empty((n_axles, n_modes))
    system = np.empty((n_axles, n_axles))
    rhs = np.empty((n_axles, 1))
    start_gap = np.zeros(n_axles)
    end_gap = np.zeros(n_axles)

    def point(theta, k):
        if theta == 0.0:
            return x[k]
        if theta == 1.0:
            return x[k + 1]
        return x[k] + theta * (x[k + 1] - x[k])

    def shapes(theta, k, phi, dphi):
        """Mode shapes and slopes under each axle at fraction ``theta`` of step ``k``."""
        xf = point(theta, k)
        for a in range(n_axles):
            if axle_span[a, k] > 0:
                shape_values(xf - off[a] - start, supports, kappa, coef, phi[a], dphi[a], ddphi)
            else:
                for j in range(n_modes):
                    phi[a, j] = 0.0
                    dphi[a, j] = 0.0

    def levels(theta, k, level):
        for a in range(n_axles):
            ra = road[a, k]
            rb = road[a, k + 1]
            level[a] = ra if theta == 0.0 else (rb if theta == 1.0 else ra + theta * (rb - ra))

    def dynamic(a, phi, dphi, level, uu, vv, qq, qqd):
        """``P_a - W_a`` of axle ``a`` as if it touched."""
        ub = 0.0
        ubd = 0.0
        for j in range(n_modes):
            ub += phi[a, j] * qq[j]
            ubd += phi[a, j] * qqd[j] + eps * speed * dphi[a, j] * qq[j]
        eu = 0.0
        ev = 0.0
        for i in range(n):
            eu += E[a, i] * uu[i]
            ev += E[a, i] * vv[i]
        return kt[a] * (cpl * ub + level[a] - eu) + ct[a] * (cpl * ubd + rate[a] - ev)

    def start_accelerations():
        """Accelerations at the (sub)step's start from the equations of motion (``phi0``)."""
        for a in range(n_axles):
            force[a] = -W[a] if flying[a] else dynamic(a, phi0, dphi0, level0, u, v, q, qd)
        for i in range(n):
            s = 0.0
            for a in range(n_axles):
                s += E[a, i] * force[a]
            for j in range(n):
                s -= C[i, j] * v[j] + K[i, j] * u[j]
            ut[i] = s
        for i in range(n):
            s = 0.0
            for j in range(n):
                s += Minv[i, j] * ut[j]
            av[i] = s
        for j in range(n_modes):
            s = -two_zw[j] * qd[j] - w2[j] * q[j]
            for a in range(n_axles):
                s -= phi0[a, j] * (W[a] + force[a])
            aq[j] = s

    def newmark(th0, th1, k, phi, dphi, level):
        """Average-acceleration step from the state at ``th0`` to ``th1``.

        The start accelerations are ``av, aq`` (:func:`start_accelerations`); ``phi, dphi,
        level`` are at ``th1``; the end state goes to ``u1, v1, q1, qd1`` and the axles'
        dynamic forces to ``force``.
        """
        h = (x[k + 1] - x[k]) / speed * (th1 - th0)
        beta = 0.25 * h * h
        gamma = 0.5 * h
        # predictors
        for i in range(n):
            ut[i] = u[i] + h * v[i] + beta * av[i]
            vt[i] = v[i] + gamma * av[i]
        for j in range(n_modes):
            qt[j] = q[j] + h * qd[j] + beta * aq[j]
            qdt[j] = qd[j] + gamma * aq[j]
        # vehicle: a = S^-1 (E^T F - C vt - K ut) = G[:, :-1] F + G[:, -1]
        for i in range(n):
            s = 0.0
            for j in range(n):
                S[i, j] = M[i, j] + gamma * C[i, j] + beta * K[i, j]
                s -= C[i, j] * vt[j] + K[i, j] * ut[j]
            for a in range(n_axles):
                G[i, a] = E[a, i]
            G[i, n_axles] = s
        solve_in_place(S, G, n, n_axles + 1)
        # modes: aq = (rt - sum_b phi_b F_b) / dd
        for j in range(n_modes):
            dd[j] = 1.0 + two_zw[j] * gamma + w2[j] * beta
            s = -two_zw[j] * qdt[j] - w2[j] * qt[j]
            for b in range(n_axles):
                s -= phi[b, j] * W[b]
            rt[j] = s
        # contact laws at the end: one equation per axle in the forces F
        for a in range(n_axles):
            for b in range(n_axles):
                system[a, b] = 0.0
            system[a, a] = 1.0
            if flying[a]:
                rhs[a, 0] = -W[a]
                continue
            s_a = kt[a] * beta + ct[a] * gamma
            value = dynamic(a, phi, dphi, level, ut, vt, qt, qdt)
            for j in range(n_modes):
                g = cpl * (s_a * phi[a, j] + ct[a] * eps * speed * beta * dphi[a, j])
                gmat[a, j] = g
                value += g * rt[j] / dd[j]
                for b in range(n_axles):
                    system[a, b] += g * phi[b, j] / dd[j]
            for i in range(n):
                value -= s_a * E[a, i] * G[i, n_axles]
                for b in range(n_axles):
                    system[a, b] += s_a * E[a, i] * G[i, b]
            rhs[a, 0] = value
        solve_in_place(system, rhs, n_axles, 1)
        for a in range(n_axles):
            force[a] = rhs[a, 0]
        for i in range(n):
            s = G[i, n_axles]
            for a in range(n_axles):
                s += G[i, a] * force[a]
            u1[i] = ut[i] + beta * s
            v1[i] = vt[i] + gamma * s
        for j in range(n_modes):
            s = rt[j]
            for b in range(n_axles):
                s -= phi[b, j] * force[b]
            s /= dd[j]
            q1[j] = qt[j] + beta * s
            qd1[j] = qdt[j] + gamma * s

    def accept(h, k):
        """The trial state becomes the state (the span peaks come from the histories: the
        mode-acceleration displacement needs the contact forces, ``modal.Modal``)."""
        track_flight(summary, flying, axle_span, k, h)
        for i in range(n):
            u[i] = u1[i]
            v[i] = v1[i]
        for j in range(n_modes):
            q[j] = q1[j]
            qd[j] = qd1[j]

    def record_state(k):
        for i in range(n):
            vehicle_hist[k, i] = u[i]
            vehicle_hist[k, n + i] = v[i]
        for j in range(n_modes):
            q_hist[k, j] = q[j]
            qd_hist[k, j] = qd[j]

    start_summary(summary, n_spans)
    if record:
        record_state(0)
    at_end = False  # phit holds the shapes at the end of the previous step
    for k in range(n_nodes):
        last = k == n_nodes - 1
        step = k - 1 if last else k
        # the contact state at the node, with this step's road rate (right limit)
        for a in range(n_axles):
            rate[a] = (road[a, step + 1] - road[a, step]) / (x[step + 1] - x[step]) * speed
        theta = 1.0 if last else 0.0
        known = at_end
        if known and not last:
            for a in range(n_axles):
                known = known and axle_span[a, k] == axle_span[a, k - 1]
        if known:
            phi0[:, :] = phit
            dphi0[:, :] = dphit
        else:
            shapes(theta, step, phi0, dphi0)
        levels(theta, step, level0)
        for a in range(n_axles):
            p = W[a] + dynamic(a, phi0, dphi0, level0, u, v, q, qd)
            if unilateral[a]:
                now = p < 0.0 if not flying[a] else p <= 0.0
                if now != flying[a]:
                    log_event(events, event_count, (x[k] - x[0]) / speed, a, now, x[k] - off[a])
                flying[a] = now
                start_gap[a] = -p if now else p
            pressing[a] = 0.0 if flying[a] else p
        if record:
            for a in range(n_axles):
                contact[k, a] = pressing[a]
        h = 0.0 if last else (x[k + 1] - x[k]) / speed
        track_axles(summary, pressing, W, off, x[k], axle_span, step, h, unilateral, weight)
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
        fresh = False  # av, aq hold the accelerations at the (sub)step's start
        while True:
            shapes(target, k, phit, dphit)
            levels(target, k, levelt)
            if not fresh:
                start_accelerations()
                fresh = True
            newmark(th0, target, k, phit, dphit, levelt)
            for a in range(n_axles):  # the one place the tyres' end-of-trial forces are read
                if unilateral[a]:
                    p = W[a] + dynamic(a, phit, dphit, levelt, u1, v1, q1, qd1)
                    end_gap[a] = -p if flying[a] else p
            action, phase, axle, tries, lo, glo, hi, ghi, side, target = locate_switch(
                phase, axle, tries, switches, lo, glo, hi, ghi, side, th0, target,
                start_gap, end_gap, unilateral, n_axles)  # fmt: skip
            if action == RETRY:
                continue
            done = action == ACCEPT_STEP
            accept(h * (target - th0), k)
            if done:
                break
            fresh = False
            phi0[:, :] = phit  # the switch is the next sub-step's start
            dphi0[:, :] = dphit
            level0[:] = levelt
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
                break
        at_end = True
        if record:
            record_state(k + 1)
