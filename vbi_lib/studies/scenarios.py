"""Scenario tables: one row per crossing, built as a full factorial or drawn at random.

:func:`grid` crosses axes (bridges x trucks x roads x speeds x ...), :func:`monte_carlo` draws
every random number of a study up front from one seed, and :func:`validate` checks a whole
table before any work, naming the bad rows.  :func:`parametric_bridges` and
:func:`parametric_trucks` build the study's parametric sets (Tables 2.15.3 and 2.15.4).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from .. import _validation as check
from ..bridges import Bridge
from ..models import MODELS
from ..profiles import Profile
from ..units import ft, slinch
from ..vehicles import Vehicle, as_system
from .recipes import ISOProfile, extent, is_recipe

#: Columns a scenario table may have; the first five are required.
REQUIRED_COLUMNS = ("bridge", "vehicle", "profile", "speed", "bridge_start")
OPTIONAL_COLUMNS = {
    "profile_offset": 0.0,
    "coupled": True,
    "convective": True,
    "model": "one-coordinate",
    "modes": None,
    "bridge_name": None,
    "vehicle_name": None,
    "profile_name": None,
}
#: Columns starting with this prefix are carried through :func:`run` unchanged.
TAG_PREFIX = "tag_"

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


# ---------------------------------------------------------------------------- validation
def _rows(mask: np.ndarray, index: pd.Index, limit: int = 8) -> str:
    bad = list(index[np.asarray(mask, dtype=bool)])
    shown = ", ".join(repr(r) for r in bad[:limit])
    more = f" and {len(bad) - limit} more" if len(bad) > limit else ""
    return f"row{'s' if len(bad) > 1 else ''} {shown}{more}"


def _as_table(scenarios: Any) -> pd.DataFrame:
    if isinstance(scenarios, pd.DataFrame):
        return scenarios
    if isinstance(scenarios, Iterable) and not isinstance(scenarios, str | bytes | Mapping):
        rows = list(scenarios)
        if rows and all(isinstance(r, Mapping) for r in rows):
            return pd.DataFrame(rows)
        if not rows:
            return pd.DataFrame()
    raise TypeError(
        "scenarios must be a pandas.DataFrame (see vbi.studies.grid) or a list of dicts, got "
        f"{type(scenarios).__name__}"
    )


def validate(scenarios: Any) -> pd.DataFrame:
    """Check a scenario table before any work and return it with defaults filled in.

    Raises ``ValueError`` for an empty table, unknown or missing columns, and rows with bad
    values or a profile that does not cover the approach and the bridge (naming the rows).
    ``modes`` must be a whole number >= 1 on ``model="modal"`` rows and empty on others.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> from vbi_lib.studies import FlatProfile
    >>> bad = grid(vbi.Bridge(30.0, 1, 2e10, 8000.0), vbi.Vehicle.from_frequency(3e4, 3.0),
    ...            FlatProfile(120.0, 0.05), 20.0, [80.0, 100.0])
    >>> validate(bad)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: scenario table: row 1: the profile (stations 0 to 120 m) does not cover ...
    """
    table = _as_table(scenarios)
    if len(table) == 0:
        raise ValueError("the study is empty: the scenario table has no rows")
    columns = [str(c) for c in table.columns]
    known = set(REQUIRED_COLUMNS) | set(OPTIONAL_COLUMNS)
    unknown = [c for c in columns if c not in known and not c.startswith(TAG_PREFIX)]
    if unknown:
        raise ValueError(
            f"scenario table has unknown columns {unknown}; allowed are "
            f"{list(REQUIRED_COLUMNS) + list(OPTIONAL_COLUMNS)} and any '{TAG_PREFIX}*' column"
        )
    missing = [c for c in REQUIRED_COLUMNS if c not in columns]
    if missing:
        raise ValueError(f"scenario table lacks the required columns {missing}")
    if table.index.has_duplicates:
        raise ValueError("scenario table has a duplicated index; call .reset_index(drop=True)")
    table = table.copy()
    for column, default in OPTIONAL_COLUMNS.items():
        if column not in table.columns and default is not None:
            table[column] = default
    if "modes" not in table.columns:
        table["modes"] = None
    index = table.index
    problems: list[str] = []

    def numbers(column: str) -> np.ndarray:
        out = np.full(len(table), np.nan)
        for i, v in enumerate(table[column].to_numpy()):
            if isinstance(v, bool | np.bool_):
                continue
            try:
                out[i] = float(v)
            except (TypeError, ValueError):
                pass
        return out

    ok = np.ones(len(table), dtype=bool)
    wrong = np.array([not isinstance(v, Bridge) for v in table["bridge"]])
    if wrong.any():
        problems.append(f"{_rows(wrong, index)}: bridge is not a vbi.Bridge")
        ok &= ~wrong
    wrong = np.array([not _is_vehicle(v) for v in table["vehicle"]])
    if wrong.any():
        problems.append(
            f"{_rows(wrong, index)}: vehicle is not a vbi.Vehicle nor another vehicle of "
            "vbi.vehicles (QuarterCar, IndependentAxles, RigidTruck, Convoy, VehicleSystem)"
        )
        ok &= ~wrong
    wrong = np.array([not (isinstance(p, Profile) or is_recipe(p)) for p in table["profile"]])
    if wrong.any():
        problems.append(
            f"{_rows(wrong, index)}: profile is neither a vbi.Profile nor a recipe "
            "(ISOProfile, HarmonicProfile, FlatProfile)"
        )
        ok &= ~wrong
    speed = numbers("speed")
    bad = ~(np.isfinite(speed) & (speed > 0))
    if bad.any():
        problems.append(f"{_rows(bad, index)}: speed must be a finite number > 0 [m/s]")
        ok &= ~bad
    start = numbers("bridge_start")
    bad = ~np.isfinite(start)
    if bad.any():
        problems.append(f"{_rows(bad, index)}: bridge_start must be a finite station [m]")
        ok &= ~bad
    offset = numbers("profile_offset")
    bad = ~(np.isfinite(offset) & (offset >= 0))
    if bad.any():
        problems.append(f"{_rows(bad, index)}: profile_offset must be a finite number >= 0 [m]")
        ok &= ~bad
    for column in ("coupled", "convective"):
        bad = np.array([not isinstance(v, bool | np.bool_) for v in table[column]])
        if bad.any():
            problems.append(f"{_rows(bad, index)}: {column} must be True or False")
            ok &= ~bad
    model = table["model"].to_numpy(dtype=object)
    bad = np.array([not (isinstance(m, str) and m in MODELS) for m in model])
    if bad.any():
        problems.append(f"{_rows(bad, index)}: model must be one of {sorted(MODELS)}")
        ok &= ~bad
    modes = table["modes"].to_numpy(dtype=object)
    modal = model == "modal"
    whole = np.array(
        [isinstance(m, int | np.integer) and not isinstance(m, bool) and m >= 1 for m in modes]
    )
    bad = modal & ~whole
    if bad.any():
        problems.append(f"{_rows(bad, index)}: modes must be a whole number >= 1 for 'modal'")
        ok &= ~bad
    bad = ~modal & ~pd.isna(modes).astype(bool)
    if bad.any():
        problems.append(f"{_rows(bad, index)}: modes applies to model='modal' only; leave it empty")
        ok &= ~bad
    if ok.any():
        rows = np.flatnonzero(ok)
        b_code, b_unique = pd.factorize(table["bridge"].iloc[rows])
        p_code, p_unique = pd.factorize(table["profile"].iloc[rows])
        v_code, v_unique = pd.factorize(table["vehicle"].iloc[rows])
        lengths = np.array([b.length for b in b_unique])[b_code]
        wheelbase = np.array([as_system(v).wheelbase for v in v_unique])[v_code]
        extents = np.array([extent(p) for p in p_unique]).reshape(-1, 2)[p_code]
        road_end = extents[:, 1] - offset[rows]
        end = start[rows] + lengths + wheelbase
        short = (start[rows] - wheelbase < extents[:, 0] - 1e-9 * np.maximum(1, abs(end))) | (
            end > road_end + 1e-9 * np.maximum(1, abs(end))
        )
        if short.any():
            first = rows[np.flatnonzero(short)[0]]
            k = np.flatnonzero(short)[0]
            mask = np.zeros(len(table), dtype=bool)
            mask[rows[short]] = True
            problems.append(
                f"{_rows(mask, index)}: the profile (stations {extents[k, 0]:g} to "
                f"{extents[k, 1]:g} m) does not cover the approach and the bridge (to station "
                f"{end[k]:g} m with bridge_start={start[first]:g} m, "
                f"profile_offset={offset[first]:g} m, vehicle wheelbase {wheelbase[k]:g} m)"
            )
    if problems:
        raise ValueError("scenario table: " + "; ".join(problems))
    table["speed"] = speed
    table["bridge_start"] = start
    table["profile_offset"] = offset
    table["coupled"] = table["coupled"].astype(bool)
    table["convective"] = table["convective"].astype(bool)
    table["modes"] = pd.array(
        [int(m) if w else pd.NA for m, w in zip(modes, modal & whole, strict=True)], dtype="Int64"
    )
    return table


def _is_vehicle(value: object) -> bool:
    try:
        as_system(value)
    except TypeError:
        return False
    return True


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


def _range(name: str, value: Any, positive: bool = True) -> tuple[float, float]:
    low, high = (value, value) if np.isscalar(value) else tuple(value)
    low = check.positive(name, low) if positive else check.non_negative(name, low)
    high = check.positive(name, high) if positive else check.non_negative(name, high)
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
    if not isinstance(n, int | np.integer) or isinstance(n, bool) or n < 1:
        raise ValueError(f"n={n!r} must be a positive integer (the number of crossings)")
    n = int(n)
    bridge_items, bridge_labels = _population("bridges", bridges, Bridge)
    vehicle_items, vehicle_labels = _population("vehicles", vehicles, Vehicle)
    if (c10_range is None) == (iso_classes is None):
        raise ValueError("give exactly one of c10_range=(low, high) [m^3] and iso_classes")
    speed_low, speed_high = _range("speed_range", speed_range)
    w_low, w_high = _range("waviness", waviness)
    off_low, off_high = _range("offset_range", offset_range, positive=False)
    approach = check.positive("approach", approach)
    spacing = check.positive("spacing", spacing)
    n_profiles = n if n_profiles is None else n_profiles
    if not isinstance(n_profiles, int | np.integer) or n_profiles < 1:
        raise ValueError(f"n_profiles={n_profiles!r} must be a positive integer")
    rng = np.random.default_rng(seed)
    length = approach + max(b.length for b in bridge_items) + off_high + spacing
    seeds = rng.integers(0, 2**31 - 1, size=n_profiles)
    w = (
        rng.uniform(w_low, w_high, size=n_profiles)
        if w_high > w_low
        else np.full(n_profiles, w_low)
    )
    if c10_range is not None:
        c_low, c_high = _range("c10_range", c10_range)
        c10 = np.exp(rng.uniform(math.log(c_low), math.log(c_high), size=n_profiles))
        roads = [
            ISOProfile(length, spacing, c10=float(c), waviness=float(x), seed=int(k))
            for c, x, k in zip(c10, w, seeds, strict=True)
        ]
    else:
        classes = [str(c).strip().upper() for c in iso_classes]
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
