"""Vehicles as linear systems: closed-form frequencies, AASHTO's HS20, convoys, footprints.

References: the two-degree-of-freedom characteristic equations of a quarter car and of a
rigid beam on two springs (bounce and pitch), AASHTO's design-truck loads and spacings,
static equilibrium, and the moving average of a sine (a sinc factor), a line and a step.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.units import g
from vbi_lib.vehicles import (
    Axle,
    Convoy,
    IndependentAxles,
    QuarterCar,
    RigidTruck,
    Tyre,
    VehicleSystem,
    as_system,
    footprint_average,
    hs20,
    seen_by_tyre,
)


def two_by_two_frequencies_hz(k11: float, k12: float, k22: float, m1: float, m2: float) -> list:
    """Roots of (k11 - m1 w^2)(k22 - m2 w^2) = k12^2, as frequencies [Hz], increasing."""
    a = m1 * m2
    b = -(k11 * m2 + k22 * m1)
    c = k11 * k22 - k12**2
    roots = np.sort(np.roots([a, b, c]).real)
    return list(np.sqrt(roots) / (2 * math.pi))


def test_the_studys_sprung_mass_is_one_bilateral_contact() -> None:
    truck = vbi.Vehicle(1e4, 4e6, 2e4)
    s = truck.system
    assert (s.n_dofs, s.n_axles, s.wheelbase) == (1, 1, 0.0)
    assert s.contact_stiffness[0] == truck.stiffness and s.contact_damping[0] == truck.damping
    assert s.static_loads[0] == truck.weight and not s.has_unilateral
    assert s.frequencies_hz[0] == pytest.approx(truck.frequency_hz, rel=1e-12)


def test_quarter_car_frequencies_are_the_two_mass_roots() -> None:
    car = QuarterCar(12_000.0, 900.0, 5e5, 1e4, 3e6, 2e3)
    expected = two_by_two_frequencies_hz(5e5, -5e5, 5e5 + 3e6, 12_000.0, 900.0)
    np.testing.assert_allclose(car.system.frequencies_hz, expected, rtol=1e-10)
    assert car.weight == pytest.approx(12_900.0 * g)
    built = QuarterCar.from_frequencies(12_000.0, 900.0, body_hz=2.0, axle_hop_hz=11.0)
    assert math.sqrt(built.suspension_stiffness / 12_000.0) / (2 * math.pi) == pytest.approx(2.0)
    hop = math.sqrt((built.suspension_stiffness + built.tyre_stiffness) / 900.0) / (2 * math.pi)
    assert hop == pytest.approx(11.0)


def test_rigid_truck_bounce_and_pitch_are_those_of_a_beam_on_two_springs() -> None:
    """Centre of mass a ahead of the rear spring, b behind the front one (a + b = L)."""
    front, rear = Axle(0.0, 50e3, 4e5, 0.0), Axle(5.0, 150e3, 1.1e6, 0.0)
    truck = RigidTruck([front, rear], pitch_inertia=1.5e5)
    b = 5.0 * 150e3 / 200e3  # moment balance of the loads about the front axle
    assert truck.centre_of_mass == pytest.approx(b)
    a = 5.0 - b
    m = 200e3 / g
    expected = two_by_two_frequencies_hz(4e5 + 1.1e6, 4e5 * b - 1.1e6 * a,
                                         4e5 * b**2 + 1.1e6 * a**2, m, 1.5e5)  # fmt: skip
    np.testing.assert_allclose(truck.system.frequencies_hz, expected, rtol=1e-10)
    np.testing.assert_allclose(truck.system.static_loads, [50e3, 150e3])
    np.testing.assert_allclose(truck.system.rigid_translation, [1.0, 0.0], atol=1e-12)


def test_rigid_truck_with_tyres_adds_one_unsprung_mass_per_axle() -> None:
    tyre = Tyre(700.0, 2e6, 1e3)
    truck = RigidTruck([Axle(0.0, 50e3, 4e5, 1e4, tyre), Axle(5.0, 150e3, 1.1e6, 3e4, tyre)],
                       pitch_inertia=1.5e5)  # fmt: skip
    s = truck.system
    assert s.dof_names == ("bounce", "pitch", "axle 1 unsprung mass", "axle 2 unsprung mass")
    assert s.dof_units[1] == "rad" and s.unilateral.all()
    assert truck.body_mass == pytest.approx(200e3 / g - 1400.0)
    # the springs balance the sprung loads at the body's centre of mass
    np.testing.assert_allclose(s.rigid_translation, [1, 0, 1, 1], atol=1e-12)


def test_hs20_axle_loads_and_spacings_are_aashtos() -> None:
    for spacing in (14, 22, 30):
        truck = hs20(rear_spacing=spacing * u.ft)
        s = truck.system
        np.testing.assert_allclose(s.static_loads / u.kip, [8, 32, 32], rtol=1e-12)
        np.testing.assert_allclose(s.offsets / u.ft, [0, 14, 14 + spacing], rtol=1e-12)
        assert s.weight == pytest.approx(72 * u.kip)
    with pytest.raises(ValueError, match="rear_spacing=.* outside AASHTO's 14 to 30 ft"):
        hs20(rear_spacing=31 * u.ft)
    with pytest.raises(ValueError, match="body='stiff'"):
        hs20(body="stiff")


def test_hs20_dynamic_parameters_are_in_the_documented_ranges() -> None:
    """Body bounce at 3 Hz per axle on its suspension; axle hop between 8 and 15 Hz."""
    truck = hs20()
    assert all(a.tyre is not None and a.tyre.footprint == 0.25 for a in truck.axles)
    for axle in truck.axles:
        bounce = math.sqrt(axle.stiffness * g / axle.sprung_load) / (2 * math.pi)
        hop = math.sqrt((axle.stiffness + axle.tyre.stiffness) / axle.tyre.unsprung_mass)
        assert bounce == pytest.approx(3.0) and 8.0 < hop / (2 * math.pi) < 15.0
    rigid = hs20(body="rigid", tyres=False)
    assert rigid.pitch_inertia == pytest.approx(rigid.body_mass * (28 * u.ft) ** 2 / 12)
    assert rigid.centre_of_mass == pytest.approx((32 * 14 + 32 * 28) / 72 * u.ft)
    assert not rigid.system.has_unilateral


def test_convoy_places_vehicles_at_their_headways() -> None:
    truck = hs20(rear_spacing=20 * u.ft)
    car = vbi.Vehicle(2e3, 8e4, 2e3)
    convoy = Convoy([truck, car, truck], [15.0, 12.0])
    s = convoy.system
    lead = as_system(truck)
    np.testing.assert_allclose(s.offsets, np.concatenate((lead.offsets, [15.0], lead.offsets + 27)))
    assert s.weight == pytest.approx(2 * lead.weight + car.weight)
    assert s.n_dofs == 2 * lead.n_dofs + 1
    np.testing.assert_allclose(s.rigid_translation, 1.0)
    with pytest.raises(ValueError, match=r"headways\[0\]=10.0 m must exceed the wheelbase"):
        Convoy([truck, car], [10.0])
    with pytest.raises(ValueError, match="one distance per following vehicle"):
        Convoy([truck, car], [15.0, 20.0])
    with pytest.raises(TypeError, match="vehicle must be a vbi vehicle"):
        Convoy([truck, "car"], [15.0])


def test_independent_axles_are_one_sprung_mass_each() -> None:
    axles = [Axle(0.0, 40e3, 1e6, 1e4), Axle(3.5, 90e3, 2e6, 2e4, Tyre(900.0, 3e6))]
    s = IndependentAxles(axles).system
    np.testing.assert_allclose(np.diag(s.mass), [40e3 / g, 90e3 / g - 900.0, 900.0])
    np.testing.assert_allclose(s.contact_stiffness, [1e6, 3e6])
    assert s.unilateral.tolist() == [False, True] and s.footprint.tolist() == [0.0, 0.25]


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"mass": [[1.0, 0.5], [0.0, 1.0]]}, "mass must be symmetric"),
        ({"static_loads": [-1.0]}, r"static_loads=\[-1.0\] must all be > 0"),
        ({"offsets": [2.0]}, "smallest must be 0"),
        ({"footprint": [-0.1]}, "footprint="),
        ({"static_loads": [5e4]}, "do not balance the weight"),
        ({"stiffness": [[4e4, 0.0], [0.0, 4e4]]}, "cannot translate rigidly"),
    ],
)
def test_vehicle_system_names_what_is_wrong(change: dict, message: str) -> None:
    car = QuarterCar(1000.0, 100.0, 4e4, 1e3, 3e5).system
    fields = {
        k: getattr(car, k)
        for k in ("mass", "stiffness", "damping", "contact", "offsets", "static_loads",
                  "contact_stiffness", "contact_damping", "unilateral", "footprint")
    }  # fmt: skip
    if "mass" in change:
        fields["stiffness"] = np.zeros((2, 2))
    with pytest.raises(ValueError, match=message):
        VehicleSystem(**(fields | change))


def test_bad_vehicle_inputs_name_the_parameter() -> None:
    with pytest.raises(ValueError, match="unsprung_mass=0.0"):
        QuarterCar(1000.0, 0.0, 4e4, 1e3, 3e5)
    with pytest.raises(ValueError, match="weighs more than the axle load"):
        Axle(0.0, 5e3, 1e5, 0.0, Tyre(800.0, 1e6))
    with pytest.raises(ValueError, match="must start at 0"):
        IndependentAxles([Axle(1.0, 5e4, 1e6)])
    with pytest.raises(ValueError, match="at least two axle groups"):
        RigidTruck([Axle(0.0, 5e4, 1e6)], pitch_inertia=1e4)
    with pytest.raises(TypeError, match="vehicle must be a vbi vehicle"):
        as_system("truck")


def test_the_profile_must_reach_a_wheelbase_beyond_the_bridge() -> None:
    truck = hs20()
    bridge = vbi.Bridge(20.0, 1, 1e10, 5e3)
    with pytest.raises(ValueError, match="wheelbase of 8.5344 m .* to 38.5344 m or later"):
        vbi.simulate(bridge, truck, vbi.Profile.flat(35.0, 0.1), 20.0, 10.0)
    with pytest.raises(ValueError, match="from 1.4656 m or earlier"):
        vbi.simulate(bridge, truck, vbi.Profile.flat(45.0, 0.1, start=5.0), 20.0, 10.0)


# ---------------------------------------------------------------------------- footprint
def test_moving_average_of_a_sine_is_attenuated_by_a_sinc() -> None:
    x = np.arange(0.0, 40.0 + 1e-9, 0.01)
    wavelength, length = 1.3, 0.25
    y = np.sin(2 * np.pi * x / wavelength)
    inside = (x > 1.0) & (x < 39.0)
    # exact for a sine; the road is read linearly between samples (error ~ (k dx)^2 / 24)
    expected = y * np.sinc(length / wavelength)
    np.testing.assert_allclose(footprint_average(x, y, length)[inside], expected[inside],
                               atol=2e-4)  # fmt: skip


def test_moving_average_keeps_a_line_and_turns_a_step_into_a_ramp() -> None:
    x = np.linspace(-2.0, 2.0, 4001)
    line = 0.3 + 0.02 * x
    inside = np.abs(x) < 1.8
    np.testing.assert_allclose(footprint_average(x, line, 0.25)[inside], line[inside], rtol=1e-12)
    road = vbi.Profile.step(4.0, 0.001, position=2.0, height=0.01, start=0.0)
    seen = seen_by_tyre(road, 0.25)
    assert np.array_equal(seen.x, road.x)
    # the step rises over the sample after 2.0 m; its average is a ramp of slope h / L_c
    mid = 2.0005
    expected = np.clip((road.x - (mid - 0.125)) / 0.25, 0.0, 1.0) * 0.01
    far = np.abs(road.x - mid - 0.125) > 0.002
    far &= np.abs(road.x - mid + 0.125) > 0.002
    np.testing.assert_allclose(seen.elevation[far], expected[far], atol=1e-12)
    assert seen_by_tyre(road, 0.0) is road
    with pytest.raises(ValueError, match="footprint=-0.1"):
        seen_by_tyre(road, -0.1)
