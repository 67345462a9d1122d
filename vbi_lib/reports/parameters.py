"""Report parameters: the nested YAML an engineer writes, checked key by key before anything runs.

A parameter file names the bridge, the truck, the road and the speeds::

    title: I-76 span 3
    bridge: {span: 140 ft, k_mid: 222278 lbf/in, first_frequency: 2.08 Hz}
    vehicle: {mass: 200 lbf*s**2/in, frequency: 2.5 Hz, damping_ratio: 0.10}
    profile: {file: deck.csv, length_unit: inch}
    speeds: [30 mph, 70 mph]

Every dimensional value is one number and one unit, as text, read strictly by
:func:`vbi_lib.units.read_quantity`; every key has a plausible range (:data:`SCHEMA`);
booleans are YAML booleans; lists are YAML lists.  A key that is not known gets a
"did you mean".  Every refusal is a :class:`ParameterError` naming the key
(``bridge.span``), the value given and what is allowed.
"""

from __future__ import annotations

import difflib
import math
import numbers
import re
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from .. import units as u

__all__ = [
    "DEFAULT_TITLE",
    "SCHEMA",
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


class ParameterError(ValueError):
    """A report parameter that cannot be used; the message names the key, value and rule."""

    def __init__(self, key: str, value: object, rule: str, message: str | None = None) -> None:
        shown = "(missing)" if value is _MISSING else repr(value)
        super().__init__(message or (f"{key}={shown} {rule}" if key else rule))
        self.key = key
        self.value = value
        self.rule = rule


_MISSING = object()


@dataclass(frozen=True)
class Key:
    """One parameter: its kind, plausible range (SI), default and a line of help."""

    kind: str
    help: str
    low: float | None = None
    high: float | None = None
    default: Any = _MISSING
    choices: tuple[str, ...] = ()


#: Every key a parameter file may hold, by section.  Ranges are in SI units.
SCHEMA: dict[str, Any] = {
    "title": Key("text", "title of the report (plain text)", 1, 200, DEFAULT_TITLE),
    "bridge": {
        "span": Key("length", "length of each span", 3.0, 300.0),
        "n_spans": Key("int", "1 (simple span) or 2 (two equal continuous spans)", 1, 2, 1),
        "k_mid": Key("stiffness", "midspan stiffness of the path, load / deflection", 1e5, 1e11),
        "EI": Key("flexural_rigidity", "flexural rigidity of the path's beam", 1e7, 1e14),
        "mass_per_length": Key(
            "mass_per_length", "mass (or weight) per length of the path's beam", 50.0, 2e5
        ),
        "first_frequency": Key("frequency", "first natural frequency", 0.2, 50.0),
        "damping_ratio": Key("ratio", "fraction of critical damping", 0.0, 0.2, 0.01),
    },
    "vehicle": {
        "mass": Key("mass", "sprung mass (or weight) of the truck", 1000.0, 100_000.0),
        "frequency": Key("frequency", "body-bounce frequency", 0.5, 20.0),
        "damping_ratio": Key("ratio", "fraction of critical damping", 0.02, 0.5, 0.10),
        "damped": Key("bool", "true when frequency is the damped frequency", default=False),
    },
    "profile": {
        "file": Key("path", "deck profile: two columns, station and elevation"),
        "length_unit": Key("length_unit", "unit of the file's stations (inch, ft, m, mm)"),
        "elevation_unit": Key("length_unit", "unit of the file's elevations if different"),
        "bridge_start": Key(
            "length", "station of the first support from the file's first point", 0.0, 10_000.0
        ),
        "approach": Key(
            "choice",
            "road before the bridge: flat, or an ISO 8608 road (fitted to the deck)",
            choices=("flat", "iso8608"),
        ),
        "approach_length": Key("length", "length of the approach", 5.0, 3000.0),
        "iso_class": Key("choice", "ISO 8608 class of a generated road", choices=tuple("ABCDEFGH")),
        "seed": Key("int", "seed of a generated road's random phases", 0, 2**32 - 1, 1),
        "spacing": Key("length", "sample spacing of a generated road", 0.005, 0.1),
    },
    "speeds": Key("speeds", "truck speeds, a YAML list", 1 * u.kph, 150 * u.kph),
    "quick": Key("bool", "fewer points in the sweeps (for tests)", default=False),
    "units": Key("choice", "units shown first (the other alongside)", choices=("US", "SI")),
}

#: Most speeds a report runs.
MAX_SPEEDS = 20

_BRIDGE_ROUTES = (
    ("k_mid", "first_frequency"),
    ("EI", "mass_per_length"),
    ("mass_per_length", "first_frequency"),
)


@dataclass(frozen=True)
class BridgeParameters:
    """The bridge's parameters in SI (``None`` where not given)."""

    span: float
    n_spans: int
    damping_ratio: float
    k_mid: float | None = None
    EI: float | None = None
    mass_per_length: float | None = None
    first_frequency: float | None = None


@dataclass(frozen=True)
class VehicleParameters:
    """The truck's parameters in SI."""

    mass: float
    frequency: float
    damping_ratio: float
    damped: bool


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
        Truck speeds [m/s].
    quick
        Fewer points in the sweeps.
    units
        ``"US"`` or ``"SI"``: the units shown first.
    given
        Each quantity as written, by key (``{"bridge.span": "140 ft"}``), for the inputs table.
    raw
        The parameters as given (plain YAML types), for the provenance section.
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


# ---------------------------------------------------------------------------- checks of one value
def _suggest(key: str, allowed: list[str]) -> str:
    if key[:1].isdigit():
        return (
            "is not a known key: it looks like the rest of a number cut at a comma (inside "
            "{ } a comma separates entries); write numbers with a decimal point, e.g. 30.5 m"
        )
    close = difflib.get_close_matches(key, allowed, n=1, cutoff=0.6)
    hint = f"did you mean {close[0]!r}? " if close else ""
    return f"is not a known key; {hint}allowed: {', '.join(allowed)}"


#: Unit a range is shown in, by kind (SI, or a decimal multiple of it).
_RANGE_UNIT = {"speed": "km/h", "mass": "t", "stiffness": "kN/m", "mass_per_length": "kg/m"}


def _range_text(key: Key, unit: str) -> str:
    """``"3 to 300 m (9.84 to 984 ft)"``: the key's range, in SI and in the unit given."""
    ureg = u.registry()
    si_unit = u.si_unit(key.kind)
    shown = _RANGE_UNIT.get(key.kind, si_unit)
    low, high = (ureg.Quantity(v, si_unit).to(shown).magnitude for v in (key.low, key.high))
    text = f"{_g(low)} to {_g(high)} {shown}"
    try:
        low, high = (ureg.Quantity(v, si_unit).to(unit).magnitude for v in (key.low, key.high))
    except Exception:  # a weight for a mass, or the same unit: SI alone
        return text
    if ureg.parse_units(unit) != ureg.parse_units(shown):
        text += f" ({_g(low)} to {_g(high)} {unit})"
    return text


def _g(value: float) -> str:
    """Three significant digits, thousands separated: ``3,000``, ``0.621``, ``1e+11``."""
    if 1e-3 <= abs(value) < 1e6:
        return f"{float(f'{value:.3g}'):,g}"
    return f"{value:.3g}"


def _quantity(name: str, key: Key, value: object, given: dict[str, str]) -> float:
    """A quantity of ``key.kind`` within the key's range; a mass may be given as a weight."""
    kinds = {"mass": ("mass", "force"), "mass_per_length": ("mass_per_length", "force_per_length")}
    kind, weight_kind = kinds.get(key.kind, (key.kind, None))
    try:
        reading = u.read_quantity(value, kind, name=name)
        si = reading.si
    except ValueError as error:
        if weight_kind is None or not isinstance(value, str) or "has units" not in str(error):
            raise ParameterError(name, value, "", message=str(error)) from None
        try:
            reading = u.read_quantity(value, weight_kind, name=name)
        except ValueError:
            what = "a mass per length or a weight per length" if "length" in kind else "a mass"
            example = "'0.99 slinch/in' or '4.6 kip/ft'" if "length" in kind else "'35 t'"
            raise ParameterError(
                name, value, f"must be {what} or a weight, e.g. {example} or '77.2 kip'"
            ) from None
        si = reading.si / u.g
    if not key.low <= si <= key.high:
        raise ParameterError(
            name, value, f"is outside the plausible range {_range_text(key, reading.unit)}"
        )
    given[name] = reading.text
    return si


def _ratio(name: str, key: Key, value: object, given: dict[str, str]) -> float:
    if isinstance(value, str):
        try:
            number = u.read_quantity(value, "dimensionless", name=name).si
        except ValueError as error:
            raise ParameterError(name, value, "", message=str(error)) from None
    elif isinstance(value, numbers.Real) and not isinstance(value, bool):
        number = float(value)
    else:
        raise ParameterError(name, value, "must be a number such as 0.05, or text such as '5 %'")
    if not (math.isfinite(number) and key.low <= number <= key.high):
        raise ParameterError(
            name, value, f"is outside the plausible range {key.low:g} to {key.high:g} "
            f"({key.low:.0%} to {key.high:.0%} of critical damping)"
        )  # fmt: skip
    given[name] = f"{number:g} ({number * 100:g} %)"
    return number


def _integer(name: str, key: Key, value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise ParameterError(
            name, value, f"must be a whole number from {key.low:g} to {key.high:g} (unquoted)"
        )
    if not key.low <= value <= key.high:
        raise ParameterError(name, value, f"is outside {key.low:g} to {key.high:g}")
    return int(value)


def _boolean(name: str, value: object) -> bool:
    if not isinstance(value, bool):
        raise ParameterError(name, value, "must be a YAML boolean: true or false, unquoted")
    return value


def _choice(name: str, key: Key, value: object) -> str:
    if not isinstance(value, str) or value.strip() not in key.choices:
        raise ParameterError(name, value, f"must be one of {', '.join(key.choices)}")
    return value.strip()


def _text(name: str, key: Key, value: object) -> str:
    if not isinstance(value, str) or not value.strip():
        raise ParameterError(name, value, "must be text")
    if len(value) > key.high:
        raise ParameterError(name, value, f"is longer than {key.high:g} characters")
    return " ".join(value.split())


def _length_unit(name: str, value: object) -> float:
    if not isinstance(value, str) or not value.strip() or any(c.isdigit() for c in value):
        raise ParameterError(name, value, "must be the name of a length unit: inch, ft, m, mm")
    try:
        return u.read_quantity(f"1 {value.strip()}", "length", name=name).si
    except ValueError:
        raise ParameterError(
            name, value, "is not a length unit pint knows; use e.g. inch, ft, m or mm"
        ) from None


def _path(name: str, value: object, base_dir: Path) -> Path:
    if not isinstance(value, str) or not value.strip():
        raise ParameterError(
            name, value, "must be the path of a profile file (text); leave the key out for a "
            "generated road"
        )  # fmt: skip
    path = Path(value.strip()).expanduser()
    if not path.is_absolute():
        path = base_dir / path
    if not path.is_file():
        where = f" (looked for {path})" if path != Path(value) else ""
        raise ParameterError(name, value, f"is not a file that exists{where}")
    return path.resolve()


def _speeds(name: str, key: Key, value: object, given: dict[str, str]) -> tuple[float, ...]:
    if not isinstance(value, list | tuple):
        raise ParameterError(
            name, value, "must be a YAML list of speeds with units, e.g. [30 mph, 45 mph]"
        )
    if not 1 <= len(value) <= MAX_SPEEDS:
        raise ParameterError(name, value, f"must list 1 to {MAX_SPEEDS} speeds")
    speeds: list[float] = []
    item_key = replace(key, kind="speed")
    for i, item in enumerate(value):
        speed = _quantity(f"{name}[{i}]", item_key, item, given)
        if any(math.isclose(speed, s, rel_tol=1e-9) for s in speeds):
            raise ParameterError(f"{name}[{i}]", item, "repeats an earlier speed")
        speeds.append(speed)
    return tuple(speeds)


# ---------------------------------------------------------------------------- sections
def _section(name: str, value: object, schema: dict[str, Key]) -> dict[str, Any]:
    if value is _MISSING:
        value = {}
    if not isinstance(value, Mapping):
        raise ParameterError(name, value, f"must be a mapping of {', '.join(schema)}")
    for key in value:
        if key not in schema:
            raise ParameterError(f"{name}.{key}", value[key], _suggest(str(key), list(schema)))
    return dict(value)


def _value(section: str, name: str, values: dict, schema: dict[str, Key], **context: Any) -> Any:
    key = schema[name]
    full = f"{section}.{name}" if section else name
    value = values.get(name, _MISSING)
    if value is _MISSING:
        if key.default is _MISSING:
            return None
        return key.default
    given = context.get("given", {})
    if key.kind in ("int",):
        return _integer(full, key, value)
    if key.kind == "bool":
        return _boolean(full, value)
    if key.kind == "choice":
        return _choice(full, key, value)
    if key.kind == "text":
        return _text(full, key, value)
    if key.kind == "ratio":
        return _ratio(full, key, value, given)
    if key.kind == "length_unit":
        return _length_unit(full, value)
    if key.kind == "path":
        return _path(full, value, context["base_dir"])
    if key.kind == "speeds":
        return _speeds(full, key, value, given)
    return _quantity(full, key, value, given)


def _required(name: str, value: object, example: str) -> None:
    if value is None:
        raise ParameterError(name, _MISSING, f"is required, e.g. {example}")


def _bridge(values: dict, given: dict[str, str]) -> BridgeParameters:
    schema = SCHEMA["bridge"]
    read = {name: _value("bridge", name, values, schema, given=given) for name in schema}
    _required("bridge.span", read["span"], "span: 140 ft")
    stiffness = [k for k in ("k_mid", "EI", "mass_per_length", "first_frequency") if k in values]
    if sorted(stiffness) not in [sorted(route) for route in _BRIDGE_ROUTES]:
        routes = "; or ".join(" and ".join(route) for route in _BRIDGE_ROUTES)
        got = ", ".join(stiffness) or "none of them"
        raise ParameterError(
            "bridge", {k: values[k] for k in stiffness}, f"needs exactly {routes}; got {got}"
        )
    return BridgeParameters(**read)


def _vehicle(values: dict, given: dict[str, str]) -> VehicleParameters:
    schema = SCHEMA["vehicle"]
    read = {name: _value("vehicle", name, values, schema, given=given) for name in schema}
    _required("vehicle.mass", read["mass"], "mass: 35 t (or a weight, 77.2 kip)")
    _required("vehicle.frequency", read["frequency"], "frequency: 2.5 Hz")
    return VehicleParameters(**read)


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
    return ProfileParameters(
        file=read["file"],
        length_unit=read["length_unit"],
        elevation_unit=read["elevation_unit"] or read["length_unit"],
        bridge_start=read["bridge_start"] or 0.0,
        approach=read["approach"] or ("flat" if has_file else "iso8608"),
        approach_length=read["approach_length"],
        iso_class=read["iso_class"] or "C",
        seed=read["seed"],
        spacing=read["spacing"] or 0.025,
    )


def _units(values: dict) -> str:
    """``"US"`` when the span is written in US customary units, else ``"SI"``."""
    span = values.get("bridge", {}).get("span")
    try:
        unit = u.read_quantity(span, "length").unit
    except ValueError:
        return "SI"
    names = set(re.findall(r"[A-Za-z_]+", str(u.registry().parse_units(unit))))
    return "US" if names & US_UNITS else "SI"


def read_parameters(values: Mapping[str, Any], base_dir: str | Path = ".") -> ReportParameters:
    """Check report parameters (the nested mapping of a parameter file) and convert them to SI.

    Parameters
    ----------
    values
        The parameters, as YAML gives them: ``title``, ``bridge``, ``vehicle``, ``profile``,
        ``speeds``, ``quick``, ``units`` (see :data:`SCHEMA`).
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
    vbi_lib.reports.parameters.ParameterError: bridge.spam='140 ft' is not a known key; \
did you mean 'span'? allowed: span, n_spans, k_mid, EI, mass_per_length, first_frequency, \
damping_ratio
    """
    if not isinstance(values, Mapping):
        raise ParameterError(
            "", values, f"parameters must be a mapping of {', '.join(SCHEMA)}; got {values!r}"
        )
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
    vehicle = _vehicle(sections["vehicle"], given)
    profile = _profile(sections["profile"], given, Path(base_dir))
    speeds = _value("", "speeds", dict(values), SCHEMA, given=given)
    _required("speeds", speeds, "speeds: [30 mph, 45 mph]")
    units = _value("", "units", dict(values), SCHEMA) or _units(dict(values))
    return ReportParameters(
        title=_value("", "title", dict(values), SCHEMA),
        bridge=bridge,
        vehicle=vehicle,
        profile=profile,
        speeds=speeds,
        quick=_value("", "quick", dict(values), SCHEMA),
        units=units,
        given=given,
        raw=dict(values),
    )


#: Names IPython itself puts in a notebook's namespace.
_IPYTHON_NAMES = {"In", "Out", "get_ipython", "exit", "quit", "open", "namespace"}


def notebook_parameters(namespace: Mapping[str, Any]) -> tuple[dict[str, Any], dict[str, Any]]:
    """The report parameters papermill put in a notebook's namespace, and the runner's ``source``.

    The template's parameters cell sets every key of :data:`SCHEMA` to ``None`` (not given)
    and ``source`` (what :mod:`vbi_lib.reports.running` knows of the parameter file) to
    ``None``; papermill then assigns the parameter file's keys.  A name papermill assigned
    that is not a key (a typo in the file) is refused here, as :func:`read_parameters`
    refuses it when the file is read directly.

    Returns
    -------
    values, source
        The parameters given (``None`` left out) and the ``source`` mapping (empty if unset).

    Raises
    ------
    ParameterError
        An unknown name, with a "did you mean".
    """
    for name, value in namespace.items():
        if name.startswith("_") or name in _IPYTHON_NAMES or name == "source":
            continue
        if name not in SCHEMA:
            raise ParameterError(name, value, _suggest(name, list(SCHEMA)))
    values = {k: namespace[k] for k in SCHEMA if namespace.get(k) is not None}
    source = namespace.get("source") or {}
    if not isinstance(source, Mapping):
        raise ParameterError("source", source, "is set by vbi-report; leave it out")
    return values, dict(source)
