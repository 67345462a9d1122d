"""The report's text, tables and figures as HTML: every value formatted, every user text escaped.

Values are shown in the report's display system (:func:`use_units`: the user's US customary
units with SI alongside, or SI alone); numbers keep three significant digits (whole numbers
in full), never ``30.000000``.  Everything the user wrote (title, file names, parameters)
passes through :func:`html.escape` before it reaches the page.

Each section of the report is one block (:func:`block`): its heading, its text, its tables
and its figures (inline SVG, scaled to the page's width) in one ``<section>`` that a printed
page does not split from its heading; wide tables are cut into parts that fit the page.
"""

from __future__ import annotations

import datetime as _dt
import html
import io
import math
import platform
import re
from collections.abc import Iterable, Sequence

import numpy as np
import yaml

from .. import display
from ..beam_statics import QUANTITY
from ..bridges import shape_function_error
from ..profiles import max_sample_spacing
from ..roughness import IN_PER_MI
from ..units import ft
from ..vehicles import as_system
from .analysis import ReportAnalysis
from .inputs import ReportInputs

__all__ = [
    "block",
    "daf_html",
    "envelopes_figure",
    "figure_html",
    "flights_html",
    "inputs_html",
    "limits_html",
    "notes_html",
    "number",
    "position_html",
    "provenance_html",
    "quantity",
    "road_html",
    "sections_html",
    "summary_html",
    "sweep_figure",
    "title_html",
    "use_units",
]

#: Highest bridge frequency the road's sampling must resolve, at least (study rule 32).
MIN_RESOLVED_HZ = 15.0
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


def figure_html(fig: object, caption: str = "") -> str:
    """A matplotlib figure as inline SVG, scaled to the page's width (the figure is closed)."""
    import matplotlib.pyplot as plt

    buffer = io.StringIO()
    fig.savefig(buffer, format="svg", bbox_inches="tight", metadata={"Date": None})
    plt.close(fig)
    svg = buffer.getvalue()
    svg = re.sub(r"<metadata>.*?</metadata>", "", svg[svg.index("<svg") :], flags=re.DOTALL)
    note = f'<figcaption class="vbi-caption">{_e(caption)}</figcaption>' if caption else ""
    return f'<figure class="vbi-figure">{svg}{note}</figure>'


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


# ---------------------------------------------------------------------------- inputs
_LABELS = {
    "bridge.span": "span",
    "bridge.spans": "spans",
    "bridge.k_mid": "midspan stiffness of the path",
    "bridge.EI": "flexural rigidity EI",
    "bridge.mass_per_length": "mass per length",
    "bridge.first_frequency": "first natural frequency",
    "bridge.damping_ratio": "bridge damping ratio",
    "vehicle.mass": "vehicle mass",
    "vehicle.unsprung_mass": "unsprung mass",
    "vehicle.frequency": "body-bounce frequency",
    "vehicle.tyre_stiffness": "tyre stiffness",
    "vehicle.damping_ratio": "suspension damping ratio",
    "vehicle.footprint": "tyre footprint",
    "vehicle.rear_axle_spacing": "rear axle spacing",
    "profile.bridge_start": "first support, from the file's first point",
    "profile.approach_length": "approach length",
    "profile.spacing": "generated road's sample spacing",
}


def _label(key: str) -> str:
    base = key.split("[", 1)[0]
    label = _LABELS.get(base, base)
    return label + (f" [{key.split('[', 1)[1]}" if "[" in key else "")


def inputs_html(inputs: ReportInputs) -> str:
    """The inputs as given, then the model built from them."""
    p = inputs.parameters
    rows = [["spans", str(p.bridge.n_spans)], ["vehicle type", p.vehicle.type]]
    for key, text in p.given.items():
        if key.startswith(("speeds", "sections")):
            continue
        rows.append([_label(key), text])
    rows.append(["speeds", ", ".join(p.given[f"speeds[{i}]"] for i in range(len(p.speeds)))])
    if p.sections is not None:
        rows.append(["sections", ", ".join(p.given[f"sections[{i}]"]
                                           for i in range(len(p.sections)))])  # fmt: skip
    rows.append(["effects", ", ".join(inputs.effects)])
    rows.append(["direction", p.direction])
    if p.vehicle.type == "sprung-mass":
        rows.append(["vehicle frequency is", "damped" if p.vehicle.damped else "undamped"])
    rows.append(["road", inputs.profile_source])
    given = _table(["input", "as given"], rows, "vbi-inputs")
    b = inputs.bridge
    spans = " + ".join(quantity(s, "length") for s in b.spans)
    model = [
        ["spans", spans],
        ["first natural frequency", f"{number(b.first_frequency_hz)} Hz"],
        ["flexural rigidity EI", quantity(b.EI, "flexural_rigidity")],
        ["mass per length", quantity(b.mass_per_length, "mass_per_length")],
        ["bridge damping", f"{number(b.damping_ratio * 100)} % of critical, every mode"],
    ]
    if inputs.model == "one-coordinate":
        model += [
            ["model", "the study's beam of one generalised coordinate (equations 33-45)"],
            ["generalised mass m*", quantity(b.generalized_mass, "mass")],
            ["generalised stiffness k*", quantity(b.generalized_stiffness, "stiffness")],
        ]
    else:
        from ..modes import beam_modes

        frequencies = beam_modes(b, inputs.modes).frequencies_hz
        shown = ", ".join(number(f) for f in frequencies[:8]) + (
            ", ..." if inputs.modes > 8 else ""
        )
        model.append(["model", f"{inputs.modes} exact Euler-Bernoulli modes of the continuous "
                      f"beam ({shown} Hz), Newmark average acceleration"])  # fmt: skip
    system = as_system(inputs.vehicle)
    model += [
        ["vehicle", system.name or p.vehicle.type],
        ["vehicle weight", quantity(system.weight, "weight")],
        ["vehicle frequencies on a rigid road",
         ", ".join(number(f) for f in system.frequencies_hz) + " Hz"],
    ]  # fmt: skip
    axles = ""
    if system.n_axles > 1:
        axle_rows = [
            [str(a + 1), quantity(system.offsets[a], "length"),
             quantity(system.static_loads[a], "weight"),
             "tyre (can leave the road)" if system.unilateral[a] else "bilateral"]
            for a in range(system.n_axles)
        ]  # fmt: skip
        axles = _table(["axle", "behind the first", "static load", "contact"], axle_rows,
                       "vbi-axles")  # fmt: skip
    elif isinstance(inputs.vehicle, object) and p.vehicle.type == "sprung-mass":
        t = inputs.vehicle
        model += [
            ["suspension stiffness", quantity(t.stiffness, "stiffness")],
            ["suspension damping", quantity(t.damping, "damping")],
            ["static midspan deflection under the weight",
             quantity(b.static_deflection(t.weight), "deflection")],
        ]  # fmt: skip
    return block(
        "Inputs",
        _p("The values as given, and the model built from them."),
        given,
        '<p class="vbi-caption">The model:</p>',
        _table(["property", "value"], model, "vbi-model"),
        axles,
    )


# ---------------------------------------------------------------------------- road
def road_html(analysis: ReportAnalysis, road_figure: str = "") -> str:
    """IRI and ISO 8608 class of each span, and the deck profile's figure."""
    r = analysis.roughness
    rows = [
        [name, number(iri), number(iri * IN_PER_MI), number(c10 * 1e6), number(w), cls]
        for name, iri, c10, w, cls in zip(
            r.names, r.iri, r.c10, r.waviness, r.iso_class, strict=True
        )
    ]
    notes = "".join(
        f"<li>{_e(name)}: {_e(why)}</li>"
        for name, why in zip(r.names, r.reasons, strict=True)
        if why
    )
    text = (
        "The deck profile and the end of the approach before it. The International Roughness "
        "Index (IRI, ASTM E1926: the golden quarter car at 80 km/h) and the ISO 8608 "
        "parameters (C10, the displacement spectral density at 0.1 cycle/m, and the "
        "waviness, fitted to 1/3-octave band averages of the Welch spectrum) are given span "
        "by span. One span is a short road for a spectrum: read the ISO 8608 class as an "
        "indication, the IRI as the better measure."
    )
    return block(
        "The road",
        _p(text),
        _table(
            ["part", "IRI [m/km]", "IRI [in/mi]", "C10 [1e-6 m³]", "waviness", "ISO 8608 class"],
            rows,
            "vbi-roughness",
        ),
        f"<ul>{notes}</ul>" if notes else "",
        road_figure,
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


# ---------------------------------------------------------------------------- figures
def sweep_figure(analysis: ReportAnalysis) -> str:
    """DAF against speed, one panel per effect."""
    import matplotlib.pyplot as plt

    effects = list(analysis.inputs.effects)
    fig, axes = plt.subplots(len(effects), 1, figsize=(7.2, 2.5 * len(effects)), sharex=True)
    axes = np.atleast_1d(axes)
    for ax, effect in zip(axes, effects, strict=True):
        analysis.sweep.plot(ax, effect=effect, allowance=analysis.allowances.aashto_lrfd)
        if ax is not axes[-1]:
            ax.set_xlabel("")
    fig.tight_layout()
    text = (
        "One crossing's DAF depends strongly on speed: the sweep runs from half the slowest to "
        f"1.2 times the fastest requested speed with {analysis.sweep.vehicle}. Solid lines "
        "forward, dashed backward; the dotted line is AASHTO LRFD's 1 + IM; crosses mark "
        "crossings whose contact became tensile (outside validity)."
    )
    return block("DAF against speed", _p(text), figure_html(fig), css="vbi-keep")


def envelopes_figure(analysis: ReportAnalysis) -> str:
    """Static and dynamic envelopes along the bridge, one panel per effect."""
    import matplotlib.pyplot as plt

    effects = list(analysis.inputs.effects)
    fig, axes = plt.subplots(len(effects), 1, figsize=(7.2, 2.3 * len(effects)), sharex=True)
    axes = np.atleast_1d(axes)
    for ax, effect in zip(axes, effects, strict=True):
        analysis.envelopes.plot(ax, effect=effect)
        if ax is not axes[-1]:
            ax.set_xlabel("")
    fig.tight_layout()
    text = (
        "The largest and smallest value of each effect at every station along the bridge: "
        "static (dashed: the axles crawling across, every position, the directions asked) and "
        f"dynamic (solid: over the requested crossings of {analysis.envelopes.vehicle}). The "
        "shear is drawn on both faces of each interior support, so it jumps there by the "
        "reaction."
    )
    return block("Envelopes along the bridge", _p(text), figure_html(fig), css="vbi-keep")


def _decimated(x: np.ndarray, y: np.ndarray, count: int = 1200) -> tuple[np.ndarray, np.ndarray]:
    """``(x, y)`` cut to about ``2 count`` points for a plot, keeping each bucket's smallest
    and largest value in order (so every peak is drawn)."""
    if x.size <= 2 * count:
        return x, y
    edges = np.linspace(0, x.size, count + 1).astype(int)
    keep = []
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        part = y[lo:hi]
        keep += sorted({lo + int(np.argmin(part)), lo + int(np.argmax(part))})
    keep = np.array(keep)
    return x[keep], y[keep]


def worst_figure(analysis: ReportAnalysis) -> str:
    """The worst requested crossing's midspan displacements and contact forces."""
    import matplotlib.pyplot as plt

    crossing = analysis.worst
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.2, 4.4), sharex=True)
    x = display.value(crossing.position - crossing.bridge_start, "length")
    for j in range(crossing.bridge.n_spans):
        y = crossing.midspan_displacement[:, j] / crossing.static_deflection
        top.plot(*_decimated(x, y), lw=1, label=f"span {j + 1}")
    system = as_system(crossing.vehicle)
    ratios = crossing.axle_contact_force / system.static_loads[None, :]
    for a in range(system.n_axles):
        label = f"axle {a + 1}" if system.n_axles > 1 else None
        bottom.plot(*_decimated(x, ratios[:, a]), lw=1, label=label)
    bottom.axhline(0.0, color="k", lw=0.8)
    for ax in (top, bottom):
        ax.axvspan(0, display.value(crossing.bridge.length, "length"), color="0.93", zorder=0)
        if len(ax.get_lines()) > 2:
            ax.legend(loc="best", fontsize="x-small")
    top.set_xlim(*worst_window(analysis))
    top.set_ylabel("displacement / static [-]")
    bottom.set_ylabel("contact force / load [-]")
    bottom.set_xlabel(display.label("first axle from the start of the bridge", "length"))
    top.set_title(worst_title(analysis), fontsize="small")
    fig.tight_layout()
    direction, _, _ = analysis.worst_key
    seen = "as the vehicle sees it, from the far support" if direction == "backward" else "forward"
    text = (
        "The crossing with the largest valid DAF: each span's midspan displacement over the "
        "static deflection the crossing divides by, and each axle's contact force over its "
        "static load, against the first axle's position from the bridge's first support "
        f"({seen}). Where a contact force reaches zero a tyre leaves the road; below zero a "
        "bilateral contact would pull on it."
    )
    return block("The worst requested crossing", _p(text), figure_html(fig), css="vbi-keep")


def road_figure(analysis: ReportAnalysis) -> str:
    """The deck profile and the end of the approach, as a figure (no heading)."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.2, 2.4))
    analysis.roughness.plot(ax, road=analysis.inputs.road)
    fig.tight_layout()
    return figure_html(fig)


def position_figure(analysis: ReportAnalysis) -> str:
    """The position study: its table and figure."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.2, 2.8))
    analysis.position.plot(ax)
    fig.tight_layout()
    text = (
        "Where the deck's bumps lie relative to midspan matters as much as how large they are. "
        "Here the deck's roughness is moved along the bridge in even steps (wrapping round its "
        "ends, so the same roughness stays on the bridge) and each requested speed is run "
        "again, forward; the DAF shown is the largest of the spans' midspan displacement DAFs."
    )
    return block("Sensitivity to the profile's position", _p(text), position_html(analysis),
                 figure_html(fig), css="vbi-keep")  # fmt: skip


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


# ---------------------------------------------------------------------------- limits, provenance
def limits_html(analysis: ReportAnalysis) -> str:
    """The model's limits, for this model and vehicle, then this case's notes."""
    inputs = analysis.inputs
    if inputs.model == "one-coordinate":
        bridge = (
            "The bridge is a uniform beam of one or two equal spans with one generalised "
            "coordinate (its first mode's shape): its higher modes are left out; the section "
            "responses add the exact statics to that mode's dynamics (mode acceleration)."
        )
    else:
        bridge = (
            f"The bridge is a uniform Euler-Bernoulli beam continuous over its spans, pinned at "
            f"every support, with its first {inputs.modes} exact modes; the section responses "
            "add the exact statics of the axle forces to the modes' dynamics (mode "
            "acceleration), so a few modes give moments and shears that converge."
        )
    vehicle = {
        "sprung-mass": "The truck is one sprung mass on one wheel path (the study's model): no "
        "axle spacing, no tyre, no pitch or roll; its contact is assumed never to leave the "
        "road, and crossings where it would have are marked and not used as results.",
        "quarter-car": "The truck is a quarter car: a sprung mass on its suspension, an "
        "unsprung mass on a tyre that can leave the road; one wheel path, no pitch or roll.",
    }.get(inputs.parameters.vehicle.type, (
        "The vehicle's axles each carry a sprung load on a suspension"
        + (" and an unsprung mass on tyres that can leave the road" if
           inputs.parameters.vehicle.tyres else "")
        + "; one wheel path, no roll. The design loads are AASHTO's; their dynamic "
        "parameters are typical of a loaded heavy truck (vbi_lib.vehicles.hs20), not a code's."
    ))  # fmt: skip
    items = [
        vehicle,
        bridge,
        "The DAF of one crossing is one sample: speed, the position of the road's features and "
        "the vehicle's frequencies all move it, as the sweeps show.",
    ]
    if inputs.parameters.vehicle.type in ("hs20", "hl93-truck", "hl93-tandem"):
        items.append(
            "AASHTO LRFD's HL-93 adds the design lane load (0.64 kip/ft), which takes no "
            "dynamic allowance, and for negative moment and interior reactions 90 % of two "
            "design trucks at least 50 ft apart (3.6.1.3.1): two trucks can be run as "
            "vehicle.type: axles."
        )
    return block(
        "The model's limits",
        "<ul>" + "".join(f"<li>{_e(i)}</li>" for i in items) + "</ul>",
        '<p class="vbi-caption">For this case:</p>',
        notes_html(analysis),
    )


def notes_html(analysis: ReportAnalysis) -> str:
    """How the road was assembled and where this case approaches the model's limits."""
    inputs = analysis.inputs
    notes = list(inputs.notes)
    slowest = min(inputs.speeds)
    resolved = max(MIN_RESOLVED_HZ, 3 * inputs.bridge.first_frequency_hz)
    s_max = max_sample_spacing(slowest, resolved)
    spacing = inputs.deck.spacing
    verdict = "meets" if spacing <= s_max else "does NOT meet"
    notes.append(
        f"The deck is sampled every {spacing * 1e3:.1f} mm; rule (32) asks for at most "
        f"{s_max * 1e3:.0f} mm to resolve {resolved:.0f} Hz at {_speed(slowest)}: the road "
        f"{verdict} it."
    )
    if inputs.model == "one-coordinate" and inputs.bridge.n_spans == 2:
        notes.append(
            "Two spans: the model's one shape function gives a midspan deflection "
            f"{shape_function_error(2):.0%} smaller than the exact beam under a static load; "
            "its DAF is a ratio of the model's own deflections."
        )
    worst = analysis.worst
    if inputs.model == "one-coordinate":
        integration = (
            "Integration: classical fourth-order Runge-Kutta on the study's model, a node at "
            "every profile sample and support, steps of at most "
            f"{worst.dt * 1e3:.2f} ms at the worst requested crossing (omega_max dt <= 0.1)."
        )
    else:
        integration = (
            "Integration: Newmark's average acceleration (unconditionally stable, no numerical "
            "damping) on the modes and the vehicle, a node at every profile sample and "
            f"support, steps of at most {worst.dt * 1e3:.2f} ms at the worst requested "
            "crossing (omega_max dt <= 0.1)."
        )
    notes.append(integration)
    notes += [n for n in analysis.notes if n]
    items = "".join(f"<li>{_e(n)}</li>" for n in dict.fromkeys(notes) if n)
    return f'<ul class="vbi-notes">{items}</ul>'


def provenance_html(inputs: ReportInputs, source: dict | None) -> str:
    """vbi version, date, input files and their SHA-256, and every parameter as given."""
    import vbi_lib

    source = source or {}
    now = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M:%S UTC")
    rows = [
        ["vbi version", vbi_lib.__version__],
        ["made", now],
        ["Python", platform.python_version()],
        ["parameter file", source.get("name") or "none (parameters given directly)"],
        ["parameter file SHA-256", source.get("sha256") or "-"],
    ]
    if inputs.parameters.profile.file is not None:
        rows += [
            ["profile file", inputs.parameters.profile.file.name],
            ["profile file SHA-256", inputs.profile_sha256],
        ]
    if source.get("results"):
        rows.append(["results as data", source["results"]])
    raw = {k: _plain(v) for k, v in inputs.parameters.raw.items()}
    text = yaml.safe_dump(raw, sort_keys=False, allow_unicode=True, default_flow_style=False)
    return block(
        "Provenance",
        _table(["item", "value"], rows, "vbi-provenance"),
        '<p class="vbi-caption">Parameters as given:</p>',
        f'<pre class="vbi-parameters">{_e(text)}</pre>',
    )


def _plain(value: object) -> object:
    """YAML-safe copy of a parameter value (numpy scalars and paths as plain values)."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    if value is None or isinstance(value, bool | int | float | str):
        return value
    return str(value)


def worst_window(analysis: ReportAnalysis) -> tuple[float, float]:
    """Stations shown in the worst crossing's plots, in display units: the end of the
    approach (a quarter of the bridge's length) and the bridge with the vehicle leaving it."""
    length = analysis.inputs.bridge.length
    wheelbase = as_system(analysis.worst.vehicle).wheelbase
    return (
        display.value(-0.25 * length, "length"),
        display.value(1.02 * length + wheelbase, "length"),
    )


def worst_title(analysis: ReportAnalysis) -> str:
    """Plot title of the worst requested crossing: speed, direction and span DAFs."""
    crossing = analysis.worst
    direction, spacing, _ = analysis.worst_key
    dafs = ", ".join(f"{d:.2f}" for d in crossing.daf)
    lost = " (contact lost: outside validity)" if crossing.lost_contact else ""
    rear = f", rear spacing {number(spacing / ft)} ft" if spacing is not None else ""
    return f"{_speed(crossing.speed)} {_arrow(direction)}{rear}: span DAF {dafs}{lost}"
