r"""The frame every crossing model shares (the part of :func:`vbi_lib.simulate` that never changes).

A crossing model, like a method of ``scipy.integrate.solve_ivp``, supplies only what differs
from one model to the next: its compiled kernel, the default time step it needs and the
static deflection its DAF divides by.  Everything else is here, written once:

* the checks of a crossing's inputs (:func:`check_crossing`);
* the node grid (:func:`node_grid`): the vehicle's position is that of its first axle;
  every profile sample under every axle, every axle's arrival at the bridge ends and the
  interior supports are nodes, so the road under each axle is a straight line within a step
  and the coefficients switch only at nodes; gaps longer than ``speed * dt`` are subdivided
  evenly; each step knows the span each axle is on (any number of spans).  The road under
  a tyre is the profile averaged over its footprint
  (:mod:`vbi_lib.vehicles.footprint`), precomputed once per crossing at the profile's
  stations;
* broadcasting of the batch arguments (:func:`broadcast`);
* the refinement of the midspan peaks inside a step (:func:`downward_peak`, from the cubic
  Hermite interpolant of the displacement and its rate at the step's ends);
* the bookkeeping of the contact force on the bridge (:func:`track_contact`): its largest and
  smallest values and the time the tyre would spend in tension, the check of the study's
  assumption that the tyre never leaves the road; with several axles the worst axle counts
  (its force over its static load), and unilateral tyres add the time in flight.

Every kernel fills one *summary* vector per crossing with the layout of the ``S_*``
constants below, so the driver turns any model's output into a result the same way.  The
summary keeps the midspan peaks of the first :data:`PEAK_SLOTS` spans; the peaks of a bridge
with more spans come from the crossing's histories (:meth:`CrossingModel.span_peaks`,
:func:`history_peaks`), refined the same way.
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
from ..vehicles import Vehicle, VehicleSystem, as_system
from ..vehicles.footprint import footprint_average

#: ``omega * dt`` of the default time step.
DEFAULT_OMEGA_DT = 0.1

# parameter vector every kernel reads first (a model may append its own entries after P_COUNT)
P_MASS, P_STIFFNESS, P_DAMPING, P_GRAVITY, P_SPEED, P_START, P_SPAN = range(7)
P_COUNT = 7

# summary vector of one crossing, filled by every kernel
# (several axles: the contact forces are those of the worst axle, P_a / W_a times the weight)
S_PEAK = 0  #: largest downward midspan deflection of span 1 (S_PEAK + 1: span 2) [m]
PEAK_SLOTS = 2  #: spans whose peaks the summary keeps (the others: from the histories)
S_MAX_FORCE = 2  #: largest contact force on the bridge [N]
S_MAX_AT = 3  #: station where it occurs [m]
S_MIN_FORCE = 4  #: smallest contact force on the bridge [N]
S_TENSION_TIME = 5  #: time on the bridge with a bilateral contact force below zero [s]
S_BRIDGE_TIME = 6  #: time on the bridge (any axle on it) [s]
S_FLIGHT_TIME = 7  #: time on the bridge with a unilateral tyre off the road [s]
SUMMARY_SIZE = 8


# ---------------------------------------------------------------------------- inputs
def check_crossing(
    bridge: Bridge, vehicle: object, profile: Profile, speed: float, bridge_start: float
) -> tuple[float, float]:
    """Check the five inputs every crossing has; return ``speed`` and ``bridge_start`` as floats.

    The whole vehicle starts on the approach (its last axle at the profile's first station,
    its first axle ``wheelbase`` ahead) and the run ends when its last axle leaves the bridge,
    so the profile must reach ``wheelbase`` beyond the bridge.

    Raises
    ------
    TypeError
        ``bridge``, ``vehicle`` or ``profile`` is not a :class:`~vbi_lib.Bridge`, one of the
        library's vehicles (:mod:`vbi_lib.vehicles`) or a :class:`~vbi_lib.Profile`.
    ValueError
        A speed that is not a positive number, a station that is not finite, or a profile that
        does not cover the approach and the bridge.
    """
    if not isinstance(bridge, Bridge):
        raise TypeError(f"bridge must be a vbi.Bridge, got {type(bridge).__name__}")
    wheelbase = as_system(vehicle).wheelbase
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
    tolerance = 1e-9 * max(1.0, abs(end) + wheelbase)
    if wheelbase > 0 and (
        bridge_start - wheelbase < profile.start - tolerance
        or end + wheelbase > profile.end + tolerance
    ):
        raise ValueError(
            f"a vehicle with a wheelbase of {wheelbase:g} m starts wholly on the approach and "
            f"ends with its last axle off the bridge: the profile (stations {profile.start:g} "
            f"to {profile.end:g} m) must run from {bridge_start - wheelbase:g} m or earlier to "
            f"{end + wheelbase:g} m or later with bridge_start={bridge_start:g} m; extend the "
            "profile or move the bridge"
        )
    return speed, bridge_start


def broadcast(args: dict[str, Any], caller: str) -> tuple[int, dict[str, list]]:
    """Repeat single values to the common length of the list arguments of a batch function."""
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


def parameters(
    vehicle: object, speed: float, bridge_start: float, span: float, extra: int = 0
) -> np.ndarray:
    """The kernel's parameter vector: the ``P_*`` entries, then ``extra`` for the model.

    The sprung-mass entries are NaN for vehicles other than :class:`~vbi_lib.Vehicle`
    (their kernels read the vehicle's :class:`~vbi_lib.vehicles.VehicleSystem` instead).
    """
    params = np.zeros(P_COUNT + extra)
    sprung = isinstance(vehicle, Vehicle)
    params[P_MASS] = vehicle.mass if sprung else np.nan
    params[P_STIFFNESS] = vehicle.stiffness if sprung else np.nan
    params[P_DAMPING] = vehicle.damping if sprung else np.nan
    params[P_GRAVITY] = GRAVITY
    params[P_SPEED] = speed
    params[P_START] = bridge_start
    params[P_SPAN] = span
    return params


# ---------------------------------------------------------------------------- grid
@dataclass(frozen=True)
class Grid:
    """Nodes of one crossing: stations [m], road elevations [m] and the span of each step.

    ``x`` is the station of the vehicle's first axle.  ``span_of_step[k]`` is 0 off the
    bridge, else the span (1, 2, ...) the first axle is on from node ``k`` to node ``k + 1``;
    it has one entry per node (the last unused), so that batches slice nodes and steps with
    the same offsets.  ``elevation`` is the road under the first axle; ``road`` and
    ``axle_span``, shape ``(n_axles, n_nodes)``, give them for every axle (the road as its
    tyre sees it).  ``dt_max`` is the longest step [s].
    """

    x: np.ndarray
    elevation: np.ndarray
    span_of_step: np.ndarray
    dt_max: float
    road: np.ndarray
    axle_span: np.ndarray


def node_grid(
    bridge: Bridge,
    profile: Profile,
    speed: float,
    bridge_start: float,
    dt: float,
    stop: float,
    vehicle: VehicleSystem | None = None,
) -> Grid:
    """Nodes from the first axle's start to ``stop``, subdivided to steps of ``speed * dt``.

    The first axle starts ``wheelbase`` after the profile's first station (the last axle on
    it).  Nodes: every profile sample under every axle, the bridge ends and supports under
    every axle.  A gap between two of those points longer than ``speed * dt`` is cut into
    equal steps no longer than that.  ``vehicle`` (a :class:`~vbi_lib.vehicles.VehicleSystem`)
    gives the axles' offsets and footprints; ``None`` is one axle with no footprint.
    """
    offsets = np.zeros(1) if vehicle is None else vehicle.offsets
    footprints = np.zeros(1) if vehicle is None else vehicle.footprint
    first = profile.start + float(offsets.max())
    supports = bridge_start + np.array(bridge.supports)
    if offsets.size == 1:  # one axle: the samples themselves
        shifted, below = profile.x, supports
    else:
        shifted = (profile.x[None, :] + offsets[:, None]).ravel()
        below = (supports[None, :] + offsets[:, None]).ravel()
    inside = shifted[(shifted > first) & (shifted < stop)]
    below = below[below >= first]
    points = np.union1d(np.concatenate(([first], inside, below)), [stop])
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
    seen: dict[float, np.ndarray] = {0.0: profile.elevation}
    span_edges = np.array(bridge.supports)
    road = np.empty((offsets.size, x.size))
    axle_span = np.zeros((offsets.size, x.size), dtype=np.int64)
    for a, (offset, footprint) in enumerate(zip(offsets, footprints, strict=True)):
        if footprint not in seen:
            seen[footprint] = footprint_average(profile.x, profile.elevation, footprint)
        road[a] = np.interp(x - offset, profile.x, seen[footprint])
        middle = 0.5 * (x[:-1] + x[1:]) - offset - bridge_start
        axle_span[a, :-1] = np.where(
            (middle > 0) & (middle < bridge.length),
            np.searchsorted(span_edges, middle, side="right"),
            0,
        )
    dt_max = float((widths.max() if widths.size else 0) / speed)
    return Grid(x, road[0], axle_span[0], dt_max, road, axle_span)


# ---------------------------------------------------------------------------- kernel helpers
@numba.njit(cache=True)
def hermite_min(a0, a1, d0, d1, h):
    """Smallest value inside a step of the cubic Hermite interpolant (values a, rates d).

    The cubic is written in the change ``a1 - a0`` and its stationary points are found with
    the cancellation-free form of the quadratic formula, so the result is as accurate as
    the data when the cubic is nearly a parabola.
    """
    m0 = h * d0
    m1 = h * d1
    rise = a1 - a0
    c3 = m0 + m1 - 2.0 * rise
    c2 = 3.0 * rise - 2.0 * m0 - m1
    c1 = m0
    best = min(a0, a1)
    qa = 3.0 * c3
    qb = 2.0 * c2
    qc = c1
    disc = qb * qb - 4.0 * qa * qc
    if disc < 0.0:
        return best
    q = -0.5 * (qb + math.copysign(math.sqrt(disc), qb))
    for k in range(2):
        if k == 0:
            if qa == 0.0:
                continue
            t = q / qa
        else:
            if q == 0.0:
                continue
            t = qc / q
        if 0.0 < t < 1.0:
            best = min(best, a0 + ((c3 * t + c2) * t + c1) * t)
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
    summary[S_FLIGHT_TIME] = 0.0


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
    """Keep the largest downward midspan deflection of ``span`` (1-based; spans beyond
    :data:`PEAK_SLOTS` are left to :func:`history_peaks`)."""
    if span <= PEAK_SLOTS and peak > summary[S_PEAK + span - 1]:
        summary[S_PEAK + span - 1] = peak


@numba.njit(cache=True)
def history_peaks(midspan, midspan_rate, x, speed, span_of_step, peaks):
    """Largest downward midspan deflection of every span while the wheel is on it, from
    histories at the nodes (``midspan``, ``midspan_rate``: ``(n_nodes, n_spans)``), refined
    inside each step as the kernels do (:func:`downward_peak`); into ``peaks``."""
    for j in range(peaks.shape[0]):
        peaks[j] = -np.inf
    for k in range(x.shape[0] - 1):
        span = span_of_step[k]
        if span > 0:
            j = span - 1
            h = (x[k + 1] - x[k]) / speed
            peak = downward_peak(
                midspan[k, j], midspan[k + 1, j], midspan_rate[k, j], midspan_rate[k + 1, j], h
            )
            if peak > peaks[j]:
                peaks[j] = peak


# ---------------------------------------------------------------------------- models
class CrossingModel:
    """What a crossing model supplies to the shared driver (scipy's ``OdeSolver`` pattern).

    A subclass sets the class attributes and implements the four methods; the driver
    (:func:`vbi_lib.simulate`, :func:`vbi_lib.simulate_many`) does everything else.  One
    instance describes one crossing's model inputs, already checked by the driver.

    Attributes
    ----------
    name
        The key of the model in :data:`vbi_lib.models.driver.MODELS`.
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
        vehicle: object,
        speed: float,
        bridge_start: float,
        *,
        coupled: bool,
        convective: bool,
        modes: int | None,
    ) -> None:
        self.bridge = bridge
        self.vehicle = vehicle
        self.system = as_system(vehicle)
        self.speed = speed
        self.bridge_start = bridge_start
        self.coupled = coupled
        self.convective = convective

    def default_time_step(self) -> tuple[float, str]:
        """The largest step [s] the model takes by default, and a note saying why."""
        raise NotImplementedError

    def static_deflection(self) -> float:
        """The static midspan deflection the DAF divides by [m].

        The largest midspan deflection under the vehicle's static axle loads crawling across
        the bridge (the study's definition for reference models), as the model computes it.
        """
        raise NotImplementedError

    def span_static_deflections(self) -> np.ndarray:
        """The static deflection each span's DAF divides by [m], ``(n_spans,)``.

        By default :meth:`static_deflection` for every span; a model for layouts whose spans
        differ gives each span its own.
        """
        return np.full(self.bridge.n_spans, self.static_deflection())

    def span_peaks(self, summary: np.ndarray, fields: dict[str, Any], grid: Grid) -> np.ndarray:
        """Largest downward midspan deflection of each span while the wheel is on it [m].

        From the summary for up to :data:`PEAK_SLOTS` spans; a model that runs bridges with
        more spans overrides this to take them from its histories (:func:`history_peaks`).
        """
        if self.bridge.n_spans > PEAK_SLOTS:
            raise NotImplementedError(
                f"{type(self).__name__} keeps the peaks of {PEAK_SLOTS} spans only"
            )
        return summary[S_PEAK : S_PEAK + self.bridge.n_spans].copy()

    def integrate(self, grid: Grid) -> tuple[np.ndarray, np.ndarray, dict[str, Any], str]:
        """Run one crossing over ``grid`` keeping its histories.

        Returns the summary vector, the contact force of every axle at every node
        ``(n_nodes, n_axles)`` [N], the model's own result fields (including
        ``dof_displacement``, ``dof_velocity`` ``(n_nodes, n_dofs)`` and
        ``midspan_displacement``) and a note on the steps taken.
        """
        raise NotImplementedError

    @classmethod
    def integrate_many(cls, models: list[CrossingModel], grids: list[Grid]) -> np.ndarray:
        """Summaries ``(n, SUMMARY_SIZE)`` of many crossings, no histories kept."""
        raise NotImplementedError
