"""The explorers of the static book: the same controls, computed in the reader's browser.

A published book is static HTML: the ipywidgets explorers draw there but compute nothing, and
no offline route gives the page Python (Pyodide's numpy and scipy live only on its CDN).  The
book's pages instead carry a small JavaScript port of the crossing models the explorers use
(``book/_static/vbi-explorers/vbi-model.js``: the study's sprung mass on one span or two equal
spans, the one-coordinate model and up to 10 exact beam modes, the generated roads), checked
against this library by ``tests/widgets/test_js_port.py``.

This module writes what a page needs for it: :func:`page_html` gives the root element of a
static explorer (``data-vbi-explorer``) with its controls' specification (ranges, steps, help,
start values) as JSON; ``book/_static/vbi-explorers.js`` builds the controls, runs the port
and draws.  :func:`live_and_static` puts a live explorer and its static twin in one output:
JupyterLab and Voila show the live widget, the book (``nb_mime_priority_overrides``) the
static one.  Each control of a static explorer is an ``input`` named after the parameter it
sets (:data:`PAGE_NAMES`), the DAF readout is ``[data-vbi-readout=daf]``, and
``window.vbiExplorers[i].settings()`` returns the setting of the readout's crossing in SI.

>>> from vbi_lib.widgets import Scenario
>>> spec = page_spec("crossing", {**Scenario().__dict__})
>>> [c["name"] for c in spec["controls"]][:3]
['span', 'n_spans', 'bridge_frequency']
>>> next(c for c in spec["controls"] if c["name"] == "bridge_damping")["scale"]
100.0
"""

from __future__ import annotations

import html
import json
import math
from dataclasses import asdict
from typing import Any

import numpy as np

from .base import SECTIONS
from .controls import (
    HELP,
    SPECS,
    SWEEP_DEFAULTS,
    ChoiceControl,
    FlagControl,
    IntControl,
    PercentControl,
    RangeControl,
)
from .scenario import ROAD_SPACING, Scenario

__all__ = [
    "LIVE_ONLY",
    "PAGE_MAX_MODES",
    "PAGE_NAMES",
    "PageExplorer",
    "live_and_static",
    "page_html",
    "page_spec",
]

#: Most beam modes the page's port runs (the live explorers run up to 20).
PAGE_MAX_MODES = 10

#: The name of each static control's ``input``, by the parameter it sets.  Ranges become two
#: inputs (low, high); ``ratio`` is the frequency map's selected cell.
PAGE_NAMES: dict[str, str | tuple[str, str]] = {
    "span_ft": "span",
    "n_spans": "n_spans",
    "bridge_frequency_hz": "bridge_frequency",
    "bridge_weight_kip_per_ft": "bridge_weight",
    "bridge_damping": "bridge_damping",
    "truck_weight_kip": "truck_weight",
    "truck_frequency_hz": "truck_frequency",
    "truck_damping": "truck_damping",
    "speed_mph": "speed",
    "road": "road",
    "iso_class": "iso_class",
    "c10_e6": "c10",
    "waviness": "waviness",
    "seed": "seed",
    "wavelength_ft": "wavelength",
    "amplitude_in": "amplitude",
    "bump_height_in": "bump_height",
    "bump_width_ft": "bump_width",
    "bump_position_ft": "bump_position",
    "road_shift_ft": "road_shift",
    "approach_ft": "approach",
    "modes": "modes",
    "coupled": "coupled",
    "speed_range_mph": ("speed_low", "speed_high"),
    "n_speeds": "n_speeds",
    "ratio_range": ("ratio_low", "ratio_high"),
    "n_ratios": "n_ratios",
}

#: What the page's port does not run, in words (the static explorer says so).
LIVE_ONLY = (
    "the quarter car, measured profile files and more than "
    f"{PAGE_MAX_MODES} beam modes need the live explorers: <code>make explore</code> (a Voila "
    "app) or this chapter in JupyterLab (<code>make lab</code>)"
)

_CROSSING = (
    "span_ft", "n_spans", "bridge_frequency_hz", "bridge_weight_kip_per_ft", "bridge_damping",
    "truck_weight_kip", "truck_frequency_hz", "truck_damping", "speed_mph", "road", "iso_class",
    "c10_e6", "waviness", "seed", "wavelength_ft", "amplitude_in", "bump_height_in",
    "bump_width_ft", "bump_position_ft", "road_shift_ft", "approach_ft", "modes", "coupled",
)  # fmt: skip

#: The controls of each kind of static explorer, in the live explorers' order.
KINDS: dict[str, tuple[str, ...]] = {
    "crossing": _CROSSING,
    "speed": (*_CROSSING, "speed_range_mph", "n_speeds"),
    "frequency": (
        *(k for k in _CROSSING if k != "truck_frequency_hz"),
        "ratio", "ratio_range", "n_ratios", "speed_range_mph", "n_speeds",
    ),
}  # fmt: skip

_TITLES = {
    "crossing": "One crossing, computed in this page",
    "speed": "DAF against speed, computed in this page",
    "frequency": "Frequency matching, computed in this page",
}

_SELECTED_HELP = {
    "speed": "The speed of the crossing the readout shows (marked on the sweep).",
    "frequency": "The speed of the map's cell the readout shows.",
}


def _section(key: str) -> str:
    for title, names in SECTIONS.items():
        if key in names:
            return title
    return "Truck-to-bridge frequency ratio" if key == "ratio" else "Speed"


def _number_spec(key: str, name: str, spec: dict[str, Any], value: float) -> dict[str, Any]:
    percent = spec["kind"] is PercentControl
    scale = 100.0 if percent else 1.0
    label = spec["description"].split(" [")[0]
    unit = "%" if percent else spec.get("unit", "")
    integer = spec["kind"] is IntControl
    high = spec["max"]
    if key == "modes":
        high = PAGE_MAX_MODES
    return {
        "name": name,
        "field": key,
        "kind": "integer" if integer else "number",
        "label": label,
        "unit": unit,
        "min": spec["min"] * scale,
        "max": high * scale,
        "step": spec.get("step", 1) * scale,
        "scale": scale,
        "value": value * scale,
    }


def page_spec(kind: str, values: dict[str, Any], precomputed: dict | None = None) -> dict:
    """The JSON specification of one static explorer: its controls and start values.

    Parameters
    ----------
    kind
        ``"crossing"``, ``"speed"`` or ``"frequency"``.
    values
        Start values by parameter (a live explorer's ``values()``); fields of
        :class:`~vbi_lib.widgets.Scenario` missing take its defaults, the sweeps' theirs;
        ``speed_mph`` and ``ratio`` are the sweeps' selected crossing.
    precomputed
        Data the library computed at build time (the frequency map).

    Raises
    ------
    ValueError
        An unknown kind, or start values the page's port does not run (a quarter car, a
        measured profile, more than :data:`PAGE_MAX_MODES` modes).
    """
    if kind not in KINDS:
        raise ValueError(f"kind={kind!r} must be one of {', '.join(KINDS)}")
    start = {**asdict(Scenario()), **SWEEP_DEFAULTS, "ratio": 1.0, **values}
    if start["vehicle_type"] != "sprung-mass" or start["road"] == "measured":
        raise ValueError(
            f"vehicle_type={start['vehicle_type']!r}, road={start['road']!r}: the page runs the "
            "study's sprung mass on generated roads; " + html.unescape(LIVE_ONLY)
        )
    if not 1 <= start["modes"] <= PAGE_MAX_MODES:
        raise ValueError(f"modes={start['modes']!r} must be 1 to {PAGE_MAX_MODES} in the page")
    controls = []
    for key in KINDS[kind]:
        if key == "ratio":
            spec = SPECS["ratio_range"]
            controls.append({
                **_number_spec(key, "ratio", {**spec, "kind": None}, start["ratio"]),
                "label": "truck f / bridge f₁ shown", "help":
                "The truck-to-bridge frequency ratio of the map's cell the readout shows.",
                "section": _section(key),
            })  # fmt: skip
            continue
        spec = SPECS[key]
        names = PAGE_NAMES[key]
        if spec["kind"] is RangeControl:
            for i, name in enumerate(names):
                entry = _number_spec(key, name, spec, start[key][i])
                entry.update(index=i, label=f"{spec['description'].split(' [')[0]}, "
                             f"{'lowest' if i == 0 else 'highest'}")  # fmt: skip
                controls.append({**entry, "help": HELP[key], "section": _section(key)})
            continue
        if spec["kind"] in (ChoiceControl, FlagControl):
            options = [[v, label] for label, v in spec["options"] if v != "measured"]
            entry = {
                "name": names,
                "field": key,
                "kind": "choice",
                "label": spec["description"],
                "options": options,
                "value": start[key],
            }
        else:
            entry = _number_spec(key, names, spec, start[key])
        help_text = HELP[key]
        if key == "speed_mph" and kind in _SELECTED_HELP:
            help_text = _SELECTED_HELP[kind]
        controls.append({**entry, "help": help_text, "section": _section(key)})
    roads = {name: list(params) for name, params in _road_parameters().items()}
    return {
        "kind": kind,
        "title": _TITLES[kind],
        "controls": controls,
        "road_parameters": roads,
        "road_spacing": ROAD_SPACING,
        "precomputed": precomputed,
    }


def _road_parameters() -> dict[str, tuple[str, ...]]:
    from .controls import ROAD_PARAMETERS

    return {k: v for k, v in ROAD_PARAMETERS.items() if k != "measured"}


def _frequency_map(result: Any, values: dict[str, Any]) -> dict[str, Any]:
    """The library's frequency map for the static explorer (it is shown until a control moves)."""
    keys = [k for k in KINDS["frequency"] if k not in ("ratio", "speed_mph")]
    return {
        "values": {k: _plain(values[k]) for k in keys if k in values},
        "ratio": [float(r) for r in result.ratio],
        "speed": [float(v) for v in result.speed],
        "daf": [[_finite(d) for d in row] for row in result.largest_daf],
        "lost": result.lost_contact.tolist(),
        "model": result.model,
    }


def _plain(value: Any) -> Any:
    if isinstance(value, tuple):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def page_html(kind: str, values: dict[str, Any], precomputed: dict | None = None) -> str:
    """The root element of a static explorer (see :func:`page_spec` for the arguments).

    ``book/_static/vbi-explorers.js`` (loaded on every page of the book) finds it by its
    ``data-vbi-explorer`` attribute and builds the explorer inside it; without JavaScript
    the element says what it would show.
    """
    spec = page_spec(kind, values, precomputed)
    data = json.dumps(spec, allow_nan=False).replace("</", "<\\/")
    return (
        f'<div class="vbi-page-explorer" data-vbi-explorer="{kind}">'
        f'<script type="application/json" class="vbi-spec">{data}</script>'
        f'<p class="vbi-runs-here"><b>{html.escape(spec["title"])}.</b> This explorer runs in '
        "your browser: a JavaScript port of vbi_lib's crossing models (the study's sprung "
        "mass on one span or two equal spans, the one-coordinate model or up to "
        f"{PAGE_MAX_MODES} exact beam modes, generated roads), checked against the library "
        f"by the test suite. Move a slider or type a value; {LIVE_ONLY}.</p>"
        "<noscript><p>With JavaScript switched off the explorer cannot run; the figure "
        "below the explorer shows its start values as vbi_lib computed them.</p></noscript>"
        "</div>"
    )


class PageExplorer:
    """A static explorer as a notebook output (``text/html``): ``PageExplorer("crossing")``."""

    def __init__(
        self, kind: str, values: dict[str, Any] | None = None, precomputed: dict | None = None
    ) -> None:
        self.kind = kind
        self.values = dict(values or {})
        self.precomputed = precomputed
        self.html = page_html(kind, self.values, precomputed)

    def _repr_html_(self) -> str:
        return self.html


class _LiveAndStatic:
    """A live explorer's widget and its static twin in one output (see :func:`live_and_static`)."""

    def __init__(self, explorer: Any, page: PageExplorer) -> None:
        self.explorer = explorer
        self.page = page

    def _repr_mimebundle_(self, **kwargs: Any) -> dict[str, Any]:
        bundle = dict(self.explorer.widget._repr_mimebundle_(**kwargs) or {})
        bundle["text/html"] = self.page.html
        return bundle


def live_and_static(explorer: Any) -> _LiveAndStatic:
    """Display a live explorer where a kernel runs it, and its static twin in the book.

    The output holds the ipywidgets view (JupyterLab and Voila show it) and the static
    explorer's HTML (the book shows it: its ``nb_mime_priority_overrides`` put ``text/html``
    first), which starts at the live explorer's values.  A
    :class:`~vbi_lib.widgets.FrequencyExplorer` passes its map, computed by the library, to
    the page, which shows it until a control moves.

    Examples
    --------
    >>> from vbi_lib.widgets import CrossingExplorer
    >>> bundle = live_and_static(CrossingExplorer(road="flat"))._repr_mimebundle_()
    >>> sorted(bundle)
    ['application/vnd.jupyter.widget-view+json', 'text/html', 'text/plain']
    """
    from .crossing import CrossingExplorer
    from .frequency import FrequencyExplorer
    from .speed import SpeedExplorer

    values = dict(explorer.values())
    precomputed = None
    if isinstance(explorer, CrossingExplorer):
        kind = "crossing"
    elif isinstance(explorer, SpeedExplorer):
        kind = "speed"
        low, high = values["speed_range_mph"]
        values["speed_mph"] = min(max(Scenario().speed_mph, low), high)
    elif isinstance(explorer, FrequencyExplorer):
        kind = "frequency"
        low, high = values["speed_range_mph"]
        values["speed_mph"] = min(max(Scenario().speed_mph, low), high)
        r_low, r_high = values["ratio_range"]
        values["ratio"] = min(max(1.0, r_low), r_high)
        if explorer.result is not None:
            precomputed = {"map": _frequency_map(explorer.result, values)}
    else:
        raise TypeError(f"explorer must be one of vbi's explorers, not {type(explorer).__name__}")
    return _LiveAndStatic(explorer, PageExplorer(kind, values, precomputed))
