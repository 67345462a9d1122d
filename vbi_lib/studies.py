r"""Parametric studies and Monte Carlo: many crossings described as a table, run in batches.

A *study* is a table of scenarios, one row per crossing: a bridge, a vehicle, a road profile
(a :class:`~vbi_lib.Profile` or a small *recipe* that builds one), a speed, where the bridge
starts on the road, how far the road is slid under the bridge, whether the model is coupled
and how many modes it uses.  :func:`grid` builds the full factorial of some axes;
:func:`run` simulates every row and returns one tidy row per crossing: every input as plain
columns, the DAF of each span (88)-(91), the peak contact-force amplification
:math:`\max R / (m_v g)` on the bridge and where and when it occurred.

How it runs
-----------
Rows are cut into chunks; each chunk is one call of :func:`~vbi_lib.simulate_many`
(compiled, no time histories kept) inside a worker of a :class:`concurrent.futures.Executor`:
a local process pool by default, or any executor you pass, such as
``dask.distributed.Client(...).get_executor()``.  Profiles are built from their recipes in the
worker and cached there (a profile shared by many rows is generated once per worker).  Every
crossing depends only on its own row, so the table is the same, bit for bit, whatever the
executor and the chunk size; random studies draw all their random numbers in
:func:`monte_carlo`, before any work, from one seed.

Sliding the road: with ``profile_offset = d >= 0`` the wheel meets, at station ``x``, the
elevation the profile has at ``x + d``; the truck still starts at the profile's first
station, so the approach length stays ``bridge_start - profile.start`` while the features on
the bridge move back by ``d`` (the study's Figure 2.15.16 slides the road in 5 ft steps).
"""

from __future__ import annotations

import concurrent.futures as cf
import functools
import importlib
import math
import multiprocessing
import os
import tempfile
from collections.abc import Callable, Iterable, Mapping, Sequence
from concurrent.futures.process import BrokenProcessPool
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from . import _validation as check
from .bridges import Bridge
from .profiles import Profile
from .units import ft, slinch
from .vehicles import Vehicle

#: Columns a scenario table may have; the first five are required.
REQUIRED_COLUMNS = ("bridge", "vehicle", "profile", "speed", "bridge_start")
OPTIONAL_COLUMNS = {
    "profile_offset": 0.0,
    "coupled": True,
    "convective": True,
    "modes": 1,
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
    "modes",
)

#: Default number of crossings per chunk handed to a worker.
DEFAULT_CHUNK_SIZE = 250
#: Studies with fewer crossings than this run in this process by default.
SERIAL_BELOW = 1500


# ---------------------------------------------------------------------------- recipes
@dataclass(frozen=True)
class FlatProfile:
    """Recipe for a smooth road: ``Profile.flat(length, spacing, start)`` built in the worker.

    >>> FlatProfile(100.0, 0.025).build().x.size
    4001
    """

    length: float
    spacing: float
    start: float = 0.0

    @property
    def end(self) -> float:
        """Last station [m]."""
        return self.start + self.length

    @property
    def label(self) -> str:
        """Short name used in result tables."""
        return "flat"

    def build(self) -> Profile:
        """The :class:`~vbi_lib.Profile` (cached per process)."""
        return _build(self)

    def _make(self) -> Profile:
        return Profile.flat(self.length, self.spacing, self.start)


@dataclass(frozen=True)
class HarmonicProfile:
    """Recipe for ``Profile.harmonic(length, spacing, wavelength, amplitude, phase, start)``.

    >>> round(float(HarmonicProfile(30.0, 0.01, 10.0, 0.002).build().elevation.max()) * 1e3, 3)
    2.0
    """

    length: float
    spacing: float
    wavelength: float
    amplitude: float
    phase: float = 0.0
    start: float = 0.0

    @property
    def end(self) -> float:
        """Last station [m]."""
        return self.start + self.length

    @property
    def label(self) -> str:
        """Short name used in result tables."""
        return f"harmonic {self.wavelength:g} m"

    def build(self) -> Profile:
        """The :class:`~vbi_lib.Profile` (cached per process)."""
        return _build(self)

    def _make(self) -> Profile:
        return Profile.harmonic(
            self.length, self.spacing, self.wavelength, self.amplitude, self.phase, self.start
        )


@dataclass(frozen=True)
class ISOProfile:
    """Recipe for an ISO 8608 random road, ``Profile.iso8608(...)`` built in the worker (87).

    Give either ``c10`` (``G_d(n0)`` at ``n0 = 0.1`` cycle/m [m^3]) or ``iso_class`` (A-H).
    ``seed`` fixes the random phases, so the same recipe always builds the same road.

    Examples
    --------
    >>> ISOProfile(200.0, 0.025, c10=300e-6, seed=1).label
    'ISO C10=300e-6 w=2 seed 1'
    """

    length: float
    spacing: float
    c10: float | None = None
    iso_class: str | None = None
    waviness: float = 2.0
    seed: int = 0
    band: tuple[float, float] = (0.011, 2.83)
    start: float = 0.0

    def __post_init__(self) -> None:
        if (self.c10 is None) == (self.iso_class is None):
            raise ValueError(
                f"ISOProfile needs exactly one of c10 and iso_class; got c10={self.c10!r}, "
                f"iso_class={self.iso_class!r}"
            )
        if not isinstance(self.seed, int | np.integer) or isinstance(self.seed, bool):
            raise ValueError(
                f"ISOProfile seed={self.seed!r} must be an integer (a study must be repeatable)"
            )
        object.__setattr__(self, "seed", int(self.seed))
        object.__setattr__(self, "band", tuple(float(b) for b in self.band))

    @property
    def end(self) -> float:
        """Last station [m]."""
        return self.start + self.length

    @property
    def label(self) -> str:
        """Short name used in result tables."""
        rough = (
            f"C10={self.c10 * 1e6:.4g}e-6" if self.c10 is not None else f"class {self.iso_class}"
        )
        return f"ISO {rough} w={self.waviness:g} seed {self.seed}"

    def build(self) -> Profile:
        """The :class:`~vbi_lib.Profile` (cached per process)."""
        return _build(self)

    def _make(self) -> Profile:
        return Profile.iso8608(
            self.length,
            self.spacing,
            c10=self.c10,
            iso_class=self.iso_class,
            waviness=self.waviness,
            seed=self.seed,
            band=self.band,
            start=self.start,
        )


_RECIPES = (FlatProfile, HarmonicProfile, ISOProfile)


@functools.lru_cache(maxsize=64)
def _build(recipe: Any) -> Profile:
    return recipe._make()


def _is_recipe(value: object) -> bool:
    return callable(getattr(value, "build", None)) and hasattr(value, "end")


def _extent(profile: Any) -> tuple[float, float]:
    """First and last station of a profile or recipe without building it."""
    if isinstance(profile, Profile):
        return profile.start, profile.end
    return float(profile.start), float(profile.end)


def _profile_label(profile: Any) -> str:
    if isinstance(profile, Profile):
        return profile.name or "profile"
    return str(getattr(profile, "label", type(profile).__name__))


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
        ``coupled``, ``convective``, ``modes``.

    Returns
    -------
    pandas.DataFrame
        Columns ``bridge, vehicle, profile, speed, bridge_start, profile_offset, coupled,
        convective, modes`` and the three ``*_name`` labels; the first axis varies slowest.

    Examples
    --------
    >>> import vbi_lib as vbi
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
            "convective, modes"
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
    if all(isinstance(v, int | np.integer) and not isinstance(v, bool) for v in frame["modes"]):
        frame["modes"] = frame["modes"].astype(np.int64)
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
    values or a profile that does not cover the approach and the bridge (naming the rows);
    ``NotImplementedError`` when ``modes > 1`` and no many-mode model is available.

    Examples
    --------
    >>> import vbi_lib as vbi
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

    kinds = {"bridge": Bridge, "vehicle": Vehicle}
    ok = np.ones(len(table), dtype=bool)
    for column, kind in kinds.items():
        wrong = np.array([not isinstance(v, kind) for v in table[column]])
        if wrong.any():
            problems.append(f"{_rows(wrong, index)}: {column} is not a vbi.{kind.__name__}")
            ok &= ~wrong
    wrong = np.array([not (isinstance(p, Profile) or _is_recipe(p)) for p in table["profile"]])
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
    modes = table["modes"].to_numpy()
    bad = np.array(
        [
            not (isinstance(m, int | np.integer) and not isinstance(m, bool) and m >= 1)
            for m in modes
        ]
    )
    if bad.any():
        problems.append(f"{_rows(bad, index)}: modes must be an integer >= 1")
        ok &= ~bad
    if ok.any():
        rows = np.flatnonzero(ok)
        b_code, b_unique = pd.factorize(table["bridge"].iloc[rows])
        p_code, p_unique = pd.factorize(table["profile"].iloc[rows])
        lengths = np.array([b.length for b in b_unique])[b_code]
        extents = np.array([_extent(p) for p in p_unique]).reshape(-1, 2)[p_code]
        road_end = extents[:, 1] - offset[rows]
        end = start[rows] + lengths
        short = (start[rows] < extents[:, 0]) | (end > road_end + 1e-9 * np.maximum(1, abs(end)))
        if short.any():
            first = rows[np.flatnonzero(short)[0]]
            k = np.flatnonzero(short)[0]
            mask = np.zeros(len(table), dtype=bool)
            mask[rows[short]] = True
            problems.append(
                f"{_rows(mask, index)}: the profile (stations {extents[k, 0]:g} to "
                f"{extents[k, 1]:g} m) does not cover the approach and the bridge (to station "
                f"{end[k]:g} m with bridge_start={start[first]:g} m, "
                f"profile_offset={offset[first]:g} m)"
            )
    if problems:
        raise ValueError("scenario table: " + "; ".join(problems))
    if (modes > 1).any():
        _modal_model()
    table["speed"] = speed
    table["bridge_start"] = start
    table["profile_offset"] = offset
    table["coupled"] = table["coupled"].astype(bool)
    table["convective"] = table["convective"].astype(bool)
    table["modes"] = table["modes"].astype(np.int64)
    return table


def _modal_model() -> Callable[..., Any]:
    """``vbi_lib.modal.simulate_modal_many`` or ``NotImplementedError`` naming what is missing."""
    try:
        modal = importlib.import_module(f"{__package__}.modal")
    except ImportError:
        modal = None
    function = getattr(modal, "simulate_modal_many", None)
    if function is None:
        raise NotImplementedError(
            "modes > 1 needs the many-mode model vbi_lib.modal.simulate_modal_many, which this "
            "version of vbi_lib does not have; use modes=1 (the one-coordinate model)"
        )
    return function


# ---------------------------------------------------------------------------- workers
def _set_threads(threads: int | None) -> None:
    if threads:
        import numba

        numba.set_num_threads(max(1, min(int(threads), numba.config.NUMBA_NUM_THREADS)))


def _init_worker() -> None:
    """Process-pool initializer: one numba thread per worker; Ctrl-C is the parent's."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _set_threads(1)


def _road(profile: Profile, offset: float) -> Profile:
    """The road slid back by ``offset``: at station ``x`` it has the profile's ``x + offset``."""
    if offset == 0.0:
        return profile
    return profile.segment(profile.start + offset, profile.end).shifted(-offset)


def _iri_of_spans(road: Profile, bridge: Bridge, start: float) -> np.ndarray:
    """IRI [m/km] of the road over each span (the golden car starts on the bridge)."""
    from .roughness import iri  # imported only when a study asks for IRI

    out = np.full(2, np.nan)
    deck = road.segment(start, start + bridge.length)
    values = iri(deck, segment_length=bridge.span).iri if bridge.n_spans > 1 else [iri(deck)]
    out[: bridge.n_spans] = np.asarray(values, dtype=float)[: bridge.n_spans]
    return out


def _run_chunk(payload: dict[str, Any]) -> dict[str, np.ndarray]:
    """Simulate one chunk of scenarios (runs inside a worker; keeps no time histories)."""
    from .simulation import simulate_many

    _set_threads(payload["threads"])
    profiles = [p if isinstance(p, Profile) else p.build() for p in payload["profiles"]]
    bridges, vehicles = payload["bridges"], payload["vehicles"]
    b, v, p = payload["b"], payload["v"], payload["p"]
    speed, start, offset = payload["speed"], payload["start"], payload["offset"]
    coupled, convective, modes = payload["coupled"], payload["convective"], payload["modes"]
    n = speed.size
    roads: dict[tuple[int, float], Profile] = {}
    for i in range(n):
        key = (int(p[i]), float(offset[i]))
        if key not in roads:
            roads[key] = _road(profiles[key[0]], key[1])
    road = [roads[(int(p[i]), float(offset[i]))] for i in range(n)]
    out = {
        "daf": np.full((n, 2), np.nan),
        "contact_force_amplification": np.full(n, np.nan),
        "peak_contact_position": np.full(n, np.nan),
        "dt": np.full(n, np.nan),
    }
    for many_modes in (False, True):
        rows = np.flatnonzero((modes > 1) == many_modes)
        if rows.size == 0:
            continue
        args = (
            [bridges[b[i]] for i in rows],
            [vehicles[v[i]] for i in rows],
            [road[i] for i in rows],
            speed[rows],
            start[rows],
        )
        flags = {"coupled": list(coupled[rows]), "convective": list(convective[rows])}
        if many_modes:
            batches = [(rows, _modal_model()(*args, modes=modes[rows], dt=payload["dt"], **flags))]
        else:
            batches = [(rows, simulate_many(*args, dt=payload["dt"], **flags))]
        for where, result in batches:
            out["daf"][where] = np.asarray(result.daf)[:, :2]
            for name in ("contact_force_amplification", "peak_contact_position", "dt"):
                out[name][where] = np.asarray(getattr(result, name))
    if payload["iri"]:
        out["iri"] = np.empty((n, 2))
        done: dict[tuple[int, int, float], np.ndarray] = {}
        for i in range(n):
            key = (id(road[i]), int(b[i]), float(start[i]))
            if key not in done:
                done[key] = _iri_of_spans(road[i], bridges[b[i]], start[i])
            out["iri"][i] = done[key]
    return out


# ---------------------------------------------------------------------------- running
_POOL: cf.ProcessPoolExecutor | None = None


def default_executor(max_workers: int | None = None) -> cf.ProcessPoolExecutor:
    """The local process pool :func:`run` uses by default (one numba thread per worker).

    Workers start with ``spawn`` (safe with numba's threads) and live for the session, so
    their import and compile-cache cost is paid once.
    """
    global _POOL
    workers = max_workers or os.cpu_count() or 1
    stale = _POOL is not None and (
        _POOL._max_workers != workers or _POOL._broken or _POOL._shutdown_thread
    )
    if stale:
        _POOL.shutdown(wait=True, cancel_futures=True)
        _POOL = None
    if _POOL is None:
        _POOL = cf.ProcessPoolExecutor(
            max_workers=workers,
            mp_context=multiprocessing.get_context("spawn"),
            initializer=_init_worker,
        )
    return _POOL


def shutdown_default_executor() -> None:
    """Stop the worker processes of :func:`default_executor` (the next run starts new ones)."""
    global _POOL
    if _POOL is not None:
        _POOL.shutdown(wait=True, cancel_futures=True)
        _POOL = None


class _Serial(cf.Executor):
    """Runs each task at once in this process (numba's threads do the parallel work)."""

    def submit(self, fn, /, *args, **kwargs):  # noqa: ANN001, ANN201
        future: cf.Future = cf.Future()
        try:
            future.set_result(fn(*args, **kwargs))
        except BaseException as exc:  # noqa: BLE001 - handed to the caller through the future
            future.set_exception(exc)
        return future


def _labels(objects: Sequence[Any], kind: str) -> list[str]:
    out = []
    for obj in objects:
        if kind == "bridge":
            out.append(f"{obj.n_spans} x {obj.span:g} m, {obj.first_frequency_hz:.2f} Hz")
        elif kind == "vehicle":
            out.append(f"{obj.mass:.0f} kg, {obj.frequency_hz:.2f} Hz")
        else:
            out.append(_profile_label(obj))
    return out


def _profile_columns(profiles: Sequence[Any]) -> dict[str, list[Any]]:
    """Scalar description of each unique profile (recipe fields, or extent and spacing)."""
    records = []
    for p in profiles:
        if isinstance(p, Profile):
            rec = {"kind": "profile", "start": p.start, "length": p.length, "spacing": p.spacing}
        else:
            rec = {"kind": type(p).__name__}
            try:
                items = asdict(p).items() if hasattr(p, "__dataclass_fields__") else ()
            except TypeError:
                items = ()
            for key, value in items:
                if value is None or isinstance(value, str | int | float | bool | np.number):
                    rec[key] = value
        records.append(rec)
    keys: list[str] = []
    for rec in records:
        keys += [k for k in rec if k not in keys]
    return {f"profile_{k}": [rec.get(k) for rec in records] for k in keys}


def run(
    scenarios: Any,
    executor: cf.Executor | str | None = None,
    *,
    chunk_size: int | None = None,
    progress: bool | None = None,
    iri: bool = False,
    dt: float | None = None,
    threads_per_task: int | None = 1,
) -> pd.DataFrame:
    """Simulate every scenario and return one tidy row per crossing.

    Parameters
    ----------
    scenarios
        A scenario table (:func:`grid`, :func:`monte_carlo`, or your own DataFrame or list of
        dicts with the columns of :data:`REQUIRED_COLUMNS` and :data:`OPTIONAL_COLUMNS`).
        It is checked in full (:func:`validate`) before any work starts.
    executor
        Any :class:`concurrent.futures.Executor` (a ``ProcessPoolExecutor``, or a Dask
        cluster's ``Client(...).get_executor()``), ``"serial"`` for this process, or ``None``:
        this process for small studies (fewer than :data:`SERIAL_BELOW` crossings), else the
        local process pool :func:`default_executor`.  Give a process pool the ``spawn``
        context (``fork`` after numba's OpenMP threads have run is unsafe); in a script, run
        the study under ``if __name__ == "__main__":``.
    chunk_size
        Crossings per task; default about four tasks per worker, at most
        :data:`DEFAULT_CHUNK_SIZE`.  Results do not depend on it.
    progress
        ``True`` always shows a tqdm bar, ``False`` never, ``None`` once a run passes 1 s.
    iri
        Also compute the IRI of the road over each span (``iri_1``, ``iri_2`` [m/km]).
    dt
        Largest time step [s]; ``None`` lets each crossing pick ``0.1 / omega_max``.
    threads_per_task
        numba threads a task may use inside a worker of a user-given executor (the default
        pool always uses one; ``"serial"`` uses numba's default).

    Returns
    -------
    pandas.DataFrame
        Indexed like ``scenarios``.  Inputs as plain columns: the ``*_name`` labels,
        ``bridge_span`` [m], ``bridge_n_spans``, ``bridge_EI`` [N m^2],
        ``bridge_mass_per_length`` [kg/m], ``bridge_damping_ratio``, ``bridge_f1_hz``,
        ``vehicle_mass`` [kg], ``vehicle_stiffness`` [N/m], ``vehicle_damping`` [N s/m],
        ``vehicle_f_hz``, ``vehicle_damping_ratio``, ``profile_*`` (the recipe's fields),
        ``speed`` [m/s], ``bridge_start``, ``profile_offset`` [m], ``coupled``,
        ``convective``, ``modes`` and any ``tag_*`` columns; results: ``daf_1``, ``daf_2``
        (NaN for one span), ``daf`` (the larger), ``contact_force_amplification``,
        ``peak_contact_position`` [m] and ``peak_contact_time`` [s from the start] of the
        largest contact force on the bridge, ``dt`` [s] and, on request, ``iri_1``, ``iri_2``.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> s = grid(vbi.Bridge(30.0, 1, 2e10, 8000.0), vbi.Vehicle.from_frequency(3e4, 3.0),
    ...          FlatProfile(130.0, 0.05), [10.0, 20.0], 100.0)
    >>> run(s, "serial")["daf"].round(3).tolist()
    [1.025, 1.072]
    """
    table = validate(scenarios)
    n = len(table)
    if isinstance(executor, str):
        if executor != "serial":
            raise ValueError(f"executor={executor!r}: give an Executor, 'serial' or None")
        pool, threads = _Serial(), None
    elif executor is None:
        if n < SERIAL_BELOW:
            pool, threads = _Serial(), None
        else:
            pool, threads = default_executor(), 1
    elif isinstance(executor, cf.Executor):
        pool, threads = executor, threads_per_task
    else:
        raise TypeError(
            f"executor must be a concurrent.futures.Executor, 'serial' or None; got "
            f"{type(executor).__name__}"
        )
    workers = getattr(pool, "_max_workers", None) or os.cpu_count() or 1
    if chunk_size is None:
        chunk_size = max(1, min(DEFAULT_CHUNK_SIZE, math.ceil(n / (4 * workers))))
    elif not isinstance(chunk_size, int | np.integer) or chunk_size < 1:
        raise ValueError(f"chunk_size={chunk_size!r} must be a positive integer")
    if dt is not None:
        dt = check.positive("dt", dt)

    b_code, bridges = pd.factorize(table["bridge"])
    v_code, vehicles = pd.factorize(table["vehicle"])
    p_code, profiles = pd.factorize(table["profile"])
    arrays = {
        "speed": table["speed"].to_numpy(float),
        "start": table["bridge_start"].to_numpy(float),
        "offset": table["profile_offset"].to_numpy(float),
        "coupled": table["coupled"].to_numpy(bool),
        "convective": table["convective"].to_numpy(bool),
        "modes": table["modes"].to_numpy(np.int64),
    }
    # rows sharing a profile go to the same chunk so the worker builds it once
    order = np.lexsort((arrays["offset"], p_code))
    chunks = [order[i : i + chunk_size] for i in range(0, n, chunk_size)]

    def payload(rows: np.ndarray) -> dict[str, Any]:
        ub, b = np.unique(b_code[rows], return_inverse=True)
        uv, v = np.unique(v_code[rows], return_inverse=True)
        up, p = np.unique(p_code[rows], return_inverse=True)
        return {
            "bridges": [bridges[i] for i in ub],
            "vehicles": [vehicles[i] for i in uv],
            "profiles": [profiles[i] for i in up],
            "b": b,
            "v": v,
            "p": p,
            **{k: a[rows] for k, a in arrays.items()},
            "dt": dt,
            "iri": bool(iri),
            "threads": threads,
        }

    daf = np.full((n, 2), np.nan)
    force = np.full(n, np.nan)
    where = np.full(n, np.nan)
    steps = np.full(n, np.nan)
    iri_values = np.full((n, 2), np.nan)
    from tqdm import tqdm

    bar = tqdm(
        total=n,
        unit="crossing",
        disable=progress is False,
        delay=0.0 if progress else 1.0,
        smoothing=0.1,
    )
    if isinstance(pool, _Serial):
        import numba

        threads_before = numba.get_num_threads()
    in_flight: dict[cf.Future, np.ndarray] = {}
    limit = max(8, 3 * workers)
    pending = iter(chunks)
    try:
        while True:
            for rows in pending:
                in_flight[pool.submit(_run_chunk, payload(rows))] = rows
                if len(in_flight) >= limit:
                    break
            if not in_flight:
                break
            done, _ = cf.wait(list(in_flight), return_when=cf.FIRST_COMPLETED)
            for future in done:
                rows = in_flight.pop(future)
                try:
                    result = future.result()
                except BrokenProcessPool:
                    raise
                except Exception as exc:
                    raise RuntimeError(
                        f"crossings in {_rows(np.isin(np.arange(n), rows), table.index)} "
                        f"failed: {exc}"
                    ) from exc
                daf[rows] = result["daf"]
                force[rows] = result["contact_force_amplification"]
                where[rows] = result["peak_contact_position"]
                steps[rows] = result["dt"]
                if iri:
                    iri_values[rows] = result["iri"]
                bar.update(rows.size)
    except BrokenProcessPool as exc:
        raise RuntimeError(
            "a worker of the process pool died; in a script, start the study under "
            "`if __name__ == '__main__':` (worker processes are spawned and import the script)"
        ) from exc
    finally:
        for future in in_flight:
            future.cancel()
        bar.close()
        if isinstance(pool, _Serial):
            numba.set_num_threads(threads_before)

    out: dict[str, Any] = {}
    for kind, codes, objects in (
        ("bridge", b_code, bridges),
        ("vehicle", v_code, vehicles),
        ("profile", p_code, profiles),
    ):
        given = table[f"{kind}_name"] if f"{kind}_name" in table.columns else None
        labels = np.array(_labels(objects, kind), dtype=object)[codes]
        if given is not None:
            labels = np.where(given.isna().to_numpy(), labels, given.to_numpy(dtype=object))
        out[f"{kind}_name"] = labels
    bridge_cols = {
        "bridge_span": [x.span for x in bridges],
        "bridge_n_spans": [x.n_spans for x in bridges],
        "bridge_EI": [x.EI for x in bridges],
        "bridge_mass_per_length": [x.mass_per_length for x in bridges],
        "bridge_damping_ratio": [x.damping_ratio for x in bridges],
        "bridge_f1_hz": [x.first_frequency_hz for x in bridges],
    }
    vehicle_cols = {
        "vehicle_mass": [x.mass for x in vehicles],
        "vehicle_stiffness": [x.stiffness for x in vehicles],
        "vehicle_damping": [x.damping for x in vehicles],
        "vehicle_f_hz": [x.frequency_hz for x in vehicles],
        "vehicle_damping_ratio": [x.damping_ratio for x in vehicles],
    }
    for cols, codes in ((bridge_cols, b_code), (vehicle_cols, v_code)):
        for name, values in cols.items():
            out[name] = np.asarray(values)[codes]
    for name, values in _profile_columns(list(profiles)).items():
        column = pd.Series(values, dtype=object)
        numeric = pd.to_numeric(column, errors="coerce")
        if numeric.notna().sum() == column.notna().sum():
            column = numeric
        out[name] = column.to_numpy()[p_code]
    out["speed"] = arrays["speed"]
    out["bridge_start"] = arrays["start"]
    out["profile_offset"] = arrays["offset"]
    out["coupled"] = arrays["coupled"]
    out["convective"] = arrays["convective"]
    out["modes"] = arrays["modes"]
    for column in table.columns:
        if str(column).startswith(TAG_PREFIX):
            out[column] = table[column].to_numpy()
    out["daf_1"] = daf[:, 0]
    out["daf_2"] = daf[:, 1]
    out["daf"] = np.fmax(daf[:, 0], daf[:, 1])
    out["contact_force_amplification"] = force
    out["peak_contact_position"] = where
    starts = np.array([_extent(p)[0] for p in profiles])[p_code]
    out["peak_contact_time"] = (where - starts) / arrays["speed"]
    out["dt"] = steps
    if iri:
        out["iri_1"] = iri_values[:, 0]
        out["iri_2"] = iri_values[:, 1]
    return pd.DataFrame(out, index=table.index.copy())


# ---------------------------------------------------------------------------- saving
def save(results: pd.DataFrame, path: str | os.PathLike[str]) -> Path:
    """Write a results table to ``.parquet`` or ``.csv`` (never a half-written file).

    The table is written to a temporary file beside ``path`` and moved into place.

    Examples
    --------
    >>> import pandas as pd, tempfile, os
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = save(pd.DataFrame({"daf": [1.1, 1.2]}), os.path.join(d, "s.csv"))
    ...     load(p)["daf"].tolist()
    [1.1, 1.2]
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".parquet", ".pq", ".csv"):
        raise ValueError(f"path={str(path)!r}: save to a '.parquet' or '.csv' file")
    if not isinstance(results, pd.DataFrame):
        raise TypeError(f"results must be a pandas.DataFrame, got {type(results).__name__}")
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(handle)
    try:
        if suffix == ".csv":
            results.to_csv(temporary, index=False)
        else:
            results.to_parquet(temporary, index=False)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return path


def load(path: str | os.PathLike[str]) -> pd.DataFrame:
    """Read a table written by :func:`save` (``.parquet`` or ``.csv``)."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".csv":
        return pd.read_csv(path)
    if suffix in (".parquet", ".pq"):
        return pd.read_parquet(path)
    raise ValueError(f"path={str(path)!r}: load a '.parquet' or '.csv' file")


# ---------------------------------------------------------------------------- Monte Carlo
def _population(name: str, values: Any, kind: type) -> tuple[list[Any], list[str] | None]:
    items, labels = _axis(name, values)
    if not items:
        raise ValueError(f"{name} is empty; give at least one vbi.{kind.__name__}")
    bad = [i for i, v in enumerate(items) if not isinstance(v, kind)]
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


def characteristic_values(
    values: Any,
    quantiles: Sequence[float] = (0.95, 0.99),
    confidence: float = 0.95,
    allowance: float | None = None,
) -> pd.DataFrame:
    """Mean and upper percentiles of a DAF sample with confidence intervals.

    * mean: Student-t interval ``mean +/- t s / sqrt(n)``;
    * percentiles: the distribution-free order-statistic interval ``[x_(l), x_(u)]`` with
      ``l, u`` the binomial ``(n, q)`` quantiles at ``(1 -/+ confidence) / 2`` (an upper bound
      beyond the largest sample is ``inf``: too few crossings to bound it);
    * ``P(DAF > 1 + allowance)``: the fraction of crossings above the code's allowance with a
      Wilson score interval (default allowance AASHTO LRFD's 33 %, Table 3.6.2.1-1).

    Parameters
    ----------
    values
        DAF of each crossing (a column of :func:`run`'s table); NaN is an error.
    quantiles
        Probabilities of the percentiles reported.
    confidence
        Confidence level of the intervals.
    allowance
        Code allowance ``IM``; ``None`` uses AASHTO LRFD's 0.33.

    Returns
    -------
    pandas.DataFrame
        Rows ``mean``, ``p95``, ``p99`` (one per quantile), ``P(DAF > 1.33)``; columns
        ``estimate``, ``lower``, ``upper``.

    Examples
    --------
    >>> c = characteristic_values([1.0, 1.1, 1.2, 1.3, 1.4], quantiles=(0.5,))
    >>> c.loc["mean"].round(3).tolist()
    [1.2, 1.004, 1.396]
    """
    from scipy import stats

    from .amplification import aashto_lrfd_allowance

    x = np.sort(np.asarray(values, dtype=float).ravel())
    if x.size < 2:
        raise ValueError(f"characteristic_values needs at least two values; got {x.size}")
    if not np.isfinite(x).all():
        raise ValueError("values contain NaN or infinity; drop failed or missing crossings first")
    if not 0.0 < confidence < 1.0:
        raise ValueError(f"confidence={confidence!r} must be in (0, 1)")
    allowance = (
        aashto_lrfd_allowance() if allowance is None else check.non_negative("allowance", allowance)
    )
    n = x.size
    alpha = 1.0 - confidence
    rows: dict[str, tuple[float, float, float]] = {}
    mean = float(x.mean())
    half = float(stats.t.ppf(1 - alpha / 2, n - 1) * x.std(ddof=1) / math.sqrt(n))
    rows["mean"] = (mean, mean - half, mean + half)
    for q in quantiles:
        if not 0.0 < q < 1.0:
            raise ValueError(f"quantile {q!r} must be in (0, 1)")
        low = int(stats.binom.ppf(alpha / 2, n, q))  # order statistic x_(low), 1-based
        high = int(stats.binom.ppf(1 - alpha / 2, n, q)) + 1
        lower = float(x[low - 1]) if low >= 1 else -np.inf
        upper = float(x[high - 1]) if high <= n else np.inf
        rows[f"p{100 * q:g}"] = (float(np.quantile(x, q)), lower, upper)
    exceed = int((x > 1.0 + allowance).sum())
    p = exceed / n
    z = float(stats.norm.ppf(1 - alpha / 2))
    centre = (p + z**2 / (2 * n)) / (1 + z**2 / n)
    spread = z * math.sqrt(p * (1 - p) / n + z**2 / (4 * n**2)) / (1 + z**2 / n)
    rows[f"P(DAF > {1 + allowance:g})"] = (p, max(0.0, centre - spread), min(1.0, centre + spread))
    return pd.DataFrame.from_dict(rows, orient="index", columns=["estimate", "lower", "upper"])
