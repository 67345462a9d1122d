"""What a worker runs: one chunk of a study's rows, a failure kept to the row at fault.

:func:`run_chunk` builds each row's road (the profile, or its recipe, slid by the row's
offset), runs the rows of each crossing model as one :func:`~vbi_lib.simulate_many` batch
(or one :func:`~vbi_lib.simulate` per row when sections are followed) and, on request, the
IRI of each span.  A row that fails keeps NaN results and its reason in the ``error`` array;
a batch that fails is run again one crossing at a time to find the rows at fault, so the
others are never lost (:func:`vbi_lib.studies.run` reports the failed rows).
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np

from ..bridges import Bridge
from ..profiles import Profile
from ..road_checks import inherit, road_notes
from ..validity import ContactLossWarning
from .envelopes import SECTION_FIELDS, section_columns

__all__ = ["SUMMARIES", "crossing_summaries", "failure", "init_worker", "run_chunk", "set_threads"]


def set_threads(threads: int | None) -> None:
    """Let numba use ``threads`` threads in this process (``None`` or 0: leave it as it is)."""
    if threads:
        import numba

        numba.set_num_threads(max(1, min(int(threads), numba.config.NUMBA_NUM_THREADS)))


def init_worker() -> None:
    """Process-pool initializer: one numba thread per worker; Ctrl-C is the parent's."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    set_threads(1)


def _road(profile: Profile, offset: float) -> Profile:
    """The road slid back by ``offset``: at station ``x`` it has the profile's ``x + offset``.

    ``profile.segment(start + offset, end).shifted(-offset)``, number for number, with one
    copy of the samples instead of two and one interpolation instead of one per sample
    (a Monte Carlo study makes one road per crossing).
    """
    if offset == 0.0:
        return profile
    x, elevation = profile.x, profile.elevation
    cut = x[0] + offset
    if not x[0] <= cut < x[-1]:
        profile.segment(cut, x[-1])  # raises with the message naming the stations
    first = np.searchsorted(x, cut, side="right")  # the samples after the cut
    stations = np.empty(x.size - first + 1)
    stations[0] = cut
    stations[1:] = x[first:]
    heights = np.empty(stations.size)
    heights[0] = np.interp(cut, x, elevation)
    heights[1:] = elevation[first:]
    return inherit(profile, Profile(stations + -offset, heights, name=profile.name))


def _iri_of_spans(road: Profile, bridge: Bridge, start: float, width: int) -> np.ndarray:
    """IRI [m/km] of the road over each span (the golden car starts on the bridge).

    Equal spans: one run over the deck in segments of a span; unequal spans: one run per
    span (the car starts afresh on each).
    """
    from ..roughness import iri  # imported only when a study asks for IRI

    out = np.full(width, np.nan)
    if bridge.equal_spans:
        deck = road.segment(start, start + bridge.length)
        values = iri(deck, segment_length=bridge.span).segment_iri
        out[: bridge.n_spans] = np.asarray(values, dtype=float)[: bridge.n_spans]
    else:
        supports = start + np.array(bridge.supports)
        for j in range(bridge.n_spans):
            out[j] = iri(road.segment(supports[j], supports[j + 1])).iri
    return out


SUMMARIES = (
    "contact_force_amplification",
    "peak_contact_position",
    "min_contact_force_ratio",
    "tension_fraction",
    "flight_fraction",
    "dt",
)


def failure(exc: BaseException) -> str:
    """One line for the ``error`` column: the exception's type and message."""
    text = str(exc)
    if text.startswith("crossing 0: "):  # simulate_many's prefix for a one-crossing batch
        text = text[len("crossing 0: ") :]
    return f"{type(exc).__name__}: {text}"


def _run_sections(payload: dict[str, Any], road: list, out: dict[str, Any]) -> None:
    """Crossings one at a time with their histories, for the responses at the sections."""
    sections = payload["sections"]
    for i in range(payload["speed"].size):
        if out["error"][i] is None:
            try:
                _one_with_sections(payload, road, out, sections, i)
            except Exception as exc:  # noqa: BLE001 - recorded for this row, the others run
                out["error"][i] = failure(exc)


def _one_with_sections(
    payload: dict[str, Any], road: list, out: dict[str, Any], sections: np.ndarray, i: int
) -> None:
    """One crossing of a chunk with its histories; its section columns into ``out``."""
    from ..models import simulate

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ContactLossWarning)
        crossing = simulate(
            payload["bridges"][payload["b"][i]],
            payload["vehicles"][payload["v"][i]],
            road[i],
            payload["speed"][i],
            payload["start"][i],
            model=payload["model"][i],
            modes=int(payload["modes"][i]) if payload["model"][i] == "modal" else None,
            coupled=bool(payload["coupled"][i]),
            convective=bool(payload["convective"][i]),
            dt=payload["dt"],
        )
    out["daf"][i, : crossing.daf.size] = crossing.daf
    for name, value in crossing_summaries(crossing).items():
        out[name][i] = value
    for name, values in section_columns(crossing.sections(sections)).items():
        out[name][i] = values


def crossing_summaries(crossing: Any) -> dict[str, float]:
    """The :data:`SUMMARIES` of one :class:`~vbi_lib.models.results.Crossing`, as
    :func:`~vbi_lib.simulate_many` gives them: every validity field, whatever way the
    crossing ran (the largest contact force is the worst axle's over its static load, at
    that axle's station)."""
    ratio = crossing.axle_contact_force_ratio
    on = crossing.axle_on_bridge
    node, axle = np.unravel_index(np.argmax(np.where(on, ratio, -np.inf)), ratio.shape)
    values = {
        "contact_force_amplification": crossing.contact_force_amplification,
        "peak_contact_position": crossing.axle_position[node, axle],
        "min_contact_force_ratio": crossing.min_contact_force_ratio,
        "tension_fraction": crossing.tension_fraction,
        "flight_fraction": crossing.flight_fraction,
        "dt": crossing.dt,
    }
    assert set(values) == set(SUMMARIES)  # noqa: S101 - a field added to one and not the other
    return values


def _batch(payload: dict[str, Any], road: list, rows: np.ndarray, name: str) -> Any:
    """:func:`~vbi_lib.simulate_many` over ``rows`` of a chunk, all of model ``name``."""
    from ..models import simulate_many

    b, v, modes = payload["b"], payload["v"], payload["modes"]
    with warnings.catch_warnings():
        # the table's columns say which crossings lost contact; run() warns once
        warnings.simplefilter("ignore", ContactLossWarning)
        return simulate_many(
            [payload["bridges"][b[i]] for i in rows],
            [payload["vehicles"][v[i]] for i in rows],
            [road[i] for i in rows],
            payload["speed"][rows],
            payload["start"][rows],
            model=name,
            modes=[int(m) for m in modes[rows]] if name == "modal" else None,
            coupled=list(payload["coupled"][rows]),
            convective=list(payload["convective"][rows]),
            dt=payload["dt"],
        )


def _roads(payload: dict[str, Any], error: np.ndarray) -> list:
    """The road of each row (the profile slid by its offset); ``None`` and an error for rows
    whose road cannot be built."""
    p, offset = payload["p"], payload["offset"]
    built: dict[int, Any] = {}
    roads: dict[tuple[int, float], Any] = {}
    out: list = []
    for i in range(p.size):
        key = (int(p[i]), float(offset[i]))
        if key not in roads:
            try:
                if key[0] not in built:
                    given = payload["profiles"][key[0]]
                    built[key[0]] = given if isinstance(given, Profile) else given.build()
                roads[key] = _road(built[key[0]], key[1])
            except Exception as exc:  # noqa: BLE001 - recorded for its rows
                roads[key] = failure(exc)
        if isinstance(roads[key], str):
            error[i] = roads[key]
            out.append(None)
        else:
            out.append(roads[key])
    return out


def run_chunk(payload: dict[str, Any]) -> dict[str, np.ndarray]:
    """Simulate one chunk of scenarios (runs inside a worker; keeps no time histories).

    A row that fails keeps NaN results and its reason in ``error``; the others run: a batch
    that fails is run again one crossing at a time to find the rows at fault.
    """
    set_threads(payload["threads"])
    b, start, model = payload["b"], payload["start"], payload["model"]
    n = payload["speed"].size
    out: dict[str, np.ndarray] = {"error": np.full(n, None, dtype=object)}
    road = _roads(payload, out["error"])
    notes = [None if r is None else "; ".join(road_notes(r)) or None for r in road]
    out["profile_notes"] = np.array(notes, dtype=object)
    out["daf"] = np.full((n, payload["width"]), np.nan)
    out |= {name: np.full(n, np.nan) for name in SUMMARIES}
    if payload["sections"] is not None:
        count = payload["sections"].size
        out |= {name: np.full((n, count), np.nan) for name in SECTION_FIELDS}
        _run_sections(payload, road, out)
        names: dict = {}  # every crossing is done
    else:
        names = dict.fromkeys(model)
    for name in names:
        rows = np.flatnonzero((model == name) & (out["error"] == None))  # noqa: E711
        if not rows.size:
            continue
        try:
            results = [(rows, _batch(payload, road, rows, name))]
        except Exception:  # noqa: BLE001 - find the rows at fault, keep the others
            results = []
            for i in rows:
                try:
                    results.append((np.array([i]), _batch(payload, road, np.array([i]), name)))
                except Exception as exc:  # noqa: BLE001
                    out["error"][i] = failure(exc)
        for done, result in results:
            out["daf"][done, : result.daf.shape[1]] = result.daf
            for column in SUMMARIES:
                out[column][done] = getattr(result, column)
    if payload["iri"]:
        out["iri"] = np.full((n, payload["width"]), np.nan)
        spans: dict[tuple[int, int, float], np.ndarray] = {}
        for i in np.flatnonzero(out["error"] == None):  # noqa: E711
            key = (id(road[i]), int(b[i]), float(start[i]))
            try:
                if key not in spans:
                    bridge = payload["bridges"][b[i]]
                    spans[key] = _iri_of_spans(road[i], bridge, start[i], payload["width"])
                out["iri"][i] = spans[key]
            except Exception as exc:  # noqa: BLE001
                out["error"][i] = failure(exc)
    return out
