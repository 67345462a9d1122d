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

DAF: mode acceleration, over the exact beam's statics
-----------------------------------------------------
The N-mode series converges slowly where a span's own modes are high (a short span beside a
long one), so the displacement every span DAF reads is the mode-acceleration one (e.g.
Craig & Kurdila; Chopra): the series plus the static part it leaves out,

.. math:: u_j(t) = \sum_n \phi_n(m_j) q_n + \sum_a F_{c,a} \Big[\sum_n
    \frac{\phi_n(m_j)\phi_n(x_a)}{\omega_n^2} - \eta_j(x_a)\Big],

``F_{c,a}`` the force axle ``a`` presses on the bridge and :math:`\eta_j` the exact influence
line of midspan ``j`` (three-moment equation, in cubic pieces:
:func:`~vbi_lib.models.statics.influence_pieces`).  At a crawl it is the exact static
deflection whatever ``N``.  The DAF of span ``j`` divides its largest downward value over
the whole run by the exact beam's largest static deflection of the same midspan under the
vehicle's axle loads, every axle in every position (:mod:`~vbi_lib.models.statics`); inside
a step the series' rate is exact and the correction's is its secant.  The series DAF (over
its own N-mode statics) is checked too: when it differs by more than 1 %, or ``modes``
leaves out a span's own fundamental, the crossing says so in ``notes`` and a
:class:`~vbi_lib.validity.TruncationWarning`.  ``modes=None`` takes every mode up to 2.3
times the highest simply supported frequency of any one span (:func:`default_modes`).
Moments, shears and displacements at any section, each with its own static counterpart,
come from :meth:`~vbi_lib.models.results.Crossing.sections`.

"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache

import numba
import numpy as np

from ..bridges import Bridge
from ..continuous_beams import count_below
from ..modes import BeamModes, beam_modes, shape_values
from ..vehicles import Vehicle, as_system
from . import modal_kernel
from .axles import event_log, logged_events, vehicle_vector
from .base import (
    DEFAULT_OMEGA_DT,
    P_DAMPING,
    P_GRAVITY,
    P_MASS,
    P_SPEED,
    P_START,
    P_STIFFNESS,
    PEAK_SLOTS,
    S_PEAK,
    SUMMARY_SIZE,
    CrossingModel,
    Grid,
    parameters,
    peaks_of,
    start_summary,
    track_contact,
)
from .batch import Batch
from .lanes_modal import run as run_lanes
from .results import Crossing
from .statics import influence_pieces, span_statics


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
    if record:
        contact[n_nodes - 1] = weight + force_b
    if span_of_step[n_nodes - 2] > 0:
        track_contact(summary, weight + force_b, x[n_nodes - 1], 0.0)


@numba.njit(cache=True)
def _correction_values(s, force, supports, kappa, coef, g, breaks, cubics, out):
    """``out[i, j] = force[i] (sum_n g[j, n] phi_n(s[i]) - eta_j(s[i]))`` at stations ``s``
    from the bridge start: the mode-acceleration correction, the exact influence line
    ``eta_j`` from its cubic pieces (``breaks``, ``cubics``:
    :func:`~vbi_lib.models.statics.influence_pieces`), as the lane kernel evaluates it."""
    n_modes = kappa.shape[0]
    phi = np.empty(n_modes)
    dphi = np.empty(n_modes)
    ddphi = np.empty(n_modes)
    last = breaks.shape[1] - 2
    for i in range(s.shape[0]):
        shape_values(s[i], supports, kappa, coef, phi, dphi, ddphi)
        for j in range(out.shape[1]):
            series = 0.0
            for n in range(n_modes):
                series += g[j, n] * phi[n]
            k = 0
            while k < last and s[i] >= breaks[j, k + 1]:
                k += 1
            width = breaks[j, k + 1] - breaks[j, k]
            u = (s[i] - breaks[j, k]) / width if width > 0.0 else 0.0
            eta = ((cubics[j, k, 3] * u + cubics[j, k, 2]) * u + cubics[j, k, 1]) * u
            out[i, j] = force[i] * (series - (eta + cubics[j, k, 0]))


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
    series_daf
        Per span, the N-mode series' DAF: the largest downward value of
        :attr:`series_midspan_displacement` over the run, over the N-mode beam's largest
        static deflection of the same midspan (``daf`` is the mode-acceleration one, over
        the exact beam's); the two agree as ``N`` grows.
    """

    modes: BeamModes
    modal_coordinates: np.ndarray
    modal_velocities: np.ndarray
    series_daf: np.ndarray

    @property
    def series_midspan_displacement(self) -> np.ndarray:
        """The N-mode series at each midspan, ``sum_n phi_n(m_j) q_n``, ``(n_time, n_spans)``
        [m] (``midspan_displacement`` adds the static part the series leaves out)."""
        return self.modal_coordinates @ self.modes.shape(np.array(self.bridge.midspans)).T

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Natural frequencies of the N modes [Hz]."""
        return self.modes.frequencies_hz

    def modal_history(self) -> tuple[BeamModes, np.ndarray]:
        """The modes and their coordinates ``q_n(t)``, for the section responses."""
        return self.modes, self.modal_coordinates


def check_modes(modes: object) -> int:
    """A number of modes: a whole number >= 1, or 0 for ``None`` (:func:`default_modes`)."""
    if modes is None:
        return 0
    if isinstance(modes, bool) or not isinstance(modes, int | np.integer) or modes < 1:
        raise ValueError(
            f"modes={modes!r} must be a whole number of modes >= 1, or None for the default "
            "(every mode up to 2.3 times the highest simply supported span frequency)"
        )
    return int(modes)


#: The default modes reach this multiple of the highest simply supported frequency of any one
#: span: above a span's clamped-clamped frequency (2.27 times), which bounds its own fundamental.
DEFAULT_MODES_REACH = 2.3


@lru_cache(maxsize=256)
def default_modes(bridge: Bridge) -> int:
    """The number of modes ``modes=None`` takes: every mode of the continuous beam with a
    frequency up to :data:`DEFAULT_MODES_REACH` times the highest simply supported frequency
    of any one span, at least one.

    A span's own fundamental lies between its simply supported and its clamped-clamped
    frequency (2.27 times), whatever its neighbours, so the default includes every span's.

    Examples
    --------
    One span: its first mode only (the second is at 4 times); a 10 m span beside a 200 m
    one: the 10 m span's fundamental and the 30 modes of the long span below it.

    >>> from vbi_lib import Bridge
    >>> default_modes(Bridge(30.0, 1, 1e10, 5000.0)), default_modes(Bridge(25.0, 2, 1e10, 5000.0))
    (1, 2)
    >>> default_modes(Bridge.continuous([10.0, 200.0], EI=1e10, mass_per_length=5000.0))
    31
    """
    reach = math.sqrt(DEFAULT_MODES_REACH) * math.pi / min(bridge.spans)  # wavenumber [1/m]
    return max(1, count_below(reach, list(bridge.spans)))


#: Stations a span is sampled at to find which spans a mode moves.
_OWN_SAMPLES = 64


@lru_cache(maxsize=1024)
def missing_spans(bridge: Bridge, count: int) -> tuple[int, ...]:
    """Spans (1-based) whose own fundamental the first ``count`` modes may leave out.

    A mode is a span's own when it moves that span at least half as much as the span it
    moves most (the largest ``|phi|`` over each span, sampled along it, not only at the
    midspans, where a long span's antisymmetric modes have a node).  A span is flagged
    when none of the modes kept is its own, or when the highest of them is below the span's
    simply supported frequency, about where its own fundamental begins (a short span's
    modes coupled to a long neighbour's lie below it and do not carry its own vibration).
    """
    basis = beam_modes(bridge, count)
    supports = np.array(bridge.supports)
    u = (np.arange(_OWN_SAMPLES) + 0.5) / _OWN_SAMPLES
    x = (supports[:-1, None] + np.diff(supports)[:, None] * u[None, :]).ravel()
    phi = np.abs(basis.shape(x))  # (n_spans * samples, N)
    largest = phi.reshape(bridge.n_spans, _OWN_SAMPLES, -1).max(axis=1)  # (n_spans, N)
    own = largest >= 0.5 * largest.max(axis=0, keepdims=True)
    lengths = np.diff(supports)
    simply = (math.pi / lengths) ** 2 * math.sqrt(bridge.EI / bridge.mass_per_length)
    simply /= 2 * math.pi  # each span's simply supported frequency [Hz]
    reach = float(basis.frequencies_hz[-1])
    return tuple(j + 1 for j in range(bridge.n_spans)
                 if not own[j].any() or reach < (1.0 - 1e-6) * simply[j])  # fmt: skip


def missing_note(spans: tuple[int, ...], count: int) -> str:
    """The sentence on spans whose own fundamental ``modes`` leaves out."""
    which = ", ".join(str(j) for j in spans)
    return (
        f"modes={count} leaves out the fundamental of span {which}: its series DAF would not "
        "have converged; the span DAF is the mode-acceleration one, exact in its statics, and "
        "modes=None includes every span's fundamental"
    )


class Modal(CrossingModel):
    """Any vehicle on the bridge's first N exact beam modes; Newmark average acceleration."""

    name = "modal"
    description = "N exact Euler-Bernoulli modes (any spans); Newmark average acceleration"
    result_type = ModalCrossing
    statics = "exact"  # the mode-acceleration headline converges to the exact beam's
    summary_peaks = False  # the headline needs the contact forces: from the histories

    lane_kernel = staticmethod(run_lanes)

    def __init__(self, bridge, vehicle, speed, bridge_start, *, coupled, convective, modes):  # noqa: ANN001
        super().__init__(bridge, vehicle, speed, bridge_start, coupled=coupled,
                         convective=convective, modes=modes)  # fmt: skip
        self.count = check_modes(modes) or default_modes(bridge)
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

    def _vector(self, grid: Grid) -> np.ndarray:
        return vehicle_vector(self.system, self.system.static_position(grid.road[:, 0]))

    def _correction(self, contact: np.ndarray, grid: Grid) -> np.ndarray:
        """``c_j`` at the nodes ``(n_nodes, n_spans)`` [m]: ``sum_a F_ca (sum_n phi_n(m_j)
        phi_n(x_a) / omega_n^2 - eta_j(x_a))``, ``F_ca`` axle a's contact force from the node on
        (zero for an axle off the bridge over the step, and at the last node)."""
        n_nodes, n_spans = grid.x.size, self.bridge.n_spans
        out = np.zeros((n_nodes, n_spans))
        g = np.ascontiguousarray(self.phi_mid / self.basis.omega**2)  # (n_spans, N)
        breaks, cubics = influence_pieces(self.bridge)
        b = self.basis
        for a, offset in enumerate(self.system.offsets):
            on = np.flatnonzero(grid.axle_span[a, : n_nodes - 1] > 0)
            if on.size == 0:
                continue
            s = np.clip(grid.x[on] - offset - self.bridge_start, 0.0, self.bridge.length)
            part = np.zeros((on.size, n_spans))
            _correction_values(s, np.ascontiguousarray(contact[on, a]), np.array(b.supports),
                               np.array(b.wavenumber), np.array(b.coefficients), g, breaks,
                               cubics, part)  # fmt: skip
            out[on] += part
        return out

    def midspan_history(self, fields, grid):  # noqa: ANN001, ANN201
        # the mode-acceleration displacement: the series plus the statics the series misses
        correction = self._correction(fields["axle_contact_force"], grid)
        h = np.diff(grid.x) / self.speed
        secant = np.zeros_like(correction)
        secant[:-1] = np.diff(correction, axis=0) / np.where(h > 0, h, 1.0)[:, None]
        value = fields["modal_coordinates"] @ self.phi_mid.T + correction
        return value, fields["modal_velocities"] @ self.phi_mid.T, secant

    def checks(self, fields, grid, daf):  # noqa: ANN001, ANN201
        warned = []
        missing = missing_spans(self.bridge, self.count)
        if missing:
            warned.append(missing_note(missing, self.count))
        series = fields["modal_coordinates"] @ self.phi_mid.T
        peaks = peaks_of(series, fields["modal_velocities"] @ self.phi_mid.T,
                         np.zeros_like(series), grid.x, self.speed)  # fmt: skip
        peaks[~(peaks > 0.0)] = np.nan
        series_daf = peaks / span_statics(self.bridge, self.system, "modal", self.count)
        quiet = []
        apart = np.abs(series_daf - daf) > 0.01 * np.abs(daf)
        if apart.any():
            j = int(np.nanargmax(np.where(apart, np.abs(series_daf - daf), np.nan)))
            quiet.append(
                f"the {self.count}-mode series gives span {j + 1} a DAF of {series_daf[j]:.4g} "
                f"against {daf[j]:.4g} by mode acceleration, the headline, which converges "
                "faster (its statics are exact): more modes bring the series to it"
            )
        return quiet, warned, {"series_daf": series_daf}

    @classmethod
    def batch_notes(cls, batch: Batch) -> list[str]:
        """The spans whose own fundamental a crossing's ``modes`` leaves out, once per bridge
        and number of modes."""
        first, _ = batch.groups(batch.bridge, batch.modes)
        out = []
        for i in first:
            bridge = batch.bridges[batch.bridge[i]]
            count = int(batch.modes[i])
            missing = missing_spans(bridge, count)
            if missing:
                out.append(missing_note(missing, count))
        return out

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
    def resolve_modes(cls, batch: Batch) -> Batch:
        """``modes=None`` (0 in the batch) made each bridge's :func:`default_modes`."""
        if (batch.modes > 0).all():
            return batch
        defaults = np.array([default_modes(b) for b in batch.bridges])[batch.bridge]
        return replace(batch, modes=np.where(batch.modes > 0, batch.modes, defaults))

    @classmethod
    def integrate_setups(cls, models, grids):  # noqa: ANN001, ANN206
        """Any vehicles: one crossing at a time with its histories, whose mode-acceleration
        peaks (:meth:`span_peaks`) go into the summary, as :func:`vbi_lib.simulate`'s."""
        summaries = np.full((len(models), SUMMARY_SIZE), np.nan)
        for i, (model, grid) in enumerate(zip(models, grids, strict=True)):
            summary, contact, fields, _ = model.integrate(grid)
            summary[S_PEAK : S_PEAK + PEAK_SLOTS] = np.nan
            width = min(model.bridge.n_spans, PEAK_SLOTS)
            history = model.midspan_history({**fields, "axle_contact_force": contact}, grid)
            summary[S_PEAK : S_PEAK + width] = model.span_peaks(summary, history, grid)[:width]
            summaries[i] = summary
        return summaries
