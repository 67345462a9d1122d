"""One driver for every crossing model: :func:`simulate` and :func:`simulate_many`.

The model is looked up by name in :data:`MODELS` (as ``solve_ivp`` looks up its ``METHODS``);
the driver checks the inputs, builds the node grid, calls the model's kernel and assembles
the result, the same way for every model.
"""

from __future__ import annotations

import warnings

import numpy as np

from .. import _validation as check
from ..bridges import Bridge
from ..costs import warn_crossing
from ..profiles import Profile
from ..ranges import warn_outside
from ..road_checks import past_the_road
from ..validity import (
    ContactLossWarning,
    TruncationWarning,
    UnresolvedRoadWarning,
    contact_note,
    flight_note,
)
from ..vehicles import as_system
from ..vehicles.footprint import unresolved_road_note, warn_unresolved_roads
from .base import (
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
    check_crossing,
    check_step,
    input_notes,
    node_grid,
)
from .batch_inputs import as_list, batch_of, check_modes_option, check_steps
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


def _never_pushed_down(peaks: np.ndarray) -> np.ndarray:
    """Spans whose midspan never went down over the run (peak <= 0)."""
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
        Number of beam modes, for ``model="modal"`` only; ``None``: every mode up to 2.3
        times the highest simply supported frequency of any one span
        (:func:`~vbi_lib.models.modal.default_modes`), which includes every span's own
        fundamental.
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
        at any section.

        ``daf[j]``, the DAF of span ``j + 1``, is the largest downward displacement of its
        midspan over the whole run divided by the largest downward static displacement of
        the same midspan under the vehicle's static axle loads, all axles in every position
        of the group, by the model's own statics: the one-shape beam's for the
        one-coordinate model (one axle: ``P / k*``, (90)-(91)), the exact beam's for the
        modal model, whose headline displacement is the mode-acceleration one
        (:mod:`~vbi_lib.models.statics`).  The DAF of a span the vehicle never pushed down
        (its midspan only rose) is NaN, and ``notes`` says so.

    Raises
    ------
    TypeError, ValueError
        Inputs of the wrong type or outside what is allowed, named in the message: the hard
        ranges of :data:`vbi_lib.ranges.RANGES` (``speed``, ``modes``, ``step_accuracy``),
        and more than :data:`~vbi_lib.ranges.MAX_NODES` nodes, counted before anything is
        allocated.

    Warns
    -----
    TruncationWarning
        ``model="modal"``: ``modes`` leaves out a span's own fundamental.  (When the N-mode
        series DAF of a span differs from the mode-acceleration DAF by more than 1 %,
        ``notes`` says so; the headline is the mode-acceleration one.)
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
    >>> run.daf.round(3), run.series_daf.round(3)  # mode acceleration, and the 5-mode series
    (array([1.034]), array([1.035]))
    """
    kind = _model(model)
    system = as_system(vehicle)
    speed, bridge_start = check_crossing(bridge, vehicle, profile, speed, bridge_start)
    coupled = check.flag("coupled", coupled)
    convective = check.flag("convective", convective)
    free_vibration = check.non_negative("free_vibration", free_vibration)
    modes = check_modes_option(modes)
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
    statics = setup.span_static_deflections()
    histories = {**fields, "axle_contact_force": contact}
    history = setup.midspan_history(histories, grid)
    fields["midspan_displacement"] = history[0]  # what the span DAFs read
    peaks = setup.span_peaks(summary, history, grid)
    never = _never_pushed_down(peaks)
    for j in np.flatnonzero(never):
        notes.append(
            f"span {j + 1} was never pushed down over the run (its midspan only rose): its "
            "DAF is not defined and is NaN"
        )
    daf = np.where(never, np.nan, peaks) / statics
    quiet, warned, extra = setup.checks(histories, grid, daf)
    notes += quiet
    for text in warned:
        notes.append(text)
        warnings.warn(text, TruncationWarning, stacklevel=2)
    fields.update(extra)
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
        daf=daf,
        static_deflection=float(statics.max()),
        dt=grid.dt_max,
        coupled=coupled,
        convective=convective,
        min_contact_force_ratio=float(min_ratio),
        tension_fraction=float(tension),
        flight_fraction=float(flight),
        notes=tuple(notes),
        **fields,
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
    args = {name: as_list(name, value) for name, value in args.items()}
    if dt is not None:
        dt = check.positive("dt", dt)
    batch = kind.resolve_modes(batch_of(kind, args))
    n = len(batch)
    defaults = kind.default_time_steps(batch)
    steps = defaults if dt is None else np.full(n, dt)
    check_steps(kind, batch, defaults, dt)
    warn_unresolved_roads(batch)  # issue 20 hook (h20): contact forces set by the sampling
    for text in kind.batch_notes(batch):
        warnings.warn(text, TruncationWarning, stacklevel=2)
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
        summary, contact, fields, _ = setup.integrate(grid)
        summaries[i] = summary
        dt_max[i] = grid.dt_max
        history = setup.midspan_history({**fields, "axle_contact_force": contact}, grid)
        peaks[i, : setup.bridge.n_spans] = setup.span_peaks(summary, history, grid)
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
