"""A contact force that converges, or a crossing that says why not (issue 20).

A damper standing on the road presses on it with ``c v dr/dx``.  Over a step that rises within
one sample interval ``dx`` that force is ``c v h / dx``: the peak contact force is the
sampling's, and it doubles each time the sampling is halved.  The crossing must say so
(``UnresolvedRoadWarning``, naming ``footprint``); a footprint, a smooth road or a contact
without a damper converge and must not warn.  Every convergence claim is checked here on a
sequence of refined samplings computed in the test; the growth of the point contact's force
is checked against its closed form ``1 + c v h / (W dx) + (a constant)``.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from problems import VEHICLE_CASES, rough_profile

import vbi_lib as vbi
from vbi_lib.vehicles import Axle, IndependentAxles
from vbi_lib.vehicles.footprint import (
    UNRESOLVED_FORCE_RATIO,
    unresolved_damper_force,
    unresolved_road_note,
)

BRIDGE = vbi.Bridge(20.0, 1, 5e9, 6000.0)
START, SPEED, HEIGHT, AT = 20.0, 20.0, 0.01, 25.0  # a 10 mm step 5 m into the span
SPACINGS = (2.5e-3, 1.25e-3, 0.625e-3)  # each half the one before
MODELS = pytest.mark.parametrize(
    "options", [{}, {"model": "modal", "modes": 5}], ids=["one-coordinate", "modal-5"]
)


def step(spacing: float, at: float = AT) -> vbi.Profile:
    return vbi.Profile.step(60.0, spacing, position=at, height=HEIGHT)


def sprung_mass(footprint: float = 0.0) -> vbi.Vehicle:
    return vbi.Vehicle.from_frequency(2e4, 3.0, 0.1, footprint=footprint)


def amplification(crossing: vbi.Crossing) -> float:
    """Largest contact force on the bridge over the weight."""
    on = crossing.on_bridge
    return float(crossing.axle_contact_force[on].max() / crossing.weight)


def runs(vehicle: object, options: dict, roads: list[vbi.Profile]) -> list[vbi.Crossing]:
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.UnresolvedRoadWarning)  # none expected
        return [vbi.simulate(BRIDGE, vehicle, road, SPEED, START, **options) for road in roads]


def assert_converges(values: list[float], tolerance: float) -> None:
    """Successive refinements change the value less and less (or by no more than the time
    steps' rounding, 1e-7), the last by under ``tolerance`` (relative)."""
    changes = np.abs(np.diff(values))
    assert changes[-1] < changes[0] or changes[-1] <= 1e-7 * abs(values[-1]), values
    assert changes[-1] <= tolerance * abs(values[-1]), values


# ---------------------------------------------------------------------------- the point contact
@MODELS
def test_the_sprung_mass_over_a_step_warns_and_its_force_follows_the_sampling(
    options: dict,
) -> None:
    truck = sprung_mass()
    damper = truck.damping * SPEED * HEIGHT / truck.weight  # c v h / W, per 1 / dx
    amps, rests, dafs = [], [], []
    for spacing in SPACINGS:
        with pytest.warns(vbi.UnresolvedRoadWarning, match="footprint") as caught:
            crossing = vbi.simulate(BRIDGE, truck, step(spacing), SPEED, START, **options)
        assert issubclass(caught[0].category, vbi.OutsideValidityWarning)
        assert any("footprint" in n and "sharper than the profile" in n for n in crossing.notes)
        amps.append(amplification(crossing))
        rests.append(amps[-1] - damper / spacing)
        dafs.append(crossing.daf[0])
    # the force doubles with each halving: it is c v h / dx plus what converges
    assert amps[-1] > 3.9 * amps[0] > 100.0
    assert np.ptp(rests) <= 1e-6 * abs(rests[0])
    # the bridge is driven by the force's impulse c h, which does not depend on dx
    assert_converges(dafs, 1e-5)


@MODELS
def test_simulate_many_warns_once_for_the_crossings_whose_force_follows_the_sampling(
    options: dict,
) -> None:
    roads = [step(s) for s in SPACINGS] + [vbi.Profile.flat(60.0, 0.05)]
    with pytest.warns(vbi.UnresolvedRoadWarning, match="3 of 4 crossings.*footprint"):
        batch = vbi.simulate_many(BRIDGE, sprung_mass(), roads, SPEED, START, **options)
    single = [vbi.simulate(BRIDGE, sprung_mass(), roads[-1], SPEED, START, **options)]
    assert batch.contact_force_amplification[-1] == pytest.approx(
        single[0].contact_force.max() / single[0].weight, rel=1e-9
    )


def test_a_step_on_the_approach_does_not_set_the_force_on_the_bridge() -> None:
    """The criterion looks where the contact force is read, under the axles on the bridge:
    a step on the approach only gives the truck a motion that decays (its impulse is
    finite), so its force on the bridge converges."""
    roads = [step(s, at=10.0) for s in SPACINGS]
    values = [amplification(c) for c in runs(sprung_mass(), {}, roads)]
    assert_converges(values, 1e-4)


# ---------------------------------------------------------------------------- what converges
@MODELS
def test_the_sprung_mass_with_a_footprint_converges_and_does_not_warn(options: dict) -> None:
    roads = [step(s) for s in SPACINGS]
    crossings = runs(sprung_mass(0.25), options, roads)
    values = [amplification(c) for c in crossings]
    assert_converges(values, 2e-3)
    assert 1.2 < values[-1] < 3.0
    # the batch path takes the general kernel, whose grid averages the road (not the lanes)
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.UnresolvedRoadWarning)
        batch = vbi.simulate_many(BRIDGE, sprung_mass(0.25), roads, SPEED, START, **options)
    assert batch.contact_force_amplification == pytest.approx(
        [c.contact_force.max() / c.weight for c in crossings], rel=1e-9
    )
    assert batch.daf[:, 0] == pytest.approx([c.daf[0] for c in crossings], rel=1e-9)


def test_the_footprint_rides_the_step_as_the_ramp_it_averages_to() -> None:
    """Independent of the averaging code: a step averaged over L_c is a ramp of h over L_c
    centred on the step (its corners rounded over one sample interval)."""
    spacing = SPACINGS[-1]
    averaged = runs(sprung_mass(0.25), {}, [step(spacing)])[0]
    ramp = vbi.Profile.ramp(60.0, spacing, position=AT + spacing / 2 - 0.125, rise=HEIGHT,
                            run=0.25)  # fmt: skip
    point = runs(sprung_mass(), {}, [ramp])[0]
    assert amplification(averaged) == pytest.approx(amplification(point), rel=2e-3)
    assert averaged.daf[0] == pytest.approx(point.daf[0], rel=1e-5)


@MODELS
def test_a_quarter_car_on_its_tyre_converges_over_the_step_and_does_not_warn(
    options: dict,
) -> None:
    car = VEHICLE_CASES["quarter car"]  # a damped tyre with the default 0.25 m footprint
    assert car.footprint == 0.25 and car.tyre_damping > 0
    values = [amplification(c) for c in runs(car, options, [step(s) for s in SPACINGS])]
    assert_converges(values, 1e-3)
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.UnresolvedRoadWarning)
        vbi.simulate_many(BRIDGE, car, [step(s) for s in SPACINGS], SPEED, START, **options)


def test_an_undamped_point_tyre_converges_and_a_damped_one_warns() -> None:
    """Without a footprint the spring's force is bounded by the step's height (it converges);
    a damper on the point contact is what the sampling sets."""
    undamped = vbi.QuarterCar.from_frequencies(12_000.0, 900.0, 2.5, 11.0, 0.1, 0.0,
                                               footprint=0.0)  # fmt: skip
    values = [amplification(c) for c in runs(undamped, {}, [step(s) for s in SPACINGS])]
    assert_converges(values, 1e-5)
    damped = vbi.QuarterCar.from_frequencies(12_000.0, 900.0, 2.5, 11.0, 0.1, 0.05,
                                             footprint=0.0)  # fmt: skip
    with pytest.warns(vbi.UnresolvedRoadWarning, match="footprint"):
        vbi.simulate(BRIDGE, damped, step(SPACINGS[0]), SPEED, START)


def test_a_smooth_iso_road_converges_and_does_not_warn() -> None:
    """An ISO 8608 class B road (w = 2) made in the test, band-limited to 2.83 cycle/m, the
    same road sampled ever finer; and the library's own generator at 50 mm."""
    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    truck = sprung_mass()
    values = []
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.UnresolvedRoadWarning)
        for spacing in (0.05, 0.025, 0.0125):
            road = rough_profile(140.0, spacing, 64e-6, seed=3)
            values.append(amplification(vbi.simulate(bridge, truck, road, 30.0, 100.0)))
        generated = vbi.Profile.iso8608(140.0, 0.05, c10=64e-6, seed=3)
        vbi.simulate(bridge, truck, generated, 30.0, 100.0)
        vbi.simulate_many(bridge, truck, generated, [20.0, 30.0], 100.0, model="modal", modes=5)
    assert_converges(values, 5e-3)


# ---------------------------------------------------------------------------- the criterion
def test_the_criterion_is_the_damper_force_of_the_one_interval_slope() -> None:
    """A step within one interval of a level road: ``c h / (dx W)`` per unit speed; the note
    appears from the speed at which that reaches 10 % of the weight."""
    truck = sprung_mass()
    spacing = SPACINGS[0]
    road = step(spacing)
    per_speed, axle, k = unresolved_damper_force(truck.system, road, START, BRIDGE.length)
    assert per_speed == pytest.approx(truck.damping * HEIGHT / (spacing * truck.weight), 1e-9)
    assert axle == 0 and road.x[k] == pytest.approx(AT)
    threshold = UNRESOLVED_FORCE_RATIO / per_speed
    assert unresolved_road_note(truck.system, road, 0.99 * threshold, START, 20.0) is None
    note = unresolved_road_note(truck.system, road, 1.01 * threshold, START, 20.0)
    assert "footprint" in note and "station 25 m" in note and "10 mm" in note
    # resolved features: a ramp's corners (kinks: the slope jumps once and stays), a
    # raised-cosine bump 50 samples wide (its slope changes smoothly), a sine sampled 4
    # times a wavelength (jumps as large as the changes outside), the same step on a grade
    ramp = vbi.Profile.ramp(60.0, spacing, position=AT, rise=0.3, run=2.0)
    assert unresolved_damper_force(truck.system, ramp, START, 20.0)[0] < 1e-9  # rounding
    bump = vbi.Profile.bump(60.0, spacing, position=AT, height=HEIGHT, width=50 * spacing)
    assert unresolved_damper_force(truck.system, bump, START, 20.0)[0] == 0.0
    for phase in np.linspace(0.0, np.pi, 7):
        sine = vbi.Profile.harmonic(60.0, spacing, 4 * spacing, HEIGHT, phase=phase)
        assert unresolved_damper_force(truck.system, sine, START, 20.0)[0] < 1e-9, phase
    graded = vbi.Profile(road.x, road.elevation + 0.05 * road.x)
    assert unresolved_damper_force(truck.system, graded, START, 20.0)[0] == pytest.approx(
        per_speed, rel=1e-6
    )


def test_a_truck_without_tyres_names_the_axle_whose_force_follows_the_sampling() -> None:
    axles = [Axle(0.0, 60e3, 1.6e6, 2.5e4), Axle(4.5, 140e3, 3.6e6, 1.2e5)]
    truck = IndependentAxles(axles)  # axle 2 has the larger c / W
    with pytest.warns(vbi.UnresolvedRoadWarning, match="axle 2's contact"):
        crossing = vbi.simulate(BRIDGE, truck, vbi.Profile.step(70.0, 2.5e-3, AT, HEIGHT),
                                SPEED, START)  # fmt: skip
    assert any("axle 2's contact" in n for n in crossing.notes)
