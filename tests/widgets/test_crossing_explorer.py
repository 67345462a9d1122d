"""The crossing explorer: every control moves its result as a direct ``vbi.simulate`` does,
the physics comes out right, and bad values leave the page consistent."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
from explorer_cases import CHANGES, direct_crossing, resolve, write_profiles

import vbi_lib as vbi
from vbi_lib import display
from vbi_lib import units as u
from vbi_lib.widgets import ControlValueError, CrossingExplorer, Scenario

KEYS = sorted(CrossingExplorer.parameters)


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    return write_profiles(tmp_path_factory.mktemp("profiles"))


def test_the_explorer_offers_a_control_for_every_input_of_a_crossing() -> None:
    assert set(KEYS) == set(Scenario.__dataclass_fields__)
    assert set(KEYS) <= set(CHANGES)


@pytest.mark.parametrize("name", KEYS)
def test_every_control_moves_the_result_as_a_direct_simulation(
    name: str, files: dict[str, str]
) -> None:
    setup, new = CHANGES[name]
    explorer = CrossingExplorer(**resolve(setup, files))
    before = explorer.result
    assert before is not None, explorer.error
    np.testing.assert_allclose(before.daf, direct_crossing(explorer.values()).daf, rtol=1e-9)

    explorer.controls[name].value = resolve({name: new}, files)[name]  # as the page does
    after = explorer.result
    assert after is not None, explorer.error
    expected = direct_crossing(explorer.values())
    np.testing.assert_allclose(after.daf, expected.daf, rtol=1e-9)
    assert after.min_contact_force_ratio == pytest.approx(expected.min_contact_force_ratio)
    assert after.model == expected.model
    assert after.daf.shape != before.daf.shape or not np.allclose(after.daf, before.daf), (
        f"{name} did not change the DAF"
    )


def test_more_bridge_damping_gives_a_lower_daf_at_resonance() -> None:
    """Harmonic road at v = f1 * wavelength: the bridge is driven at its own frequency."""
    speed_mph = 3.0 * 30.0 * u.ft / u.mph  # 61.4 mph
    explorer = CrossingExplorer(road="harmonic", amplitude_in=0.1, speed_mph=round(speed_mph))
    dafs = []
    for zeta in (0.0, 0.01, 0.02, 0.05, 0.1):
        explorer.controls["bridge_damping"].value = zeta
        assert not explorer.result.lost_contact
        dafs.append(explorer.result.daf[0])
    assert np.all(np.diff(dafs) < 0), dafs


def test_more_truck_damping_gives_a_lower_daf_when_the_road_drives_the_truck() -> None:
    """Forcing v / wavelength equal to the truck's 3 Hz bounce (and the bridge's f1)."""
    explorer = CrossingExplorer(
        road="harmonic", amplitude_in=0.1, speed_mph=61, truck_frequency_hz=3.0
    )
    dafs, forces = [], []
    for zeta in (0.05, 0.1, 0.2, 0.4):
        explorer.controls["truck_damping"].value = zeta
        dafs.append(explorer.result.daf[0])
        forces.append(explorer.result.contact_force_amplification)
    assert np.all(np.diff(dafs) < 0), dafs
    assert np.all(np.diff(forces) < 0), forces


def test_a_flat_road_under_a_stiff_heavy_bridge_gives_a_daf_near_one() -> None:
    """Speed parameter v / (2 f1 L) = 0.012: the load is nearly static (Fryba: DAF ~ 1 + a)."""
    explorer = CrossingExplorer(
        road="flat", bridge_frequency_hz=12.0, bridge_weight_kip_per_ft=20.0, speed_mph=20.0
    )
    assert explorer.result.daf[0] == pytest.approx(1.0, abs=0.02)
    assert "DAF 1.00" in explorer.readout.value
    assert "contact held" in explorer.readout.value


def test_the_readout_never_shows_a_daf_outside_validity_bare() -> None:
    explorer = CrossingExplorer(road="bump", bump_height_in=2.0, speed_mph=60)
    crossing = explorer.result
    assert crossing.lost_contact
    text = explorer.readout.value
    assert f"DAF {crossing.daf[0]:.3f}</b> &mdash; " in text
    assert "the tyre would leave the road" in text
    assert "outside the model's validity" in text
    explorer.set(road="flat")
    assert "outside the model's validity" not in explorer.readout.value


def test_the_readout_gives_the_daf_the_codes_and_which_model_ran() -> None:
    display.set_units("US")
    try:
        explorer = CrossingExplorer(road="flat", modes=3, coupled=False)
    finally:
        display.set_units("SI")
    text = explorer.readout.value
    assert f"DAF {explorer.result.daf[0]:.3f}" in text
    assert "AASHTO LRFD 1.33" in text  # 1 + 0.33 of Table 3.6.2.1-1
    assert f"AASHTO Standard {1 + 50 / (100 + 125):.2f}" in text  # 100 ft span
    assert "OHBDC 1983 1.40" in text  # 3 Hz lies on the 0.40 plateau
    assert "3 exact beam modes" in text and "decoupled" in text
    assert "100 ft (30.5 m)" in text and "41 mph" in text
    assert explorer.result.model == "modal"


def test_the_figure_shows_the_result() -> None:
    explorer = CrossingExplorer(road="harmonic", n_spans=2)
    for speed in (35.0, 48.0):
        explorer.controls["speed_mph"].value = speed
        crossing = explorer.result
        top, bottom = explorer.axes
        x = display.value(crossing.position - crossing.bridge_start, "length")
        for j in range(2):
            np.testing.assert_allclose(top.lines[j].get_xdata(), x)
            np.testing.assert_allclose(
                top.lines[j].get_ydata(),
                crossing.midspan_displacement[:, j] / crossing.static_deflection,
            )
        np.testing.assert_allclose(bottom.lines[0].get_ydata(), crossing.contact_force_ratio)
        low, high = top.get_ylim()
        assert low <= top.lines[0].get_ydata().min() and high >= top.lines[1].get_ydata().max()
    assert explorer.view.widget.value[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_nan_is_refused_with_its_name_and_the_page_stays_consistent() -> None:
    explorer = CrossingExplorer(road="flat")
    daf = explorer.result.daf.copy()
    readout = explorer.readout.value
    with pytest.raises(ControlValueError, match=r"span_ft=nan must be a finite number"):
        explorer.controls["span_ft"].value = float("nan")
    assert explorer.controls["span_ft"].value == 100.0
    np.testing.assert_array_equal(explorer.result.daf, daf)
    assert explorer.readout.value == readout
    assert "span_ft=nan" in explorer.notice.value and "keeps 100" in explorer.notice.value


@pytest.mark.parametrize(
    ("name", "bad", "pattern"),
    [
        ("n_spans", 3, r"n_spans=3 must be one of 1, 2"),
        ("road", "gravel", r"road='gravel' must be one of 'flat'"),
        ("coupled", "yes", r"coupled='yes' must be one of True, False"),
        ("modes", 2.5, r"modes=2.5 must be a whole number from 1 to 20"),
        ("speed_mph", "fast", r"speed_mph='fast' must be a finite number from 5 to 100 mph"),
        ("profile_path", 3, r"profile_path=3 must be text"),
    ],
)
def test_invalid_selections_are_refused_by_name(name: str, bad: object, pattern: str) -> None:
    explorer = CrossingExplorer(road="flat")
    old = explorer.controls[name].value
    with pytest.raises(ValueError, match=pattern):
        explorer.controls[name].value = bad
    assert explorer.controls[name].value == old
    assert name in explorer.notice.value


def test_a_value_beyond_a_slider_is_clamped_and_said_so() -> None:
    explorer = CrossingExplorer(road="flat")
    explorer.controls["span_ft"].value = 900.0
    assert explorer.controls["span_ft"].value == 250.0
    assert explorer.result.bridge.span == pytest.approx(250 * u.ft)
    assert "span_ft=900 ft is outside the control's range 20 to 250 ft" in explorer.notice.value
    explorer.controls["speed_mph"].value = 30.0  # the next change clears the note
    assert explorer.notice.value == ""


def test_settings_without_a_valid_crossing_show_why_and_no_number(tmp_path: Path) -> None:
    explorer = CrossingExplorer(road="flat")
    explorer.controls["road"].value = "measured"  # no file yet
    assert explorer.result is None
    assert "profile_path is empty" in explorer.readout.value
    assert "DAF" not in explorer.readout.value
    assert all(len(line.get_xdata()) == 0 for ax in explorer.axes for line in ax.lines)

    short = tmp_path / "short.csv"
    short.write_text("0,0\n100,0.1\n200,0\n")  # 200 in: shorter than the approach
    explorer.controls["profile_path"].value = str(short)
    assert explorer.result is None
    # said in the explorer's units, naming its controls (not the library's bridge_start)
    text = explorer.readout.value
    assert "runs 16.7 ft" in text and "the bridge ends 420.0 ft from its start" in text
    assert "approach_ft=320" in text and "span_ft=100" in text and "bridge_start" not in text

    broken = tmp_path / "broken.csv"
    broken.write_text("0,0\n1,x\n")
    explorer.controls["profile_path"].value = str(broken)
    assert "line 2: elevation 'x' is not a number" in explorer.readout.value

    explorer.controls["road"].value = "flat"
    assert explorer.result is not None and "DAF" in explorer.readout.value
    assert explorer.error is None


def test_an_uploaded_profile_is_read_and_driven(files: dict[str, str]) -> None:
    explorer = CrossingExplorer(road="flat")
    content = Path(files["A"]).read_bytes()
    upload = {
        "name": "deck.csv",
        "type": "text/csv",
        "size": len(content),
        "content": memoryview(content),
        "last_modified": 0,
    }
    explorer.upload.set_state({"value": [upload]})  # what the page sends
    values = explorer.values()
    assert values["road"] == "measured" and values["profile_path"].endswith("deck.csv")
    np.testing.assert_allclose(explorer.result.daf, direct_crossing(values).daf, rtol=1e-9)


def test_only_the_chosen_roads_controls_are_shown() -> None:
    explorer = CrossingExplorer(road="harmonic")
    shown = {k for k, c in explorer.controls.items() if c.box.layout.display != "none"}
    assert {"wavelength_ft", "amplitude_in", "road_shift_ft"} <= shown
    assert not {"iso_class", "bump_height_in", "profile_path"} & shown
    explorer.controls["road"].value = "measured"
    assert explorer.controls["profile_path"].layout.display != "none"
    assert explorer.upload.layout.display != "none"


def test_set_changes_several_controls_with_one_computation() -> None:
    explorer = CrossingExplorer(road="flat")
    renders = explorer.view.renders
    explorer.set(span_ft=60.0, n_spans=2, speed_mph=50.0)
    assert explorer.view.renders == renders + 1
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        np.testing.assert_allclose(
            explorer.result.daf, direct_crossing(explorer.values()).daf, rtol=1e-9
        )
    with pytest.raises(ValueError, match=r"\['span'\] are not controls"):
        explorer.set(span=3)
