"""What the static explorers are told by the library: their controls are the live ones (same
ranges, steps, help, start values), named as the contract says, in the units shown."""

from __future__ import annotations

import json
import re

import pytest

from vbi_lib.widgets import CrossingExplorer, FrequencyExplorer, SpeedExplorer, live_and_static
from vbi_lib.widgets.controls import HELP, SPECS, PercentControl
from vbi_lib.widgets.page import KINDS, PAGE_MAX_MODES, PAGE_NAMES, page_html, page_spec


@pytest.mark.parametrize("kind", list(KINDS))
def test_the_static_controls_are_the_live_ones(kind: str) -> None:
    spec = page_spec(kind, {})
    names = [c["name"] for c in spec["controls"]]
    assert len(names) == len(set(names)), names
    assert "speed" in names  # the contract's key press lands on input[name=speed]
    for control in spec["controls"]:
        key = control["field"]
        if key == "ratio":
            continue
        live = SPECS[key]
        expected = PAGE_NAMES[key]
        if isinstance(expected, tuple):
            expected = expected[control["index"]]
        assert control["name"] == expected
        if control["kind"] == "choice":
            offered = [v for _, v in live["options"] if v != "measured"]
            assert [v for v, _ in control["options"]] == offered
            continue
        scale = 100.0 if live["kind"] is PercentControl else 1.0
        assert control["scale"] == scale
        assert control["min"] == live["min"] * scale
        top = PAGE_MAX_MODES if key == "modes" else live["max"]
        assert control["max"] == top * scale
        assert control["unit"] == ("%" if scale == 100 else live.get("unit", ""))
        assert control["min"] <= control["value"] <= control["max"], key
    helps = {c["field"]: c["help"] for c in spec["controls"]}
    assert helps.get("span_ft") == HELP["span_ft"]


def test_the_page_runs_what_its_port_runs_and_says_what_needs_make_explore() -> None:
    with pytest.raises(ValueError, match="make explore"):
        page_spec("crossing", {"vehicle_type": "quarter-car"})
    with pytest.raises(ValueError, match="make explore"):
        page_spec("crossing", {"road": "measured"})
    with pytest.raises(ValueError, match="modes=12"):
        page_spec("crossing", {"modes": 12})
    text = page_html("crossing", {})
    assert "runs in your browser" in text and "make explore" in text and "quarter car" in text


def test_the_specification_cannot_end_its_script_early() -> None:
    text = page_html("crossing", {})
    payload = re.search(r'<script type="application/json" class="vbi-spec">(.*?)</script>', text)
    assert payload and json.loads(payload.group(1))["kind"] == "crossing"
    assert text.count("</script>") == 1


@pytest.mark.parametrize("kind", [CrossingExplorer, SpeedExplorer, FrequencyExplorer])
def test_an_explorers_output_holds_the_live_widget_and_its_static_twin(kind: type) -> None:
    small = {SpeedExplorer: {"n_speeds": 3}, FrequencyExplorer: {"n_speeds": 3, "n_ratios": 3}}
    explorer = kind(**small.get(kind, {}))
    bundle = live_and_static(explorer)._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    spec = json.loads(re.search(r'class="vbi-spec">(.*?)</script>', bundle["text/html"]).group(1))
    start = {
        c["field"]: c["value"] if c["kind"] == "choice" else c["value"] / c["scale"]
        for c in spec["controls"]
        if "index" not in c
    }
    for key, value in explorer.values().items():
        if key in start:
            assert start[key] == pytest.approx(value), key
    if kind is FrequencyExplorer:
        heat = spec["precomputed"]["map"]
        assert heat["ratio"] == pytest.approx(explorer.result.ratio.tolist())
        assert len(heat["daf"]) == explorer.result.speed.size
