r"""What an explorer's controls describe: one crossing, in the study's engineering units.

A :class:`Scenario` holds the values of the controls (US customary units, as the study's
tables) and turns them into the library's SI inputs: a :class:`~vbi_lib.Bridge`
(:meth:`~vbi_lib.Bridge.from_frequency`: span, mass per length and first frequency), the
truck (one of :data:`VEHICLE_TYPES`: the study's sprung mass (85), a
:class:`~vbi_lib.Vehicle`, or a :class:`~vbi_lib.QuarterCar` whose tyre can leave the road),
the road the truck drives on and the options of :func:`vbi_lib.simulate`.

Both trucks weigh ``truck_weight_kip`` and bounce at ``truck_frequency_hz`` with the
damping ratio ``truck_damping`` on their suspension.  The quarter car splits the weight into
a sprung (body) and an unsprung (axle and wheels) mass, ``unsprung_fraction`` of it, and puts
a tyre under the axle (:meth:`~vbi_lib.QuarterCar.from_frequencies`):

.. math::
    k_s = m_s (2\pi f_{body})^2, \qquad k_t = m_u (2\pi f_{hop})^2 - k_s,
    \qquad c_s = 2 \zeta m_s 2\pi f_{body},

with ``f_body = truck_frequency_hz`` (the body on its suspension, the tyre held rigid),
``f_hop = axle_hop_hz`` (the axle between suspension and tyre, the body held still) and
``zeta = truck_damping``; the tyre is undamped and touches the road over
:data:`~vbi_lib.vehicles.footprint.DEFAULT_FOOTPRINT` (0.25 m).  The tyre must be a spring,
``k_t > 0``, so ``axle_hop_hz`` must exceed ``truck_frequency_hz * sqrt(m_s / m_u)``.

The road is one of :data:`ROADS`.  Generated roads start at station 0 (where the truck starts,
at rest) and are sampled every inch, as the study's; the first support is ``approach_ft``
further on.  ``road_shift_ft`` slides the road back under the truck and the bridge: after the
shift, station ``x`` carries the elevation the unshifted road has at ``x + shift``, so a bump
or a rough patch meets the bridge earlier.  Generated roads are made long enough for the
largest shift (:data:`MAX_ROAD_SHIFT_FT`), so that shifting slides one road instead of drawing
a new one.

>>> s = Scenario(span_ft=80, n_spans=2, bridge_frequency_hz=4.2, road="flat")
>>> round(s.bridge().first_frequency_hz, 6), s.bridge().n_spans
(4.2, 2)
>>> s.simulate_options()
{'model': 'one-coordinate', 'coupled': True}
>>> car = s.replace(vehicle_type="quarter-car").vehicle()
>>> type(car).__name__, round(car.unsprung_mass / (car.sprung_mass + car.unsprung_mass), 3)
('QuarterCar', 0.1)
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, fields, replace
from functools import lru_cache
from pathlib import Path

import numpy as np

from .. import _validation as check
from .. import display
from .. import units as u
from ..bridges import Bridge
from ..profile_files import LENGTH_UNITS
from ..profiles import ISO_CLASS_MEANS, Profile
from ..ranges import check_range
from ..vehicles import QuarterCar, Vehicle

__all__ = [
    "MAX_MODES",
    "MAX_ROAD_SHIFT_FT",
    "MAX_UNSPRUNG_FRACTION",
    "ROADS",
    "ROAD_SPACING",
    "VEHICLE_TYPES",
    "Scenario",
]

#: The kinds of road an explorer offers: key and what the control shows.
ROADS = {
    "flat": "flat",
    "harmonic": "harmonic",
    "bump": "one bump",
    "iso-class": "ISO 8608 class",
    "iso-c10": "ISO 8608 C10 and waviness",
    "measured": "measured profile file",
}

#: The kinds of truck an explorer offers: key and what the control shows.
VEHICLE_TYPES = {
    "sprung-mass": "sprung mass (the study's)",
    "quarter-car": "quarter car (tyre can leave the road)",
}

#: Largest share of the truck's weight the quarter car's unsprung mass may take.
MAX_UNSPRUNG_FRACTION = 0.5

#: Sample spacing of the generated roads [m] (one inch, as the study's profiles).
ROAD_SPACING = 1 * u.inch

#: Largest position shift of a generated road [ft]; generated roads are this much longer.
MAX_ROAD_SHIFT_FT = 200.0

#: Most beam modes the many-mode model is offered with.
MAX_MODES = 20

_INTEGERS = {"n_spans", "seed", "modes"}
_TEXTS = {"vehicle_type", "road", "iso_class", "profile_path", "profile_unit"}
_POSITIVE = ("span_ft", "bridge_frequency_hz", "bridge_weight_kip_per_ft", "truck_weight_kip",
             "truck_frequency_hz", "axle_hop_hz", "unsprung_fraction", "speed_mph", "c10_e6",
             "waviness", "wavelength_ft", "bump_width_ft")  # fmt: skip


@dataclass(frozen=True)
class Scenario:
    """One crossing as the controls describe it (US customary units; damping as fractions).

    Parameters
    ----------
    span_ft, n_spans
        Length of each span [ft]; 1 (simple span) or 2 (two equal continuous spans).
    bridge_frequency_hz, bridge_weight_kip_per_ft, bridge_damping
        First natural frequency [Hz], weight per length [kip/ft] (the mass is weight / g) and
        damping ratio of the bridge.
    vehicle_type
        A key of :data:`VEHICLE_TYPES`: ``"sprung-mass"`` (the study's, its contact never
        leaves the road) or ``"quarter-car"`` (sprung and unsprung masses, a tyre that can
        leave the road); see the module docstring.
    truck_weight_kip, truck_frequency_hz, truck_damping
        The truck's weight [kip] (all of it, for both types), undamped body-bounce frequency
        [Hz] (the quarter car's with its tyre held rigid) and suspension damping ratio.
    axle_hop_hz, unsprung_fraction
        The quarter car's axle-hop frequency [Hz] (unsprung mass between suspension and tyre,
        :data:`vbi_lib.ranges.RANGES` ``vehicle_frequency``: refused outside 0.05 to 1000 Hz,
        intended 0.5 to 50 Hz; trucks hop at 8 to 15 Hz) and the share of the weight below
        the suspension, ``0 < unsprung_fraction <=`` :data:`MAX_UNSPRUNG_FRACTION` (0.1 to
        0.2 for a truck).  Defaults 20 Hz and 0.1: with the study's 3.5 Hz body the tyre is
        then about 2.6 times as stiff as the suspension, the unsprung mass of the study's
        35 t truck (3.5 t) stays inside its intended range, and the frequency map's bodies
        up to twice a 3 Hz bridge's frequency can still be built (they need more than
        18 Hz).  Unused for the sprung mass.
    speed_mph
        Truck speed [mph].
    road
        A key of :data:`ROADS`.
    iso_class
        ``"A"`` to ``"H"`` for ``road="iso-class"`` (waviness 2, ISO 8608's).
    c10_e6, waviness
        ``C10`` [1e-6 m^3] and waviness for ``road="iso-c10"``.
    seed
        Seed of the random phases of an ISO 8608 road.
    wavelength_ft, amplitude_in
        Wavelength [ft] and amplitude [in] of a harmonic road.
    bump_height_in, bump_width_ft, bump_position_ft
        A raised-cosine bump (a dip if the height is negative): height [in], base length
        [ft] and crest station from the first support [ft] (negative: on the approach).
    profile_path, profile_unit
        A measured profile file (two columns, station and elevation, read with
        :func:`vbi_lib.read_profile`) and the unit of both columns.
    road_shift_ft
        How far the road slides back under the bridge [ft].
    approach_ft
        Road before the first support [ft] (from the first station of the road).
    modes
        1: the study's one-coordinate model; more: the many-mode model with that many modes.
    coupled
        ``False`` for the decoupled model (the contact force ignores the bridge's motion).

    Raises
    ------
    ValueError, TypeError
        A value of the wrong kind or outside what the model allows, named as the field; for
        the quarter car, an ``axle_hop_hz`` too low for its body (the tyre's stiffness
        would not be positive).
    """

    span_ft: float = 100.0
    n_spans: int = 1
    bridge_frequency_hz: float = 3.0
    bridge_weight_kip_per_ft: float = 4.6
    bridge_damping: float = 0.01
    truck_weight_kip: float = 77.2
    truck_frequency_hz: float = 3.5
    truck_damping: float = 0.10
    vehicle_type: str = "sprung-mass"
    axle_hop_hz: float = 20.0
    unsprung_fraction: float = 0.1
    speed_mph: float = 41.0
    road: str = "iso-class"
    iso_class: str = "B"
    c10_e6: float = 300.0
    waviness: float = 2.0
    seed: int = 1
    wavelength_ft: float = 30.0
    amplitude_in: float = 0.25
    bump_height_in: float = 1.0
    bump_width_ft: float = 3.0
    bump_position_ft: float = 0.0
    profile_path: str = ""
    profile_unit: str = "in"
    road_shift_ft: float = 0.0
    approach_ft: float = 320.0
    modes: int = 1
    coupled: bool = True

    def __post_init__(self) -> None:
        for item in fields(self):
            name, value = item.name, getattr(self, item.name)
            if name == "coupled":
                check.flag(name, value)
            elif name in _TEXTS:
                if not isinstance(value, str):
                    raise TypeError(f"{name}={value!r} must be text")
            elif name in _INTEGERS:
                _whole(name, value)
            else:
                check.number(name, value)
                if not math.isfinite(value):
                    raise ValueError(f"{name}={value!r} must be a finite number")
        for name in _POSITIVE:
            check.positive(name, getattr(self, name))
        check.damping_ratio("bridge_damping", self.bridge_damping)
        # 1 or more is an overdamped suspension: taken (the vehicle warns above the intended
        # range, and the explorers put that on their note line), never refused
        check_range("vehicle_damping_ratio", self.truck_damping, "truck_damping", warn=False)
        check.n_spans(self.n_spans)
        if self.vehicle_type not in VEHICLE_TYPES:
            raise ValueError(
                f"vehicle_type={self.vehicle_type!r} is not offered; use one of "
                f"{', '.join(VEHICLE_TYPES)}"
            )
        check_range("vehicle_frequency", self.axle_hop_hz, "axle_hop_hz", warn=False)
        if not 0.0 < self.unsprung_fraction <= MAX_UNSPRUNG_FRACTION:
            raise ValueError(
                f"unsprung_fraction={self.unsprung_fraction!r} must be above 0 and at most "
                f"{MAX_UNSPRUNG_FRACTION:g} (the axles and wheels weigh about a tenth of a "
                "loaded truck); give the share of the weight below the suspension"
            )
        if self.vehicle_type == "quarter-car":
            lowest = self.lowest_axle_hop_hz
            if self.axle_hop_hz <= lowest:
                raise ValueError(
                    f"axle_hop_hz={self.axle_hop_hz:g} must be above {lowest:.3g} Hz for a "
                    f"quarter car whose body bounces at {self.truck_frequency_hz:g} Hz "
                    f"(truck_frequency_hz) with unsprung_fraction={self.unsprung_fraction:g}: "
                    "below it the tyre's stiffness k_t = m_u (2 pi f_hop)^2 - k_s is not "
                    "positive; raise axle_hop_hz or unsprung_fraction, or lower the body's "
                    "frequency"
                )
        if self.road not in ROADS:
            raise ValueError(f"road={self.road!r} is not offered; use one of {', '.join(ROADS)}")
        if self.iso_class not in ISO_CLASS_MEANS:
            raise ValueError(f"iso_class={self.iso_class!r} must be one of 'A' to 'H'")
        for name in ("amplitude_in", "road_shift_ft", "approach_ft"):
            check.non_negative(name, getattr(self, name))
        if self.seed < 0:
            raise ValueError(f"seed={self.seed!r} must be a whole number >= 0")
        if self.profile_unit not in LENGTH_UNITS:
            raise ValueError(
                f"profile_unit={self.profile_unit!r} is not a length unit; use one of "
                f"{', '.join(LENGTH_UNITS)}"
            )
        if not 1 <= self.modes <= MAX_MODES:
            raise ValueError(f"modes={self.modes!r} must be a whole number from 1 to {MAX_MODES}")
        if self.road != "measured" and self.road_shift_ft > MAX_ROAD_SHIFT_FT:
            raise ValueError(
                f"road_shift_ft={self.road_shift_ft!r} must be at most {MAX_ROAD_SHIFT_FT:g} "
                "for a generated road (it is generated that much longer)"
            )

    # ------------------------------------------------------------------ the model's inputs
    def bridge(self) -> Bridge:
        """The bridge [SI]: :meth:`~vbi_lib.Bridge.from_frequency` of span, mass and f1."""
        mass = self.bridge_weight_kip_per_ft * u.kip / u.ft / u.g
        return Bridge.from_frequency(
            self.span_ft * u.ft, self.n_spans, mass, self.bridge_frequency_hz, self.bridge_damping
        )

    def vehicle(self) -> Vehicle | QuarterCar:
        """The truck [SI]: a :class:`~vbi_lib.Vehicle` or a :class:`~vbi_lib.QuarterCar`.

        ``"sprung-mass"``: the study's sprung mass (85), mass = weight / g, undamped bounce
        frequency ``truck_frequency_hz``, damping ratio ``truck_damping``.
        ``"quarter-car"``: :meth:`~vbi_lib.QuarterCar.from_frequencies` with sprung mass
        ``(1 - unsprung_fraction)`` and unsprung mass ``unsprung_fraction`` times weight / g,
        body ``truck_frequency_hz``, axle hop ``axle_hop_hz``, suspension damping ratio
        ``truck_damping``, an undamped tyre (see the module docstring).

        Raises
        ------
        ValueError
            A mass outside :data:`vbi_lib.ranges.RANGES` (``vehicle_mass``,
            ``unsprung_mass``).
        """
        mass = self.truck_weight_kip * u.kip / u.g
        if self.vehicle_type == "sprung-mass":
            return Vehicle.from_frequency(mass, self.truck_frequency_hz, self.truck_damping)
        unsprung = self.unsprung_fraction * mass
        return QuarterCar.from_frequencies(
            mass - unsprung,
            unsprung,
            body_hz=self.truck_frequency_hz,
            axle_hop_hz=self.axle_hop_hz,
            suspension_damping_ratio=self.truck_damping,
        )

    @property
    def lowest_axle_hop_hz(self) -> float:
        """The axle-hop frequency [Hz] at which the quarter car's tyre stiffness would be 0.

        ``truck_frequency_hz * sqrt(m_s / m_u)``: ``k_t = m_u (2 pi f_hop)^2 - k_s > 0``
        needs a higher ``axle_hop_hz``.
        """
        ratio = (1.0 - self.unsprung_fraction) / self.unsprung_fraction
        return self.truck_frequency_hz * math.sqrt(ratio)

    def vehicle_text(self, vehicle: Vehicle | QuarterCar | None = None) -> str:
        """The truck in words, for the explorer's readout (weights in display units).

        ``vehicle`` is this scenario's :meth:`vehicle` if already built (not built again).
        """
        weight = display.fmt(self.truck_weight_kip * u.kip, "weight")
        if self.vehicle_type == "sprung-mass":
            return (
                f"the study's sprung mass, {weight}, {self.truck_frequency_hz:.2f} Hz, "
                f"damping {self.truck_damping:.0%} (contact assumed never to leave the road)"
            )
        frequencies = (vehicle or self.vehicle()).system.frequencies_hz
        return (
            f"quarter car, {weight} ({self.unsprung_fraction:.0%} unsprung), body "
            f"{self.truck_frequency_hz:.2f} Hz on a rigid tyre, axle hop {self.axle_hop_hz:.1f} Hz"
            f", suspension damping {self.truck_damping:.0%} (together they vibrate at "
            f"{frequencies[0]:.2f} and {frequencies[1]:.1f} Hz); the tyre can leave the road"
        )

    @property
    def speed(self) -> float:
        """Truck speed [m/s]."""
        return self.speed_mph * u.mph

    def profile(self) -> Profile:
        """The road the truck drives on, after the position shift (stations in metres).

        A measured profile that ends one or two samples short of the bridge's far support
        (the study's I-76 deck files end 23 mm short of their 140 ft) is completed by holding
        its last elevation, as the report does (:meth:`road_notes` says so).

        Raises
        ------
        ValueError
            No file for a measured road, a file that cannot be read, a shift longer than the
            road, or a measured road that does not reach the bridge's far support (the
            message names the controls: ``approach_ft``, ``span_ft``, ``n_spans``).
        """
        return self._completed(self._shifted_road())[0]

    def road_notes(self) -> list[str]:
        """Sentences on how the road was completed (a measured deck a sample or two short)."""
        if self.road != "measured":
            return []
        return self._completed(self._shifted_road())[1]

    def _shifted_road(self) -> Profile:
        base = self._base_road()
        shift = self.road_shift_ft * u.ft
        if shift == 0.0:
            return base
        if shift >= base.length:
            raise ValueError(
                f"road_shift_ft={self.road_shift_ft:g} must be shorter than the road "
                f"({base.length / u.ft:.0f} ft); shift it less"
            )
        # slide the road back: station x now carries the elevation the road had at x + shift
        return base.segment(base.start + shift, base.end).shifted(-shift)

    def _completed(self, road: Profile) -> tuple[Profile, list[str]]:
        """A measured road held level to the far support if it stops a sample or two short."""
        if self.road != "measured":
            return road, []
        from ..reports.deck import SHORT_SAMPLES  # the report's rule, shared

        end = road.start + (self.approach_ft + self.n_spans * self.span_ft) * u.ft
        short = end - road.end
        if short <= 1e-9 * max(1.0, abs(end)):
            return road, []
        spacing = road.spacing
        if short <= SHORT_SAMPLES * spacing + 1e-9:
            completed = Profile(
                np.append(road.x, end), np.append(road.elevation, road.elevation[-1]), road.name
            )
            return completed, [
                f"The measured profile ends {short * 1e3:.0f} mm ({short / u.inch:.2f} in) "
                f"before the bridge's far support, less than {SHORT_SAMPLES} samples: its last "
                "elevation is held over that length, as the report does."
            ]
        shifted = f" after road_shift_ft={self.road_shift_ft:g}" if self.road_shift_ft else ""
        raise ValueError(
            f"the measured profile ({Path(self.profile_path).name}, profile_unit="
            f"{self.profile_unit!r}) runs {(road.end - road.start) / u.ft:.1f} ft{shifted}, but "
            f"the bridge ends {(end - road.start) / u.ft:.1f} ft from its start (approach_ft="
            f"{self.approach_ft:g} + n_spans={self.n_spans} x span_ft={self.span_ft:g}): lower "
            "approach_ft (a deck profile that starts at the first support needs approach_ft=0) "
            "or span_ft, check profile_unit, or use a longer profile"
        )

    def bridge_start(self, profile: Profile) -> float:
        """Station of the first support on ``profile`` [m]: ``approach_ft`` after its start."""
        return profile.start + self.approach_ft * u.ft

    def simulate_options(self) -> dict[str, object]:
        """The keyword options of :func:`vbi_lib.simulate` this scenario runs with."""
        if self.modes == 1:
            return {"model": "one-coordinate", "coupled": self.coupled}
        return {"model": "modal", "modes": self.modes, "coupled": self.coupled}

    def model_text(self) -> str:
        """Which model runs, in words, for the explorer's readout."""
        if self.modes == 1:
            what = "the study's one-coordinate model (integrated with RK4)"
        else:
            what = f"{self.modes} exact beam modes (integrated with Newmark average acceleration)"
        coupling = "coupled" if self.coupled else "decoupled: the bridge does not move the wheel"
        return f"{what}, {coupling}"

    def road_text(self) -> str:
        """The road in words: its kind, its parameters and the shift."""
        if self.road == "flat":
            text = "flat"
        elif self.road == "harmonic":
            text = (
                f"harmonic, wavelength {self.wavelength_ft:g} ft, "
                f"amplitude {self.amplitude_in:g} in"
            )
        elif self.road == "bump":
            text = (
                f"bump {self.bump_height_in:g} in high, {self.bump_width_ft:g} ft long, "
                f"crest {self.bump_position_ft:g} ft from the first support"
            )
        elif self.road == "iso-class":
            text = f"ISO 8608 class {self.iso_class} (w = 2), seed {self.seed}"
        elif self.road == "iso-c10":
            text = f"ISO 8608 C10 = {self.c10_e6:g}e-6 m³, w = {self.waviness:g}, seed {self.seed}"
        else:
            text = f"measured, {self.profile_path} (stations and elevations in {self.profile_unit})"
        if self.road_shift_ft:
            text += f", shifted {self.road_shift_ft:g} ft"
        return text

    def wavelength(self) -> float | None:
        """The road's wavelength [m] if it is harmonic, else ``None``."""
        return self.wavelength_ft * u.ft if self.road == "harmonic" else None

    def replace(self, **changes: object) -> Scenario:
        """A copy with some fields changed (checked again)."""
        return replace(self, **changes)

    # ------------------------------------------------------------------ roads
    def _base_road(self) -> Profile:
        if self.road == "measured":
            return _measured(self.profile_path, self.profile_unit)
        length = (self.approach_ft + self.n_spans * self.span_ft + MAX_ROAD_SHIFT_FT) * u.ft
        if self.road == "flat":
            return Profile.flat(length, ROAD_SPACING)
        if self.road == "harmonic":
            return Profile.harmonic(
                length, ROAD_SPACING, self.wavelength_ft * u.ft, self.amplitude_in * u.inch
            )
        if self.road == "bump":
            return Profile.bump(
                length,
                ROAD_SPACING,
                position=(self.approach_ft + self.bump_position_ft) * u.ft,
                height=self.bump_height_in * u.inch,
                width=self.bump_width_ft * u.ft,
            )
        if self.road == "iso-class":
            return Profile.iso8608(length, ROAD_SPACING, iso_class=self.iso_class, seed=self.seed)
        return Profile.iso8608(
            length,
            ROAD_SPACING,
            c10=self.c10_e6 * 1e-6,
            waviness=self.waviness,
            seed=self.seed,
        )


def _whole(name: str, value: object) -> None:
    if isinstance(value, bool | np.bool_) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}={value!r} must be a whole number")


def _measured(path_text: str, unit: str) -> Profile:
    if not path_text.strip():
        raise ValueError(
            "profile_path is empty: type the path of a measured profile file (two columns, "
            "station and elevation) or upload one"
        )
    path = Path(path_text.strip()).expanduser()
    try:
        stat = path.stat()
    except OSError:
        raise ValueError(
            f"profile_path={path_text!r} is not a file that can be read; check the path"
        ) from None
    return _read(str(path.resolve()), stat.st_mtime_ns, stat.st_size, unit)


@lru_cache(maxsize=8)
def _read(path: str, mtime_ns: int, size: int, unit: str) -> Profile:
    """A measured profile, read once per version of the file (the key holds its mtime)."""
    from ..profile_files import read_profile

    return read_profile(path, unit=unit)
