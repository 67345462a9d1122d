r"""A vehicle-only predictor of dynamic amplification: the contact force on a rigid road.

**Contact-force amplification** (:func:`contact_force_amplification`).  The study's
vehicle-only metric: the truck (a sprung mass) rides the profile on a rigid road, its contact
force is weighted by a half sine over each span (the span's midspan influence line shape), and
the peak is divided by the weight (:eq:`eq-roads-window` in the book).  The sprung mass is
driven by a piecewise-linear road, so it too is stepped exactly with a matrix exponential.

The study weighed it in its chapter 14 against the DAF of the full model (Figure 2.14.3).
"""

from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np
import scipy.linalg

from . import _validation as check
from .profiles import Profile
from .vehicles import Vehicle
from .vehicles.footprint import footprint_average

__all__ = ["ContactForceAmplification", "contact_force_amplification", "quarter_car_contact_force"]


@dataclass(frozen=True, eq=False)
class ContactForceAmplification:
    """The study's vehicle-only metric for one crossing (chapter 14).

    Attributes
    ----------
    amplification
        Per span, the largest ``R(t) sin(pi xi / L)`` over the vehicle's weight while the
        vehicle is on that span (``xi`` its distance from the span's start); with
        ``dynamic_only=True`` the dynamic part ``F = R - W`` is windowed instead.
    peak_position
        Station of each span's peak [m].
    position, time, contact_force
        Wheel station [m], time from the start [s] and contact force ``R = W + F`` [N] at
        every profile sample up to the end of the bridge (force just after the station).
    weight
        Vehicle weight ``W`` [N].
    """

    amplification: np.ndarray
    peak_position: np.ndarray
    position: np.ndarray
    time: np.ndarray
    contact_force: np.ndarray
    weight: float
    dynamic_only: bool = False

    @property
    def peak(self) -> float:
        """Largest amplification over the spans."""
        return float(self.amplification.max())

    def __repr__(self) -> str:
        values = ", ".join(f"{a:.3f}" for a in self.amplification)
        kind = "dynamic part" if self.dynamic_only else "contact force"
        return f"ContactForceAmplification(windowed {kind} / weight per span: {values})"


def quarter_car_contact_force(
    profile: Profile, vehicle: Vehicle, speed: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Contact force of a sprung mass riding ``profile`` on a rigid road (decoupled model, 92).

    The book writes the decoupled force as :eq:`study-92`.
    ``m u'' = F``, ``F = k (Delta - u) + c (Delta' - u')`` with the profile linear between
    samples, so over each step the input rate is constant and the step is exact:
    the augmented state ``(u, u', Delta, Delta')`` is advanced with ``exp(M h)``.  The mass
    starts at rest on the first sample (``u = Delta(x0)``).  ``Delta`` is the road the
    vehicle's footprint sees (:func:`~vbi_lib.vehicles.footprint.footprint_average`; the
    study's point contact, footprint 0, rides the samples).

    Returns
    -------
    time [s], force_after, force_before
        At every sample: ``F`` [N] with the road rate of the step that starts there
        (``force_after``, the last sample uses the step that ends there) and with the rate of
        the step that ends there (``force_before``; the first sample uses the one starting).
    """
    speed = check.positive("speed", speed)
    m, k, c = vehicle.mass, vehicle.stiffness, vehicle.damping
    x = profile.x
    delta = footprint_average(x, profile.elevation, vehicle.footprint)
    h = np.diff(x) / speed
    rate = np.diff(delta) / h
    system = np.array(
        [
            [0.0, 1.0, 0.0, 0.0],
            [-k / m, -c / m, k / m, c / m],
            [0.0, 0.0, 0.0, 1.0],
            [0.0, 0.0, 0.0, 0.0],
        ]
    )
    keys = np.round(h / h.max(), 9)
    unique, which = np.unique(keys, return_inverse=True)
    transitions = np.stack([scipy.linalg.expm(system * (u * h.max())) for u in unique])
    u = np.empty(x.size)
    v = np.empty(x.size)
    u[0], v[0] = delta[0], 0.0
    _sdof_kernel(transitions, which.astype(np.int64), delta, rate, u, v)
    after_rate = np.append(rate, rate[-1])
    before_rate = np.insert(rate, 0, rate[0])
    spring = k * (delta - u) - c * v
    time = np.concatenate(([0.0], np.cumsum(h)))
    return time, spring + c * after_rate, spring + c * before_rate


@numba.njit(cache=True)
def _sdof_kernel(transitions, which, delta, rate, u, v):
    for i in range(rate.size):
        t = transitions[which[i]]
        a, b, d, r = u[i], v[i], delta[i], rate[i]
        u[i + 1] = t[0, 0] * a + t[0, 1] * b + t[0, 2] * d + t[0, 3] * r
        v[i + 1] = t[1, 0] * a + t[1, 1] * b + t[1, 2] * d + t[1, 3] * r


def contact_force_amplification(
    profile: Profile,
    vehicle: Vehicle,
    speed: float,
    bridge_start: float,
    span: float,
    n_spans: int = 1,
    dynamic_only: bool = False,
) -> ContactForceAmplification:
    """The study's vehicle-only roughness metric (chapter 14), per span.

    The truck rides the profile on a rigid road from ``profile.x[0]`` (at rest), see
    :func:`quarter_car_contact_force`.  While it is on span ``j`` its contact force
    ``R = W + F`` is multiplied by the half sine ``sin(pi xi / span)`` (``xi`` its distance
    into the span: the shape of the span's midspan influence line); the largest value over the
    weight ``W`` is that span's amplification.  A smooth road gives 1.  With
    ``dynamic_only=True`` only ``F`` is windowed (a smooth road gives 0).

    Parameters
    ----------
    profile, vehicle
        The road and the sprung mass.
    speed
        Vehicle speed [m/s].
    bridge_start
        Station of the first support [m].
    span
        Span length [m].
    n_spans
        Number of equal spans (any whole number >= 1).
    dynamic_only
        Window the dynamic force ``F`` instead of ``R``.

    Examples
    --------
    >>> from vbi_lib import units as u
    >>> truck = Vehicle.from_frequency(200 * u.slinch, 2.8, 0.2)
    >>> road = Profile.flat(500 * u.ft, 1 * u.inch)
    >>> contact_force_amplification(road, truck, 720 * u.inch, 320 * u.ft, 100 * u.ft)
    ContactForceAmplification(windowed contact force / weight per span: 1.000)
    """
    speed = check.positive("speed", speed)
    span = check.positive("span", span)
    bridge_start = check.finite("bridge_start", bridge_start)
    n_spans = check.integer("n_spans", n_spans, low=1)
    end = bridge_start + n_spans * span
    if not (profile.start <= bridge_start and end <= profile.end):
        raise ValueError(
            f"the bridge [{bridge_start:g}, {end:g}] m must lie on the profile "
            f"[{profile.start:g}, {profile.end:g}] m"
        )
    supports = bridge_start + span * np.arange(n_spans + 1)
    midspans = supports[:-1] + 0.5 * span
    x = np.concatenate((profile.x[profile.x < end], supports, midspans))
    x = np.unique(x[(x >= profile.start) & (x <= end)])
    road = Profile(x, profile.elevation_at(x), name=profile.name)
    time, after, before = quarter_car_contact_force(road, vehicle, speed)
    weight = vehicle.weight
    force = np.maximum(after, before)
    if not dynamic_only:
        force = force + weight
    amplification = np.empty(n_spans)
    where = np.empty(n_spans)
    for j in range(n_spans):
        on = (x >= supports[j]) & (x <= supports[j + 1])
        windowed = force[on] * np.sin(np.pi * (x[on] - supports[j]) / span)
        best = int(np.argmax(windowed))
        amplification[j] = windowed[best] / weight
        where[j] = x[on][best]
    return ContactForceAmplification(
        amplification=amplification,
        peak_position=where,
        position=x,
        time=time,
        contact_force=weight + after,
        weight=weight,
        dynamic_only=bool(dynamic_only),
    )
