"""The road a report's vehicle needs before the bridge: how fast its start-up motion decays.

The vehicle starts at rest in static equilibrium; on a rough approach its slowest free
motion, decaying as ``exp(-r t)`` (:func:`decay_rate`), must fall to :data:`DECAY` before it
reaches the bridge (:func:`approach_length`).  Used by :mod:`.inputs`, which re-exports it.
"""

from __future__ import annotations

import math

import numpy as np

from ..vehicles import Vehicle, as_system

__all__ = ["DECAY", "MIN_APPROACH", "approach_length", "decay_rate"]

#: Fraction of the start-up motion left when the vehicle reaches the bridge.
DECAY = 0.01
#: Shortest approach [m].
MIN_APPROACH = 10.0


def decay_rate(vehicle: object) -> float:
    """Rate [1/s] at which the vehicle's slowest free motion on a rigid road decays.

    For the study's sprung mass the slower root of ``s^2 + 2 zeta_v omega_v s + omega_v^2``:
    ``zeta_v omega_v`` up to critical damping, ``(zeta_v - sqrt(zeta_v^2 - 1)) omega_v``
    above it (an overdamped suspension creeps back slowly, the more slowly the more it is
    damped); for any other vehicle the smallest ``-Re(lambda)`` of its system (every contact
    on, tyres included).

    >>> import warnings
    >>> with warnings.catch_warnings():  # VBI-2D's verification vehicle, damped 2.09 critical
    ...     warnings.simplefilter("ignore")
    ...     overdamped = Vehicle(5750.0, 1595e3, 4e5)
    >>> round(decay_rate(overdamped), 2)  # zeta omega would say 34.78
    4.25
    """
    if isinstance(vehicle, Vehicle):
        zeta, omega = vehicle.damping_ratio, vehicle.circular_frequency
        if zeta <= 1.0:
            return zeta * omega
        return (zeta - math.sqrt(zeta * zeta - 1.0)) * omega
    system = as_system(vehicle)
    n = system.n_dofs
    damping = system.damping + system.contact.T @ (system.contact_damping[:, None] * system.contact)
    inverse = system.mass_inverse
    state = np.block(
        [[np.zeros((n, n)), np.eye(n)], [-inverse @ system.road_stiffness, -inverse @ damping]]
    )
    return float(np.min(-np.linalg.eigvals(state).real))


def approach_length(vehicle: object, speed: float) -> float:
    """Road needed for the vehicle's start-up motion to decay to :data:`DECAY` at ``speed`` [m].

    ``speed * ln(1 / DECAY) / rate`` (:func:`decay_rate`), at least :data:`MIN_APPROACH`.

    >>> truck = Vehicle.from_frequency(35000.0, 2.5, 0.10)
    >>> round(approach_length(truck, 30.0), 1)
    88.0
    """
    return max(MIN_APPROACH, speed * math.log(1.0 / DECAY) / decay_rate(vehicle))
