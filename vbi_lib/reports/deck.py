"""A measured deck from a profile file: read, cut at the supports, checked for unit slips.

**Plausibility.**  A profile file far longer than it needs to be, when another length unit
would make it fit the bridge, is refused naming ``profile.length_unit``; one merely long is
warned about.  A deck whose fitted roughness lies outside a measured deck's range
(:data:`vbi_lib.ranges.RANGES` ``measured_c10``, ``waviness``) is warned about, naming
``profile.elevation_unit`` and the unit that would fit.  The warnings go into the report's
summary and to the command line.
"""

from __future__ import annotations

import hashlib
import math

import numpy as np

from .. import units as u
from .._files import FileReadError, read_bytes
from ..profile_files import ProfileFileError, read_profile
from ..profiles import Profile, iso8608_class
from ..ranges import RANGES
from ..roughness import fit_iso8608, iri
from .parameters import ParameterError, ReportParameters

__all__ = ["SHORT_SAMPLES", "measured_deck"]

#: A deck may be this many samples shorter than the bridge (the rest is held level).
SHORT_SAMPLES = 2
#: A profile file more than this many times as long as the road to the bridge's far support
#: is checked for a length-unit slip (refused when another unit fits), and above
#: :data:`LONG_WARNING` warned about.
LONG_CHECK, LONG_WARNING = 2.5, 4.0
#: Length units a slip is looked for among.
_UNITS = {"inch": u.inch, "ft": u.ft, "m": 1.0, "mm": 1e-3, "cm": 1e-2, "yd": 3 * u.ft}


def _length_slip(p: ReportParameters, extent: float, needed: float, spacing: float) -> str | None:
    """A unit in which a file ``extent`` [m] long would reach just past ``needed`` [m]."""
    given = p.profile.length_unit
    for name, size in _UNITS.items():
        if math.isclose(size, given, rel_tol=1e-9):
            continue
        other = extent * size / given
        if needed - SHORT_SAMPLES * spacing * size / given <= other <= 1.5 * needed:
            return name
    return None


def measured_deck(p: ReportParameters, length: float) -> tuple[Profile, str, str, list, list]:
    """The file's deck from the first support, completed if one or two samples short."""
    path = p.profile.file
    try:
        raw = read_profile(
            path, unit=p.profile.length_unit, elevation_unit=p.profile.elevation_unit
        )
        data = read_bytes(path, "profile.file")  # for its hash: the safe reader, as above
    except (OSError, ProfileFileError, FileReadError) as error:
        known = isinstance(error, ProfileFileError | FileReadError)
        detail = error.problem if known else str(error)
        where = f" (line {error.line})" if getattr(error, "line", None) else ""
        raise ParameterError(
            "profile.file", str(path.name), f"cannot be read{where}: {detail}"
        ) from None
    start = raw.start + p.profile.bridge_start
    covered = raw.end - start
    spacing = raw.spacing
    notes, warnings = [], []
    unit = p.profile.length_unit_name or "its unit"
    needed = p.profile.bridge_start + length
    extent = raw.end - raw.start
    if extent > LONG_CHECK * needed:
        slip = _length_slip(p, extent, needed, spacing)
        if slip is not None:
            other = extent * _UNITS[slip] / p.profile.length_unit
            raise ParameterError(
                "profile.length_unit", unit, f"makes profile.file={path.name!r} run "
                f"{extent:.1f} m, {extent / needed:.1f} times the {needed:.1f} m to the "
                f"bridge's far support; in {slip} it would run {other:.1f} m and fit the "
                f"bridge: are its stations in {slip}? Say so with profile.length_unit: {slip} "
                "(and profile.elevation_unit, if its elevations are in another unit)",
            )  # fmt: skip
        if extent > LONG_WARNING * needed:
            warnings.append(
                f"The profile file runs {extent:.0f} m ({extent / u.ft:.0f} ft), "
                f"{extent / needed:.1f} times the {needed:.1f} m to the bridge's far support; "
                f"only that much is used. If its stations are not in {unit}, correct "
                "profile.length_unit."
            )
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
    warnings += _elevation_warnings(p, deck)
    return deck, source, hashlib.sha256(data).hexdigest(), notes, warnings


#: A typical C10 of a measured deck [m^3] (the study's I-76 decks fit 1.2e-5 to 1.5e-4): of
#: the elevation units that would make a deck plausible, the one nearest it is named.
TYPICAL_C10 = 4e-5


def _e6(c10: float) -> str:
    """``"94.4e-6"``: a C10 [m^3] in millionths, three significant digits."""
    value = c10 * 1e6
    return f"{float(f'{value:.3g}'):,g}e-6"


def _elevation_warnings(p: ReportParameters, deck: Profile) -> list[str]:
    """Sentences when the deck's fitted roughness lies outside a measured deck's range."""
    try:
        c10, waviness = fit_iso8608(deck)
        roughness = iri(deck).iri
    except ValueError:  # too short to fit: nothing to judge by
        return []
    out = []
    low, high = RANGES["measured_c10"].soft
    name = p.profile.elevation_unit_name or p.profile.length_unit_name or "its unit"
    given = p.profile.elevation_unit
    said = "profile.elevation_unit" if p.profile.elevation_unit_name else (
        "profile.elevation_unit (it defaults to profile.length_unit)"
    )  # fmt: skip
    if not low <= c10 <= high:
        side = "below" if c10 < low else "above"
        bound = low if c10 < low else high
        fits = []
        for unit, size in _UNITS.items():
            scale = (size / given) ** 2  # C10 goes with the square of the elevations
            if not math.isclose(size, given, rel_tol=1e-9) and low <= c10 * scale <= high:
                fits.append((abs(math.log(c10 * scale / TYPICAL_C10)), unit, size, scale))
        hint = f" If its elevations are not in {name}, say so with {said}"
        if fits:
            _, unit, size, scale = min(fits)
            hint += (
                f": in {unit} it would fit C10 = {_e6(c10 * scale)} m³ (class "
                f"{iso8608_class(c10 * scale)}, IRI {roughness * size / given:.2g} m/km)."
            )
        else:
            hint += "."
        out.append(
            f"The deck profile's elevations fit an ISO 8608 C10 of {_e6(c10)} m³ (class "
            f"{iso8608_class(c10)}, IRI {roughness:.2g} m/km), {side} the {_e6(bound)} m³ of "
            f"measured decks (vbi_lib.ranges.RANGES['measured_c10']).{hint}"
        )
    w_low, w_high = RANGES["waviness"].soft
    if not w_low <= waviness <= w_high:
        out.append(
            f"The deck profile's fitted waviness is {waviness:.2f}, outside the "
            f"{w_low:g} to {w_high:g} of measured roads (vbi_lib.ranges.RANGES['waviness']): "
            "check that the file is a profile (station, elevation), and its units "
            f"(profile.length_unit and {said})."
        )
    return out
