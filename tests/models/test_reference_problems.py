"""Every crossing model on the same reference problems (as scipy's ``test_ivp`` loops methods).

References: the closed-form response to a moving constant force (Fryba), a crawl (DAF 1),
a stiff heavy bridge (DAF tends to 1), the steady-state transmissibility of a base-excited
sprung mass, the free decay of the bridge at its damping ratio, and the batch path equal to
the single-crossing path.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from problems import (
    LB_IN,
    MODEL_CASES,
    VEHICLE_CASES,
    build_case,
    covering,
    flat,
    rough_profile,
)

import vbi_lib as vbi
from vbi_lib.closed_forms import moving_force_peak

MODELS = pytest.mark.parametrize("options", MODEL_CASES.values(), ids=MODEL_CASES.keys())


def test_every_model_is_in_the_cases() -> None:
    assert {o.get("model", "one-coordinate") for o in MODEL_CASES.values()} == set(vbi.MODELS)


@MODELS
@pytest.mark.parametrize("alpha", [0.1, 0.5, 0.617, 1.0, 2.0])
def test_decoupled_flat_road_is_a_moving_constant_force(options: dict, alpha: float) -> None:
    """Decoupled on a flat road the truck is a constant force: the DAF is Fryba's peak.

    A flexible 30 m span (f1 = 0.79 Hz), so that alpha = 2 is reached at 95 m/s, a speed a
    vehicle can have (the DAF of a moving force depends on alpha alone).
    """
    bridge = vbi.Bridge(30.0, 1, 1.65e9, 8000.0, damping_ratio=0.0)
    vehicle = vbi.Vehicle.from_frequency(2e4, 2.0, 0.1)
    speed = alpha * 2 * bridge.first_frequency_hz * bridge.span
    crossing = vbi.simulate(
        bridge, vehicle, flat(bridge, 10.0), speed, 10.0, coupled=False, dt=5e-5, **options
    )
    modes = options.get("modes", 1)
    # the model's DAF divides by its own static deflection: with the odd modes up to N,
    # the static midspan deflection of a midspan load is w0 * sum 1/n^4
    static = sum(1.0 / n**4 for n in range(1, modes + 1, 2))
    expected = float(moving_force_peak(alpha, modes)) / static
    # the closed form is the N-mode series' (the modal model's series_daf; its headline
    # daf adds the static part the series leaves out)
    daf = crossing.series_daf if options.get("model") == "modal" else crossing.daf
    assert daf[0] == pytest.approx(expected, rel=5e-6 if modes == 1 else 2e-4)


@MODELS
def test_crawl_gives_daf_one_on_both_spans(options: dict) -> None:
    bridge = vbi.Bridge(20.0, 2, 8e9, 6000.0)
    vehicle = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    crossing = vbi.simulate(bridge, vehicle, vbi.Profile.flat(45.0, 0.5), 0.05, 4.0, **options)
    np.testing.assert_allclose(crossing.daf, 1.0, atol=3e-3)


@MODELS
def test_very_stiff_heavy_bridge_gives_daf_one(options: dict) -> None:
    """As the bridge stiffens (alpha = v / (2 f1 L) -> 0) the DAF tends to 1."""
    vehicle = vbi.Vehicle.from_frequency(3e4, 3.0, 0.1)
    excess = []
    for ei in (1e13, 1e14, 1e15, 9.8e15):  # f1 from 32 Hz to 998 Hz; 30 times the truck's mass
        stiff = vbi.Bridge(30.0, 1, ei, 3e4)
        crossing = vbi.simulate(stiff, vehicle, vbi.Profile.flat(60.0, 0.05), 25.0, 20.0, **options)
        excess.append(crossing.daf[0] - 1.0)
    assert all(a > b for a, b in zip(excess, excess[1:], strict=False))
    assert 0 <= excess[-1] < 2e-3


@MODELS
def test_sprung_mass_on_rigid_road_follows_transmissibility(options: dict) -> None:
    """Steady state on a harmonic road: |u_v / Y| = |k + i c w| / |k - m w^2 + i c w|."""
    vehicle = vbi.Vehicle.from_frequency(1.5e4, 2.5, 0.15)
    wavelength, amplitude, speed = 8.0, 0.004, 15.0
    road = vbi.Profile.harmonic(400.0, 0.02, wavelength, amplitude)
    bridge = vbi.Bridge(10.0, 1, 1e10, 5000.0)
    crossing = vbi.simulate(bridge, vehicle, road, speed, 380.0, **options)
    w = 2 * np.pi * speed / wavelength
    m, k, c = vehicle.mass, vehicle.stiffness, vehicle.damping
    expected = amplitude * abs((k + 1j * c * w) / (k - m * w**2 + 1j * c * w))
    late = (crossing.position > 250.0) & (crossing.position < 370.0)
    measured = 0.5 * np.ptp(crossing.vehicle_displacement[late])
    assert measured == pytest.approx(expected, rel=2e-3)


@MODELS
def test_free_vibration_decays_at_the_bridge_damping(options: dict) -> None:
    zeta = 0.03
    bridge = vbi.Bridge(25.0, 1, 1e10, 5000.0, damping_ratio=zeta)
    vehicle = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    crossing = vbi.simulate(
        bridge, vehicle, flat(bridge, 15.0), 20.0, 10.0, free_vibration=3.0, dt=2e-4, **options
    )
    after = crossing.position > bridge.length + 10.0 + 1e-9
    z = crossing.midspan_displacement[after, 0]
    tops = [i for i in range(1, z.size - 1) if z[i] > z[i - 1] and z[i] >= z[i + 1]]
    # the many-mode model's higher modes decay fast; measure after a few cycles
    peaks = z[tops[2:]]
    ratio = np.log(peaks[0] / peaks[5]) / 5
    assert ratio == pytest.approx(2 * np.pi * zeta / np.sqrt(1 - zeta**2), rel=3e-3)
    period = np.diff(crossing.time[after][tops[2:]])
    damped_f = bridge.first_frequency_hz * np.sqrt(1 - zeta**2)
    assert 1 / period.mean() == pytest.approx(damped_f, rel=1e-3)


@MODELS
def test_two_span_sign_convention(options: dict) -> None:
    """A load on span 1 pushes span 1 down and lifts span 2."""
    bridge = vbi.Bridge(20.0, 2, 8e9, 6000.0)
    vehicle = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    crossing = vbi.simulate(bridge, vehicle, vbi.Profile.flat(45.0, 0.1), 0.2, 4.0, **options)
    on_span_1 = (crossing.position > 4.0 + 9.0) & (crossing.position < 4.0 + 11.0)
    assert (crossing.midspan_displacement[on_span_1, 0] < 0).all()
    assert (crossing.midspan_displacement[on_span_1, 1] > 0).all()


@MODELS
def test_simulate_many_equals_simulate(options: dict) -> None:
    """The batch path gives the single-crossing path's numbers, one and two spans."""
    two, vehicle, road, speed, start = build_case("100ft-4Hz-two-spans")
    one = vbi.Bridge.from_midspan_stiffness(two.span, 1, 497527 * LB_IN, 3.99)
    bridges, speeds, coupled = (
        [two, one, two],
        [speed, 0.8 * speed, 0.9 * speed],
        [True, True, False],
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        batch = vbi.simulate_many(bridges, vehicle, road, speeds, start, coupled=coupled, **options)
        singles = [
            vbi.simulate(b, vehicle, road, v, start, coupled=c, **options)
            for b, v, c in zip(bridges, speeds, coupled, strict=True)
        ]
    for i, single in enumerate(singles):
        n = single.bridge.n_spans
        np.testing.assert_allclose(batch.daf[i, :n], single.daf, rtol=1e-12)
        assert np.isnan(batch.daf[i, n:]).all()
        assert batch.min_contact_force_ratio[i] == pytest.approx(
            single.min_contact_force_ratio, rel=1e-12
        )
        assert batch.tension_fraction[i] == pytest.approx(single.tension_fraction, abs=1e-12)
        assert batch.dt[i] == single.dt


@MODELS
def test_contact_checks_describe_the_contact_force_history(options: dict) -> None:
    """The smallest contact force and the time in tension are those of the history."""
    bridge, vehicle, road, speed, start = build_case("40ft-10Hz-one-span")
    rough = vbi.Profile(road.x, 8 * road.elevation)  # a road rough enough to lift the wheel
    with pytest.warns(vbi.ContactLossWarning, match="contact lost"):
        crossing = vbi.simulate(bridge, vehicle, rough, speed, start, **options)
    on = crossing.span_of_step[:-1] > 0
    ratio = crossing.contact_force_ratio
    smallest = min(ratio[:-1][on].min(), ratio[-1])  # the run ends at the bridge's end
    assert crossing.min_contact_force_ratio == pytest.approx(smallest, rel=1e-12)
    steps = np.diff(crossing.time)
    expected = steps[on & (ratio[:-1] < 0)].sum() / steps[on].sum()
    assert crossing.tension_fraction == pytest.approx(expected, rel=1e-12)
    assert crossing.lost_contact and any("contact lost" in n for n in crossing.notes)
    assert "CONTACT LOST" in repr(crossing)


@MODELS
def test_flat_roads_never_warn_of_lost_contact(options: dict) -> None:
    bridge, vehicle, road, speed, start = build_case("100ft-4Hz-two-spans")
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.VbiWarning)
        crossing = vbi.simulate(bridge, vehicle, flat(bridge, start), speed, start, **options)
    assert not crossing.lost_contact
    assert crossing.tension_fraction == 0.0
    assert 0.5 < crossing.min_contact_force_ratio < 1.0 < crossing.contact_force_amplification


# ---------------------------------------------------------------------------- every vehicle
VEHICLES = pytest.mark.parametrize("vehicle", VEHICLE_CASES.values(), ids=VEHICLE_CASES.keys())


@MODELS
@VEHICLES
def test_every_vehicle_crawls_to_daf_one(options: dict, vehicle: object) -> None:
    """A crawl is static: the peak is the static deflection of the axle group at its worst.

    On one span the DAF is 1; on two spans the DAF divides each span's peak by the larger
    static deflection of the two, so the larger DAF is 1 (an asymmetric axle group loads
    the two spans' midspans unequally in the many-mode beam).
    """
    one = vbi.Bridge(20.0, 1, 8e9, 6000.0)
    two = vbi.Bridge(20.0, 2, 8e9, 6000.0)
    for bridge in (one, two):
        road = covering(bridge, vehicle, 2.0, 0.5)
        crossing = vbi.simulate(bridge, vehicle, road, 0.2, 2.0, **options)
        assert crossing.daf.max() == pytest.approx(1.0, abs=3e-3)
        assert (crossing.daf < 1.0 + 3e-3).all()


@MODELS
@VEHICLES
def test_every_vehicle_runs_in_batches_as_alone(options: dict, vehicle: object) -> None:
    """simulate_many (the general kernel in parallel) gives simulate's numbers."""
    bridge = vbi.Bridge(15.0, 2, 6e9, 5000.0)
    base = rough_profile(80.0, 0.05, 300e-6, seed=4)
    wheelbase = vbi.vehicles.as_system(vehicle).wheelbase
    road = vbi.Profile(base.x - 15.0, base.elevation)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        batch = vbi.simulate_many(bridge, vehicle, road, [14.0, 18.0], wheelbase, **options)
        singles = [vbi.simulate(bridge, vehicle, road, v, wheelbase, **options) for v in (14, 18)]
    for i, single in enumerate(singles):
        np.testing.assert_allclose(batch.daf[i], single.daf, rtol=1e-12)
        assert batch.min_contact_force_ratio[i] == pytest.approx(
            single.min_contact_force_ratio, rel=1e-12, abs=1e-12
        )
        assert batch.flight_fraction[i] == pytest.approx(single.flight_fraction, abs=1e-12)
        assert batch.contact_force_amplification[i] == pytest.approx(
            single.contact_force_amplification, rel=1e-12
        )


@MODELS
@VEHICLES
def test_flat_roads_never_warn_for_any_vehicle(options: dict, vehicle: object) -> None:
    bridge = vbi.Bridge(25.0, 2, 2e10, 8000.0)
    road = covering(bridge, vehicle, 10.0, 0.1)
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.VbiWarning)
        crossing = vbi.simulate(bridge, vehicle, road, 25.0, 10.0, **options)
    assert not crossing.lost_contact and crossing.flight_fraction == 0.0
    assert crossing.tension_fraction == 0.0 and not crossing.contact_events.size
    assert 0.0 < crossing.min_contact_force_ratio < 1.0 < crossing.contact_force_amplification


@MODELS
@pytest.mark.parametrize("name", ["40ft-10Hz-one-span", "100ft-4Hz-two-spans"])
@pytest.mark.parametrize("roughness", [1.0, 8.0])
def test_the_general_kernel_reproduces_the_sprung_mass_kernel(
    options: dict, name: str, roughness: float
) -> None:
    """The study's sprung mass runs on its compiled kernel; as a VehicleSystem (one dof, one
    bilateral contact) it runs on the general kernel of every vehicle: the same crossing,
    to round-off, on the study's cases (the rough one loses contact)."""
    bridge, vehicle, road, speed, start = build_case(name)
    road = vbi.Profile(road.x, roughness * road.elevation)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        fast = vbi.simulate(bridge, vehicle, road, speed, start, free_vibration=0.3, **options)
        general = vbi.simulate(bridge, vehicle.system, road, speed, start, free_vibration=0.3,
                               **options)  # fmt: skip
    assert general.time.size == fast.time.size
    for field in ("midspan_displacement", "vehicle_displacement", "vehicle_velocity",
                  "contact_force"):  # fmt: skip
        a, b = getattr(general, field), getattr(fast, field)
        assert np.abs(a - b).max() <= 1e-12 * np.abs(b).max(), field
    np.testing.assert_allclose(general.daf, fast.daf, rtol=1e-12)
    assert general.min_contact_force_ratio == pytest.approx(fast.min_contact_force_ratio, 1e-12)
    assert general.tension_fraction == pytest.approx(fast.tension_fraction, abs=1e-12)
    assert general.contact_force_amplification == pytest.approx(
        fast.contact_force_amplification, rel=1e-12
    )
