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

(the contact force pressing on the road is :math:`R = m_v g + F`).  :math:`\epsilon = 1` keeps
the convective part of the wheel's velocity; the study's own code had :math:`\epsilon = 0`.
The decoupled variant (92)-(99) drops the bridge from :math:`F`.  Written as
:math:`\dot z = A(x_v) z + B(x_v) U + f(x_v)`, the matrices are built in one place,
:func:`state_matrices`.

Integration
-----------
Classical fourth-order Runge-Kutta on the shared node grid (every profile sample, the bridge
ends and the interior support), subdivided so that :math:`\omega_{max} \Delta t \le 0.1`
(``omega_max`` the largest eigenvalue modulus of :math:`A`).  Between nodes the profile is a
straight line, so the input is exact on each step; the coefficients switch only at nodes.
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
from functools import lru_cache

import numba
import numpy as np

from ..bridges import Bridge
from ..vehicles import Vehicle
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
    Batch,
    CrossingModel,
    Grid,
    downward_peak,
    parameters,
    start_summary,
    track_contact,
    track_peak,
)
from .lanes_one_coordinate import run as run_lanes
from .one_coordinate_step import (
    C_CB,
    C_CV,
    C_KB,
    C_KV,
    C_MB,
    C_MV,
    C_SPAN,
    C_SPEED,
    COEFFICIENTS,
    omega_max,
    omega_max_threads,
)
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
        if on:
            # midspan displacement of span j is psi(mid_j) z_b = +z_b (span 1), -z_b (span 2)
            sign = 1.0 if span == 1 else -1.0
            track_peak(summary, span, downward_peak(sign * za, sign * z[2], sign * da,
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
def _speed_matters(vehicle: Vehicle, coupled: bool, convective: bool) -> bool:
    """Whether ``A`` depends on the speed: only through the damper's convective term."""
    return coupled and convective and vehicle.damping != 0.0


#: The parameter-vector entries the default step needs, in the order of ``C_*``.
_STEP_COLUMNS = [P_MASS, P_STIFFNESS, P_DAMPING, _M_B, _K_B, _C_B, P_SPEED, P_SPAN]


@lru_cache(maxsize=4096)
def _cached_omega_max(
    bridge: Bridge, vehicle: Vehicle, speed: float, coupled: bool, convective: bool
) -> float:
    rows = _parameters(bridge, vehicle, speed, 0.0)[None, _STEP_COLUMNS]
    return float(omega_max(rows, np.array([coupled]), np.array([convective]))[0])


def highest_circular_frequency(
    bridge: Bridge, vehicle: Vehicle, speed: float, coupled: bool = True, convective: bool = True
) -> float:
    """Largest eigenvalue modulus of ``A`` over the wheel positions [rad/s].

    Taken at ``psi = 0, 1/4, 1/2, 3/4, 1`` (with the slope ``psi'`` of the half sine there);
    compiled, and remembered for each bridge, vehicle and options (and speed, when the
    damper's convective term makes ``A`` depend on it).
    """
    if not _speed_matters(vehicle, coupled, convective):
        speed = 0.0  # A is the same at every speed: one entry serves them all
    return _cached_omega_max(bridge, vehicle, float(speed), bool(coupled), bool(convective))


def default_time_step(
    bridge: Bridge, vehicle: Vehicle, speed: float, coupled: bool = True, convective: bool = True
) -> float:
    """``DEFAULT_OMEGA_DT / omega_max``: the largest step the model takes by default [s]."""
    return DEFAULT_OMEGA_DT / highest_circular_frequency(
        bridge, vehicle, speed, coupled, convective
    )


def _step_rows(batch: Batch, rows: np.ndarray, speed: np.ndarray) -> np.ndarray:
    """The default step's coefficients (``C_*``) of the crossings ``rows`` at ``speed``."""
    out = np.empty((rows.size, COEFFICIENTS))
    for column, objects, name in (
        (C_MV, "vehicles", "mass"),
        (C_KV, "vehicles", "stiffness"),
        (C_CV, "vehicles", "damping"),
        (C_MB, "bridges", "generalized_mass"),
        (C_KB, "bridges", "generalized_stiffness"),
        (C_CB, "bridges", "generalized_damping"),
        (C_SPAN, "bridges", "span"),
    ):
        out[:, column] = batch.column(objects, name)[rows]
    out[:, C_SPEED] = speed
    return out


def default_time_steps(batch: Batch) -> np.ndarray:
    """:func:`default_time_step` of every crossing of a batch [s], ``(n,)``.

    ``A`` is built and its eigenvalues found once per distinct bridge, vehicle, options and
    (where it matters) speed: through the cache of :func:`highest_circular_frequency` for a
    few, in compiled code for many (on numba's threads for thousands).
    """
    damped = np.array([x.damping != 0.0 for x in batch.vehicles])[batch.vehicle]
    speed = np.where(batch.coupled & batch.convective & damped, batch.speed, 0.0)
    first, inverse = batch.groups(batch.bridge, batch.vehicle, batch.coupled,
                                  batch.convective, speed)  # fmt: skip
    bridges = [batch.bridges[k] for k in batch.bridge[first]]
    vehicles = [batch.vehicles[k] for k in batch.vehicle[first]]
    rows = list(zip(bridges, vehicles, speed[first], strict=True))
    coupled, convective = batch.coupled[first], batch.convective[first]
    if first.size <= 64:
        omega = np.array([highest_circular_frequency(b, v, s, c, e) for (b, v, s), c, e
                          in zip(rows, coupled, convective, strict=True)])  # fmt: skip
    else:  # ~4 us a row: threads only when their wake-up (ms on a busy machine) is worth it
        solve = omega_max_threads if first.size > 4096 else omega_max
        omega = solve(_step_rows(batch, first, speed[first]), coupled, convective)
    return DEFAULT_OMEGA_DT / omega[inverse]


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


class OneCoordinate(CrossingModel):
    """The study's model: one sprung mass on the one-coordinate beam, RK4 (33)-(99)."""

    name = "one-coordinate"
    description = "the study's beam with one coordinate psi z_b (1 or 2 spans); RK4"
    result_type = OneCoordinateCrossing

    def __init__(self, bridge, vehicle, speed, bridge_start, *, coupled, convective, modes):  # noqa: ANN001
        self.check_modes(modes)
        super().__init__(bridge, vehicle, speed, bridge_start, coupled=coupled,
                         convective=convective, modes=modes)  # fmt: skip
        self.params = _parameters(bridge, vehicle, speed, bridge_start)

    @classmethod
    def check_modes(cls, modes: object) -> int:
        if modes is not None:
            raise ValueError(
                f"modes={modes!r} applies to model='modal'; the one-coordinate model bends the "
                "beam in one shape (pass model='modal', modes=N for N beam modes)"
            )
        return 0

    def default_time_step(self) -> tuple[float, str]:
        dt = default_time_step(self.bridge, self.vehicle, self.speed, self.coupled, self.convective)
        return dt, (
            f"dt picked as {DEFAULT_OMEGA_DT} / omega_max = {dt * 1e3:.3f} ms "
            "(or the profile step if smaller)"
        )

    def static_deflection(self) -> float:
        return self.bridge.static_deflection(self.vehicle.weight)

    def integrate(self, grid: Grid):  # noqa: ANN201
        n = grid.x.size
        states = np.empty((n, 4))
        contact = np.empty(n)
        summary = np.empty(SUMMARY_SIZE)
        _kernel(grid.x, grid.elevation, grid.span_of_step, self.params, self.bridge.n_spans,
                self.coupled, self.convective, states, contact, summary)  # fmt: skip
        signs = np.array([1.0, -1.0][: self.bridge.n_spans])
        fields = {
            "vehicle_displacement": states[:, 0],
            "vehicle_velocity": states[:, 1],
            "bridge_coordinate": states[:, 2],
            "bridge_velocity": states[:, 3],
            "midspan_displacement": states[:, 2:3] * signs,
        }
        note = f"{n - 1} RK4 steps, largest {grid.dt_max * 1e3:.3f} ms"
        return summary, contact, fields, note

    @classmethod
    def default_time_steps(cls, batch: Batch) -> np.ndarray:
        return default_time_steps(batch)

    @classmethod
    def static_deflections(cls, batch: Batch) -> np.ndarray:
        weight = np.array([x.weight for x in batch.vehicles])[batch.vehicle]
        return weight / batch.column("bridges", "generalized_stiffness")

    @classmethod
    def integrate_many(cls, batch: Batch, dt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Summaries and largest steps of a batch: the lane kernel for the study's vehicles."""
        if batch.plain_vehicles():
            return run_lanes(batch, dt)
        return super().integrate_many(batch, dt)
