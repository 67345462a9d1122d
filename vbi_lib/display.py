"""Display units: how results are shown (tables, plots, reprs), chosen once for a session.

The library computes in SI; what a reader sees is a separate choice, made once at the edge
(pycba's ``set_units`` does the same for its plots).  Two systems are defined:

* ``"US"``: the study's US customary units (ft, in, mph, kip, lbf/in, slinch), with SI
  alongside in formatted text;
* ``"SI"``: m, mm, km/h, kN, kN/m, t, with US customary alongside.

Results' ``plot`` and ``to_dataframe`` methods and the chapters use :func:`value`,
:func:`symbol`, :func:`label` and :func:`fmt`, so a chapter never converts by hand; the book
shows a table as a numbered, captioned table with :func:`table`::

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

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import units as u

__all__ = [
    "QUANTITIES",
    "System",
    "Table",
    "current",
    "fmt",
    "label",
    "set_units",
    "short",
    "symbol",
    "table",
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
        "spacing": ("in", u.inch),
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
        "spacing": ("mm", u.mm),
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


def value(si_value: Any, quantity: str) -> Any:
    """An SI value (a number or an array, any shape) in the display unit of ``quantity``
    (the same type and shape back); ``ValueError`` for an unknown quantity."""
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


def _plain(number: float, digits: int) -> str:
    """``number`` with ``digits`` significant digits, in fixed notation between 1e-3 and 1e6."""
    size = abs(number)
    if not np.isfinite(number) or size == 0:
        return f"{number:g}"
    if not 1e-3 <= size < 1e6:
        return f"{number:.{digits - 1}e}"
    decimals = max(0, digits - 1 - int(np.floor(np.log10(size))))
    return f"{number:.{decimals}f}"


def short(si_value: float, quantity: str, digits: int = 4) -> str:
    """A value in the display unit only, for reprs: ``"100.0 ft"``, ``"30.48 m"``.

    ``digits`` significant digits in fixed notation (scientific below 1e-3 and from 1e6 on,
    e.g. flexural rigidities); ``ValueError`` for an unknown quantity.

    >>> set_units("US")
    >>> short(30.48, "length")
    '100.0 ft'
    >>> set_units("SI")
    >>> short(30.48, "length")
    '30.48 m'
    >>> short(2.16e10, "flexural_rigidity")
    '2.160e+10 N m²'
    """
    symbol_, size = _unit(quantity)
    return f"{_plain(float(si_value) / size, digits)} {symbol_}"


# ---------------------------------------------------------------------------- book tables
_LABEL = re.compile(r"^[a-z][a-z0-9]*(-[a-z0-9]+)*$")


@dataclass(frozen=True)
class Table:
    """A numbered, captioned table for the book: MyST Markdown shown by Jupyter.

    ``markdown`` is a ``{table}`` directive around a pipe table.  A notebook cell that
    returns it publishes the text as ``text/markdown``; with the cell's metadata
    ``"mystnb": {"markdown_format": "myst"}`` the book parses the directive, numbers the
    table and lets ``{numref}`` refer to its ``name``.
    """

    markdown: str
    name: str

    def _repr_markdown_(self) -> str:
        return self.markdown

    def __repr__(self) -> str:
        return f"Table({self.name!r})"


#: What a table shows for a missing value (NaN, None): an en dash.
MISSING = "\u2013"
#: A column's format: ``str.format`` text such as ``"{:.2f}"``, or a function of the value.
Format = str | Callable[[Any], str]


def _cell(value: Any, number_format: Format) -> str:
    """One cell's text: integers as integers, other numbers in ``number_format``, a missing
    value as :data:`MISSING`."""
    kind = getattr(getattr(value, "dtype", None), "kind", "")
    if value is None or (isinstance(value, float | np.floating) and np.isnan(value)):
        return MISSING
    if isinstance(value, bool | np.bool_) or kind == "b":
        return "yes" if value else "no"
    if isinstance(value, int | np.integer) or kind in ("i", "u"):
        return str(int(value))
    if isinstance(value, float | np.floating) or kind == "f":
        if callable(number_format):
            return number_format(float(value))
        try:
            return number_format.format(float(value))
        except (ValueError, TypeError):
            return str(value)
    return str(value)


def _flat(name: Any) -> str:
    """A column name as one header: the levels of a multi-level name joined by commas."""
    if isinstance(name, tuple):
        return ", ".join(str(level) for level in name if str(level))
    return str(name)


def table(
    frame: Any,
    caption: str,
    name: str,
    number_format: Format = "{:.4g}",
    index: bool = True,
    formats: Mapping[str, Format] | None = None,
) -> Table:
    """A DataFrame as a numbered, captioned table of the book (MyST ``{table}`` directive).

    The one way the chapters show a table.  Numbers are written with ``number_format``
    (``str.format`` syntax or a function of the value), or with the column's own entry in
    ``formats``, unless the column is already text; format a column yourself (e.g. with
    :func:`fmt`) to give each cell its unit.  Integers stay integers, booleans read "yes"
    and "no", a missing value (NaN, None) is an en dash.  Column names should carry their
    units (:func:`label`); a multi-level column name is joined with commas.  Numeric
    columns are right-aligned; pipes and line breaks in cells are escaped.

    Parameters
    ----------
    frame
        A ``pandas.DataFrame``.
    caption
        The table's caption (MyST Markdown: math and roles allowed), one line.
    name
        The label ``{numref}`` refers to: lowercase words joined by hyphens,
        e.g. ``"table-study-beams"``.
    number_format
        Format of numeric cells.
    index
        Whether the index is the first column (its name heads it; the levels of a
        multi-level index are columns of their own).
    formats
        Formats of particular columns, by their (joined) names; every name must be a column.

    Returns
    -------
    Table

    Raises
    ------
    TypeError
        ``frame`` is not a DataFrame.
    ValueError
        An empty or multi-line caption, a name that is not a label, a table without rows or
        columns, or ``formats`` naming a column the table does not have.

    Examples
    --------
    >>> import pandas as pd
    >>> t = table(pd.DataFrame({"DAF [-]": [1.234567], "span [m]": [30.48]},
    ...                        index=pd.Index(["a"], name="run")),
    ...           "One run.", "table-one-run", formats={"span [m]": "{:.1f}"})
    >>> print(t.markdown)
    :::{table} One run.
    :name: table-one-run
    <BLANKLINE>
    | run | DAF [-] | span [m] |
    |:---|---:|---:|
    | a | 1.235 | 30.5 |
    :::
    """
    import pandas as pd

    if not isinstance(frame, pd.DataFrame):
        raise TypeError(f"frame={type(frame).__name__} must be a pandas DataFrame")
    if not isinstance(caption, str) or not caption.strip() or "\n" in caption.strip():
        raise ValueError(f"caption={caption!r} must be one line of text")
    if not isinstance(name, str) or not _LABEL.match(name):
        raise ValueError(
            f"name={name!r} must be a label of lowercase words joined by hyphens, "
            "e.g. 'table-study-beams'"
        )
    if frame.empty:
        raise ValueError("frame has no rows or no columns: there is no table to show")
    shown = frame.reset_index() if index else frame.copy()
    if index and shown.columns[0] == "index":
        shown = shown.rename(columns={"index": ""})
    shown.columns = [_flat(c) for c in shown.columns]
    formats = dict(formats or {})
    unknown = sorted(set(formats) - set(shown.columns))
    if unknown:
        raise ValueError(
            f"formats={unknown} name no column of the table; its columns are {list(shown.columns)}"
        )
    types = pd.api.types
    numeric = [
        types.is_numeric_dtype(shown.iloc[:, k]) and not types.is_bool_dtype(shown.iloc[:, k])
        for k in range(shown.shape[1])
    ]

    def escape(text: object) -> str:
        return str(text).replace("|", "\\|").replace("\n", " ")

    column_formats = [formats.get(c, number_format) for c in shown.columns]
    header = "| " + " | ".join(escape(c) for c in shown.columns) + " |"
    rule = "|" + "|".join("---:" if n else ":---" for n in numeric) + "|"
    rows = [
        "| "
        + " | ".join(escape(_cell(v, f)) for v, f in zip(row, column_formats, strict=True))
        + " |"
        for row in shown.itertuples(index=False)
    ]
    text = "\n".join([f":::{{table}} {caption.strip()}", f":name: {name}", "", header, rule, *rows])
    return Table(text + "\n:::", name)
