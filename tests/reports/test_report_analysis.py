"""What a report computes, against direct library calls and closed forms; how it is shown."""

from __future__ import annotations

import math

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import display
from vbi_lib.reports import analyse, prepare, read_parameters
from vbi_lib.reports import render as R
from vbi_lib.reports.analysis import allowances, shifted_deck


@pytest.fixture(autouse=True)
def _display_restored():  # noqa: ANN202
    """Tests here choose display units; the session's default (SI, alongside) comes back."""
    yield
    display.set_units("SI")


def case(iso_class: str = "A", **vehicle: object) -> dict:
    return {
        "title": "<img src=x onerror=alert(1)> & co",
        "bridge": {"span": "100 ft", "k_mid": "497527 lbf/in", "first_frequency": "3.99 Hz"},
        "vehicle": {"mass": "77.2 kip", "frequency": "4.5 Hz", **vehicle},
        "profile": {"iso_class": iso_class, "seed": 2},
        "speeds": ["35 mph", "65 mph"],
        "quick": True,
    }


@pytest.fixture(scope="module")
def smooth():
    return analyse(prepare(read_parameters(case("A"))))


@pytest.fixture(scope="module")
def rough():
    return analyse(prepare(read_parameters(case("F", damping_ratio=0.02))))


def test_daf_at_each_speed_is_a_direct_simulation(smooth) -> None:
    """The study's case: its span DAF, coupled and decoupled, and the DAF of each effect at
    midspan, each a crossing run here; the generated road's approach starts for each speed
    as far before the bridge as the start-up rule asks at that speed."""
    inputs = smooth.inputs
    rows = smooth.sections.rows
    midspan = inputs.bridge.span / 2
    assert set(rows.section_m) == {midspan} and set(rows.direction) == {"forward", "backward"}
    for i, speed in enumerate(inputs.speeds):
        needed = max(10.0, speed * math.log(100) / (0.10 * 2 * math.pi * 4.5))
        road = inputs.road.segment(inputs.bridge_start - needed, inputs.road.x[-1])
        for coupled, result in (
            (True, smooth.requested.coupled),
            (False, smooth.requested.decoupled),
        ):
            direct = vbi.simulate(inputs.bridge, inputs.vehicle, road, speed,
                                  inputs.bridge_start, coupled=coupled)  # fmt: skip
            assert result.daf[i, 0] == pytest.approx(direct.daf[0], rel=1e-12)
            if not coupled:
                continue
            response = direct.sections([midspan])
            for e, effect in enumerate(("displacement", "moment", "shear")):
                row = rows[(rows.effect == effect) & (rows.direction == "forward")
                           & (rows.speed_m_s == speed)].iloc[0]  # fmt: skip
                assert row.daf == pytest.approx(response.daf[e, 0], rel=1e-12)
    largest, at = smooth.requested.largest(0)
    assert largest == pytest.approx(smooth.requested.coupled.daf[:, 0].max())
    best = rows.loc[rows.daf.idxmax()]
    assert smooth.worst.speed == best.speed_m_s


def test_the_deck_moved_along_the_bridge_keeps_its_roughness() -> None:
    x = np.linspace(0.0, 30.0, 301)
    z = 0.002 * x / 30 + 0.003 * np.exp(-(((x - 6.0) / 0.5) ** 2))
    deck = vbi.Profile(x, z)
    moved = shifted_deck(deck, 9.0)
    trend = 0.002 * x / 30
    rest, moved_rest = z - trend, moved.elevation - trend
    assert x[np.argmax(moved_rest)] == pytest.approx(15.0)  # the bump moved 9 m on
    assert moved.elevation[0] == pytest.approx(z[0], abs=1e-9)
    assert moved.elevation[-1] == pytest.approx(z[-1], abs=1e-9)
    assert np.sort(moved_rest)[-50:] == pytest.approx(np.sort(rest)[-50:], abs=1e-12)
    assert shifted_deck(deck, 30.0).elevation == pytest.approx(z, abs=1e-12)  # a full turn


def test_position_study_starts_from_the_road_as_given(smooth) -> None:
    study = smooth.position
    assert study.offsets[0] == 0.0 and study.offsets.size == 8
    assert study.daf[:, 0] == pytest.approx(smooth.requested.coupled.daf[:, 0], rel=1e-12)
    assert np.ptp(study.daf) > 0  # where the bumps lie matters


def test_code_allowances_are_the_closed_forms() -> None:
    bridge = vbi.Bridge.from_midspan_stiffness(
        140 * 0.3048, 1, 222278 * 4.4482216152605 / 0.0254, 2.08
    )
    codes = allowances(bridge)
    assert codes.aashto_lrfd == pytest.approx(1.33) and codes.aashto_fatigue == 1.15
    values = list(codes.daf.values())
    assert values[:2] == pytest.approx([1.33, 1.15])
    assert values[2] == pytest.approx(1 + 50 / (140 + 125))
    assert values[3] == pytest.approx(1 + 0.20 + 0.20 * (2.08 - 1.0) / 1.5)  # OHBDC ramp


def test_the_aashto_standard_s_loaded_length_follows_the_place_and_effect() -> None:
    """AASHTO Standard 3.8.2.2: the span for positive moment, the mean of the adjacent spans
    for negative moment, the loaded part of the span for shear."""
    from vbi_lib.reports.analysis import Column, loaded_length
    from vbi_lib.reports.inputs import Place

    bridge = vbi.Bridge.continuous([20.0, 30.0, 25.0], EI=1e10, mass_per_length=8e3)
    pier = Place(20.0, "pier 1 (interior support)", 1, 0)
    inside = Place(26.0, "span 2 at 0.2 of its length", None, 1)
    assert loaded_length(bridge, Column(pier, "moment")) == 25.0
    assert loaded_length(bridge, Column(pier, "shear", "left")) == 20.0
    assert loaded_length(bridge, Column(pier, "shear", "right")) == 30.0
    assert loaded_length(bridge, Column(inside, "moment")) == 30.0
    assert loaded_length(bridge, Column(inside, "shear")) == 24.0
    codes = allowances(bridge, (Column(pier, "moment"), Column(inside, "shear")))
    feet = 0.3048
    assert codes.by_column[0]["AASHTO Standard"] == pytest.approx(1 + 50 / (25 / feet + 125))
    assert codes.by_column[1]["AASHTO Standard"] == pytest.approx(1 + 50 / (24 / feet + 125))


def test_roughness_per_span_is_the_library_measure(smooth) -> None:
    deck = smooth.inputs.deck
    assert smooth.roughness.iri[0] == pytest.approx(vbi.iri(deck.segment(0, deck.x[-1])).iri)
    assert smooth.roughness.iso_class[0] in "AB"


def test_the_summary_says_plainly_whether_the_tyre_kept_contact(smooth, rough) -> None:
    display.set_units("US")
    kept = R.summary_html(smooth)
    assert not smooth.requested.lost_contact.any() and not smooth.sections.rows.lost_contact.any()
    assert "The vehicle stayed on the road at every requested speed and direction" in kept
    rows = smooth.sections.rows
    for effect in ("displacement", "moment", "shear"):
        daf = rows[rows.effect == effect].daf.max()
        assert f"<td>{daf:.2f}</td>" in kept
    assert rough.requested.lost_contact.any()
    lost = R.summary_html(rough)
    assert "a real wheel would have lifted off" in lost and "outside its validity" in lost
    table = R.daf_html(rough)
    for i in np.flatnonzero(rough.requested.lost_contact):
        assert f"{rough.requested.coupled.daf[i, 0]:.3f} (contact lost: outside validity)" in table


def test_user_text_is_escaped(smooth) -> None:
    title = R.title_html(smooth.inputs)
    assert "<img" not in title and "&lt;img src=x onerror=alert(1)&gt; &amp; co" in title
    from vbi_lib.reports.appendix import provenance_html

    provenance = provenance_html(smooth.inputs, {"name": "<b>p.yaml</b>", "sha256": "0" * 64})
    assert "<b>" not in provenance and "&lt;b&gt;p.yaml&lt;/b&gt;" in provenance


@pytest.mark.parametrize(
    ("value", "text"),
    [(30.0, "30"), (103.228799, "103"), (0.012345, "0.0123"), (222278.0, "222,278"),
     (2.196e13, "2.2e13"), (-1.5, "-1.5"), (1.0, "1"), (math.nan, "-")],
)  # fmt: skip
def test_numbers_are_formatted_for_people(value: float, text: str) -> None:
    assert R.number(value) == text


def test_quantities_show_the_users_units_with_si_alongside() -> None:
    display.set_units("US")
    assert R.quantity(30 * 0.44704, "speed") == "30 mph (48.3 km/h)"
    assert R.quantity(42.672, "length") == "140 ft (42.7 m)"
    display.set_units("SI", alongside=False)
    assert R.quantity(30 * 0.44704, "speed") == "48.3 km/h"
