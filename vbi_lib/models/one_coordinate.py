r"""The study's model: a sprung mass on a beam with one generalised coordinate (equations 33-99).

States and inputs (49)-(50): :math:`z = (u_v, \dot u_v, z_b, \dot z_b)`,
:math:`U = (\Delta, \dot\Delta)` with :math:`\dot\Delta = v\, d\Delta/dx`.  With the wheel at
:math:`x_v = x_0 + v t`, the shape function :math:`\psi = \psi(x_v)` and
:math:`\psi' = d\psi/dx` (both zero while the wheel is off the bridge), the road under the
wheel is :math:`r = \psi z_b + \Delta` and

.. math::
    F &= k_v (r - u_v) + c_v (\dot r - \dot u_v), \qquad
        \dot r = \psi \dot z_b + \epsilon\, v \psi' z_b + \dot\Delta \\
    m_v \ddot u_v &= F \\
    m^* \ddot z_b + c^* \dot z_b + k^* z_b &= -\psi\, (m_v g + F)

(the contact force pressing on the road is :math:`F_c = m_v g + F`).  :math:`\epsilon = 1` keeps
the convective part of the wheel's velocity; the study's own code had :math:`\epsilon = 0`.
The decoupled variant (92)-(99) drops the bridge from :math:`F`.  Written as
:math:`\dot z = A(x_v) z + B(x_v) U + f(x_v)`, the matrices are built in one place,
:func:`state_matrices`.

Any vehicle
-----------
Every vehicle of :mod:`vbi_lib.vehicles` (several axles, tyres that can leave the road) is
integrated by the general kernel of :mod:`~vbi_lib.models.coordinate_kernel`, of which the
equations above are the one-axle case.  The study's sprung mass (:class:`~vbi_lib.Vehicle`)
keeps the compiled 4x4 kernel below, single crossings and batches: it is 1.5 times faster,
and the general kernel reproduces it to 1e-14 (its ``.system`` runs through the general
kernel; the tests compare the two).

DAF
---
The DAF of span ``j`` is the largest downward deflection of its midspan,
:math:`\psi(m_j) z_b`, over the whole run, divided by the largest static deflection of the
same midspan of the one-shape beam under the vehicle's static axle loads, every axle in every
position of the group: :math:`\max_p \psi(m_j) \sum_a \psi(p - o_a) P_a / k^*`, span by span
(:func:`~vbi_lib.models.statics.span_statics`, ``"one-shape"``).  One axle gives
:math:`P / k^*` on every span, the study's (90)-(91).

Integration
-----------
Classical fourth-order Runge-Kutta on the shared node grid (every profile sample under
every axle, the bridge ends and the interior support), subdivided so that
:math:`\omega_{max} \Delta t \le 0.1` (``omega_max`` the largest eigenvalue modulus of
the state matrix with every contact on, the axles sampled together along the span).
Between nodes the profile is a straight line, so the input is exact on each step; the
coefficients switch only at nodes.
RK4 is explicit, cheap (four evaluations of a 4x4 system) and, at
:math:`\omega \Delta t \le 0.1`, has a phase error of order :math:`(\omega\Delta t)^4/120` per
radian: far below what the DAF can resolve.  Forward Euler (the study's choice) adds energy
every cycle and inflates the DAF; see :mod:`vbi_lib.models.reference` and the model chapter.
The midspan peaks are refined inside each step from the cubic Hermite interpolant of
:math:`z_b` and :math:`\dot z_b`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np

from ..bridges import Bridge
from ..modes import BeamModes, beam_modes
from ..vehicles import Vehicle, VehicleSystem, as_system
from . import coordinate_kernel
from .axles import event_log, logged_events, vehicle_vector
from .base import (
    DEFAULT_OMEGA_DT,
    P_COUNT,
    P_DAMPING,
    P_GRAVITY,
    P_MASS,
    P_SPAN,
    P_SPEED,
    P_START,
    P_STIFFNESS,
    SUMMARY_SIZE,
    CrossingModel,
    Grid,
    downward_peak,
    parameters,
    start_summary,
    track_contact,
    track_peak,
)
from .batch import Batch
from .lanes_one_coordinate import run as run_lanes
from .one_coordinate_step import sprung_mass_omega, sprung_mass_time_steps
from .results import Crossing

# the model's entries of the parameter vector, after the shared ones
_M_B, _K_B, _C_B = P_COUNT, P_COUNT + 1, P_COUNT + 2


# ---------------------------------------------------------------------------- state space
@numba.njit(cache=True)
def _fill_state_matrices(A, B, f, psi, dpsi, params, coupled, convective):  # noqa: N803
    """Fill ``A`` (4x4), ``B`` (4x2) and ``f`` (4) in place; see :func:`state_matrices`."""
    m_v = params[P_MASS]
    k_v = params[P_STIFFNESS]
    c_v = params[P_DAMPING]
    m_b = params[_M_B]
    k_b = params[_K_B]
    c_b = params[_C_B]
    speed = params[P_SPEED]
    for i in range(4):
        f[i] = 0.0
        B[i, 0] = 0.0
        B[i, 1] = 0.0
        for j in range(4):
            A[i, j] = 0.0
    # suspension force F = k_v (r - u_v) + c_v (r' - u_v') with r = psi z_b + Delta
    kz = 0.0  # dF / dz_b
    cz = 0.0  # dF / dz_b'
    if coupled:
        kz = k_v * psi + (c_v * speed * dpsi if convective else 0.0)
        cz = c_v * psi
    A[0, 1] = 1.0
    A[1, 0] = -k_v / m_v
    A[1, 1] = -c_v / m_v
    A[1, 2] = kz / m_v
    A[1, 3] = cz / m_v
    B[1, 0] = k_v / m_v
    B[1, 1] = c_v / m_v
    A[2, 3] = 1.0
    A[3, 0] = psi * k_v / m_b
    A[3, 1] = psi * c_v / m_b
    A[3, 2] = (-k_b - psi * kz) / m_b
    A[3, 3] = (-c_b - psi * cz) / m_b
    B[3, 0] = -psi * k_v / m_b
    B[3, 1] = -psi * c_v / m_b
    f[3] = -psi * m_v * params[P_GRAVITY] / m_b


def state_matrices(
    bridge: Bridge,
    vehicle: Vehicle,
    speed: float,
    psi: float,
    dpsi: float = 0.0,
    coupled: bool = True,
    convective: bool = True,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    r"""The study's state-space matrices (51)-(58), (72)-(81), (95)-(99): ``dz/dt = A z + B U + f``.

    With :math:`\kappa = k_v \psi + \epsilon c_v v \psi'` and :math:`\gamma = c_v \psi`
    (both zero when ``coupled=False``):

    .. math::
        A = \begin{bmatrix} 0 & 1 & 0 & 0 \\
            -k_v/m_v & -c_v/m_v & \kappa/m_v & \gamma/m_v \\
            0 & 0 & 0 & 1 \\
            \psi k_v/m^* & \psi c_v/m^* & -(k^* + \psi\kappa)/m^* & -(c^* + \psi\gamma)/m^*
            \end{bmatrix},\quad
        B = \begin{bmatrix} 0 & 0 \\ k_v/m_v & c_v/m_v \\ 0 & 0 \\
            -\psi k_v/m^* & -\psi c_v/m^* \end{bmatrix},\quad
        f = \begin{bmatrix} 0 \\ 0 \\ 0 \\ -\psi m_v g / m^* \end{bmatrix}.

    Off the bridge :math:`\psi = \psi' = 0`: the vehicle rides the rigid road and the bridge
    vibrates freely (56)-(58).

    Parameters
    ----------
    bridge, vehicle
        The beam and the sprung mass.
    speed
        Vehicle speed [m/s].
    psi, dpsi
        Shape function ``sin(pi x/L)`` and its slope ``(pi/L) cos(pi x/L)`` [1/m] at the wheel.
    coupled, convective
        As in :func:`vbi_lib.simulate`.

    Examples
    --------
    >>> from vbi_lib import Bridge, Vehicle
    >>> A, B, f = state_matrices(Bridge(20.0, 1, 1e10, 5000.0), Vehicle(1e4, 4e6, 2e4), 20.0, 1.0)
    >>> A.shape, B.shape, f.shape
    ((4, 4), (4, 2), (4,))
    """
    A = np.zeros((4, 4))
    B = np.zeros((4, 2))
    f = np.zeros(4)
    params = _parameters(bridge, vehicle, speed, 0.0)
    _fill_state_matrices(A, B, f, float(psi), float(dpsi), params, coupled, convective)
    return A, B, f


def _parameters(bridge: Bridge, vehicle: Vehicle, speed: float, bridge_start: float) -> np.ndarray:
    params = parameters(vehicle, speed, bridge_start, bridge.span, extra=3)
    params[_M_B] = bridge.generalized_mass
    params[_K_B] = bridge.generalized_stiffness
    params[_C_B] = bridge.generalized_damping
    return params


# ---------------------------------------------------------------------------- kernel
@numba.njit(cache=True)
def _shape(x, params, on_bridge):
    """``psi`` and ``dpsi/dx`` at station ``x`` (zero off the bridge)."""
    if not on_bridge:
        return 0.0, 0.0
    k = math.pi / params[P_SPAN]
    xi = x - params[P_START]
    return math.sin(k * xi), k * math.cos(k * xi)


@numba.njit(cache=True)
def _derivative(out, z, A, B, f, elevation, elevation_rate):
    for i in range(4):
        out[i] = (
            A[i, 0] * z[0]
            + A[i, 1] * z[1]
            + A[i, 2] * z[2]
            + A[i, 3] * z[3]
            + B[i, 0] * elevation
            + B[i, 1] * elevation_rate
            + f[i]
        )


@numba.njit(cache=True)
def _kernel(x, elevation, span_of_step, params, n_spans, coupled, convective, states, contact,
            summary):  # fmt: skip
    """Integrate one crossing with RK4 over the nodes ``x``.

    The contact force at a node is evaluated with the step that starts there (the profile
    slope, hence the damper force, jumps at every sample).  ``states`` (n_nodes x 4) and
    ``contact`` (n_nodes) receive the history when they have ``n_nodes`` rows; with one row
    only the summary is kept.
    """
    n_nodes = x.shape[0]
    record = states.shape[0] == n_nodes
    speed = params[P_SPEED]
    m_v = params[P_MASS]
    weight = m_v * params[P_GRAVITY]
    A0 = np.empty((4, 4))
    B0 = np.empty((4, 2))
    f0 = np.empty(4)
    Am = np.empty((4, 4))
    Bm = np.empty((4, 2))
    fm = np.empty(4)
    A1 = np.empty((4, 4))
    B1 = np.empty((4, 2))
    f1 = np.empty(4)
    k1 = np.empty(4)
    k2 = np.empty(4)
    k3 = np.empty(4)
    k4 = np.empty(4)
    tmp = np.empty(4)
    z = np.zeros(4)
    z[0] = elevation[0]  # at rest in static equilibrium on the profile
    start_summary(summary, n_spans)
    if record:
        for i in range(4):
            states[0, i] = z[i]
    for k in range(n_nodes - 1):
        xa = x[k]
        xb = x[k + 1]
        dx = xb - xa
        h = dx / speed
        slope = (elevation[k + 1] - elevation[k]) / dx
        rate = slope * speed
        span = span_of_step[k]
        on = span > 0
        psi_a, dpsi_a = _shape(xa, params, on)
        psi_m, dpsi_m = _shape(0.5 * (xa + xb), params, on)
        psi_b, dpsi_b = _shape(xb, params, on)
        _fill_state_matrices(A0, B0, f0, psi_a, dpsi_a, params, coupled, convective)
        _fill_state_matrices(Am, Bm, fm, psi_m, dpsi_m, params, coupled, convective)
        _fill_state_matrices(A1, B1, f1, psi_b, dpsi_b, params, coupled, convective)
        e_a = elevation[k]
        e_m = 0.5 * (elevation[k] + elevation[k + 1])
        e_b = elevation[k + 1]
        _derivative(k1, z, A0, B0, f0, e_a, rate)
        force = weight + m_v * k1[1]
        if record:
            contact[k] = force
        if on:
            track_contact(summary, force, xa, h)
        for i in range(4):
            tmp[i] = z[i] + 0.5 * h * k1[i]
        _derivative(k2, tmp, Am, Bm, fm, e_m, rate)
        for i in range(4):
            tmp[i] = z[i] + 0.5 * h * k2[i]
        _derivative(k3, tmp, Am, Bm, fm, e_m, rate)
        for i in range(4):
            tmp[i] = z[i] + h * k3[i]
        _derivative(k4, tmp, A1, B1, f1, e_b, rate)
        za = z[2]
        da = z[3]
        for i in range(4):
            z[i] += h * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]) / 6.0
        if record:
            for i in range(4):
                states[k + 1, i] = z[i]
        # every midspan over the whole run: psi(mid_j) z_b = +z_b (span 1), -z_b (span 2)
        for j in range(n_spans):
            sign = 1.0 if j == 0 else -1.0
            track_peak(summary, j + 1, downward_peak(sign * za, sign * z[2], sign * da,
                                                     sign * z[3], h))  # fmt: skip
    # the last node starts no step: its force uses the last step's matrices and slope
    k = n_nodes - 1
    on = span_of_step[k - 1] > 0
    psi_b, dpsi_b = _shape(x[k], params, on)
    _fill_state_matrices(A1, B1, f1, psi_b, dpsi_b, params, coupled, convective)
    slope = (elevation[k] - elevation[k - 1]) / (x[k] - x[k - 1])
    _derivative(k1, z, A1, B1, f1, elevation[k], slope * speed)
    force = weight + m_v * k1[1]
    if record:
        contact[k] = force
    if on:
        track_contact(summary, force, x[k], 0.0)


# ---------------------------------------------------------------------------- model
def system_matrix(
    bridge: Bridge,
    vehicle: object,
    speed: float,
    psi: float | np.ndarray,
    dpsi: float | np.ndarray = 0.0,
    coupled: bool = True,
    convective: bool = True,
) -> np.ndarray:
    """State matrix of any vehicle on the one-coordinate beam, every contact on the road.

    States ``(u, du/dt, z_b, dz_b/dt)``, shape ``(2n + 2, 2n + 2)``; ``psi`` and ``dpsi``
    are the shape function and its slope at each axle (one value for all).  For the study's
    sprung mass it is :func:`state_matrices`' ``A``.
    """
    s = as_system(vehicle)
    return _couple(_vehicle_block(bridge, s), bridge, s, speed, psi, dpsi, coupled, convective)


def _couple(block, bridge, s, speed, psi, dpsi, coupled, convective) -> np.ndarray:  # noqa: ANN001
    """:func:`system_matrix` from the entries that do not depend on the axles' positions."""
    n = s.n_dofs
    A = block.copy()
    psi = np.broadcast_to(np.asarray(psi, dtype=float), (s.n_axles,))
    dpsi = np.broadcast_to(np.asarray(dpsi, dtype=float), (s.n_axles,))
    cpl = 1.0 if coupled else 0.0
    eps = 1.0 if convective else 0.0
    k, c = s.contact_stiffness, s.contact_damping
    # the dynamic contact forces F = -k E u - c E v + Fz z_b + Fzd dz_b/dt
    Fz = cpl * (k * psi + c * eps * speed * dpsi)
    Fzd = cpl * c * psi
    ME = s.mass_inverse @ s.contact.T
    mb = bridge.generalized_mass
    A[n : 2 * n, 2 * n] = ME @ Fz
    A[n : 2 * n, 2 * n + 1] = ME @ Fzd
    A[2 * n + 1, :n] = (psi * k) @ s.contact / mb
    A[2 * n + 1, n : 2 * n] = (psi * c) @ s.contact / mb
    A[2 * n + 1, 2 * n] = -(bridge.generalized_stiffness + psi @ Fz) / mb
    A[2 * n + 1, 2 * n + 1] = -(bridge.generalized_damping + psi @ Fzd) / mb
    return A


def _vehicle_block(bridge: Bridge, s: VehicleSystem) -> np.ndarray:
    """The state matrix's entries that do not depend on where the axles are."""
    n = s.n_dofs
    E = s.contact
    A = np.zeros((2 * n + 2, 2 * n + 2))
    A[:n, n : 2 * n] = np.eye(n)
    A[n : 2 * n, :n] = -s.mass_inverse @ s.road_stiffness
    A[n : 2 * n, n : 2 * n] = -s.mass_inverse @ (s.damping + E.T @ (s.contact_damping[:, None] * E))
    A[2 * n, 2 * n + 1] = 1.0
    return A


def highest_circular_frequency(
    bridge: Bridge, vehicle: object, speed: float, coupled: bool = True, convective: bool = True
) -> float:
    """Largest eigenvalue modulus of the state matrix over the wheel positions [rad/s].

    The axles are put together at five positions from the support to midspan (the coupling
    is strongest when they all are at midspan), ``psi = 0, 1/4, ..., 1`` with the slope of
    the half sine there.  The study's sprung mass takes the roots of its characteristic
    quartic in compiled code (:mod:`~vbi_lib.models.one_coordinate_step`), remembered for
    each bridge, vehicle and options (and speed, where the damper's convective term makes
    ``A`` depend on it); other vehicles the eigenvalues of their state matrices.
    """
    if _is_sprung_mass(vehicle):
        return sprung_mass_omega(bridge, vehicle, speed, coupled, convective)
    s = as_system(vehicle)
    block = _vehicle_block(bridge, s)
    stack = []
    for psi in np.linspace(0.0, 1.0, 5):
        dpsi = math.pi / bridge.span * math.sqrt(max(0.0, 1.0 - psi**2))
        stack.append(_couple(block, bridge, s, speed, psi, dpsi, coupled, convective))
    return float(np.abs(np.linalg.eigvals(np.array(stack))).max())


def default_time_step(
    bridge: Bridge, vehicle: object, speed: float, coupled: bool = True, convective: bool = True
) -> float:
    """``DEFAULT_OMEGA_DT / omega_max``: the largest step the model takes by default [s]."""
    return DEFAULT_OMEGA_DT / highest_circular_frequency(
        bridge, vehicle, speed, coupled, convective
    )


def _is_sprung_mass(vehicle: object) -> bool:
    """Whether the compiled 4x4 batch kernel of the study's sprung mass applies."""
    return isinstance(vehicle, Vehicle)


@dataclass(frozen=True, eq=False, kw_only=True, repr=False)
class OneCoordinateCrossing(Crossing):
    """A crossing of the study's one-coordinate model; adds the bridge's coordinate.

    Attributes
    ----------
    bridge_coordinate, bridge_velocity
        Generalised coordinate ``z_b`` [m] and its rate [m/s] at every node.
    """

    bridge_coordinate: np.ndarray
    bridge_velocity: np.ndarray

    def modal_history(self) -> tuple[BeamModes, np.ndarray]:
        """The one shape as the first mode, ``phi_1 = psi / sqrt(m*)``, ``q = sqrt(m*) z_b``.

        ``psi = sin(pi x / L)`` is the first mode of one span and of two equal spans, and
        ``m*``, ``k*`` are its generalised mass and stiffness, so the section responses
        (:mod:`vbi_lib.models.sections`) are the exact statics plus this mode's dynamics.
        """
        scale = math.sqrt(self.bridge.generalized_mass)
        return beam_modes(self.bridge, 1), self.bridge_coordinate[:, None] * scale


class OneCoordinate(CrossingModel):
    """The study's model: any vehicle on the one-coordinate beam, RK4 (33)-(99)."""

    name = "one-coordinate"
    description = "the study's beam with one coordinate psi z_b (1 or 2 spans); RK4"
    max_omega_dt = 2.0  # RK4 is stable below 2.8
    result_type = OneCoordinateCrossing
    statics = "one-shape"  # psi(m_j) sum_a psi(x_a) P_a / k*; one axle: P / k* (90)-(91)

    lane_kernel = staticmethod(run_lanes)

    def __init__(self, bridge, vehicle, speed, bridge_start, *, coupled, convective, modes):  # noqa: ANN001
        self.check_bridge(bridge)
        self.check_modes(modes)
        super().__init__(bridge, vehicle, speed, bridge_start, coupled=coupled,
                         convective=convective, modes=modes)  # fmt: skip
        self.params = _parameters(bridge, vehicle, speed, bridge_start)

    @classmethod
    def check_bridge(cls, bridge: Bridge) -> None:
        if not bridge.study_layout:
            raise ValueError(
                f"the one-coordinate model bends one span or two equal spans in the study's "
                f"shape sin(pi x / L); this bridge has spans {bridge.spans} m.  Use "
                "model='modal', modes=N (exact modes of any layout)"
            )

    @classmethod
    def check_modes(cls, modes: object) -> int:
        if modes is not None:
            raise ValueError(
                f"modes={modes!r} applies to model='modal'; the one-coordinate model bends the "
                "beam in one shape (pass model='modal', modes=N for N beam modes)"
            )
        return 0

    @classmethod
    def default_time_steps(cls, batch: Batch) -> np.ndarray:
        sprung = np.array([_is_sprung_mass(v) for v in batch.vehicles])[batch.vehicle]
        if not sprung.any():
            return super().default_time_steps(batch)
        steps = np.empty(len(batch))
        steps[sprung] = sprung_mass_time_steps(batch.take(sprung))
        if not sprung.all():
            steps[~sprung] = super().default_time_steps(batch.take(~sprung))
        return steps

    def default_time_step(self) -> tuple[float, str]:
        dt = default_time_step(self.bridge, self.vehicle, self.speed, self.coupled, self.convective)
        return dt, (
            f"dt picked as {DEFAULT_OMEGA_DT} / omega_max = {dt * 1e3:.3f} ms "
            "(or the profile step if smaller)"
        )

    def midspan_history(self, fields, grid):  # noqa: ANN001, ANN201
        # midspan j deflects psi(m_j) z_b: +z_b on span 1, -z_b on span 2
        signs = np.array([1.0, -1.0][: self.bridge.n_spans])
        value = fields["bridge_coordinate"][:, None] * signs
        return value, fields["bridge_velocity"][:, None] * signs, np.zeros_like(value)

    def _vector(self, grid: Grid) -> np.ndarray:
        return vehicle_vector(self.system, self.system.static_position(grid.road[:, 0]))

    def integrate(self, grid: Grid):  # noqa: ANN201
        if _is_sprung_mass(self.vehicle):
            return self._integrate_sprung_mass(grid)
        n = grid.x.size
        s: VehicleSystem = self.system
        states = np.empty((n, 2 * s.n_dofs + 2))
        contact = np.empty((n, s.n_axles))
        summary = np.empty(SUMMARY_SIZE)
        events = event_log(n)
        coordinate_kernel.kernel(grid.x, grid.road, grid.axle_span, self.params,
                                 self.bridge.n_spans, self.coupled, self.convective,
                                 self._vector(grid), s.n_dofs, s.n_axles, states, contact,
                                 summary, *events)  # fmt: skip
        signs = np.array([1.0, -1.0][: self.bridge.n_spans])
        z = 2 * s.n_dofs
        fields = {
            "dof_displacement": states[:, : s.n_dofs],
            "dof_velocity": states[:, s.n_dofs : z],
            "bridge_coordinate": states[:, z],
            "bridge_velocity": states[:, z + 1],
            "midspan_displacement": states[:, z : z + 1] * signs,
            "contact_events": logged_events(*events),
        }
        note = f"{n - 1} RK4 steps, largest {grid.dt_max * 1e3:.3f} ms"
        return summary, contact, fields, note

    def _integrate_sprung_mass(self, grid: Grid):  # noqa: ANN202
        """The study's sprung mass on its own compiled 4x4 kernel."""
        n = grid.x.size
        states = np.empty((n, 4))
        contact = np.empty(n)
        summary = np.empty(SUMMARY_SIZE)
        _kernel(grid.x, grid.elevation, grid.span_of_step, self.params, self.bridge.n_spans,
                self.coupled, self.convective, states, contact, summary)  # fmt: skip
        signs = np.array([1.0, -1.0][: self.bridge.n_spans])
        fields = {
            "dof_displacement": states[:, 0:1],
            "dof_velocity": states[:, 1:2],
            "bridge_coordinate": states[:, 2],
            "bridge_velocity": states[:, 3],
            "midspan_displacement": states[:, 2:3] * signs,
        }
        note = f"{n - 1} RK4 steps, largest {grid.dt_max * 1e3:.3f} ms"
        return summary, contact[:, None], fields, note

    @classmethod
    def integrate_setups(cls, models, grids):  # noqa: ANN001, ANN206
        """Any vehicles: the general kernel, one crossing per parallel task."""
        n = len(models)
        offsets = np.zeros(n + 1, dtype=np.int64)
        offsets[1:] = np.cumsum([g.x.size for g in grids])
        road_offsets = np.zeros(n + 1, dtype=np.int64)
        road_offsets[1:] = np.cumsum([g.road.size for g in grids])
        vectors = [m._vector(g) for m, g in zip(models, grids, strict=True)]
        vec_offsets = np.zeros(n + 1, dtype=np.int64)
        vec_offsets[1:] = np.cumsum([v.size for v in vectors])
        summaries = np.full((n, SUMMARY_SIZE), np.nan)
        coordinate_kernel.batch_kernel(
            offsets,
            np.concatenate([g.x for g in grids]),
            np.concatenate([g.road.ravel() for g in grids]),
            np.concatenate([g.axle_span.ravel() for g in grids]),
            road_offsets,
            np.array([m.params for m in models]),
            np.array([m.bridge.n_spans for m in models], dtype=np.int64),
            np.array([m.coupled for m in models], dtype=np.bool_),
            np.array([m.convective for m in models], dtype=np.bool_),
            np.concatenate(vectors),
            vec_offsets,
            np.array([[m.system.n_dofs, m.system.n_axles] for m in models], dtype=np.int64),
            summaries,
        )
        return summaries
