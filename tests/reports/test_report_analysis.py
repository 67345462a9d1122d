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
    inputs = smooth.inputs
    for i, speed in enumerate(inputs.speeds):
        for coupled, result in (
            (True, smooth.requested.coupled),
            (False, smooth.requested.decoupled),
        ):
            direct = vbi.simulate(inputs.bridge, inputs.vehicle, inputs.road, speed,
                                  inputs.bridge_start, coupled=coupled)  # fmt: skip
            assert result.daf[i, 0] == pytest.approx(direct.daf[0], rel=1e-12)
    largest, at = smooth.requested.largest(0)
    assert largest == pytest.approx(smooth.requested.coupled.daf[:, 0].max())
    assert smooth.worst.speed == at


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
    assert codes.aashto_lrfd == pytest.approx(1.33)
    values = list(codes.daf.values())
    assert values[1] == pytest.approx(1 + 50 / (140 + 125))
    assert values[2] == pytest.approx(1 + 0.20 + 0.20 * (2.08 - 1.0) / 1.5)  # OHBDC ramp


def test_roughness_per_span_is_the_library_measure(smooth) -> None:
    deck = smooth.inputs.deck
    assert smooth.roughness.iri[0] == pytest.approx(vbi.iri(deck.segment(0, deck.x[-1])).iri)
    assert smooth.roughness.iso_class[0] in "AB"


def test_the_summary_says_plainly_whether_the_tyre_kept_contact(smooth, rough) -> None:
    display.set_units("US")
    kept = R.summary_html(smooth)
    assert not smooth.requested.lost_contact.any()
    assert "The tyre stayed on the road at every requested speed" in kept
    daf = smooth.requested.coupled.daf[:, 0].max()
    assert f"<td>{daf:.2f}</td>" in kept
    assert rough.requested.lost_contact.any()
    lost = R.summary_html(rough)
    assert "would have left the road" in lost and "the model's validity" in lost
    table = R.daf_html(rough)
    for i in np.flatnonzero(rough.requested.lost_contact):
        assert f"{rough.requested.coupled.daf[i, 0]:.3f} (contact lost: outside validity)" in table


def test_user_text_is_escaped(smooth) -> None:
    title = R.title_html(smooth.inputs)
    assert "<img" not in title and "&lt;img src=x onerror=alert(1)&gt; &amp; co" in title
    provenance = R.provenance_html(smooth.inputs, {"name": "<b>p.yaml</b>", "sha256": "0" * 64})
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
