r"""From checked parameters to what a report runs on: the bridge, the truck and the road.

The road is the deck (a measured deck profile, or a generated ISO 8608 road) with an approach
placed before it, so that the truck, which starts at rest in static equilibrium, has shed its
start-up motion before it reaches the bridge.  A sprung mass's free motion decays as
:math:`e^{-\zeta_v \omega_v t}`; to 1 % of its start after :math:`t = \ln 100 / (\zeta_v
\omega_v)`, so the approach is that long at the fastest speed simulated.  The approach is flat
by default (then the truck simply stays at rest on it) or an ISO 8608 road with the parameters
fitted to the deck (study equation 87).  The deck's stations start at the bridge's first
support (the file's first point, or ``profile.bridge_start`` after it); a deck one or two
samples shorter than the bridge is completed by holding its last elevation, and the report
says so.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass

import numpy as np

from .. import units as u
from ..bridges import Bridge
from ..profile_files import ProfileFileError, read_profile
from ..profiles import Profile
from ..roughness import fit_iso8608
from ..vehicles import Vehicle
from .parameters import ParameterError, ReportParameters

__all__ = ["ReportInputs", "approach_length", "prepare", "sweep_speeds"]

#: Fraction of the start-up motion left when the truck reaches the bridge.
DECAY = 0.01
#: Shortest approach [m].
MIN_APPROACH = 10.0
#: A deck may be this many samples shorter than the bridge (the rest is held level).
SHORT_SAMPLES = 2
#: The speed sweep runs from this fraction of the slowest to this multiple of the fastest speed.
SWEEP_RANGE = (0.5, 1.2)


@dataclass(frozen=True, eq=False)
class ReportInputs:
    """What a report runs on, in SI.

    Attributes
    ----------
    parameters
        The checked parameters.
    bridge, vehicle
        The model objects (study equations 82-85).
    deck
        The road on the bridge: stations from 0 (first support) to ``bridge.length`` [m].
    approach
        The road before the bridge, ending where the deck starts, or ``None`` when flat.
    road
        Approach and deck: the profile the truck drives, from station 0.
    bridge_start
        Station of the first support on ``road`` (the approach's length) [m].
    profile_source
        One line on where the deck profile comes from.
    profile_sha256
        SHA-256 of the profile file (``None`` for a generated road).
    notes
        Sentences on how the road was assembled (approach, completion of a short deck).
    """

    parameters: ReportParameters
    bridge: Bridge
    vehicle: Vehicle
    deck: Profile
    approach: Profile | None
    road: Profile
    bridge_start: float
    profile_source: str
    profile_sha256: str | None
    notes: tuple[str, ...]

    @property
    def speeds(self) -> tuple[float, ...]:
        """The requested speeds [m/s]."""
        return self.parameters.speeds

    def with_deck(self, deck: Profile) -> Profile:
        """The road with another deck (same stations span) behind the same approach."""
        return _join(self.approach, deck, self.bridge_start)


def sweep_speeds(speeds: tuple[float, ...], count: int) -> np.ndarray:
    """``count`` speeds from half the slowest to 1.2 times the fastest (at most 150 km/h) [m/s]."""
    low = max(SWEEP_RANGE[0] * min(speeds), 1 * u.kph)
    high = max(min(SWEEP_RANGE[1] * max(speeds), 150 * u.kph), max(speeds))
    return np.linspace(low, high, count)


def approach_length(vehicle: Vehicle, speed: float) -> float:
    """Road needed for the truck's start-up motion to decay to :data:`DECAY` at ``speed`` [m].

    ``speed * ln(1 / DECAY) / (zeta_v omega_v)``, at least :data:`MIN_APPROACH`.

    >>> truck = Vehicle.from_frequency(35000.0, 2.5, 0.10)
    >>> round(approach_length(truck, 30.0), 1)
    88.0
    """
    rate = vehicle.damping_ratio * vehicle.circular_frequency
    return max(MIN_APPROACH, speed * math.log(1.0 / DECAY) / rate)


def _bridge(p: ReportParameters) -> Bridge:
    b = p.bridge
    if b.k_mid is not None:
        return Bridge.from_midspan_stiffness(
            b.span, b.n_spans, b.k_mid, b.first_frequency, b.damping_ratio
        )
    if b.EI is not None:
        return Bridge(b.span, b.n_spans, b.EI, b.mass_per_length, b.damping_ratio)
    return Bridge.from_frequency(
        b.span, b.n_spans, b.mass_per_length, b.first_frequency, b.damping_ratio
    )


def _join(approach: Profile | None, deck: Profile, start: float) -> Profile:
    """Approach (flat at the deck's first elevation when ``None``) and deck, one profile."""
    first = float(deck.elevation[0])
    if approach is None:
        x_before, z_before = np.array([0.0]), np.array([first])
    else:
        x_before = approach.x[:-1]
        z_before = approach.elevation[:-1] - approach.elevation[-1] + first
    return Profile(
        np.concatenate((x_before, start + deck.x)),
        np.concatenate((z_before, deck.elevation)),
        name=deck.name,
    )


def _measured_deck(p: ReportParameters, length: float) -> tuple[Profile, str, str, list[str]]:
    """The file's deck from the first support, completed if one or two samples short."""
    path = p.profile.file
    try:
        data = path.read_bytes()
        raw = read_profile(
            path, unit=p.profile.length_unit, elevation_unit=p.profile.elevation_unit
        )
    except (OSError, ProfileFileError) as error:
        detail = error.problem if isinstance(error, ProfileFileError) else str(error)
        where = f" (line {error.line})" if getattr(error, "line", None) else ""
        raise ParameterError(
            "profile.file", str(path.name), f"cannot be read{where}: {detail}"
        ) from None
    start = raw.start + p.profile.bridge_start
    covered = raw.end - start
    spacing = raw.spacing
    notes = []
    if covered < length - SHORT_SAMPLES * spacing - 1e-9:
        raise ParameterError(
            "profile.file",
            path.name,
            f"covers {covered:.2f} m ({covered / u.ft:.1f} ft) from the bridge's first support "
            f"but the bridge is {length:.2f} m ({length / u.ft:.1f} ft) long; a deck profile "
            f"may be at most {SHORT_SAMPLES} samples ({SHORT_SAMPLES * spacing * 1e3:.0f} mm) "
            "short: give a profile of the whole deck (or check profile.length_unit and "
            "profile.bridge_start)",
        )
    if covered <= 0:
        raise ParameterError(
            "profile.bridge_start", p.given.get("profile.bridge_start"), "is past the file's end"
        )
    tolerance = 1e-9 * max(1.0, length)
    inside = (raw.x > start + tolerance) & (raw.x < start + length - tolerance)
    x = np.concatenate(([0.0], raw.x[inside] - start, [length]))
    if covered < length - tolerance:
        notes.append(
            f"The deck profile ends {(length - covered) * 1e3:.0f} mm "
            f"({(length - covered) / u.inch:.2f} in, less than {SHORT_SAMPLES} samples) before "
            "the bridge's far support; its last elevation is held over that length."
        )
    deck = Profile(x, raw.elevation_at(x + start), name=raw.name)
    if p.profile.bridge_start > 0:
        notes.append(
            f"The file's first {p.profile.bridge_start:.2f} m before the bridge are not used: "
            "the approach below replaces them."
        )
    source = (
        f"measured deck profile {path.name} ({raw.x.size} samples every {spacing * 1e3:.1f} mm)"
    )
    return deck, source, hashlib.sha256(data).hexdigest(), notes


def _approach(
    p: ReportParameters, deck: Profile, length: float, generated: Profile | None
) -> tuple[Profile | None, str]:
    """The road before the bridge and a sentence saying what it is."""
    if p.profile.approach == "flat":
        return None, "flat (the truck stays at rest on it until the bridge)"
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
    road = Profile.iso8608(length, spacing, c10=c10, waviness=waviness, seed=p.profile.seed)
    return road, (
        f"an ISO 8608 road with the deck's fitted parameters (C10 = {c10 * 1e6:.0f}e-6 m^3, "
        f"waviness {waviness:.2f}, seed {p.profile.seed})"
    )


def prepare(parameters: ReportParameters) -> ReportInputs:
    """Build the bridge, the truck and the road (deck and approach) of a report.

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
        A profile file that cannot be read or does not cover the deck, naming ``profile.file``.

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
    """
    p = parameters
    bridge = _bridge(p)
    vehicle = Vehicle.from_frequency(
        p.vehicle.mass, p.vehicle.frequency, p.vehicle.damping_ratio, damped=p.vehicle.damped
    )
    fastest = float(sweep_speeds(p.speeds, 2)[-1])
    length = p.profile.approach_length or approach_length(vehicle, fastest)
    generated = None
    if p.profile.file is not None:
        deck, source, sha256, notes = _measured_deck(p, bridge.length)
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
    approach, what = _approach(p, deck, length, generated)
    rule = "" if p.profile.approach_length else (
        f", long enough at {fastest / u.kph:.0f} km/h ({fastest / u.mph:.0f} mph), the fastest "
        f"speed simulated, for the truck's start-up motion to decay to {DECAY:.0%}"
    )  # fmt: skip
    notes.insert(
        0,
        f"An approach of {length:.0f} m ({length / u.ft:.0f} ft) is placed before the bridge"
        f"{rule}: {what}.",
    )
    needed = approach_length(vehicle, fastest)
    if approach is not None and length < needed:
        notes.insert(
            1,
            f"That approach is shorter than the {needed:.0f} m the truck's start-up motion "
            f"needs to decay to {DECAY:.0%} at {fastest / u.kph:.0f} km/h: the fastest "
            "crossings may reach the bridge still moving from their start.",
        )
    return ReportInputs(
        parameters=p,
        bridge=bridge,
        vehicle=vehicle,
        deck=deck,
        approach=approach,
        road=_join(approach, deck, length),
        bridge_start=length,
        profile_source=source,
        profile_sha256=sha256,
        notes=tuple(notes),
    )
