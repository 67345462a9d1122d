"""Reports: inputs checked before anything runs, HTML written whole or not at all."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import vbi_lib as vbi
from vbi_lib import reports
from vbi_lib import units as u

BRIDGE = {"span": "100 ft", "k_mid": "497527 lbf/in", "first_frequency": "3.99 Hz"}


def test_inputs_become_the_study_objects() -> None:
    inputs = reports.read_inputs(**BRIDGE, vehicle_mass="77.2 kip", vehicle_frequency="4.5 Hz")
    expected = vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * u.lbf / u.inch, 3.99)
    assert inputs.bridge.EI == pytest.approx(expected.EI)
    assert inputs.bridge.mass_per_length == pytest.approx(expected.mass_per_length)
    assert inputs.vehicle.mass == pytest.approx(77.2 * 4448.2216152605 / 9.80665)
    assert inputs.speeds_mph == (30.0, 45.0, 60.0)
    assert inputs.bridge_start == pytest.approx(320 * 0.3048)


def test_weight_per_length_is_accepted_as_mass() -> None:
    inputs = reports.read_inputs(
        span="100 ft", EI="7.5e12 lbf*inch**2", mass_per_length="4.6 kip/ft"
    )
    assert round(inputs.bridge.first_frequency_hz, 2) == 3.00  # Table 2.13.1


@pytest.mark.parametrize(
    ("parameters", "message"),
    [
        ({"colour": "red"}, r"unknown report parameter\(s\) \['colour'\]"),
        ({**BRIDGE, "span": "100 kg"}, "span='100 kg'"),
        ({"span": "100 ft"}, "the bridge needs k_mid and first_frequency"),
        ({**BRIDGE, "speeds": "fast"}, "speeds='fast'"),
        ({**BRIDGE, "vehicle_mass": "3 m"}, "vehicle_mass='3 m'"),
        ({**BRIDGE, "n_spans": 3}, "n_spans=3"),
        ({**BRIDGE, "bridge_damping": 1.5}, "damping_ratio=1.5"),
    ],
)
def test_bad_inputs_are_named(parameters: dict, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        reports.read_inputs(**parameters)


def test_short_measured_profile_is_refused(shared_data: Path) -> None:
    path = shared_data / "profiles" / "i76-span2.csv"
    with pytest.raises(ValueError, match="covers 42.6 m"):
        reports.read_inputs(
            **{**BRIDGE, "span": "140 ft"},
            profile_path=str(path),
            profile_unit="inch",
            approach="10 ft",
        )


def test_report_is_written(tmp_path: Path) -> None:
    output = reports.make_report(
        tmp_path / "out" / "report.html", quick=True, **BRIDGE, speeds="45 mph"
    )
    html = output.read_text()
    inputs = reports.read_inputs(**BRIDGE, speeds="45 mph")
    daf = vbi.simulate(
        inputs.bridge, inputs.vehicle, inputs.profile, 45 * u.mph, inputs.bridge_start
    ).daf[0]
    assert f"{daf:.3f}" in html
    assert "AASHTO LRFD" in html
    assert list((tmp_path / "out").iterdir()) == [output]


def test_failed_report_leaves_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    broken = json.loads(reports.TEMPLATE.read_text())
    broken["cells"].append(
        {
            "cell_type": "code",
            "id": "boom",
            "metadata": {},
            "execution_count": None,
            "outputs": [],
            "source": ["raise RuntimeError('boom')"],
        }
    )
    template = tmp_path / "broken.ipynb"
    template.write_text(json.dumps(broken))
    monkeypatch.setattr(reports, "TEMPLATE", template)
    with pytest.raises(Exception, match="boom"):
        reports.make_report(tmp_path / "out" / "report.html", quick=True, **BRIDGE)
    assert not any((tmp_path / "out").glob("*"))
