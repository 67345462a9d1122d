"""The readouts never call a result valid when an input is outside its intended range, and
count every computed crossing, also one with no DAF."""

from __future__ import annotations

import re

import numpy as np

import vbi_lib as vbi
from vbi_lib.widgets import CrossingExplorer, SpeedExplorer
from vbi_lib.widgets.readouts import daf_text, sweep_html

BRIDGE = vbi.Bridge.from_frequency(30.0, 1, 8000.0, 3.0, 0.02)


def text(html: str) -> str:
    return re.sub(r"<[^>]+>", "", html.replace("<br>", "\n"))


def sweep(outside: bool, daf_rows: list[list[float]], ratio: list[float], flight: list[float]):
    return text(
        sweep_html(
            np.array(daf_rows),
            np.array(ratio),
            BRIDGE,
            lambda i: f"at row {i}",
            "a model",
            None,
            np.array(flight),
            outside=outside,
        )  # fmt: skip
    )


def test_a_sweep_with_inputs_outside_their_range_calls_nothing_valid() -> None:
    rows = [[1.2, np.nan], [1.5, np.nan], [1.1, np.nan]]
    inside = sweep(False, rows, [0.3, 0.1, 0.2], [0.0, 0.2, 0.0])
    assert "largest DAF 1.500 at row 1, among crossings within the model's validity" in inside
    outside = sweep(True, rows, [0.3, 0.1, 0.2], [0.0, 0.2, 0.0])
    assert "within the model's validity" not in outside
    assert "inputs outside their intended ranges" in outside
    assert "outside the model's validity" in outside


def test_a_computed_crossing_without_a_daf_is_counted_not_dropped() -> None:
    # rows 0 and 2 were computed (their smallest contact force is known) but no span was
    # pushed down; row 3 is still to compute (NaN everywhere)
    rows = [[np.nan, np.nan], [1.3, np.nan], [np.nan, np.nan], [np.nan, np.nan]]
    said = sweep(False, rows, [0.0, 0.0, 0.0, np.nan], [1.0, 0.4, 1.0, np.nan])
    assert "2 of 3 crossings have no DAF" in said
    assert "the wheel left the road in 3 of 3 crossings" in said
    assert "largest DAF 1.300 at row 1" in said


def test_a_crossing_with_no_daf_says_so() -> None:
    assert daf_text([np.nan, np.nan]) == "no DAF (no span was pushed down during the crossing)"
    explorer = CrossingExplorer(vehicle_type="quarter-car", road="iso-class", iso_class="H",
                                speed_mph=100)  # fmt: skip
    readout = text(explorer.readout.value)
    assert np.isnan(explorer.result.daf).all()  # the reference: the crossing's own result
    assert readout.startswith("no DAF")
    assert "inputs outside their intended ranges" in readout  # class H is no paved road


def test_the_speed_explorer_readout_agrees_with_its_note_line() -> None:
    explorer = SpeedExplorer(vehicle_type="quarter-car", road="iso-class", iso_class="H",
                             speed_range_mph=(60, 120), n_speeds=7)  # fmt: skip
    readout, note = text(explorer.readout.value), text(explorer.notice.value)
    assert "iso_class='H'" in note and "outside the model's validity." in note
    assert "within the model's validity" not in readout
    computed = np.isfinite(explorer.result.min_contact_force_ratio).sum()
    no_daf = int((~np.isfinite(explorer.result.daf).any(axis=1)).sum())
    if no_daf:
        assert f"{no_daf} of {computed} crossings have no DAF" in readout


def test_a_profile_too_short_names_the_stations_it_needs() -> None:
    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    truck = vbi.Vehicle.from_frequency(3e4, 3.0, 0.1)
    try:
        vbi.simulate(bridge, truck, vbi.Profile.flat(200.0, 0.05), 20.0, -10.0)
    except ValueError as error:
        assert "stations -10 to 20 m with bridge_start=-10 m" in str(error)
    else:  # pragma: no cover - the test fails here
        raise AssertionError("a bridge starting before the profile was accepted")
