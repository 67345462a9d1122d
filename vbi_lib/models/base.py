r"""The frame every crossing model shares (the part of :func:`vbi_lib.simulate` that never changes).

A crossing model, like a method of ``scipy.integrate.solve_ivp``, supplies only what differs
from one model to the next: its compiled kernel, the default time step it needs and the
static deflection its DAF divides by.  Everything else is here, written once:

* the checks of a crossing's inputs (:func:`check_crossing`);
* the node grid (:func:`~vbi_lib.models.grid.node_grid`, compiled): every profile sample,
  the bridge ends and the interior supports are nodes, so the road is a straight line within
  a step and the coefficients switch only at nodes; gaps longer than ``speed * dt`` are
  subdivided evenly;
* the checked inputs of a batch (:class:`Batch`) and what a model does with one
  (:meth:`CrossingModel.integrate_many` and friends, with fallbacks that take one crossing
  at a time);
* the refinement of the midspan peaks inside a step (:func:`downward_peak`, from the cubic
  Hermite interpolant of the displacement and its rate at the step's ends);
* the bookkeeping of the contact force on the bridge (:func:`track_contact`): its largest and
  smallest values and the time the tyre would spend in tension, the check of the study's
  assumption that the tyre never leaves the road.

Every kernel fills one *summary* vector per crossing with the layout of the ``S_*``
constants below, so the driver turns any model's output into a result the same way.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numba
import numpy as np

from .. import _validation as check
from ..bridges import Bridge
from ..profiles import Profile
from ..units import g as GRAVITY
from ..vehicles import Vehicle
from .grid import Grid, node_grid

__all__ = ["Batch", "CrossingModel", "Grid", "check_crossing", "node_grid"]

#: ``omega * dt`` of the default time step.
DEFAULT_OMEGA_DT = 0.1

# parameter vector every kernel reads first (a model may append its own entries after P_COUNT)
P_MASS, P_STIFFNESS, P_DAMPING, P_GRAVITY, P_SPEED, P_START, P_SPAN = range(7)
P_COUNT = 7

# summary vector of one crossing, filled by every kernel
S_PEAK = 0  #: largest downward midspan deflection of span 1 (S_PEAK + 1: span 2) [m]
S_MAX_FORCE = 2  #: largest contact force on the bridge [N]
S_MAX_AT = 3  #: station where it occurs [m]
S_MIN_FORCE = 4  #: smallest contact force on the bridge [N]
S_TENSION_TIME = 5  #: time on the bridge with the contact force below zero [s]
S_BRIDGE_TIME = 6  #: time on the bridge [s]
SUMMARY_SIZE = 7


# ---------------------------------------------------------------------------- inputs
def check_crossing(
    bridge: Bridge, vehicle: Vehicle, profile: Profile, speed: float, bridge_start: float
) -> tuple[float, float]:
    """Check the five inputs every crossing has; return ``speed`` and ``bridge_start`` as floats.

    Raises
    ------
    TypeError
        ``bridge``, ``vehicle`` or ``profile`` is not a :class:`~vbi_lib.Bridge`,
        :class:`~vbi_lib.Vehicle` or :class:`~vbi_lib.Profile`.
    ValueError
        A speed that is not a positive number, a station that is not finite, or a profile that
        does not cover the approach and the bridge.
    """
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


@dataclass(frozen=True, eq=False)
class Batch:
    """The checked inputs of ``n`` crossings, one array entry per crossing.

    Objects shared by crossings are stored once: crossing ``i`` has the bridge
    ``bridges[bridge[i]]``, the vehicle ``vehicles[vehicle[i]]`` and the road
    ``profiles[profile[i]]``.  ``modes[i]`` is the model's checked ``modes`` option, 0 for a
    model that takes none.  Built by :func:`vbi_lib.simulate_many`.
    """

    bridges: tuple[Bridge, ...]
    vehicles: tuple[Any, ...]
    profiles: tuple[Profile, ...]
    bridge: np.ndarray
    vehicle: np.ndarray
    profile: np.ndarray
    speed: np.ndarray
    bridge_start: np.ndarray
    coupled: np.ndarray
    convective: np.ndarray
    modes: np.ndarray

    def __len__(self) -> int:
        return int(self.speed.size)

    def column(self, objects: str, attribute: str) -> np.ndarray:
        """An attribute of each crossing's bridge or vehicle, e.g. ``column("bridges", "span")``."""
        values = np.array([getattr(obj, attribute) for obj in getattr(self, objects)])
        return values[getattr(self, objects[:-1])]

    @staticmethod
    def groups(*keys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Distinct rows of the key columns: one crossing of each, and each crossing's row.

        Returns ``(first, inverse)``: ``first[k]`` is a crossing with the ``k``-th distinct
        combination of keys, and crossing ``i`` has combination ``inverse[i]``.
        """
        order = np.lexsort(keys[::-1])
        change = np.zeros(order.size, dtype=bool)
        change[0] = True
        for key in keys:
            ordered = key[order]
            change[1:] |= ordered[1:] != ordered[:-1]
        label = np.cumsum(change) - 1
        inverse = np.empty(order.size, np.int64)
        inverse[order] = label
        return order[change], inverse

    def plain_vehicles(self) -> bool:
        """Whether every vehicle is the study's sprung mass (the lane kernels take only those)."""
        return all(type(v) is Vehicle for v in self.vehicles)

    def crossing(self, i: int) -> tuple[Bridge, Any, Profile, float, float, dict[str, Any]]:
        """Crossing ``i``'s bridge, vehicle, road, speed, bridge start and model options."""
        modes = int(self.modes[i]) if self.modes[i] else None
        options = {"coupled": bool(self.coupled[i]), "convective": bool(self.convective[i]),
                   "modes": modes}  # fmt: skip
        return (self.bridges[self.bridge[i]], self.vehicles[self.vehicle[i]],
                self.profiles[self.profile[i]], float(self.speed[i]),
                float(self.bridge_start[i]), options)  # fmt: skip


def parameters(
    vehicle: Vehicle, speed: float, bridge_start: float, span: float, extra: int = 0
) -> np.ndarray:
    """The kernel's parameter vector: the ``P_*`` entries, then ``extra`` for the model."""
    params = np.zeros(P_COUNT + extra)
    params[P_MASS] = vehicle.mass
    params[P_STIFFNESS] = vehicle.stiffness
    params[P_DAMPING] = vehicle.damping
    params[P_GRAVITY] = GRAVITY
    params[P_SPEED] = speed
    params[P_START] = bridge_start
    params[P_SPAN] = span
    return params


# ---------------------------------------------------------------------------- kernel helpers
@numba.njit(cache=True)
def hermite_min(a0, a1, d0, d1, h):
    """Smallest value inside a step of the cubic Hermite interpolant (values a, rates d)."""
    m0 = h * d0
    m1 = h * d1
    c3 = 2.0 * a0 + m0 - 2.0 * a1 + m1
    c2 = -3.0 * a0 - 2.0 * m0 + 3.0 * a1 - m1
    c1 = m0
    best = min(a0, a1)
    qa = 3.0 * c3
    qb = 2.0 * c2
    qc = c1
    if abs(qa) < 1e-300:
        if abs(qb) > 1e-300:
            t = -qc / qb
            if 0.0 < t < 1.0:
                best = min(best, ((c3 * t + c2) * t + c1) * t + a0)
        return best
    disc = qb * qb - 4.0 * qa * qc
    if disc < 0.0:
        return best
    # the roots without cancellation (qa may be rounding noise: the textbook formula then
    # loses the root inside the step): q = -(qb + sign(qb) sqrt(disc)) / 2, t = q/qa, qc/q
    root = math.sqrt(disc)
    q = -0.5 * (qb + root) if qb >= 0.0 else -0.5 * (qb - root)
    for t in (q / qa, qc / q if q != 0.0 else -1.0):
        if 0.0 < t < 1.0:
            best = min(best, ((c3 * t + c2) * t + c1) * t + a0)
    return best


@numba.njit(cache=True)
def downward_peak(m0, m1, v0, v1, h):
    """Largest downward midspan deflection within a step (displacements positive up).

    ``m0, m1`` are the displacements and ``v0, v1`` their rates at the ends of a step of
    ``h`` seconds; where the rate changes sign the extreme inside the step comes from the
    cubic Hermite interpolant.
    """
    if v0 * v1 <= 0.0:
        return -hermite_min(m0, m1, v0, v1, h)
    return max(-m0, -m1)


@numba.njit(cache=True)
def start_summary(summary, n_spans):
    """Reset a summary vector before a crossing."""
    for j in range(2):
        summary[S_PEAK + j] = -np.inf if j < n_spans else np.nan
    summary[S_MAX_FORCE] = -np.inf
    summary[S_MAX_AT] = np.nan
    summary[S_MIN_FORCE] = np.inf
    summary[S_TENSION_TIME] = 0.0
    summary[S_BRIDGE_TIME] = 0.0


@numba.njit(cache=True)
def track_contact(summary, force, x, h):
    """Account the contact force ``force`` [N] at station ``x`` held for ``h`` seconds."""
    if force > summary[S_MAX_FORCE]:
        summary[S_MAX_FORCE] = force
        summary[S_MAX_AT] = x
    if force < summary[S_MIN_FORCE]:
        summary[S_MIN_FORCE] = force
    summary[S_BRIDGE_TIME] += h
    if force < 0.0:
        summary[S_TENSION_TIME] += h


@numba.njit(cache=True)
def track_peak(summary, span, peak):
    """Keep the largest downward midspan deflection of ``span`` (1-based)."""
    if peak > summary[S_PEAK + span - 1]:
        summary[S_PEAK + span - 1] = peak


# ---------------------------------------------------------------------------- models
class CrossingModel:
    """What a crossing model supplies to the shared driver (scipy's ``OdeSolver`` pattern).

    A subclass sets the class attributes and implements the four methods; the driver
    (:func:`vbi_lib.simulate`, :func:`vbi_lib.simulate_many`) does everything else.  One
    instance describes one crossing's model inputs, already checked by the driver.

    Attributes
    ----------
    name
        The key of the model in :data:`vbi_lib.models.MODELS`.
    description
        One line for listings: the bridge model and the integrator.
    result_type
        The :class:`~vbi_lib.models.results.Crossing` subclass the driver returns.
    """

    name: ClassVar[str]
    description: ClassVar[str]
    result_type: ClassVar[type]

    def __init__(
        self,
        bridge: Bridge,
        vehicle: Vehicle,
        speed: float,
        bridge_start: float,
        *,
        coupled: bool,
        convective: bool,
        modes: int | None,
    ) -> None:
        self.bridge = bridge
        self.vehicle = vehicle
        self.speed = speed
        self.bridge_start = bridge_start
        self.coupled = coupled
        self.convective = convective

    def default_time_step(self) -> tuple[float, str]:
        """The largest step [s] the model takes by default, and a note saying why."""
        raise NotImplementedError

    def static_deflection(self) -> float:
        """The static midspan deflection under the vehicle's weight that the DAF divides by [m]."""
        raise NotImplementedError

    def integrate(self, grid: Grid) -> tuple[np.ndarray, np.ndarray, dict[str, Any], str]:
        """Run one crossing over ``grid`` keeping its histories.

        Returns the summary vector, the contact force at every node [N], the model's own
        result fields (including ``vehicle_displacement``, ``vehicle_velocity`` and
        ``midspan_displacement``) and a note on the steps taken.
        """
        raise NotImplementedError

    # ------------------------------------------------------------------ batches
    @classmethod
    def check_modes(cls, modes: object) -> int:
        """The ``modes`` option checked; 0 for a model that takes none (``modes=None``)."""
        if modes is not None:
            raise ValueError(f"modes={modes!r}: model={cls.name!r} takes no modes option")
        return 0

    @classmethod
    def one_of(cls, batch: Batch, i: int) -> CrossingModel:
        """The model of crossing ``i`` of a batch."""
        bridge, vehicle, _, speed, start, options = batch.crossing(i)
        return cls(bridge, vehicle, speed, start, **options)

    @classmethod
    def default_time_steps(cls, batch: Batch) -> np.ndarray:
        """Largest default step of each crossing of a batch [s], ``(n,)``.

        This fallback asks one crossing at a time; models override it with array code.
        """
        return np.array([cls.one_of(batch, i).default_time_step()[0] for i in range(len(batch))])

    @classmethod
    def static_deflections(cls, batch: Batch) -> np.ndarray:
        """The static deflection each crossing's DAF divides by [m], ``(n,)`` (fallback: a loop)."""
        return np.array([cls.one_of(batch, i).static_deflection() for i in range(len(batch))])

    @classmethod
    def integrate_many(cls, batch: Batch, dt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Summaries ``(n, SUMMARY_SIZE)`` and largest steps ``(n,)`` [s] of a batch.

        ``dt`` is each crossing's largest step [s].  This fallback runs one crossing at a time
        through :meth:`integrate` (any vehicle the model's kernel takes); models override it
        with their lane kernels.
        """
        n = len(batch)
        summaries = np.empty((n, SUMMARY_SIZE))
        steps = np.empty(n)
        for i in range(n):
            bridge, _, road, speed, start, _ = batch.crossing(i)
            grid = node_grid(bridge, road, speed, start, float(dt[i]), start + bridge.length)
            summaries[i] = cls.one_of(batch, i).integrate(grid)[0]
            steps[i] = grid.dt_max
        return summaries, steps
