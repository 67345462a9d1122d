"""Display units: how results are shown (tables, plots, reprs), chosen once for a session.

The library computes in SI; what a reader sees is a separate choice, made once at the edge
(pycba's ``set_units`` does the same for its plots).  Two systems are defined:

* ``"US"``: the study's US customary units (ft, in, mph, kip, lbf/in, slinch), with SI
  alongside in formatted text;
* ``"SI"``: m, mm, km/h, kN, kN/m, t, with US customary alongside.

Results' ``plot`` and ``to_dataframe`` methods and the chapters use :func:`value`,
:func:`symbol`, :func:`label` and :func:`fmt`, so a chapter never converts by hand::

    >>> from vbi_lib import display
    >>> display.set_units("US")
    >>> display.fmt(30.48, "length")
    '100 ft (30.5 m)'
    >>> display.label("span", "length")
    'span [ft]'
    >>> display.set_units("SI")
    >>> display.fmt(30.48, "length")
    '30.5 m (100 ft)'
"""

from __future__ import annotations

from dataclasses import dataclass, field

from . import units as u

__all__ = [
    "QUANTITIES",
    "System",
    "current",
    "fmt",
    "label",
    "set_units",
    "symbol",
    "value",
]


@dataclass(frozen=True)
class System:
    """A display system: for each kind of quantity, a unit symbol and its size in SI."""

    name: str
    units: dict[str, tuple[str, float]] = field(repr=False)


_COMMON = {
    "frequency": ("Hz", 1.0),
    "time": ("s", 1.0),
    "ratio": ("-", 1.0),
    "damping_ratio": ("%", 0.01),
    "roughness": ("m/km", 1e-3),  # IRI
}

US = System(
    "US",
    {
        **_COMMON,
        "length": ("ft", u.ft),
        "deflection": ("in", u.inch),
        "elevation": ("in", u.inch),
        "speed": ("mph", u.mph),
        "force": ("kip", u.kip),
        "weight": ("kip", u.kip),
        "mass": ("slinch", u.slinch),
        "stiffness": ("lbf/in", u.lbf / u.inch),
        "damping": ("lbf s/in", u.lbf * u.s / u.inch),
        "flexural_rigidity": ("lbf in²", u.lbf * u.inch**2),
        "mass_per_length": ("kip/ft", u.kip / u.ft / u.g),
        "moment": ("kip ft", u.kip * u.ft),
        "acceleration": ("g", u.g),
        "spectral_density": ("m³", 1.0),
    },
)

SI = System(
    "SI",
    {
        **_COMMON,
        "length": ("m", 1.0),
        "deflection": ("mm", u.mm),
        "elevation": ("mm", u.mm),
        "speed": ("km/h", u.kph),
        "force": ("kN", u.kN),
        "weight": ("kN", u.kN),
        "mass": ("t", 1000.0),
        "stiffness": ("kN/m", u.kN),
        "damping": ("kN s/m", u.kN),
        "flexural_rigidity": ("N m²", 1.0),
        "mass_per_length": ("kg/m", 1.0),
        "moment": ("kN m", u.kN),
        "acceleration": ("m/s²", 1.0),
        "spectral_density": ("m³", 1.0),
    },
)

SYSTEMS = {"US": US, "SI": SI}
#: The kinds of quantity every system defines.
QUANTITIES = tuple(sorted(US.units))

_state = {"system": SI, "alongside": True}


def set_units(system: str = "SI", *, alongside: bool = True) -> None:
    """Choose the display system for this session: ``"US"`` or ``"SI"``.

    Parameters
    ----------
    system
        ``"US"`` (the study's units) or ``"SI"``.
    alongside
        Whether :func:`fmt` adds the other system's value in brackets.

    Raises
    ------
    ValueError
        An unknown system.
    """
    key = str(system).upper()
    if key not in SYSTEMS:
        raise ValueError(f"system={system!r} is not known; use 'US' or 'SI'")
    if not isinstance(alongside, bool):
        raise TypeError(f"alongside={alongside!r} must be True or False")
    _state["system"] = SYSTEMS[key]
    _state["alongside"] = alongside


def current() -> System:
    """The display system in use."""
    return _state["system"]


def _unit(quantity: str, system: System | None = None) -> tuple[str, float]:
    units = (system or current()).units
    if quantity not in units:
        raise ValueError(f"quantity={quantity!r} is not known; use one of {', '.join(QUANTITIES)}")
    return units[quantity]


def value(si_value, quantity: str):  # noqa: ANN001, ANN201
    """An SI value (a number or an array) in the display unit of ``quantity``."""
    return si_value / _unit(quantity)[1]


def symbol(quantity: str) -> str:
    """The display unit's symbol for ``quantity``, e.g. ``"ft"``."""
    return _unit(quantity)[0]


def label(text: str, quantity: str) -> str:
    """An axis or column label with the display unit: ``"span [ft]"``."""
    return f"{text} [{symbol(quantity)}]"


def fmt(si_value: float, quantity: str, digits: int = 3) -> str:
    """A value with its display unit, the other system alongside: ``"100 ft (30.5 m)"``.

    ``digits`` significant digits (``"g"`` format); ratios and percentages are shown alone.
    """
    symbol_, size = _unit(quantity)
    main = f"{si_value / size:.{digits}g} {symbol_}"
    if not _state["alongside"] or quantity in _COMMON:
        return main
    other = SI if current() is US else US
    other_symbol, other_size = _unit(quantity, other)
    if other_symbol == symbol_:
        return main
    return f"{main} ({si_value / other_size:.{digits}g} {other_symbol})"
