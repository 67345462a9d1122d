"""A report's road: the deck from the file's first point, an approach before it, short decks."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib.reports.approach import approach_length
from vbi_lib.reports.inputs import prepare
from vbi_lib.reports.parameters import ParameterError, read_parameters

FT, INCH, MPH = 0.3048, 0.0254, 0.44704


def i76(profile: dict, folder: Path, speeds: tuple[str, ...] = ("30 mph", "70 mph")) -> dict:
    return {
        "bridge": {"span": "140 ft", "k_mid": "222278 lbf/in", "first_frequency": "2.08 Hz"},
        "vehicle": {"mass": "200 lbf*s**2/in", "frequency": "2.5 Hz", "damping_ratio": 0.10},
        "profile": profile,
        "speeds": list(speeds),
    }


@pytest.mark.parametrize("span", [2, 3, 4, 5, 6])
def test_a_deck_only_profile_starts_the_bridge_at_its_first_point(
    shared_data: Path, span: int
) -> None:
    path = shared_data / "profiles" / f"i76-span{span}.csv"
    rows = np.loadtxt(path, delimiter=",")
    inputs = prepare(read_parameters(i76({"file": str(path), "length_unit": "inch"}, path)))
    deck, road, start = inputs.deck, inputs.road, inputs.bridge_start
    # the file's samples, moved so that the first one is the first support
    assert np.allclose(deck.x[:-1], (rows[:, 0] - rows[0, 0]) * INCH)
    assert np.allclose(road.elevation_at(start + deck.x[:-1]), rows[:, 1] * INCH)
    # the file stops 0.9 in short of 140 ft: the last elevation is held to the far support
    short = 140 * 12 - (rows[-1, 0] - rows[0, 0])  # inches
    assert 0 < short < 0.98425
    assert deck.x[-1] == pytest.approx(140 * FT)
    assert deck.elevation[-1] == pytest.approx(rows[-1, 1] * INCH)
    assert any(f"ends {short * 25.4:.0f} mm ({short:.2f} in" in note for note in inputs.notes)
    # a flat approach at the deck's first elevation: the truck stays at rest on it, so it
    # only has to stand on it (10 m; a sprung mass has no wheelbase)
    assert start == pytest.approx(10.0)
    before = road.x[road.x <= start]
    assert np.all(road.elevation_at(before) == rows[0, 1] * INCH)
    assert "flat" in inputs.notes[0] and f"{start:.0f} m" in inputs.notes[0]
    assert "long enough for the whole vehicle to stand on it" in inputs.notes[0]


def test_a_much_shorter_profile_is_refused(tmp_path: Path) -> None:
    deck = tmp_path / "short.csv"
    deck.write_text("\n".join(f"{i * 0.98425},0" for i in range(1600)))  # 131 ft
    with pytest.raises(ParameterError, match=r"profile.file='short.csv' covers 39.97 m .* but the "
                       r"bridge is 42.67 m \(140.0 ft\) long"):  # fmt: skip
        prepare(read_parameters(i76({"file": "short.csv", "length_unit": "inch"}, deck),
                                base_dir=tmp_path))  # fmt: skip
    # three samples short is too short too; one is filled
    for missing, accepted in ((3, False), (1, True)):
        count = int(round(140 * 12 / 0.98425)) + 1 - missing
        deck.write_text("\n".join(f"{i * 0.98425},0" for i in range(count)))
        parameters = read_parameters(
            i76({"file": "short.csv", "length_unit": "inch"}, deck), base_dir=tmp_path
        )
        if accepted:
            prepare(parameters)
        else:
            with pytest.raises(ParameterError, match="at most 2 samples"):
                prepare(parameters)


def test_a_profile_file_that_cannot_be_read_names_the_line(tmp_path: Path) -> None:
    (tmp_path / "bad.csv").write_text("0,0\n1,x\n")
    parameters = read_parameters(
        i76({"file": "bad.csv", "length_unit": "inch"}, tmp_path), base_dir=tmp_path
    )
    with pytest.raises(ParameterError, match=r"profile.file='bad.csv' cannot be read \(line 2\)"):
        prepare(parameters)


def test_the_fitted_approach_continues_the_deck_without_a_step(shared_data: Path) -> None:
    path = shared_data / "profiles" / "i76-span3.csv"
    profile = {"file": str(path), "length_unit": "inch", "approach": "iso8608", "seed": 4}
    inputs = prepare(read_parameters(i76(profile, path)))
    road, start = inputs.road, inputs.bridge_start
    approach = road.segment(road.start, start)
    assert road.elevation_at(start) == pytest.approx(inputs.deck.elevation[0])
    fit = vbi.fit_iso8608(inputs.deck)
    regenerated = vbi.Profile.iso8608(start, inputs.deck.spacing, c10=fit.c10,
                                      waviness=fit.waviness, seed=4)  # fmt: skip
    # the approach is that ISO 8608 road, moved up or down to meet the deck
    offset = approach.elevation - regenerated.elevation_at(approach.x)
    assert np.ptp(offset) < 1e-12
    assert "ISO 8608" in inputs.notes[0]


def test_bridge_start_and_a_given_approach_length(tmp_path: Path) -> None:
    (tmp_path / "road.csv").write_text("\n".join(f"{i * 0.1},{i % 3 * 0.001}" for i in range(601)))
    profile = {"file": "road.csv", "length_unit": "m", "bridge_start": "10 m",
               "approach_length": "25 m"}  # fmt: skip
    values = {
        "bridge": {"span": "30 m", "EI": "2e10 N*m**2", "mass_per_length": "8 t/m"},
        "vehicle": {"mass": "30 t", "frequency": "3 Hz"},
        "profile": profile,
        "speeds": ["60 km/h"],
    }
    inputs = prepare(read_parameters(values, base_dir=tmp_path))
    assert inputs.bridge_start == 25.0
    assert inputs.deck.x[-1] == 30.0
    x = np.arange(0, 300) * 0.1
    assert np.allclose(inputs.deck.elevation_at(x), (np.arange(100, 400) % 3) * 0.001)


def test_the_approach_rule_and_a_generated_road() -> None:
    truck = vbi.Vehicle.from_frequency(30e3, 3.0, 0.2)
    assert approach_length(truck, 25.0) == pytest.approx(25 * math.log(100) / (0.2 * 6 * math.pi))
    assert approach_length(truck, 0.1) == 10.0  # never shorter than 10 m
    values = {
        "bridge": {"span": "30 m", "mass_per_length": "8 t/m", "first_frequency": "4 Hz"},
        "vehicle": {"mass": "30 t", "frequency": "3 Hz", "damping_ratio": 0.2},
        "profile": {"iso_class": "D", "seed": 7},
        "speeds": ["60 km/h"],
    }
    inputs = prepare(read_parameters(values))
    length = inputs.bridge_start + 30.0
    road = vbi.Profile.iso8608(length, 0.025, iso_class="D", seed=7)
    # one continuous generated road: approach and deck
    assert np.allclose(inputs.road.elevation_at(road.x), road.elevation, atol=1e-12)


@pytest.mark.parametrize("zeta", [1.5, 2.09, 8.0])
def test_the_approach_of_an_overdamped_suspension_waits_for_its_slow_root(zeta: float) -> None:
    """Reference: the free motion of ``m u'' + c u' + k u = 0`` from a unit offset at rest,
    computed in the test as the matrix exponential of its first-order system (no roots
    taken); overdamped, it creeps back without overshoot, and its decay rate late in the
    motion is measured between two times.  The approach is the road over which that rate
    takes the motion down by DECAY.  ``zeta * omega`` (the rule below critical damping) would
    make it far too short: 8 times at 2.09 times critical, VBI-2D's verification vehicle
    (5750 kg bouncing at 2.65 Hz)."""
    from scipy.linalg import expm

    from vbi_lib.reports.approach import DECAY

    m, omega = 5750.0, 2 * math.pi * 2.65
    k, c = m * omega**2, 2 * zeta * m * omega
    with pytest.warns(vbi.OutsideValidityWarning, match="damping_ratio"):
        truck = vbi.Vehicle(m, k, c)  # above the intended 0.5: accepted, warned of
    speed = 20.0
    t = approach_length(truck, speed) / speed  # [s] on the approach
    system = np.array([[0.0, 1.0], [-k / m, -c / m]])
    late, later = (float((expm(system * time) @ [1.0, 0.0])[0]) for time in (t, 2 * t))
    assert late > 0 and later > 0  # no overshoot
    measured = math.log(late / later) / t  # the slow root's rate: the fast one's share is gone
    assert math.log(1 / DECAY) / measured == pytest.approx(t, rel=1e-6)
    assert zeta * omega > 2.5 * measured


# ---------------------------------------------------------------------------- unit slips
def test_stations_in_inches_declared_as_feet_are_refused(shared_data: Path) -> None:
    path = shared_data / "profiles" / "i76-span3.csv"
    values = i76({"file": str(path), "length_unit": "ft"}, path)
    with pytest.raises(ParameterError, match=r"profile.length_unit='ft' makes profile.file="
                       r"'i76-span3.csv' run 511.8 m, 12.0 times the 42.7 m to the bridge's far "
                       r"support; in inch it would run 42.6 m .* "
                       r"profile.length_unit: inch"):  # fmt: skip
        prepare(read_parameters(values))


def test_elevations_in_feet_read_as_inches_are_warned_about(tmp_path: Path, shared_data) -> None:
    rows = np.loadtxt(shared_data / "profiles" / "i76-span3.csv", delimiter=",")
    deck = tmp_path / "feet.csv"  # stations in inches, elevations in feet
    np.savetxt(deck, np.column_stack([rows[:, 0], rows[:, 1] / 12]), delimiter=",")
    inputs = prepare(read_parameters(i76({"file": "feet.csv", "length_unit": "inch"}, deck),
                                     base_dir=tmp_path))  # fmt: skip
    assert len(inputs.warnings) == 1
    warning = inputs.warnings[0]
    assert "fit an ISO 8608 C10 of 0.656e-6 m³ (class A, IRI 0.29 m/km), below the 1e-6 m³" in (
        warning
    )
    assert "profile.elevation_unit (it defaults to profile.length_unit)" in warning
    assert "in ft it would fit C10 = 94.4e-6 m³ (class B, IRI 3.5 m/km)." in warning
    # said as ft, the same file gives the deck's own roughness and no warning
    right = prepare(read_parameters(
        i76({"file": "feet.csv", "length_unit": "inch", "elevation_unit": "ft"}, deck),
        base_dir=tmp_path))  # fmt: skip
    assert right.warnings == ()
    assert np.allclose(right.deck.elevation[:-1], rows[:, 1] * INCH)


def test_a_long_profile_is_warned_about(tmp_path: Path) -> None:
    (tmp_path / "long.csv").write_text("\n".join(f"{i * 0.5},0.001" for i in range(1001)))
    values = {
        "bridge": {"span": "30 m", "EI": "2e10 N*m**2", "mass_per_length": "8 t/m"},
        "vehicle": {"mass": "30 t", "frequency": "3 Hz"},
        "profile": {"file": "long.csv", "length_unit": "m"},
        "speeds": ["60 km/h"],
    }
    inputs = prepare(read_parameters(values, base_dir=tmp_path))
    assert any("runs 500 m (1640 ft), 16.7 times the 30.0 m to the bridge's far support"
               in w and "correct profile.length_unit" in w for w in inputs.warnings)  # fmt: skip


# ---------------------------------------------------------------------------- real bridges
def three_spans(profile: dict | None = None, **vehicle: object) -> dict:
    return {
        "bridge": {"spans": ["60 ft", "80 ft", "70 ft"], "EI": "4e11 kip*in**2",
                   "mass_per_length": "9 kip/ft"},
        "vehicle": vehicle or {"type": "hs20", "rear_axle_spacing": "14 ft"},
        "profile": profile or {"iso_class": "B", "seed": 3},
        "speeds": ["40 mph", "60 mph"],
    }  # fmt: skip


def test_a_backward_crossing_sees_the_spans_and_the_deck_reversed() -> None:
    inputs = prepare(read_parameters(three_spans()))
    assert inputs.model == "modal" and inputs.modes >= 3
    assert [p.name for p in inputs.places] == [
        "midspan of span 1", "pier 1 (interior support)", "midspan of span 2",
        "pier 2 (interior support)", "midspan of span 3",
    ]  # fmt: skip
    forward, backward = inputs.run("forward"), inputs.run("backward")
    assert backward.bridge.spans == pytest.approx(forward.bridge.spans[::-1])
    length = inputs.bridge.length
    x = np.linspace(0.0, length, 97)
    np.testing.assert_allclose(
        backward.road.elevation_at(inputs.bridge_start + length - x) - backward.road.elevation_at(
            inputs.bridge_start),
        forward.road.elevation_at(inputs.bridge_start + x) - forward.road.elevation_at(
            inputs.bridge_start + length), atol=1e-12)  # fmt: skip
    # the road goes on past the far support for the truck's wheelbase: its last axle leaves
    wheelbase = 28 * FT
    for run in (forward, backward):
        assert run.road.x[-1] >= run.bridge_start + length + wheelbase
        assert run.road.x[0] <= run.bridge_start - wheelbase
    # a crossing at a lower speed starts later on the same rough road
    slow = inputs.run("forward", 40 * MPH)
    assert slow.road.x[0] > forward.road.x[0]
    assert slow.road.elevation_at(slow.road.x[5]) == forward.road.elevation_at(slow.road.x[5])


def test_an_approach_shorter_than_the_wheelbase_is_refused() -> None:
    values = three_spans({"iso_class": "B", "approach_length": "5 m"})
    with pytest.raises(ParameterError, match=r"profile.approach_length='5 m' is shorter than the "
                       r"vehicle's wheelbase, 8.53 m \(28.0 ft\)"):  # fmt: skip
        prepare(read_parameters(values))


def test_a_quarter_car_s_tyre_must_give_a_plausible_axle_hop() -> None:
    values = three_spans(type="quarter-car", mass="30 t", unsprung_mass="3 t",
                         frequency="2 Hz", tyre_stiffness="100 GN/m")  # fmt: skip
    with pytest.raises(ParameterError, match=r"vehicle.tyre_stiffness='100 GN/m' gives an axle-hop "
                       r"frequency of 919 Hz"):  # fmt: skip
        prepare(read_parameters(values))
