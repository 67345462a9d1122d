"""The report's text, tables and figures as HTML: every value formatted, every user text escaped.

Values are shown in the report's display system (:func:`use_units`: the user's US customary
units with SI alongside, or SI alone); numbers keep three significant digits (whole numbers
in full), never ``30.000000``.  Everything the user wrote (title, file names, parameters)
passes through :func:`html.escape` before it reaches the page.

Each section of the report is one block (:func:`block`): its heading, its text, its tables
and its figures (:mod:`.figures`: inline SVG, scaled to the page's width) in one
``<section>`` whose heading a printed page keeps with what follows; wide tables are cut into
parts that fit the page.  Here: the title, the summary, the DAF tables, the tyres' flights;
the inputs, the road, the limits and the provenance are :mod:`.appendix`'s.
"""

from __future__ import annotations

import datetime as _dt
import html
import math
from collections.abc import Iterable, Sequence

import numpy as np

from .. import display
from ..beam_statics import QUANTITY
from ..units import ft
from ..vehicles import as_system
from .analysis import ReportAnalysis
from .inputs import ReportInputs

__all__ = [
    "block",
    "daf_html",
    "flights_html",
    "number",
    "position_html",
    "quantity",
    "sections_html",
    "summary_html",
    "title_html",
    "use_units",
]

#: Most speed columns in one table (wider tables are cut into parts).
SPEEDS_PER_TABLE = 6


def use_units(inputs: ReportInputs) -> None:
    """Show the user's system first: US customary with SI alongside, or SI alone."""
    system = inputs.parameters.units
    display.set_units(system, alongside=system == "US")


def number(value: float, digits: int = 3) -> str:
    """A number for people: three significant digits, whole numbers in full, no ``30.000000``.

    >>> [number(v) for v in (30.0, 103.228799, 0.012345, 222278.0, 2.196e13, -1.5, float("nan"))]
    ['30', '103', '0.0123', '222,278', '2.2e13', '-1.5', '-']
    """
    if value is None or not math.isfinite(value):
        return "-"
    if value == 0:
        return "0"
    exponent = math.floor(math.log10(abs(value)))
    if exponent >= 7 or exponent < -3:
        mantissa, power = f"{value:.{digits - 1}e}".split("e")
        return f"{_trim(mantissa)}e{int(power)}"
    decimals = max(0, digits - 1 - exponent)
    return _trim(f"{round(value, decimals):,.{decimals}f}")


def _trim(text: str) -> str:
    """``"30.0"`` -> ``"30"``, ``"1.50"`` -> ``"1.5"``."""
    return text.rstrip("0").rstrip(".") if "." in text else text


def quantity(si_value: float, kind: str, digits: int = 3) -> str:
    """A value in the display unit of ``kind``, the other system alongside when chosen.

    >>> display.set_units("US")
    >>> quantity(42.672, "length")
    '140 ft (42.7 m)'
    >>> display.set_units("SI", alongside=False)
    >>> quantity(42.672, "length")
    '42.7 m'
    """
    main = f"{number(display.value(si_value, kind), digits)} {display.symbol(kind)}"
    text = display.fmt(1.0, kind)  # tells whether the other system is shown alongside
    if "(" not in text:
        return main
    other = display.SI if display.current() is display.US else display.US
    symbol, size = other.units[kind]
    return f"{main} ({number(si_value / size, digits)} {symbol})"


def _e(text: object) -> str:
    return html.escape(str(text), quote=False)  # text nodes only, never attributes


def _table(header: Iterable[str], rows: Iterable[Iterable[str]], css: str) -> str:
    """An HTML table; every cell is escaped."""
    head = "".join(f"<th>{_e(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{_e(c)}</td>" for c in row) + "</tr>" for row in rows)
    return (
        f'<table class="vbi-table {css}"><thead><tr>{head}</tr></thead>'
        f"<tbody>{body}</tbody></table>"
    )


def block(heading: str, *parts: str, css: str = "") -> str:
    """One section of the report: ``<h2>`` and its parts (HTML), printed together."""
    return (
        f'<section class="vbi-block {css}"><h2>{_e(heading)}</h2>' + "".join(parts) + "</section>"
    )


def _p(text: str, css: str = "") -> str:
    return f'<p class="{css}">{_e(text)}</p>' if css else f"<p>{_e(text)}</p>"


def _speed(speed: float) -> str:
    return quantity(speed, "speed")


def _arrow(direction: str) -> str:
    return "forward" if direction == "forward" else "backward"


def _vehicle_name(analysis_or_inputs: object) -> str:
    inputs = getattr(analysis_or_inputs, "inputs", analysis_or_inputs)
    kind = inputs.parameters.vehicle.type
    names = {
        "sprung-mass": "one truck (the study's sprung mass)",
        "quarter-car": "one truck as a quarter car (sprung and unsprung mass, a tyre)",
        "hs20": "the AASHTO HS20 design truck",
        "hl93-truck": "the AASHTO LRFD (HL-93) design truck",
        "hl93-tandem": "the AASHTO LRFD (HL-93) design tandem",
        "axles": "a permit vehicle of its axles",
    }
    return names[kind]


def title_html(inputs: ReportInputs) -> str:
    """The title and one line on what the report is."""
    import vbi_lib

    today = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d")
    effects = ", ".join(inputs.effects)
    return (
        f'<h1 class="vbi-title">{_e(inputs.parameters.title)}</h1>'
        f'<p class="vbi-subtitle">Dynamic amplification factor (DAF) of the {_e(effects)} at '
        f"{len(inputs.places)} places of the bridge under {_e(_vehicle_name(inputs))}, "
        f"computed with vbi {_e(vbi_lib.__version__)} on {today}.</p>"
    )


# ---------------------------------------------------------------------------- summary
def _verdict(daf: float, allowance: float) -> str:
    return f"exceeds {allowance:.2f}" if daf > allowance else f"within {allowance:.2f}"


def _short_speed(speed: float) -> str:
    """A speed in the display unit alone (tables): ``"55 mph"``."""
    return f"{number(display.value(speed, 'speed'))} {display.symbol('speed')}"


def _where(row: object) -> str:
    text = f"{_short_speed(row.speed_m_s)} {_arrow(row.direction)}"
    spacing = row.rear_axle_spacing_m
    if spacing is not None and np.isfinite(spacing):
        text += f", {number(spacing / ft)} ft rear spacing"
    return text


def _contact_sentence(analysis: ReportAnalysis) -> str:
    rows = analysis.sections.rows.drop_duplicates("crossing")
    lost = rows[rows.lost_contact]
    system = as_system(analysis.inputs.vehicle)
    flights = analysis.flights
    parts = []
    if lost.empty:
        if not system.has_unilateral:
            ratio = float(rows.min_contact_force_ratio.min())
            parts.append(
                "The vehicle stayed on the road at every requested speed and direction: no "
                f"axle's contact force fell below {number(ratio)} times its static load, so "
                "the model's assumption that the wheels never leave the road held."
            )
    else:
        where = " and ".join(_where(r) for r in lost.itertuples())
        every = len(lost) == len(rows)
        parts.append(
            f"At {where} the contact force became tensile: a real wheel would have lifted "
            "off, and the model, which keeps it on the road, is outside its validity there. "
            + ("No DAF in this report is within the model's validity." if every else
               "Those crossings are marked 'contact lost' and left out of the largest DAFs.")
        )  # fmt: skip
    if system.has_unilateral:
        prints = sorted({number(f * 1000) for f in flights.footprint})
        footprint = f"each tyre averages the road over a footprint of {' or '.join(prints)} mm"
        table = flights.table
        on = table[table.on_bridge] if not table.empty else table
        if on.empty:
            parts.append(
                f"The tyres can leave the road in this model ({footprint}); none did on the "
                "bridge at the requested speeds."
            )
        else:
            first = on.loc[on.duration_s.fillna(np.inf).idxmax()]
            parts.append(
                f"The tyres left the road on the bridge in {len(on)} flights ({footprint}): "
                f"the longest, axle {first.axle} at {_speed(first.speed_m_s)} "
                f"{_arrow(first.direction)}, took off at {quantity(first.take_off_m, 'length')} "
                f"from the first support and stayed off {number(first.duration_s * 1000)} ms. "
                "A flight is modelled (the tyre lands again), not a loss of validity; the "
                "section 'The tyres' lists every flight."
            )
    return " ".join(parts)


def summary_html(analysis: ReportAnalysis) -> str:
    """The DAF of each effect at each place against the design codes, and the contact check."""
    study = analysis.sections
    codes = analysis.allowances
    rows = []
    for c, col in enumerate(study.columns):
        best = study.largest(c)
        code = codes.by_column[c]
        place = f"{col.label} ({number(display.value(col.place.x, 'length'))} " + (
            f"{display.symbol('length')})"
        )  # fmt: skip
        if best is None:
            some = study.rows[(study.rows.column == c) & study.rows.daf.notna()]
            got = f"{some.daf.max():.2f}" if not some.empty else "-"
            rows.append([place, col.effect,
                         f"none valid (the model gives {got}, contact lost)", "-",
                         "not comparable", "not comparable", "-", "-"])  # fmt: skip
            continue
        rows.append([
            place,
            col.effect,
            f"{best.daf:.2f}",
            _where(best),
            _verdict(best.daf, code["AASHTO LRFD"]),
            _verdict(best.daf, code["AASHTO LRFD fatigue"]),
            f"{code['AASHTO Standard']:.2f}",
            f"{code['OHBDC 1983']:.2f}",
        ])  # fmt: skip
    header = ["place", "effect", "largest DAF", "at", "LRFD 1 + IM", "LRFD fatigue",
              "AASHTO Std.", "OHBDC 1983"]  # fmt: skip
    warnings = ""
    if analysis.inputs.warnings:
        items = "".join(f"<li>{_e(w)}</li>" for w in analysis.inputs.warnings)
        warnings = (
            '<div class="vbi-warning"><strong>Check these inputs before using the results.'
            f"</strong><ul>{items}</ul></div>"
        )
    lost = study.rows.lost_contact.any()
    css = "vbi-lost" if lost else "vbi-kept"
    lrfd = codes.aashto_lrfd
    text = (
        "The largest DAF of each effect at each place over the requested speeds and "
        f"directions, against AASHTO LRFD's dynamic load allowance (1 + IM = {lrfd:.2f}, "
        f"{codes.aashto_fatigue:.2f} for fatigue and fracture; Table 3.6.2.1-1), the AASHTO "
        "Standard Specifications' impact 50 / (L + 125) <= 0.30 with its loaded length L in "
        "feet for that place and effect (3.8.2.2) and the Ontario code of 1983 (from the first "
        "frequency)."
    )
    return block(
        "Summary",
        warnings,
        _p(text),
        _table(header, rows, "vbi-largest vbi-wide"),
        f'<p class="{css}"><strong>Contact.</strong> {_e(_contact_sentence(analysis))}</p>',
        css="vbi-summary",
    )


# ---------------------------------------------------------------------------- DAF tables
def _chunks(items: Sequence, size: int) -> list:
    return [items[i : i + size] for i in range(0, len(items), size)] or [items]


def sections_html(analysis: ReportAnalysis) -> str:
    """The DAF of each effect at each place, per requested speed and direction."""
    study = analysis.sections
    inputs = analysis.inputs
    rows_all = study.rows
    runs = [(d, v) for v in inputs.speeds for d in inputs.directions]
    parts = []
    for effect in inputs.effects:
        cols = [c for c, col in enumerate(study.columns) if col.effect == effect]
        if not cols:
            continue
        quantity_kind = QUANTITY[effect]
        unit = display.symbol(quantity_kind)
        for chunk in _chunks(runs, SPEEDS_PER_TABLE):
            header = ["place", f"static [{unit}]"] + [
                f"{_short_speed(v)} {_arrow(d)}" for d, v in chunk
            ]
            body = []
            for c in cols:
                mine = rows_all[rows_all.column == c]
                forward = mine[mine.direction == inputs.directions[0]].iloc[0]
                static = number(display.value(forward.static, quantity_kind))
                row = [study.columns[c].label, static]
                for d, v in chunk:
                    r = mine[(mine.direction == d) & (mine.speed_m_s == v)].iloc[0]
                    cell = "-" if not np.isfinite(r.daf) else f"{r.daf:.3f}"
                    if r.lost_contact:
                        cell += " (contact lost)"
                    row.append(cell)
                body.append(row)
            parts.append(f'<p class="vbi-caption">{_e(effect.capitalize())}:</p>')
            parts.append(_table(header, body, f"vbi-sections vbi-wide vbi-{effect}"))
    text = (
        "Each DAF is the extreme of the effect at that place over the whole crossing, by the "
        "mode-acceleration method (exact statics plus the modes' dynamics), divided by its "
        "extreme when the same axle loads crawl across in the same direction, in the sense "
        "(the largest or the smallest) in which that static extreme is the larger; the static "
        f"column gives it ({inputs.directions[0]}). Signs: displacement up, moment sagging, "
        "shear dM/dx with x from the first support. At an interior support the shear is given "
        "just left and just right of it."
    )
    spacing = ""
    if analysis.spacing_search is not None:
        spacing = _spacing_html(analysis)
    return block("DAF of each effect at each place", _p(text), spacing, *parts)


def _spacing_html(analysis: ReportAnalysis) -> str:
    study = analysis.sections
    low, high = analysis.inputs.parameters.vehicle.rear_axle_spacing
    rows, found = [], []
    for c, col in enumerate(study.columns):
        spacing = study.rows[study.rows.column == c].rear_axle_spacing_m.iloc[0]
        found.append(spacing)
        rows.append([col.label, col.effect, f"{number(spacing / ft)} ft ({number(spacing)} m)"])
    text = (
        f"The design truck's rear axle spacing is varied from {number(low / ft)} to "
        f"{number(high / ft)} ft to produce the extreme force effects (AASHTO LRFD "
        "3.6.1.2.2): for each place and effect the spacing whose static extreme is the "
        "largest (every 0.5 ft, exact statics, the directions asked) governs, and the truck "
        "with that spacing is run."
    )
    if len(set(found)) == 1:
        return _p(text + f" Here {number(found[0] / ft)} ft governs every place and effect.")
    return _p(text) + _table(["place", "effect", "governing rear spacing"], rows, "vbi-spacing")


def daf_html(analysis: ReportAnalysis) -> str:
    """The study's span DAF at each requested speed (coupled, decoupled bound) and the contact
    checks (the study's own case), with the design codes' values."""
    study = analysis.requested
    codes = [[name, f"{value:.2f}"] for name, value in analysis.allowances.daf.items()]
    codes_table = _table(["design code", "design DAF (1 + IM)"], codes, "vbi-codes")
    if study is None:
        return block("Design codes", codes_table)
    n = analysis.inputs.bridge.n_spans
    header = ["speed"]
    for j in range(n):
        header += [f"DAF span {j + 1}", f"DAF span {j + 1}, decoupled bound"]
    header += ["contact force / weight, smallest to largest", "contact"]
    rows = []
    for i, speed in enumerate(study.speeds):
        lost = bool(study.lost_contact[i])
        row = [_speed(speed)]
        for j in range(n):
            daf = f"{study.coupled.daf[i, j]:.3f}"
            row += [f"{daf} (contact lost: outside validity)" if lost else daf,
                    f"{study.decoupled.daf[i, j]:.3f}"]  # fmt: skip
        low = number(float(study.coupled.min_contact_force_ratio[i]), 2)
        high = number(float(study.coupled.contact_force_amplification[i]), 2)
        row += [f"{low} to {high}", "LOST: outside validity" if lost else "kept"]
        rows.append(row)
    text = (
        "The study's span DAF (its equations 88-91: the largest downward midspan deflection "
        "over the static one), forward. Coupled: the contact force depends on the bridge's "
        "motion (the study's model). Decoupled: the truck rides the road as if it were rigid "
        "and its contact force is applied to the bridge (equations 92-99); the study found it "
        "a conservative bound."
    )
    return block("The study's span DAF", _p(text), _table(header, rows, "vbi-daf"), codes_table)


def position_html(analysis: ReportAnalysis) -> str:
    """Range of the DAF over the positions of the deck's roughness, per speed."""
    study = analysis.position
    rows = []
    for i, speed in enumerate(study.speeds):
        valid = study.daf[i][~study.lost[i] & np.isfinite(study.daf[i])]
        spread = f"{valid.min():.2f} to {valid.max():.2f}" if valid.size else "none valid"
        rows.append([_speed(speed), spread, f"{int(study.lost[i].sum())} of {study.offsets.size}"])
    return _table(
        ["speed", "largest DAF of the spans, over the positions", "positions that lost contact"],
        rows,
        "vbi-position",
    )


def flights_html(analysis: ReportAnalysis) -> str:
    """Every flight of a tyre on the bridge in the requested crossings (or why there are none)."""
    flights = analysis.flights
    if not flights.unilateral:
        return ""
    table = flights.table
    on = table[table.on_bridge] if not table.empty else table
    prints = sorted({number(f * 1000) for f in flights.footprint})
    text = (
        "The tyres push on the road but never pull: when a tyre's force would become tensile "
        "the wheel leaves the road and lands again, which the model follows. Each tyre "
        f"averages the road over a footprint of {' or '.join(prints)} mm."
    )
    if on.empty:
        return block("The tyres", _p(text + " No tyre left the road on the bridge."))
    rows = [
        [_speed(r.speed_m_s), _arrow(r.direction), str(r.axle),
         quantity(r.take_off_m, "length"), quantity(r.landing_m, "length"),
         f"{number(r.duration_s * 1000)} ms"]
        for r in on.itertuples()
    ]  # fmt: skip
    return block(
        "The tyres",
        _p(text + " Stations from the first support (forward)."),
        _table(
            ["speed", "direction", "axle", "take-off", "landing", "in the air"], rows, "vbi-flights"
        ),  # fmt: skip
    )
