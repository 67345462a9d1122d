"""The report's studies of the road and of the study's own spans.

* :class:`SpanRoughness`: IRI (ASTM E1926) and the ISO 8608 fit of each span's deck;
* :class:`PositionStudy`: the DAF with the deck's roughness moved along the bridge;
* :class:`SpeedStudy`: the study's span DAF, coupled and decoupled (its bound), for its own
  case (the sprung mass on one span or two equal spans).

Each crossing starts as far before the bridge as its speed needs
(:meth:`~vbi_lib.reports.inputs.ReportInputs.approach_at`).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .. import display
from ..models import BatchResult, simulate_many
from ..profiles import Profile, iso8608_class
from ..roughness import fit_iso8608, iri
from ..validity import VbiWarning
from .inputs import ReportInputs

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "PositionStudy",
    "SpanRoughness",
    "SpeedStudy",
    "position_study",
    "quiet",
    "shifted_deck",
    "span_roughness",
    "speed_study",
]


def quiet(function, *args, **kwargs):  # noqa: ANN001, ANN002, ANN003, ANN202
    """Call ``function`` with the library's warnings kept, not shown: (result, messages)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", VbiWarning)
        result = function(*args, **kwargs)
    return result, [str(w.message) for w in caught if issubclass(w.category, VbiWarning)]


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
    coupled, _ = quiet(simulate_many, *args)
    decoupled, _ = quiet(simulate_many, *args, coupled=False)
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
    result, _ = quiet(simulate_many, inputs.bridge, vehicle, every_road, every_speed,
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
