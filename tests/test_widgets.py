"""The explorers recompute when a control changes, and agree with direct library calls."""

from __future__ import annotations

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.widgets import CrossingExplorer, Scenario, SpeedExplorer


@pytest.fixture(autouse=True)
def _agg(monkeypatch: pytest.MonkeyPatch) -> None:
    import matplotlib

    matplotlib.use("Agg")


def test_scenario_builds_the_bridge_truck_and_road_it_describes() -> None:
    scenario = Scenario(span_ft=80, n_spans=2, bridge_frequency_hz=4.2, truck_frequency_hz=3.1)
    bridge, truck, road = scenario.bridge(), scenario.vehicle(), scenario.profile()
    assert bridge.span == pytest.approx(80 * 0.3048)
    assert bridge.first_frequency_hz == pytest.approx(4.2)
    assert bridge.mass_per_length == pytest.approx(4.6 * 4448.2216152605 / 0.3048 / 9.80665)
    assert truck.frequency_hz == pytest.approx(3.1)
    assert truck.weight == pytest.approx(77.2 * 4448.2216152605)
    assert road.end >= (320 + 160) * 0.3048


def test_crossing_explorer_follows_its_controls() -> None:
    explorer = CrossingExplorer()
    explorer.controls["speed_mph"].value = 55.0  # the observer recomputes
    expected = vbi.simulate(
        explorer.scenario().bridge(),
        explorer.scenario().vehicle(),
        explorer.scenario().profile(),
        55.0 * u.mph,
        320 * u.ft,
    )
    np.testing.assert_allclose(explorer.result.daf, expected.daf)
    assert "DAF" in explorer.summary.value


def test_speed_explorer_covers_both_spans() -> None:
    explorer = SpeedExplorer(speeds_mph=np.array([20.0, 40.0]))
    assert np.isnan(explorer.result[:, 1]).all()
    explorer.controls["n_spans"].value = 2
    assert explorer.result.shape == (2, 2)
    assert np.isfinite(explorer.result).all()
