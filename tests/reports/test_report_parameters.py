"""Report parameters: every value strictly read, every refusal naming key, value and rule."""

from __future__ import annotations

from pathlib import Path

import pytest

from vbi_lib import reports
from vbi_lib.reports import legacy
from vbi_lib.reports.parameters import ParameterError, notebook_parameters, read_parameters

LBF, INCH, FT, G = 4.4482216152605, 0.0254, 0.3048, 9.80665


def base(**changes: object) -> dict:
    """The issue's I-76 parameters with a generated road, then ``changes`` (``"a.b": v``)."""
    values = {
        "title": "I-76 span 3",
        "bridge": {
            "span": "140 ft",
            "n_spans": 1,
            "k_mid": "222278 lbf/in",
            "first_frequency": "2.08 Hz",
            "damping_ratio": 0.01,
        },
        "vehicle": {"mass": "200 lbf*s**2/in", "frequency": "2.5 Hz", "damping_ratio": 0.10},
        "speeds": ["30 mph", "70 mph"],
    }
    for key, value in changes.items():
        section, _, name = key.partition(".")
        target = values.setdefault(section, {}) if name else values
        if value is ...:
            target.pop(name or section, None)
        else:
            target[name or section] = value
    return values


def test_the_issue_parameters_are_read_in_si() -> None:
    p = read_parameters(base())
    assert p.bridge.span == pytest.approx(140 * FT)
    assert p.bridge.k_mid == pytest.approx(222278 * LBF / INCH)
    assert p.bridge.first_frequency == 2.08
    assert p.vehicle.mass == pytest.approx(200 * LBF / INCH)
    assert p.speeds == pytest.approx((30 * 0.44704, 70 * 0.44704))
    assert p.units == "US"
    assert p.given["bridge.span"] == "140 ft"
    assert p.profile.file is None and p.profile.iso_class == "C"


def test_a_mass_may_be_given_as_a_weight_and_si_spans_show_si() -> None:
    weight = read_parameters(base(**{"vehicle.mass": "77.2 kip"})).vehicle.mass
    assert weight == pytest.approx(77.2e3 * LBF / G)
    assert read_parameters(base(**{"vehicle.mass": "35 t"})).vehicle.mass == 35000.0
    si = read_parameters(base(**{"bridge.span": "42.7 m"}))
    assert si.units == "SI"
    assert read_parameters(base(units="SI")).units == "SI"


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        # strict quantities
        ({"bridge.span": "100,5 ft"}, r"bridge.span='100,5 ft' has a comma in its number"),
        ({"speeds": ["30; 45 mph"]}, r"speeds\[0\]='30; 45 mph' holds a comma or semicolon"),
        ({"speeds": ["30 45 mph"]}, r"speeds\[0\]='30 45 mph' holds more than one number"),
        ({"speeds": ["nan mph"]}, r"speeds\[0\]='nan mph' is not a finite number"),
        ({"speeds": ["inf mph"]}, r"is not a finite number"),
        ({"bridge.span": 140}, r"bridge.span=140 must be text with one number and one unit"),
        ({"bridge.span": "140 kg"}, r"bridge.span='140 kg' has units 'kg' but a length"),
        ({"vehicle.mass": "3 m"}, r"vehicle.mass='3 m' must be a mass or a weight"),
        # plausible ranges, in SI and in the unit given
        ({"bridge.span": "1000 ft"}, r"bridge.span='1000 ft' is outside the plausible range "
         r"3 to 300 m \(9.84 to 984 ft\)"),
        ({"speeds": ["200 mph"]}, r"speeds\[0\]='200 mph' is outside the plausible range "
         r"1 to 150 km/h \(0.621 to 93.2 mph\)"),
        ({"bridge.first_frequency": "0.01 Hz"}, r"is outside the plausible range 0.2 to 50 Hz"),
        ({"vehicle.mass": "500 kg"}, r"vehicle.mass='500 kg' is outside the plausible range"),
        ({"bridge.damping_ratio": 1.5}, r"bridge.damping_ratio=1.5 is outside"),
        ({"bridge.damping_ratio": "5 %"}, None),
        # types
        ({"quick": "False"}, r"quick='False' must be a YAML boolean: true or false, unquoted"),
        ({"vehicle.damped": 1}, r"vehicle.damped=1 must be a YAML boolean"),
        ({"bridge.n_spans": 3}, r"bridge.n_spans=3 is outside 1 to 2"),
        ({"bridge.n_spans": "1"}, r"bridge.n_spans='1' must be a whole number"),
        ({"bridge.n_spans": True}, r"bridge.n_spans=True must be a whole number"),
        ({"profile.seed": "1"}, r"profile.seed='1' must be a whole number"),
        ({"profile.iso_class": "Z"}, r"profile.iso_class='Z' must be one of A, B, C"),
        ({"speeds": "30 mph, 45 mph"}, r"speeds='30 mph, 45 mph' must be a YAML list"),
        ({"speeds": []}, r"speeds=\[\] must list 1 to 20 speeds"),
        ({"speeds": ["30 mph", "30 mph"]}, r"speeds\[1\]='30 mph' repeats an earlier speed"),
        ({"profile.file": None}, r"profile.file=None must be the path of a profile file"),
        ({"title": ["a"]}, r"title=\['a'\] must be text"),
        ({"bridge": "140 ft"}, r"bridge='140 ft' must be a mapping"),
        # unknown keys get a did-you-mean
        ({"bridge.spam": "140 ft"}, r"bridge.spam='140 ft' is not a known key; did you mean "
         r"'span'\?"),
        ({"speed": ["30 mph"]}, r"speed=\['30 mph'\] is not a known key; did you mean 'speeds'"),
        ({"colour": "red"}, r"colour='red' is not a known key; allowed: title, bridge"),
        # required keys and consistent sets
        ({"bridge.span": ...}, r"bridge.span=\(missing\) is required"),
        ({"vehicle": ...}, r"vehicle=\(missing\) is required"),
        ({"speeds": ...}, r"speeds=\(missing\) is required"),
        ({"bridge.k_mid": ...}, r"bridge=.* needs exactly k_mid and first_frequency; or EI and "
         r"mass_per_length; or mass_per_length and first_frequency; got first_frequency"),
        ({"bridge.EI": "7.5e12 lbf*in**2"}, r"needs exactly .* got k_mid, EI, first_frequency"),
        ({"profile.length_unit": "inch"}, r"profile.length_unit='inch' applies to profile.file"),
    ],
)  # fmt: skip
def test_bad_parameters_are_refused_by_key(changes: dict, message: str | None) -> None:
    if message is None:
        read_parameters(base(**changes))
        return
    with pytest.raises(ParameterError, match=message):
        read_parameters(base(**changes))


def test_profile_file_keys(tmp_path: Path) -> None:
    (tmp_path / "deck.csv").write_text("0,0\n1,0\n")
    with pytest.raises(ParameterError, match=r"profile.length_unit=\(missing\) is required"):
        read_parameters(base(profile={"file": "deck.csv"}), base_dir=tmp_path)
    with pytest.raises(ParameterError, match=r"profile.file='nope.csv' is not a file that exists"):
        read_parameters(base(profile={"file": "nope.csv", "length_unit": "in"}), base_dir=tmp_path)
    with pytest.raises(ParameterError, match=r"profile.length_unit='furlongs2' must be the name"):
        read_parameters(
            base(profile={"file": "deck.csv", "length_unit": "furlongs2"}), base_dir=tmp_path
        )
    with pytest.raises(ParameterError, match=r"profile.iso_class='B' applies to a generated road"):
        read_parameters(
            base(profile={"file": "deck.csv", "length_unit": "in", "iso_class": "B"}),
            base_dir=tmp_path,
        )
    p = read_parameters(base(profile={"file": "deck.csv", "length_unit": "inch"}), tmp_path)
    assert p.profile.file == (tmp_path / "deck.csv").resolve()
    assert p.profile.length_unit == INCH and p.profile.approach == "flat"


def test_notebook_names_that_are_not_keys_are_refused() -> None:
    namespace = {"In": [], "_": None, "title": "t", "bridge": None, "source": {"name": "a"}}
    values, source = notebook_parameters(namespace)
    assert values == {"title": "t"} and source == {"name": "a"}
    with pytest.raises(ParameterError, match=r"vehicel=.* did you mean 'vehicle'"):
        notebook_parameters({**namespace, "vehicel": {}})


# ---------------------------------------------------------------------------- the flat form
FLAT = {"span": "100 ft", "k_mid": "497527 lbf/in", "first_frequency": "3.99 Hz"}


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"span": "100,5 ft"}, r"bridge.span='100,5 ft' has a comma"),
        ({"speeds": "30; 45 mph"}, r"speeds\[0\]='30; 45 mph' holds a comma or semicolon"),
        ({"speeds": "nan mph"}, r"speeds\[0\]='nan mph' is not a finite number"),
        ({"quick": "False"}, r"quick='False' must be a YAML boolean"),
        ({"seed": "1"}, r"profile.seed='1' must be a whole number"),
        ({"colour": "red"}, r"colour='red' is not a known key"),
    ],
)
def test_the_flat_form_is_as_strict(changes: dict, message: str) -> None:
    with pytest.raises(ParameterError, match=message):
        legacy.read_inputs(**{**FLAT, **changes})


def test_the_flat_form_maps_onto_the_nested_keys() -> None:
    inputs = reports.read_inputs(**FLAT, vehicle_mass="77.2 kip", speeds=["30 mph", "45 mph"])
    assert inputs.bridge.first_frequency_hz == pytest.approx(3.99)
    assert inputs.vehicle.mass == pytest.approx(77.2e3 * LBF / G)
    assert inputs.speeds == pytest.approx((30 * 0.44704, 45 * 0.44704))
    assert inputs.bridge_start == pytest.approx(320 * FT)  # the old default approach
    with pytest.raises(ParameterError, match="profile.file=None"):
        legacy.read_inputs(**FLAT, profile_path=None, approach="0 ft")
