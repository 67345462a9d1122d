r"""A sprung-mass truck crossing a one-coordinate beam: the study's 2-DOF model (equations 46-99).

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
Classical fourth-order Runge-Kutta on a grid of wheel positions that contains every profile
sample, the bridge ends and the interior support, subdivided so that
:math:`\omega_{max} \Delta t \le 0.1` (``omega_max`` the largest eigenvalue modulus of
:math:`A`).  Between nodes the profile is a straight line, so the input is exact on each
step; the coefficients switch only at nodes.  RK4 is explicit, cheap (four evaluations of a
4x4 system) and, at :math:`\omega \Delta t \le 0.1`, has a phase error of order
:math:`(\omega\Delta t)^4/120` per radian: far below what the DAF can resolve.  Forward Euler
(the study's choice) adds energy every cycle and inflates the DAF; see the model chapter.
The midspan peaks are refined inside each step with the cubic Hermite interpolant of
:math:`z_b` and :math:`\dot z_b`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numba
import numpy as np

from . import _validation as check
from .bridges import Bridge
from .profiles import Profile
from .units import g as GRAVITY
from .vehicles import Vehicle

#: ``omega_max * dt`` used when ``dt=None``.
DEFAULT_OMEGA_DT = 0.1

# parameter vector layout shared by the kernels
_M_V, _K_V, _C_V, _M_B, _K_B, _C_B, _GRAV, _SPEED, _START, _SPAN = range(10)
_N_PARAMS = 10


# ---------------------------------------------------------------------------- state space
@numba.njit(cache=True)
def _fill_state_matrices(A, B, f, psi, dpsi, params, coupled, convective):  # noqa: N803
    """Fill ``A`` (4x4), ``B`` (4x2) and ``f`` (4) in place; see :func:`state_matrices`."""
    m_v = params[_M_V]
    k_v = params[_K_V]
    c_v = params[_C_V]
    m_b = params[_M_B]
    k_b = params[_K_B]
    c_b = params[_C_B]
    speed = params[_SPEED]
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
    f[3] = -psi * m_v * params[_GRAV] / m_b


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
        As in :func:`simulate`.

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
    params = np.empty(_N_PARAMS)
    params[_M_V] = vehicle.mass
    params[_K_V] = vehicle.stiffness
    params[_C_V] = vehicle.damping
    params[_M_B] = bridge.generalized_mass
    params[_K_B] = bridge.generalized_stiffness
    params[_C_B] = bridge.generalized_damping
    params[_GRAV] = GRAVITY
    params[_SPEED] = speed
    params[_START] = bridge_start
    params[_SPAN] = bridge.span
    return params


# ---------------------------------------------------------------------------- kernel
@numba.njit(cache=True)
def _shape(x, params, on_bridge):
    """``psi`` and ``dpsi/dx`` at station ``x`` (zero off the bridge)."""
    if not on_bridge:
        return 0.0, 0.0
    k = math.pi / params[_SPAN]
    xi = x - params[_START]
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
def _hermite_peak(a0, a1, d0, d1, h, sign):
    """Largest ``-sign * z(t)`` inside a step from the cubic Hermite interpolant of ``z``."""
    m0 = h * d0
    m1 = h * d1
    c3 = 2.0 * a0 + m0 - 2.0 * a1 + m1
    c2 = -3.0 * a0 - 2.0 * m0 + 3.0 * a1 - m1
    c1 = m0
    best = max(-sign * a0, -sign * a1)
    # roots of 3 c3 t^2 + 2 c2 t + c1 in (0, 1)
    qa = 3.0 * c3
    qb = 2.0 * c2
    qc = c1
    roots = np.empty(2)
    n = 0
    if abs(qa) < 1e-300:
        if abs(qb) > 1e-300:
            roots[0] = -qc / qb
            n = 1
    else:
        disc = qb * qb - 4.0 * qa * qc
        if disc >= 0.0:
            s = math.sqrt(disc)
            roots[0] = (-qb - s) / (2.0 * qa)
            roots[1] = (-qb + s) / (2.0 * qa)
            n = 2
    for i in range(n):
        t = roots[i]
        if 0.0 < t < 1.0:
            value = ((c3 * t + c2) * t + c1) * t + a0
            best = max(best, -sign * value)
    return best


@numba.njit(cache=True)
def _crossing_kernel(
    x,
    elevation,
    span_of_step,
    params,
    n_spans,
    coupled,
    convective,
    states,
    contact,
    peaks,
):
    """Integrate one crossing with RK4 over the nodes ``x``.

    The contact force at a node is evaluated with the step that starts there (the profile
    slope, hence the damper force, jumps at every sample).  ``span_of_step[k]`` is 0 off the
    bridge, else the span (1 or 2) the wheel is on from node k to node k + 1 (one entry per
    node, the last unused).  ``states`` (n_nodes x 4) and ``contact`` (n_nodes) receive the
    history when they have ``n_nodes`` rows; with one row only the summary is kept.
    ``peaks`` receives, per span, the largest downward midspan deflection while the wheel is
    on that span, then the largest contact force on the bridge and the station where it
    occurs.
    """
    n_nodes = x.shape[0]
    record = states.shape[0] == n_nodes
    speed = params[_SPEED]
    m_v = params[_M_V]
    weight = m_v * params[_GRAV]
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
    for j in range(n_spans):
        peaks[j] = -np.inf
    peaks[n_spans] = 0.0
    peaks[n_spans + 1] = np.nan
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
        if record:
            contact[k] = weight + m_v * k1[1]
        elif on:
            force = weight + m_v * k1[1]
            if force > peaks[n_spans]:
                peaks[n_spans] = force
                peaks[n_spans + 1] = xa
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
            if da * z[3] <= 0.0:
                peak = _hermite_peak(za, z[2], da, z[3], h, sign)
            else:
                peak = max(-sign * za, -sign * z[2])
            if peak > peaks[span - 1]:
                peaks[span - 1] = peak
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
    elif on and force > peaks[n_spans]:
        peaks[n_spans] = force
        peaks[n_spans + 1] = x[k]


@numba.njit(cache=True, parallel=True)
def _batch_kernel(offsets, x, elevation, span_of_step, params, n_spans, coupled, convective, peaks):
    """Run many crossings in parallel; crossing i uses nodes ``offsets[i]:offsets[i+1]``."""
    n_jobs = offsets.shape[0] - 1
    for i in numba.prange(n_jobs):
        a = offsets[i]
        b = offsets[i + 1]
        states = np.empty((1, 4))
        contact = np.empty(1)
        _crossing_kernel(
            x[a:b],
            elevation[a:b],
            span_of_step[a:b],
            params[i],
            n_spans[i],
            coupled[i],
            convective[i],
            states,
            contact,
            peaks[i],
        )


# ---------------------------------------------------------------------------- preparation
def _check_inputs(
    bridge: Bridge, vehicle: Vehicle, profile: Profile, speed: float, bridge_start: float
) -> tuple[float, float]:
    if not isinstance(bridge, Bridge):
        raise TypeError(f"bridge must be a vbi.Bridge, got {type(bridge).__name__}")
    if not isinstance(vehicle, Vehicle):
        raise TypeError(f"vehicle must be a vbi.Vehicle, got {type(vehicle).__name__}")
    if not isinstance(profile, Profile):
        raise TypeError(f"profile must be a vbi.Profile, got {type(profile).__name__}")
    speed = check.positive("speed", speed)
    try:
        bridge_start = float(bridge_start)
    except (TypeError, ValueError):
        raise ValueError(f"bridge_start={bridge_start!r} must be a station in metres") from None
    if not math.isfinite(bridge_start):
        raise ValueError(f"bridge_start={bridge_start!r} must be a finite station in metres")
    end = bridge_start + bridge.length
    if bridge_start < profile.start or end > profile.end + 1e-9 * max(1.0, abs(end)):
        raise ValueError(
            f"the profile (stations {profile.start:g} to {profile.end:g} m) does not cover the "
            f"approach and the bridge (stations {profile.start:g} to {end:g} m with "
            f"bridge_start={bridge_start:g} m); extend the profile or move the bridge"
        )
    return speed, bridge_start


def highest_circular_frequency(
    bridge: Bridge, vehicle: Vehicle, speed: float, coupled: bool = True, convective: bool = True
) -> float:
    """Largest eigenvalue modulus of ``A`` over the wheel positions [rad/s]."""
    largest = 0.0
    for psi in np.linspace(0.0, 1.0, 5):
        dpsi = math.pi / bridge.span * math.sqrt(max(0.0, 1.0 - psi**2))
        A, _, _ = state_matrices(bridge, vehicle, speed, psi, dpsi, coupled, convective)
        largest = max(largest, float(np.abs(np.linalg.eigvals(A)).max()))
    return largest


def default_time_step(
    bridge: Bridge, vehicle: Vehicle, speed: float, coupled: bool = True, convective: bool = True
) -> float:
    """``DEFAULT_OMEGA_DT / omega_max``: the largest step ``simulate`` takes by default [s]."""
    return DEFAULT_OMEGA_DT / highest_circular_frequency(
        bridge, vehicle, speed, coupled, convective
    )


@dataclass(frozen=True)
class _Grid:
    x: np.ndarray
    elevation: np.ndarray
    span_of_step: np.ndarray
    dt_max: float


def _grid(
    bridge: Bridge,
    profile: Profile,
    speed: float,
    bridge_start: float,
    dt: float,
    stop: float,
) -> _Grid:
    """Nodes: every profile sample before ``stop``, bridge ends and supports, subdivided."""
    supports = bridge_start + bridge.span * np.arange(bridge.n_spans + 1)
    inside = profile.x[(profile.x > profile.start) & (profile.x < stop)]
    points = np.union1d(np.concatenate(([profile.start], inside, supports)), [stop])
    points = points[points <= stop]
    gaps = np.diff(points)
    keep = np.concatenate(([True], gaps > 1e-12 * max(1.0, abs(stop))))
    points = points[keep]
    gaps = np.diff(points)
    pieces = np.maximum(1, np.ceil(gaps / (speed * dt) - 1e-9)).astype(np.int64)
    starts = np.repeat(points[:-1], pieces)
    widths = np.repeat(gaps / pieces, pieces)
    within = np.arange(pieces.sum()) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    x = np.append(starts + within * widths, points[-1])
    elevation = np.interp(x, profile.x, profile.elevation)
    middle = 0.5 * (x[:-1] + x[1:]) - bridge_start
    # one entry per node (the step that starts there; the last node starts none), so that
    # batches can slice nodes and steps with the same offsets
    span_of_step = np.zeros(x.size, dtype=np.int64)
    span_of_step[:-1] = np.where(
        (middle > 0) & (middle < bridge.length), np.floor(middle / bridge.span) + 1, 0
    )
    return _Grid(x, elevation, span_of_step, float((widths.max() if widths.size else 0) / speed))


# ---------------------------------------------------------------------------- results
class _CrossingViews:
    """What every crossing result offers from its histories (one- and many-mode models)."""

    bridge: Bridge
    vehicle: Vehicle
    bridge_start: float
    position: np.ndarray
    contact_force: np.ndarray
    midspan_displacement: np.ndarray
    static_deflection: float

    @property
    def on_bridge(self) -> np.ndarray:
        """True at nodes where the wheel is on the bridge (ends included)."""
        rel = self.position - self.bridge_start
        return (rel >= -1e-12) & (rel <= self.bridge.length + 1e-12)

    @property
    def contact_force_amplification(self) -> float:
        """Largest contact force while on the bridge over the vehicle's weight."""
        return float(self.contact_force[self.on_bridge].max() / self.vehicle.weight)

    def plot(self, ax=None, span: int | None = None):  # noqa: ANN001, ANN201
        """Plot the midspan deflection (in static deflections) against the wheel position."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        spans = range(self.bridge.n_spans) if span is None else [span - 1]
        x = self.position - self.bridge_start
        for j in spans:
            ax.plot(
                x, self.midspan_displacement[:, j] / self.static_deflection, label=f"span {j + 1}"
            )
        ax.axvspan(0, self.bridge.length, color="0.92", zorder=0)
        ax.set_xlabel("wheel position from the start of the bridge [m]")
        ax.set_ylabel("midspan displacement / static deflection [-]")
        ax.legend(loc="best")
        return ax


@dataclass(frozen=True, eq=False)
class Crossing(_CrossingViews):
    """One crossing: time histories (SI, displacements positive up) and the DAF of each span.

    Attributes
    ----------
    time, position
        Time [s] from the start and wheel station [m] at every node.
    vehicle_displacement
        ``u_v`` [m] from the static position.
    bridge_coordinate
        Generalised coordinate ``z_b`` [m].
    midspan_displacement
        ``(n_time, n_spans)`` midspan displacement of each span [m].
    contact_force
        Force pressing on the road ``R = m_v g + F`` [N].
    daf
        Largest downward midspan deflection of each span while the wheel is on it, over the
        model's static deflection (88)-(91).
    dt
        Largest time step used [s].
    """

    bridge: Bridge
    vehicle: Vehicle
    speed: float
    bridge_start: float
    time: np.ndarray
    position: np.ndarray
    vehicle_displacement: np.ndarray
    vehicle_velocity: np.ndarray
    bridge_coordinate: np.ndarray
    bridge_velocity: np.ndarray
    midspan_displacement: np.ndarray
    contact_force: np.ndarray
    span_of_step: np.ndarray
    daf: np.ndarray
    static_deflection: float
    dt: float
    coupled: bool = True
    convective: bool = True
    notes: tuple[str, ...] = field(default=())

    def __repr__(self) -> str:
        spans = "1 span" if self.bridge.n_spans == 1 else "2 spans"
        dafs = ", ".join(f"{d:.3f}" for d in self.daf)
        return f"Crossing({spans}, {self.speed:.2f} m/s, dt {self.dt * 1e3:.3f} ms: DAF {dafs})"


# ---------------------------------------------------------------------------- public entry
def simulate(
    bridge: Bridge,
    vehicle: Vehicle,
    profile: Profile,
    speed: float,
    bridge_start: float,
    coupled: bool = True,
    convective: bool = True,
    dt: float | None = None,
    free_vibration: float = 0.0,
    modes: int = 1,
) -> Crossing:
    """Simulate one crossing of a sprung-mass truck over a one- or two-span beam.

    The truck starts at ``profile.x[0]`` at rest in static equilibrium, drives at constant
    ``speed`` and the run ends when it leaves the bridge (plus ``free_vibration`` seconds).

    Parameters
    ----------
    bridge, vehicle, profile
        The beam, the sprung mass and the road (stations and elevations in metres).
    speed
        Vehicle speed [m/s].
    bridge_start
        Station of the first support [m]; the bridge spans
        ``[bridge_start, bridge_start + n_spans * span]``.
    coupled
        ``False`` for the decoupled model (92)-(99): the contact force ignores the bridge.
    convective
        Keep the ``v psi' z_b`` term in the wheel's vertical velocity (``False`` is the
        study's code).
    dt
        Largest time step [s]; ``None`` picks ``0.1 / omega_max`` (and at least one step per
        profile sample).  The step used is ``Crossing.dt`` and is noted in ``notes``.
    free_vibration
        Seconds to continue after the truck leaves the bridge.
    modes
        1 (default) for the study's one-coordinate model; ``N > 1`` for the first ``N``
        exact beam modes (:func:`vbi_lib.modal.simulate_modal`, Newmark average
        acceleration), whose result adds ``modal_coordinates``, ``displacement_at`` and
        ``moment_at``.

    Returns
    -------
    Crossing
        (a :class:`vbi_lib.modal.ModalCrossing` when ``modes > 1``)

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> from vbi_lib import units as u
    >>> bridge = vbi.Bridge(100 * u.ft, 1, 7.5e12 * u.lbf * u.inch**2, 4.6 * u.kip / u.ft / u.g)
    >>> truck = vbi.Vehicle.from_frequency(100 * u.slinch, 4.0, 0.10)
    >>> road = vbi.Profile.flat(450 * u.ft, 1 * u.inch)
    >>> vbi.simulate(bridge, truck, road, 720 * u.inch / u.s, 320 * u.ft).daf.round(2)
    array([1.04])
    """
    if isinstance(modes, bool) or not isinstance(modes, int | np.integer) or modes < 1:
        raise ValueError(f"modes={modes!r} must be a whole number >= 1 (1: the study's model)")
    if modes > 1:
        from .modal import simulate_modal

        return simulate_modal(
            bridge,
            vehicle,
            profile,
            speed,
            bridge_start,
            int(modes),
            coupled,
            convective,
            dt,
            free_vibration,
        )
    speed, bridge_start = _check_inputs(bridge, vehicle, profile, speed, bridge_start)
    free_vibration = check.non_negative("free_vibration", free_vibration)
    notes = []
    if dt is None:
        dt = default_time_step(bridge, vehicle, speed, coupled, convective)
        notes.append(
            f"dt picked as {DEFAULT_OMEGA_DT} / omega_max = {dt * 1e3:.3f} ms "
            "(or the profile step if smaller)"
        )
    else:
        dt = check.positive("dt", dt)
    stop = bridge_start + bridge.length + speed * free_vibration
    grid = _grid(bridge, profile, speed, bridge_start, dt, stop)
    n = grid.x.size
    states = np.empty((n, 4))
    contact = np.empty(n)
    peaks = np.empty(bridge.n_spans + 2)
    params = _parameters(bridge, vehicle, speed, bridge_start)
    _crossing_kernel(
        grid.x,
        grid.elevation,
        grid.span_of_step,
        params,
        bridge.n_spans,
        bool(coupled),
        bool(convective),
        states,
        contact,
        peaks,
    )
    static = bridge.static_deflection(vehicle.weight)
    signs = np.array([1.0, -1.0][: bridge.n_spans])
    notes.append(f"{n - 1} RK4 steps, largest {grid.dt_max * 1e3:.3f} ms")
    return Crossing(
        bridge=bridge,
        vehicle=vehicle,
        speed=speed,
        bridge_start=bridge_start,
        time=(grid.x - grid.x[0]) / speed,
        position=grid.x,
        vehicle_displacement=states[:, 0],
        vehicle_velocity=states[:, 1],
        bridge_coordinate=states[:, 2],
        bridge_velocity=states[:, 3],
        midspan_displacement=states[:, 2:3] * signs,
        contact_force=contact,
        span_of_step=grid.span_of_step,
        daf=peaks[: bridge.n_spans] / static,
        static_deflection=static,
        dt=grid.dt_max,
        coupled=bool(coupled),
        convective=bool(convective),
        notes=tuple(notes),
    )


@dataclass(frozen=True)
class BatchResult:
    """Summaries of many crossings (no time histories).

    ``daf`` is ``(n, 2)`` (NaN in the second column for one-span bridges);
    ``contact_force_amplification`` the largest contact force on the bridge over the weight;
    ``peak_contact_position`` the station of that force [m]; ``dt`` the largest step [s].
    """

    daf: np.ndarray
    contact_force_amplification: np.ndarray
    peak_contact_position: np.ndarray
    dt: np.ndarray


def _broadcast(args: dict, caller: str) -> tuple[int, dict[str, list]]:
    """Repeat single values to the common length of the list arguments (batch functions)."""
    lengths = {k: len(v) for k, v in args.items() if isinstance(v, list | tuple | np.ndarray)}
    if len(set(lengths.values())) > 1:
        raise ValueError(f"list arguments must have one length; got {lengths}")
    n = next(iter(lengths.values())) if lengths else 1
    if n == 0:
        raise ValueError(f"{caller} needs at least one crossing; got empty lists")
    expanded = {
        k: (list(v) if isinstance(v, list | tuple | np.ndarray) else [v] * n)
        for k, v in args.items()
    }
    return n, expanded


def simulate_many(
    bridges: Bridge | list[Bridge],
    vehicles: Vehicle | list[Vehicle],
    profiles: Profile | list[Profile],
    speeds: float | list[float] | np.ndarray,
    bridge_starts: float | list[float] | np.ndarray,
    coupled: bool | list[bool] = True,
    convective: bool | list[bool] = True,
    dt: float | None = None,
    modes: int | list[int] | np.ndarray = 1,
) -> BatchResult:
    """DAF of many crossings at once, compiled and run in parallel (numba threads).

    Every argument is one value or a list; lists must share one length ``n`` and single
    values are repeated.  Results match :func:`simulate` crossing by crossing.  Any
    ``modes`` above 1 sends the batch to :func:`vbi_lib.modal.simulate_modal_many`.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> b = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    >>> t = vbi.Vehicle.from_frequency(3.0e4, 3.0, 0.1)
    >>> r = vbi.simulate_many(b, t, vbi.Profile.flat(130.0, 0.05), [10.0, 20.0], 100.0)
    >>> r.daf.shape
    (2, 2)
    """
    if np.any(np.asarray(modes) != 1):
        from .modal import simulate_modal_many

        return simulate_modal_many(
            bridges, vehicles, profiles, speeds, bridge_starts, modes, coupled, convective, dt
        )
    args = {
        "bridges": bridges,
        "vehicles": vehicles,
        "profiles": profiles,
        "speeds": speeds,
        "bridge_starts": bridge_starts,
        "coupled": coupled,
        "convective": convective,
    }
    n, expanded = _broadcast(args, "simulate_many")
    xs, es, spans, offsets = [], [], [], [0]
    params = np.empty((n, _N_PARAMS))
    dts = np.empty(n)
    for i in range(n):
        bridge = expanded["bridges"][i]
        vehicle = expanded["vehicles"][i]
        profile = expanded["profiles"][i]
        try:
            speed, start = _check_inputs(
                bridge, vehicle, profile, expanded["speeds"][i], expanded["bridge_starts"][i]
            )
        except ValueError as exc:
            raise ValueError(f"crossing {i}: {exc}") from None
        step = dt
        if step is None:
            step = default_time_step(
                bridge, vehicle, speed, expanded["coupled"][i], expanded["convective"][i]
            )
        grid = _grid(bridge, profile, speed, start, step, start + bridge.length)
        xs.append(grid.x)
        es.append(grid.elevation)
        spans.append(grid.span_of_step)
        offsets.append(offsets[-1] + grid.x.size)
        params[i] = _parameters(bridge, vehicle, speed, start)
        dts[i] = grid.dt_max
    n_spans = np.array([b.n_spans for b in expanded["bridges"]], dtype=np.int64)
    peaks = np.full((n, 4), np.nan)
    _batch_kernel(
        np.asarray(offsets, dtype=np.int64),
        np.concatenate(xs),
        np.concatenate(es),
        np.concatenate(spans),
        params,
        n_spans,
        np.asarray(expanded["coupled"], dtype=np.bool_),
        np.asarray(expanded["convective"], dtype=np.bool_),
        peaks,
    )
    daf = np.full((n, 2), np.nan)
    force = np.empty(n)
    where = np.empty(n)
    for i, bridge in enumerate(expanded["bridges"]):
        static = bridge.static_deflection(expanded["vehicles"][i].weight)
        daf[i, : bridge.n_spans] = peaks[i, : bridge.n_spans] / static
        force[i] = peaks[i, bridge.n_spans] / expanded["vehicles"][i].weight
        where[i] = peaks[i, bridge.n_spans + 1]
    return BatchResult(daf, force, where, dts)


# ---------------------------------------------------------------------------- references
def reference_daf(
    bridge: Bridge,
    vehicle: Vehicle,
    profile: Profile,
    speed: float,
    bridge_start: float,
    coupled: bool = True,
    convective: bool = True,
    rtol: float = 1e-10,
) -> np.ndarray:
    """DAF of each span from ``scipy.integrate.solve_ivp`` (DOP853) at tight tolerance.

    A slow, readable path for checking the compiled kernel: the right-hand side is
    :func:`state_matrices` with the road read by linear interpolation, integrated one profile
    interval at a time (the road's slope, hence the input, jumps at every sample and the
    coefficients switch at the supports), and sampled at nine points per interval for the
    peaks (a sampling error below 2e-5 at 10 Hz and 1 in / 720 in/s intervals).

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> b = vbi.Bridge(20.0, 1, 5e9, 6000.0, damping_ratio=0.0)
    >>> t = vbi.Vehicle.from_frequency(1e4, 3.0, 0.1)
    >>> road = vbi.Profile.flat(30.0, 0.1)
    >>> d = reference_daf(b, t, road, 15.0, 5.0, coupled=False)
    >>> bool(abs(d[0] / vbi.simulate(b, t, road, 15.0, 5.0, coupled=False).daf[0] - 1) < 1e-5)
    True
    """
    from scipy.integrate import solve_ivp

    speed, bridge_start = _check_inputs(bridge, vehicle, profile, speed, bridge_start)
    grid = _grid(bridge, profile, speed, bridge_start, np.inf, bridge_start + bridge.length)
    k = math.pi / bridge.span

    def rhs(t: float, z: np.ndarray, x0: float, e0: float, slope: float, on: bool) -> np.ndarray:
        x = x0 + speed * t
        psi, dpsi = (math.sin(k * (x - bridge_start)), k * math.cos(k * (x - bridge_start)))
        if not on:
            psi = dpsi = 0.0
        A, B, f = state_matrices(bridge, vehicle, speed, psi, dpsi, coupled, convective)
        return A @ z + B @ np.array([e0 + slope * (x - x0), slope * speed]) + f

    z = np.array([grid.elevation[0], 0.0, 0.0, 0.0])
    peaks = np.full(bridge.n_spans, -np.inf)
    for i in range(grid.x.size - 1):
        x0, x1 = grid.x[i], grid.x[i + 1]
        slope = (grid.elevation[i + 1] - grid.elevation[i]) / (x1 - x0)
        span = int(grid.span_of_step[i])
        duration = (x1 - x0) / speed
        sol = solve_ivp(
            rhs,
            (0.0, duration),
            z,
            method="DOP853",
            t_eval=np.linspace(0.0, duration, 9),
            args=(x0, grid.elevation[i], slope, span > 0),
            rtol=rtol,
            atol=1e-14,
        )
        z = sol.y[:, -1]
        if span > 0:
            sign = 1.0 if span == 1 else -1.0
            peaks[span - 1] = max(peaks[span - 1], float(np.max(-sign * sol.y[2])))
    return peaks / bridge.static_deflection(vehicle.weight)


@numba.njit(cache=True)
def _euler_kernel(x, elevation, span_of_step, params, n_spans, coupled, convective, peaks):
    speed = params[_SPEED]
    A = np.empty((4, 4))
    B = np.empty((4, 2))
    f = np.empty(4)
    rate = np.empty(4)
    z = np.zeros(4)
    z[0] = elevation[0]
    for j in range(n_spans):
        peaks[j] = -np.inf
    for k in range(x.shape[0] - 1):
        h = (x[k + 1] - x[k]) / speed
        slope = (elevation[k + 1] - elevation[k]) / (x[k + 1] - x[k])
        span = span_of_step[k]
        psi, dpsi = _shape(x[k], params, span > 0)
        _fill_state_matrices(A, B, f, psi, dpsi, params, coupled, convective)
        _derivative(rate, z, A, B, f, elevation[k], slope * speed)
        for i in range(4):
            z[i] += h * rate[i]
        if span > 0:
            sign = 1.0 if span == 1 else -1.0
            peaks[span - 1] = max(peaks[span - 1], -sign * z[2])


def study_explicit_euler_daf(
    bridge: Bridge,
    vehicle: Vehicle,
    profile: Profile,
    speed: float,
    bridge_start: float,
    coupled: bool = True,
    convective: bool = False,
) -> np.ndarray:
    """DAF by the study's own scheme: forward Euler at one step per profile sample.

    Kept only to show its error (see the model chapter); use :func:`simulate`.  Forward Euler
    multiplies the amplitude of an undamped oscillation by ``sqrt(1 + (omega dt)^2)`` every
    step, so it adds energy and inflates the DAF most on stiff (high-frequency) bridges.
    ``convective=False`` by default, as in the study's code.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> b = vbi.Bridge(12.0, 1, 2e9, 5000.0)
    >>> t = vbi.Vehicle.from_frequency(2e4, 10.0, 0.1)
    >>> road = vbi.Profile.flat(40.0, 0.025)
    >>> euler = study_explicit_euler_daf(b, t, road, 18.0, 20.0)
    >>> bool(euler[0] > vbi.simulate(b, t, road, 18.0, 20.0, convective=False).daf[0])
    True
    """
    speed, bridge_start = _check_inputs(bridge, vehicle, profile, speed, bridge_start)
    grid = _grid(bridge, profile, speed, bridge_start, np.inf, bridge_start + bridge.length)
    peaks = np.empty(bridge.n_spans)
    _euler_kernel(
        grid.x,
        grid.elevation,
        grid.span_of_step,
        _parameters(bridge, vehicle, speed, bridge_start),
        bridge.n_spans,
        bool(coupled),
        bool(convective),
        peaks,
    )
    return peaks / bridge.static_deflection(vehicle.weight)
