"""The checks of one report parameter: its kind, its unit, its range, and what a refusal says.

Each reader takes the key's dotted name (``bridge.span``), its :class:`Key` and the value as
YAML gives it, and returns it in SI or raises a :class:`ParameterError` naming the key, the
value and what is allowed.  Ranges are :data:`vbi_lib.ranges.RANGES`'s (:class:`Key`
``range``); quantities are read strictly by :func:`vbi_lib.units.read_quantity`.
"""

from __future__ import annotations

import difflib
import math
import numbers
from collections.abc import Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from .. import units as u
from ..beam_statics import EFFECTS
from ..ranges import RANGES

__all__ = ["Key", "ParameterError"]

#: Most speeds, sections and axles a report takes; longest title.
MAX_SPEEDS, MAX_SECTIONS, MAX_AXLES, MAX_TITLE = 20, 30, 20, 200
#: Seeds of a generated road.
SEED_RANGE = (0, 2**32 - 1)


class ParameterError(ValueError):
    """A report parameter that cannot be used; the message names the key, value and rule.

    Public as ``vbi_lib.reports.ParameterError`` (and named so in tracebacks).
    """

    __module__ = "vbi_lib.reports"

    def __init__(self, key: str, value: object, rule: str, message: str | None = None) -> None:
        shown = "(missing)" if value is _MISSING else _short(value)
        super().__init__(message or (f"{key}={shown} {rule}" if key else rule))
        self.key = key
        self.value = value
        self.rule = rule


_MISSING = object()


def _short(value: object, limit: int = 200) -> str:
    """``repr`` of a value, cut to ``limit`` characters (a huge value never fills a message)."""
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 5] + " ...)"


@dataclass(frozen=True)
class Key:
    """One parameter: its kind, the row of :data:`vbi_lib.ranges.RANGES` holding its range,
    its default and a line of help."""

    kind: str
    help: str
    range: str | None = None
    default: Any = _MISSING
    choices: tuple[str, ...] = ()
    #: Outside the intended range but inside the hard one: a warning, not a refusal (a
    #: truck's mass: a light truck is possible, and a unit slip the likely reason).
    warn: bool = False

    @property
    def bounds(self) -> tuple[float, float]:
        """The range [SI]: the entry's soft (intended) range, else its hard one."""
        spec = RANGES[self.range]
        return spec.soft or spec.hard

    @property
    def hard(self) -> tuple[float, float]:
        """The entry's hard range [SI]."""
        return RANGES[self.range].hard

    @property
    def open_low(self) -> bool:
        """Whether the lower bound itself is excluded (a speed > 0)."""
        spec = RANGES[self.range]
        return spec.open_low and (spec.soft is None or spec.soft[0] == spec.hard[0])


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
_RANGE_UNIT = {
    "speed": "km/h",
    "mass": "t",
    "stiffness": "kN/m",
    "mass_per_length": "kg/m",
    "force": "kN",
}


def _range_text(key: Key, unit: str, kind: str | None = None) -> str:
    """``"3 to 300 m (9.84 to 984 ft)"``: the key's range, in SI and in the unit given."""
    ureg = u.registry()
    kind = kind or key.kind
    si_unit = u.si_unit(kind)
    shown = _RANGE_UNIT.get(kind, si_unit)
    bounds = key.bounds
    if math.isinf(bounds[1]):
        return f"above {_g(ureg.Quantity(bounds[0], si_unit).to(shown).magnitude)} {shown}"
    low, high = (ureg.Quantity(v, si_unit).to(shown).magnitude for v in bounds)
    text = f"{_g(low)} to {_g(high)} {shown}"
    try:
        low, high = (ureg.Quantity(v, si_unit).to(unit).magnitude for v in bounds)
    except Exception:  # another dimension: a mass given as a weight, or no alongside
        try:
            low, high = (ureg.Quantity(v * u.g, "N").to(unit).magnitude for v in bounds)
        except Exception:
            return text
    if ureg.parse_units(unit) != ureg.parse_units(shown):
        text += f" ({_g(low)} to {_g(high)} {unit})"
    return text


def _g(value: float) -> str:
    """Three significant digits, thousands separated: ``3,000``, ``0.621``, ``1e+11``."""
    if value == 0:
        return "0"
    if 1e-3 <= abs(value) < 1e6:
        return f"{float(f'{value:.3g}'):,g}"
    return f"{value:.3g}"


def _inside(key: Key, si: float) -> bool:
    low, high = key.bounds
    above = si > low if key.open_low else si >= low
    return above and si <= high


def _outside(key: Key, unit: str, kind: str | None = None) -> str:
    spec = RANGES[key.range]
    what = "intended" if spec.soft else "allowed"
    return (
        f"is outside the {what} range {_range_text(key, unit, kind)} of {spec.quantity} "
        f"(vbi_lib.ranges.RANGES[{key.range!r}])"
    )


#: Units of one dimension that are confused for one another (the same number in another).
_SLIP_UNITS = {
    "force": ("kip", "kN", "lbf", "N", "MN"),
    "mass": ("t", "kg", "slinch", "slug", "lb"),
}


def _likely_slip(number: str, unit: str, kind: str, key: Key) -> str:
    """``" did you mean '77.2 kip' (35 t)?"`` when the same number in another unit of the
    same dimension lands in the key's range; else empty."""
    ureg = u.registry()
    found = []
    for other in _SLIP_UNITS.get(kind, ()):
        try:
            if ureg.parse_units(other) == ureg.parse_units(unit):
                continue
            si = ureg.Quantity(float(number), other).to(u.si_unit(kind)).magnitude
        except Exception:  # pint cannot convert it: no suggestion
            continue
        mass = si / u.g if kind == "force" else si
        if _inside(key, mass):
            found.append(f"'{number} {other}' ({_g(mass / 1000)} t)")
    return f"; did you mean {' or '.join(found[:2])}?" if found else ""


def _quantity(
    name: str, key: Key, value: object, given: dict[str, str], warnings: list | None = None
) -> float:
    """A quantity of ``key.kind`` within the key's range; a mass may be given as a weight.

    A key with ``warn`` is refused outside its entry's hard range only; outside the
    intended range a sentence goes to ``warnings`` (naming the likely slip) instead.
    """
    kinds = {"mass": ("mass", "force"), "mass_per_length": ("mass_per_length", "force_per_length")}
    kind, weight_kind = kinds.get(key.kind, (key.kind, None))
    read_kind = kind
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
        read_kind = weight_kind
    if key.range is None and si < 0:
        raise ParameterError(name, value, "must not be negative")
    if key.range is not None and not _inside(key, si):
        rule = _outside(key, reading.unit, kind)
        if key.kind == "mass":
            lead = f"is a weight of {_g(si / 1000)} t, which " if read_kind == "force" else ""
            rule = lead + rule + _likely_slip(reading.number, reading.unit, read_kind, key)
        low, high = key.hard
        if key.warn and not low <= si <= high:
            spec = RANGES[key.range]
            rule = f"is outside {spec.hard_text()} ({spec.reason}; {rule})"
        if not (key.warn and warnings is not None and low <= si <= high):
            raise ParameterError(name, value, rule)
        warnings.append(f"{name}={value!r} {rule}.".replace("?.", "?"))
    given[name] = reading.text
    return si


def _ratio(
    name: str, key: Key, value: object, given: dict[str, str], warnings: list[str] | None = None
) -> float:
    if isinstance(value, str):
        try:
            number = u.read_quantity(value, "dimensionless", name=name).si
        except ValueError as error:
            raise ParameterError(name, value, "", message=str(error)) from None
    elif isinstance(value, numbers.Real) and not isinstance(value, bool):
        number = float(value)
    else:
        raise ParameterError(name, value, "must be a number such as 0.05, or text such as '5 %'")
    if not math.isfinite(number):
        raise ParameterError(name, value, "must be a finite number such as 0.05, or '5 %'")
    low, high = key.bounds
    if not low <= number <= high:
        rule = (
            f"is outside the intended range {low:g} to {high:g} ({low:.0%} to "
            f"{high:.0%} of critical damping; vbi_lib.ranges.RANGES[{key.range!r}])"
        )
        spec = RANGES[key.range]
        hard_low, hard_high = spec.hard
        if not (key.warn and warnings is not None and hard_low <= number <= hard_high):
            if key.warn:
                rule = f"must be {spec.hard_text()} ({spec.reason})"
            raise ParameterError(name, value, rule)
        warnings.append(f"{name}={value!r} {rule}: {spec.intended}; {spec.reason}.")
    given[name] = f"{number:g} ({number * 100:g} %)"
    return number


def _integer(name: str, key: Key, value: object) -> int:
    low, high = RANGES[key.range].hard if key.range else SEED_RANGE
    if isinstance(value, bool) or not isinstance(value, int):
        raise ParameterError(
            name, value, f"must be a whole number from {low:g} to {high:g} (unquoted)"
        )
    if not low <= value <= high:
        source = f" (vbi_lib.ranges.RANGES[{key.range!r}])" if key.range else ""
        raise ParameterError(name, value, f"is outside {low:g} to {high:g}{source}")
    return int(value)


def _boolean(name: str, value: object) -> bool:
    if not isinstance(value, bool):
        raise ParameterError(name, value, "must be a YAML boolean: true or false, unquoted")
    return value


def _choice(name: str, key: Key, value: object) -> str:
    if not isinstance(value, str) or value.strip() not in key.choices:
        raise ParameterError(name, value, f"must be one of {', '.join(key.choices)}")
    return value.strip()


def _text(name: str, value: object) -> str:
    if not isinstance(value, str) or not value.strip():
        raise ParameterError(name, value, "must be text")
    if len(value) > MAX_TITLE:
        raise ParameterError(name, value, f"is longer than {MAX_TITLE} characters")
    return " ".join(value.split())


def _length_unit(name: str, value: object) -> tuple[float, str]:
    if not isinstance(value, str) or not value.strip() or any(c.isdigit() for c in value):
        raise ParameterError(name, value, "must be the name of a length unit: inch, ft, m, mm")
    try:
        return u.read_quantity(f"1 {value.strip()}", "length", name=name).si, value.strip()
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


def _list(name: str, value: object, low: int, high: int, example: str) -> list:
    if not isinstance(value, list | tuple):
        raise ParameterError(name, value, f"must be a YAML list, e.g. {example}")
    if not low <= len(value) <= high:
        count = f"{low}" if low == high else f"{low} to {high}"
        raise ParameterError(name, value, f"must list {count} values, e.g. {example}")
    return list(value)


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


def _lengths(name: str, key: Key, value: object, given: dict[str, str], high: int) -> tuple:
    items = _list(name, value, 1, high, "[90 ft, 120 ft]")
    item_key = replace(key, kind="length")
    return tuple(_quantity(f"{name}[{i}]", item_key, v, given) for i, v in enumerate(items))


def _weights(name: str, key: Key, value: object, given: dict[str, str]) -> tuple:
    items = _list(name, value, 1, MAX_AXLES, "[12 kip, 34 kip, 34 kip]")
    item_key = replace(key, kind="force")
    return tuple(_quantity(f"{name}[{i}]", item_key, v, given) for i, v in enumerate(items))


def _spacing(name: str, value: object, given: dict[str, str]) -> tuple[float, float]:
    """One rear spacing (``14 ft``) or a range (``[14 ft, 30 ft]``), within 14 to 30 ft."""
    from ..vehicles.fleet import REAR_SPACING_RANGE

    items = value if isinstance(value, list | tuple) else [value]
    if not 1 <= len(items) <= 2:
        raise ParameterError(
            name, value, "must be one length (14 ft) or a YAML list of two, the range in "
            "which the governing spacing is found ([14 ft, 30 ft])"
        )  # fmt: skip
    low, high = REAR_SPACING_RANGE
    out = []
    for i, item in enumerate(items):
        label = f"{name}[{i}]" if len(items) > 1 else name
        try:
            reading = u.read_quantity(item, "length", name=label)
        except ValueError as error:
            raise ParameterError(label, item, "", message=str(error)) from None
        if not low - 1e-9 <= reading.si <= high + 1e-9:
            raise ParameterError(
                label, item, "is outside AASHTO's 14 to 30 ft (4.27 to 9.14 m; LRFD 3.6.1.2.2)"
            )
        given[label] = reading.text
        out.append(min(max(reading.si, low), high))
    if len(out) == 2 and out[1] < out[0]:
        raise ParameterError(name, value, "must list the shorter spacing first")
    return (out[0], out[-1])


def _effects(name: str, key: Key, value: object) -> tuple[str, ...]:
    items = _list(name, value, 1, len(EFFECTS), "[moment, shear]")
    for i, item in enumerate(items):
        if item not in key.choices:
            raise ParameterError(f"{name}[{i}]", item, f"must be one of {', '.join(EFFECTS)}")
    if len(set(items)) != len(items):
        raise ParameterError(name, value, "names an effect twice")
    return tuple(effect for effect in EFFECTS if effect in items)


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
        if key.kind == "spacing":
            return _spacing(full, key.default, {})
        return key.default
    given = context.get("given", {})
    readers = {
        "int": lambda: _integer(full, key, value),
        "bool": lambda: _boolean(full, value),
        "choice": lambda: _choice(full, key, value),
        "text": lambda: _text(full, value),
        "ratio": lambda: _ratio(full, key, value, given, context.get("warnings")),
        "length_unit": lambda: _length_unit(full, value),
        "path": lambda: _path(full, value, context["base_dir"]),
        "speeds": lambda: _speeds(full, key, value, given),
        "lengths": lambda: _lengths(full, key, value, given, context.get("most", MAX_AXLES)),
        "weights": lambda: _weights(full, key, value, given),
        "spacing": lambda: _spacing(full, value, given),
        "effects": lambda: _effects(full, key, value),
    }
    if key.kind in readers:
        return readers[key.kind]()
    if key.warn:
        return _quantity(full, key, value, given, context.get("warnings"))
    if key.range is None and key.kind in ("stiffness",):  # no range of its own: > 0
        try:
            reading = u.read_quantity(value, key.kind, name=full)
        except ValueError as error:
            raise ParameterError(full, value, "", message=str(error)) from None
        if reading.si <= 0:
            raise ParameterError(full, value, "must be greater than zero")
        given[full] = reading.text
        return reading.si
    return _quantity(full, key, value, given)


def _required(name: str, value: object, example: str) -> None:
    if value is None:
        raise ParameterError(name, _MISSING, f"is required, e.g. {example}")


def _truck_weight(name: str, value: object, weight: float, warnings: list[str]) -> None:
    """A vehicle's weight whose mass lies outside a truck's intended range is warned about
    (outside its hard range refused), naming the likely slip."""
    key = Key("mass", "", "truck_mass")
    mass = weight / u.g
    if _inside(key, mass):
        return
    slip = ""
    if isinstance(value, list) and value and all(isinstance(v, str) for v in value):
        units = {u.read_quantity(v, "force").unit for v in value}
        if len(units) == 1:
            unit = units.pop()
            for other in _SLIP_UNITS["force"]:
                try:
                    factor = u.registry().Quantity(1.0, other).to(unit).magnitude
                except Exception:  # pint cannot convert it: no suggestion
                    continue
                if factor != 1.0 and _inside(key, mass * factor):
                    slip = (
                        f"; in {other} instead of {unit} it would weigh {_g(mass * factor / 1e3)} t"
                    )
                    break
    rule = (
        f"weigh {_g(mass / 1000)} t in all, outside the intended range {_range_text(key, 't')} "
        f"of a truck's mass (vbi_lib.ranges.RANGES['truck_mass']){slip}"
    )
    low, high = key.hard
    if not low <= mass <= high:
        raise ParameterError(name, value, rule)
    warnings.append(f"{name}={value!r} {rule}.")
