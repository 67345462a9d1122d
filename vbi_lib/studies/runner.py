"""The study runner: every row of a scenario table simulated in chunks on any executor.

Rows are cut into chunks; each chunk is one call of :func:`~vbi_lib.simulate_many` per model
(compiled, no time histories kept) inside a worker of a :class:`concurrent.futures.Executor`:
a local process pool by default, or any executor you pass, such as
``dask.distributed.Client(...).get_executor()``.  Every crossing depends only on its own row,
so the table is the same, bit for bit, whatever the executor and the chunk size.
"""

from __future__ import annotations

import concurrent.futures as cf
import math
import multiprocessing
import os
import warnings
from collections.abc import Sequence
from concurrent.futures.process import BrokenProcessPool
from dataclasses import asdict
from typing import Any

import numpy as np
import pandas as pd

from .. import _validation as check
from ..profiles import Profile
from ..ranges import outside_note
from ..road_checks import warn_implausible
from ..validity import ContactLossWarning, FailedRowsWarning, WorkerLostWarning
from ..vehicles import Vehicle, as_system
from .checks import TAG_PREFIX, _rows, validate
from .chunks import SUMMARIES, failure, init_worker, run_chunk
from .envelopes import SECTION_FIELDS, check_sections
from .recipes import extent, profile_label
from .workers import (
    death_reason,
    exit_statuses,
    lost_worker,
    missing_guard,
    processes,
    replacement,
)

#: Default number of crossings per chunk handed to a worker.
DEFAULT_CHUNK_SIZE = 250
#: Studies with fewer crossings than this run in this process by default.
SERIAL_BELOW = 1500


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
            initializer=init_worker,
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
            layout = (
                f"{obj.n_spans} x {obj.span:g} m"
                if obj.equal_spans
                else " + ".join(f"{s:g}" for s in obj.spans) + " m"
            )
            out.append(f"{layout}, {obj.first_frequency_hz:.2f} Hz")
        elif kind == "vehicle" and isinstance(obj, Vehicle):
            out.append(f"{obj.mass:.0f} kg, {obj.frequency_hz:.2f} Hz")
        elif kind == "vehicle":
            system = as_system(obj)
            out.append(f"{system.name or type(obj).__name__}, {system.total_mass:.0f} kg")
        else:
            out.append(profile_label(obj))
    return out


def _bridge_notes(bridge: Any) -> str | None:
    """The bridge's inputs outside their intended ranges, as a crossing's notes give them."""
    notes = (
        *(outside_note("span", length, "span") for length in sorted(set(bridge.spans))),
        outside_note("mass_per_length", bridge.mass_per_length),
        outside_note("bridge_frequency", bridge.first_frequency_hz, "first_frequency_hz"),
        outside_note("bridge_damping_ratio", bridge.damping_ratio, "damping_ratio"),
    )
    return "; ".join(n for n in notes if n) or None


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
    sections: Sequence[float] | np.ndarray | None = None,
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
        the study under ``if __name__ == "__main__":``.  A process pool whose worker dies is
        replaced by a new one of the same settings (:mod:`~vbi_lib.studies.workers`); the one
        given is then broken.
    chunk_size
        Crossings per task; default about four tasks per worker, at most
        :data:`DEFAULT_CHUNK_SIZE`.  Results do not depend on it.
    progress
        ``True`` always shows a tqdm bar, ``False`` never, ``None`` once a run passes 1 s.
    iri
        Also compute the IRI of the road over each span (``iri_1``, ``iri_2``, ... [m/km]).
    dt
        Largest time step [s]; ``None`` lets each crossing pick ``0.1 / omega_max``.
    threads_per_task
        numba threads a task may use inside a worker of a user-given executor (the default
        pool always uses one; ``"serial"`` uses numba's default).
    sections
        Stations from the bridge start [m] (on every bridge of the table) where the
        displacement, moment and shear are followed: each crossing then runs with its
        histories (:func:`vbi_lib.simulate`, slower than the batch kernel) and the table
        gains the columns of :mod:`vbi_lib.studies.envelopes` (``moment_max_1``,
        ``moment_daf_1``, ...); :func:`~vbi_lib.studies.envelope` takes their envelope.

    Returns
    -------
    pandas.DataFrame
        Indexed like ``scenarios``.  Inputs as plain columns: the ``*_name`` labels,
        ``bridge_span`` [m], ``bridge_n_spans``, ``bridge_EI`` [N m^2],
        ``bridge_mass_per_length`` [kg/m], ``bridge_damping_ratio``, ``bridge_f1_hz``,
        ``vehicle_mass`` [kg] (the whole vehicle's), ``vehicle_axles``, and for the study's
        sprung mass ``vehicle_stiffness`` [N/m], ``vehicle_damping`` [N s/m],
        ``vehicle_f_hz``, ``vehicle_damping_ratio`` (NaN for other vehicles),
        ``profile_*`` (the recipe's fields),
        ``speed`` [m/s], ``bridge_start``, ``profile_offset`` [m], ``coupled``,
        ``convective``, ``model``, ``modes`` and any ``tag_*`` columns; results: ``daf_1``,
        ``daf_2``, ... (one per span of the longest layout, at least two; NaN beyond a
        bridge's spans), ``daf`` (the largest), ``contact_force_amplification``,
        ``peak_contact_position`` [m] and ``peak_contact_time`` [s from the start; one-axle
        vehicles] of the largest contact force on the bridge; the contact checks
        ``min_contact_force_ratio`` (worst axle), ``tension_fraction``,
        ``flight_fraction`` (a tyre off the road, modelled), ``outside_validity`` (a
        bilateral contact became tensile: outside the model's validity; one
        ``ContactLossWarning`` says how many did) and ``lost_contact`` (either);
        ``dt`` [s]; the inputs outside their intended ranges, as sentences (text columns,
        missing when there are none): ``bridge_notes``, ``vehicle_notes`` (whatever the
        vehicle's constructors warned of, :attr:`~vbi_lib.vehicles.VehicleSystem.notes`)
        and ``profile_notes`` (a road given as data that is no plausible road,
        :mod:`vbi_lib.road_checks`); and, on request, ``iri_1``, ``iri_2``.  These columns
        are the same whatever the options (``sections``, the executor, the chunk size).
        When a row fails (its crossing
        cannot be run: too many time steps, say), its results are NaN, the other rows are
        kept, and an ``error`` column (present only then) gives the reason of each failed
        row (``None`` for the others).

    Raises
    ------
    TypeError, ValueError
        A table that :func:`~vbi_lib.studies.checks.validate` refuses (naming the rows),
        or a bad executor, chunk size or ``dt``; nothing has run.

    Warns
    -----
    ContactLossWarning
        Once, with how many crossings lost contact.
    FailedRowsWarning
        Once, naming the rows that failed and the first reason.
    WorkerLostWarning
        A worker of a process pool died (killed, perhaps out of memory): the chunks it held
        run again once, one at a time, in a new pool of the same settings; a chunk whose
        worker dies again keeps NaN results and the reason in ``error``; every finished row
        is kept.  (A Dask cluster reschedules such work itself.)
    OutsideValidityWarning
        A road given as a :class:`~vbi_lib.Profile` that is no plausible road (once each).

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> from vbi_lib.studies import FlatProfile, grid
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
    sections = check_sections(sections, list(bridges), table.index, b_code)
    width = max(2, *(b.n_spans for b in bridges))
    v_code, vehicles = pd.factorize(table["vehicle"])
    p_code, profiles = pd.factorize(table["profile"])
    for road in profiles:
        if isinstance(road, Profile):  # warned of here once, whatever the executor
            warn_implausible(road, reader="studies.run")
    arrays = {
        "speed": table["speed"].to_numpy(float),
        "start": table["bridge_start"].to_numpy(float),
        "offset": table["profile_offset"].to_numpy(float),
        "coupled": table["coupled"].to_numpy(bool),
        "convective": table["convective"].to_numpy(bool),
        "model": table["model"].to_numpy(dtype=object),
        "modes": table["modes"].to_numpy(dtype=object),
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
            "sections": sections,
            "width": width,
        }

    daf = np.full((n, width), np.nan)
    errors = np.full(n, None, dtype=object)
    summaries = {name: np.full(n, np.nan) for name in SUMMARIES}
    iri_values = np.full((n, width), np.nan)
    per_section = {
        name: np.full((n, 0 if sections is None else sections.size), np.nan)
        for name in SECTION_FIELDS
    }
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

    profile_notes = np.full(n, None, dtype=object)

    def record(rows: np.ndarray, result: dict[str, Any]) -> None:
        errors[rows] = result["error"]
        daf[rows] = result["daf"]
        profile_notes[rows] = result["profile_notes"]
        for name in SUMMARIES:
            summaries[name][rows] = result[name]
        if sections is not None:
            for name in SECTION_FIELDS:
                per_section[name][rows] = result[name]
        if iri:
            iri_values[rows] = result["iri"]

    owned: list[cf.Executor] = []  # pools made here to replace broken ones
    limit = max(8, 3 * workers)
    pending = list(range(len(chunks)))[::-1]  # chunk numbers, the next one last
    alone: list[int] = []  # chunks held by a worker that died: run again, one at a time
    tries = np.zeros(len(chunks), dtype=int)
    finished = 0
    in_flight: dict[cf.Future, int] = {}
    try:
        while pending or alone or in_flight:
            if alone:
                if not in_flight:
                    k = alone.pop()
                    in_flight[pool.submit(run_chunk, payload(chunks[k]))] = k
            else:
                while pending and len(in_flight) < limit:
                    k = pending.pop()
                    in_flight[pool.submit(run_chunk, payload(chunks[k]))] = k
            before = processes(pool)
            done, _ = cf.wait(list(in_flight), return_when=cf.FIRST_COMPLETED)
            broken = []
            for future in done:
                k = in_flight.pop(future)
                tries[k] += 1
                try:
                    record(chunks[k], future.result())
                    finished += 1
                except BrokenProcessPool:
                    broken.append(k)
                    continue
                except Exception as exc:  # noqa: BLE001 - the chunk's rows failed, not the run
                    errors[chunks[k]] = lost_worker(exc) or failure(exc)
                bar.update(chunks[k].size)
            if broken:  # the pool is dead: every chunk it held fails alike
                for future in list(in_flight):
                    tries[in_flight[future]] += 1
                    broken.append(in_flight.pop(future))
                pool.shutdown(wait=True, cancel_futures=True)
                statuses = exit_statuses(before)
                told = "; ".join(statuses) or "no exit status"
                script = missing_guard(pool) if not finished else None
                if script is not None:
                    raise RuntimeError(
                        f"the worker processes of the process pool died as they started "
                        f"({told}): the script {script} has no `if __name__ == '__main__':` "
                        "guard, so each spawned worker re-runs it; start the study under "
                        "that guard"
                    )
                again = [k for k in broken if tries[k] >= 2]
                for k in again:
                    errors[chunks[k]] = death_reason(statuses, again=True)
                    bar.update(chunks[k].size)
                alone += [k for k in broken if tries[k] < 2]
                warnings.warn(
                    f"a worker of the process pool died ({told}), perhaps out of memory: "
                    f"{len(broken) - len(again)} chunk(s) it held run again, one at a time, "
                    f"in a new pool; {len(again)} whose worker died on their second run keep "
                    "NaN and the reason in column error; every finished row is kept",
                    WorkerLostWarning,
                    stacklevel=2,
                )
                if executor is None:
                    pool = default_executor(workers)
                else:
                    pool = replacement(pool)
                    owned.append(pool)
    finally:
        for future in in_flight:
            future.cancel()
        for extra in owned:
            extra.shutdown(wait=True, cancel_futures=True)
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

    def sprung(name: str) -> list[float]:
        return [getattr(x, name) if isinstance(x, Vehicle) else np.nan for x in vehicles]

    vehicle_cols = {
        "vehicle_mass": [as_system(x).total_mass for x in vehicles],
        "vehicle_axles": [as_system(x).n_axles for x in vehicles],
        "vehicle_stiffness": sprung("stiffness"),
        "vehicle_damping": sprung("damping"),
        "vehicle_f_hz": sprung("frequency_hz"),
        "vehicle_damping_ratio": sprung("damping_ratio"),
    }
    for cols, codes in ((bridge_cols, b_code), (vehicle_cols, v_code)):
        for name, values in cols.items():
            out[name] = np.asarray(values)[codes]
    bridge_notes = np.array([_bridge_notes(x) for x in bridges], dtype=object)
    out["bridge_notes"] = pd.array(bridge_notes[b_code], dtype="str")
    vehicle_notes = np.array(["; ".join(as_system(x).notes) or None for x in vehicles], object)
    out["vehicle_notes"] = pd.array(vehicle_notes[v_code], dtype="str")
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
    out["model"] = arrays["model"]
    out["modes"] = table["modes"].to_numpy()
    for column in table.columns:
        if str(column).startswith(TAG_PREFIX):
            out[column] = table[column].to_numpy()
    for j in range(width):
        out[f"daf_{j + 1}"] = daf[:, j]
    out["daf"] = np.fmax.reduce(daf, axis=1)
    out["contact_force_amplification"] = summaries["contact_force_amplification"]
    out["peak_contact_position"] = where = summaries["peak_contact_position"]
    starts = np.array([extent(p)[0] for p in profiles])[p_code]
    one_axle = np.array([as_system(x).n_axles == 1 for x in vehicles])[v_code]
    out["peak_contact_time"] = np.where(one_axle, (where - starts) / arrays["speed"], np.nan)
    out["min_contact_force_ratio"] = summaries["min_contact_force_ratio"]
    out["tension_fraction"] = summaries["tension_fraction"]
    out["flight_fraction"] = summaries["flight_fraction"]
    out["outside_validity"] = lost = summaries["min_contact_force_ratio"] < 0
    out["lost_contact"] = lost | (summaries["flight_fraction"] > 0)
    out["dt"] = summaries["dt"]
    out["profile_notes"] = pd.array(profile_notes, dtype="str")
    if lost.any():
        warnings.warn(
            f"{int(lost.sum())} of {n} crossings lost contact (column lost_contact): the "
            "contact force became tensile, which the model's contact assumption excludes; "
            "their DAFs are outside the model's validity",
            ContactLossWarning,
            stacklevel=2,
        )
    if iri:
        for j in range(width):
            out[f"iri_{j + 1}"] = iri_values[:, j]
    if sections is not None:
        for k, station in enumerate(sections):
            out[f"section_{k + 1}"] = np.full(n, station)
            for name in SECTION_FIELDS:
                out[f"{name}_{k + 1}"] = per_section[name][:, k]
    failed = errors != None  # noqa: E711
    if failed.any():
        out["error"] = errors
        first = int(np.flatnonzero(failed)[0])
        warnings.warn(
            f"{int(failed.sum())} of {n} crossings failed and have no results (column error; "
            f"the others are kept): {_rows(failed, table.index, limit=20)}; row "
            f"{table.index[first]!r}: {errors[first]}",
            FailedRowsWarning,
            stacklevel=2,
        )
    return pd.DataFrame(out, index=table.index.copy())
