"""What a report computes: the DAF of each effect at each place, its sweep, envelopes, the road.

Each result type exports itself (``to_dataframe()``) and plots itself (``plot(ax=...)``), in
the display units of :mod:`vbi_lib.display`.

**The DAF of a place and effect** is the crossing's :meth:`~vbi_lib.Crossing.sections`: the
extreme of the effect there over the whole crossing, by the mode-acceleration method, over
its extreme when the same axles crawl across (exact influence lines), in the sense in which
the static extreme is larger (:mod:`vbi_lib.models.sections`).  Every place is run in each
direction asked, at each requested speed, with the model of :mod:`.inputs` (the study's
one-coordinate model for its sprung mass on one span or two equal spans, else the modal
model).  At an interior support the shear is given on both faces.  A backward crossing is
run on the bridge seen from its far end; its stations, faces and signs are turned back, so
every station, face and sign here is the forward one (shear ``V = dM/dx`` with ``x`` from the
first support).

**The design truck's rear spacing.**  Given a range, the spacing that governs each place,
effect and face is found from the statics first
(:func:`vbi_lib.vehicles.governing_rear_spacing`), and each row is the crossing of the truck
with its governing spacing.

**Validity.**  A crossing whose bilateral contact became tensile (the study's sprung mass
pulling on the road) is outside the model's validity: ``lost_contact``, never taken as a
result.  A tyre that leaves the road is modelled (``flight_fraction``, :class:`Flights`),
and said.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .. import display
from ..beam_statics import EFFECTS, QUANTITY, field_envelope
from ..bridges import Bridge
from ..models import Crossing, SectionResponse, simulate, simulate_many
from ..profiles import Profile
from ..vehicles.fleet import RearSpacingSearch, governing_rear_spacing
from .along import Envelopes, Flights, envelopes, flights, flip, vehicle_label
from .codes import Allowances, allowances, loaded_length
from .columns import Column, columns
from .columns import entries as station_entries
from .inputs import ReportInputs, sweep_speeds, vehicle_at
from .road import (
    PositionStudy,
    SpanRoughness,
    SpeedStudy,
    position_study,
    quiet,
    shifted_deck,
    span_roughness,
    speed_study,
)

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "Allowances",
    "Column",
    "Envelopes",
    "Flights",
    "PositionStudy",
    "ReportAnalysis",
    "SectionStudy",
    "SpanRoughness",
    "SpeedStudy",
    "Sweep",
    "allowances",
    "analyse",
    "columns",
    "loaded_length",
    "position_study",
    "shifted_deck",
    "span_roughness",
    "speed_study",
]

#: Speeds of the sweep: (full, quick), for the study's model and for the modal model.
SWEEP_COUNTS = {"one-coordinate": (40, 12), "modal": (12, 6)}
#: Positions of the deck's roughness tried: (full, quick), same keys.
POSITION_COUNTS = {"one-coordinate": (24, 8), "modal": (3, 2)}
#: Stations of the envelopes along the bridge: (full, quick).
FIELD_COUNTS = (49, 25)
#: The JSON's row keys, in order (SI units).
ROW_KEYS = (
    "speed_m_s", "section_m", "effect", "direction", "daf", "static", "dynamic",
    "lost_contact", "flight_fraction", "face", "sense", "place", "rear_axle_spacing_m", "valid",
)  # fmt: skip


# ---------------------------------------------------------------------------- the crossings
@dataclass(frozen=True, eq=False)
class _Runs:
    """Crossings and their section responses, by (direction, rear spacing, speed)."""

    crossings: dict
    responses: dict
    notes: list


def _run(
    inputs: ReportInputs,
    vehicle: object,
    direction: str,
    speed: float,
    entries: list[tuple[float, str]],
) -> tuple[Crossing, SectionResponse, list[str]]:
    """One crossing in ``direction`` and its sections at ``entries`` (forward stations)."""
    run = inputs.run(direction, speed)
    x = inputs.to_run(np.array([e[0] for e in entries]), direction)
    faces = tuple(f if direction == "forward" else flip(f) for _, f in entries)
    options = {"model": inputs.model}
    if inputs.modes is not None:
        options["modes"] = inputs.modes
    crossing, said = quiet(
        simulate, run.bridge, vehicle, run.road, speed, run.bridge_start, **options
    )
    return crossing, crossing.sections(x, side=faces), said


def _values(response: SectionResponse, direction: str, e: int, i: int) -> tuple:
    """DAF, static and dynamic extreme (forward signs) and the sense at entry ``i``."""
    governing = response.governing[e, i] > 0
    static = (response.static.maximum if governing else response.static.minimum)[e, i]
    dynamic = (response.maximum if governing else response.minimum)[e, i]
    sense = "max" if governing else "min"
    if direction == "backward" and EFFECTS[e] == "shear":  # V = dM/dx turns sign with x
        static, dynamic, sense = -static, -dynamic, "min" if governing else "max"
    return float(response.daf[e, i]), float(static), float(dynamic), sense


@dataclass(frozen=True, eq=False)
class SectionStudy:
    """The DAF of each effect at each place, per requested speed and direction.

    ``rows`` holds one row per speed, place, effect (and face) and direction, in SI: the
    keys of :data:`ROW_KEYS` (the report's JSON), ``column`` (index into ``columns``) and
    ``crossing`` (the key of the crossing it comes from).
    """

    columns: tuple[Column, ...]
    rows: pd.DataFrame

    def largest(self, c: int) -> pd.Series | None:
        """The row of the largest valid DAF of column ``c``, ``None`` if none is valid."""
        rows = self.rows[(self.rows.column == c) & self.rows.valid & self.rows.daf.notna()]
        return None if rows.empty else rows.loc[rows.daf.idxmax()]

    def to_dataframe(self) -> pd.DataFrame:
        """The rows in display units: speed, direction, place, effect, face, static and
        dynamic extremes, DAF, the contact checks."""
        out = []
        for _, row in self.rows.iterrows():
            quantity = QUANTITY[row.effect]
            out.append({
                display.label("speed", "speed"): display.value(row.speed_m_s, "speed"),
                "direction": row.direction,
                "place": row.place,
                display.label("station", "length"): display.value(row.section_m, "length"),
                "effect": row.effect,
                "face": row.face,
                "unit": display.symbol(quantity),
                "static": display.value(row.static, quantity),
                "dynamic": display.value(row.dynamic, quantity),
                "DAF": row.daf,
                "contact lost": row.lost_contact,
                "tyre off the road [fraction of the time]": row.flight_fraction,
            })  # fmt: skip
        return pd.DataFrame(out)

    def plot(self, ax: Axes | None = None, allowance: float | None = None) -> Axes:
        """The largest valid DAF of each place and effect, as horizontal bars."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 0.3 * len(self.columns) + 1))
        best = [self.largest(c) for c in range(len(self.columns))]
        labels = [f"{col.label}: {col.effect}" for col in self.columns]
        values = [np.nan if b is None else b.daf for b in best]
        ax.barh(labels, values, color=[f"C{EFFECTS.index(c.effect)}" for c in self.columns])
        if allowance is not None:
            ax.axvline(allowance, color="k", ls=":", label="AASHTO LRFD (1 + IM)")
            ax.legend(loc="lower right", fontsize="small")
        ax.invert_yaxis()
        ax.set_xlabel("largest DAF at the requested speeds [-]")
        return ax


def _section_study(
    inputs: ReportInputs,
    cols: tuple[Column, ...],
    entries: list[tuple[float, str]],
    spacing_of: list[float | None],
    runs: _Runs,
) -> SectionStudy:
    rows = []
    for c, col in enumerate(cols):
        e, i = EFFECTS.index(col.effect), entries.index(col.key)
        for direction in inputs.directions:
            for speed in inputs.speeds:
                key = (direction, spacing_of[c], speed)
                crossing, response = runs.crossings[key], runs.responses[key]
                daf, static, dynamic, sense = _values(response, direction, e, i)
                rows.append({
                    "speed_m_s": float(speed),
                    "section_m": float(col.place.x),
                    "effect": col.effect,
                    "direction": direction,
                    "daf": daf,
                    "static": static,
                    "dynamic": dynamic,
                    "lost_contact": bool(crossing.lost_contact),
                    "flight_fraction": float(crossing.flight_fraction),
                    "face": col.face,
                    "sense": sense,
                    "place": col.place.name,
                    "rear_axle_spacing_m": spacing_of[c],
                    "valid": not bool(crossing.lost_contact),
                    "min_contact_force_ratio": float(crossing.min_contact_force_ratio),
                    "column": c,
                    "crossing": key,
                })  # fmt: skip
    return SectionStudy(cols, pd.DataFrame(rows))


# ---------------------------------------------------------------------------- the sweep
@dataclass(frozen=True, eq=False)
class Sweep:
    """The DAF of each place and effect against speed, per direction.

    ``daf`` is ``(n_directions, n_speeds, n_columns)``; ``lost`` ``(n_directions,
    n_speeds)`` marks crossings whose bilateral contact became tensile (outside validity),
    ``flight`` the fraction of the time a tyre was off the road.
    """

    speeds: np.ndarray
    directions: tuple[str, ...]
    columns: tuple[Column, ...]
    daf: np.ndarray
    lost: np.ndarray
    flight: np.ndarray
    vehicle: str

    def to_dataframe(self) -> pd.DataFrame:
        """One row per direction and speed: the DAF of every place and effect."""
        rows = []
        for d, direction in enumerate(self.directions):
            for s, speed in enumerate(self.speeds):
                row = {
                    display.label("speed", "speed"): display.value(speed, "speed"),
                    "direction": direction,
                    "contact lost": bool(self.lost[d, s]),
                }
                for c, col in enumerate(self.columns):
                    row[f"{col.label}: {col.effect}"] = self.daf[d, s, c]
                rows.append(row)
        return pd.DataFrame(rows)

    def plot(self, ax: Axes | None = None, effect: str = "moment",
             allowance: float | None = None) -> Axes:  # fmt: skip
        """DAF of ``effect`` against speed at every place (solid forward, dashed backward);
        lost contact crossed out."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        v = display.value(self.speeds, "speed")
        shown = [c for c, col in enumerate(self.columns) if col.effect == effect]
        for k, c in enumerate(shown):
            color = f"C{k % 10}"
            for d, direction in enumerate(self.directions):
                y = np.where(self.lost[d], np.nan, self.daf[d, :, c])
                label = self.columns[c].label if d == 0 else None
                ax.plot(v, y, "-" if direction == "forward" else "--", color=color, lw=1.2,
                        label=label)  # fmt: skip
                lost = self.lost[d]
                ax.plot(v[lost], self.daf[d, lost, c], "x", color=color, ms=5)
        if self.lost.any():
            ax.plot([], [], "x", color="k", label="contact lost: outside validity")
        if allowance is not None:
            ax.axhline(allowance, color="k", lw=1, ls=":", label="AASHTO LRFD (1 + IM)")
        ax.set_xlabel(display.label("speed", "speed"))
        ax.set_ylabel(f"DAF of the {effect} [-]")
        ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize="x-small",
                  frameon=False)  # fmt: skip
        return ax


# ---------------------------------------------------------------------------- everything
@dataclass(frozen=True, eq=False)
class ReportAnalysis:
    """Everything a report shows (see :func:`analyse`)."""

    inputs: ReportInputs
    sections: SectionStudy
    sweep: Sweep
    envelopes: Envelopes
    flights: Flights
    position: PositionStudy
    roughness: SpanRoughness
    allowances: Allowances
    worst: Crossing
    worst_key: tuple
    vehicles: dict
    spacing_search: RearSpacingSearch | None = None
    requested: SpeedStudy | None = None
    notes: tuple[str, ...] = field(default=())

    def to_dataframe(self) -> pd.DataFrame:
        """The DAF of every place and effect at the requested speeds
        (:meth:`SectionStudy.to_dataframe`)."""
        return self.sections.to_dataframe()

    def plot(self, ax: Axes | None = None) -> Axes:
        """The largest DAF of each place and effect with the AASHTO LRFD value."""
        return self.sections.plot(ax, allowance=self.allowances.aashto_lrfd)

    def results(self) -> list[dict]:
        """The rows of the report's JSON: one per speed, place, effect (face) and direction,
        SI units, the keys of :data:`ROW_KEYS`; NaN as ``None``."""
        out = []
        for record in self.sections.rows[list(ROW_KEYS)].to_dict(orient="records"):
            out.append({
                k: (None if isinstance(v, float) and not np.isfinite(v) else v)
                for k, v in record.items()
            })  # fmt: skip
        return out


def _spacings(
    inputs: ReportInputs, cols: tuple[Column, ...]
) -> tuple[list, RearSpacingSearch | None]:
    """The rear spacing each column runs with, and the search (for a design truck's range):
    each column's own, its shear on its own face."""
    spacing = inputs.parameters.vehicle.rear_axle_spacing
    if spacing is None:
        return [None] * len(cols), None
    low, high = spacing
    if high - low < 1e-9:
        return [low] * len(cols), None
    search = governing_rear_spacing(
        inputs.bridge.spans, inputs.bridge.EI, [col.place.x for col in cols], low, high,
        direction=inputs.parameters.direction, side=[col.face or "both" for col in cols],
    )  # fmt: skip
    out = [float(search.governing[EFFECTS.index(col.effect), c]) for c, col in enumerate(cols)]
    return out, search


def analyse(inputs: ReportInputs, quick: bool | None = None) -> ReportAnalysis:
    """Run every crossing a report needs.

    In each direction asked and at each requested speed, a crossing of the vehicle (of each
    governing rear spacing of a design truck given a range) and its sections; a sweep of
    speeds from half the slowest to 1.2 times the fastest (:data:`SWEEP_COUNTS`) in each
    direction; the static and dynamic envelopes along the bridge; the deck moved along the
    bridge (:data:`POSITION_COUNTS`, forward); the flights of the tyres; the code values.
    For the study's own case also its span DAF, coupled and decoupled (the bound).

    Parameters
    ----------
    inputs
        From :func:`~vbi_lib.reports.inputs.prepare`.
    quick
        Fewer points in the sweeps; ``None`` takes ``inputs.parameters.quick``.

    Returns
    -------
    ReportAnalysis
    """
    quick = inputs.parameters.quick if quick is None else bool(quick)
    cols = columns(inputs)
    entries = station_entries(cols)
    spacing_of, search = _spacings(inputs, cols)
    vehicles = {s: inputs.vehicles.get(s) or vehicle_at(inputs.parameters, s)
                for s in dict.fromkeys(spacing_of)}  # fmt: skip
    counts = Counter(spacing_of)
    main = min(counts, key=lambda s: (-counts[s], s if s is not None else 0.0))
    crossings, responses, notes = {}, {}, []
    for direction in inputs.directions:
        for spacing, vehicle in vehicles.items():
            for speed in inputs.speeds:
                crossing, response, said = _run(inputs, vehicle, direction, speed, entries)
                crossings[direction, spacing, speed] = crossing
                responses[direction, spacing, speed] = response
                notes += said
    runs = _Runs(crossings, responses, notes)
    study = _section_study(inputs, cols, entries, spacing_of, runs)
    # the sweep, with the vehicle of the main spacing
    count = SWEEP_COUNTS[inputs.model][1 if quick else 0]
    speeds = sweep_speeds(inputs.speeds, count)
    daf = np.full((len(inputs.directions), speeds.size, len(cols)), np.nan)
    lost = np.zeros((len(inputs.directions), speeds.size), dtype=bool)
    flight = np.zeros_like(daf[..., 0])
    for d, direction in enumerate(inputs.directions):
        for s, speed in enumerate(speeds):
            crossing, response, said = _run(inputs, vehicles[main], direction, speed, entries)
            notes += said
            lost[d, s] = crossing.lost_contact
            flight[d, s] = crossing.flight_fraction
            for c, col in enumerate(cols):
                e, i = EFFECTS.index(col.effect), entries.index(col.key)
                daf[d, s, c] = _values(response, direction, e, i)[0]
    sweep = Sweep(speeds, inputs.directions, cols, daf, lost, flight,
                  vehicle_label(vehicles[main]))  # fmt: skip
    along = envelopes(inputs, vehicles[main], runs.crossings, main,
                      FIELD_COUNTS[1 if quick else 0])  # fmt: skip
    # the worst valid requested crossing
    valid = study.rows[study.rows.valid & study.rows.daf.notna()]
    pool = valid if not valid.empty else study.rows[study.rows.daf.notna()]
    worst_key = pool.loc[pool.daf.idxmax(), "crossing"] if not pool.empty else next(iter(crossings))
    requested = None
    if inputs.study_case:
        requested = speed_study(inputs, np.asarray(inputs.speeds))
    position = position_study(
        inputs, POSITION_COUNTS[inputs.model][1 if quick else 0], vehicles[main]
    )
    return ReportAnalysis(
        inputs=inputs,
        sections=study,
        sweep=sweep,
        envelopes=along,
        flights=flights(inputs, runs.crossings),
        position=position,
        roughness=span_roughness(inputs),
        allowances=allowances(inputs.bridge, cols),
        worst=crossings[worst_key],
        worst_key=worst_key,
        vehicles=vehicles,
        spacing_search=search,
        requested=requested,
        notes=tuple(dict.fromkeys(notes)),
    )


def warm_up() -> None:
    """Run two tiny crossings and their sections (each model once, and a batch), so that the
    compiled kernels are loaded before a real report.

    A fresh process loads numba's cached machine code on first call (about two seconds);
    the report runner has its kernel call this first, while it prepares the rest.
    """
    from ..vehicles import Vehicle
    from ..vehicles.fleet import hs20

    road = Profile.flat(50.0, 0.1)
    one = Bridge(10.0, 1, 2e9, 5000.0)
    truck = Vehicle.from_frequency(2e4, 3.0, 0.1)
    quiet(simulate, one, truck, road, 14.0, 12.0)[0].sections([5.0])
    quiet(simulate_many, one, truck, [road, road], [14.0, 15.0], 12.0)
    two = Bridge.continuous([10.0, 12.0], EI=2e9, mass_per_length=5000.0)
    run, _ = quiet(simulate, two, hs20(), road, 14.0, 12.0, model="modal", modes=2)
    run.sections([5.0, 10.0, 10.0], side=("left", "left", "right"))
    field_envelope(two.spans, two.EI, [1.0, 2.0], [0.0, 3.0], count=11)
