"""The scenario the controls describe, the app's tabs and the explore notebook Voila serves."""

from __future__ import annotations

import json

import numpy as np
import pytest
from conftest import ROOT

from vbi_lib import units as u
from vbi_lib.widgets import ExplorerApp, Scenario

NOTEBOOK = ROOT / "explore" / "explore.ipynb"


def test_scenario_builds_the_bridge_and_truck_it_describes() -> None:
    scenario = Scenario(
        span_ft=80,
        n_spans=2,
        bridge_frequency_hz=4.2,
        truck_frequency_hz=3.1,
        truck_damping=0.2,
        bridge_damping=0.03,
    )
    bridge, truck = scenario.bridge(), scenario.vehicle()
    assert bridge.span == pytest.approx(80 * 0.3048)
    assert bridge.first_frequency_hz == pytest.approx(4.2)
    assert bridge.mass_per_length == pytest.approx(4.6 * 4448.2216152605 / 0.3048 / 9.80665)
    assert bridge.damping_ratio == 0.03
    assert truck.weight == pytest.approx(77.2 * 4448.2216152605)
    assert truck.frequency_hz == pytest.approx(3.1)
    assert truck.damping_ratio == pytest.approx(0.2)
    assert scenario.speed == pytest.approx(41 * 1609.344 / 3600)


@pytest.mark.parametrize("kind", ["flat", "harmonic", "bump", "iso-class", "iso-c10"])
def test_generated_roads_reach_past_the_bridge_and_slide_when_shifted(kind: str) -> None:
    scenario = Scenario(road=kind)
    road = scenario.profile()
    assert road.start == 0.0
    assert road.end == pytest.approx((320 + 100 + 200) * u.ft)
    shifted = scenario.replace(road_shift_ft=37.0).profile()
    x = np.linspace(0.0, shifted.end, 777)
    np.testing.assert_allclose(
        shifted.elevation_at(x), road.elevation_at(x + 37 * u.ft), atol=1e-12
    )


def test_road_shapes_follow_their_controls() -> None:
    harmonic = Scenario(road="harmonic", wavelength_ft=20, amplitude_in=0.3).profile()
    assert harmonic.elevation.max() == pytest.approx(0.3 * u.inch, rel=1e-4)
    assert harmonic.elevation_at(5 * u.ft) == pytest.approx(0.3 * u.inch)  # quarter wave
    bump = Scenario(road="bump", bump_height_in=2, bump_position_ft=30).profile()
    assert bump.elevation_at((320 + 30) * u.ft) == pytest.approx(2 * u.inch)
    assert bump.elevation_at((320 + 30 + 2) * u.ft) == 0.0  # 3 ft long: 1.5 ft each side
    assert not Scenario(road="flat").profile().elevation.any()


@pytest.mark.parametrize(
    ("changes", "pattern"),
    [
        ({"span_ft": float("nan")}, r"span_ft=nan must be a finite number"),
        ({"bridge_damping": 1.2}, r"bridge_damping=1.2 is outside \[0, 1\)"),
        ({"n_spans": 3}, r"n_spans=3 is not supported"),
        ({"road": "gravel"}, r"road='gravel' is not offered"),
        ({"modes": 0}, r"modes=0 must be a whole number from 1 to 20"),
        ({"seed": 1.5}, r"seed=1.5 must be a whole number"),
        ({"road_shift_ft": 250.0}, r"road_shift_ft=250.0 must be at most 200"),
        ({"coupled": "no"}, r"coupled='no' must be True or False"),
        ({"profile_unit": "furlong"}, r"profile_unit='furlong' is not a length unit"),
    ],
)
def test_a_scenario_refuses_values_by_name(changes: dict, pattern: str) -> None:
    with pytest.raises((ValueError, TypeError), match=pattern):
        Scenario(**changes)


def test_the_model_follows_the_number_of_modes() -> None:
    assert Scenario(modes=1).simulate_options() == {"model": "one-coordinate", "coupled": True}
    assert Scenario(modes=6, coupled=False).simulate_options() == {
        "model": "modal",
        "modes": 6,
        "coupled": False,
    }
    assert "one-coordinate" in Scenario().model_text()
    assert "6 exact beam modes" in Scenario(modes=6).model_text()


def test_the_app_holds_the_three_explorers_in_tabs() -> None:
    app = ExplorerApp()
    assert app.widget.children == (app.crossing.widget, app.speed.widget, app.frequency.widget)
    assert all(e.result is not None for e in (app.crossing, app.speed, app.frequency))
    assert len(app.widget.titles) == 3


def test_the_explore_notebook_is_stored_clean_and_builds_the_app() -> None:
    notebook = json.loads(NOTEBOOK.read_text())
    code = [c for c in notebook["cells"] if c["cell_type"] == "code"]
    assert not any(c.get("outputs") or c.get("execution_count") for c in code)
    assert notebook["metadata"]["kernelspec"]["name"] == "python3"
    namespace: dict = {}
    from vbi_lib import display

    try:
        exec("\n".join("".join(c["source"]) for c in code), namespace)
    finally:
        display.set_units("SI")
    assert isinstance(namespace["app"], ExplorerApp)
