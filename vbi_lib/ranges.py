"""Ranges of validity of every physical input: one table, one check.

:data:`RANGES` is the one table of what each physical input may be, used by the classes and
functions that take it (the book's page of ranges is generated from it, :func:`ranges_markdown`):

* a value outside the **hard** limits is physically meaningless (a 1 mm span, a speed of
  10^6 m/s, a road with 100 m of relief): it is refused with a ``ValueError`` naming the
  parameter, its value and the range (:func:`check_range`);
* a value inside the hard limits but outside the **soft** ones is merely outside the use the
  model was made and checked for (a 500 m span, 200 km/h): it is accepted with an
  :class:`~vbi_lib.validity.OutsideValidityWarning`, and a crossing says so in its ``notes``.

Text, bools and other non-numbers are refused with a ``TypeError`` before any range applies
(:mod:`vbi_lib._validation`).  Allocations are bounded before they are made: a crossing has at
most :data:`MAX_NODES` nodes and a generated road at most :data:`MAX_SAMPLES` samples.
"""

from __future__ import annotations

import math
import sys
import warnings
from dataclasses import dataclass

from . import _validation as check
from ._deck_ranges import DECK_RANGES
from .validity import OutsideValidityWarning

__all__ = [
    "MAX_NODES",
    "MAX_SAMPLES",
    "RANGES",
    "Range",
    "check_range",
    "outside_note",
    "ranges_markdown",
    "warn_outside",
    "within_rounding",
]


#: Most nodes (time steps + 1) one crossing may have; checked before anything is allocated.
#: The grid alone takes at least 40 bytes a node and a crossing's histories 100 or more, so
#: 2e7 nodes are some 3 GB, about what a shared 2-core machine can hold.
MAX_NODES = 20_000_000

#: Most samples a generated road may have (5e7 samples are 400 MB per array).
MAX_SAMPLES = 50_000_000


@dataclass(frozen=True)
class Range:
    """The range of validity of one physical input (SI units).

    Attributes
    ----------
    quantity
        What the input is, in words.
    unit
        Its SI unit (``"-"`` for a ratio or a count).
    hard
        ``(low, high)``: outside, the value is physically meaningless and refused.
    soft
        ``(low, high)`` or ``None``: outside, the model is merely outside its intended use
        (a warning).
    reason
        Why the hard limits are where they are.
    intended
        What the soft limits cover (source or reason).
    used_by
        The classes and functions that check it.
    open_low, open_high
        Whether a hard limit itself is excluded (``damping < 1``, ``speed > 0``).
    """

    quantity: str
    unit: str
    hard: tuple[float, float]
    soft: tuple[float, float] | None
    reason: str
    intended: str
    used_by: str
    open_low: bool = False
    open_high: bool = False

    def hard_text(self) -> str:
        """The hard limits in words, e.g. ``"from 1 to 2000 m"``."""
        return _interval(self.hard, self.unit, self.open_low, self.open_high)

    def soft_text(self) -> str:
        """The soft limits in words (empty when there are none)."""
        return "" if self.soft is None else _interval(self.soft, self.unit)


def _number_text(value: float) -> str:
    if value == math.inf:
        return "inf"
    return f"{value:.4g}"


def _interval(
    bounds: tuple[float, float], unit: str, open_low: bool = False, open_high: bool = False
) -> str:
    low, high = (_number_text(b) for b in bounds)
    unit_text = "" if unit == "-" else f" {unit}"
    if bounds[1] == math.inf:
        return f"{'above' if open_low else 'at least'} {low}{unit_text}"
    if open_low:
        return f"above {low} and at most {high}{unit_text}"
    if open_high:
        return f"at least {low} and below {high}{unit_text}"
    return f"from {low} to {high}{unit_text}"


_ROAD = "Profile generators (flat, harmonic, iso8608, bump, ramp, step), studies' recipes"

#: The range of validity of every physical input, by key (see the module docstring).
RANGES: dict[str, Range] = {
    "span": Range(
        "span length",
        "m",
        (1.0, 2000.0),
        (3.0, 300.0),
        "a span under 1 m is a culvert slab, one over 2 km no beam",
        "road bridges modelled as beams, from short slabs to the longest girders; the "
        "reports allow 3 to 300 m, the study's spans are 40 to 140 ft",
        "Bridge, Bridge.continuous (each span), Bridge.from_midspan_stiffness, "
        "Bridge.from_frequency, reference_beam",
    ),
    "n_spans": Range(
        "number of continuous spans",
        "-",
        (1, 50),
        None,
        "a continuous unit of more than 50 spans is no single beam, and its exact modes "
        "would take minutes to find",
        "",
        "Bridge.continuous",
    ),
    "EI": Range(
        "flexural rigidity",
        "N m^2",
        (1e3, 1e18),
        None,
        "from a timber plank to a hundred times the stiffest box girder",
        "no limit of its own: the first frequency and the mass per length bound the beam",
        "Bridge",
    ),
    "mass_per_length": Range(
        "mass per length of the beam",
        "kg/m",
        (1.0, 1e6),
        (50.0, 2e5),
        "from a plank to ten times the heaviest deck",
        "decks from a light footbridge to a massive multi-cell box, as the reports allow",
        "Bridge, Bridge.from_frequency",
    ),
    "k_mid": Range(
        "midspan stiffness of the path",
        "N/m",
        (1e3, 1e13),
        (1e5, 1e11),
        "from a plank to a hundred times the stiffest short span",
        "road bridges, as the reports allow",
        "Bridge.from_midspan_stiffness, reference_beam",
    ),
    "bridge_frequency": Range(
        "first natural frequency of the bridge",
        "Hz",
        (0.05, 1000.0),
        (0.5, 50.0),
        "no structure a vehicle crosses vibrates outside these",
        "road bridges vibrate first between about 1 and 30 Hz; above 50 Hz a bridge is rigid "
        "to a truck, below 0.5 Hz it is a cable-supported span a beam does not represent",
        "Bridge (from EI, mass and spans), Bridge.from_midspan_stiffness, "
        "Bridge.from_frequency, reference_beam",
    ),
    "bridge_damping_ratio": Range(
        "damping ratio of the bridge",
        "-",
        (0.0, 1.0),
        (0.0, 0.2),
        "at critical damping, 1, nothing vibrates",
        "measured bridge damping is 0.5 to 5 %; the reports allow up to 20 %",
        "Bridge and its constructors",
        open_high=True,
    ),
    "vehicle_mass": Range(
        "sprung (body) mass",
        "kg",
        (1.0, 1e6),
        (100.0, 2e5),
        "from a toy to the heaviest load ever moved on one suspension",
        "a quarter of a car to the heaviest permit load on one body",
        "Vehicle, Vehicle.from_frequency, QuarterCar (sprung_mass)",
    ),
    "truck_mass": Range(
        "mass of a truck: the study's one sprung mass, or a report vehicle's weight over g",
        "kg",
        (100.0, 1e6),
        (9070.0, 2e5),
        "a vehicle under 100 kg is no truck, and no single vehicle weighs 1000 t",
        "trucks that load bridges, from AASHTO's lightest design truck, H10 (20 kip, 9.07 t), "
        "to a 200 t permit load; a lighter value is most often a unit slip (kN for kip)",
        "reports (vehicle.mass of a sprung-mass or quarter-car truck, the weight of every "
        "report vehicle)",
    ),
    "unsprung_mass": Range(
        "unsprung (axle) mass",
        "kg",
        (0.1, 1e5),
        (10.0, 5000.0),
        "from a toy's wheel to far beyond any axle",
        "a car's wheel, about 30 kg, to a heavy tandem axle, 2 to 3 t",
        "QuarterCar, Tyre, QuarterCar.from_frequencies, QuarterCar.from_vehicle",
    ),
    "vehicle_frequency": Range(
        "natural frequency of the vehicle (body bounce, axle hop)",
        "Hz",
        (0.05, 1000.0),
        (0.5, 50.0),
        "no suspended body or wheel vibrates outside these",
        "body bounce 1 to 4 Hz, axle hop 8 to 15 Hz: Cebon 1999",
        "Vehicle (from mass and stiffness), Vehicle.from_frequency, QuarterCar and "
        "QuarterCar.from_frequencies (body and axle hop), hs20 (bounce_hz); VehicleSystem "
        "(its frequencies on a rigid road: soft limits only)",
    ),
    "vehicle_damping_ratio": Range(
        "damping ratio of a suspension or a tyre",
        "-",
        (0.0, math.inf),
        (0.0, 0.5),
        "a damper cannot give energy back; 1 or more is a valid, overdamped suspension (VBI-2D's "
        "verification vehicle is damped 2.09 times critical)",
        "truck suspensions are damped 5 to 30 %, the study's truck 10 %",
        "Vehicle, Vehicle.from_frequency, QuarterCar.from_frequencies (suspension and tyre), hs20",
    ),
    "vehicle_weight": Range(
        "weight of a vehicle (the sum of its static axle loads)",
        "N",
        (1.0, 1e8),
        (1e3, 5e6),
        "from 0.1 kg to 10 000 t",
        "a car to a convoy of heavy trucks, about 500 t",
        "VehicleSystem (so every vehicle), Axle (load)",
    ),
    "footprint": Range(
        "tyre contact length",
        "m",
        (0.0, 2.0),
        (0.0, 0.5),
        "a tyre touching the road over more than 2 m is no tyre",
        "truck tyres touch the road over 0.15 to 0.3 m; the library's default is 0.25 m "
        "(the study's sprung mass: 0, its point contact)",
        "Tyre, QuarterCar, Vehicle",
    ),
    "axle_offset": Range(
        "distance of an axle behind the first",
        "m",
        (0.0, 100.0),
        (0.0, 30.0),
        "no vehicle is 100 m long",
        "the longest trucks have about 25 m from the first to the last axle",
        "Axle",
    ),
    "headway": Range(
        "distance between the first axles of two vehicles of a convoy",
        "m",
        (0.0, 1000.0),
        None,
        "vehicles more than 1 km apart cross a bridge one at a time: run them separately",
        "",
        "Convoy",
        open_low=True,
    ),
    "speed": Range(
        "vehicle speed",
        "m/s",
        (0.0, 400.0),
        (0.0, 150 / 3.6),
        "nothing has moved on land faster than 341 m/s, the land speed record; moving-force "
        "benchmarks that sweep the speed parameter alpha up to 2 on stiff spans stay below "
        "400 m/s",
        "the fastest trucks drive at about 150 km/h; above, a speed stands for a speed "
        "parameter, not a truck; any lower speed is in use, a crawl being the static response",
        "simulate, simulate_many, studies (validate, monte_carlo)",
        open_low=True,
    ),
    "step_accuracy": Range(
        "largest time step times the model's highest frequency, omega_max dt",
        "-",
        (0.0, math.inf),
        (0.0, 0.5),
        "",
        "the default step is 0.1; up to 0.5 the DAF changes by well under 1 %; the "
        "one-coordinate model's RK4 refuses more than 2, being unstable beyond 2.8; the "
        "modal model's Newmark rule is stable at any step but its period error grows",
        "simulate, simulate_many (the step actually taken: dt, or less at profile samples)",
        open_low=True,
    ),
    "modes": Range(
        "number of beam modes",
        "-",
        (1, 200),
        None,
        "a DAF converges with a few modes; hundreds only cost time",
        "",
        "simulate, simulate_many (model='modal')",
    ),
    "profile_length": Range(
        "length of a generated road",
        "m",
        (0.0, 1e6),
        None,
        "1000 km is longer than any road profile measured in one run",
        "",
        _ROAD,
        open_low=True,
    ),
    "spacing": Range(
        "sample spacing of a road profile",
        "m",
        (1e-4, 10.0),
        None,
        "under 0.1 mm is finer than any profiler; a road sampled every 10 m or more tells "
        "nothing of its unevenness",
        "see sample_spacing (the crossing's needs) and iri_spacing",
        _ROAD + ", read_erd (the declared interval)",
    ),
    "sample_spacing": Range(
        "sample spacing over speed, against the model's highest frequency: "
        "spacing * 2 f_max / speed (study equation 32)",
        "-",
        (0.0, math.inf),
        (0.0, 1.0),
        "",
        "the study's rule 32: at least two samples per period of the highest frequency "
        "the crossing responds to; a coarser road misses what excites it",
        "simulate, simulate_many (roads that are not straight lines)",
    ),
    "c10": Range(
        "ISO 8608 roughness G_d(0.1 cycle/m), the study's C10",
        "m^3",
        (1e-12, 0.524288),
        (1e-12, 8.192e-3),
        "below 1e-12 m^3 the road's rms is under 1 micrometre, beneath any profiler: a "
        "straight line to rounding error; above the top of class H, 0.524 m^3, it is no road",
        "ISO 8608 classes A to E, paved roads and decks; classes F to H are unpaved tracks "
        "and rough ground",
        "Profile.iso8608, ISOProfile, studies.monte_carlo (c10_range), fit_iso8608 (the fit)",
    ),
    "measured_c10": Range(
        "ISO 8608 C10 fitted to a measured deck or road profile",
        "m^3",
        (0.0, math.inf),
        (1e-6, 8.192e-3),
        "",
        "measured decks and paved roads, from 1e-6 m^3 (an IRI of about 0.5 m/km, smoother "
        "than a new pavement) to the top of class E; the study's I-76 decks fit 1.2e-5 to "
        "1.5e-4 m^3; outside, the profile's elevation unit is the likely slip",
        "reports (the fit to the deck profile, before anything runs)",
        open_low=True,
    ),
    "road_rms": Range(
        "rms of a generated ISO 8608 road over its band",
        "m",
        (0.0, 1.0),
        None,
        "no road's unevenness has an rms of a metre; the top of class H with W = 2 has 0.7 m",
        "",
        "Profile.iso8608, ISOProfile (from c10, waviness, band and length, before building)",
        open_low=True,
    ),
    "waviness": Range(
        "ISO 8608 waviness W",
        "-",
        (1.0, 5.0),
        (1.5, 4.5),
        "outside 1 to 5 the spectrum is nothing like a road's",
        "ISO 8608 uses 2; measured roads lie between 1.5 and 3.5; the study used 2, 3 and 4, "
        "and a fit of a road of 4 scatters about it",
        "Profile.iso8608, ISOProfile, studies.monte_carlo, fit_iso8608 (the fit)",
    ),
    "unevenness": Range(
        "height of a road feature: harmonic amplitude, bump or step height, either sign",
        "m",
        (0.0, 1.0),
        (0.0, 0.15),
        "a 1 m obstacle is a wall, not a road feature",
        "speed humps, joints and potholes are up to about 0.15 m; higher, the tyre's "
        "enveloping and the vehicle's geometry matter",
        "Profile.harmonic (amplitude), Profile.bump and Profile.step (height)",
    ),
    "grade": Range(
        "grade of a ramp, rise over run, either sign",
        "-",
        (0.0, 1.0),
        (0.0, 0.15),
        "a 45-degree ramp is no road",
        "road grades stay under about 15 %",
        "Profile.ramp",
    ),
    "feature_length": Range(
        "length of a road feature: wavelength, bump width, ramp run",
        "m",
        (1e-3, 1e4),
        None,
        "a feature shorter than 1 mm or longer than 10 km is no road feature",
        "",
        "Profile.harmonic (wavelength), Profile.bump (width), Profile.ramp (run)",
    ),
    "iri_spacing": Range(
        "sample spacing of a profile for the IRI",
        "m",
        (0.0, 10.0),
        (0.0, 0.25),
        "",
        "the IRI's 250 mm moving average needs a sample at least every 250 mm; coarser "
        "roads read low: 2 % at 0.25 m, 7 % at 0.3 m, 9 % at 1 m on ISO 8608 roads",
        "iri",
        open_low=True,
    ),
    "iri_length": Range(
        "length of a profile for the IRI",
        "m",
        (0.25, math.inf),
        (11.0, math.inf),
        "shorter than the 250 mm moving average there is no slope to follow",
        "the golden car starts on the mean slope of the first 11 m; a shorter road gives an "
        "IRI of its start-up; ASTM E1926",
        "iri",
        open_low=True,
    ),
}
#: The decks' inputs (:mod:`vbi_lib.decks`), kept in their own module for length.
RANGES.update((key, Range(*spec[:7], **spec[7])) for key, spec in DECK_RANGES.items())


def _caller_level() -> int:
    """``stacklevel`` that points a warning at the first caller outside the library."""
    frame = sys._getframe(1)
    level = 1
    while frame is not None and frame.f_globals.get("__name__", "").startswith("vbi_lib"):
        frame = frame.f_back
        level += 1
    return level


def warn_outside(message: str) -> None:
    """Raise an :class:`OutsideValidityWarning` pointed at the caller outside the library."""
    warnings.warn(message, OutsideValidityWarning, stacklevel=_caller_level())


def outside_note(key: str, value: float, name: str | None = None) -> str | None:
    """The sentence saying ``value`` is outside ``key``'s soft range, or ``None`` inside it.

    >>> print(outside_note("span", 500.0)[:71])
    span=500 m is outside the intended range from 3 to 300 m of span length
    """
    spec = RANGES[key]
    if spec.soft is None:
        return None
    low, high = spec.soft
    magnitude = abs(value) if key in _SIGNED else value
    if low <= magnitude <= high:
        return None
    unit = "" if spec.unit == "-" else f" {spec.unit}"
    return (
        f"{name or key}={value:.6g}{unit} is outside the intended range {spec.soft_text()} "
        f"of {spec.quantity} ({spec.intended}); the result is outside the model's validity"
    )


#: Keys whose range applies to the magnitude (either sign allowed).
_SIGNED = {"unevenness", "grade"}


def check_range(key: str, value: object, name: str | None = None, *, warn: bool = True) -> float:
    """``value`` as a float, checked against :data:`RANGES` ``[key]``.

    Parameters
    ----------
    key
        The row of :data:`RANGES`.
    value
        The value given.
    name
        The parameter's name in messages (default ``key``).
    warn
        Warn (:class:`OutsideValidityWarning`) when outside the soft range; ``False`` when
        the caller puts the sentence of :func:`outside_note` in a result instead.

    Raises
    ------
    TypeError
        ``value`` is not a real number (text, a bool, ``None``).
    ValueError
        ``value`` is not finite or lies outside the hard limits.

    Examples
    --------
    >>> check_range("span", 30.0)
    30.0
    >>> check_range("span", 0.001)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: span=0.001 must be from 1 to 2000 m (a span under 1 m is a culvert slab, ...)
    """
    name = name or key
    number = check.number(name, value)
    spec = RANGES[key]
    if not math.isfinite(number):
        raise ValueError(f"{name}={value!r} must be a finite number")
    low, high = spec.hard
    magnitude = abs(number) if key in _SIGNED else number
    below = magnitude < low or (spec.open_low and magnitude == low)
    above = magnitude > high or (spec.open_high and magnitude == high)
    if below or above:
        size = " in size" if key in _SIGNED else ""
        raise ValueError(f"{name}={value!r} must be{size} {spec.hard_text()} ({spec.reason})")
    if warn:
        note = outside_note(key, number, name)
        if note:
            warn_outside(note)
    return number


def within_rounding(key: str, value: float, rel: float = 1e-9) -> float:
    """``value`` moved onto the nearer hard limit of ``key`` when it misses it by rounding
    only (relative ``rel``): a quantity derived from others (a frequency from EI, mass and
    span) lands a few ulps off a limit its inputs were chosen to meet.

    >>> within_rounding("bridge_frequency", 1000.0000000000001)
    1000.0
    """
    low, high = RANGES[key].hard
    for limit in (low, high):
        if math.isfinite(limit) and abs(value - limit) <= rel * abs(limit):
            return float(limit)
    return value


def ranges_markdown() -> str:
    """The table of :data:`RANGES` in Markdown (the book's page of ranges of validity)."""
    lines = [
        "| input | quantity | refused outside | warned outside | checked by |",
        "|---|---|---|---|---|",
    ]
    for key, spec in RANGES.items():
        hard = f"{spec.hard_text()} ({spec.reason})" if spec.reason else "-"
        soft = (spec.soft_text() + f" ({spec.intended})") if spec.soft else "-"
        cells = [f"`{key}`", spec.quantity, hard, soft, spec.used_by]
        lines.append("| " + " | ".join(c.replace("|", "/") for c in cells) + " |")
    return "\n".join(lines) + "\n"
