r"""From checked parameters to what a report runs on: the bridge, the vehicle, the road, the places.

**The road** is the deck (a measured profile, or a generated ISO 8608 road) behind an
approach.  The vehicle starts at rest in static equilibrium; on a flat approach (the default
with a file) it stays so, and the approach is just the vehicle and 10 m long.  On a rough one
(generated, or fitted to the deck, study equation 87) its slowest free motion, decaying as
:math:`e^{-r t}` (:func:`~vbi_lib.reports.approach.decay_rate`), falls to 1 % after
:math:`\ln 100 / r`: the approach is that long at the fastest speed, and each crossing
starts on it only as far before the bridge as its own speed needs.  The deck starts at the
first support (the file's first point or ``profile.bridge_start``); one or two samples
short, its last elevation is held.

**Directions.**  A vehicle crossing backward, from the last support, sees the bridge with its
spans in reverse order and the deck reversed, behind an approach of its own (flat, or a
generated road of the next seed).  :meth:`ReportInputs.run` gives the bridge, road and
first-support station of either direction; stations and faces convert with
:meth:`ReportInputs.to_run`.

**Places.**  The report's sections are stations from the first support (by default the
midspans and the interior supports), each named (:class:`Place`).

**The model.**  The study's one-coordinate model for its own case, the sprung mass on one
span or two equal spans; the modal model otherwise, with every mode up to 2.3 times the
highest simply supported frequency of any span (each span's own fundamental, below its
clamped-clamped frequency of 2.27 times it, is then included) unless ``bridge.modes`` says.

**Plausibility** of a deck profile file (unit slips) is :mod:`vbi_lib.reports.deck`'s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from .. import units as u
from ..bridges import Bridge
from ..continuous_beams import count_below, natural_wavenumbers
from ..profiles import Profile
from ..ranges import RANGES
from ..roughness import fit_iso8608
from ..vehicles import QuarterCar, Vehicle, as_system
from ..vehicles.fleet import hl93_tandem, hl93_truck, hs20, permit_vehicle
from .approach import DECAY, MIN_APPROACH, approach_length
from .deck import measured_deck
from .parameters import ParameterError, ReportParameters

__all__ = [
    "Place",
    "ReportInputs",
    "Run",
    "default_modes",
    "prepare",
    "sweep_speeds",
]

#: The speed sweep runs from this fraction of the slowest to this multiple of the fastest speed.
SWEEP_RANGE = (0.5, 1.2)
#: The modal model keeps every mode up to this multiple of the highest simply supported
#: frequency of a span (the rule of the DAF definitions, issue 20).
MODE_FREQUENCY_FACTOR = 2.3


@dataclass(frozen=True)
class Place:
    """A station the report gives results at.

    Attributes
    ----------
    x
        Station from the first support [m].
    name
        ``"midspan of span 2"``, ``"pier 1"`` (an interior support), ``"abutment 1"``,
        ``"span 2 at 0.25 L"``.
    support
        Index of the support there (0 for the first), or ``None``.
    span
        The span it lies in (0-based; at a support, the span on its left, 0 at the start).
    """

    x: float
    name: str
    support: int | None
    span: int

    @property
    def interior_support(self) -> bool:
        """Whether the station is an interior support (the shear has two faces there)."""
        return self.support is not None and self.name.startswith("pier")


@dataclass(frozen=True, eq=False)
class Run:
    """The bridge, road and first-support station a vehicle crossing in one direction sees."""

    direction: str
    bridge: Bridge
    road: Profile
    bridge_start: float


@dataclass(frozen=True, eq=False)
class ReportInputs:
    """What a report runs on, in SI.

    Attributes
    ----------
    parameters
        The checked parameters.
    bridge
        The bridge (study equations 82-85, or :meth:`Bridge.continuous`).
    vehicle
        The vehicle (at the shortest rear spacing of a design truck given a range).
    vehicles
        Every vehicle the report runs, by the rear axle spacing of a design truck [m]
        (``{None: vehicle}`` for any other vehicle); :func:`vbi_lib.reports.analysis.analyse`
        adds the governing spacings.
    deck
        The road on the bridge: stations from 0 (first support) to ``bridge.length`` [m].
    approach
        The road before the bridge, ending where the deck starts, or ``None`` when flat.
    road
        Approach and deck: the profile the vehicle drives forward, from station 0.
    bridge_start
        Station of the first support on ``road`` (the approach's length) [m].
    approach_back
        The road beyond the far support (the approach of a backward crossing, driven the
        other way), or ``None`` when flat.
    exit_length
        Road kept beyond the far support [m]: the longest vehicle's wheelbase and 1 m, so
        that its last axle leaves the bridge on a road (0 for one axle).
    profile_source
        One line on where the deck profile comes from.
    profile_sha256
        SHA-256 of the profile file (``None`` for a generated road).
    notes
        Sentences on how the road was assembled (approach, completion of a short deck).
    warnings
        Sentences on inputs that look like a slip (a unit), for the summary and the command
        line.
    places
        The stations reported (:class:`Place`), sorted.
    model, modes
        ``"one-coordinate"`` or ``"modal"``, and the number of modes (``None`` for the
        one-coordinate model).
    """

    parameters: ReportParameters
    bridge: Bridge
    vehicle: object
    deck: Profile
    approach: Profile | None
    road: Profile
    bridge_start: float
    profile_source: str
    profile_sha256: str | None
    notes: tuple[str, ...]
    warnings: tuple[str, ...] = ()
    places: tuple[Place, ...] = ()
    model: str = "one-coordinate"
    modes: int | None = None
    vehicles: dict = field(default_factory=dict)
    approach_back: Profile | None = None
    exit_length: float = 0.0
    #: Whether each crossing starts on the approach as far before the bridge as its own speed
    #: needs (a rough approach of the length the rule gives): see :meth:`run`.
    per_speed_approach: bool = False
    #: The wheelbase of the longest vehicle the report runs [m].
    wheelbase: float = 0.0

    @property
    def speeds(self) -> tuple[float, ...]:
        """The requested speeds [m/s]."""
        return self.parameters.speeds

    @property
    def directions(self) -> tuple[str, ...]:
        """``("forward",)``, ``("backward",)`` or both."""
        d = self.parameters.direction
        return ("forward", "backward") if d == "both" else (d,)

    @property
    def effects(self) -> tuple[str, ...]:
        """The effects reported."""
        return self.parameters.effects

    @property
    def study_case(self) -> bool:
        """The study's own case: its sprung mass on its one-coordinate beam."""
        return self.model == "one-coordinate" and isinstance(self.vehicle, Vehicle)

    def with_deck(self, deck: Profile) -> Profile:
        """The road with another deck (same stations span) behind the same approach."""
        return _join(self.approach, deck, self.bridge_start, self.approach_back,
                     self.exit_length)  # fmt: skip

    @cached_property
    def back_bridge(self) -> Bridge:
        """The bridge seen from its far end: the spans in reverse order."""
        spans = self.bridge.spans
        if spans == spans[::-1]:
            return self.bridge
        return Bridge.continuous(
            spans[::-1],
            EI=self.bridge.EI,
            mass_per_length=self.bridge.mass_per_length,
            damping_ratio=self.bridge.damping_ratio,
        )

    @cached_property
    def back_road(self) -> Profile:
        """The road of a backward crossing: its own approach, then the deck reversed."""
        length = self.bridge.length
        deck = Profile(length - self.deck.x[::-1], self.deck.elevation[::-1], name=self.deck.name)
        return _join(self.approach_back, deck, self.bridge_start, self.approach,
                     self.exit_length)  # fmt: skip

    def approach_at(self, speed: float) -> float:
        """Approach a crossing at ``speed`` [m/s] drives [m]: the whole approach, or on a rough
        approach of the rule's length only the part its own speed needs for the start-up
        motion to decay (:func:`approach_length`; the same road, started later)."""
        if not self.per_speed_approach:
            return self.bridge_start
        needed = max(approach_length(self.vehicle, speed), self.wheelbase + MIN_APPROACH)
        return min(self.bridge_start, needed)

    def run(self, direction: str, speed: float | None = None) -> Run:
        """The bridge, road and first-support station of a crossing in ``direction`` (at
        ``speed`` [m/s]: the road then starts :meth:`approach_at` before the bridge)."""
        if direction == "forward":
            bridge, road = self.bridge, self.road
        elif direction == "backward":
            bridge, road = self.back_bridge, self.back_road
        else:
            raise ValueError(f"direction={direction!r} must be 'forward' or 'backward'")
        if speed is not None and self.per_speed_approach:
            start = self.bridge_start - self.approach_at(speed)
            if start > road.x[0] + 1e-9:
                road = road.segment(start, road.x[-1])
        return Run(direction, bridge, road, self.bridge_start)

    def to_run(self, x: np.ndarray | float, direction: str) -> np.ndarray:
        """Stations from the first support as seen in ``direction`` (``L - x`` backward)."""
        x = np.asarray(x, dtype=float)
        return x if direction == "forward" else self.bridge.length - x


def sweep_speeds(speeds: tuple[float, ...], count: int) -> np.ndarray:
    """``count`` speeds from half the slowest to 1.2 times the fastest (at most 150 km/h) [m/s]."""
    low = max(SWEEP_RANGE[0] * min(speeds), 1 * u.kph)
    high = max(min(SWEEP_RANGE[1] * max(speeds), 150 * u.kph), max(speeds))
    return np.linspace(low, high, count)


def default_modes(bridge: Bridge) -> int:
    """Modes of the modal model: every mode of the continuous beam up to
    :data:`MODE_FREQUENCY_FACTOR` times the highest simply supported frequency of any span
    (at least one).

    Three spans: the three modes of the first band, one per span; one span: its first.

    >>> default_modes(Bridge.continuous([20.0, 30.0, 20.0], EI=1e10, mass_per_length=8e3))
    3
    >>> default_modes(Bridge(30.0, 1, 1e10, 8e3))
    1
    """
    shortest = min(bridge.spans)
    limit = math.sqrt(MODE_FREQUENCY_FACTOR) * math.pi / shortest  # wavenumber, omega ~ k^2
    return max(1, count_below(limit * (1 + 1e-12), list(bridge.spans)))


def _bridge(p: ReportParameters) -> Bridge:
    b = p.bridge
    try:
        if b.k_mid is not None:
            return Bridge.from_midspan_stiffness(
                b.span, b.n_spans, b.k_mid, b.first_frequency, b.damping_ratio
            )
        if b.EI is not None:
            EI = b.EI
        else:  # EI from the first frequency of this layout: omega_1 = k_1^2 sqrt(EI / mbar)
            k1 = float(natural_wavenumbers(list(b.spans), 1)[0])
            EI = b.mass_per_length * (2 * math.pi * b.first_frequency / k1**2) ** 2
        if b.study_layout:
            return Bridge(b.span, b.n_spans, EI, b.mass_per_length, b.damping_ratio)
        return Bridge.continuous(
            list(b.spans), EI=EI, mass_per_length=b.mass_per_length, damping_ratio=b.damping_ratio
        )
    except ValueError as error:
        raise ParameterError(
            "bridge", p.raw.get("bridge"), "", message=f"bridge: {error}"
        ) from None


def vehicle_at(p: ReportParameters, spacing: float | None = None) -> object:
    """The vehicle of the parameters (a design truck at rear ``spacing`` [m])."""
    v = p.vehicle
    truck = {
        "body": v.body,
        "tyres": v.tyres,
        "bounce_hz": v.frequency,
        "suspension_damping_ratio": v.damping_ratio,
    }
    if v.footprint is not None:
        truck["footprint"] = v.footprint
    try:
        if v.type == "sprung-mass":
            return Vehicle.from_frequency(v.mass, v.frequency, v.damping_ratio, damped=v.damped)
        if v.type == "quarter-car":
            omega = 2 * math.pi * v.frequency
            stiffness = v.mass * omega**2
            hop = math.sqrt((stiffness + v.tyre_stiffness) / v.unsprung_mass) / (2 * math.pi)
            low, high = RANGES["vehicle_frequency"].soft
            if not low <= hop <= high:
                raise ParameterError(
                    "vehicle.tyre_stiffness", p.raw["vehicle"].get("tyre_stiffness"),
                    f"gives an axle-hop frequency of {hop:.3g} Hz with this unsprung mass, "
                    f"outside the intended {low:g} to {high:g} Hz "
                    "(vbi_lib.ranges.RANGES['vehicle_frequency']; trucks hop at 8 to 15 Hz)",
                )  # fmt: skip
            extra = {} if v.footprint is None else {"footprint": v.footprint}
            damping = 2 * v.damping_ratio * v.mass * omega
            return QuarterCar(
                v.mass, v.unsprung_mass, stiffness, damping, v.tyre_stiffness, **extra
            )
        if v.type == "hs20":
            return hs20(spacing or v.rear_axle_spacing[0], **truck)
        if v.type == "hl93-truck":
            return hl93_truck(spacing or v.rear_axle_spacing[0], **truck)
        if v.type == "hl93-tandem":
            return hl93_tandem(**truck)
        return permit_vehicle(list(v.loads), list(v.spacings), name="permit vehicle", **truck)
    except ParameterError:
        raise
    except (TypeError, ValueError) as error:
        raise ParameterError(
            "vehicle", p.raw.get("vehicle"), "", message=f"vehicle: {error}"
        ) from None


def _join(
    approach: Profile | None,
    deck: Profile,
    start: float,
    beyond: Profile | None = None,
    exit_length: float = 0.0,
) -> Profile:
    """Approach (flat at the deck's first elevation when ``None``), deck and ``exit_length``
    of road beyond the far support, one profile.

    The road beyond is ``beyond`` (the other direction's approach, ending at the far
    support) driven the other way, or flat at the deck's last elevation when ``None``.
    """
    first = float(deck.elevation[0])
    if approach is None:
        x_before, z_before = np.array([0.0]), np.array([first])
    else:
        x_before = approach.x[:-1]
        z_before = approach.elevation[:-1] - approach.elevation[-1] + first
    x_after, z_after = np.empty(0), np.empty(0)
    if exit_length > 0:
        last, end = float(deck.elevation[-1]), start + float(deck.x[-1])
        if beyond is None:
            x_after, z_after = np.array([end + exit_length]), np.array([last])
        else:
            far = beyond.x[-1] - beyond.x[::-1]  # distance past the far support
            keep = (far > 0) & (far <= exit_length + beyond.spacing)
            x_after = end + far[keep]
            z_after = beyond.elevation[::-1][keep] - beyond.elevation[-1] + last
    return Profile(
        np.concatenate((x_before, start + deck.x, x_after)),
        np.concatenate((z_before, deck.elevation, z_after)),
        name=deck.name,
    )


def _approach(
    p: ReportParameters, deck: Profile, length: float, generated: Profile | None, seed: int
) -> tuple[Profile | None, str]:
    """The road before the bridge and a sentence saying what it is."""
    if p.profile.approach == "flat":
        return None, "flat (the vehicle stays at rest on it until the bridge)"
    if generated is not None:
        return generated, f"the same generated ISO 8608 class {p.profile.iso_class} road"
    try:
        c10, waviness = fit_iso8608(deck)
    except ValueError as error:
        raise ParameterError(
            "profile.approach",
            "iso8608",
            f"needs ISO 8608 parameters fitted to the deck, which failed ({error}); "
            "use approach: flat",
        ) from None
    spacing = min(deck.spacing, 0.1)
    road = Profile.iso8608(length, spacing, c10=c10, waviness=waviness, seed=seed)
    return road, (
        f"an ISO 8608 road with the deck's fitted parameters (C10 = {c10 * 1e6:.0f}e-6 m^3, "
        f"waviness {waviness:.2f}, seed {seed})"
    )


def _places(p: ReportParameters, bridge: Bridge) -> tuple[Place, ...]:
    supports = np.array(bridge.supports)
    length = bridge.length
    if p.sections is None:
        stations = sorted([*bridge.midspans, *supports[1:-1]])
    else:
        stations = list(p.sections)
    places = []
    tolerance = 1e-9 * length
    for x in stations:
        near = np.flatnonzero(np.abs(supports - x) <= tolerance)
        if near.size:
            i = int(near[0])
            x = float(supports[i])
            if i == 0:
                name = "abutment 1 (first support)"
            elif i == supports.size - 1:
                name = "abutment 2 (last support)"
            else:
                name = f"pier {i} (interior support)"
            places.append(Place(x, name, i, max(0, i - 1)))
            continue
        j = int(np.clip(np.searchsorted(supports, x) - 1, 0, supports.size - 2))
        span = supports[j + 1] - supports[j]
        ratio = (x - supports[j]) / span
        name = f"midspan of span {j + 1}" if abs(ratio - 0.5) < 1e-9 else (
            f"span {j + 1} at {ratio:.3g} of its length"
        )  # fmt: skip
        places.append(Place(float(x), name, None, j))
    return tuple(places)


def prepare(parameters: ReportParameters) -> ReportInputs:
    """Build the bridge, the vehicle and the road (deck and approaches) of a report.

    Parameters
    ----------
    parameters
        Checked parameters (:func:`~vbi_lib.reports.parameters.read_parameters`).

    Returns
    -------
    ReportInputs

    Raises
    ------
    ParameterError
        A profile file that cannot be read or does not cover the deck, naming
        ``profile.file``; a profile far too long for its length unit, naming
        ``profile.length_unit``; a bridge or vehicle the library refuses.

    Examples
    --------
    >>> from vbi_lib.reports.parameters import read_parameters
    >>> p = read_parameters({
    ...     "bridge": {"span": "30 m", "EI": "2e10 N*m**2", "mass_per_length": "8 t/m"},
    ...     "vehicle": {"mass": "30 t", "frequency": "3 Hz"},
    ...     "speeds": ["60 km/h"], "profile": {"iso_class": "B", "seed": 3}})
    >>> inputs = prepare(p)

    The approach: 1.2 x 60 km/h = 20 m/s for ln(100) / (0.1 x 2 pi x 3 Hz) = 2.44 s:

    >>> round(inputs.bridge_start, 1), round(inputs.road.end - inputs.bridge_start, 1)
    (48.9, 30.0)
    >>> inputs.model, [place.name for place in inputs.places]
    ('one-coordinate', ['midspan of span 1'])
    """
    p = parameters
    bridge = _bridge(p)
    vehicle = vehicle_at(p)
    spacing = p.vehicle.rear_axle_spacing
    vehicles = {None: vehicle} if spacing is None else {spacing[0]: vehicle}
    fastest = float(sweep_speeds(p.speeds, 2)[-1])
    # the longest vehicle the report may run (a design truck at the longest rear spacing)
    longest = vehicle if spacing is None else vehicle_at(p, spacing[1])
    wheelbase = as_system(longest).wheelbase
    exit_length = wheelbase + 1.0 if wheelbase > 0 else 0.0
    # on a flat approach the vehicle stays at rest in equilibrium: it only has to fit on it
    rough = p.profile.approach == "iso8608"
    needed = approach_length(vehicle, fastest) if rough else MIN_APPROACH
    needed = max(needed, wheelbase + MIN_APPROACH)
    length = p.profile.approach_length or needed
    if length < wheelbase + 1e-9:
        raise ParameterError(
            "profile.approach_length", p.given.get("profile.approach_length"), "is shorter "
            f"than the vehicle's wheelbase, {wheelbase:.2f} m ({wheelbase / u.ft:.1f} ft): the "
            "whole vehicle starts on the approach; give a longer one or leave the key out"
        )  # fmt: skip
    generated = None
    warnings: list[str] = list(p.warnings)
    if p.profile.file is not None:
        deck, source, sha256, notes, said = measured_deck(p, bridge.length)
        warnings += said
        back_generated = None
    else:
        road = Profile.iso8608(
            length + bridge.length,
            p.profile.spacing,
            iso_class=p.profile.iso_class,
            seed=p.profile.seed,
        )
        generated = road.segment(0.0, length)
        part = road.segment(length, length + bridge.length)
        deck = Profile(
            part.x - length, part.elevation, name=f"ISO 8608 class {p.profile.iso_class}"
        )
        source = (
            f"generated ISO 8608 class {p.profile.iso_class} road (seed {p.profile.seed}, "
            f"every {p.profile.spacing * 1e3:.0f} mm)"
        )
        sha256, notes = None, []
        back_generated = Profile.iso8608(
            length, p.profile.spacing, iso_class=p.profile.iso_class, seed=p.profile.seed + 1
        )
    approach, what = _approach(p, deck, length, generated, p.profile.seed)
    approach_back = None
    if p.direction != "forward" or exit_length > 0:  # the road beyond the far support
        approach_back, _ = _approach(p, deck, length, back_generated, p.profile.seed + 1)
    rule = "" if p.profile.approach_length else (
        f", long enough at {fastest / u.kph:.0f} km/h ({fastest / u.mph:.0f} mph), the fastest "
        f"speed simulated, for the vehicle's start-up motion to decay to {DECAY:.0%} (a "
        "slower crossing starts on it only as far before the bridge as its speed needs)"
    ) if rough else ", long enough for the whole vehicle to stand on it"  # fmt: skip
    behind = " (a backward crossing has one of its own, of the same kind)" if (
        p.direction != "forward"
    ) else ""  # fmt: skip
    notes.insert(
        0,
        f"An approach of {length:.0f} m ({length / u.ft:.0f} ft) is placed before the bridge"
        f"{rule}: {what}{behind}.",
    )
    if approach is not None and length < needed:
        notes.insert(
            1,
            f"That approach is shorter than the {needed:.0f} m the vehicle's start-up motion "
            f"needs to decay to {DECAY:.0%} at {fastest / u.kph:.0f} km/h: the fastest "
            "crossings may reach the bridge still moving from their start.",
        )
    study = p.vehicle.type == "sprung-mass" and bridge.study_layout
    model = "one-coordinate" if study else "modal"
    modes = None if study else (p.bridge.modes or default_modes(bridge))
    return ReportInputs(
        parameters=p,
        bridge=bridge,
        vehicle=vehicle,
        deck=deck,
        approach=approach,
        road=_join(approach, deck, length, approach_back, exit_length),
        bridge_start=length,
        profile_source=source,
        profile_sha256=sha256,
        notes=tuple(notes),
        warnings=tuple(warnings),
        places=_places(p, bridge),
        model=model,
        modes=modes,
        vehicles=vehicles,
        approach_back=approach_back,
        exit_length=exit_length,
        per_speed_approach=rough and not p.profile.approach_length,
        wheelbase=wheelbase,
    )
