"""Report parameters: the nested YAML an engineer writes, checked key by key before anything runs.

A parameter file names the bridge, the vehicle, the road, the speeds and what to report::

    title: Three spans under the HS20
    bridge: {spans: [90 ft, 120 ft, 90 ft], EI: 5.3e11 kip*in**2, mass_per_length: 11 kip/ft}
    vehicle: {type: hs20, rear_axle_spacing: [14 ft, 30 ft]}
    profile: {iso_class: B, seed: 7}
    speeds: [35 mph, 55 mph, 70 mph]
    effects: [displacement, moment, shear]

Every dimensional value is one number and one unit, as text, read strictly by
:func:`vbi_lib.units.read_quantity`; booleans are YAML booleans; lists are YAML lists.  A key
that is not known gets a "did you mean"; a key that belongs to another vehicle type says
which.  Every refusal is a :class:`ParameterError` naming the key (``bridge.span``), the
value given and what is allowed.

**Ranges.**  Every quantity's range is the intended (soft) range of its input in
:data:`vbi_lib.ranges.RANGES`, the library's one table (its hard range where it has no soft
one): a report is filed for the use the model was made and checked for, so a value outside
it is refused here, where the library would only warn.  ``Key.range`` names the entry.  A
mass outside a truck's range (``truck_mass``) that another unit of the same number would
put inside is most likely a unit slip, and the message names it (``77.2 kN``: did you mean
``77.2 kip``?).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .. import units as u
from ..beam_statics import DIRECTIONS, EFFECTS
from ..ranges import RANGES
from .values import (
    _MISSING,
    MAX_SECTIONS,
    Key,
    ParameterError,
    _list,
    _quantity,
    _required,
    _section,
    _short,
    _suggest,
    _truck_weight,
    _value,
)

__all__ = [
    "DEFAULT_TITLE",
    "SCHEMA",
    "VEHICLE_KEYS",
    "VEHICLE_TYPES",
    "BridgeParameters",
    "ParameterError",
    "ProfileParameters",
    "ReportParameters",
    "VehicleParameters",
    "notebook_parameters",
    "read_parameters",
]

DEFAULT_TITLE = "Dynamic amplification of a bridge under one truck"

#: Unit names pint uses for US customary units: a span written in one of them makes the
#: report show US customary units first (SI alongside).
US_UNITS = {"foot", "inch", "mile", "yard", "mile_per_hour", "force_pound", "kip", "slinch"}

#: Vehicle types and the keys of ``vehicle`` each takes (``type`` aside).
VEHICLE_KEYS: dict[str, tuple[str, ...]] = {
    "sprung-mass": ("mass", "frequency", "damping_ratio", "damped"),
    "quarter-car": (
        "mass", "unsprung_mass", "frequency", "tyre_stiffness", "damping_ratio", "footprint",
    ),
    "hs20": ("rear_axle_spacing", "frequency", "damping_ratio", "tyres", "body", "footprint"),
    "hl93-truck": (
        "rear_axle_spacing", "frequency", "damping_ratio", "tyres", "body", "footprint",
    ),
    "hl93-tandem": ("frequency", "damping_ratio", "tyres", "body", "footprint"),
    "axles": ("loads", "spacings", "frequency", "damping_ratio", "tyres", "body", "footprint"),
}  # fmt: skip
VEHICLE_TYPES = tuple(VEHICLE_KEYS)


#: Every key a parameter file may hold, by section.  Ranges come from RANGES.
SCHEMA: dict[str, Any] = {
    "title": Key("text", "title of the report (plain text, at most 200 characters)",
                 default=DEFAULT_TITLE),
    "bridge": {
        "span": Key("length", "length of each of n_spans equal spans", "span"),
        "spans": Key("lengths", "span lengths from the first support, a YAML list", "span"),
        "n_spans": Key("int", "number of equal spans of span (1, 2: the study's)", "n_spans", 1),
        "k_mid": Key("stiffness", "midspan stiffness of the path, load / deflection (one span "
                     "or two equal spans)", "k_mid"),
        "EI": Key("flexural_rigidity", "flexural rigidity of the path's beam (or one per span, "
                  "equal)", "EI"),
        "mass_per_length": Key("mass_per_length", "mass (or weight) per length of the path's "
                               "beam (or one per span, equal)", "mass_per_length"),
        "first_frequency": Key("frequency", "first natural frequency", "bridge_frequency"),
        "damping_ratio": Key("ratio", "fraction of critical damping", "bridge_damping_ratio",
                             0.01),
        "modes": Key("int", "modes of the modal model (default: every mode up to 2.3 times "
                     "the highest simply supported frequency of a span)", "modes"),
    },
    "vehicle": {
        "type": Key("choice", "sprung-mass, quarter-car, hs20, hl93-truck, hl93-tandem or axles",
                    default="sprung-mass", choices=VEHICLE_TYPES),
        "mass": Key("mass", "sprung mass (or weight) of the truck", "truck_mass", warn=True),
        "unsprung_mass": Key("mass", "unsprung (axle) mass of a quarter car", "unsprung_mass"),
        "frequency": Key("frequency", "body-bounce frequency (trucks: 3 Hz)",
                         "vehicle_frequency"),
        "tyre_stiffness": Key("stiffness", "tyre stiffness of a quarter car (all its tyres)"),
        "damping_ratio": Key("ratio", "fraction of critical damping of the suspension (1 or "
                             "more: overdamped, warned of)", "vehicle_damping_ratio", 0.10,
                             warn=True),
        "damped": Key("bool", "true when frequency is the damped frequency", default=False),
        "footprint": Key("length", "tyre contact length (default 0.25 m)", "footprint"),
        "rear_axle_spacing": Key("spacing", "rear axle spacing of the design truck, 14 to 30 "
                                 "ft, or [low, high] to find the governing one",
                                 default=("14 ft", "30 ft")),
        "tyres": Key("bool", "trucks: each axle on an unsprung mass and tyres", default=True),
        "body": Key("choice", "trucks: independent axles, or one rigid body",
                    default="independent", choices=("independent", "rigid")),
        "loads": Key("weights", "axle loads front to rear, a YAML list", "vehicle_weight"),
        "spacings": Key("lengths", "distance from each axle to the next, a YAML list",
                        "axle_offset"),
    },
    "profile": {
        "file": Key("path", "deck profile: two columns, station and elevation"),
        "length_unit": Key("length_unit", "unit of the file's stations (inch, ft, m, mm)"),
        "elevation_unit": Key("length_unit", "unit of the file's elevations if different"),
        "bridge_start": Key("length", "station of the first support from the file's first "
                            "point (0 or more)"),
        "approach": Key("choice", "road before the bridge: flat, or an ISO 8608 road (fitted "
                        "to the deck)", choices=("flat", "iso8608")),
        "approach_length": Key("length", "length of the approach", "profile_length"),
        "iso_class": Key("choice", "ISO 8608 class of a generated road",
                         choices=tuple("ABCDEFGH")),
        "seed": Key("int", "seed of a generated road's random phases", default=1),
        "spacing": Key("length", "sample spacing of a generated road", "spacing"),
    },
    "speeds": Key("speeds", "vehicle speeds, a YAML list", "speed"),
    "sections": Key("lengths", "stations from the first support (default: the midspans and "
                    "the interior supports)"),
    "effects": Key("effects", "any of displacement, moment, shear (default: all three)",
                   choices=EFFECTS),
    "direction": Key("choice", "forward (from the first support), backward or both",
                     default="both", choices=DIRECTIONS),
    "quick": Key("bool", "fewer points in the sweeps (for tests)", default=False),
    "units": Key("choice", "units shown first (the other alongside)", choices=("US", "SI")),
}  # fmt: skip


_BRIDGE_ROUTES = (
    ("k_mid", "first_frequency"),
    ("EI", "mass_per_length"),
    ("mass_per_length", "first_frequency"),
)


@dataclass(frozen=True)
class BridgeParameters:
    """The bridge's parameters in SI (``None`` where not given).

    ``spans`` are the span lengths (``n_spans`` times ``span`` when given so); ``span`` is
    the longest.
    """

    span: float
    n_spans: int
    damping_ratio: float
    k_mid: float | None = None
    EI: float | None = None
    mass_per_length: float | None = None
    first_frequency: float | None = None
    spans: tuple[float, ...] = ()
    modes: int | None = None

    @property
    def study_layout(self) -> bool:
        """One span, or two equal spans: the study's beam."""
        return len(self.spans) == 1 or (len(self.spans) == 2 and self.spans[0] == self.spans[1])


@dataclass(frozen=True)
class VehicleParameters:
    """The vehicle's parameters in SI (``None`` where not given or not of its type).

    ``rear_axle_spacing`` is ``(low, high)``: one spacing when equal, else the range in
    which the report finds the governing one.
    """

    mass: float | None
    frequency: float | None
    damping_ratio: float
    damped: bool
    type: str = "sprung-mass"
    unsprung_mass: float | None = None
    tyre_stiffness: float | None = None
    footprint: float | None = None
    rear_axle_spacing: tuple[float, float] | None = None
    tyres: bool = True
    body: str = "independent"
    loads: tuple[float, ...] = ()
    spacings: tuple[float, ...] = ()


@dataclass(frozen=True)
class ProfileParameters:
    """The road's parameters in SI; ``file`` is ``None`` for a generated road."""

    file: Path | None
    length_unit: float | None
    elevation_unit: float | None
    bridge_start: float
    approach: str
    approach_length: float | None
    iso_class: str
    seed: int
    spacing: float
    #: The units as written (``"inch"``), for messages naming a likely slip.
    length_unit_name: str | None = None
    elevation_unit_name: str | None = None


@dataclass(frozen=True)
class ReportParameters:
    """Checked report parameters.

    Attributes
    ----------
    title
        The report's title (plain text; escaped when shown).
    bridge, vehicle, profile
        The sections, in SI.
    speeds
        Vehicle speeds [m/s].
    quick
        Fewer points in the sweeps.
    units
        ``"US"`` or ``"SI"``: the units shown first.
    given
        Each quantity as written, by key (``{"bridge.span": "140 ft"}``), for the inputs table.
    raw
        The parameters as given (plain YAML types), for the provenance section.
    sections
        Stations from the first support [m], sorted; ``None`` for the default (the midspans
        and the interior supports).
    warnings
        Sentences on values outside their intended range that are read all the same (a
        truck's mass), each naming the likely slip.
    effects
        The effects reported, in the order of :data:`vbi_lib.beam_influence.EFFECTS`.
    direction
        ``"forward"``, ``"backward"`` or ``"both"``.
    """

    title: str
    bridge: BridgeParameters
    vehicle: VehicleParameters
    profile: ProfileParameters
    speeds: tuple[float, ...]
    quick: bool
    units: str
    given: dict[str, str] = field(repr=False)
    raw: dict[str, Any] = field(repr=False)
    sections: tuple[float, ...] | None = None
    effects: tuple[str, ...] = EFFECTS
    direction: str = "both"
    warnings: tuple[str, ...] = ()


def _per_span(name: str, values: dict, key: Key, given: dict[str, str], count: int) -> Any:
    """``EI`` or ``mass_per_length``: one value, or a YAML list of one per span (equal)."""
    value = values.get(name, _MISSING)
    if not isinstance(value, list | tuple):
        return _value("bridge", name, values, SCHEMA["bridge"], given=given)
    items = _list(f"bridge.{name}", value, count, count, f"one per span ({count})")
    read = [_quantity(f"bridge.{name}[{i}]", key, v, given) for i, v in enumerate(items)]
    if any(not math.isclose(v, read[0], rel_tol=1e-9) for v in read):
        raise ParameterError(
            f"bridge.{name}", value, "differs from span to span; the report's beam is uniform "
            "(one EI and one mass per length over every span): give one value, or model the "
            "bridge with the library's Bridge.continuous"
        )  # fmt: skip
    given[f"bridge.{name}"] = ", ".join(given.pop(f"bridge.{name}[{i}]") for i in range(count))
    return read[0]


def _bridge(values: dict, given: dict[str, str]) -> BridgeParameters:
    schema = SCHEMA["bridge"]
    if "span" in values and "spans" in values:
        raise ParameterError(
            "bridge.spans", values["spans"], "and bridge.span are both given; give spans (a "
            "list of span lengths) or span and n_spans (equal spans)"
        )  # fmt: skip
    if "spans" in values and "n_spans" in values:
        raise ParameterError(
            "bridge.n_spans", values["n_spans"], "applies to bridge.span; with spans the "
            "number of spans is the length of the list"
        )  # fmt: skip
    if "spans" in values:
        most = int(RANGES["n_spans"].hard[1])
        spans = _value("bridge", "spans", values, schema, given=given, most=most)
    else:
        span = _value("bridge", "span", values, schema, given=given)
        _required("bridge.span", span, "span: 140 ft (or spans: [90 ft, 120 ft, 90 ft])")
        n_spans = _value("bridge", "n_spans", values, schema)
        spans = (span,) * n_spans
    count = len(spans)
    read = {
        name: _value("bridge", name, values, schema, given=given)
        for name in ("k_mid", "first_frequency", "damping_ratio", "modes")
    }
    for name in ("EI", "mass_per_length"):
        read[name] = _per_span(name, values, schema[name], given, count)
    stiffness = [k for k in ("k_mid", "EI", "mass_per_length", "first_frequency") if k in values]
    if sorted(stiffness) not in [sorted(route) for route in _BRIDGE_ROUTES]:
        routes = "; or ".join(" and ".join(route) for route in _BRIDGE_ROUTES)
        got = ", ".join(stiffness) or "none of them"
        raise ParameterError(
            "bridge", {k: values[k] for k in stiffness}, f"needs exactly {routes}; got {got}"
        )
    result = BridgeParameters(
        span=max(spans), n_spans=count, spans=tuple(spans), **read
    )  # fmt: skip
    if read["k_mid"] is not None and not result.study_layout:
        raise ParameterError(
            "bridge.k_mid", values["k_mid"], "is the study's route for one span or two equal "
            f"spans (equations 82-84); for {count} spans give EI and mass_per_length, or "
            "mass_per_length and first_frequency"
        )  # fmt: skip
    return result


def _vehicle(values: dict, given: dict[str, str], warnings: list[str]) -> VehicleParameters:
    schema = SCHEMA["vehicle"]
    kind = _value("vehicle", "type", values, schema)
    allowed = VEHICLE_KEYS[kind]
    for name in values:
        if name != "type" and name not in allowed:
            others = [t for t, keys in VEHICLE_KEYS.items() if name in keys]
            raise ParameterError(
                f"vehicle.{name}", values[name], f"does not apply to vehicle.type {kind}; it "
                f"belongs to {', '.join(others)}. {kind} takes: {', '.join(allowed)}"
            )  # fmt: skip
    read = {
        name: _value("vehicle", name, values, schema, given=given, warnings=warnings)
        for name in allowed
    }
    if kind in ("sprung-mass", "quarter-car"):
        _required("vehicle.mass", read["mass"], "mass: 35 t (or a weight, 77.2 kip)")
        _required("vehicle.frequency", read["frequency"], "frequency: 2.5 Hz")
    if kind == "quarter-car":
        _required("vehicle.unsprung_mass", read["unsprung_mass"], "unsprung_mass: 3 t")
        _required("vehicle.tyre_stiffness", read["tyre_stiffness"], "tyre_stiffness: 10 MN/m")
    if kind == "axles":
        _required("vehicle.loads", read["loads"], "loads: [12 kip, 34 kip, 34 kip]")
        needed = len(read["loads"]) - 1
        spacings = read["spacings"] or ()
        if len(spacings) != needed:
            raise ParameterError(
                "vehicle.spacings", values.get("spacings", _MISSING), f"must list {needed} "
                f"distances, one from each axle to the next (vehicle.loads has "
                f"{len(read['loads'])} axles)"
            )  # fmt: skip
        total = sum(spacings)
        hard = RANGES["axle_offset"].hard[1]
        if total > hard:
            raise ParameterError(
                "vehicle.spacings", values["spacings"], f"add up to {total:.1f} m from the "
                f"first axle to the last, more than the {hard:g} m of any vehicle"
            )  # fmt: skip
        _truck_weight("vehicle.loads", values["loads"], sum(read["loads"]), warnings)
        read["spacings"] = tuple(spacings)
    if kind in ("hs20", "hl93-truck", "hl93-tandem", "axles") and read.get("frequency") is None:
        read["frequency"] = 3.0
    return VehicleParameters(
        type=kind,
        mass=read.get("mass"),
        frequency=read.get("frequency"),
        damping_ratio=read["damping_ratio"],
        damped=bool(read.get("damped", False)),
        unsprung_mass=read.get("unsprung_mass"),
        tyre_stiffness=read.get("tyre_stiffness"),
        footprint=read.get("footprint"),
        rear_axle_spacing=read.get("rear_axle_spacing"),
        tyres=read.get("tyres", True),
        body=read.get("body") or "independent",
        loads=tuple(read.get("loads") or ()),
        spacings=tuple(read.get("spacings") or ()),
    )


def _profile(values: dict, given: dict[str, str], base_dir: Path) -> ProfileParameters:
    schema = SCHEMA["profile"]
    has_file = "file" in values
    only = (
        ("length_unit", "elevation_unit", "bridge_start") if has_file else ("iso_class", "spacing")
    )
    for name in values:
        if name not in only and name in (
            "length_unit", "elevation_unit", "bridge_start", "iso_class", "spacing"
        ):  # fmt: skip
            rule = (
                "applies to a generated road only; leave it out with profile.file"
                if has_file
                else "applies to profile.file only; give the file or leave the key out"
            )
            raise ParameterError(f"profile.{name}", values[name], rule)
    read = {
        name: _value("profile", name, values, schema, given=given, base_dir=base_dir)
        for name in schema
    }
    if has_file and read["length_unit"] is None:
        raise ParameterError(
            "profile.length_unit", _MISSING, "is required with profile.file, e.g. length_unit: inch"
        )
    length_unit, length_name = read["length_unit"] or (None, None)
    elevation_unit, elevation_name = read["elevation_unit"] or (length_unit, None)
    return ProfileParameters(
        file=read["file"],
        length_unit=length_unit,
        elevation_unit=elevation_unit,
        bridge_start=read["bridge_start"] or 0.0,
        approach=read["approach"] or ("flat" if has_file else "iso8608"),
        approach_length=read["approach_length"],
        iso_class=read["iso_class"] or "C",
        seed=read["seed"],
        spacing=read["spacing"] or 0.025,
        length_unit_name=length_name,
        elevation_unit_name=elevation_name,
    )


def _units(values: dict) -> str:
    """``"US"`` when the span (or the first of the spans) is in US customary units, else SI."""
    bridge = values.get("bridge", {})
    span = bridge.get("span") if "span" in bridge else (bridge.get("spans") or [None])[0]
    try:
        unit = u.read_quantity(span, "length").unit
    except (ValueError, TypeError):
        return "SI"
    names = set(re.findall(r"[A-Za-z_]+", str(u.registry().parse_units(unit))))
    return "US" if names & US_UNITS else "SI"


def read_parameters(values: Mapping[str, Any], base_dir: str | Path = ".") -> ReportParameters:
    """Check report parameters (the nested mapping of a parameter file) and convert them to SI.

    Parameters
    ----------
    values
        The parameters, as YAML gives them: ``title``, ``bridge``, ``vehicle``, ``profile``,
        ``speeds``, ``sections``, ``effects``, ``direction``, ``quick``, ``units`` (see
        :data:`SCHEMA`).
    base_dir
        Folder a relative ``profile.file`` is read from (the parameter file's folder).

    Returns
    -------
    ReportParameters

    Raises
    ------
    ParameterError
        The first key that cannot be used, with its value and what is allowed.

    Examples
    --------
    >>> p = read_parameters({
    ...     "bridge": {"span": "140 ft", "k_mid": "222278 lbf/in", "first_frequency": "2.08 Hz"},
    ...     "vehicle": {"mass": "77.2 kip", "frequency": "2.5 Hz"},
    ...     "speeds": ["30 mph", "70 mph"]})
    >>> round(p.bridge.span, 3), p.units, p.given["vehicle.mass"]
    (42.672, 'US', '77.2 kip')
    >>> read_parameters({"bridge": {"spam": "140 ft"}})
    Traceback (most recent call last):
    ...
    vbi_lib.reports.ParameterError: bridge.spam='140 ft' is not a known key; \
did you mean 'span'? allowed: span, spans, n_spans, k_mid, EI, mass_per_length, \
first_frequency, damping_ratio, modes

    A truck's weight in kN where kip was meant is read, and warned about:

    >>> p = read_parameters({
    ...     "bridge": {"span": "140 ft", "k_mid": "222278 lbf/in", "first_frequency": "2.08 Hz"},
    ...     "vehicle": {"mass": "77.2 kN", "frequency": "2.5 Hz"}, "speeds": ["30 mph"]})
    >>> print(p.warnings[0])  # doctest: +ELLIPSIS
    vehicle.mass='77.2 kN' is a weight of 7.87 t, which is outside the intended range 9.07 to \
200 t ... did you mean '77.2 kip' (35 t)?
    """
    if not isinstance(values, Mapping):
        raise ParameterError(
            "", values, f"parameters must be a mapping of {', '.join(SCHEMA)}; got "
            f"{_short(values)}"
        )  # fmt: skip
    for name in values:
        if name not in SCHEMA:
            raise ParameterError(str(name), values[name], _suggest(str(name), list(SCHEMA)))
    given: dict[str, str] = {}
    sections = {
        name: _section(name, values.get(name, _MISSING), SCHEMA[name])
        for name in ("bridge", "vehicle", "profile")
    }
    if "bridge" not in values:
        raise ParameterError("bridge", _MISSING, "is required, e.g. bridge: {span: 140 ft, ...}")
    bridge = _bridge(sections["bridge"], given)
    if "vehicle" not in values:
        raise ParameterError("vehicle", _MISSING, "is required, e.g. vehicle: {mass: 35 t, ...}")
    warnings: list[str] = []
    vehicle = _vehicle(sections["vehicle"], given, warnings)
    profile = _profile(sections["profile"], given, Path(base_dir))
    top = dict(values)
    speeds = _value("", "speeds", top, SCHEMA, given=given)
    _required("speeds", speeds, "speeds: [30 mph, 45 mph]")
    stations = None
    if "sections" in top:
        stations = _value("", "sections", top, SCHEMA, given=given, most=MAX_SECTIONS)
        length = math.fsum(bridge.spans)
        for i, x in enumerate(stations):
            if x > length * (1 + 1e-12):
                raise ParameterError(
                    f"sections[{i}]", top["sections"][i], f"lies beyond the bridge's far "
                    f"support, {length:.3f} m ({length / u.ft:.2f} ft) from the first"
                )  # fmt: skip
        if len(set(stations)) != len(stations):
            raise ParameterError("sections", top["sections"], "names a station twice")
        stations = tuple(sorted(min(x, length) for x in stations))
    effects = _value("", "effects", top, SCHEMA) or EFFECTS
    units = _value("", "units", top, SCHEMA) or _units(top)
    return ReportParameters(
        title=_value("", "title", top, SCHEMA),
        bridge=bridge,
        vehicle=vehicle,
        profile=profile,
        speeds=speeds,
        quick=_value("", "quick", top, SCHEMA),
        units=units,
        given=given,
        raw=top,
        sections=stations,
        effects=effects,
        direction=_value("", "direction", top, SCHEMA),
        warnings=tuple(warnings),
    )


#: Names IPython itself puts in a notebook's namespace.
_IPYTHON_NAMES = {"In", "Out", "get_ipython", "exit", "quit", "open", "namespace"}
#: Names the template takes besides the parameter file's keys (set by vbi-report).
RUNNER_NAMES = ("source", "results_file")


def notebook_parameters(namespace: Mapping[str, Any]) -> tuple[dict[str, Any], dict[str, Any]]:
    """The report parameters papermill put in a notebook's namespace, and the runner's ``source``.

    The template's parameters cell sets every key of :data:`SCHEMA` to ``None`` (not given),
    ``source`` (what :mod:`vbi_lib.reports.running` knows of the parameter file) to ``None``
    and ``results_file`` (where the results' JSON goes) to ``None``; papermill then assigns
    the parameter file's keys.  A name papermill assigned that is not a key (a typo in the
    file) is refused here, as :func:`read_parameters` refuses it when the file is read
    directly.

    Returns
    -------
    values, source
        The parameters given (``None`` left out) and the ``source`` mapping (empty if unset;
        ``results_file`` is added to it when given).

    Raises
    ------
    ParameterError
        An unknown name, with a "did you mean".
    """
    for name, value in namespace.items():
        if name.startswith("_") or name in _IPYTHON_NAMES or name in RUNNER_NAMES:
            continue
        if name not in SCHEMA:
            raise ParameterError(name, value, _suggest(name, list(SCHEMA)))
    values = {k: namespace[k] for k in SCHEMA if namespace.get(k) is not None}
    source = namespace.get("source") or {}
    if not isinstance(source, Mapping):
        raise ParameterError("source", source, "is set by vbi-report; leave it out")
    source = dict(source)
    results = namespace.get("results_file")
    if results is not None:
        if not isinstance(results, str | Path) or not str(results).strip():
            raise ParameterError(
                "results_file", results, "must be the path of the JSON file of results"
            )
        source["results_file"] = str(results)
    return values, source
