"""The checks of :func:`vbi_lib.simulate_many`'s arguments as arrays, before any crossing runs.

Lists or single values become one :class:`~vbi_lib.models.batch.Batch`; the arrays find the
crossings that may fail a check, and those alone get :func:`vbi_lib.simulate`'s checks, so
that an error names its crossing and a valid batch pays for no crossing-by-crossing loop.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .. import _validation as check
from ..bridges import Bridge
from ..profiles import Profile
from ..ranges import MAX_NODES, RANGES, check_range, warn_outside
from ..road_checks import road_notes
from ..vehicles import as_system
from .base import (
    DEFAULT_OMEGA_DT,
    CrossingModel,
    _uneven_spacing,
    check_crossing,
    check_step,
    input_notes,
    node_grid,
)
from .batch import Batch

__all__ = ["as_list", "batch_of", "check_modes_option", "check_steps"]


def check_modes_option(modes: object) -> int | None:
    """``None``, or a number of modes: an int within the range of ``modes``."""
    if modes is None:
        return None
    return int(check_range("modes", check.integer("modes", modes), warn=False))


def _is_list(value: object) -> bool:
    return isinstance(value, list | tuple | np.ndarray)


def as_list(name: str, value: object) -> object:
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
        return np.full(n, kind.check_modes(check_modes_option(values)), np.int64)
    out = np.empty(n, np.int64)
    for i, value in enumerate(values):
        try:
            out[i] = kind.check_modes(check_modes_option(value))
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


def batch_of(kind: type[CrossingModel], args: dict[str, Any]) -> Batch:
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


def check_steps(
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
