"""From the explorer to a report (issue 22's last item): an explorer writes its current setting
as a parameter file that ``vbi-report`` accepts as it is, describing the same bridge, truck,
deck and speeds; settings the report cannot take are refused naming the explorer's control."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from vbi_lib import OutsideValidityWarning
from vbi_lib import units as u
from vbi_lib.reports import load_job, prepare, read_parameters
from vbi_lib.reports.parameter_file import read_parameter_file
from vbi_lib.widgets import CrossingExplorer, FrequencyExplorer, Scenario, SpeedExplorer
from vbi_lib.widgets.report_file import report_files, write_report_files

SETTINGS: list[dict[str, Any]] = [
    {},  # the explorer's start: ISO 8608 class B, the report's generated road
    {"road": "bump", "n_spans": 2, "span_ft": 80, "approach_ft": 150},
    {"road": "harmonic", "road_shift_ft": 37, "bridge_damping": 0.03, "truck_damping": 0.25},
    {"road": "iso-c10", "c10_e6": 600, "waviness": 3, "seed": 7, "approach_ft": 5},
    {"road": "iso-class", "iso_class": "C", "road_shift_ft": 20},
    {"road": "flat", "modes": 4, "coupled": False},
    {"road": "bump", "truck_damping": 2.09, "approach_ft": 0},  # overdamped (h20), no approach
]


def _prepared(folder: Path, name: str) -> Any:
    values, _ = read_parameter_file(folder / f"{name}.yaml")  # vbi-report's own reader
    return prepare(read_parameters(values, base_dir=folder))


@pytest.mark.filterwarnings(  # the overdamped setting's, asserted in the last test
    r"ignore:damping_ratio \(from damping\)=2.09 is outside:vbi_lib.OutsideValidityWarning"
)
@pytest.mark.parametrize("changes", SETTINGS)
def test_the_report_takes_the_explorers_setting_as_it_is(changes: dict, tmp_path: Path) -> None:
    scenario = Scenario(**changes)
    files = report_files({**scenario.__dict__}, [scenario.speed_mph, 60.0], name="mine")
    write_report_files(files, tmp_path)
    inputs = _prepared(tmp_path, "mine")
    bridge, truck = scenario.bridge(), scenario.vehicle()
    mine = inputs.bridge
    assert (mine.span, mine.n_spans) == (bridge.span, bridge.n_spans)
    for name in ("EI", "mass_per_length", "damping_ratio", "first_frequency_hz"):
        assert getattr(mine, name) == pytest.approx(getattr(bridge, name), rel=1e-9), name
    for name in ("mass", "stiffness", "damping"):
        assert getattr(inputs.vehicle, name) == pytest.approx(getattr(truck, name), rel=1e-9)
    assert inputs.speeds == pytest.approx(sorted({scenario.speed, 60 * u.mph}), rel=1e-12)
    if scenario.approach_ft > 0:
        assert inputs.bridge_start == pytest.approx(scenario.approach_ft * u.ft, rel=1e-12)
    profile = scenario.profile()
    start = scenario.bridge_start(profile)
    if scenario.road == "iso-class" and scenario.road_shift_ft == 0:
        assert [f.name for f in files.files] == ["mine.yaml"]
        assert inputs.deck.name == f"ISO 8608 class {scenario.iso_class}"
        return
    # the deck is the one the explorer drives, from the first support to the far one
    assert [f.name for f in files.files] == ["mine.yaml", "mine-deck.csv"]
    deck = inputs.deck
    assert deck.start == 0.0 and deck.end == pytest.approx(bridge.length, rel=1e-12)
    expected = profile.elevation_at(start + deck.x)
    scale = max(float(np.abs(expected).max()), 1e-9)
    np.testing.assert_allclose(deck.elevation, expected, rtol=0, atol=1e-12 * scale)
    tolerance = 1e-9 * bridge.length  # a sample at a support is the support
    inside = (profile.x > start + tolerance) & (profile.x < start + bridge.length - tolerance)
    assert deck.x.size == int(inside.sum()) + 2  # every sample of the road on the bridge


@pytest.mark.parametrize(
    ("explorer", "pattern"),
    [
        (lambda: CrossingExplorer(speed_mph=95), r"speed_mph=95 mph is above the report's 93\.2"),
        (
            lambda: CrossingExplorer(vehicle_type="quarter-car"),
            r"vehicle_type='quarter-car' has no report keys",
        ),
    ],
)
def test_a_setting_the_report_cannot_take_is_refused_naming_the_control(
    explorer: Any, pattern: str
) -> None:
    live = explorer()
    with pytest.raises(ValueError, match=pattern):
        live.report_files()
    live.report_button.click()
    assert (
        "was not written" in live.report_links.value and "download=" not in live.report_links.value
    )


def test_each_live_explorer_writes_its_crossing(tmp_path: Path) -> None:
    crossing = CrossingExplorer(road="flat", speed_mph=50)
    paths = crossing.write_report_parameters(tmp_path)
    assert [p.name for p in paths] == ["vbi-crossing.yaml", "vbi-crossing-deck.csv"]
    assert _prepared(tmp_path, "vbi-crossing").speeds == pytest.approx((50 * u.mph,))
    sweep = SpeedExplorer(road="flat", speed_range_mph=(30.0, 70.0), n_speeds=5)
    sweep.write_report_parameters(tmp_path)
    speeds = _prepared(tmp_path, "vbi-speed").speeds
    assert speeds[0] == pytest.approx(30 * u.mph) and speeds[-1] == pytest.approx(70 * u.mph)
    heat = FrequencyExplorer(road="flat", n_ratios=3, n_speeds=3)
    heat.write_report_parameters(tmp_path)
    inputs = _prepared(tmp_path, "vbi-frequency")
    ratios = heat.grid()[0] * heat.controls["bridge_frequency_hz"].value
    assert any(inputs.vehicle.frequency_hz == pytest.approx(f, rel=1e-6) for f in ratios)


def test_vbi_report_runs_the_file_a_live_explorer_wrote(tmp_path: Path) -> None:
    CrossingExplorer().write_report_parameters(tmp_path / "in")
    program = str(Path(sys.executable).parent / "vbi-report")
    parameters = str(tmp_path / "in" / "vbi-crossing.yaml")
    command = [program, parameters, "--output-dir", str(tmp_path / "out"), "--no-pdf"]
    result = subprocess.run(command, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    assert (tmp_path / "out" / "vbi-crossing.html").stat().st_size > 10_000


def test_an_overdamped_truck_goes_to_the_report_which_warns_of_it(tmp_path: Path) -> None:
    """h20's rule at both ends: the explorer takes a suspension damped 209 % of critical
    (VBI-2D's verification vehicle) and writes it; vbi-report's reader takes it as it is and
    warns that it is outside the intended range (an overdamped suspension)."""
    live = CrossingExplorer(road="flat", truck_damping=2.09)
    said = live.notice.value  # the note line: outside the intended range, not refused
    assert "damping_ratio" in said and "outside the intended range" in said
    (parameters, _) = live.write_report_parameters(tmp_path)
    assert "damping_ratio: 209 %" in parameters.read_text()
    with pytest.warns(OutsideValidityWarning, match=r"damping_ratio \(from damping\)=2.09"):
        job = load_job(parameters)  # the truck built, outside the intended range
    assert job.parameters.vehicle.damping_ratio == pytest.approx(2.09, rel=1e-12)
    assert any("vehicle.damping_ratio='209 %'" in w and "overdamped" in w for w in job.warnings)
