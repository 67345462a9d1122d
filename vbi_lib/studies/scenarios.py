"""Scenario tables: one row per crossing, built as a full factorial or drawn at random.

:func:`grid` crosses axes (bridges x trucks x roads x speeds x ...) and :func:`monte_carlo` draws
every random number of a study up front from one seed;
:func:`~vbi_lib.studies.checks.validate` checks a whole table before any work, naming the
bad rows.  :func:`parametric_bridges` and
:func:`parametric_trucks` build the study's parametric sets (Tables 2.15.3 and 2.15.4).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from .. import _validation as check
from ..bridges import Bridge
from ..profiles import check_seed
from ..ranges import check_range
from ..units import ft, slinch
from ..vehicles import Vehicle
from .checks import OPTIONAL_COLUMNS, REQUIRED_COLUMNS, TAG_PREFIX, _is_vehicle, validate
from .recipes import ISOProfile

__all__ = [
    "OPTIONAL_COLUMNS",
    "REQUIRED_COLUMNS",
    "TAG_PREFIX",
    "grid",
    "monte_carlo",
    "parametric_bridges",
    "parametric_trucks",
    "validate",
]

# grid() keyword -> scenario column (plural and singular spellings)
_GRID_AXES = {
    "bridges": "bridge",
    "bridge": "bridge",
    "vehicles": "vehicle",
    "vehicle": "vehicle",
    "profiles": "profile",
    "profile": "profile",
    "speeds": "speed",
    "speed": "speed",
    "bridge_starts": "bridge_start",
    "bridge_start": "bridge_start",
    "profile_offsets": "profile_offset",
    "profile_offset": "profile_offset",
    "coupled": "coupled",
    "convective": "convective",
    "model": "model",
    "modes": "modes",
}
_AXIS_ORDER = (
    "bridge",
    "vehicle",
    "profile",
    "speed",
    "bridge_start",
    "profile_offset",
    "coupled",
    "convective",
    "model",
    "modes",
)


# ---------------------------------------------------------------------------- parameter builders
def parametric_bridges(
    frequencies_hz: Sequence[float] = (2.0, 3.0, 4.0, 5.0),
    span: float = 100 * ft,
    total_mass: float = 2000 * slinch,
    damping_ratio: float = 0.01,
) -> dict[str, Bridge]:
    """The study's Table 2.15.3 bridges: one 100 ft span, 2000 slinch in all, 1 % damping.

    ``EI = (2 pi f)^2 mbar L^4 / pi^4`` sets each first frequency.

    Examples
    --------
    >>> from vbi_lib import units as u
    >>> b = parametric_bridges()
    >>> [f"{x.EI / (u.lbf * u.inch**2):.3e}" for x in b.values()]
    ['5.603e+12', '1.261e+13', '2.241e+13', '3.502e+13']
    """
    mass_per_length = check.positive("total_mass", total_mass) / check.positive("span", span)
    return {
        f"bridge {i + 1} ({f:g} Hz)": Bridge.from_frequency(
            span, 1, mass_per_length, f, damping_ratio
        )
        for i, f in enumerate(frequencies_hz)
    }


def parametric_trucks(
    frequencies_hz: Sequence[float] = (2.0, 3.0, 4.0, 5.0),
    mass: float = 200 * slinch,
    damping_ratio: float = 0.10,
) -> dict[str, Vehicle]:
    """The study's Table 2.15.4 trucks: 200 slinch, 10 % damping, ``k = m (2 pi f)^2``.

    Examples
    --------
    >>> from vbi_lib import units as u
    >>> t = parametric_trucks()
    >>> [round(v.stiffness / (u.lbf / u.inch), 1) for v in t.values()]
    [31582.7, 71061.2, 126330.9, 197392.1]
    """
    return {
        f"truck {i + 1} ({f:g} Hz)": Vehicle.from_frequency(mass, f, damping_ratio)
        for i, f in enumerate(frequencies_hz)
    }


# ---------------------------------------------------------------------------- grid
def _axis(name: str, values: Any) -> tuple[list[Any], list[str] | None]:
    """Values and labels of one axis (a scalar, a sequence, or a mapping label -> value)."""
    if isinstance(values, Mapping):
        return list(values.values()), [str(k) for k in values]
    if isinstance(values, pd.Series | pd.Index):
        return list(values), None
    if isinstance(values, np.ndarray):
        return list(values.ravel()), None
    if isinstance(values, list | tuple | range):
        return list(values), None
    return [values], None


def grid(
    bridges: Any,
    vehicles: Any,
    profiles: Any,
    speeds: Any,
    bridge_start: Any,
    **axes: Any,
) -> pd.DataFrame:
    """The full factorial of the axes as a scenario table (one row per crossing).

    Parameters
    ----------
    bridges, vehicles, profiles
        One object, a list, or a ``{label: object}`` mapping (labels fill ``bridge_name``,
        ``vehicle_name``, ``profile_name``).  Profiles are :class:`~vbi_lib.Profile` objects
        or recipes (:class:`ISOProfile`, :class:`HarmonicProfile`, :class:`FlatProfile`).
    speeds
        Speeds [m/s].
    bridge_start
        Station(s) of the first support [m].
    **axes
        More axes: ``profile_offsets`` (slide of the road under the bridge [m], >= 0),
        ``coupled``, ``convective``, ``model`` (a key of :data:`vbi_lib.models.driver.MODELS`) and
        ``modes`` (the number of beam modes, for ``model="modal"`` only).

    Returns
    -------
    pandas.DataFrame
        Columns ``bridge, vehicle, profile, speed, bridge_start, profile_offset, coupled,
        convective, model, modes`` and the three ``*_name`` labels; the first axis varies slowest.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> from vbi_lib.studies import FlatProfile
    >>> s = grid(vbi.Bridge(30.0, 1, 2e10, 8000.0), vbi.Vehicle.from_frequency(3e4, 3.0),
    ...          FlatProfile(130.0, 0.05), [10.0, 20.0], 100.0, coupled=[True, False])
    >>> s[["speed", "coupled"]].to_records(index=False).tolist()
    [(10.0, True), (10.0, False), (20.0, True), (20.0, False)]
    """
    unknown = sorted(set(axes) - set(_GRID_AXES))
    if unknown:
        raise ValueError(
            f"grid() got unknown axes {unknown}; the axes are "
            "bridges, vehicles, profiles, speeds, bridge_start, profile_offsets, coupled, "
            "convective, model, modes"
        )
    given = {
        "bridge": bridges,
        "vehicle": vehicles,
        "profile": profiles,
        "speed": speeds,
        "bridge_start": bridge_start,
    }
    for key, value in axes.items():
        column = _GRID_AXES[key]
        if column in given:
            raise ValueError(f"grid() got the axis {column!r} twice (as {key!r})")
        given[column] = value
    values: dict[str, list[Any]] = {}
    labels: dict[str, list[str] | None] = {}
    for column in _AXIS_ORDER:
        values[column], labels[column] = _axis(
            column, given.get(column, OPTIONAL_COLUMNS.get(column))
        )
        if not values[column]:
            raise ValueError(f"grid(): the axis {column!r} is empty; give at least one value")
    sizes = [len(values[c]) for c in _AXIS_ORDER]
    index = np.stack(np.unravel_index(np.arange(math.prod(sizes)), sizes), axis=1)
    table: dict[str, Any] = {}
    for k, column in enumerate(_AXIS_ORDER):
        items = np.empty(len(values[column]), dtype=object)
        for i, value in enumerate(values[column]):
            items[i] = value
        table[column] = items[index[:, k]]
    for column in ("bridge", "vehicle", "profile"):
        if labels[column] is not None:
            table[f"{column}_name"] = [
                labels[column][i] for i in index[:, _AXIS_ORDER.index(column)]
            ]
    frame = pd.DataFrame(table)
    for column in ("speed", "bridge_start", "profile_offset"):
        try:
            frame[column] = frame[column].astype(float)
        except (TypeError, ValueError):
            pass  # run() names the offending rows
    for column in ("coupled", "convective"):
        if all(isinstance(v, bool | np.bool_) for v in frame[column]):
            frame[column] = frame[column].astype(bool)
    return frame


# ---------------------------------------------------------------------------- Monte Carlo
def _population(name: str, values: Any, kind: type) -> tuple[list[Any], list[str] | None]:
    items, labels = _axis(name, values)
    if not items:
        raise ValueError(f"{name} is empty; give at least one vbi.{kind.__name__}")
    fits = _is_vehicle if kind is Vehicle else (lambda v: isinstance(v, kind))
    bad = [i for i, v in enumerate(items) if not fits(v)]
    if bad:
        raise ValueError(f"{name}: items {bad} are not vbi.{kind.__name__} objects")
    return items, labels


def _range(name: str, value: Any, key: str | None = None) -> tuple[float, float]:
    """``(low, high)`` from one value or a pair, each within ``RANGES[key]`` (else >= 0)."""
    if isinstance(value, str | bytes) or (
        not np.isscalar(value) and (not hasattr(value, "__len__") or len(value) != 2)
    ):
        raise TypeError(f"{name}={value!r} must be one number or a pair (low, high)")
    low, high = (value, value) if np.isscalar(value) else tuple(value)
    if key is None:
        low, high = check.non_negative(f"{name}[0]", low), check.non_negative(f"{name}[1]", high)
    else:
        low, high = check_range(key, low, f"{name}[0]"), check_range(key, high, f"{name}[1]")
    if high < low:
        raise ValueError(f"{name}={value!r}: give (low, high) with low <= high")
    return low, high


def monte_carlo(
    bridges: Any,
    vehicles: Any,
    n: int,
    *,
    speed_range: Any,
    c10_range: Any = None,
    iso_classes: Sequence[str] | None = None,
    waviness: Any = 2.0,
    offset_range: Any = 0.0,
    approach: float = 200 * ft,
    spacing: float = 0.0254,
    n_profiles: int | None = None,
    coupled: bool = True,
    seed: int = 0,
) -> pd.DataFrame:
    """A random scenario table: random ISO 8608 roads, phases, offsets, speeds and trucks.

    Every random number is drawn here, from ``numpy.random.default_rng(seed)``, so the table
    (and :func:`run`'s results) are the same for a given seed whatever the executor.

    Parameters
    ----------
    bridges, vehicles
        One object, a list or a ``{label: object}`` mapping; each crossing picks one of each
        uniformly at random (a bridge population, a truck population).
    n
        Number of crossings.
    speed_range
        ``(low, high)`` [m/s], uniform; or one speed.
    c10_range, iso_classes
        Roughness: ``c10_range = (low, high)`` [m^3] drawn log-uniformly, or ``iso_classes``
        (e.g. ``["A", "B", "C"]``) drawn uniformly, the class mean used.  Give one.
    waviness
        ``w``: one value or ``(low, high)`` uniform.
    offset_range
        Slide of the road under the bridge ``(low, high)`` [m], uniform; or one value.
    approach
        Road before the bridge [m] (default 200 ft, the study's free-decay length at
        75 mph, Figure 2.15.6).
    spacing
        Profile sample spacing [m] (default 1 in).
    n_profiles
        Number of distinct random roads (phase draws); crossings pick among them.  Default
        ``n``: every crossing has its own road.
    coupled
        Coupled (default) or decoupled model.
    seed
        Seed of all draws.

    Returns
    -------
    pandas.DataFrame
        A scenario table for :func:`run`; the profile recipes carry ``c10`` or ``iso_class``,
        ``waviness`` and ``seed``.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> s = monte_carlo(vbi.Bridge(30.0, 1, 2e10, 8000.0), vbi.Vehicle.from_frequency(3e4, 3.0),
    ...                 4, speed_range=(15.0, 30.0), iso_classes=["A", "B"], seed=1)
    >>> len(s), bool(s["speed"].between(15.0, 30.0).all())
    (4, True)
    """
    n = check.integer("n", n, low=1, high=10_000_000)
    bridge_items, bridge_labels = _population("bridges", bridges, Bridge)
    vehicle_items, vehicle_labels = _population("vehicles", vehicles, Vehicle)
    if (c10_range is None) == (iso_classes is None):
        raise ValueError("give exactly one of c10_range=(low, high) [m^3] and iso_classes")
    speed_low, speed_high = _range("speed_range", speed_range, "speed")
    w_low, w_high = _range("waviness", waviness, "waviness")
    off_low, off_high = _range("offset_range", offset_range)
    approach = check_range("profile_length", approach, "approach")
    spacing = check_range("spacing", spacing)
    n_profiles = n if n_profiles is None else check.integer("n_profiles", n_profiles, low=1)
    coupled = check.flag("coupled", coupled)
    rng = np.random.default_rng(check_seed(seed))
    length = approach + max(b.length for b in bridge_items) + off_high + spacing
    seeds = rng.integers(0, 2**31 - 1, size=n_profiles)
    w = (
        rng.uniform(w_low, w_high, size=n_profiles)
        if w_high > w_low
        else np.full(n_profiles, w_low)
    )
    if c10_range is not None:
        c_low, c_high = _range("c10_range", c10_range, "c10")
        c10 = np.exp(rng.uniform(math.log(c_low), math.log(c_high), size=n_profiles))
        roads = [
            ISOProfile(length, spacing, c10=float(c), waviness=float(x), seed=int(k))
            for c, x, k in zip(c10, w, seeds, strict=True)
        ]
    else:
        if isinstance(iso_classes, str) or not all(isinstance(c, str) for c in iso_classes):
            raise TypeError(f"iso_classes={iso_classes!r} must be a list of letters 'A' to 'H'")
        classes = [c.strip().upper() for c in iso_classes]
        if not classes or any(c not in "ABCDEFGH" or len(c) != 1 for c in classes):
            raise ValueError(f"iso_classes={iso_classes!r} must be letters 'A' to 'H'")
        picked = rng.integers(0, len(classes), size=n_profiles)
        roads = [
            ISOProfile(length, spacing, iso_class=classes[i], waviness=float(x), seed=int(k))
            for i, x, k in zip(picked, w, seeds, strict=True)
        ]
    which_road = rng.integers(0, n_profiles, size=n)
    which_bridge = rng.integers(0, len(bridge_items), size=n)
    which_vehicle = rng.integers(0, len(vehicle_items), size=n)
    speed = rng.uniform(speed_low, speed_high, size=n)
    offset = rng.uniform(off_low, off_high, size=n) if off_high > off_low else np.full(n, off_low)
    table = pd.DataFrame(
        {
            "bridge": pd.Series([bridge_items[i] for i in which_bridge], dtype=object),
            "vehicle": pd.Series([vehicle_items[i] for i in which_vehicle], dtype=object),
            "profile": pd.Series([roads[i] for i in which_road], dtype=object),
            "speed": speed,
            "bridge_start": approach,
            "profile_offset": offset,
            "coupled": bool(coupled),
        }
    )
    if bridge_labels is not None:
        table["bridge_name"] = [bridge_labels[i] for i in which_bridge]
    if vehicle_labels is not None:
        table["vehicle_name"] = [vehicle_labels[i] for i in which_vehicle]
    return table
