"""The report's text and tables as HTML: every value formatted, every user text escaped.

Values are shown in the report's display system (:func:`use_units`: the user's US customary
units with SI alongside, or SI alone); numbers keep three significant digits (whole numbers
in full), never ``30.000000``.  Everything the user wrote (title, file names, parameters)
passes through :func:`html.escape` before it reaches the page.
"""

from __future__ import annotations

import datetime as _dt
import html
import math
import platform
from collections.abc import Iterable

import numpy as np
import yaml

from .. import display
from ..bridges import shape_function_error
from ..profiles import max_sample_spacing
from ..roughness import IN_PER_MI
from .analysis import ReportAnalysis
from .inputs import ReportInputs

__all__ = [
    "daf_html",
    "inputs_html",
    "notes_html",
    "number",
    "position_html",
    "provenance_html",
    "quantity",
    "road_html",
    "summary_html",
    "title_html",
    "use_units",
]

#: Highest bridge frequency the road's sampling must resolve, at least (study rule 32).
MIN_RESOLVED_HZ = 15.0


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


def _speed(speed: float) -> str:
    return quantity(speed, "speed")


def title_html(inputs: ReportInputs) -> str:
    """The title and one line on what the report is."""
    import vbi_lib

    today = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d")
    return (
        f'<h1 class="vbi-title">{_e(inputs.parameters.title)}</h1>'
        f'<p class="vbi-subtitle">Dynamic amplification factor (DAF) of the midspan deflection '
        f"under one truck, computed with vbi {_e(vbi_lib.__version__)} on {today}.</p>"
    )


# ---------------------------------------------------------------------------- summary
def _verdict(daf: float, allowance: float) -> str:
    return "exceeds" if daf > allowance else "is within"


def _contact_sentence(analysis: ReportAnalysis) -> str:
    study = analysis.requested
    lost = study.lost_contact
    ratios = study.coupled.min_contact_force_ratio
    if not lost.any():
        return (
            "The tyre stayed on the road at every requested speed: the contact force never "
            f"fell below {number(float(ratios.min()))} times the truck's weight, so the "
            "model's assumption that the tyre never leaves the road held."
        )
    speeds = " and ".join(_speed(v) for v in study.speeds[lost])
    fell = " and ".join(number(float(r)) for r in ratios[lost])
    share = " and ".join(f"{f:.1%}" for f in study.coupled.tension_fraction[lost])
    head = "At every requested speed" if lost.all() else f"At {speeds}"
    tail = (
        "No DAF in this report is within the model's validity."
        if lost.all()
        else "The DAF at those speeds is outside the model's validity: the tables mark it "
        "'contact lost' and the largest DAF above leaves it out."
    )
    return (
        f"{head} the tyre would have left the road: the contact force fell to {fell} times "
        f"the truck's weight (it would have had to pull the road down for {share} of the time "
        "on the bridge). The model keeps the tyre on the road, so a real truck would have "
        f"lifted off and landed instead. {tail}"
    )


def summary_html(analysis: ReportAnalysis) -> str:
    """Largest DAF per span against the design codes, and the contact check, in plain words."""
    codes = analysis.allowances
    lrfd = codes.aashto_lrfd
    rows = []
    for j in range(analysis.inputs.bridge.n_spans):
        best = analysis.requested.largest(j)
        if best is None:
            study = analysis.requested
            i = int(np.argmax(study.coupled.daf[:, j]))
            rows.append([
                f"span {j + 1}",
                f"none within the model's validity (the model gives "
                f"{study.coupled.daf[i, j]:.2f}, with the tyre off the road)",
                _speed(study.speeds[i]),
                f"not comparable ({lrfd:.2f})",
            ])  # fmt: skip
            continue
        daf, speed = best
        rows.append(
            [f"span {j + 1}", f"{daf:.2f}", _speed(speed), f"{_verdict(daf, lrfd)} {lrfd:.2f}"]
        )
    others = "; ".join(f"{name}: {value:.2f}" for name, value in codes.daf.items())
    contact = _contact_sentence(analysis)
    css = "vbi-lost" if analysis.requested.lost_contact.any() else "vbi-kept"
    return (
        '<div class="vbi-summary">'
        + _table(
            ["", "largest DAF at the requested speeds", "at", "AASHTO LRFD (1 + IM)"],
            rows,
            "vbi-largest",
        )
        + f"<p>Design values of the DAF for this bridge: {_e(others)}.</p>"
        + f'<p class="{css}"><strong>Contact.</strong> {_e(contact)}</p>'
        + "</div>"
    )


# ---------------------------------------------------------------------------- inputs
_LABELS = {
    "bridge.span": "span",
    "bridge.k_mid": "midspan stiffness of the path",
    "bridge.EI": "flexural rigidity EI",
    "bridge.mass_per_length": "mass per length",
    "bridge.first_frequency": "first natural frequency",
    "bridge.damping_ratio": "bridge damping ratio",
    "vehicle.mass": "truck sprung mass",
    "vehicle.frequency": "truck body-bounce frequency",
    "vehicle.damping_ratio": "truck damping ratio",
    "profile.bridge_start": "first support, from the file's first point",
    "profile.approach_length": "approach length",
    "profile.spacing": "generated road's sample spacing",
}


def inputs_html(inputs: ReportInputs) -> str:
    """The inputs as given (with SI), then the model built from them."""
    p = inputs.parameters
    kinds = {"bridge.damping_ratio": None, "vehicle.damping_ratio": None}
    rows = [["spans", str(p.bridge.n_spans), ""]]
    for key, text in p.given.items():
        if key.startswith("speeds"):
            continue
        label = _LABELS.get(key, key)
        si = _si_of(key, inputs)
        rows.append([label, text, "" if key in kinds else si])
    rows.append(["speeds", ", ".join(p.given[f"speeds[{i}]"] for i in range(len(p.speeds))),
                 ", ".join(_si(v, "speed") for v in p.speeds)])  # fmt: skip
    rows.append(["truck frequency is", "damped" if p.vehicle.damped else "undamped", ""])
    rows.append(["road", inputs.profile_source, ""])
    given = _table(["input", "as given", "SI"], rows, "vbi-inputs")
    b, t = inputs.bridge, inputs.vehicle
    model = [
        ["first natural frequency", f"{number(b.first_frequency_hz)} Hz"],
        ["flexural rigidity EI", quantity(b.EI, "flexural_rigidity")],
        ["mass per length", quantity(b.mass_per_length, "mass_per_length")],
        ["generalised mass m*", quantity(b.generalized_mass, "mass")],
        ["generalised stiffness k*", quantity(b.generalized_stiffness, "stiffness")],
        ["truck mass", quantity(t.mass, "mass")],
        ["truck weight", quantity(t.weight, "weight")],
        ["suspension stiffness", quantity(t.stiffness, "stiffness")],
        ["suspension damping", quantity(t.damping, "damping")],
        ["truck frequency (undamped)", f"{number(t.frequency_hz)} Hz"],
        ["static midspan deflection under the truck's weight",
         quantity(b.static_deflection(t.weight), "deflection")],
    ]  # fmt: skip
    return (
        given
        + '<p class="vbi-caption">The model built from them (study equations 82-85):</p>'
        + _table(["property", "value"], model, "vbi-model")
    )


#: Display kind of each quantity key, for its SI column.
_KINDS = {
    "span": "length",
    "k_mid": "stiffness",
    "EI": "flexural_rigidity",
    "mass_per_length": "mass_per_length",
    "first_frequency": "frequency",
    "mass": "mass",
    "frequency": "frequency",
    "bridge_start": "length",
    "approach_length": "length",
    "spacing": "deflection",
}


def _si(value: float, kind: str) -> str:
    """``value`` [SI] in the SI display unit of ``kind``: ``"42.7 m"``, ``"38,927 kN/m"``."""
    symbol, size = display.SI.units[kind]
    return f"{number(value / size)} {symbol}"


def _si_of(key: str, inputs: ReportInputs) -> str:
    section, name = key.split(".", 1)
    value = getattr(getattr(inputs.parameters, section), name, None)
    if name not in _KINDS or value is None:
        return ""
    return _si(value, _KINDS[name])


# ---------------------------------------------------------------------------- road, DAF, position
def road_html(analysis: ReportAnalysis) -> str:
    """IRI and ISO 8608 class of each span."""
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
    return _table(
        ["part", "IRI [m/km]", "IRI [in/mi]", "C10 [1e-6 m³]", "waviness", "ISO 8608 class"],
        rows,
        "vbi-roughness",
    ) + (f"<ul>{notes}</ul>" if notes else "")


def daf_html(analysis: ReportAnalysis) -> str:
    """The DAF at each requested speed (coupled, decoupled bound) and the contact checks."""
    study = analysis.requested
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
    codes = [[name, f"{value:.2f}"] for name, value in analysis.allowances.daf.items()]
    return _table(header, rows, "vbi-daf") + _table(
        ["design code", "design DAF (1 + IM)"], codes, "vbi-codes"
    )


def position_html(analysis: ReportAnalysis) -> str:
    """Range of the DAF over the positions of the deck's roughness, per speed."""
    study = analysis.position
    rows = []
    for i, speed in enumerate(study.speeds):
        valid = study.daf[i][~study.lost[i]]
        spread = f"{valid.min():.2f} to {valid.max():.2f}" if valid.size else "none valid"
        rows.append([_speed(speed), spread, f"{int(study.lost[i].sum())} of {study.offsets.size}"])
    return _table(
        ["speed", "largest DAF of the spans, over the positions", "positions that lost contact"],
        rows,
        "vbi-position",
    )


# ---------------------------------------------------------------------------- limits, provenance
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
    if inputs.bridge.n_spans == 2:
        notes.append(
            "Two spans: the model's one shape function gives a midspan deflection "
            f"{shape_function_error(2):.0%} smaller than the exact beam under a static load; "
            "its DAF is a ratio of the model's own deflections."
        )
    notes.append(
        "Integration: classical fourth-order Runge-Kutta on the study's two-degree-of-freedom "
        "model, a node at every profile sample and support, steps of at most "
        f"{analysis.worst.dt * 1e3:.2f} ms at the worst requested speed (omega_max dt <= 0.1); "
        "the DAF changes by far less than 0.1 % when the step halves."
    )
    items = "".join(f"<li>{_e(n)}</li>" for n in notes if n)
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
    raw = {k: _plain(v) for k, v in inputs.parameters.raw.items()}
    text = yaml.safe_dump(raw, sort_keys=False, allow_unicode=True, default_flow_style=False)
    return (
        _table(["item", "value"], rows, "vbi-provenance")
        + '<p class="vbi-caption">Parameters as given:</p>'
        + f'<pre class="vbi-parameters">{_e(text)}</pre>'
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
    approach (a quarter of the bridge's length) and the bridge."""
    length = analysis.inputs.bridge.length
    return display.value(-0.25 * length, "length"), display.value(1.02 * length, "length")


def worst_title(analysis: ReportAnalysis) -> str:
    """Plot title of the worst requested crossing: its speed and DAF (plain text)."""
    crossing = analysis.worst
    dafs = ", ".join(f"{d:.2f}" for d in crossing.daf)
    lost = " (contact lost: outside validity)" if crossing.lost_contact else ""
    return f"{_speed(crossing.speed)}: DAF {dafs}{lost}"
