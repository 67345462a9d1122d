"""Checks of a scenario table before any work: the columns, every row, every road.

:func:`validate` refuses a table with unknown or missing columns, and names the rows whose
values are of the wrong type or outside their ranges of validity
(:data:`vbi_lib.ranges.RANGES`), whose model cannot run their bridge, whose road cannot be
built or does not cover the approach and the bridge; it returns the table with the defaults
of the optional columns filled in.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np
import pandas as pd

from ..bridges import Bridge
from ..models import MODELS
from ..profiles import Profile
from ..ranges import RANGES, outside_note, warn_outside
from ..vehicles import as_system
from .recipes import _RECIPES, extent, is_recipe

__all__ = ["OPTIONAL_COLUMNS", "REQUIRED_COLUMNS", "TAG_PREFIX", "validate"]

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
    values or a profile that does not cover the approach and the bridge (naming the rows):
    a speed outside its hard range (:data:`vbi_lib.ranges.RANGES`), ``modes`` that is not a
    whole number from 1 to 200 on ``model="modal"`` rows or not empty on others, a bridge
    the one-coordinate model cannot bend (three spans or more, unequal spans), and a
    profile recipe that cannot be built (the library's recipes check themselves when made;
    another recipe is built once here).  Warns (:class:`~vbi_lib.OutsideValidityWarning`)
    once, naming the rows, for speeds outside their intended range.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> from vbi_lib.studies import FlatProfile, grid
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
    spec = RANGES["speed"]
    bad = ~(np.isfinite(speed) & (speed > spec.hard[0]) & (speed <= spec.hard[1]))
    if bad.any():
        problems.append(
            f"{_rows(bad, index)}: speed must be a number {spec.hard_text()} ({spec.reason})"
        )
        ok &= ~bad
    unusual = np.array(
        [bool(good and outside_note("speed", v)) for good, v in zip(~bad, speed, strict=True)]
    )
    if unusual.any():
        first = int(np.flatnonzero(unusual)[0])
        warn_outside(
            f"scenario table: {_rows(unusual, index)}: "
            + str(outside_note("speed", speed[first], f"speed (row {index[first]!r})"))
        )
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
    most = RANGES["modes"].hard[1]
    whole = np.array(
        [
            isinstance(m, int | np.integer) and not isinstance(m, bool) and 1 <= m <= most
            for m in modes
        ]
    )
    bad = modal & ~whole
    if bad.any():
        problems.append(
            f"{_rows(bad, index)}: modes must be a whole number from 1 to {most} for 'modal'"
        )
        ok &= ~bad
    bad = ~modal & ~pd.isna(modes).astype(bool)
    if bad.any():
        problems.append(f"{_rows(bad, index)}: modes applies to model='modal' only; leave it empty")
        ok &= ~bad
    layout = np.array(
        [
            isinstance(b, Bridge) and m == "one-coordinate" and not b.study_layout
            for b, m in zip(table["bridge"], model, strict=True)
        ]
    )
    if layout.any():
        problems.append(
            f"{_rows(layout, index)}: the one-coordinate model bends one span or two equal "
            "spans only; use model='modal' with modes for this bridge"
        )
        ok &= ~layout
    unbuilt = _unbuildable(table["profile"])
    if unbuilt:
        for message, mask in unbuilt.items():
            problems.append(f"{_rows(mask, index)}: the profile recipe cannot be built: {message}")
            ok &= ~mask
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


def _unbuildable(profiles: pd.Series) -> dict[str, np.ndarray]:
    """Rows whose profile is a recipe that cannot be built, by the reason.

    The library's recipes checked themselves when they were made; any other recipe is
    built here, once per distinct recipe (``build()`` caches it for the run).
    """
    codes, unique = pd.factorize(profiles)
    failed: dict[str, np.ndarray] = {}
    for k, recipe in enumerate(unique):
        if isinstance(recipe, Profile) or isinstance(recipe, _RECIPES) or not is_recipe(recipe):
            continue
        try:
            built = recipe.build()
            if not isinstance(built, Profile):
                raise TypeError(f"build() returned {type(built).__name__}, not a vbi.Profile")
        except (TypeError, ValueError) as exc:
            message = f"{type(exc).__name__}: {exc}"
            failed[message] = failed.get(message, np.zeros(len(profiles), dtype=bool)) | (
                codes == k
            )
    return failed


def _is_vehicle(value: object) -> bool:
    try:
        as_system(value)
    except TypeError:
        return False
    return True
