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
from dataclasses import dataclass, field
from typing import Any

from . import units as u

__all__ = [
    "QUANTITIES",
    "System",
    "Table",
    "current",
    "fmt",
    "label",
    "set_units",
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


def _cell(value: Any, number_format: str) -> str:
    """One cell's text: integers as integers, other numbers in ``number_format``."""
    kind = getattr(getattr(value, "dtype", None), "kind", "")
    if isinstance(value, bool) or kind == "b":
        return "yes" if value else "no"
    if isinstance(value, int) or kind in ("i", "u"):
        return str(int(value))
    if isinstance(value, float) or kind == "f":
        try:
            return number_format.format(float(value))
        except (ValueError, TypeError):
            return str(value)
    return str(value)


def table(
    frame: Any,
    caption: str,
    name: str,
    number_format: str = "{:.4g}",
    index: bool = True,
) -> Table:
    """A DataFrame as a numbered, captioned table of the book (MyST ``{table}`` directive).

    Numbers are written with ``number_format`` (``str.format`` syntax) unless the column is
    already text, so format a column yourself (e.g. with :func:`fmt`) to give it units or its
    own digits; numeric columns are right-aligned.  Column names should carry their units
    (:func:`label`).  Pipes and line breaks in cells are escaped.

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
        Whether the index is the first column (its name heads it).

    Returns
    -------
    Table

    Raises
    ------
    TypeError
        ``frame`` is not a DataFrame.
    ValueError
        An empty or multi-line caption, a name that is not a label, or a table without
        rows or columns.

    Examples
    --------
    >>> import pandas as pd
    >>> t = table(pd.DataFrame({"DAF [-]": [1.234567]}, index=pd.Index(["a"], name="run")),
    ...           "One run.", "table-one-run")
    >>> print(t.markdown)
    :::{table} One run.
    :name: table-one-run
    <BLANKLINE>
    | run | DAF [-] |
    |:---|---:|
    | a | 1.235 |
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
    shown = frame.reset_index() if index else frame
    if index and shown.columns[0] == "index":
        shown = shown.rename(columns={"index": ""})
    types = pd.api.types
    numeric = [
        types.is_numeric_dtype(shown[c]) and not types.is_bool_dtype(shown[c])
        for c in shown.columns
    ]

    def escape(text: object) -> str:
        return str(text).replace("|", "\\|").replace("\n", " ")

    header = "| " + " | ".join(escape(c) for c in shown.columns) + " |"
    rule = "|" + "|".join("---:" if n else ":---" for n in numeric) + "|"
    rows = [
        "| " + " | ".join(escape(_cell(v, number_format)) for v in row) + " |"
        for row in shown.itertuples(index=False)
    ]
    text = "\n".join([f":::{{table}} {caption.strip()}", f":name: {name}", "", header, rule, *rows])
    return Table(text + "\n:::", name)
