r"""A many-mode reference model: the truck on the bridge's first N exact Euler-Bernoulli modes.

The study's model (:mod:`vbi_lib.models.one_coordinate`) bends the beam in one assumed
shape.  Here the beam deflects in its first ``N`` exact free-vibration modes
(:func:`vbi_lib.modes`), :math:`u_b(x, t) = \sum_n \phi_n(x)\, q_n(t)`, each with its own
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

Any vehicle
-----------
Every vehicle of :mod:`vbi_lib.vehicles` is integrated by the general kernel of
:mod:`~vbi_lib.models.modal_kernel` (the equations above are its one-axle case).  The
study's sprung mass (:class:`~vbi_lib.Vehicle`) keeps the compiled kernel below, single
crossings and batches (twice as fast with few modes); the general kernel reproduces it to
1e-14 (a vehicle's ``.system`` runs through the general kernel; the tests compare them).

Static deflection and DAF
-------------------------
The model's static deflection is the largest static midspan deflection under the vehicle's
static axle loads over all its positions, from the same N modes (the crawl run of a
finite-element study): the modal influence line of each midspan summed over the axles
(:func:`vbi_lib.modes.largest_static_deflection` for one axle).  The DAF of span ``j``
divides the largest downward midspan deflection while an axle is on span ``j`` by it.  On
other layouts than one span or two equal spans, the spans differ in stiffness and each
span's DAF divides by its own largest static midspan deflection (``Crossing.static_deflection``
is then the largest of them).  Moments, shears and displacements at any section, each with
its own static counterpart, come from :meth:`~vbi_lib.models.results.Crossing.sections`.

"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numba
import numpy as np

from ..bridges import Bridge
from ..modes import BeamModes, beam_modes, largest_static_deflection, shape_values
from ..vehicles import Vehicle, as_system
from . import modal_kernel
from .axles import event_log, largest_over_positions, logged_events, vehicle_vector
from .base import (
    DEFAULT_OMEGA_DT,
    P_DAMPING,
    P_GRAVITY,
    P_MASS,
    P_SPEED,
    P_START,
    P_STIFFNESS,
    PEAK_SLOTS,
    SUMMARY_SIZE,
    CrossingModel,
    Grid,
    downward_peak,
    history_peaks,
    parameters,
    start_summary,
    track_contact,
    track_peak,
)
from .batch import Batch
from .lanes_modal import run as run_lanes
from .results import Crossing


def default_time_step(bridge: Bridge, vehicle: object, modes: int) -> float:
    """Largest default step [s]: ``0.1 / omega`` of the vehicle and the first two modes.

    ``omega`` of the vehicle is its highest natural frequency on a rigid road (the axle hop
    of a tyred vehicle).  Higher modes respond almost statically to the truck and the
    average-acceleration rule keeps them stable at any step, so they do not set the step;
    the dt convergence study in the validation chapter shows the DAF settled at this step.

    Examples
    --------
    >>> from vbi_lib import Bridge, Vehicle
    >>> dt = default_time_step(Bridge(30.0, 1, 1e10, 5000.0), Vehicle(1e4, 4e6, 2e4), 5)
    >>> round(dt * 1e3, 3)   # ms; the vehicle at 3.18 Hz, mode 2 at 9.87 Hz
    1.612
    """
    basis = beam_modes(bridge, modes)
    highest = float(as_system(vehicle).circular_frequencies.max())
    omega = max(highest, float(basis.omega[: min(2, basis.count)].max()))
    return DEFAULT_OMEGA_DT / omega


@lru_cache(maxsize=256)
def _axle_group_static(bridge: Bridge, modes: int, offsets: tuple, loads: tuple) -> tuple:
    """Largest midspan deflection of each span under the axle loads at their worst position."""
    basis = beam_modes(bridge, modes)
    weights = basis.shape(np.array(bridge.midspans)) / basis.omega**2
    offsets_arr = np.array(offsets)
    loads_arr = np.array(loads)

    def deflection(front: np.ndarray, span: int) -> np.ndarray:
        xi = front[:, None] - offsets_arr[None, :]
        on = (xi >= 0.0) & (xi <= bridge.length)
        values = np.zeros(front.size)
        for a in range(offsets_arr.size):
            rows = np.flatnonzero(on[:, a])
            if rows.size:
                values[rows] += loads_arr[a] * (basis.shape(xi[rows, a]) @ weights[span])
        return values

    last = bridge.length + float(offsets_arr.max())
    return tuple(
        largest_over_positions(lambda f, j=j: deflection(f, j), 0.0, last)
        for j in range(bridge.n_spans)
    )


def span_static_deflections(bridge: Bridge, vehicle: object, modes: int) -> np.ndarray:
    """The N-mode beam's largest static midspan deflection of each span under the axle loads [m].

    One axle: :func:`~vbi_lib.modes.largest_static_deflection` times the weight; several:
    the modal influence lines of the midspans summed over the axles, at the group's worst
    position for each span.
    """
    s = as_system(vehicle)
    if s.n_axles == 1:
        return np.array(largest_static_deflection(bridge, modes)) * s.weight
    return np.array(_axle_group_static(bridge, modes, tuple(s.offsets), tuple(s.static_loads)))


def static_deflection(bridge: Bridge, vehicle: object, modes: int) -> float:
    """The largest of :func:`span_static_deflections` [m]: the crawl run's static deflection."""
    return float(span_static_deflections(bridge, vehicle, modes).max())


# ---------------------------------------------------------------------------- kernel
@numba.njit(cache=True)
def _kernel(
    x,
    elevation,
    span_of_step,
    params,
    supports,
    kappa,
    coef,
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

    ``span_of_step[k]``: 0 off the bridge, else the span (1, 2, ...) of step k; the modes
    are evaluated from ``supports``, ``kappa`` and ``coef`` (:func:`shape_values`).  History
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
            shape_values(xa - start, supports, kappa, coef, phi, dphi, ddphi)
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
            shape_values(xb - start, supports, kappa, coef, phi, dphi, ddphi)
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
        The :class:`~vbi_lib.modes.BeamModes` used.
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

    def modal_history(self) -> tuple[BeamModes, np.ndarray]:
        """The modes and their coordinates ``q_n(t)``, for the section responses."""
        return self.modes, self.modal_coordinates


def check_modes(modes: object) -> int:
    """A number of modes: a whole number >= 1."""
    if isinstance(modes, bool) or not isinstance(modes, int | np.integer) or modes < 1:
        raise ValueError(
            f"modes={modes!r} must be a whole number of modes >= 1 (model='modal' needs it)"
        )
    return int(modes)


class Modal(CrossingModel):
    """Any vehicle on the bridge's first N exact beam modes; Newmark average acceleration."""

    name = "modal"
    description = "N exact Euler-Bernoulli modes (any spans); Newmark average acceleration"
    result_type = ModalCrossing

    lane_kernel = staticmethod(run_lanes)

    def __init__(self, bridge, vehicle, speed, bridge_start, *, coupled, convective, modes):  # noqa: ANN001
        super().__init__(bridge, vehicle, speed, bridge_start, coupled=coupled,
                         convective=convective, modes=modes)  # fmt: skip
        self.count = check_modes(modes)
        self.basis = beam_modes(bridge, self.count)
        self.params = parameters(vehicle, speed, bridge_start, bridge.span)
        self.phi_mid = np.ascontiguousarray(self.basis.shape(np.array(bridge.midspans)))

    @classmethod
    def check_modes(cls, modes: object) -> int:
        return check_modes(modes)

    def default_time_step(self) -> tuple[float, str]:
        dt = default_time_step(self.bridge, self.vehicle, self.count)
        return dt, f"dt picked as {DEFAULT_OMEGA_DT} / omega = {dt * 1e3:.3f} ms"

    @classmethod
    def default_time_steps(cls, batch: Batch) -> np.ndarray:
        """:func:`default_time_step` once per distinct bridge, vehicle and number of modes."""
        first, inverse = batch.groups(batch.bridge, batch.vehicle, batch.modes)
        steps = [default_time_step(batch.bridges[batch.bridge[i]],
                                   batch.vehicles[batch.vehicle[i]], int(batch.modes[i]))
                 for i in first]  # fmt: skip
        return np.array(steps)[inverse]

    @classmethod
    def span_static_deflections_of(cls, batch: Batch) -> np.ndarray:
        """As the base's; one-axle vehicles scale the unit load's value per bridge and modes."""
        one_axle = np.array([as_system(v).n_axles == 1 for v in batch.vehicles])
        if not one_axle[batch.vehicle].all():
            return super().span_static_deflections_of(batch)
        first, inverse = batch.groups(batch.bridge, batch.modes)
        unit = np.full((first.size, max(PEAK_SLOTS, int(batch.n_spans().max()))), np.nan)
        for k, i in enumerate(first):
            bridge = batch.bridges[batch.bridge[i]]
            each = np.array(largest_static_deflection(bridge, int(batch.modes[i])))
            unit[k, : each.size] = np.full(each.size, each.max()) if bridge.study_layout else each
        weight = np.array([as_system(v).weight for v in batch.vehicles])[batch.vehicle]
        return unit[inverse] * weight[:, None]

    def static_deflection(self) -> float:
        return static_deflection(self.bridge, self.system, self.count)

    def _vector(self, grid: Grid) -> np.ndarray:
        return vehicle_vector(self.system, self.system.static_position(grid.road[:, 0]))

    def span_static_deflections(self) -> np.ndarray:
        each = span_static_deflections(self.bridge, self.system, self.count)
        if self.bridge.study_layout:  # the spans are alike: one value, as the study's model
            return np.full(each.size, each.max())
        return each

    def span_peaks(self, summary, fields, grid):  # noqa: ANN001, ANN201
        if self.bridge.n_spans <= PEAK_SLOTS:
            return super().span_peaks(summary, fields, grid)
        peaks = np.empty(self.bridge.n_spans)
        history_peaks(fields["midspan_displacement"], fields["modal_velocities"] @ self.phi_mid.T,
                      grid.x, self.speed, grid.span_of_step, peaks)  # fmt: skip
        return peaks

    def _zeta(self) -> np.ndarray:
        return np.full(self.count, self.bridge.damping_ratio)

    def integrate(self, grid: Grid):  # noqa: ANN201
        if isinstance(self.vehicle, Vehicle):
            return self._integrate_sprung_mass(grid)
        n = grid.x.size
        s = self.system
        q = np.empty((n, self.count))
        qd = np.empty((n, self.count))
        veh = np.empty((n, 2 * s.n_dofs))
        contact = np.empty((n, s.n_axles))
        summary = np.empty(SUMMARY_SIZE)
        events = event_log(n)
        b = self.basis
        # writable copies: the batch passes writable arrays, and numba compiles one kernel
        modal_kernel.kernel(grid.x, grid.road, grid.axle_span, self.params,
                            np.array(b.supports), np.array(b.wavenumber),
                            np.array(b.coefficients), np.array(b.omega),
                            self._zeta(), self.phi_mid, self.coupled, self.convective,
                            self._vector(grid), s.n_dofs, s.n_axles, q, qd, veh, contact,
                            summary, *events)  # fmt: skip
        fields = {
            "modes": b,
            "dof_displacement": veh[:, : s.n_dofs],
            "dof_velocity": veh[:, s.n_dofs :],
            "modal_coordinates": q,
            "modal_velocities": qd,
            "contact_events": logged_events(*events),
            "midspan_displacement": q @ self.phi_mid.T,
        }
        note = f"{n - 1} average-acceleration steps, largest {grid.dt_max * 1e3:.3f} ms"
        return summary, contact, fields, note

    def _integrate_sprung_mass(self, grid: Grid):  # noqa: ANN202
        """The study's sprung mass on its own compiled kernel."""
        n = grid.x.size
        q = np.empty((n, self.count))
        qd = np.empty((n, self.count))
        veh = np.empty((n, 2))
        contact = np.empty(n)
        summary = np.empty(SUMMARY_SIZE)
        b = self.basis
        _kernel(grid.x, grid.elevation, grid.span_of_step, self.params, b.supports, b.wavenumber,
                b.coefficients, b.omega, self._zeta(), self.phi_mid, self.coupled,
                self.convective, q, qd, veh, contact, summary)  # fmt: skip
        fields = {
            "modes": b,
            "dof_displacement": veh[:, 0:1],
            "dof_velocity": veh[:, 1:2],
            "modal_coordinates": q,
            "modal_velocities": qd,
            "midspan_displacement": q @ self.phi_mid.T,
        }
        note = f"{n - 1} average-acceleration steps, largest {grid.dt_max * 1e3:.3f} ms"
        return summary, contact[:, None], fields, note

    @classmethod
    def integrate_setups(cls, models, grids):  # noqa: ANN001, ANN206
        """Any vehicles: the general kernel, one crossing per parallel task."""
        n = len(models)
        counts = [m.count for m in models]

        def offsets_of(sizes: list[int]) -> np.ndarray:
            return np.concatenate(([0], np.cumsum(sizes))).astype(np.int64)

        most = max(m.bridge.n_spans for m in models)
        phi_mid = np.full((n, max(2, most), max(counts)), np.nan)
        supports = np.full((n, most + 1), np.nan)
        coef = np.zeros((sum(counts), most, 4))
        first = 0
        for i, m in enumerate(models):
            phi_mid[i, : m.bridge.n_spans, : m.count] = m.phi_mid
            supports[i, : m.bridge.n_spans + 1] = m.basis.supports
            coef[first : first + m.count, : m.bridge.n_spans] = m.basis.coefficients
            first += m.count
        vectors = [m._vector(g) for m, g in zip(models, grids, strict=True)]
        summaries = np.full((n, SUMMARY_SIZE), np.nan)
        modal_kernel.batch_kernel(
            offsets_of([g.x.size for g in grids]),
            np.concatenate([g.x for g in grids]),
            np.concatenate([g.road.ravel() for g in grids]),
            np.concatenate([g.axle_span.ravel() for g in grids]),
            offsets_of([g.road.size for g in grids]),
            np.array([m.params for m in models]),
            offsets_of(counts),
            supports,
            np.concatenate([m.basis.wavenumber for m in models]),
            coef,
            np.concatenate([m.basis.omega for m in models]),
            np.concatenate([m._zeta() for m in models]),
            phi_mid,
            np.array([m.bridge.n_spans for m in models], dtype=np.int64),
            np.array([m.coupled for m in models], dtype=np.bool_),
            np.array([m.convective for m in models], dtype=np.bool_),
            np.concatenate(vectors),
            offsets_of([v.size for v in vectors]),
            np.array([[m.system.n_dofs, m.system.n_axles] for m in models], dtype=np.int64),
            summaries,
        )
        return summaries
