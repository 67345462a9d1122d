"""What a report computes: DAF against speed, the worst crossing, the road and the code values.

Each function returns one result type that exports itself (``to_dataframe()``) and plots
itself (``plot(ax=...)``), in the display units of :mod:`vbi_lib.display`.  The crossings are
the study's one-coordinate model (RK4) run by :func:`vbi_lib.simulate_many` (coupled, and
decoupled as a bound: the contact force of the truck on a rigid road, (92)-(99)).  Every
crossing reports whether the tyre stayed on the road (``lost_contact``): a DAF of a crossing
that lost contact is outside the model's validity and is never taken as a result.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .. import amplification as amp
from .. import display
from ..bridges import Bridge
from ..models import BatchResult, Crossing, simulate, simulate_many
from ..profiles import Profile, iso8608_class
from ..roughness import fit_iso8608, iri
from ..validity import ContactLossWarning
from .inputs import ReportInputs, sweep_speeds

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "Allowances",
    "PositionStudy",
    "ReportAnalysis",
    "SpanRoughness",
    "SpeedStudy",
    "allowances",
    "analyse",
    "position_study",
    "span_roughness",
    "speed_study",
]


# ---------------------------------------------------------------------------- speeds
@dataclass(frozen=True, eq=False)
class SpeedStudy:
    """DAF of each span at each speed, coupled and decoupled, with the contact checks.

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
            ax.plot(
                v,
                self.decoupled.daf[:, j],
                "--",
                color=line.get_color(),
                lw=1,
                label=f"span {j + 1}, decoupled (bound)",
            )
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
    """Coupled and decoupled crossings of ``inputs.road`` at ``speeds`` [m/s].

    Warnings of lost contact are not raised: the result holds them (``lost_contact``).
    """
    speeds = np.asarray(speeds, dtype=float)
    args = (inputs.bridge, inputs.vehicle, inputs.road, list(speeds), inputs.bridge_start)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ContactLossWarning)
        coupled = simulate_many(*args)
        decoupled = simulate_many(*args, coupled=False)
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
    """Largest DAF of the spans with the deck's roughness moved along the bridge.

    ``daf`` and ``lost`` are ``(n_speeds, n_offsets)``: for each requested speed and each
    ``offset`` [m], the largest DAF of the spans and whether that crossing lost contact.
    """

    speeds: np.ndarray
    offsets: np.ndarray
    daf: np.ndarray
    lost: np.ndarray

    def to_dataframe(self) -> pd.DataFrame:
        """One row per speed: the smallest, median and largest valid DAF over the offsets."""
        rows = []
        for i, speed in enumerate(self.speeds):
            valid = self.daf[i][~self.lost[i]]
            rows.append(
                {
                    display.label("speed", "speed"): display.value(speed, "speed"),
                    "smallest DAF": valid.min() if valid.size else np.nan,
                    "median DAF": np.median(valid) if valid.size else np.nan,
                    "largest DAF": valid.max() if valid.size else np.nan,
                    "positions that lost contact": int(self.lost[i].sum()),
                    "positions": self.offsets.size,
                }
            )
        return pd.DataFrame(rows)

    def plot(self, ax: Axes | None = None) -> Axes:
        """Largest DAF of the spans against the offset, one line per speed."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.4))
        x = display.value(self.offsets, "length")
        for i, speed in enumerate(self.speeds):
            label = f"{display.value(speed, 'speed'):.0f} {display.symbol('speed')}"
            (line,) = ax.plot(
                x, np.where(self.lost[i], np.nan, self.daf[i]), "o-", ms=3, label=label
            )
            ax.plot(x[self.lost[i]], self.daf[i][self.lost[i]], "x", color=line.get_color())
        if self.lost.any():
            ax.plot([], [], "x", color="k", label="contact lost: outside validity")
        ax.set_xlabel(display.label("deck roughness moved along the bridge by", "length"))
        ax.set_ylabel("largest DAF of the spans [-]")
        ax.legend(loc="best", fontsize="small")
        return ax


def position_study(inputs: ReportInputs, count: int) -> PositionStudy:
    """DAF at the requested speeds with the deck moved by ``count`` even steps over its length."""
    deck = inputs.deck
    offsets = np.arange(count) * deck.length / count
    roads = [inputs.with_deck(shifted_deck(deck, offset)) for offset in offsets]
    speeds = np.asarray(inputs.speeds, dtype=float)
    every_road = [road for _ in speeds for road in roads]
    every_speed = [speed for speed in speeds for _ in roads]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ContactLossWarning)
        result = simulate_many(
            inputs.bridge, inputs.vehicle, every_road, every_speed, inputs.bridge_start
        )
    n = inputs.bridge.n_spans
    daf = np.max(result.daf[:, :n], axis=1).reshape(speeds.size, count)
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
        ax.plot(
            display.value(self.deck.x, "length"),
            display.value(self.deck.elevation, "elevation"),
            lw=0.8,
            label="deck",
        )
        ax.axvspan(0, display.value(self.deck.x[-1], "length"), color="0.94", zorder=0)
        ax.set_xlabel(display.label("station from the bridge's first support", "length"))
        ax.set_ylabel(display.label("elevation", "elevation"))
        ax.legend(loc="best", fontsize="small")
        return ax


def _iri_value(profile: Profile) -> float:
    """The whole-profile IRI [m/km]."""
    return iri(profile).iri


def span_roughness(inputs: ReportInputs) -> SpanRoughness:
    """IRI (ASTM E1926) and the ISO 8608 fit of each span's deck and of the whole deck."""
    deck, span, n = inputs.deck, inputs.bridge.span, inputs.bridge.n_spans
    parts = [
        (f"span {j + 1}", deck.segment(j * span, min((j + 1) * span, deck.end))) for j in range(n)
    ]
    if n > 1:
        parts.append(("whole deck", deck))
    values = np.full((len(parts), 3), np.nan)
    reasons = []
    for i, (_, part) in enumerate(parts):
        why = []
        try:
            values[i, 0] = _iri_value(part)
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
    """Design DAF ``1 + IM`` of the codes for this bridge, by code (see :mod:`amplification`)."""

    daf: dict[str, float]
    #: AASHTO LRFD Table 3.6.2.1-1, all limit states but fatigue and deck joints.
    aashto_lrfd: float

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


def allowances(bridge: Bridge) -> Allowances:
    """AASHTO LRFD, AASHTO Standard (span in feet) and OHBDC 1983 (first frequency)."""
    lrfd = amp.aashto_lrfd_allowance()
    return Allowances(
        aashto_lrfd=1.0 + lrfd,
        daf={
            f"AASHTO LRFD, Table 3.6.2.1-1 (IM {lrfd:.0%})": 1.0 + lrfd,
            "AASHTO Standard, 50 / (L + 125) <= 0.30": 1.0
            + float(amp.aashto_standard_impact(bridge.span)),
            f"OHBDC 1983, at f1 = {bridge.first_frequency_hz:.2f} Hz": 1.0
            + float(amp.ohbdc_1983_allowance(bridge.first_frequency_hz)),
        },
    )


# ---------------------------------------------------------------------------- everything
@dataclass(frozen=True, eq=False)
class ReportAnalysis:
    """Everything a report shows (see :func:`analyse`)."""

    inputs: ReportInputs
    requested: SpeedStudy
    sweep: SpeedStudy
    position: PositionStudy
    roughness: SpanRoughness
    allowances: Allowances
    worst: Crossing

    def to_dataframe(self) -> pd.DataFrame:
        """The DAF table at the requested speeds (:meth:`SpeedStudy.to_dataframe`)."""
        return self.requested.to_dataframe()

    def plot(self, ax: Axes | None = None) -> Axes:
        """DAF against speed with the AASHTO LRFD value (:meth:`SpeedStudy.plot`)."""
        return self.sweep.plot(ax, allowance=self.allowances.aashto_lrfd)


def analyse(inputs: ReportInputs, quick: bool | None = None) -> ReportAnalysis:
    """Run every crossing a report needs.

    The requested speeds (coupled and decoupled), a sweep of speeds from half the slowest to
    1.2 times the fastest (40 speeds, 12 when ``quick``), the deck moved along the bridge in
    24 steps (8 when ``quick``) at the requested speeds, and the histories of the worst valid
    requested crossing.

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
    requested = speed_study(inputs, np.asarray(inputs.speeds))
    sweep = speed_study(inputs, sweep_speeds(inputs.speeds, 12 if quick else 40))
    n = inputs.bridge.n_spans
    largest = np.max(requested.coupled.daf[:, :n], axis=1)
    valid = ~requested.lost_contact
    worst = int(np.argmax(np.where(valid, largest, -np.inf) if valid.any() else largest))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ContactLossWarning)
        crossing = simulate(
            inputs.bridge, inputs.vehicle, inputs.road, inputs.speeds[worst], inputs.bridge_start
        )
    return ReportAnalysis(
        inputs=inputs,
        requested=requested,
        sweep=sweep,
        position=position_study(inputs, 8 if quick else 24),
        roughness=span_roughness(inputs),
        allowances=allowances(inputs.bridge),
        worst=crossing,
    )


def warm_up() -> None:
    """Run a tiny report's crossings, so the compiled kernels are loaded before a real one.

    A fresh process loads numba's cached machine code on first call (about two seconds);
    the report runner has its kernel call this first, while it prepares the rest.
    """
    from .. import units as u
    from .inputs import prepare
    from .parameters import read_parameters

    tiny = read_parameters(
        {
            "bridge": {"span": "10 m", "EI": "2e9 N*m**2", "mass_per_length": "5 t/m"},
            "vehicle": {"mass": "20 t", "frequency": "3 Hz"},
            "profile": {"approach_length": "10 m", "spacing": "0.1 m"},
            "speeds": ["50 km/h"],
            "quick": True,
        }
    )
    inputs = prepare(tiny)
    analysis = analyse(inputs)
    del analysis, u
