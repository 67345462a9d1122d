"""Report parameters: every value strictly read, every refusal naming key, value and rule."""

from __future__ import annotations

import re
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
        ({"bridge.span": "1000 ft"}, r"bridge.span='1000 ft' is outside the intended range "
         r"3 to 300 m \(9.84 to 984 ft\) of span length \(vbi_lib.ranges.RANGES\['span'\]\)"),
        ({"speeds": ["200 mph"]}, r"speeds\[0\]='200 mph' is outside the intended range "
         r"0 to 150 km/h \(0 to 93.2 mph\)"),
        ({"speeds": ["0 mph"]}, r"speeds\[0\]='0 mph' is outside the intended range"),
        ({"bridge.first_frequency": "0.3 Hz"}, r"is outside the intended range 0.5 to 50 Hz"),
        ({"vehicle.mass": "50 kg"}, r"vehicle.mass='50 kg' is outside from 100 to 1e\+06 kg \(a "
         r"vehicle under 100 kg is no truck.*; is outside the intended range 9.07 to 200 t"),
        ({"vehicle.mass": "35 kg"}, r"vehicle.mass='35 kg' is outside from 100 to 1e\+06 kg .*did "
         r"you mean '35 t' \(35 t\)\?"),
        ({"bridge.damping_ratio": 1.5}, r"bridge.damping_ratio=1.5 is outside"),
        ({"bridge.damping_ratio": "5 %"}, None),
        ({"vehicle.damping_ratio": -0.1}, r"vehicle.damping_ratio=-0.1 must be at least 0 "
         r"\(a damper cannot give energy back"),
        ({"vehicle.damping_ratio": float("nan")}, r"vehicle.damping_ratio=nan must be a finite "
         r"number"),
        # types
        ({"quick": "False"}, r"quick='False' must be a YAML boolean: true or false, unquoted"),
        ({"vehicle.damped": 1}, r"vehicle.damped=1 must be a YAML boolean"),
        ({"bridge.n_spans": 60}, r"bridge.n_spans=60 is outside 1 to 50 "
         r"\(vbi_lib.ranges.RANGES\['n_spans'\]\)"),
        ({"bridge.n_spans": 3}, r"bridge.k_mid=.* is the study's route for one span or two equal "
         r"spans"),
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


@pytest.mark.parametrize("ratio", [0.6, 1.0, 2.09, "209 %"])
def test_an_overdamped_suspension_is_taken_and_warned_of(ratio: object) -> None:
    """h20's rule: a suspension damped above the intended 50 % (at or above critical: it
    creeps back without vibrating) is a valid truck, run and warned of, never refused."""
    p = read_parameters(base(**{"vehicle.damping_ratio": ratio}))
    expected = 2.09 if ratio == "209 %" else ratio
    assert p.vehicle.damping_ratio == pytest.approx(expected, rel=1e-12)
    (warning,) = p.warnings
    assert warning.startswith(f"vehicle.damping_ratio={ratio!r} is outside the intended range")
    assert "overdamped" in warning
    assert not read_parameters(base(**{"vehicle.damping_ratio": 0.5})).warnings


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


# ---------------------------------------------------------------------------- one table of ranges
def _keys(schema: dict, prefix: str = ""):  # noqa: ANN202
    for name, value in schema.items():
        if isinstance(value, dict):
            yield from _keys(value, f"{name}.")
        else:
            yield prefix + name, value


def test_every_range_is_the_library_s() -> None:
    """The report keeps no table of its own: each key's range is its RANGES entry's intended
    (soft) range, or the hard one where there is none."""
    from vbi_lib.ranges import RANGES
    from vbi_lib.reports.parameters import SCHEMA

    checked = 0
    for name, key in _keys(SCHEMA):
        if key.range is None:
            continue
        spec = RANGES[key.range]
        assert key.bounds == (spec.soft or spec.hard), name
        checked += 1
    assert checked >= 15
    # and where the two tables once disagreed, the library's holds
    assert read_parameters(base(**{"bridge.first_frequency": "0.5 Hz"})).bridge.first_frequency
    assert read_parameters(base(**{"vehicle.frequency": "40 Hz"})).vehicle.frequency == 40.0
    assert read_parameters(base(**{"vehicle.mass": "150 t"})).vehicle.mass == 150e3
    with pytest.raises(ParameterError, match=r"first_frequency='0.4 Hz' is outside the intended"):
        read_parameters(base(**{"bridge.first_frequency": "0.4 Hz"}))


@pytest.mark.parametrize(
    ("mass", "slip"),
    [
        ("77.2 kN", r"is a weight of 7.87 t, which is outside the intended range 9.07 to 200 t "
         r"\(88.9 to 1,960 kN\) .*; did you mean '77.2 kip' \(35 t\)\?"),
        ("5 kip", r"is a weight of 2.27 t, which is outside the intended range 9.07 to 200 t "
         r"\(20 to 441 kip\) of mass of a truck"),
        ("500 kip", r"is a weight of 227 t.*did you mean '500 kN' \(51 t\)"),
    ],
)  # fmt: skip
def test_a_mass_outside_a_truck_s_range_names_the_likely_slip(mass: str, slip: str) -> None:
    """Warned about, not refused: a light truck is possible (an explorer's 5 kip one), and
    the warning heads the report's summary and goes to the command line."""
    p = read_parameters(base(**{"vehicle.mass": mass}))
    assert len(p.warnings) == 1
    assert re.search(slip, p.warnings[0]), p.warnings[0]
    assert p.warnings[0].startswith(f"vehicle.mass={mass!r} ")
    assert read_parameters(base()).warnings == ()


def three_spans(**vehicle: object) -> dict:
    values = base(**{"bridge.span": ..., "bridge.n_spans": ..., "bridge.k_mid": ...,
                     "bridge.first_frequency": ...})  # fmt: skip
    values["bridge"].update(spans=["90 ft", "120 ft", "90 ft"], EI="5.3e11 kip*in**2",
                            mass_per_length="11 kip/ft")  # fmt: skip
    values["vehicle"] = vehicle or {"type": "hs20"}
    return values


def test_real_bridges_and_design_vehicles_are_read() -> None:
    p = read_parameters(three_spans())
    assert p.bridge.spans == pytest.approx((90 * FT, 120 * FT, 90 * FT))
    assert p.bridge.span == pytest.approx(120 * FT) and p.bridge.n_spans == 3
    assert not p.bridge.study_layout
    assert p.vehicle.type == "hs20" and p.vehicle.frequency == 3.0
    assert p.vehicle.rear_axle_spacing == pytest.approx((14 * FT, 30 * FT))  # the default range
    assert p.direction == "both" and p.effects == ("displacement", "moment", "shear")
    assert p.sections is None and p.units == "US"
    one = read_parameters(three_spans(type="hl93-truck", rear_axle_spacing="20 ft"))
    assert one.vehicle.rear_axle_spacing == pytest.approx((20 * FT, 20 * FT))
    permit = read_parameters(three_spans(type="axles", loads=["12 kip", "34 kip", "34 kip"],
                                         spacings=["14 ft", "4 ft"], tyres=False))  # fmt: skip
    assert permit.vehicle.loads == pytest.approx((12e3 * LBF, 34e3 * LBF, 34e3 * LBF))
    assert permit.vehicle.spacings == pytest.approx((14 * FT, 4 * FT)) and not permit.vehicle.tyres
    car = read_parameters(three_spans(type="quarter-car", mass="30 t", unsprung_mass="3 t",
                                      frequency="2 Hz", tyre_stiffness="10 MN/m"))  # fmt: skip
    assert car.vehicle.unsprung_mass == 3000.0 and car.vehicle.tyre_stiffness == 1e7
    chosen = read_parameters({**three_spans(), "sections": ["120 ft", "45 ft"],
                              "effects": ["shear", "moment"], "direction": "backward"})  # fmt: skip
    assert chosen.sections == pytest.approx((45 * FT, 120 * FT))
    assert chosen.effects == ("moment", "shear") and chosen.direction == "backward"
    same = three_spans()
    same["bridge"]["EI"] = ["5.3e11 kip*in**2"] * 3
    assert read_parameters(same).bridge.EI == pytest.approx(p.bridge.EI)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (lambda v: v["bridge"].update(span="100 ft"), r"bridge.spans=.* and bridge.span are "
         r"both given"),
        (lambda v: v["bridge"].update(n_spans=3), r"bridge.n_spans=3 applies to bridge.span"),
        (lambda v: v["bridge"].update(EI=["5e11 kip*in**2", "6e11 kip*in**2", "5e11 kip*in**2"]),
         r"bridge.EI=.* differs from span to span; the report's beam is uniform"),
        (lambda v: v["bridge"].update(EI=["5e11 kip*in**2"]), r"bridge.EI=.* must list 3"),
        (lambda v: v["bridge"].update(spans="90 ft"), r"bridge.spans='90 ft' must be a YAML list"),
        (lambda v: v.update(vehicle={"type": "hs20", "mass": "35 t"}), r"vehicle.mass='35 t' "
         r"does not apply to vehicle.type hs20; it belongs to sprung-mass, quarter-car"),
        (lambda v: v.update(vehicle={"type": "hs21"}), r"vehicle.type='hs21' must be one of "
         r"sprung-mass, quarter-car, hs20"),
        (lambda v: v.update(vehicle={"type": "hs20", "rear_axle_spacing": "35 ft"}),
         r"vehicle.rear_axle_spacing='35 ft' is outside AASHTO's 14 to 30 ft"),
        (lambda v: v.update(vehicle={"type": "hs20", "rear_axle_spacing": ["30 ft", "14 ft"]}),
         r"must list the shorter spacing first"),
        (lambda v: v.update(vehicle={"type": "axles", "loads": ["12 kip", "34 kip"]}),
         r"vehicle.spacings=\(missing\) must list 1 distances"),
        (lambda v: v.update(vehicle={"type": "axles", "loads": ["0.3 kN", "0.3 kN"],
                                     "spacings": ["14 ft"]}),
         r"vehicle.loads\[0\]='0.3 kN' is outside the intended range 1 to 5,000 kN of weight of "
         r"a vehicle"),
        (lambda v: v.update(vehicle={"type": "quarter-car", "mass": "30 t", "frequency": "2 Hz"}),
         r"vehicle.unsprung_mass=\(missing\) is required"),
        (lambda v: v.update(sections=["400 ft"]), r"sections\[0\]='400 ft' lies beyond the "
         r"bridge's far support, 91.440 m \(300.00 ft\)"),
        (lambda v: v.update(sections=["-1 ft"]), r"sections\[0\]='-1 ft' must not be negative"),
        (lambda v: v.update(sections=["90 ft", "90 ft"]), r"sections=.* names a station twice"),
        (lambda v: v.update(effects=["torque"]), r"effects\[0\]='torque' must be one of "
         r"displacement, moment, shear"),
        (lambda v: v.update(effects="moment"), r"effects='moment' must be a YAML list"),
        (lambda v: v.update(direction="both ways"), r"direction='both ways' must be one of "
         r"forward, backward, both"),
        (lambda v: v["bridge"].update(k_mid="1e8 N/m", first_frequency="3 Hz", EI=None) or
         v["bridge"].pop("EI") or v["bridge"].pop("mass_per_length"),
         r"bridge.k_mid=.* is the study's route for one span or two equal spans"),
    ],
)  # fmt: skip
def test_bad_real_bridge_keys_are_refused_by_key(change, message: str) -> None:  # noqa: ANN001
    values = three_spans()
    change(values)
    with pytest.raises(ParameterError, match=message):
        read_parameters(values)


def test_axle_loads_outside_a_truck_s_range_name_the_likely_slip() -> None:
    values = three_spans(type="axles", loads=["8 kN", "32 kN", "32 kN"],
                         spacings=["14 ft", "14 ft"])  # fmt: skip
    p = read_parameters(values)
    assert len(p.warnings) == 1
    expected = (
        r"vehicle.loads=.* weigh 7.34 t in all, outside the intended range 9.07 to 200 t .* in "
        r"kip instead of kN it would weigh 32.7 t"
    )
    assert re.search(expected, p.warnings[0]), p.warnings[0]
