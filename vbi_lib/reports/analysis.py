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

import warnings
from collections import Counter
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .. import amplification as amp
from .. import display
from ..beam_statics import EFFECTS, QUANTITY, StaticEnvelope, field_envelope
from ..bridges import Bridge
from ..models import BatchResult, Crossing, SectionResponse, simulate, simulate_many
from ..profiles import Profile, iso8608_class
from ..roughness import fit_iso8608, iri
from ..units import ft
from ..validity import VbiWarning
from ..vehicles import as_system
from ..vehicles.fleet import RearSpacingSearch, governing_rear_spacing
from .inputs import Place, ReportInputs, sweep_speeds, vehicle_at

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
    "position_study",
    "span_roughness",
    "speed_study",
]

#: Speeds of the sweep: (full, quick), for the study's model and for the modal model.
SWEEP_COUNTS = {"one-coordinate": (40, 12), "modal": (12, 6)}
#: Positions of the deck's roughness tried: (full, quick), same keys.
POSITION_COUNTS = {"one-coordinate": (24, 8), "modal": (4, 3)}
#: Stations of the envelopes along the bridge: (full, quick).
FIELD_COUNTS = (61, 31)
#: The JSON's row keys, in order (SI units).
ROW_KEYS = (
    "speed_m_s", "section_m", "effect", "direction", "daf", "static", "dynamic",
    "lost_contact", "flight_fraction", "face", "sense", "place", "rear_axle_spacing_m", "valid",
)  # fmt: skip


def _quiet(function, *args, **kwargs):  # noqa: ANN001, ANN002, ANN003, ANN202
    """Call ``function`` with the library's warnings kept, not shown: (result, messages)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", VbiWarning)
        result = function(*args, **kwargs)
    return result, [str(w.message) for w in caught if issubclass(w.category, VbiWarning)]


def vehicle_label(vehicle: object) -> str:
    """How the report names a vehicle: the design truck's own name, else what it is."""
    from ..vehicles import QuarterCar, Vehicle

    if isinstance(vehicle, Vehicle):
        return "the truck (the study's sprung mass)"
    if isinstance(vehicle, QuarterCar):
        return "the truck (a quarter car)"
    return as_system(vehicle).name or "the vehicle"


def _flip(face: str) -> str:
    return {"left": "right", "right": "left"}.get(face, face)


# ---------------------------------------------------------------------------- columns
@dataclass(frozen=True)
class Column:
    """One result of a crossing: an effect at a place, on one face for a support's shear."""

    place: Place
    effect: str
    face: str = ""

    @property
    def label(self) -> str:
        """``"pier 1 (interior support), left face"``."""
        return self.place.name + (f", {self.face} face" if self.face else "")

    @property
    def key(self) -> tuple[float, str]:
        """The station and face a crossing's sections are computed at."""
        return self.place.x, self.face or "left"


def columns(inputs: ReportInputs) -> tuple[Column, ...]:
    """Every place and effect the report gives (the displacement over a support, zero
    statically, is left out; the shear of an interior support on both faces)."""
    out = []
    last = len(inputs.bridge.spans)
    for place in inputs.places:
        for effect in inputs.effects:
            if effect == "displacement" and place.support is not None:
                continue
            if effect == "shear" and place.interior_support:
                out += [Column(place, effect, "left"), Column(place, effect, "right")]
            elif effect == "shear" and place.support == 0:
                out.append(Column(place, effect, "right"))
            elif effect == "shear" and place.support == last:
                out.append(Column(place, effect, "left"))
            else:
                out.append(Column(place, effect))
    return tuple(out)


def _entries(cols: tuple[Column, ...]) -> list[tuple[float, str]]:
    seen: list[tuple[float, str]] = []
    for col in cols:
        if col.key not in seen:
            seen.append(col.key)
    return seen


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
    faces = tuple(f if direction == "forward" else _flip(f) for _, f in entries)
    options = {"model": inputs.model}
    if inputs.modes is not None:
        options["modes"] = inputs.modes
    crossing, said = _quiet(
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


# ---------------------------------------------------------------------------- envelopes
@dataclass(frozen=True, eq=False)
class Envelopes:
    """Static and dynamic envelopes along the bridge (forward stations and signs).

    ``static`` is the exact static envelope of the vehicle's axles over the directions
    asked (:func:`vbi_lib.beam_statics.field_envelope`, each interior support twice, both
    faces); ``maximum`` and ``minimum`` ``(3, n)`` are the dynamic extremes over the
    requested crossings of that vehicle at the same stations (crossings that lost contact
    left out, unless all did).
    """

    static: StaticEnvelope
    maximum: np.ndarray
    minimum: np.ndarray
    supports: tuple[float, ...]
    vehicle: str

    def to_dataframe(self) -> pd.DataFrame:
        """One row per station and effect: static and dynamic extremes (display units)."""
        rows = []
        faces = self.static.faces
        for e, effect in enumerate(EFFECTS):
            quantity = QUANTITY[effect]
            for i, x in enumerate(self.static.sections):
                rows.append({
                    display.label("station", "length"): display.value(x, "length"),
                    "effect": effect,
                    "face": faces[i] if effect == "shear" else "",
                    "unit": display.symbol(quantity),
                    "static maximum": display.value(self.static.maximum[e, i], quantity),
                    "static minimum": display.value(self.static.minimum[e, i], quantity),
                    "dynamic maximum": display.value(self.maximum[e, i], quantity),
                    "dynamic minimum": display.value(self.minimum[e, i], quantity),
                })  # fmt: skip
        return pd.DataFrame(rows)

    def plot(self, ax: Axes | None = None, effect: str = "moment") -> Axes:
        """Static (dashed) and dynamic (solid) envelope of ``effect`` along the bridge."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 2.6))
        e = EFFECTS.index(effect)
        quantity = QUANTITY[effect]
        x = display.value(self.static.sections, "length")
        for bound, static, dynamic, color in (
            ("maximum", self.static.maximum[e], self.maximum[e], "C3"),
            ("minimum", self.static.minimum[e], self.minimum[e], "C0"),
        ):
            ax.plot(x, display.value(dynamic, quantity), color=color, lw=1.3,
                    label=f"dynamic {bound}")  # fmt: skip
            ax.plot(x, display.value(static, quantity), "--", color=color, lw=0.9,
                    label=f"static {bound}")  # fmt: skip
        for s in self.supports:
            ax.axvline(display.value(s, "length"), color="0.6", lw=0.6)
        ax.axhline(0.0, color="k", lw=0.6)
        ax.set_xlabel(display.label("station from the first support", "length"))
        ax.set_ylabel(display.label(effect, quantity))
        ax.legend(loc="best", fontsize="x-small", ncol=2)
        return ax


def _envelopes(inputs: ReportInputs, vehicle: object, runs: _Runs, spacing: float | None,
               count: int) -> Envelopes:  # fmt: skip
    system = as_system(vehicle)
    static = field_envelope(inputs.bridge.spans, inputs.bridge.EI, system.static_loads,
                            system.offsets, count=count,
                            direction=inputs.parameters.direction)  # fmt: skip
    faces = tuple(f or "left" for f in static.faces)
    maximum = np.full((3, static.sections.size), -np.inf)
    minimum = np.full((3, static.sections.size), np.inf)
    keys = [k for k in runs.crossings if k[1] == spacing]
    valid = [k for k in keys if not runs.crossings[k].lost_contact] or keys
    for key in valid:
        direction = key[0]
        crossing = runs.crossings[key]
        x = inputs.to_run(static.sections, direction)
        side = faces if direction == "forward" else tuple(_flip(f) for f in faces)
        response = crossing.sections(x, side=side)
        high, low = response.maximum.copy(), response.minimum.copy()
        if direction == "backward":
            high[2], low[2] = -response.minimum[2], -response.maximum[2]
        maximum = np.maximum(maximum, high)
        minimum = np.minimum(minimum, low)
    return Envelopes(static, maximum, minimum, inputs.bridge.supports, vehicle_label(vehicle))


# ---------------------------------------------------------------------------- flights
@dataclass(frozen=True, eq=False)
class Flights:
    """Every flight of a tyre in the requested crossings (forward stations), and the
    tyres' footprint."""

    table: pd.DataFrame
    footprint: tuple[float, ...]
    unilateral: bool

    def to_dataframe(self) -> pd.DataFrame:
        """One row per flight: direction, speed, axle, take-off and landing station [m] from
        the first support, duration [s]."""
        return self.table.copy()

    def plot(self, ax: Axes | None = None) -> Axes:
        """Where the tyres flew: a bar from take-off to landing station, one row per flight."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 2.0))
        for k, row in enumerate(self.table.itertuples()):
            start = display.value(min(row.take_off_m, row.landing_m), "length")
            size = display.value(abs(row.landing_m - row.take_off_m), "length")
            ax.barh(k, size, left=start, color="C3")
        ax.set_xlabel(display.label("station from the first support", "length"))
        ax.set_yticks([])
        return ax


def _flights(inputs: ReportInputs, runs: _Runs) -> Flights:
    rows = []
    length = inputs.bridge.length
    for (direction, spacing, speed), crossing in runs.crossings.items():
        start = crossing.bridge_start
        for row in crossing.flights().itertuples(index=False):
            take_off, landing = row[3] - start, row[4] - start
            if direction == "backward":
                take_off, landing = length - take_off, length - landing
            rows.append({
                "direction": direction,
                "speed_m_s": float(speed),
                "rear_axle_spacing_m": spacing,
                "axle": int(row[0]),
                "take_off_m": float(take_off),
                "landing_m": float(landing),
                "duration_s": float(row[5]),
                "on_bridge": bool(-1e-9 <= take_off <= length + 1e-9),
            })  # fmt: skip
    columns = ["direction", "speed_m_s", "rear_axle_spacing_m", "axle", "take_off_m",
               "landing_m", "duration_s", "on_bridge"]  # fmt: skip
    system = as_system(inputs.vehicle)
    return Flights(
        pd.DataFrame(rows, columns=columns),
        tuple(float(f) for f in system.footprint),
        bool(system.has_unilateral),
    )


# ---------------------------------------------------------------------------- study's spans
@dataclass(frozen=True, eq=False)
class SpeedStudy:
    """The study's span DAF at each speed, coupled and decoupled, with the contact checks.

    ``coupled`` and ``decoupled`` are :class:`~vbi_lib.BatchResult` rows in the order of
    ``speeds`` [m/s]; ``n_spans`` columns of their ``daf`` are used.
    """

    speeds: np.ndarray
    coupled: BatchResult
    decoupled: BatchResult
    n_spans: int

    @property
    def lost_contact(self) -> np.ndarray:
        """Whether the coupled crossing at each speed lost contact (outside validity)."""
        return self.coupled.lost_contact

    def largest(self, span: int) -> tuple[float, float] | None:
        """Largest valid coupled DAF of ``span`` (0-based) and its speed, ``None`` if none."""
        valid = ~self.lost_contact
        if not valid.any():
            return None
        daf = np.where(valid, self.coupled.daf[:, span], -np.inf)
        best = int(np.argmax(daf))
        return float(daf[best]), float(self.speeds[best])

    def to_dataframe(self) -> pd.DataFrame:
        """One row per speed: DAF per span (coupled, decoupled) and the contact checks."""
        columns: dict[str, object] = {
            display.label("speed", "speed"): display.value(self.speeds, "speed")
        }
        for j in range(self.n_spans):
            columns[f"DAF span {j + 1}"] = self.coupled.daf[:, j]
            columns[f"DAF span {j + 1}, decoupled"] = self.decoupled.daf[:, j]
        columns["largest contact force / weight"] = self.coupled.contact_force_amplification
        columns["smallest contact force / weight"] = self.coupled.min_contact_force_ratio
        columns["contact lost"] = self.lost_contact
        return pd.DataFrame(columns)

    def plot(self, ax: Axes | None = None, allowance: float | None = None) -> Axes:
        """DAF against speed: coupled (solid), decoupled (dashed), lost contact crossed out."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.4))
        v = display.value(self.speeds, "speed")
        lost = self.lost_contact
        for j in range(self.n_spans):
            coupled = self.coupled.daf[:, j]
            (line,) = ax.plot(v, np.where(lost, np.nan, coupled), label=f"span {j + 1}, coupled")
            ax.plot(v, self.decoupled.daf[:, j], "--", color=line.get_color(), lw=1,
                    label=f"span {j + 1}, decoupled (bound)")  # fmt: skip
            ax.plot(v[lost], coupled[lost], "x", color=line.get_color(), ms=6)
        if lost.any():
            ax.plot([], [], "x", color="k", label="contact lost: outside validity")
        if allowance is not None:
            ax.axhline(allowance, color="k", lw=1, ls=":", label="AASHTO LRFD (1 + IM)")
        ax.set_xlabel(display.label("speed", "speed"))
        ax.set_ylabel("DAF [-]")
        ax.legend(loc="best", fontsize="small")
        return ax


def speed_study(inputs: ReportInputs, speeds: np.ndarray) -> SpeedStudy:
    """The study's coupled and decoupled crossings of ``inputs.road`` at ``speeds`` [m/s]
    (its span DAF; the report's own case only: its sprung mass on its beam)."""
    speeds = np.asarray(speeds, dtype=float)
    roads = [inputs.run("forward", speed).road for speed in speeds]
    args = (inputs.bridge, inputs.vehicle, roads, list(speeds), inputs.bridge_start)
    coupled, _ = _quiet(simulate_many, *args)
    decoupled, _ = _quiet(simulate_many, *args, coupled=False)
    return SpeedStudy(speeds, coupled, decoupled, inputs.bridge.n_spans)


# ---------------------------------------------------------------------------- position
def shifted_deck(deck: Profile, offset: float) -> Profile:
    """The deck's roughness moved ``offset`` [m] along the bridge, wrapping round its ends.

    The straight line through the deck's end elevations is kept; the rest (zero at both ends)
    is read at ``(x - offset) mod L``, so the shifted deck has the same roughness, no step,
    and its features lie ``offset`` further on.

    >>> deck = Profile(np.array([0.0, 1.0, 2.0, 3.0, 4.0]), np.array([0.0, 1.0, 0.0, 0.0, 0.0]))
    >>> shifted_deck(deck, 1.0).elevation.tolist()
    [0.0, 0.0, 1.0, 0.0, 0.0]
    """
    x, z = deck.x, deck.elevation
    length = x[-1] - x[0]
    trend = z[0] + (z[-1] - z[0]) * (x - x[0]) / length
    rest = z - trend
    moved = np.interp(np.mod(x - x[0] - offset, length) + x[0], x, rest)
    return Profile(x, trend + moved, name=deck.name)


@dataclass(frozen=True, eq=False)
class PositionStudy:
    """Largest span DAF with the deck's roughness moved along the bridge (forward).

    ``daf`` and ``lost`` are ``(n_speeds, n_offsets)``: for each requested speed and each
    ``offset`` [m], the largest DAF of the spans (the midspan displacement's, of
    :func:`vbi_lib.simulate`) and whether that crossing lost contact.
    """

    speeds: np.ndarray
    offsets: np.ndarray
    daf: np.ndarray
    lost: np.ndarray

    def to_dataframe(self) -> pd.DataFrame:
        """One row per speed: the smallest, median and largest valid DAF over the offsets."""
        rows = []
        for i, speed in enumerate(self.speeds):
            valid = self.daf[i][~self.lost[i] & np.isfinite(self.daf[i])]
            rows.append({
                display.label("speed", "speed"): display.value(speed, "speed"),
                "smallest DAF": valid.min() if valid.size else np.nan,
                "median DAF": np.median(valid) if valid.size else np.nan,
                "largest DAF": valid.max() if valid.size else np.nan,
                "positions that lost contact": int(self.lost[i].sum()),
                "positions": self.offsets.size,
            })  # fmt: skip
        return pd.DataFrame(rows)

    def plot(self, ax: Axes | None = None) -> Axes:
        """Largest DAF of the spans against the offset, one line per speed."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.4))
        x = display.value(self.offsets, "length")
        for i, speed in enumerate(self.speeds):
            label = f"{display.value(speed, 'speed'):.0f} {display.symbol('speed')}"
            (line,) = ax.plot(x, np.where(self.lost[i], np.nan, self.daf[i]), "o-", ms=3,
                              label=label)  # fmt: skip
            ax.plot(x[self.lost[i]], self.daf[i][self.lost[i]], "x", color=line.get_color())
        if self.lost.any():
            ax.plot([], [], "x", color="k", label="contact lost: outside validity")
        ax.set_xlabel(display.label("deck roughness moved along the bridge by", "length"))
        ax.set_ylabel("largest DAF of the spans [-]")
        ax.legend(loc="best", fontsize="small")
        return ax


def _started(inputs: ReportInputs, road: Profile, speed: float) -> Profile:
    """``road`` from where a crossing at ``speed`` starts (:meth:`ReportInputs.approach_at`)."""
    start = inputs.bridge_start - inputs.approach_at(speed)
    return road.segment(start, road.x[-1]) if start > road.x[0] + 1e-9 else road


def position_study(
    inputs: ReportInputs, count: int, vehicle: object | None = None
) -> PositionStudy:
    """DAF at the requested speeds with the deck moved by ``count`` even steps over its length."""
    deck = inputs.deck
    vehicle = inputs.vehicle if vehicle is None else vehicle
    offsets = np.arange(count) * deck.length / count
    roads = [inputs.with_deck(shifted_deck(deck, offset)) for offset in offsets]
    speeds = np.asarray(inputs.speeds, dtype=float)
    every_road = [_started(inputs, road, speed) for speed in speeds for road in roads]
    every_speed = [speed for speed in speeds for _ in roads]
    options = {"model": inputs.model}
    if inputs.modes is not None:
        options["modes"] = inputs.modes
    result, _ = _quiet(simulate_many, inputs.bridge, vehicle, every_road, every_speed,
                       inputs.bridge_start, **options)  # fmt: skip
    n = inputs.bridge.n_spans
    daf = np.nanmax(result.daf[:, :n], axis=1).reshape(speeds.size, count)
    return PositionStudy(speeds, offsets, daf, result.lost_contact.reshape(speeds.size, count))


# ---------------------------------------------------------------------------- the road
@dataclass(frozen=True, eq=False)
class SpanRoughness:
    """IRI and ISO 8608 parameters of each span's deck profile (and of the whole deck).

    ``names`` label the rows (``"span 1"``, ..., ``"whole deck"``); ``iri`` [m/km], ``c10``
    [m^3] and ``waviness`` are NaN where they could not be computed (``reasons`` says why).
    """

    names: tuple[str, ...]
    iri: np.ndarray
    c10: np.ndarray
    waviness: np.ndarray
    reasons: tuple[str, ...]
    deck: Profile
    approach_end: float

    @property
    def iso_class(self) -> tuple[str, ...]:
        """ISO 8608 class of each row's fitted C10 (``"-"`` where not fitted)."""
        return tuple(iso8608_class(c) if np.isfinite(c) else "-" for c in self.c10)

    def to_dataframe(self) -> pd.DataFrame:
        """One row per span (and the whole deck): IRI, C10, waviness, ISO class."""
        return pd.DataFrame(
            {
                display.label("IRI", "roughness"): display.value(self.iri, "roughness"),
                "C10 [1e-6 m^3]": self.c10 * 1e6,
                "waviness [-]": self.waviness,
                "ISO 8608 class": self.iso_class,
            },
            index=pd.Index(self.names, name="part"),
        )

    def plot(self, ax: Axes | None = None, road: Profile | None = None) -> Axes:
        """The deck profile (and the end of the approach), elevation against station."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 2.8))
        if road is not None:
            x = np.linspace(-0.25 * self.deck.length, 0.0, 200)
            z = road.elevation_at(x + self.approach_end)
            ax.plot(display.value(x, "length"), display.value(z, "elevation"), color="0.55",
                    lw=0.8, label="approach")  # fmt: skip
        ax.plot(display.value(self.deck.x, "length"),
                display.value(self.deck.elevation, "elevation"), lw=0.8, label="deck")  # fmt: skip
        ax.axvspan(0, display.value(self.deck.x[-1], "length"), color="0.94", zorder=0)
        ax.set_xlabel(display.label("station from the bridge's first support", "length"))
        ax.set_ylabel(display.label("elevation", "elevation"))
        ax.legend(loc="best", fontsize="small")
        return ax


def span_roughness(inputs: ReportInputs) -> SpanRoughness:
    """IRI (ASTM E1926) and the ISO 8608 fit of each span's deck and of the whole deck."""
    deck = inputs.deck
    supports = inputs.bridge.supports
    n = inputs.bridge.n_spans
    parts = [
        (f"span {j + 1}", deck.segment(supports[j], min(supports[j + 1], deck.end)))
        for j in range(n)
    ]
    if n > 1:
        parts.append(("whole deck", deck))
    values = np.full((len(parts), 3), np.nan)
    reasons = []
    for i, (_, part) in enumerate(parts):
        why = []
        try:
            values[i, 0] = iri(part).iri
        except ValueError as error:
            why.append(f"IRI not computed: {error}")
        try:
            values[i, 1:] = fit_iso8608(part)
        except ValueError as error:
            why.append(f"ISO 8608 fit not computed: {error}")
        reasons.append("; ".join(why))
    return SpanRoughness(
        names=tuple(name for name, _ in parts),
        iri=values[:, 0],
        c10=values[:, 1],
        waviness=values[:, 2],
        reasons=tuple(reasons),
        deck=deck,
        approach_end=inputs.bridge_start,
    )


# ---------------------------------------------------------------------------- design codes
@dataclass(frozen=True)
class Allowances:
    """Design DAF ``1 + IM`` of the codes for this bridge, by code (see :mod:`amplification`).

    ``daf`` are the bridge-wide values (the AASHTO Standard's at the longest span);
    ``by_column`` the values of each place and effect (the AASHTO Standard's loaded length
    depends on them, 3.8.2.2).
    """

    daf: dict[str, float]
    #: AASHTO LRFD Table 3.6.2.1-1, all limit states but fatigue and deck joints.
    aashto_lrfd: float
    #: AASHTO LRFD Table 3.6.2.1-1, fatigue and fracture.
    aashto_fatigue: float = 1.15
    by_column: tuple[dict[str, float], ...] = ()

    def to_dataframe(self) -> pd.DataFrame:
        """One row per code: its design DAF."""
        return pd.DataFrame({"design DAF (1 + IM)": self.daf}).rename_axis("code")

    def plot(self, ax: Axes | None = None) -> Axes:
        """Horizontal bars of the design DAFs."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6, 2))
        ax.barh(list(self.daf), list(self.daf.values()), color="0.6")
        ax.set_xlabel("design DAF (1 + IM) [-]")
        return ax


def loaded_length(bridge: Bridge, column: Column) -> float:
    """The AASHTO Standard's loaded length of a place and effect [m] (3.8.2.2): the span for
    a displacement or a moment in a span, the mean of the two spans at an interior support
    (negative moment), for the shear the longer part of the span on its face's side."""
    spans, supports = bridge.spans, bridge.supports
    place = column.place
    if place.interior_support:
        left, right = spans[place.support - 1], spans[place.support]
        if column.effect == "moment":
            return 0.5 * (left + right)
        return left if column.face == "left" else right
    if place.support is not None:
        return spans[0] if place.support == 0 else spans[-1]
    j = place.span
    if column.effect == "shear":
        s = place.x - supports[j]
        return max(s, spans[j] - s)
    return spans[j]


def allowances(bridge: Bridge, cols: tuple[Column, ...] = ()) -> Allowances:
    """AASHTO LRFD (33 %, 15 % for fatigue), AASHTO Standard (loaded length in feet) and
    OHBDC 1983 (first frequency)."""
    lrfd = amp.aashto_lrfd_allowance()
    fatigue = amp.aashto_lrfd_allowance("fatigue and fracture")
    ohbdc = 1.0 + float(amp.ohbdc_1983_allowance(bridge.first_frequency_hz))
    by_column = []
    for col in cols:
        length = loaded_length(bridge, col)
        by_column.append({
            "AASHTO LRFD": 1.0 + lrfd,
            "AASHTO LRFD fatigue": 1.0 + fatigue,
            "AASHTO Standard": 1.0 + float(amp.aashto_standard_impact(length)),
            "OHBDC 1983": ohbdc,
            "loaded length [m]": length,
        })  # fmt: skip
    return Allowances(
        aashto_lrfd=1.0 + lrfd,
        aashto_fatigue=1.0 + fatigue,
        daf={
            f"AASHTO LRFD, Table 3.6.2.1-1 (IM {lrfd:.0%})": 1.0 + lrfd,
            f"AASHTO LRFD, fatigue and fracture (IM {fatigue:.0%})": 1.0 + fatigue,
            f"AASHTO Standard, 50 / (L + 125) <= 0.30, at L = {bridge.span / ft:.0f} ft": 1.0
            + float(amp.aashto_standard_impact(bridge.span)),
            f"OHBDC 1983, at f1 = {bridge.first_frequency_hz:.2f} Hz": ohbdc,
        },
        by_column=tuple(by_column),
    )


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
    entries = _entries(cols)
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
    envelopes = _envelopes(inputs, vehicles[main], runs, main, FIELD_COUNTS[1 if quick else 0])
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
        envelopes=envelopes,
        flights=_flights(inputs, runs),
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
    from ..bridges import Bridge
    from ..vehicles import Vehicle
    from ..vehicles.fleet import hs20

    road = Profile.flat(50.0, 0.1)
    one = Bridge(10.0, 1, 2e9, 5000.0)
    truck = Vehicle.from_frequency(2e4, 3.0, 0.1)
    _quiet(simulate, one, truck, road, 14.0, 12.0)[0].sections([5.0])
    _quiet(simulate_many, one, truck, [road, road], [14.0, 15.0], 12.0)
    two = Bridge.continuous([10.0, 12.0], EI=2e9, mass_per_length=5000.0)
    run, _ = _quiet(simulate, two, hs20(), road, 14.0, 12.0, model="modal", modes=2)
    run.sections([5.0, 10.0, 10.0], side=("left", "left", "right"))
    field_envelope(two.spans, two.EI, [1.0, 2.0], [0.0, 3.0], count=11)
