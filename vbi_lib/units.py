"""Units: SI inside the library, US customary factors at the edge.

Every quantity in :mod:`vbi_lib` is in SI (m, kg, s, N).  The study writes its tables in
US customary units, so this module gives the conversion factors as plain floats: multiply
to go *into* SI, divide to come back out::

    >>> from vbi_lib import units as u
    >>> span = 100 * u.ft            # 30.48 m
    >>> round(span / u.inch)         # back to inches
    1200

``slinch`` is the study's mass unit, one lbf s^2 / in (about 175 kg).  Text inputs such as
``"100 ft"`` (report parameters) are parsed with :func:`parse`, which uses the ``pint``
units library and checks the dimension.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

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


@lru_cache(maxsize=1)
def registry() -> Any:
    """The shared ``pint.UnitRegistry`` with the study's ``slinch`` and ``kip`` defined."""
    import pint

    ureg = pint.UnitRegistry()
    if "slinch" not in ureg:
        ureg.define("slinch = lbf * s**2 / inch")
    ureg.define("kip_mass = kip / gravity")
    return ureg


def parse(text: str | float | int, kind: str, *, name: str = "value") -> float:
    """Convert a quantity written as text (``"100 ft"``, ``"4.6 kip/ft"``) to an SI float.

    Parameters
    ----------
    text
        Number and unit, e.g. ``"720 in/s"``, ``"65 mph"``, ``"200 slinch"``.  A bare
        number is taken as already in SI.
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

    Examples
    --------
    >>> round(parse("100 ft", "length"), 4)
    30.48
    >>> round(parse("4.6 kip/ft", "force_per_length") / g, 1)   # mass per metre
    6845.6
    """
    if kind not in _SI_UNIT:
        raise ValueError(f"kind={kind!r} is not known; use one of {sorted(_SI_UNIT)}")
    if isinstance(text, int | float):
        return float(text)
    ureg = registry()
    try:
        quantity = ureg.Quantity(str(text).strip())
    except Exception as exc:  # pint raises several error types for bad text
        raise ValueError(f"{name}={text!r} is not a quantity pint can read ({exc})") from exc
    try:
        return float(quantity.to(_SI_UNIT[kind]).magnitude)
    except Exception as exc:
        raise ValueError(
            f"{name}={text!r} has units {quantity.units:~} but a {kind.replace('_', ' ')} "
            f"(convertible to {_SI_UNIT[kind] or 'a pure number'}) is needed"
        ) from exc
