"""A report's road: the deck from the file's first point, an approach before it, short decks."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib.reports.inputs import approach_length, prepare
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
    # a flat approach at the deck's first elevation, as long as the decay rule asks
    fastest = 1.2 * 70 * MPH
    omega = 2 * math.pi * 2.5
    assert start == pytest.approx(fastest * math.log(100) / (0.10 * omega))
    before = road.x[road.x <= start]
    assert np.all(road.elevation_at(before) == rows[0, 1] * INCH)
    assert "flat" in inputs.notes[0] and f"{start:.0f} m" in inputs.notes[0]


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
