"""The live explorers' controls say what they do (issue 25): percent boxes take percent, start
values outside a slider are refused, the study's deck profiles are accepted as the report
accepts them, messages are in the explorer's units, and there is a reset and a line of help."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
from conftest import ROOT

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.widgets import ControlValueError, CrossingExplorer, SpeedExplorer
from vbi_lib.widgets.controls import HELP, SPECS, PercentControl, make_controls

DECKS = ROOT.parent / "shared" / "data" / "profiles"


@pytest.mark.parametrize("name", ["bridge_damping", "truck_damping", "unsprung_fraction"])
def test_a_percent_box_takes_percent(name: str) -> None:
    control = make_controls([name])[name]
    assert isinstance(control, PercentControl) and not control.readout
    control.text.value = 3.0  # typed into the box that shows percent
    assert control.value == pytest.approx(0.03)
    control.value = 0.05  # the slider moved: the box follows, in percent
    assert control.text.value == pytest.approx(5.0)


def test_typing_one_into_the_bridge_damping_box_sets_one_percent() -> None:
    explorer = CrossingExplorer(road="flat")
    explorer.controls["bridge_damping"].text.value = 1.0
    assert explorer.result.bridge.damping_ratio == pytest.approx(0.01)
    explorer.controls["bridge_damping"].text.value = 15.0  # beyond the slider: clamped, said
    assert explorer.controls["bridge_damping"].value == pytest.approx(0.10)
    assert explorer.controls["bridge_damping"].text.value == pytest.approx(10.0)
    assert "bridge_damping=15 % is outside the control's range 0 to 10 %" in explorer.notice.value
    assert explorer.result.bridge.damping_ratio == pytest.approx(0.10)


@pytest.mark.parametrize(
    ("values", "pattern"),
    [
        (
            {"span_ft": 300},
            r"span_ft=300 \(300 ft\) is outside the control's range from 20 to 250 ft",
        ),
        ({"speed_mph": 0}, r"speed_mph=0 \(0 mph\) is outside the control's range from 5 to 100"),
        ({"truck_damping": 2.6}, r"truck_damping=2.6 \(260 %\) is outside .* from 0 to 250 %"),
        ({"speed_range_mph": (1.0, 50.0)}, r"speed_range_mph=\(1.0, 50.0\)"),
    ],
)
def test_a_start_value_outside_a_slider_is_refused_not_clamped(values: dict, pattern: str) -> None:
    kind = SpeedExplorer if "speed_range_mph" in values else CrossingExplorer
    with pytest.raises(ControlValueError, match=pattern):
        kind(road="flat", **values)


def test_every_control_has_a_line_of_help() -> None:
    assert set(HELP) >= set(SPECS), sorted(set(SPECS) - set(HELP))
    controls = make_controls(list(SPECS))
    for name, control in controls.items():
        assert control.tooltip == HELP[name] and len(HELP[name]) < 100, name


def test_reset_puts_every_control_back() -> None:
    explorer = CrossingExplorer(road="flat", speed_mph=50)
    start = explorer.result.daf.copy()
    explorer.set(speed_mph=70, span_ft=140, truck_damping=0.3)
    assert explorer.result.daf[0] != pytest.approx(start[0])
    explorer.reset_button.click()
    assert explorer.values() == explorer.start_values
    assert explorer.controls["speed_mph"].value == 50
    np.testing.assert_allclose(explorer.result.daf, start, rtol=1e-12)


@pytest.mark.parametrize("span", ["i76-span2.csv", "i76-span3.csv", "i76-span4.csv"])
def test_the_studys_deck_profiles_are_driven_as_the_report_drives_them(span: str) -> None:
    path = DECKS / span
    if not path.is_file():
        pytest.skip(f"{path} is not here (../shared/data beside the repository)")
    explorer = CrossingExplorer(
        road="measured", profile_path=str(path), profile_unit="in", span_ft=140, approach_ft=0
    )
    assert explorer.error is None and explorer.result is not None
    assert "before the bridge's far support" in explorer.notice.value
    # the same road, completed the report's way: the deck's last elevation held to 140 ft
    deck = vbi.read_profile(path, unit="in")
    end = 140 * u.ft
    assert end - deck.end < 2 * deck.spacing
    completed = vbi.Profile(np.append(deck.x, end), np.append(deck.elevation, deck.elevation[-1]))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        result = explorer.result
        direct = vbi.simulate(result.bridge, result.vehicle, completed, result.speed, 0.0)
    np.testing.assert_allclose(explorer.result.daf, direct.daf, rtol=1e-12)


def test_a_deck_profile_too_short_is_refused_in_feet_naming_the_controls(tmp_path: Path) -> None:
    deck = tmp_path / "deck.csv"
    x = np.arange(0.0, 1600.0, 1.0)  # 1599 in: 6.75 ft short of 140 ft
    np.savetxt(deck, np.column_stack([x, 0.01 * np.sin(x / 50)]), delimiter=",")
    explorer = CrossingExplorer(
        road="measured", profile_path=str(deck), profile_unit="in", span_ft=140, approach_ft=0
    )
    assert explorer.result is None
    assert "runs 133.2 ft" in explorer.error and "the bridge ends 140.0 ft" in explorer.error
    assert "approach_ft=0" in explorer.error and "span_ft=140" in explorer.error
    assert "bridge_start" not in explorer.error and " m " not in explorer.error
