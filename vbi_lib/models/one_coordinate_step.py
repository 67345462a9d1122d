r"""The default step of the one-coordinate model: the largest eigenvalue modulus of ``A``.

The model's default step is ``DEFAULT_OMEGA_DT / omega_max``, ``omega_max`` the largest
eigenvalue modulus of the state matrix ``A`` (51)-(58) at five wheel positions.  The
eigenvalues of ``A`` are the roots of the characteristic quartic of the two-degree-of-freedom
system, :math:`\det(\lambda^2 M + \lambda C + K) = 0`,

.. math::
    (m_v\lambda^2 + c_v\lambda + k_v)\,(m^*\lambda^2 + (c^* + \psi\gamma)\lambda
    + k^* + \psi\kappa) - \psi(\gamma\lambda + \kappa)(c_v\lambda + k_v) = 0,

with :math:`\kappa = k_v\psi + \epsilon c_v v\psi'` and :math:`\gamma = c_v\psi` (both zero
when decoupled).  Compiled code finds them by Aberth's simultaneous iteration from the roots
of the two uncoupled factors (about a microsecond each; the eigenvalues of the quartic's
companion matrix, through LAPACK, if the iteration has not settled), one function for one
crossing and for a batch, so both get the same step: :func:`sprung_mass_omega` (one
crossing, remembered) and :func:`sprung_mass_time_steps` (a batch).  Other vehicles take the
eigenvalues of their state matrices
(:func:`~vbi_lib.models.one_coordinate.highest_circular_frequency`).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numba
import numpy as np

from ..bridges import Bridge
from ..vehicles import Vehicle
from .base import DEFAULT_OMEGA_DT
from .batch import Batch

#: Columns of a row of coefficients: the truck, the bridge's generalised coordinate, the
#: speed and the span.
C_MV, C_KV, C_CV, C_MB, C_KB, C_CB, C_SPEED, C_SPAN = range(8)
COEFFICIENTS = 8
#: Wheel positions where the step looks at ``A``: ``psi = 0, 1/4, ..., 1``.
STEP_POSITIONS = 5


@numba.njit(cache=True)
def _quadratic_roots(a, b, c):
    """Both roots of ``a x^2 + b x + c`` (complex), without cancellation."""
    disc = complex(b * b - 4.0 * a * c)
    root = np.sqrt(disc)
    q = -0.5 * (b + root) if b >= 0.0 else -0.5 * (b - root)
    if q == 0.0:
        return 0j, 0j
    return q / a, c / q


@numba.njit(cache=True)
def largest_root_modulus(row, psi, dpsi, coupled, convective):
    """Largest eigenvalue modulus of ``A`` at one wheel position [rad/s].

    ``row`` holds the coefficients (``C_*`` columns); ``psi`` and ``dpsi`` the shape function
    and its slope at the wheel.
    """
    m_v = row[C_MV]
    k_v = row[C_KV]
    c_v = row[C_CV]
    m_b = row[C_MB]
    kz = 0.0
    cz = 0.0
    if coupled:
        kz = k_v * psi + (c_v * row[C_SPEED] * dpsi if convective else 0.0)
        cz = c_v * psi
    b1 = row[C_CB] + psi * cz
    b0 = row[C_KB] + psi * kz
    lead = m_v * m_b
    coef = np.empty(5)  # monic quartic, highest power first
    coef[0] = 1.0
    coef[1] = (m_v * b1 + c_v * m_b) / lead
    coef[2] = (m_v * b0 + c_v * b1 + k_v * m_b - psi * cz * c_v) / lead
    coef[3] = (c_v * b0 + k_v * b1 - psi * (cz * k_v + kz * c_v)) / lead
    coef[4] = (k_v * b0 - psi * kz * k_v) / lead
    z = np.empty(4, np.complex128)
    z[0], z[1] = _quadratic_roots(m_v, c_v, k_v)
    z[2], z[3] = _quadratic_roots(m_b, b1, b0)
    scale = abs(coef[4]) ** 0.25 + 1e-300
    for i in range(4):  # distinct starts (the uncoupled roots may coincide)
        z[i] = z[i] * (1.0 + 1e-3 * (i + 1)) + 1e-3 * scale * complex(0.5 * i, 1.0)
    for _ in range(60):
        largest_change = 0.0
        for i in range(4):
            p = complex(coef[0])
            dp = 0j
            for k in range(1, 5):
                dp = dp * z[i] + p
                p = p * z[i] + coef[k]
            ratio = p / dp if dp != 0 else 0j
            pull = 0j
            for j in range(4):
                if j != i:
                    pull += 1.0 / (z[i] - z[j])
            change = ratio / (1.0 - ratio * pull)
            z[i] -= change
            largest_change = max(largest_change, abs(change) / (abs(z[i]) + 1e-300))
        if largest_change < 1e-15:
            if np.isfinite(z).all():
                return np.abs(z).max()
            break
    companion = np.zeros((4, 4), np.complex128)
    for k in range(4):
        companion[0, k] = -coef[k + 1]
    for k in range(3):
        companion[k + 1, k] = 1.0
    return np.abs(np.linalg.eigvals(companion)).max()


@numba.njit(cache=True)
def _omega_max_row(row, coupled, convective):
    """Largest eigenvalue modulus of ``A`` over the wheel positions [rad/s].

    ``psi = i / 4`` (i = 0..4) with the slope of the half sine there,
    ``(pi/L) sqrt(1 - psi^2)``.
    """
    largest = 0.0
    for i in range(STEP_POSITIONS):
        psi = i / (STEP_POSITIONS - 1.0)
        dpsi = math.pi / row[C_SPAN] * math.sqrt(max(0.0, 1.0 - psi**2))
        largest = max(largest, largest_root_modulus(row, psi, dpsi, coupled, convective))
    return largest


@numba.njit(cache=True)
def omega_max(rows, coupled, convective):
    """:func:`_omega_max_row` of each row of coefficients [rad/s] (one or a few crossings)."""
    out = np.empty(rows.shape[0])
    for i in range(rows.shape[0]):
        out[i] = _omega_max_row(rows[i], coupled[i], convective[i])
    return out


@numba.njit(cache=True, parallel=True)
def omega_max_threads(rows, coupled, convective):
    """:func:`omega_max` on numba's threads (many crossings; the same numbers)."""
    out = np.empty(rows.shape[0])
    for i in numba.prange(rows.shape[0]):
        out[i] = _omega_max_row(rows[i], coupled[i], convective[i])
    return out


# ---------------------------------------------------------------------------- crossings
def _speed_matters(vehicle: Vehicle, coupled: bool, convective: bool) -> bool:
    """Whether ``A`` depends on the speed: only through the damper's convective term."""
    return coupled and convective and vehicle.damping != 0.0


@lru_cache(maxsize=4096)
def _omega_of(
    bridge: Bridge, vehicle: Vehicle, speed: float, coupled: bool, convective: bool
) -> float:
    row = np.empty((1, COEFFICIENTS))
    row[0, C_MV], row[0, C_KV], row[0, C_CV] = vehicle.mass, vehicle.stiffness, vehicle.damping
    row[0, C_MB] = bridge.generalized_mass
    row[0, C_KB] = bridge.generalized_stiffness
    row[0, C_CB] = bridge.generalized_damping
    row[0, C_SPEED], row[0, C_SPAN] = speed, bridge.span
    return float(omega_max(row, np.array([coupled]), np.array([convective]))[0])


def sprung_mass_omega(
    bridge: Bridge, vehicle: Vehicle, speed: float, coupled: bool, convective: bool
) -> float:
    """``omega_max`` of the study's sprung mass on the one-coordinate beam [rad/s].

    Remembered for each bridge, vehicle and options, and speed where the damper's
    convective term makes ``A`` depend on it.
    """
    if not _speed_matters(vehicle, coupled, convective):
        speed = 0.0  # A is the same at every speed: one entry serves them all
    return _omega_of(bridge, vehicle, float(speed), bool(coupled), bool(convective))


def _step_rows(batch: Batch, rows: np.ndarray, speed: np.ndarray) -> np.ndarray:
    """The coefficients (``C_*``) of the crossings ``rows`` at ``speed``."""
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


def sprung_mass_time_steps(batch: Batch) -> np.ndarray:
    """The default step of every crossing of a batch of sprung masses [s], ``(n,)``.

    ``DEFAULT_OMEGA_DT / omega_max``, ``omega_max`` found once per distinct bridge, vehicle,
    options and (where it matters) speed: through :func:`sprung_mass_omega` for a few, in
    compiled code for many (on numba's threads for thousands).
    """
    damped = np.array([x.damping != 0.0 for x in batch.vehicles])[batch.vehicle]
    speed = np.where(batch.coupled & batch.convective & damped, batch.speed, 0.0)
    first, inverse = batch.groups(batch.bridge, batch.vehicle, batch.coupled,
                                  batch.convective, speed)  # fmt: skip
    coupled, convective = batch.coupled[first], batch.convective[first]
    if first.size <= 64:
        omega = np.array([sprung_mass_omega(batch.bridges[batch.bridge[i]],
                                            batch.vehicles[batch.vehicle[i]], speed[i],
                                            batch.coupled[i], batch.convective[i])
                          for i in first])  # fmt: skip
    else:  # ~4 us a row: threads only when their wake-up (ms on a busy machine) is worth it
        solve = omega_max_threads if first.size > 4096 else omega_max
        omega = solve(_step_rows(batch, first, speed[first]), coupled, convective)
    return DEFAULT_OMEGA_DT / omega[inverse]
