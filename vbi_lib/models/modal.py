r"""A many-mode reference model: the truck on the bridge's first N exact Euler-Bernoulli modes.

The study's model (:mod:`vbi_lib.models.one_coordinate`) bends the beam in one assumed
shape.  Here the beam deflects in its first ``N`` exact free-vibration modes
(:func:`vbi_lib.beam_modes`), :math:`u_b(x, t) = \sum_n \phi_n(x)\, q_n(t)`, each with its own
frequency :math:`\omega_n` and the bridge's damping ratio :math:`\zeta_b` (modal damping, as in
a modal finite-element analysis).  The sprung mass couples to the modes exactly as to the one
coordinate of the study's model (:math:`\psi z_b` becomes :math:`\sum \phi_n q_n`):

.. math::
    F &= k_v (r - u_v) + c_v (\dot r - \dot u_v), \qquad
        r = \textstyle\sum_n \phi_n(x_v) q_n + \Delta(x_v) \\
    m_v \ddot u_v &= F, \qquad
    \ddot q_n + 2 \zeta_b \omega_n \dot q_n + \omega_n^2 q_n = -\phi_n(x_v)\,(m_v g + F).

With one mode this is the study's two-degree-of-freedom model (the first mode of either beam
is its shape function, and its generalised mass is the study's :math:`m^*`).

Integration
-----------
High modes are stiff (mode 5 of a 10 Hz simple span vibrates at 250 Hz), so an explicit
scheme would need a step set by the highest mode.  The modes and the vehicle are instead
integrated together with the Newmark average-acceleration (trapezoidal) rule, which is
unconditionally stable and second-order accurate; the implicit equations of a step reduce,
because the coupling has rank one, to a single scalar equation for the suspension force, so
a step costs O(N).  The accelerations at the start of each step are recomputed from the
equations of motion (the mass matrix is diagonal), so the jumps of the road's slope at
profile samples and of the coupling where the wheel leaves the bridge are honoured exactly.
Every profile sample is a node; the default step also resolves the vehicle and the lowest
bridge modes (:func:`default_time_step`).

Static deflection and DAF
-------------------------
The model's static deflection is the largest static midspan deflection under the weight over
all load positions, from the same N modes (the crawl run of a finite-element study;
:func:`vbi_lib.beam_modes.largest_static_deflection`), and the DAF of span ``j`` divides the
largest downward midspan deflection while the wheel is on span ``j`` by it.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numba
import numpy as np

from ..beam_modes import BeamModes, beam_modes, largest_static_deflection, shape_values
from ..bridges import Bridge
from ..vehicles import Vehicle
from .base import (
    DEFAULT_OMEGA_DT,
    P_DAMPING,
    P_GRAVITY,
    P_MASS,
    P_SPAN,
    P_SPEED,
    P_START,
    P_STIFFNESS,
    SUMMARY_SIZE,
    Batch,
    CrossingModel,
    Grid,
    downward_peak,
    parameters,
    start_summary,
    track_contact,
    track_peak,
)
from .lanes_modal import run as run_lanes
from .results import Crossing


def default_time_step(bridge: Bridge, vehicle: Vehicle, modes: int) -> float:
    """Largest default step [s]: ``0.1 / omega`` of the vehicle and the first two modes.

    Higher modes respond almost statically to the truck and the average-acceleration rule
    keeps them stable at any step, so they do not set the step; the dt convergence study in
    the validation chapter shows the DAF settled at this step.

    Examples
    --------
    >>> from vbi_lib import Bridge, Vehicle
    >>> dt = default_time_step(Bridge(30.0, 1, 1e10, 5000.0), Vehicle(1e4, 4e6, 2e4), 5)
    >>> round(dt * 1e3, 3)   # ms; the vehicle at 3.18 Hz, mode 2 at 9.87 Hz
    1.612
    """
    basis = beam_modes(bridge, modes)
    omega = max(vehicle.circular_frequency, float(basis.omega[: min(2, basis.count)].max()))
    return DEFAULT_OMEGA_DT / omega


# ---------------------------------------------------------------------------- kernel
@numba.njit(cache=True)
def _kernel(
    x,
    elevation,
    span_of_step,
    params,
    kind,
    kappa,
    amp,
    omega,
    zeta,
    phi_mid,
    coupled,
    convective,
    q_hist,
    qd_hist,
    vehicle_hist,
    contact,
    summary,
):
    """Newmark average acceleration on the vehicle and N modes over the nodes ``x``.

    ``span_of_step[k]``: 0 off the bridge, else the span (1 or 2) of step k.  History
    arrays are filled when they have one row per node; ``summary`` gets the peaks and the
    contact checks (layout of :mod:`vbi_lib.models.base`).
    """
    n_nodes = x.shape[0]
    n_modes = omega.shape[0]
    n_spans = phi_mid.shape[0]
    record = q_hist.shape[0] == n_nodes
    m_v = params[P_MASS]
    k_v = params[P_STIFFNESS]
    c_v = params[P_DAMPING]
    weight = m_v * params[P_GRAVITY]
    speed = params[P_SPEED]
    start = params[P_START]
    span = params[P_SPAN]
    eps = 1.0 if convective else 0.0
    cpl = 1.0 if coupled else 0.0

    y = np.zeros(n_modes)
    v = np.zeros(n_modes)
    a = np.zeros(n_modes)
    yt = np.empty(n_modes)
    vt = np.empty(n_modes)
    r = np.empty(n_modes)
    gvec = np.empty(n_modes)
    dd = np.empty(n_modes)
    phi = np.zeros(n_modes)
    dphi = np.zeros(n_modes)
    ddphi = np.empty(n_modes)
    two_zw = 2.0 * zeta * omega
    w2 = omega * omega
    uv = elevation[0]  # at rest in static equilibrium on the profile
    vv = 0.0
    mid0 = np.zeros(n_spans)
    midv0 = np.zeros(n_spans)
    start_summary(summary, n_spans)
    if record:
        vehicle_hist[0, 0] = uv
        vehicle_hist[0, 1] = vv
        for n in range(n_modes):
            q_hist[0, n] = 0.0
            qd_hist[0, n] = 0.0
    force_b = 0.0
    for k in range(n_nodes - 1):
        xa = x[k]
        xb = x[k + 1]
        h = (xb - xa) / speed
        rate = (elevation[k + 1] - elevation[k]) / (xb - xa) * speed
        span_k = span_of_step[k]
        on = span_k > 0
        beta = 0.25 * h * h
        gamma = 0.5 * h
        # ---- accelerations at the start of the step (right limit), from the equations
        if on:
            shape_values(xa - start, kind, kappa, amp, span, phi, dphi, ddphi)
        else:
            for n in range(n_modes):
                phi[n] = 0.0
                dphi[n] = 0.0
        ub = 0.0
        ubd = 0.0
        for n in range(n_modes):
            ub += phi[n] * y[n]
            ubd += phi[n] * v[n] + eps * speed * dphi[n] * y[n]
        force = k_v * (cpl * ub + elevation[k] - uv) + c_v * (cpl * ubd + rate - vv)
        av = force / m_v
        for n in range(n_modes):
            a[n] = -two_zw[n] * v[n] - w2[n] * y[n] - phi[n] * (weight + force)
        if record:
            contact[k] = weight + force
        if on:
            track_contact(summary, weight + force, xa, h)
        # midspan displacement and rate at the start
        for j in range(n_spans):
            s0 = 0.0
            s1 = 0.0
            for n in range(n_modes):
                s0 += phi_mid[j, n] * y[n]
                s1 += phi_mid[j, n] * v[n]
            mid0[j] = s0
            midv0[j] = s1
        # ---- predictors
        for n in range(n_modes):
            yt[n] = y[n] + h * v[n] + beta * a[n]
            vt[n] = v[n] + gamma * a[n]
        uvt = uv + h * vv + beta * av
        vvt = vv + gamma * av
        # ---- the implicit equations at the end of the step reduce to one for F
        if on:
            shape_values(xb - start, kind, kappa, amp, span, phi, dphi, ddphi)
        s_v = k_v * beta + c_v * gamma
        ub = 0.0
        ubd = 0.0
        for n in range(n_modes):
            ub += phi[n] * yt[n]
            ubd += phi[n] * vt[n] + eps * speed * dphi[n] * yt[n]
        f_tilde = k_v * (cpl * ub + elevation[k + 1] - uvt) + c_v * (cpl * ubd + rate - vvt)
        denominator = 1.0 + s_v / m_v
        numerator = f_tilde
        for n in range(n_modes):
            dd[n] = 1.0 + two_zw[n] * gamma + w2[n] * beta
            r[n] = -two_zw[n] * vt[n] - w2[n] * yt[n] - phi[n] * weight
            gvec[n] = cpl * (s_v * phi[n] + c_v * eps * speed * beta * dphi[n])
            denominator += gvec[n] * phi[n] / dd[n]
            numerator += gvec[n] * r[n] / dd[n]
        force_b = numerator / denominator
        avb = force_b / m_v
        for n in range(n_modes):
            a[n] = (r[n] - phi[n] * force_b) / dd[n]
            y[n] = yt[n] + beta * a[n]
            v[n] = vt[n] + gamma * a[n]
        uv = uvt + beta * avb
        vv = vvt + gamma * avb
        if record:
            vehicle_hist[k + 1, 0] = uv
            vehicle_hist[k + 1, 1] = vv
            for n in range(n_modes):
                q_hist[k + 1, n] = y[n]
                qd_hist[k + 1, n] = v[n]
        if on:
            j = span_k - 1
            s0 = 0.0
            s1 = 0.0
            for n in range(n_modes):
                s0 += phi_mid[j, n] * y[n]
                s1 += phi_mid[j, n] * v[n]
            track_peak(summary, span_k, downward_peak(mid0[j], s0, midv0[j], s1, h))
    if record:
        contact[n_nodes - 1] = weight + force_b
    if span_of_step[n_nodes - 2] > 0:
        track_contact(summary, weight + force_b, x[n_nodes - 1], 0.0)


# ---------------------------------------------------------------------------- model
@dataclass(frozen=True, eq=False, kw_only=True, repr=False)
class ModalCrossing(Crossing):
    """A crossing of the many-mode model; adds the modes and their coordinates.

    Attributes
    ----------
    modes
        The :class:`~vbi_lib.beam_modes.BeamModes` used.
    modal_coordinates, modal_velocities
        ``q_n`` and ``dq_n/dt``, shape ``(n_time, N)`` [kg^1/2 m, kg^1/2 m/s].
    """

    modes: BeamModes
    modal_coordinates: np.ndarray
    modal_velocities: np.ndarray

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Natural frequencies of the N modes [Hz]."""
        return self.modes.frequencies_hz

    def displacement_at(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """Deflection history ``sum_n phi_n(x) q_n(t)`` [m] at stations from the bridge start.

        Returns shape ``(n_time,)`` for one station, ``(n_time, n_x)`` for several.
        """
        values = self.modal_coordinates @ self.modes.shape(x_from_bridge_start).T
        return values[:, 0] if np.ndim(x_from_bridge_start) == 0 else values

    def moment_at(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """Bending moment ``EI sum_n phi_n''(x) q_n(t)`` [N m], sagging positive.

        From the curvature of the modes; it converges more slowly in N than the deflection
        (mode n contributes in proportion to ``1/n^2`` rather than ``1/n^4``).
        Returns shape ``(n_time,)`` for one station, ``(n_time, n_x)`` for several.
        """
        values = self.bridge.EI * (
            self.modal_coordinates @ self.modes.curvature(x_from_bridge_start).T
        )
        return values[:, 0] if np.ndim(x_from_bridge_start) == 0 else values


def check_modes(modes: object) -> int:
    """A number of modes: a whole number >= 1."""
    if isinstance(modes, bool) or not isinstance(modes, int | np.integer) or modes < 1:
        raise ValueError(
            f"modes={modes!r} must be a whole number of modes >= 1 (model='modal' needs it)"
        )
    return int(modes)


class Modal(CrossingModel):
    """The sprung mass on the bridge's first N exact beam modes; Newmark average acceleration."""

    name = "modal"
    description = "N exact Euler-Bernoulli modes (1 or 2 spans); Newmark average acceleration"
    result_type = ModalCrossing

    def __init__(self, bridge, vehicle, speed, bridge_start, *, coupled, convective, modes):  # noqa: ANN001
        super().__init__(bridge, vehicle, speed, bridge_start, coupled=coupled,
                         convective=convective, modes=modes)  # fmt: skip
        self.count = check_modes(modes)
        self.basis = beam_modes(bridge, self.count)
        self.params = parameters(vehicle, speed, bridge_start, bridge.span)
        self.phi_mid = midspan_shapes(bridge, self.count)

    @classmethod
    def check_modes(cls, modes: object) -> int:
        return check_modes(modes)

    def default_time_step(self) -> tuple[float, str]:
        dt = default_time_step(self.bridge, self.vehicle, self.count)
        return dt, f"dt picked as {DEFAULT_OMEGA_DT} / omega = {dt * 1e3:.3f} ms"

    def static_deflection(self) -> float:
        return max(largest_static_deflection(self.bridge, self.count)) * self.vehicle.weight

    @classmethod
    def default_time_steps(cls, batch: Batch) -> np.ndarray:
        return _per_design(batch, lambda b, v, m: default_time_step(b, v, m))

    @classmethod
    def static_deflections(cls, batch: Batch) -> np.ndarray:
        unit = _per_design(batch, lambda b, v, m: max(largest_static_deflection(b, m)))
        return unit * np.array([x.weight for x in batch.vehicles])[batch.vehicle]

    def _zeta(self) -> np.ndarray:
        return np.full(self.count, self.bridge.damping_ratio)

    def integrate(self, grid: Grid):  # noqa: ANN201
        n = grid.x.size
        q = np.empty((n, self.count))
        qd = np.empty((n, self.count))
        veh = np.empty((n, 2))
        contact = np.empty(n)
        summary = np.empty(SUMMARY_SIZE)
        b = self.basis
        _kernel(grid.x, grid.elevation, grid.span_of_step, self.params, b.kind, b.wavenumber,
                b.amplitude, b.omega, self._zeta(), self.phi_mid, self.coupled, self.convective,
                q, qd, veh, contact, summary)  # fmt: skip
        fields = {
            "modes": b,
            "vehicle_displacement": veh[:, 0],
            "vehicle_velocity": veh[:, 1],
            "modal_coordinates": q,
            "modal_velocities": qd,
            "midspan_displacement": q @ self.phi_mid.T,
        }
        note = f"{n - 1} average-acceleration steps, largest {grid.dt_max * 1e3:.3f} ms"
        return summary, contact, fields, note

    @classmethod
    def integrate_many(cls, batch: Batch, dt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Summaries and largest steps of a batch: the lane kernel for the study's vehicles."""
        if batch.plain_vehicles():
            return run_lanes(batch, dt)
        return super().integrate_many(batch, dt)


def _per_design(batch: Batch, function) -> np.ndarray:  # noqa: ANN001
    """``function(bridge, vehicle, modes)`` once per distinct triple, spread to the crossings."""
    first, inverse = batch.groups(batch.bridge, batch.vehicle, batch.modes)
    values = np.array([function(batch.bridges[batch.bridge[i]], batch.vehicles[batch.vehicle[i]],
                                int(batch.modes[i])) for i in first])  # fmt: skip
    return values[inverse]


@lru_cache(maxsize=512)
def midspan_shapes(bridge: Bridge, count: int) -> np.ndarray:
    """``phi_n`` at each midspan, ``(n_spans, count)`` (read-only, shared)."""
    values = np.ascontiguousarray(beam_modes(bridge, count).shape(np.array(bridge.midspans)))
    values.setflags(write=False)
    return values
