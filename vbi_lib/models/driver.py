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
from ..profiles import Profile
from ..validity import ContactLossWarning, contact_note, flight_note
from ..vehicles import as_system
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
    broadcast,
    check_crossing,
    node_grid,
)
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
    if not isinstance(model, str) or model not in MODELS:
        listing = "; ".join(f"{k!r}: {v.description}" for k, v in MODELS.items())
        raise ValueError(f"model={model!r} is not a crossing model; use one of {listing}")
    return MODELS[model]


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
        at any section.

    Raises
    ------
    TypeError, ValueError
        Inputs of the wrong type or outside what is allowed, named in the message.

    Warns
    -----
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
    setup = kind(bridge, vehicle, speed, bridge_start, coupled=coupled, convective=convective,
                 modes=modes)  # fmt: skip
    notes = []
    if dt is None:
        dt, note = setup.default_time_step()
        notes.append(note)
    else:
        dt = check.positive("dt", dt)
    stop = bridge_start + bridge.length + system.wheelbase + speed * free_vibration
    grid = node_grid(bridge, profile, speed, bridge_start, dt, stop, vehicle=system)
    summary, contact, fields, note = setup.integrate(grid)
    notes.append(note)
    static = setup.static_deflection()
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
        daf=setup.span_peaks(summary, fields, grid) / setup.span_static_deflections(),
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
    crossing (no histories are kept).  Batches of the study's sprung mass run on each
    model's compiled sprung-mass kernel; any other vehicle on the general kernel, one
    crossing per parallel task.  A bridge of three or more spans (``model="modal"``) runs one
    crossing at a time, its span peaks taken from the histories.

    Returns
    -------
    BatchResult
        ``daf`` has ``max(2, n_spans)`` columns (NaN beyond a crossing's spans).

    Warns
    -----
    ContactLossWarning
        Once, naming how many crossings lost contact.

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
    n, expanded = broadcast(args, "simulate_many")
    if dt is not None:
        dt = check.positive("dt", dt)
    setups, grids = [], []
    cache: dict = {}
    for i in range(n):
        bridge = expanded["bridges"][i]
        vehicle = expanded["vehicles"][i]
        profile = expanded["profiles"][i]
        try:
            speed, start = check_crossing(
                bridge, vehicle, profile, expanded["speeds"][i], expanded["bridge_starts"][i]
            )
            setup = kind(
                bridge,
                vehicle,
                speed,
                start,
                coupled=check.flag("coupled", expanded["coupled"][i]),
                convective=check.flag("convective", expanded["convective"][i]),
                modes=expanded["modes"][i],
            )
        except (TypeError, ValueError) as exc:
            raise type(exc)(f"crossing {i}: {exc}") from None
        step = setup.default_time_step()[0] if dt is None else dt
        system = setup.system
        axles = (tuple(system.offsets), tuple(system.footprint))
        key = (id(profile), bridge.supports, speed, start, step, axles)
        if key not in cache:
            stop = start + bridge.length + system.wheelbase
            cache[key] = node_grid(bridge, profile, speed, start, step, stop, vehicle=system)
        setups.append(setup)
        grids.append(cache[key])
    wide = [i for i, s in enumerate(setups) if s.bridge.n_spans > PEAK_SLOTS]
    narrow = sorted(set(range(n)) - set(wide))
    peaks = np.full((n, max(PEAK_SLOTS, *(s.bridge.n_spans for s in setups))), np.nan)
    summaries = np.full((n, SUMMARY_SIZE), np.nan)
    if narrow:
        summaries[narrow] = kind.integrate_many([setups[i] for i in narrow],
                                                [grids[i] for i in narrow])  # fmt: skip
        peaks[narrow, :PEAK_SLOTS] = summaries[narrow, S_PEAK : S_PEAK + PEAK_SLOTS]
    for i in wide:  # more spans than the summary holds: one crossing with its histories
        summary, _, fields, _ = setups[i].integrate(grids[i])
        summaries[i] = summary
        peaks[i, : setups[i].bridge.n_spans] = setups[i].span_peaks(summary, fields, grids[i])
    weights = np.array([s.system.weight for s in setups])
    statics = np.full(peaks.shape, np.nan)
    for i, s in enumerate(setups):
        statics[i, : s.bridge.n_spans] = s.span_static_deflections()
    daf = peaks / statics
    unilateral = np.array([s.system.has_unilateral for s in setups])
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
        speed=np.array([s.speed for s in setups]),
        daf=daf,
        contact_force_amplification=summaries[:, S_MAX_FORCE] / weights,
        peak_contact_position=summaries[:, S_MAX_AT],
        min_contact_force_ratio=min_ratio,
        tension_fraction=tension,
        flight_fraction=flight,
        dt=np.array([g.dt_max for g in grids]),
    )
