"""Road profiles: ISO 8608 roads, teaching shapes, placing a road on a bridge.

References: ISO 8608's spectrum integrated in closed form (Parseval), the class table of
ISO 8608, closed-form shapes.
"""

from __future__ import annotations

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.profiles import ISO_CLASS_MEANS


# ---------------------------------------------------------------------------- ISO 8608
@pytest.mark.parametrize("waviness", [2.0, 3.0, 4.0])
def test_iso8608_variance_matches_the_integral_of_its_spectrum(waviness: float) -> None:
    """Parseval: mean square of the road = integral of G_d over the band (closed form)."""
    c10, low, high = 300e-6, 0.011, 2.83
    w = waviness
    integral = c10 * 0.1**w * (low ** (1 - w) - high ** (1 - w)) / (w - 1)
    squares = [
        np.mean(vbi.Profile.iso8608(5000.0, 0.05, c10=c10, waviness=w, seed=s).elevation ** 2)
        for s in range(3)
    ]
    # a Riemann sum with dn = 1/5000 of a spectrum this steep at 0.011: ~1 %
    assert np.mean(squares) == pytest.approx(integral, rel=0.03)


def test_iso8608_is_reproducible_from_its_seed() -> None:
    a = vbi.Profile.iso8608(100.0, 0.05, c10=300e-6, seed=4)
    b = vbi.Profile.iso8608(100.0, 0.05, c10=300e-6, seed=4)
    c = vbi.Profile.iso8608(100.0, 0.05, c10=300e-6, seed=5)
    np.testing.assert_array_equal(a.elevation, b.elevation)
    assert not np.allclose(a.elevation, c.elevation)


def test_the_studys_twelve_profiles_are_one_line_each() -> None:
    roads = [
        vbi.Profile.iso8608(650 * u.ft, 1 * u.inch, c10=c10, waviness=w, seed=draw)
        for c10 in (300e-6, 600e-6)
        for w in (2, 3, 4)
        for draw in (1, 2)
    ]
    assert len(roads) == 12
    for road in roads:
        assert road.x[0] == 0.0 and road.x[-1] == pytest.approx(650 * u.ft)
        assert road.spacing == pytest.approx(1 * u.inch)
    # twice the C10 with the same phases is sqrt(2) times the road
    np.testing.assert_allclose(
        roads[6].elevation, np.sqrt(2) * roads[0].elevation, rtol=1e-9, atol=1e-15
    )


def test_iso_class_uses_the_class_geometric_mean() -> None:
    by_class = vbi.Profile.iso8608(50.0, 0.05, iso_class="c", seed=1)
    by_value = vbi.Profile.iso8608(50.0, 0.05, c10=256e-6, seed=1)
    np.testing.assert_allclose(by_class.elevation, by_value.elevation)
    assert ISO_CLASS_MEANS["A"] == pytest.approx(16e-6)
    assert ISO_CLASS_MEANS["H"] == pytest.approx(262144e-6)


def test_an_uneven_last_station_continues_the_same_road() -> None:
    """The last station off the grid is summed directly; it must lie on the same road."""
    road = vbi.Profile.iso8608(100.0 + 0.01, 0.05, c10=300e-6, waviness=3, seed=2)
    assert road.x[-1] == pytest.approx(100.01)
    slope = np.diff(road.elevation[-4:-1]) / 0.05
    extrapolated = road.elevation[-2] + slope[-1] * 0.01
    assert road.elevation[-1] == pytest.approx(extrapolated, abs=2e-5)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({}, "exactly one of c10"),
        ({"c10": 1e-4, "iso_class": "A"}, "exactly one of c10"),
        ({"iso_class": "Z"}, "iso_class='Z'"),
        ({"c10": -1.0}, "c10=-1.0"),
        ({"c10": 1e-4, "waviness": 0.0}, "waviness"),
        ({"c10": 1e-4, "band": (0.5, 0.1)}, "band"),
    ],
)
def test_iso8608_rejects_bad_parameters(kwargs: dict, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        vbi.Profile.iso8608(100.0, 0.05, **kwargs)


def test_iso8608_refuses_a_spacing_that_cannot_carry_the_band() -> None:
    with pytest.raises(ValueError, match="resolves only up to 2 cycle/m"):
        vbi.Profile.iso8608(100.0, 0.25, c10=1e-4)


@pytest.mark.parametrize(
    ("c10", "expected"),
    [
        (16e-6, "A"),
        (31e-6, "A"),
        (33e-6, "B"),
        (300e-6, "C"),
        (600e-6, "D"),
        (0.1, "G"),
        (1.0, "H"),
    ],
)
def test_iso8608_class_limits(c10: float, expected: str) -> None:
    """ISO 8608 class limits: A < 32e-6 <= B < 128e-6 <= C < 512e-6 <= D ... m^3."""
    assert vbi.iso8608_class(c10) == expected


# ---------------------------------------------------------------------------- teaching shapes
def test_bump_is_a_raised_cosine() -> None:
    road = vbi.Profile.bump(10.0, 0.01, position=5.0, height=-0.02, width=2.0)
    x = np.array([3.9, 4.0, 4.5, 5.0, 5.5, 6.0, 6.5])
    expected = np.where(np.abs(x - 5.0) <= 1.0, -0.01 * (1 + np.cos(np.pi * (x - 5.0))), 0.0)
    np.testing.assert_allclose(road.elevation_at(x), expected, atol=1e-5)


def test_ramp_has_exact_corners_and_a_straight_grade() -> None:
    road = vbi.Profile.ramp(10.0, 0.3, position=2.05, rise=0.03, run=3.0)
    assert 2.05 in road.x and 5.05 in road.x
    np.testing.assert_allclose(
        road.elevation_at([1.0, 2.05, 3.55, 5.05, 9.0]), [0, 0, 0.015, 0.03, 0.03]
    )
    grade = vbi.Profile.ramp(50.0, 0.1, position=0.0, rise=0.5, run=50.0)
    np.testing.assert_allclose(np.diff(grade.elevation) / np.diff(grade.x), 0.01)


def test_step_rises_over_one_sample() -> None:
    road = vbi.Profile.step(10.0, 0.1, position=4.03, height=0.01)
    assert 4.03 in road.x
    assert road.elevation_at(4.03) == 0.0
    assert road.elevation_at(4.1) == pytest.approx(0.01)
    assert road.elevation[-1] == pytest.approx(0.01)


def test_shapes_reject_bad_numbers() -> None:
    with pytest.raises(ValueError, match="height=nan must be a finite number"):
        vbi.Profile.bump(10.0, 0.1, position=5.0, height=float("nan"), width=1.0)
    with pytest.raises(TypeError, match="position='x' must be a number"):
        vbi.Profile.step(10.0, 0.1, position="x", height=0.01)
    with pytest.raises(ValueError, match="run=0"):
        vbi.Profile.ramp(10.0, 0.1, position=1.0, rise=0.01, run=0)


def test_placing_a_road_on_a_bridge_in_five_foot_steps() -> None:
    """The study's position study: the same road moved along the bridge in 5 ft steps."""
    road = vbi.Profile.iso8608(200 * u.ft, 1 * u.inch, c10=300e-6, seed=3)
    for k in range(4):
        moved = road.shifted(k * 5 * u.ft)
        assert moved.elevation_at(moved.start + 50 * u.ft) == pytest.approx(
            road.elevation_at(50 * u.ft)
        )
    part = road.segment(20 * u.ft, 120 * u.ft)
    assert part.length == pytest.approx(100 * u.ft)
    coarse = road.resampled(1 * u.ft)
    assert coarse.spacing == pytest.approx(1 * u.ft)
