"""One driver for every crossing model: :func:`simulate` and :func:`simulate_many`.

The model is looked up by name in :data:`MODELS` (as ``solve_ivp`` looks up its ``METHODS``);
the driver checks the inputs, builds the node grid, calls the model's kernel and assembles
the result, the same way for every model.
"""

from __future__ import annotations

import math
import warnings
from typing import Any

import numpy as np

from .. import _validation as check
from ..bridges import Bridge
from ..costs import warn_crossing
from ..profiles import Profile
from ..ranges import MAX_NODES, RANGES, check_range, warn_outside
from ..road_checks import past_the_road, road_notes
from ..validity import ContactLossWarning, UnresolvedRoadWarning, contact_note, flight_note
from ..vehicles import as_system
from ..vehicles.footprint import unresolved_road_note, warn_unresolved_roads
from .base import (
    DEFAULT_OMEGA_DT,
    PEAK_SLOTS,
    S_BRIDGE_TIME,
    S_FLIGHT_TIME,
    S_MAX_AT,
    S_MAX_FORCE,
    S_MIN_FORCE,
    S_PEAK,
    S_TENSION_TIME,
    SUMMARY_SIZE,
    CrossingModel,
    _uneven_spacing,
    check_crossing,
    check_step,
    input_notes,
    node_grid,
)
from .batch import Batch
from .modal import Modal
from .one_coordinate import OneCoordinate
from .results import BatchResult, Crossing

#: The crossing models by name.
MODELS: dict[str, type[CrossingModel]] = {
    OneCoordinate.name: OneCoordinate,
    Modal.name: Modal,
}


def _model(model: object) -> type[CrossingModel]:
    if isinstance(model, type) and issubclass(model, CrossingModel):
        return model
    if not isinstance(model, str):
        raise TypeError(f"model={model!r} must be the name of a crossing model ({list(MODELS)})")
    if model not in MODELS:
        listing = "; ".join(f"{k!r}: {v.description}" for k, v in MODELS.items())
        raise ValueError(f"model={model!r} is not a crossing model; use one of {listing}")
    return MODELS[model]


def _modes(modes: object) -> int | None:
    """``None``, or a number of modes: an int within the range of ``modes``."""
    if modes is None:
        return None
    return int(check_range("modes", check.integer("modes", modes), warn=False))


def _never_pushed_down(peaks: np.ndarray) -> np.ndarray:
    """Spans whose midspan never went down while the vehicle was on them (peak <= 0)."""
    return ~(peaks > 0.0) & ~np.isnan(peaks)


def _contact(summary: np.ndarray, weight: float, unilateral: object = False) -> tuple:
    """Smallest contact force over the weight, fractions of the time in tension and in flight.

    The flight time is read only for vehicles with a unilateral contact (``unilateral``).
    """
    bridge_time = summary[..., S_BRIDGE_TIME]
    if summary.ndim == 1:  # one crossing: plain numbers
        on = bridge_time > 0

        def fraction(column: int) -> float:
            return float(summary[column] / bridge_time) if on else 0.0

    else:

        def fraction(column: int) -> np.ndarray:
            return np.divide(
                summary[:, column],
                bridge_time,
                out=np.zeros_like(bridge_time),
                where=bridge_time > 0,
            )

    flight = np.where(unilateral, fraction(S_FLIGHT_TIME), 0.0)
    return summary[..., S_MIN_FORCE] / weight, fraction(S_TENSION_TIME), flight


def simulate(
    bridge: Bridge,
    vehicle: object,
    profile: Profile,
    speed: float,
    bridge_start: float,
    *,
    model: str = "one-coordinate",
    modes: int | None = None,
    coupled: bool = True,
    convective: bool = True,
    dt: float | None = None,
    free_vibration: float = 0.0,
) -> Crossing:
    """Simulate one crossing of a vehicle over a bridge.

    The vehicle starts with its last axle at ``profile.x[0]``, at rest in static equilibrium,
    drives at constant ``speed`` and the run ends when its last axle leaves the bridge (plus
    ``free_vibration`` seconds).  Positions in the result are those of its first axle.

    Parameters
    ----------
    bridge, profile
        The beam and the road (stations and elevations in metres).
    vehicle
        Any vehicle of :mod:`vbi_lib.vehicles`: the study's sprung mass
        (:class:`~vbi_lib.Vehicle`), a :class:`~vbi_lib.QuarterCar`, a multi-axle truck,
        a :class:`~vbi_lib.vehicles.Convoy` or a :class:`~vbi_lib.vehicles.VehicleSystem`.
    speed
        Vehicle speed [m/s].
    bridge_start
        Station of the first support [m]; the bridge spans
        ``[bridge_start, bridge_start + bridge.length]``.
    model
        A key of :data:`MODELS`: ``"one-coordinate"`` (default), the study's model (33)-(99),
        RK4, one span or two equal spans; ``"modal"``, the first ``modes`` exact beam modes
        of any layout of spans (:meth:`~vbi_lib.Bridge.continuous`), Newmark average
        acceleration.
    modes
        Number of beam modes, for ``model="modal"`` only.
    coupled
        ``False`` for the decoupled model (92)-(99): the contact force ignores the bridge.
    convective
        Keep the ``v psi' z_b`` term in the wheel's vertical velocity (``False`` is the
        study's code).
    dt
        Largest time step [s]; ``None`` lets the model pick it (and at least one step per
        profile sample).  The step used is ``Crossing.dt`` and is noted in ``notes``.
    free_vibration
        Seconds to continue after the truck leaves the bridge.

    Returns
    -------
    Crossing
        The model's subclass of :class:`~vbi_lib.models.results.Crossing`; its
        ``moment_at``, ``shear_at``, ``displacement_at`` and ``sections`` give the responses
        at any section.  The DAF of a span the vehicle never pushed down (its midspan only
        rose while the vehicle was on it) is NaN, and ``notes`` says so.

    Raises
    ------
    TypeError, ValueError
        Inputs of the wrong type or outside what is allowed, named in the message: the hard
        ranges of :data:`vbi_lib.ranges.RANGES` (``speed``, ``modes``, ``step_accuracy``),
        and more than :data:`~vbi_lib.ranges.MAX_NODES` nodes, counted before anything is
        allocated.

    Warns
    -----
    OutsideValidityWarning
        The speed, the profile's sampling (the study's rule (32)) or the step outside their
        intended ranges; the sentence is also in ``notes``, with those on the bridge and the
        vehicle (which their constructors warned of).
    ContactLossWarning
        A bilateral contact force became tensile on the bridge: the result is outside the
        model's validity (also in ``notes`` and ``lost_contact``).  A unilateral tyre that
        leaves the road is modelled, not a loss of validity: it is stated in ``notes`` and
        ``flight_fraction``, without a warning.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> from vbi_lib import units as u
    >>> bridge = vbi.Bridge(100 * u.ft, 1, 7.5e12 * u.lbf * u.inch**2, 4.6 * u.kip / u.ft / u.g)
    >>> truck = vbi.Vehicle.from_frequency(100 * u.slinch, 4.0, 0.10)
    >>> road = vbi.Profile.flat(450 * u.ft, 1 * u.inch)
    >>> vbi.simulate(bridge, truck, road, 720 * u.inch / u.s, 320 * u.ft).daf.round(2)
    array([1.04])
    >>> run = vbi.simulate(bridge, truck, road, 720 * u.inch, 320 * u.ft, model="modal", modes=5)
    >>> run.daf.round(2)
    array([1.04])
    """
    kind = _model(model)
    system = as_system(vehicle)
    speed, bridge_start = check_crossing(bridge, vehicle, profile, speed, bridge_start)
    coupled = check.flag("coupled", coupled)
    convective = check.flag("convective", convective)
    free_vibration = check.non_negative("free_vibration", free_vibration)
    modes = _modes(modes)
    given = None if dt is None else check.positive("dt", dt)
    setup = kind(bridge, vehicle, speed, bridge_start, coupled=coupled, convective=convective,
                 modes=modes)  # fmt: skip
    default, note = setup.default_time_step()
    notes = [note] if given is None else []
    dt = default if given is None else given
    stop = bridge_start + bridge.length + system.wheelbase + speed * free_vibration
    grid = node_grid(bridge, profile, speed, bridge_start, dt, stop, vehicle=system)
    notes += past_the_road(profile, stop, free_vibration, speed)  # h23 (road_checks)
    warn_crossing(kind.name, grid.x.size, getattr(setup, "count", modes), system.n_axles)  # h23
    objects, outside = input_notes(bridge, system, profile, speed, default)
    step_note = check_step(grid.dt_max, default, given, kind.max_omega_dt)
    outside += [step_note] if step_note else []
    for text in outside:
        warn_outside(text)
    summary, contact, fields, note = setup.integrate(grid)
    notes += [note, *objects, *outside]
    road_note = unresolved_road_note(system, profile, speed, bridge_start, bridge.length)
    if road_note:  # issue 20 hook (h20): a contact force set by the road's sampling
        notes.append(road_note)
        warnings.warn(road_note, UnresolvedRoadWarning, stacklevel=2)
    static = setup.static_deflection()
    peaks = setup.span_peaks(summary, fields, grid)
    never = _never_pushed_down(peaks)
    for j in np.flatnonzero(never):
        notes.append(
            f"span {j + 1} was never pushed down while the vehicle was on it (its midspan only "
            "rose): its DAF is not defined and is NaN"
        )
    min_ratio, tension, flight = _contact(summary, system.weight, system.has_unilateral)
    if flight > 0:
        notes.append(flight_note(float(flight)))
    if min_ratio < 0:
        text = contact_note(float(min_ratio), float(tension))
        notes.append(text)
        warnings.warn(text, ContactLossWarning, stacklevel=2)
    return kind.result_type(
        model=kind.name,
        bridge=bridge,
        vehicle=vehicle,
        speed=speed,
        bridge_start=bridge_start,
        time=(grid.x - grid.x[0]) / speed,
        position=grid.x,
        vehicle_displacement=fields["dof_displacement"][:, 0],
        vehicle_velocity=fields["dof_velocity"][:, 0],
        contact_force=contact.sum(axis=1),
        axle_contact_force=contact,
        span_of_step=grid.span_of_step,
        daf=np.where(never, np.nan, peaks) / setup.span_static_deflections(),
        static_deflection=static,
        dt=grid.dt_max,
        coupled=coupled,
        convective=convective,
        min_contact_force_ratio=float(min_ratio),
        tension_fraction=float(tension),
        flight_fraction=float(flight),
        notes=tuple(notes),
        **fields,
    )


def _is_list(value: object) -> bool:
    return isinstance(value, list | tuple | np.ndarray)


def _as_list(name: str, value: object) -> object:
    """A pandas Series or Index as its array; other iterables that are not a list, tuple or
    array (a set, a generator, a dict) refused by name: they have no order to trust."""
    if _is_list(value):
        return value
    to_numpy = getattr(value, "to_numpy", None)
    if callable(to_numpy) and hasattr(value, "__len__"):
        return to_numpy()
    if isinstance(value, set | frozenset | dict) or hasattr(value, "__next__"):
        raise TypeError(
            f"{name} must be one value or a list, tuple or array of them, not a "
            f"{type(value).__name__}; pass list({name}) or a numpy array"
        )
    return value


def _factorize(values: object, n: int) -> tuple[np.ndarray, tuple]:
    """Codes and the distinct objects (by identity) of a list, or of one repeated value."""
    if not _is_list(values):
        return np.zeros(n, np.int64), (values,)
    codes = np.empty(n, np.int64)
    seen: dict[int, int] = {}
    distinct = []
    for i, obj in enumerate(values):
        code = seen.get(id(obj))
        if code is None:
            code = seen[id(obj)] = len(distinct)
            distinct.append(obj)
        codes[i] = code
    return codes, tuple(distinct)


def _numbers(values: object, n: int) -> np.ndarray:
    """Floats of a list (or one repeated value); entries that are not numbers become NaN."""
    if isinstance(values, np.ndarray) and values.dtype.kind in "fiu" and values.ndim == 1:
        return values.astype(float)
    items = values if _is_list(values) else [values]
    out = np.full(len(items), np.nan)
    for i, value in enumerate(items):
        if isinstance(value, int | float | np.integer | np.floating) and not isinstance(
            value, bool | np.bool_
        ):
            out[i] = value
    return out if _is_list(values) else np.full(n, out[0])


def _flags(name: str, values: object, n: int) -> np.ndarray:
    if isinstance(values, np.ndarray) and values.dtype == np.bool_ and values.ndim == 1:
        return values.copy()
    if not _is_list(values):
        return np.full(n, check.flag(name, values))
    out = np.empty(n, dtype=bool)
    for i, value in enumerate(values):
        try:
            out[i] = check.flag(name, value)
        except TypeError as exc:
            raise TypeError(f"crossing {i}: {exc}") from None
    return out


def _batch_modes(kind: type[CrossingModel], values: object, n: int) -> np.ndarray:
    """Each crossing's ``modes``, checked as :func:`simulate` checks it (range, then model)."""
    if not _is_list(values):
        return np.full(n, kind.check_modes(_modes(values)), np.int64)
    out = np.empty(n, np.int64)
    for i, value in enumerate(values):
        try:
            out[i] = kind.check_modes(_modes(value))
        except (TypeError, ValueError) as exc:
            raise type(exc)(f"crossing {i}: {exc}") from None
    return out


def _one_crossing(args: dict[str, Any], i: int) -> tuple[float, float]:
    """:func:`check_crossing` of crossing ``i``, its message prefixed with the crossing."""
    values = [args[k][i] if _is_list(args[k]) else args[k]
              for k in ("bridges", "vehicles", "profiles", "speeds", "bridge_starts")]  # fmt: skip
    try:
        return check_crossing(*values)
    except (TypeError, ValueError) as exc:
        raise type(exc)(f"crossing {i}: {exc}") from None


def _wheelbase(vehicle: object) -> float:
    """A vehicle's wheelbase [m]; NaN for an object that is not one of the library's vehicles."""
    try:
        return as_system(vehicle).wheelbase
    except TypeError:
        return math.nan


def _batch(kind: type[CrossingModel], args: dict[str, Any]) -> Batch:
    """Check the arguments of :func:`simulate_many` as arrays; errors name the crossing.

    The arrays find the crossings that may fail :func:`check_crossing` (or the model's
    layout check); those alone are checked one at a time, whose message is raised.
    """
    lengths = {k: len(v) for k, v in args.items() if _is_list(v)}
    if len(set(lengths.values())) > 1:
        raise ValueError(f"list arguments must have one length; got {lengths}")
    n = next(iter(lengths.values())) if lengths else 1
    if n == 0:
        raise ValueError("simulate_many needs at least one crossing; got empty lists")
    b, bridges = _factorize(args["bridges"], n)
    v, vehicles = _factorize(args["vehicles"], n)
    p, profiles = _factorize(args["profiles"], n)
    speed = _numbers(args["speeds"], n)
    start = _numbers(args["bridge_starts"], n)
    # where the arrays see a problem, one crossing's checks name it (or accept the value)
    wheelbase = np.array([_wheelbase(x) for x in vehicles])
    suspects = np.isnan(wheelbase)[v]
    for codes, objects, kind_ in ((b, bridges, Bridge), (p, profiles, Profile)):
        wrong = [k for k, obj in enumerate(objects) if not isinstance(obj, kind_)]
        suspects |= np.isin(codes, wrong)
    low, high = RANGES["speed"].hard
    suspects |= ~(np.isfinite(speed) & (speed > low) & (speed <= high)) | ~np.isfinite(start)
    for i in np.flatnonzero(suspects):
        speed[i], start[i] = _one_crossing(args, int(i))
    # the profile covers the approach, the bridge and (several axles) the wheelbase beyond
    wheelbase = wheelbase[v]
    end = start + np.array([x.length for x in bridges])[b]
    first = np.array([x.start for x in profiles])[p]
    last = np.array([x.end for x in profiles])[p]
    short = (start < first) | (end > last + 1e-9 * np.maximum(1.0, np.abs(end)))
    slack = 1e-9 * np.maximum(1.0, np.abs(end) + wheelbase)
    short |= (wheelbase > 0) & ((start - wheelbase < first - slack)
                                | (end + wheelbase > last + slack))  # fmt: skip
    for i in np.flatnonzero(short):
        _one_crossing(args, int(i))
    for k, bridge in enumerate(bridges):
        try:
            kind.check_bridge(bridge)
        except ValueError as exc:
            raise ValueError(f"crossing {int(np.argmax(b == k))}: {exc}") from None
    return Batch(
        bridges=bridges,
        vehicles=vehicles,
        profiles=profiles,
        bridge=b,
        vehicle=v,
        profile=p,
        speed=speed,
        bridge_start=start,
        coupled=_flags("coupled", args["coupled"], n),
        convective=_flags("convective", args["convective"], n),
        modes=_batch_modes(kind, args["modes"], n),
    )


def _crossing_notes(kind: type[CrossingModel], batch: Batch, i: int, dt: float | None) -> list[str]:
    """:func:`simulate`'s checks of crossing ``i`` on its grid (node count, step) and its
    sentences on inputs outside their intended ranges; errors name the crossing."""
    try:
        setup = kind.one_of(batch, i)
        default = setup.default_time_step()[0]
        system, bridge = setup.system, setup.bridge
        profile = batch.profiles[batch.profile[i]]
        stop = setup.bridge_start + bridge.length + system.wheelbase
        step = default if dt is None else dt
        grid = node_grid(bridge, profile, setup.speed, setup.bridge_start, step, stop,
                         vehicle=system)  # fmt: skip
        notes = input_notes(bridge, system, profile, setup.speed, default)[1]
        notes.append(check_step(grid.dt_max, default, dt, kind.max_omega_dt))
    except (TypeError, ValueError) as exc:
        raise type(exc)(f"crossing {i}: {exc}") from None
    return [text for text in notes if text]


def _check_steps(
    kind: type[CrossingModel], batch: Batch, defaults: np.ndarray, dt: float | None
) -> None:
    """The checks :func:`simulate` makes on a crossing's grid, for a batch.

    Bounds written with arrays (nodes at most ``n_axles (samples + supports) + 3`` plus one
    per ``speed * dt``; the longest step at most ``dt``) find the crossings that may have too
    many nodes, too long a step, or an input outside its intended range; those alone get
    :func:`simulate`'s checks on their grid (:func:`_crossing_notes`), which raise or give the
    sentences of one warning for the batch.
    """
    n = len(batch)
    step = defaults if dt is None else np.full(n, dt)
    systems = [as_system(x) for x in batch.vehicles]
    axles = np.array([x.offsets.size for x in systems])[batch.vehicle]
    wheelbase = np.array([x.wheelbase for x in systems])[batch.vehicle]
    samples = np.array([x.x.size for x in batch.profiles])[batch.profile]
    first = np.array([x.start for x in batch.profiles])[batch.profile]
    supports = np.array([len(x.supports) for x in batch.bridges])[batch.bridge]
    length = np.array([x.length for x in batch.bridges])[batch.bridge]
    stop = batch.bridge_start + length + wheelbase
    nodes = axles * (samples + supports) + 3 + (stop - first) / (batch.speed * step)
    suspects = ~(nodes <= MAX_NODES)
    ratio = DEFAULT_OMEGA_DT * step * (1.0 + 1e-8) / defaults  # omega_max dt, at most
    suspects |= ratio > min(kind.max_omega_dt, RANGES["step_accuracy"].soft[1])
    low, high = RANGES["speed"].soft
    suspects |= (batch.speed < low) | (batch.speed > high)
    spacing = np.array([_uneven_spacing(x) or np.nan for x in batch.profiles])[batch.profile]
    f_max = DEFAULT_OMEGA_DT / defaults / (2.0 * math.pi)
    suspects |= spacing * 2.0 * f_max / batch.speed > RANGES["sample_spacing"].soft[1]
    suspects |= np.array([bool(road_notes(x)) for x in batch.profiles])[batch.profile]  # h23
    outside: dict[int, list[str]] = {}
    for i in np.flatnonzero(suspects):
        notes = _crossing_notes(kind, batch, int(i), dt)
        if notes:
            outside[int(i)] = notes
    if outside:
        first_i = next(iter(outside))
        warn_outside(
            f"{len(outside)} of {n} crossings have inputs outside their intended ranges "
            f"(crossing {first_i}: {'; '.join(outside[first_i])})"
        )


def simulate_many(
    bridges: Bridge | list[Bridge],
    vehicles: object | list,
    profiles: Profile | list[Profile],
    speeds: float | list[float] | np.ndarray,
    bridge_starts: float | list[float] | np.ndarray,
    *,
    model: str = "one-coordinate",
    modes: int | list[int] | np.ndarray | None = None,
    coupled: bool | list[bool] = True,
    convective: bool | list[bool] = True,
    dt: float | None = None,
) -> BatchResult:
    """DAF and contact checks of many crossings at once, compiled and run in parallel.

    Every argument but ``model`` and ``dt`` is one value or a list; lists must share one
    length ``n`` and single values are repeated.  Results equal :func:`simulate` crossing by
    crossing to rounding (no histories are kept).  The study's sprung mass on one or two
    spans runs on each model's lane kernel: blocks of crossings advance together on the
    SIMD lanes of the CPU (:mod:`~vbi_lib.models.lanes`), the blocks shared among numba's
    threads; any other vehicle on the model's general kernel, one crossing per parallel
    task.  A bridge of three or more spans (``model="modal"``) runs one crossing at a time,
    its span peaks taken from the histories.

    Returns
    -------
    BatchResult
        ``daf`` has ``max(2, n_spans)`` columns (NaN beyond a crossing's spans, and for a
        span the vehicle never pushed down).

    Raises
    ------
    TypeError, ValueError
        As :func:`simulate`, naming the crossing (``crossing 3: speed=...``).

    Warns
    -----
    ContactLossWarning
        Once, naming how many crossings lost contact.
    OutsideValidityWarning
        Once, naming how many crossings have a speed, a sampling or a step outside their
        intended ranges (see :func:`simulate`).

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> b = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    >>> t = vbi.Vehicle.from_frequency(3.0e4, 3.0, 0.1)
    >>> r = vbi.simulate_many(b, t, vbi.Profile.flat(130.0, 0.05), [10.0, 20.0], 100.0)
    >>> r.daf.shape
    (2, 2)
    """
    kind = _model(model)
    args = {
        "bridges": bridges,
        "vehicles": vehicles,
        "profiles": profiles,
        "speeds": speeds,
        "bridge_starts": bridge_starts,
        "coupled": coupled,
        "convective": convective,
        "modes": modes,
    }
    args = {name: _as_list(name, value) for name, value in args.items()}
    if dt is not None:
        dt = check.positive("dt", dt)
    batch = _batch(kind, args)
    n = len(batch)
    defaults = kind.default_time_steps(batch)
    steps = defaults if dt is None else np.full(n, dt)
    _check_steps(kind, batch, defaults, dt)
    warn_unresolved_roads(batch)  # issue 20 hook (h20): contact forces set by the sampling
    n_spans = batch.n_spans()
    peaks = np.full((n, max(PEAK_SLOTS, int(n_spans.max()))), np.nan)
    summaries = np.full((n, SUMMARY_SIZE), np.nan)
    dt_max = np.full(n, np.nan)
    narrow = n_spans <= PEAK_SLOTS
    if narrow.any():
        summaries[narrow], dt_max[narrow] = kind.integrate_many(batch.take(narrow), steps[narrow])
        peaks[narrow, :PEAK_SLOTS] = summaries[narrow, S_PEAK : S_PEAK + PEAK_SLOTS]
    wide = np.flatnonzero(~narrow)
    models, grids = kind.models_and_grids(batch, steps, wide)
    for i, setup, grid in zip(wide, models, grids, strict=True):
        # more spans than the summary holds: one crossing with its histories
        summary, _, fields, _ = setup.integrate(grid)
        summaries[i] = summary
        dt_max[i] = grid.dt_max
        peaks[i, : setup.bridge.n_spans] = setup.span_peaks(summary, fields, grid)
    daf = np.where(_never_pushed_down(peaks), np.nan, peaks)
    daf /= kind.span_static_deflections_of(batch)
    systems = [as_system(x) for x in batch.vehicles]
    weights = np.array([x.weight for x in systems])[batch.vehicle]
    unilateral = np.array([x.has_unilateral for x in systems])[batch.vehicle]
    min_ratio, tension, flight = _contact(summaries, weights, unilateral)
    lost = int((min_ratio < 0).sum())
    if lost:
        worst = int(np.argmin(min_ratio))
        warnings.warn(
            f"{lost} of {n} crossings lost contact (crossing {worst}: "
            + contact_note(float(min_ratio[worst]), float(tension[worst]))
            + ")",
            ContactLossWarning,
            stacklevel=2,
        )
    return BatchResult(
        model=kind.name,
        speed=batch.speed,
        daf=daf,
        contact_force_amplification=summaries[:, S_MAX_FORCE] / weights,
        peak_contact_position=summaries[:, S_MAX_AT],
        min_contact_force_ratio=min_ratio,
        tension_fraction=tension,
        flight_fraction=flight,
        dt=dt_max,
    )
