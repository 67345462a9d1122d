r"""The frame every crossing model shares (the part of :func:`vbi_lib.simulate` that never changes).

A crossing model, like a method of ``scipy.integrate.solve_ivp``, supplies only what differs
from one model to the next: its compiled kernel, the default time step it needs and the
static deflection its DAF divides by.  Everything else is here, written once:

* the checks of a crossing's inputs (:func:`check_crossing`);
* the node grid (:func:`~vbi_lib.models.grid.node_grid`): the vehicle's position is that of
  its first axle; every profile sample under every axle, every axle's arrival at the bridge
  ends and the interior supports are nodes, so the road under each axle is a straight line
  within a step and the coefficients switch only at nodes; gaps longer than
  ``speed * dt`` are subdivided evenly; each step knows the span each axle is on (any
  number of spans).  The road under a tyre is the profile averaged over its footprint
  (:mod:`vbi_lib.vehicles.footprint`);
* what a model does with a batch's checked inputs (:class:`~vbi_lib.models.batch.Batch`;
  :meth:`CrossingModel.integrate_many` and friends): the study's sprung mass on one or two
  spans goes to the model's lane kernel (:mod:`~vbi_lib.models.lanes`), every other
  crossing to fallbacks that build one model and one grid per crossing;
* the refinement of the midspan peaks inside a step (:func:`downward_peak`, from the cubic
  Hermite interpolant of the displacement and its rate at the step's ends);
* the bookkeeping of the contact force on the bridge (:func:`track_contact`): its largest and
  smallest values and the time the tyre would spend in tension, the check of the study's
  assumption that the tyre never leaves the road; with several axles the worst axle counts
  (its force over its static load), and unilateral tyres add the time in flight.

Every kernel fills one *summary* vector per crossing with the layout of the ``S_*``
constants below, so the driver turns any model's output into a result the same way.  The
summary keeps the midspan peaks of the first :data:`PEAK_SLOTS` spans for the batches; a
single crossing takes every span's peak from its histories (:meth:`CrossingModel.span_peaks`,
:func:`history_peaks`), refined the same way.

**The span DAF, one definition.**  The DAF of span ``j`` is the largest downward displacement
of its midspan over the whole run (the vehicle starts on the approach and the run ends when
its last axle leaves the bridge, plus ``free_vibration``), divided by the largest downward
static displacement of the same midspan under the same vehicle's static axle loads, all
axles in every position of the group, by the same model's statics
(:mod:`~vbi_lib.models.statics`).  Every kernel and :func:`history_peaks` track every span's
midspan at every step, whichever span the axles are on.
"""

from __future__ import annotations

import math
import weakref
from typing import Any, ClassVar

import numba
import numpy as np

from .. import _validation as check
from ..bridges import Bridge
from ..profiles import Profile
from ..ranges import check_range, outside_note
from ..road_checks import crossing_road_notes
from ..units import g as GRAVITY
from ..vehicles import Vehicle, VehicleSystem, as_system
from .batch import PEAK_SLOTS, Batch
from .grid import Grid, node_grid
from .statics import span_statics

__all__ = ["CrossingModel", "Grid", "check_crossing", "node_grid"]

#: ``omega * dt`` of the default time step.
DEFAULT_OMEGA_DT = 0.1

# parameter vector every kernel reads first (a model may append its own entries after P_COUNT)
P_MASS, P_STIFFNESS, P_DAMPING, P_GRAVITY, P_SPEED, P_START, P_SPAN = range(7)
P_COUNT = 7

# summary vector of one crossing, filled by every kernel
# (several axles: the contact forces are those of the worst axle, P_a / W_a times the weight)
S_PEAK = 0  #: largest downward midspan deflection of span 1 (S_PEAK + 1: span 2) [m]
# PEAK_SLOTS (from .batch): spans whose peaks the summary keeps (the others: from histories)
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
        library's vehicles (:mod:`vbi_lib.vehicles`) or a :class:`~vbi_lib.Profile`; a speed
        or station that is not a number.
    ValueError
        A speed outside its hard range (:data:`vbi_lib.ranges.RANGES`, ``speed``), a station
        that is not finite, or a profile that does not cover the approach and the bridge.
    """
    check.instance("bridge", bridge, Bridge, "a vbi.Bridge")
    wheelbase = as_system(vehicle).wheelbase
    check.instance("profile", profile, Profile, "a vbi.Profile")
    speed = check_range("speed", speed, warn=False)  # the crossing notes and warns
    bridge_start = check.finite("bridge_start", bridge_start)
    end = bridge_start + bridge.length
    if bridge_start < profile.start or end > profile.end + 1e-9 * max(1.0, abs(end)):
        first = min(profile.start, bridge_start)
        raise ValueError(
            f"the profile (stations {profile.start:g} to {profile.end:g} m) does not cover the "
            f"approach and the bridge (stations {first:g} to {end:g} m with "
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


def check_step(dt_max: float, default_dt: float, dt: float | None, hard: float) -> str | None:
    """Check the largest step taken against the model's default ``0.1 / omega_max``.

    ``omega_max dt`` beyond ``hard`` (the model's :attr:`CrossingModel.max_omega_dt`) is
    refused; beyond the soft limit of ``step_accuracy`` (:data:`vbi_lib.ranges.RANGES`), the
    sentence for the notes is returned.

    Raises
    ------
    ValueError
        A step so long that the model's integrator is unstable.
    """
    ratio = DEFAULT_OMEGA_DT * dt_max / default_dt
    if ratio > hard:
        longest = hard * default_dt / DEFAULT_OMEGA_DT
        raise ValueError(
            f"dt={dt!r} must give omega_max dt of at most {hard:g} (the model's integrator is "
            f"unstable beyond); its steps of up to {dt_max:.3g} s give {ratio:.3g}: give "
            f"dt <= {longest:.3g} s or leave it to the model (dt=None)"
        )
    return outside_note("step_accuracy", ratio, f"omega_max dt (dt={dt!r} s)")


def input_notes(
    bridge: Bridge, system: VehicleSystem, profile: Profile, speed: float, default_dt: float
) -> tuple[list[str], list[str]]:
    """Sentences on inputs outside their intended (soft) ranges, for a crossing's notes.

    Returns the sentences on the bridge and the vehicle (their constructors warned already:
    the span, mass, damping and first frequency, and every note of the vehicle,
    :attr:`~vbi_lib.vehicles.VehicleSystem.notes`) and those on the crossing itself (the
    speed, and the profile's sampling against the study's rule (32): at least two samples
    per period of the highest frequency the model follows, ``omega_max = 0.1 / dt_default``,
    at this speed; a road that is a straight line is exact at any spacing).  A road given
    as data that is not a plausible road (:func:`vbi_lib.road_checks.road_notes`) is in the
    first list when it was warned of already (when read), else in the second.
    """
    objects = [
        *(outside_note("span", length, "span") for length in sorted(set(bridge.spans))),
        outside_note("mass_per_length", bridge.mass_per_length),
        outside_note("bridge_frequency", bridge.first_frequency_hz, "first_frequency_hz"),
        outside_note("bridge_damping_ratio", bridge.damping_ratio, "damping_ratio"),
        *system.notes,  # h23: all the vehicle's constructors warned of (vbi_lib.vehicles)
    ]
    noted, fresh = crossing_road_notes(profile)  # h23: the road (vbi_lib.road_checks)
    objects += noted
    crossing = [outside_note("speed", speed), *fresh]
    spacing = _uneven_spacing(profile)
    if spacing is not None:
        f_max = DEFAULT_OMEGA_DT / default_dt / (2.0 * math.pi)
        crossing.append(
            outside_note(
                "sample_spacing",
                spacing * 2.0 * f_max / speed,
                f"profile spacing {spacing:.3g} m x 2 x {f_max:.3g} Hz / speed",
            )
        )
    return [n for n in objects if n], [n for n in crossing if n]


_SPACINGS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _uneven_spacing(profile: Profile) -> float | None:
    """The largest sample interval of a road that is not a straight line [m], else ``None``
    (once per profile while it lives: a batch shares its roads)."""
    if profile not in _SPACINGS:
        spacing = None
        if profile.x.size > 2:
            slopes = np.diff(profile.elevation) / np.diff(profile.x)
            if np.ptp(slopes) > 1e-9 * max(1e-12, float(np.abs(slopes).max())):
                spacing = float(np.diff(profile.x).max())
        _SPACINGS[profile] = spacing
    return _SPACINGS[profile]


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
def history_peaks(midspan, midspan_rate, step_rate, x, speed, peaks):
    """Largest downward midspan deflection of every span over the whole run, from histories
    at the nodes (``midspan``, ``midspan_rate``: ``(n_nodes, n_spans)``), refined inside each
    step as the kernels do (:func:`downward_peak`); into ``peaks``.  ``step_rate[k]`` is
    added to both end rates of step ``k`` (a part of the displacement known only by its
    secant over the step; zeros if none)."""
    for j in range(peaks.shape[0]):
        peaks[j] = -np.inf
    for k in range(x.shape[0] - 1):
        h = (x[k + 1] - x[k]) / speed
        if h <= 0.0:
            continue
        for j in range(peaks.shape[0]):
            extra = step_rate[k, j]
            peak = downward_peak(midspan[k, j], midspan[k + 1, j], midspan_rate[k, j] + extra,
                                 midspan_rate[k + 1, j] + extra, h)  # fmt: skip
            if peak > peaks[j]:
                peaks[j] = peak


def peaks_of(value: np.ndarray, rate: np.ndarray, step_rate: np.ndarray, x: np.ndarray,
             speed: float) -> np.ndarray:  # fmt: skip
    """:func:`history_peaks` of histories ``(n_nodes, n_spans)``: the peaks ``(n_spans,)`` [m]."""
    peaks = np.empty(value.shape[1])
    history_peaks(np.ascontiguousarray(value), np.ascontiguousarray(rate),
                  np.ascontiguousarray(step_rate), x, speed, peaks)  # fmt: skip
    return peaks


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
    max_omega_dt
        The largest ``omega_max dt`` the integrator tolerates (an explicit scheme's stability
        limit, with a margin); ``inf`` for an unconditionally stable one.  The driver refuses
        longer steps (:func:`check_step`).
    statics
        The statics every span DAF of the model divides by (:data:`~vbi_lib.models.statics.KINDS`):
        ``"one-shape"`` for a model that bends the beam in one shape, ``"exact"`` for one whose
        headline displacement converges to the exact beam's.
    """

    max_omega_dt: ClassVar[float] = math.inf
    statics: ClassVar[str] = "exact"
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
        """The largest of :meth:`span_static_deflections` [m]."""
        return float(np.max(self.span_static_deflections()))

    def span_static_deflections(self) -> np.ndarray:
        """The static deflection each span's DAF divides by [m], ``(n_spans,)``.

        The largest downward static deflection of each midspan under the vehicle's static
        axle loads, all axles in every position of the group, by the model's own statics
        (:attr:`statics`; :func:`~vbi_lib.models.statics.span_statics`).
        """
        return span_statics(self.bridge, self.system, self.statics)

    def midspan_history(self, fields: dict[str, Any], grid: Grid) -> tuple[np.ndarray, ...]:
        """The headline displacement of every midspan at the nodes [m] (up positive), its
        rate [m/s] and a rate added over each step [m/s], each ``(n_nodes, n_spans)``: what
        a span's DAF reads (:func:`history_peaks`)."""
        raise NotImplementedError

    #: Whether the kernels' summaries hold the span peaks (of the first :data:`PEAK_SLOTS`
    #: spans, tracked at every step and sub-step); else they come from the histories.
    summary_peaks: ClassVar[bool] = True

    def span_peaks(self, summary: np.ndarray, history: tuple, grid: Grid) -> np.ndarray:
        """Largest downward midspan deflection of each span over the whole run [m].

        ``history`` is :meth:`midspan_history`'s.  The kernels track every midspan at every
        step, whichever span the axles are on, for the first :data:`PEAK_SLOTS` spans
        (:attr:`summary_peaks`); otherwise the peaks come from ``history``
        (:func:`history_peaks`), refined the same way.
        """
        if self.summary_peaks and self.bridge.n_spans <= PEAK_SLOTS:
            return summary[S_PEAK : S_PEAK + self.bridge.n_spans].copy()
        return peaks_of(*history, grid.x, self.speed)

    def checks(
        self, fields: dict[str, Any], grid: Grid, daf: np.ndarray
    ) -> tuple[list, list, dict]:
        """The model's own checks of a crossing: sentences for ``notes``, sentences the
        driver also warns of (:class:`~vbi_lib.validity.TruncationWarning`), and extra
        result fields.  None by default."""
        return [], [], {}

    def integrate(self, grid: Grid) -> tuple[np.ndarray, np.ndarray, dict[str, Any], str]:
        """Run one crossing over ``grid`` keeping its histories.

        Returns the summary vector, the contact force of every axle at every node
        ``(n_nodes, n_axles)`` [N], the model's own result fields (including
        ``dof_displacement``, ``dof_velocity`` ``(n_nodes, n_dofs)`` and
        ``midspan_displacement``) and a note on the steps taken.
        """
        raise NotImplementedError

    # ------------------------------------------------------------------ batches
    #: The model's lane kernel, ``run(batch, dt) -> (summaries, dt_max)``, for the crossings
    #: of :meth:`~vbi_lib.models.batch.Batch.lane_rows`; ``None``: every crossing takes the
    #: fallbacks.
    lane_kernel: ClassVar[Any] = None

    @classmethod
    def check_modes(cls, modes: object) -> int:
        """The ``modes`` option checked; 0 for a model that takes none (``modes=None``)."""
        if modes is not None:
            raise ValueError(f"modes={modes!r}: model={cls.name!r} takes no modes option")
        return 0

    @classmethod
    def resolve_modes(cls, batch: Batch) -> Batch:
        """The batch with each crossing's ``modes`` as the model runs it (unchanged by default)."""
        return batch

    @classmethod
    def batch_notes(cls, batch: Batch) -> list[str]:
        """Sentences on the model's own approximations in a batch (none by default); the
        driver warns of them with :class:`~vbi_lib.validity.TruncationWarning`."""
        return []

    @classmethod
    def check_bridge(cls, bridge: Bridge) -> None:
        """Refuse a layout of spans the model cannot run (by default it runs any)."""

    @classmethod
    def one_of(cls, batch: Batch, i: int) -> CrossingModel:
        """The model of crossing ``i`` of a batch."""
        bridge, vehicle, _, speed, start, options = batch.crossing(i)
        return cls(bridge, vehicle, speed, start, **options)

    @classmethod
    def default_time_steps(cls, batch: Batch) -> np.ndarray:
        """Largest default step of each crossing of a batch [s], ``(n,)``.

        This fallback asks one crossing of each distinct bridge, vehicle, options and speed;
        models override it with array code.
        """
        first, inverse = batch.groups(batch.bridge, batch.vehicle, batch.modes, batch.coupled,
                                      batch.convective, batch.speed)  # fmt: skip
        steps = np.array([cls.one_of(batch, int(i)).default_time_step()[0] for i in first])
        return steps[inverse]

    @classmethod
    def span_static_deflections_of(cls, batch: Batch) -> np.ndarray:
        """Each crossing's :meth:`span_static_deflections` [m], ``(n, max(2, n_spans))``.

        NaN beyond a crossing's spans; computed once per distinct bridge and vehicle.
        """
        first, inverse = batch.groups(batch.bridge, batch.vehicle)
        out = np.full((first.size, max(PEAK_SLOTS, int(batch.n_spans().max()))), np.nan)
        for k, i in enumerate(first):
            bridge = batch.bridges[batch.bridge[i]]
            system = as_system(batch.vehicles[batch.vehicle[i]])
            values = span_statics(bridge, system, cls.statics)
            out[k, : values.size] = values
        return out[inverse]

    @classmethod
    def integrate_many(cls, batch: Batch, dt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Summaries ``(n, SUMMARY_SIZE)`` and largest steps ``(n,)`` [s] of a batch.

        ``dt`` is each crossing's largest step [s].  The crossings of
        :meth:`~vbi_lib.models.batch.Batch.lane_rows` run on the model's :attr:`lane_kernel`;
        the others get one model and one grid each and go to :meth:`integrate_setups`.  Bridges
        with more spans than :data:`PEAK_SLOTS` are the driver's (one crossing at a time, with
        histories).
        """
        n = len(batch)
        lanes = batch.lane_rows() if cls.lane_kernel is not None else np.zeros(n, dtype=bool)
        if lanes.all():
            return cls.lane_kernel(batch, dt)
        summaries = np.full((n, SUMMARY_SIZE), np.nan)
        steps = np.full(n, np.nan)
        if lanes.any():
            summaries[lanes], steps[lanes] = cls.lane_kernel(batch.take(lanes), dt[lanes])
        models, grids = cls.models_and_grids(batch, dt, np.flatnonzero(~lanes))
        summaries[~lanes] = cls.integrate_setups(models, grids)
        steps[~lanes] = [g.dt_max for g in grids]
        return summaries, steps

    @classmethod
    def models_and_grids(
        cls, batch: Batch, dt: np.ndarray, rows: np.ndarray
    ) -> tuple[list[CrossingModel], list[Grid]]:
        """One model and one grid of each crossing ``rows`` (equal grids built once)."""
        models, grids = [], []
        cache: dict = {}
        for i in rows:
            model = cls.one_of(batch, int(i))
            system = model.system
            key = (int(batch.profile[i]), model.bridge.supports, model.speed,
                   model.bridge_start, float(dt[i]), tuple(system.offsets),
                   tuple(system.footprint))  # fmt: skip
            if key not in cache:
                stop = model.bridge_start + model.bridge.length + system.wheelbase
                cache[key] = node_grid(model.bridge, batch.profiles[batch.profile[i]],
                                       model.speed, model.bridge_start, float(dt[i]), stop,
                                       vehicle=system)  # fmt: skip
            models.append(model)
            grids.append(cache[key])
        return models, grids

    @classmethod
    def integrate_setups(cls, models: list[CrossingModel], grids: list[Grid]) -> np.ndarray:
        """Summaries ``(n, SUMMARY_SIZE)`` of crossings given as models and grids (no
        histories kept): the model's kernel for any vehicle, in parallel."""
        raise NotImplementedError
