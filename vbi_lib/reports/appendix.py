"""The report's inputs, road, limits and provenance: the sections that say what was run.

Every value formatted and every user text escaped as in :mod:`.render`.
"""

from __future__ import annotations

import datetime as _dt
import platform

import numpy as np
import yaml

from ..bridges import shape_function_error
from ..profiles import max_sample_spacing
from ..roughness import IN_PER_MI
from ..vehicles import as_system
from .analysis import ReportAnalysis
from .inputs import ReportInputs
from .render import _e, _p, _speed, _table, block, number, quantity

__all__ = ["inputs_html", "limits_html", "notes_html", "provenance_html", "road_html"]

#: Highest bridge frequency the road's sampling must resolve, at least (study rule 32).
MIN_RESOLVED_HZ = 15.0


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
