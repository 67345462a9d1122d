"""The explorers' truck model: the study's sprung mass or a quarter car whose tyre can leave
the road.  The quarter car is checked against one built in the test from its own formulas,
its frequencies against the closed form of a two-mass oscillator, and its contact against
what a tyre can do (push, never pull)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from explorer_cases import direct_crossing, quarter_car

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.widgets import (
    ControlValueError,
    CrossingExplorer,
    FrequencyExplorer,
    Scenario,
    SpeedExplorer,
)

QUARTER = {"vehicle_type": "quarter-car"}
#: A 2 in bump, 1 ft long, at 60 mph: the study's sprung mass would have to pull the road
#: down; a quarter car on a stiff tyre (axle hop 25 Hz) is thrown off the road.
THROWN = {"road": "bump", "bump_height_in": 2.0, "bump_width_ft": 1.0, "speed_mph": 60.0}
STIFF_TYRE = {"axle_hop_hz": 25.0}


def two_mass_frequencies(m_s: float, m_u: float, k_s: float, k_t: float) -> tuple[float, float]:
    """Undamped frequencies [Hz] of body and axle on a rigid road: the roots in w^2 of
    ``m_s m_u w^4 - (m_s (k_s + k_t) + m_u k_s) w^2 + k_s k_t = 0``."""
    b = m_s * (k_s + k_t) + m_u * k_s
    root = math.sqrt(b * b - 4 * m_s * m_u * k_s * k_t)
    low, high = (b - root) / (2 * m_s * m_u), (b + root) / (2 * m_s * m_u)
    return math.sqrt(low) / (2 * math.pi), math.sqrt(high) / (2 * math.pi)


def test_the_quarter_car_is_the_one_its_formulas_give_and_weighs_the_truck() -> None:
    scenario = Scenario(**QUARTER, truck_frequency_hz=2.5, axle_hop_hz=11.0, truck_damping=0.2)
    car = scenario.vehicle()
    values = {f: getattr(scenario, f) for f in Scenario.__dataclass_fields__}
    expected = quarter_car(values)
    assert isinstance(car, vbi.QuarterCar)
    for name in ("sprung_mass", "unsprung_mass", "suspension_stiffness", "suspension_damping",
                 "tyre_stiffness", "tyre_damping", "footprint", "unilateral"):  # fmt: skip
        assert getattr(car, name) == pytest.approx(getattr(expected, name), rel=1e-12), name
    assert car.weight == pytest.approx(77.2 * u.kip)  # the truck's weight, all of it
    assert car.unsprung_mass * u.g == pytest.approx(0.1 * 77.2 * u.kip)
    assert isinstance(Scenario().vehicle(), vbi.Vehicle)  # the study's, by default


def test_the_readout_names_the_quarter_car_and_its_coupled_frequencies() -> None:
    explorer = CrossingExplorer(**QUARTER, road="flat")
    car = explorer.result.vehicle
    low, high = two_mass_frequencies(
        car.sprung_mass, car.unsprung_mass, car.suspension_stiffness, car.tyre_stiffness
    )
    text = explorer.readout.value
    assert "quarter car" in text and "10% unsprung" in text
    assert "body 3.50 Hz on a rigid tyre, axle hop 20.0 Hz" in text
    assert f"vibrate at {low:.2f} and {high:.1f} Hz" in text
    explorer.controls["vehicle_type"].value = "sprung-mass"
    text = explorer.readout.value
    assert "the study's sprung mass" in text and "quarter car" not in text
    assert "sprung mass: " in text and "contact held" in text


def test_on_a_flat_road_over_a_stiff_heavy_bridge_the_quarter_car_gives_a_daf_near_one() -> None:
    """Speed parameter v / (2 f1 L) = 0.012: a nearly static load; the wheel never lifts."""
    explorer = CrossingExplorer(
        **QUARTER,
        road="flat",
        bridge_frequency_hz=12.0,
        bridge_weight_kip_per_ft=20.0,
        speed_mph=20.0,
    )
    crossing = explorer.result
    assert crossing.daf[0] == pytest.approx(1.0, abs=0.02)
    assert crossing.flight_fraction == 0.0 and not crossing.lost_contact
    assert crossing.min_contact_force_ratio > 0.9
    assert "the wheel stayed on the road" in explorer.readout.value
    assert "DAF 1.0" in explorer.readout.value


def test_a_bump_that_pulls_on_the_sprung_mass_throws_the_quarter_cars_wheel() -> None:
    """The same bump: the study's contact goes tensile (outside validity); the quarter car's
    tyre force stops at zero while the wheel flies, and the readout gives the flight time."""
    explorer = CrossingExplorer(**THROWN, **STIFF_TYRE)
    assert explorer.result.min_contact_force_ratio < 0.0
    assert "outside the model's validity" in explorer.readout.value

    explorer.controls["vehicle_type"].value = "quarter-car"
    crossing = explorer.result
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.OutsideValidityWarning)
        expected = direct_crossing(explorer.values())
    np.testing.assert_allclose(crossing.contact_force, expected.contact_force, rtol=1e-9)
    np.testing.assert_allclose(crossing.dof_displacement, expected.dof_displacement, rtol=1e-9)
    assert crossing.flight_fraction == pytest.approx(expected.flight_fraction)

    assert crossing.flight_fraction > 0.0
    assert crossing.contact_force.min() >= 0.0  # a tyre pushes, never pulls
    # the flights' durations over the time on the bridge give the flight fraction
    flights = crossing.flights()
    on = crossing.on_bridge
    on_time = crossing.time[on][-1] - crossing.time[on][0]
    assert flights["duration [s]"].sum() / on_time == pytest.approx(
        crossing.flight_fraction, abs=0.01
    )
    text = explorer.readout.value
    assert f"DAF {crossing.daf[0]:.3f}</b> &mdash; quarter car: " in text
    assert f"the wheel left the road for {crossing.flight_fraction:.0%} of the time" in text
    assert "outside the model's validity" not in text  # a flight is modelled


def test_the_figure_draws_the_quarter_cars_result() -> None:
    explorer = CrossingExplorer(**THROWN, **STIFF_TYRE, n_spans=2)
    for kind in ("quarter-car", "sprung-mass", "quarter-car"):
        explorer.controls["vehicle_type"].value = kind
        crossing = explorer.result
        top, bottom = explorer.axes
        x = vbi.display.value(crossing.position - crossing.bridge_start, "length")
        np.testing.assert_allclose(bottom.lines[0].get_xdata(), x)
        np.testing.assert_allclose(bottom.lines[0].get_ydata(), crossing.contact_force_ratio)
        for j in range(2):
            np.testing.assert_allclose(
                top.lines[j].get_ydata(),
                crossing.midspan_displacement[:, j] / crossing.static_deflection,
            )
        low, high = bottom.get_ylim()
        ratio = crossing.contact_force_ratio
        assert low <= min(ratio.min(), 0.0) and high >= ratio.max()
    assert crossing.dof_displacement.shape[1] == 2
    assert explorer.view.widget.value[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_quarter_cars_sliders_show_only_when_it_is_chosen() -> None:
    explorer = CrossingExplorer()

    def shown(name: str) -> bool:
        return explorer.controls[name].box.layout.display != "none"

    assert not shown("axle_hop_hz") and not shown("unsprung_fraction")
    explorer.controls["vehicle_type"].value = "quarter-car"
    assert shown("axle_hop_hz") and shown("unsprung_fraction")
    explorer.set(vehicle_type="sprung-mass")
    assert not shown("axle_hop_hz") and not shown("unsprung_fraction")


@pytest.mark.parametrize(
    ("name", "bad", "pattern"),
    [
        ("vehicle_type", "truck", r"vehicle_type='truck' must be one of 'sprung-mass'"),
        ("axle_hop_hz", float("nan"), r"axle_hop_hz=nan must be a finite number from 2 to 50"),
        ("unsprung_fraction", "a tenth", r"unsprung_fraction='a tenth' must be a finite number"),
    ],
)
def test_bad_values_are_refused_by_the_controls_by_name(
    name: str, bad: object, pattern: str
) -> None:
    explorer = CrossingExplorer(**QUARTER, road="flat")
    old = explorer.controls[name].value
    with pytest.raises(ControlValueError, match=pattern):
        explorer.controls[name].value = bad
    assert explorer.controls[name].value == old
    assert name in explorer.notice.value


def test_an_axle_hop_too_low_for_the_body_shows_why_and_no_number() -> None:
    """k_t = m_u (2 pi f_hop)^2 - k_s > 0 needs f_hop > 3.5 Hz * sqrt(0.9 / 0.1) = 10.5 Hz."""
    explorer = CrossingExplorer(**QUARTER, unsprung_fraction=0.1, road="flat")
    explorer.controls["axle_hop_hz"].value = 10.0
    assert explorer.result is None
    text = explorer.readout.value
    assert "axle_hop_hz=10 must be above 10.5 Hz" in text and "DAF" not in text
    explorer.controls["axle_hop_hz"].value = 10.6  # just above: a (soft) tyre again
    assert explorer.result is not None
    assert explorer.result.vehicle.tyre_stiffness > 0


@pytest.mark.parametrize(
    ("changes", "pattern"),
    [
        ({"vehicle_type": "lorry"}, r"vehicle_type='lorry' is not offered"),
        ({"unsprung_fraction": 0.0}, r"unsprung_fraction=0.0 must be a finite number greater"),
        ({"unsprung_fraction": 0.6}, r"unsprung_fraction=0.6 must be above 0 and at most 0.5"),
        ({"axle_hop_hz": -1.0}, r"axle_hop_hz=-1.0 must be"),
        ({"axle_hop_hz": 2000.0}, r"axle_hop_hz=2000.0 must be from 0.05 to 1000 Hz"),
        ({"vehicle_type": "quarter-car", "axle_hop_hz": 8.0}, r"axle_hop_hz=8 must be above"),
    ],
)
def test_a_scenario_refuses_a_bad_truck_by_name(changes: dict, pattern: str) -> None:
    with pytest.raises(ValueError, match=pattern):
        Scenario(**changes)


def test_a_speed_sweep_says_how_many_crossings_threw_the_wheel() -> None:
    bump = {k: v for k, v in THROWN.items() if k != "speed_mph"}
    explorer = SpeedExplorer(**QUARTER, **bump, **STIFF_TYRE, speed_range_mph=(10, 70), n_speeds=7)
    result = explorer.result
    flew = result.flight_fraction > 0
    assert flew.any()
    assert not result.outside_validity.any()  # a tyre never goes tensile
    text = explorer.readout.value
    assert f"the wheel left the road in {flew.sum()} of 7 crossings" in text
    assert f"longest {result.flight_fraction.max():.0%} of the time" in text
    assert "every crossing kept contact" not in text
    assert len(explorer.lost_daf.get_xdata()) == flew.sum()


def test_the_frequency_map_runs_the_quarter_car_and_refuses_a_column_it_cannot_build() -> None:
    small = {"n_ratios": 3, "n_speeds": 3, "speed_range_mph": (40.0, 60.0)}
    explorer = FrequencyExplorer(**QUARTER, axle_hop_hz=20.0, unsprung_fraction=0.1, **small)
    # bodies 1.5 to 6 Hz
    result = explorer.result
    assert result is not None, explorer.error
    assert result.flight_fraction.shape == (3, 3)
    # body 6 Hz at ratio 2 needs an axle hop above 6 * sqrt(9) = 18 Hz
    explorer.set(axle_hop_hz=15.0)
    assert explorer.result is None
    assert "at the frequency ratio 2.00: axle_hop_hz=15 must be above 18 Hz" in explorer.error
