"""Is a road given as data a plausible road?  The generators' ranges, applied to samples.

A generated road (:meth:`vbi_lib.Profile.harmonic`, ``bump``, ``step``, ``ramp``,
``iso8608``) is checked through its parameters against :data:`vbi_lib.ranges.RANGES`.  A road
given as data (a file read by :func:`vbi_lib.read_profile` or :func:`vbi_lib.read_erd`, or a
:class:`~vbi_lib.Profile` built from arrays) has no parameters; :func:`road_notes` measures
the same things on its samples:

* **unevenness** (``unevenness``: intended up to 0.15 m, no road feature above 1 m): the
  largest departure of the elevation from its own moving average over
  :data:`RELIEF_BASE` (10 m), at least half that base from the ends; a bump or pothole
  shows its height, a step half of it, a grade or a long vertical curve nothing;
* **slope** (``grade``: intended up to 0.15, none above 1): the largest rise over run across
  :data:`SLOPE_BASE` (1 m), the base over which a grade is felt (a 25 mm joint reads 0.025,
  not the slope of the one sample interval it rises over);
* **roughness class**: the IRI of the road (:func:`vbi_lib.iri`, when it is at least 11 m
  long) read as the ISO 8608 class of a road of waviness 2 with that IRI
  (``IRI = IRI_PER_ROOT_C10 * sqrt(c10)``) and checked as ``c10`` is (intended classes A to
  E, nothing beyond H);

Outside an intended range the road is warned about (:class:`~vbi_lib.OutsideValidityWarning`)
once, by the reader or by the first crossing on it, and every crossing on it says so in its
``notes``.  Beyond a hard limit (no road is like it), or outside every intended range at
once, the sentence names the likely unit slip:
when the elevations divided (or the stations multiplied) by a common factor, such as 1000
for millimetres read as metres, bring every measure inside its intended range, it says so
(a deck in millimetres read with ``unit="m"`` turns a 25 mm joint into a 25 m wall; a
quarter car would then report a DAF of 240).

The verdict is kept on the profile (an attribute, so it travels with the profile to a
study's workers), computed once.  Generated roads are marked as checked when they are made,
so the check costs nothing for them.
"""

from __future__ import annotations

import math
import warnings
from typing import Any

import numpy as np

from ._road_marks import _NOTES, _WARNED, _store, inherit, mark_checked
from .ranges import RANGES, warn_outside

__all__ = [
    "IRI_PER_ROOT_C10",
    "RELIEF_BASE",
    "SLOPE_BASE",
    "crossing_road_notes",
    "inherit",
    "mark_checked",
    "past_the_road",
    "road_measures",
    "road_notes",
    "warn_implausible",
]

#: Base of the moving average the unevenness is measured from [m].
RELIEF_BASE = 10.0
#: Base over which the slope is measured [m].
SLOPE_BASE = 1.0
#: IRI [m/km] of an ISO 8608 road of waviness 2 over the square root of its ``c10`` [m^3]:
#: 543, the mean over eight roads of 2 km sampled every 50 mm (:meth:`Profile.iso8608` over
#: its default band, standard deviation 2.4).  A road's IRI gives its ISO class through it.
IRI_PER_ROOT_C10 = 543.0

#: Unit slips, the likeliest first: the factor by which a length came out too large, the
#: words for it and the unit to read the file in.
_SLIPS = (
    (1000.0, "millimetres read as metres", "mm"),
    (1 / 0.0254, "inches read as metres", "in"),
    (100.0, "centimetres read as metres", "cm"),
    (1 / 0.3048, "feet read as metres", "ft"),
    (25.4, "millimetres read as inches", "mm"),
    (304.8, "millimetres read as feet", "mm"),
    (12.0, "inches read as feet", "in"),
    (10.0, "millimetres read as centimetres", "mm"),
)


def _moving_average(x: np.ndarray, z: np.ndarray, base: float, at: np.ndarray) -> np.ndarray:
    """The mean of the road (linear between samples) over ``[at - base/2, at + base/2]``."""
    area = np.concatenate(([0.0], np.cumsum(0.5 * (z[1:] + z[:-1]) * np.diff(x))))
    half = 0.5 * base
    return (np.interp(at + half, x, area) - np.interp(at - half, x, area)) / base


def road_measures(profile: Any) -> dict[str, float]:
    """What :func:`road_notes` measures on a profile's samples (see the module docstring).

    Returns ``{"unevenness": m, "slope": -, "iri": m/km or NaN, "c10": m^3 or NaN}``; the
    IRI (and the ``c10`` it implies) is NaN for a road shorter than 11 m or sampled more
    coarsely than 1 m.
    """
    x = np.asarray(profile.x, dtype=float)
    z = np.asarray(profile.elevation, dtype=float)
    length = float(x[-1] - x[0])
    spacing = float(np.median(np.diff(x)))
    if length > 2 * RELIEF_BASE:
        inner = x[(x >= x[0] + 0.5 * RELIEF_BASE) & (x <= x[-1] - 0.5 * RELIEF_BASE)]
        at = inner if inner.size else np.array([0.5 * (x[0] + x[-1])])
        relief = float(np.abs(np.interp(at, x, z) - _moving_average(x, z, RELIEF_BASE, at)).max())
    else:  # a short road: its departure from its own straight line
        fit = np.polyval(np.polyfit(x - x[0], z, 1), x - x[0])
        relief = float(np.abs(z - fit).max())
    if length > SLOPE_BASE:
        at = x[(x >= x[0] + 0.5 * SLOPE_BASE) & (x <= x[-1] - 0.5 * SLOPE_BASE)]
        at = at if at.size else np.array([0.5 * (x[0] + x[-1])])
        half = 0.5 * SLOPE_BASE
        rise = np.interp(at + half, x, z) - np.interp(at - half, x, z)
        slope = float(np.abs(rise).max() / SLOPE_BASE)
    else:
        slope = float(abs(z[-1] - z[0]) / length)
    roughness = c10 = math.nan
    if length >= 11.0 and spacing <= 1.0:
        from .roughness import iri  # the golden car; roughness imports profiles

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a coarse or short road: the IRI reads low
            roughness = float(iri(profile).iri)
        c10 = (roughness / IRI_PER_ROOT_C10) ** 2
    return {"unevenness": relief, "slope": slope, "iri": roughness, "c10": c10}


def _state(key: str, value: float) -> str:
    """``"inside"``, ``"soft"`` (above the intended range) or ``"hard"`` (above the hard
    limit) for a measure; a smooth road is never implausible, and NaN (not measured) is
    inside."""
    spec = RANGES[key]
    if not math.isfinite(value):
        return "inside"
    if value > spec.hard[1]:
        return "hard"
    if spec.soft is not None and value > spec.soft[1]:
        return "soft"
    return "inside"


def _inside(measures: dict[str, float]) -> bool:
    return all(_state(key, measures[key]) == "inside" for key in ("unevenness", "grade", "c10"))


def _scaled(measures: dict[str, float], elevation: float, stations: float) -> dict[str, float]:
    """The measures of the road with its elevations divided by ``elevation`` and its
    stations multiplied by ``stations`` (to the first order: the IRI as the slope)."""
    slope_factor = stations * elevation
    return {
        "unevenness": measures["unevenness"] / elevation,
        "grade": measures["slope"] / slope_factor,
        "c10": measures["c10"] / slope_factor**2,
    }


def _fits(profile: Any, stations: float, elevations: float) -> bool:
    """Whether the road with its stations and elevations divided by these factors would be
    inside every intended range (measured again: the slips are tried on implausible roads
    only)."""
    from .profiles import Profile  # profiles marks its roads with this module

    copy = Profile(profile.x / stations, profile.elevation / elevations)
    return _inside(_scaled(road_measures(copy), 1.0, 1.0))


def _slip(profile: Any, measures: dict[str, float]) -> str:
    """The unit slips (at most two, the likeliest first) that would make the road plausible,
    in words: of both columns (a file read in the wrong unit), else of the elevations."""
    spacing = float(np.median(np.diff(profile.x)))
    both = [
        (f, words, unit) for f, words, unit in _SLIPS
        if spacing / f <= RANGES["iri_spacing"].soft[1] < spacing and _fits(profile, f, f)
    ]  # fmt: skip
    if both:
        told = " or ".join(
            f"{words} ({f:.4g} times too large: unit={unit!r})" for f, words, unit in both[:2]
        )
        return (
            f"a unit slip of both columns would explain it (samples {spacing:.3g} m apart): {told}?"
        )
    fits = [(f, words, unit) for f, words, unit in _SLIPS if _inside(_scaled(measures, f, 1.0))]
    if fits:
        told = " or ".join(
            f"{words} ({f:.4g} times too large: elevation_unit={unit!r})"
            for f, words, unit in fits[:2]
        )
        return f"a unit slip of the elevations would explain it: {told}?"
    for factor, _, _ in _SLIPS:
        if _inside(_scaled(measures, 1.0, factor)):
            return (
                f"stations {factor:.4g} times too close together would explain it (stations "
                f"in metres read in a unit {factor:.4g} times smaller?): check unit=, the "
                "stations' unit"
            )
    return "no common unit slip explains it: check the file's units and content"


def _describe(measures: dict[str, float]) -> list[tuple[str, str]]:
    """``(state, words)`` of each measure above its intended range."""
    from .profiles import iso8608_class  # profiles marks its roads with this module

    out = []
    for key, measure in (("unevenness", "unevenness"), ("grade", "slope"), ("c10", "c10")):
        state = _state(key, measures[measure])
        if state == "inside":
            continue
        spec = RANGES[key]
        if key == "c10":
            words = (
                f"IRI {measures['iri']:.3g} m/km, that of an ISO 8608 road of "
                f"c10={measures['c10']:.3g} m^3 (waviness 2)"
            )
            words += (
                ", beyond the roughest class, H: no road" if state == "hard" else
                f", class {iso8608_class(measures['c10'])}, rougher than the intended classes "
                f"A to E ({spec.intended})"
            )  # fmt: skip
        else:
            value = measures[measure]
            words = (
                f"unevenness {value:.3g} m (largest departure from its {RELIEF_BASE:g} m "
                "moving average)" if key == "unevenness" else
                f"slope {value:.3g} over {SLOPE_BASE:g} m"
            )  # fmt: skip
            unit = "" if spec.unit == "-" else f" {spec.unit}"
            words += (
                f", beyond the largest {spec.hard[1]:g}{unit} ({spec.reason})" if state == "hard"
                else f", above the intended {spec.soft[1]:g}{unit} ({spec.intended})"
            )  # fmt: skip
        out.append((state, words))
    return out


def road_notes(profile: Any) -> tuple[str, ...]:
    """The sentence on a profile outside the ranges of a road, or ``()`` (see the module).

    Computed once per profile (a generated road is marked plausible when made).

    Examples
    --------
    A 25 mm joint of a deck in millimetres read as metres:

    >>> import numpy as np, vbi_lib as vbi
    >>> x = np.arange(0.0, 60.0, 0.025)
    >>> deck = vbi.Profile(x, np.where(x > 30.0, 25.0, 0.0), name="deck")
    >>> print(road_notes(deck)[0][:73])
    profile 'deck' is not a plausible road: unevenness 12.5 m (largest depart
    >>> "millimetres read as metres" in road_notes(deck)[0]
    True
    """
    known = profile.__dict__.get(_NOTES)
    if known is not None:
        return known
    measures = road_measures(profile)
    found = _describe(measures)
    notes: tuple[str, ...] = ()
    if found:
        hard = any(state == "hard" for state, _ in found)
        label = f"profile {profile.name!r}" if profile.name else "the profile"
        verdict = "is not a plausible road" if hard else "is outside the intended range of roads"
        slip = f"; {_slip(profile, measures)}" if hard or len(found) == 3 else ""
        notes = (
            f"{label} {verdict}: {'; '.join(words for _, words in found)}{slip}; the result is "
            "outside the model's validity",
        )
    return mark_checked(profile, notes).__dict__[_NOTES]


def warn_implausible(profile: Any, reader: str | None = None) -> tuple[str, ...]:
    """Warn (once per profile) when :func:`road_notes` finds the road implausible; the notes.

    ``reader`` names the function that read it, for the message.
    """
    notes = road_notes(profile)
    if notes and not profile.__dict__.get(_WARNED):
        _store(profile, _WARNED, True)
        warn_outside(notes[0] if reader is None else f"{reader}: {notes[0]}")
    return notes


def crossing_road_notes(profile: Any) -> tuple[list[str], list[str]]:
    """The road's sentence for a crossing's notes: ``(already warned, to warn)``.

    A road warned of when it was read goes to the notes only; one never warned of is warned
    by the crossing (and then marked, so the next crossing does not warn again).
    """
    notes = list(road_notes(profile))
    if not notes or profile.__dict__.get(_WARNED):
        return notes, []
    _store(profile, _WARNED, True)
    return [], notes


def past_the_road(profile: Any, stop: float, free_vibration: float, speed: float) -> list[str]:
    """The note of a run whose first axle goes past the profile's last station (a long
    ``free_vibration``): beyond it the road is held level at its last elevation.

    ``stop`` is the first axle's last station [m]; ``[]`` when the road reaches it.

    >>> import vbi_lib as vbi
    >>> past_the_road(vbi.Profile.flat(90.0, 0.5), 120.0, 2.0, 20.0)[0][:60]
    'the run went 30 m past the end of the road (profile stations'
    """
    beyond = stop - float(profile.x[-1])
    if beyond <= 1e-9 * max(1.0, abs(stop)):
        return []
    return [
        f"the run went {beyond:.3g} m past the end of the road (profile stations "
        f"{float(profile.x[0]):g} to {float(profile.x[-1]):g} m; free_vibration="
        f"{free_vibration:g} s at {speed:g} m/s): beyond its last station the road is held "
        "level at its last elevation; extend the profile to follow the road itself"
    ]
