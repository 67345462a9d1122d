"""Units: SI inside the library, US customary factors at the edge.

Every quantity in :mod:`vbi_lib` is in SI (m, kg, s, N).  The study writes its tables in
US customary units, so this module gives the conversion factors as plain floats: multiply
to go *into* SI, divide to come back out::

    >>> from vbi_lib import units as u
    >>> span = 100 * u.ft            # 30.48 m
    >>> round(span / u.inch)         # back to inches
    1200

``slinch`` is the study's mass unit, one lbf s^2 / in (about 175 kg).  Text inputs such as
``"100 ft"`` (report parameters) are read with :func:`read_quantity` (or :func:`parse`,
which returns the SI float): exactly one number and one unit, read with the ``pint`` units
library, dimension checked.
"""

from __future__ import annotations

import math
import re
from functools import lru_cache
from typing import Any, NamedTuple

#: Standard gravity [m/s^2].
g = 9.80665

m = 1.0  #: metre
s = 1.0  #: second
kg = 1.0  #: kilogram
N = 1.0  #: newton
inch = 0.0254  #: [m]
ft = 12 * inch  #: [m]
mile = 5280 * ft  #: [m]
km = 1000.0  #: [m]
mm = 1e-3  #: [m]
lbf = 4.4482216152605  #: pound-force [N]
kip = 1000 * lbf  #: [N]
kN = 1000.0  #: [N]
slinch = lbf / inch  #: lbf s^2/in, the study's mass unit [kg]
slug = lbf / ft  #: lbf s^2/ft [kg]
mph = mile / 3600.0  #: [m/s]
kph = 1000.0 / 3600.0  #: [m/s]
psi = lbf / inch**2  #: [Pa]

#: SI unit that each kind of input is converted to by :func:`parse`.
_SI_UNIT = {
    "length": "m",
    "mass": "kg",
    "force": "N",
    "speed": "m/s",
    "frequency": "Hz",
    "stiffness": "N/m",
    "damping": "N*s/m",
    "flexural_rigidity": "N*m**2",
    "mass_per_length": "kg/m",
    "force_per_length": "N/m",
    "time": "s",
    "dimensionless": "",
}

#: An example of each kind, for error messages.
_EXAMPLE = {
    "length": "'140 ft' or '42.7 m'",
    "mass": "'200 slinch' or '35 t'",
    "force": "'77.2 kip' or '343 kN'",
    "speed": "'45 mph' or '70 km/h'",
    "frequency": "'2.5 Hz'",
    "stiffness": "'222278 lbf/in' or '38900 kN/m'",
    "damping": "'2650 lbf*s/in'",
    "flexural_rigidity": "'7.5e12 lbf*in**2' or '2.2e10 N*m**2'",
    "mass_per_length": "'0.99 slinch/in' or '6850 kg/m'",
    "force_per_length": "'4.6 kip/ft' or '67 kN/m'",
    "time": "'2 s'",
    "dimensionless": "'1 %' or '0.01 dimensionless'",
}


def si_unit(kind: str) -> str:
    """The SI unit (pint text) that :func:`parse` converts a ``kind`` of quantity to.

    >>> si_unit("stiffness")
    'N/m'
    """
    if kind not in _SI_UNIT:
        raise ValueError(f"kind={kind!r} is not known; use one of {sorted(_SI_UNIT)}")
    return _SI_UNIT[kind]


@lru_cache(maxsize=1)
def registry() -> Any:
    """The shared ``pint.UnitRegistry`` with the study's ``slinch`` and ``kip`` defined."""
    import pint

    ureg = pint.UnitRegistry()
    if "slinch" not in ureg:
        ureg.define("slinch = lbf * s**2 / inch")
    ureg.define("kip_mass = kip / gravity")
    return ureg


class Reading(NamedTuple):
    """A quantity read from text by :func:`read_quantity`.

    ``si`` is the value in the SI unit of its kind; ``number`` and ``unit`` are the text as
    written (``"140"``, ``"ft"``), for showing a value in the user's own units.
    """

    si: float
    number: str
    unit: str

    @property
    def text(self) -> str:
        """The quantity as written, spaces tidied: ``"140 ft"``."""
        return f"{self.number} {self.unit}".strip()


_NUMBER = re.compile(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?")
_EXPONENT = re.compile(r"(?:\*\*|\^)\s*\(?\s*[+-]?\d+(?:\.\d+)?\s*\)?")
_NOT_FINITE = re.compile(r"[+-]?(?:nan|inf|infinity)\b", re.IGNORECASE)


def _split(text: str, kind: str, name: str) -> tuple[str, str]:
    """``text`` as (number, unit) texts, or ``ValueError`` saying what is wrong with it."""
    example = _EXAMPLE.get(kind, "'100 ft'")
    if not text:
        raise ValueError(f"{name}='' is empty; give one number and one unit, e.g. {example}")
    if _NOT_FINITE.match(text):
        raise ValueError(f"{name}={text!r} is not a finite number; give e.g. {example}")
    match = _NUMBER.match(text)
    if match is None:
        raise ValueError(
            f"{name}={text!r} does not start with a number; give one number and one unit, "
            f"e.g. {example}"
        )
    number, unit = match.group(), text[match.end() :].strip()
    comma = re.match(r"([+-]?\d+),(\d+)(.*)$", text)
    if comma:
        whole, part, rest = comma.groups()
        raise ValueError(
            f"{name}={text!r} has a comma in its number: a comma is neither a decimal point "
            f"nor a thousands separator here; write '{whole}.{part}{rest}' or "
            f"'{whole}{part}{rest}', whichever you mean"
        )
    if any(mark in unit for mark in ",;"):
        raise ValueError(
            f"{name}={text!r} holds a comma or semicolon; give one number and one unit "
            f"(e.g. {example}), and several values as a YAML list ([30 mph, 45 mph])"
        )
    if not unit:
        raise ValueError(
            f"{name}={text!r} has no unit; give one number and one unit, e.g. {example}"
        )
    if re.search(r"\d", _EXPONENT.sub("", unit)):
        raise ValueError(
            f"{name}={text!r} holds more than one number; give exactly one number and one "
            f"unit (e.g. {example}), and several values as a YAML list ([30 mph, 45 mph])"
        )
    return number, " ".join(unit.split())


def read_quantity(text: object, kind: str, *, name: str = "value") -> Reading:
    """Read exactly one number and one unit (``"140 ft"``) strictly, as an SI value.

    Stricter than pint alone, which multiplies ``"30 45 mph"`` into 1350 mph and reads
    ``"100,5 ft"`` as 1005 ft: the text must be one finite number (a decimal point, no
    comma) followed by one unit that pint knows and whose dimension fits ``kind``.  Units
    may be products, quotients and powers (``"lbf*s**2/in"``, ``"lbf in**2"``).

    Parameters
    ----------
    text
        The quantity as text.  Numbers without a unit are refused (write ``"0.5 Hz"``).
    kind
        What the value is (the kinds of :func:`parse`).
    name
        Parameter name used in error messages.

    Returns
    -------
    Reading
        The SI value and the number and unit as written.

    Raises
    ------
    ValueError
        Naming ``name``, the text and what is allowed: an empty text, no number, NaN or
        infinity, a decimal comma, two numbers, no unit, a unit pint does not know or one of
        the wrong dimension.

    Examples
    --------
    >>> read_quantity("140 ft", "length")
    Reading(si=42.672, number='140', unit='ft')
    >>> read_quantity("30 45 mph", "speed", name="speeds[0]")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: speeds[0]='30 45 mph' holds more than one number; give exactly one number...
    """
    if kind not in _SI_UNIT:
        raise ValueError(f"kind={kind!r} is not known; use one of {sorted(_SI_UNIT)}")
    if not isinstance(text, str):
        example = _EXAMPLE.get(kind, "'100 ft'")
        raise ValueError(
            f"{name}={text!r} must be text with one number and one unit, e.g. {example}"
        )
    text = text.strip()
    number, unit = _split(text, kind, name)
    ureg = registry()
    try:
        units = ureg.parse_units(unit)
    except Exception:  # pint raises several error types for text it cannot read
        raise ValueError(
            f"{name}={text!r}: {unit!r} is not a unit pint knows; give e.g. "
            f"{_EXAMPLE.get(kind, chr(39) + '100 ft' + chr(39))}"
        ) from None
    magnitude = float(number)
    try:
        si = float(ureg.Quantity(magnitude, units).to(_SI_UNIT[kind]).magnitude)
    except Exception:
        raise ValueError(
            f"{name}={text!r} has units {unit!r} but a {kind.replace('_', ' ')} "
            f"(convertible to {_SI_UNIT[kind] or 'a pure number'}) is needed, e.g. "
            f"{_EXAMPLE.get(kind, chr(39) + '100 ft' + chr(39))}"
        ) from None
    if not math.isfinite(si):
        raise ValueError(f"{name}={text!r} is not a finite number")
    return Reading(si, number, unit)


def parse(text: str | float | int, kind: str, *, name: str = "value") -> float:
    """Convert a quantity written as text (``"100 ft"``, ``"4.6 kip/ft"``) to an SI float.

    Text is read strictly by :func:`read_quantity` (one number, one unit); a number that is
    not text is taken as already in SI.

    Parameters
    ----------
    text
        Number and unit, e.g. ``"720 in/s"``, ``"65 mph"``, ``"200 slinch"``.  A bare
        number (int or float, not text) is taken as already in SI.
    kind
        What the value is: one of ``length``, ``mass``, ``force``, ``speed``,
        ``frequency``, ``stiffness``, ``damping``, ``flexural_rigidity``,
        ``mass_per_length``, ``force_per_length``, ``time``, ``dimensionless``.
    name
        Parameter name used in error messages.

    Returns
    -------
    float
        The value in the SI unit of ``kind`` (m, kg, N, m/s, Hz, N/m, N s/m, N m^2, kg/m).

    Raises
    ------
    ValueError
        Text that is not one number and one unit of the right dimension, or a number that is
        not finite, naming ``name``.

    Examples
    --------
    >>> round(parse("100 ft", "length"), 4)
    30.48
    >>> round(parse("4.6 kip/ft", "force_per_length") / g, 1)   # mass per metre
    6845.6
    """
    if kind not in _SI_UNIT:
        raise ValueError(f"kind={kind!r} is not known; use one of {sorted(_SI_UNIT)}")
    if isinstance(text, int | float) and not isinstance(text, bool):
        if not math.isfinite(text):
            raise ValueError(f"{name}={text!r} is not a finite number")
        return float(text)
    return read_quantity(text, kind, name=name).si
