"""Vehicles with tyres and several axles on both models, against independent references.

References: the study's sprung mass as the limit of a stiff, light-wheeled quarter car; the
ballistic flight of a mass and of a whole quarter car off a ramp; the convergence of the
located take-off time; step and bump inputs that converge as the sampling is refined; the
steady-state transmissibility of a quarter car (a 2x2 complex solve written here) with
the footprint's moving-average attenuation; constant forces crossing a simple span (the
modal series of several forces with time offsets, written in ``problems.py``); and the
superposition of decoupled bilateral axles.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from problems import MODEL_CASES, build_case, covering, flat, moving_forces_midspan

import vbi_lib as vbi
from vbi_lib.units import g
from vbi_lib.vehicles import Axle, Convoy, IndependentAxles, QuarterCar, VehicleSystem

MODELS = pytest.mark.parametrize("options", MODEL_CASES.values(), ids=MODEL_CASES.keys())
MODAL = {"model": "modal", "modes": 5}


def stiff_wheel(truck: vbi.Vehicle, ratio: float) -> VehicleSystem:
    """The sprung mass on a wheel ``ratio`` times as heavy and a tyre 1/ratio as stiff.

    A quarter car's system built directly: such a wheel is far outside what QuarterCar
    accepts (its mass and axle hop are physically meaningless), but as a limiting case of
    the general vehicle system it must reproduce the sprung mass.
    """
    m, mu = truck.mass, truck.mass * ratio
    k, c = truck.stiffness, truck.damping
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.OutsideValidityWarning)  # its axle hop frequency
        return VehicleSystem(mass=np.diag([m, mu]), stiffness=[[k, -k], [-k, k]],
                             damping=[[c, -c], [-c, c]], contact=[[0.0, 1.0]], offsets=[0.0],
                             static_loads=[(m + mu) * g], contact_stiffness=[k / ratio],
                             contact_damping=[0.0], unilateral=[True], footprint=[0.0],
                             name="stiff wheel")  # fmt: skip


# ---------------------------------------------------------------------------- the study's limit
@pytest.mark.parametrize("modes", [1, 5])
def test_stiff_tyre_light_wheel_is_the_sprung_mass_on_a_flat_road(modes: int) -> None:
    """Coupled crossing of the two-span case: the tyre never unloads, so nothing differs.

    The wheel (1e-8 of the body, tyre 1e8 times the suspension) is far too stiff for an
    explicit scheme; the average-acceleration model integrates it at the sprung mass's step.
    """
    bridge, truck, _, speed, start = build_case("100ft-4Hz-two-spans")
    road = flat(bridge, start)
    options = {"model": "modal", "modes": modes}
    dt = vbi.simulate(bridge, truck, road, speed, start, **options).dt / 4
    ref = vbi.simulate(bridge, truck, road, speed, start, dt=dt, **options)
    car = vbi.simulate(bridge, stiff_wheel(truck, 1e-8), road, speed, start, dt=dt, **options)
    assert car.flight_fraction == 0.0 and ref.min_contact_force_ratio > 0
    np.testing.assert_allclose(car.daf, ref.daf, rtol=1e-6)
    np.testing.assert_allclose(car.contact_force, ref.contact_force, atol=1e-6 * truck.weight)
    scale = bridge.static_deflection(truck.weight)
    np.testing.assert_allclose(
        car.vehicle_displacement, ref.vehicle_displacement, atol=1e-6 * scale
    )


def test_stiff_tyre_light_wheel_is_the_sprung_mass_on_a_rough_road() -> None:
    """A rough road on which the study's contact force stays compressive (min 0.5 W).

    Every profile sample jumps the road's slope; the unresolved wheel rings at each jump in
    the average-acceleration scheme (its tyre force is not comparable node by node), but
    the body and the bridge's modes equal the sprung mass's.
    """
    bridge, truck, road, speed, start = build_case("100ft-4Hz-two-spans")
    road = vbi.Profile(road.x, 0.2 * road.elevation)
    dt = vbi.simulate(bridge, truck, road, speed, start, **MODAL).dt / 4
    ref = vbi.simulate(bridge, truck, road, speed, start, dt=dt, **MODAL)
    car = vbi.simulate(bridge, stiff_wheel(truck, 1e-8), road, speed, start, dt=dt, **MODAL)
    assert ref.min_contact_force_ratio > 0.4 and car.flight_fraction == 0.0
    np.testing.assert_allclose(car.series_daf, ref.series_daf, rtol=1e-6)
    # the mode-acceleration headline adds R(t) times the statics the series leaves out, and
    # R is the ringing tyre force: the DAFs agree to the ringing's share of that part
    np.testing.assert_allclose(car.daf, ref.daf, rtol=1e-3)
    scale = np.abs(ref.vehicle_displacement).max()
    np.testing.assert_allclose(
        car.vehicle_displacement, ref.vehicle_displacement, atol=1e-6 * scale
    )


# ---------------------------------------------------------------------------- flight
def ramp_road(slope: float) -> vbi.Profile:
    """Level, a 5 m parabolic sag into a straight ramp, a sharp crest at 15 m, level again."""
    x = np.arange(0.0, 60.0 + 1e-9, 0.01)
    y = np.where(x < 5.0, 0.0, slope * (x - 5.0) ** 2 / 10.0)
    y = np.where(x < 10.0, y, 2.5 * slope + slope * (x - 10.0))
    return vbi.Profile(x, np.where(x < 15.0, y, 7.5 * slope))


def tyred_mass(k: float = 1e8, zeta: float = 0.2, m: float = 1000.0) -> VehicleSystem:
    """A rigid mass on a tyre (unilateral Kelvin-Voigt contact), no footprint."""
    c = 2 * zeta * math.sqrt(k * m)
    return VehicleSystem(mass=[[m]], stiffness=[[0.0]], damping=[[0.0]], contact=[[1.0]],
                         offsets=[0.0], static_loads=[m * g], contact_stiffness=[k],
                         contact_damping=[c], unilateral=[True], footprint=[0.0])  # fmt: skip


@MODELS
def test_a_mass_flies_off_a_ramp_ballistically(options: dict) -> None:
    """Off the crest at v0 = v s the mass falls freely; the tyre touches again when
    k (v0 t - g t^2 / 2) + c (v0 - g t) = W (its spring and damper would push).

    For k -> infinity that is the textbook 2 v0 / g; the compliance shortens it by 0.3 %.
    """
    mass = tyred_mass()
    speed, slope = 20.0, 0.1
    run = vbi.simulate(vbi.Bridge(10.0, 1, 1e10, 5e3), mass, ramp_road(slope), speed, 45.0,
                       **options)  # fmt: skip
    first = run.flights().iloc[0]  # (it bounces on after landing: the tyre is elastic)
    v0 = speed * slope
    k, c, w = mass.contact_stiffness[0], mass.contact_damping[0], mass.weight
    landing = max(np.roots([-k * g / 2, k * v0 - c * g, c * v0 - w]).real)
    assert first["axle"] == 1
    assert first["take-off station [m]"] == pytest.approx(15.0, abs=1e-9)
    assert first["duration [s]"] == pytest.approx(landing, rel=2e-4)
    assert landing == pytest.approx(2 * v0 / g, rel=5e-3)
    assert first["landing station [m]"] == pytest.approx(15.0 + speed * landing, rel=2e-4)
    # in flight the mass is a parabola with curvature -g
    air = (run.time > first["take-off [s]"] + 0.01) & (run.time < first["landing [s]"] - 0.01)
    fit = np.polyfit(run.time[air], run.vehicle_displacement[air], 2)
    assert fit[0] == pytest.approx(-g / 2, rel=1e-9)


@MODELS
def test_a_flight_on_the_bridge_is_noted_not_warned(options: dict) -> None:
    """A tyre off the road is modelled physics: a note and flight_fraction, no warning.

    The fraction is the time with the wheel in the air while on the bridge, from the
    located take-offs and landings.
    """
    car = QuarterCar.from_frequencies(4000.0, 500.0, 1.5, 12.0, 0.1, 0.02)
    road = vbi.Profile.step(60.0, 0.01, position=15.0, height=0.06)
    bridge = vbi.Bridge(30.0, 1, 1e10, 5e3)
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.VbiWarning)
        run = vbi.simulate(bridge, car, road, 20.0, 10.0, **options)
    flights = run.flights()
    assert len(flights) >= 1 and not run.outside_validity and run.lost_contact
    assert run.min_contact_force_ratio == 0.0 and run.tension_fraction == 0.0
    on = flights[flights["landing station [m]"] < 40.0]
    airborne = on["duration [s]"].sum() / (bridge.length / run.speed)
    assert run.flight_fraction == pytest.approx(airborne, rel=1e-9)
    assert any("left the road" in n for n in run.notes) and "off the road" in repr(run)
    assert (run.axle_contact_force >= 0).all()


@MODELS
def test_a_quarter_car_in_flight_keeps_its_centre_of_mass_on_a_parabola(options: dict) -> None:
    """Internal suspension forces cancel: the centre of mass falls at g while the wheel flies."""
    car = QuarterCar(1000.0, 100.0, 4e4, 2e3, 1e7, 1e3, footprint=0.0)
    run = vbi.simulate(vbi.Bridge(10.0, 1, 1e10, 5e3), car, ramp_road(0.1), 20.0, 45.0,
                       **options)  # fmt: skip
    first = run.flights().iloc[0]
    air = (run.time > first["take-off [s]"] + 1e-3) & (run.time < first["landing [s]"] - 1e-3)
    assert air.sum() > 50
    d = car.system.rigid_translation
    mass = car.system.mass
    height = run.dof_displacement[air] @ (mass @ d) / (d @ mass @ d)
    fit = np.polyfit(run.time[air], height, 2)
    assert fit[0] == pytest.approx(-g / 2, rel=1e-6)


@MODELS
def test_take_off_time_converges_as_the_step_is_halved(options: dict) -> None:
    """A quarter car launched by a bump: the located take-off converges at the scheme's order.

    A coarse profile (0.1 m samples) so that the step, not the sampling, sets the grid; the
    steps split each sample interval into 8, 16, 32 and 64 (RK4 reaches its asymptotic
    order from there).
    """
    car = QuarterCar.from_frequencies(3000.0, 400.0, 1.5, 10.0, 0.1, 0.0, footprint=0.0)
    road = vbi.Profile.bump(40.0, 0.1, position=10.0, height=0.08, width=2.0)
    times = []
    for dt in 0.1 / 15.0 / np.array([8.0, 16.0, 32.0, 64.0]):
        run = vbi.simulate(vbi.Bridge(10.0, 1, 1e10, 5e3), car, road, 15.0, 25.0, dt=dt,
                           **options)  # fmt: skip
        times.append(run.flights()["take-off [s]"].iloc[0])
    changes = np.abs(np.diff(times))
    order = 4 if "model" not in options else 2  # RK4, average acceleration
    assert changes[2] < changes[1] < changes[0]
    assert np.log2(changes[1] / changes[2]) > order - 0.7
    assert changes[2] < 1e-5  # seconds


# ---------------------------------------------------------------------------- footprint
@MODELS
@pytest.mark.parametrize("shape", ["step", "bump"])
def test_step_and_bump_converge_as_the_sampling_is_refined(options: dict, shape: str) -> None:
    """Issue 11: a 10 mm step (or a 20 mm x 0.3 m bump) sampled at 2.5 and 0.5 mm gives
    the same peak contact force and DAF within 1 % once the tyre averages over its
    footprint; the study's sprung mass, without one, does not converge (its damper follows
    the sampled slope)."""
    bridge = vbi.Bridge(20.0, 1, 3e9, 4000.0)
    car = QuarterCar.from_frequencies(15_000.0, 1_100.0, 2.0, 12.0, 0.1, 0.02)
    sprung = vbi.Vehicle.from_frequency(15_000.0, 2.0, 0.1)

    def road(spacing: float) -> vbi.Profile:
        if shape == "step":
            return vbi.Profile.step(35.0, spacing, position=12.0, height=0.01)
        return vbi.Profile.bump(35.0, spacing, position=12.0, height=0.02, width=0.3)

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        runs = {
            (name, s): vbi.simulate(bridge, v, road(s), 20.0, 8.0, **options)
            for name, v in (("tyre", car), ("sprung", sprung))
            for s in (2.5e-3, 0.5e-3)
        }
    coarse, fine = runs[("tyre", 2.5e-3)], runs[("tyre", 0.5e-3)]
    assert coarse.contact_force_amplification == pytest.approx(
        fine.contact_force_amplification, rel=1e-2
    )
    np.testing.assert_allclose(coarse.daf, fine.daf, rtol=1e-2)
    if shape == "step":
        ratio = runs[("sprung", 0.5e-3)].contact_force_amplification
        assert ratio > 3 * runs[("sprung", 2.5e-3)].contact_force_amplification


@MODELS
@pytest.mark.parametrize("footprint", [0.0, 0.25])
def test_quarter_car_transmissibility_on_a_harmonic_road(options: dict, footprint: float) -> None:
    """Steady state of the base-excited two-mass system, solved here as a 2x2 complex system.

    The tyre sees the harmonic road through a moving average of length L_c, which scales
    its amplitude by sin(pi L_c / lambda) / (pi L_c / lambda).
    """
    car = QuarterCar.from_frequencies(3000.0, 300.0, 1.8, 11.0, 0.2, 0.03, footprint=footprint)
    wavelength, amplitude, speed = 4.0, 0.003, 10.0
    road = vbi.Profile.harmonic(300.0, 0.01, wavelength, amplitude)
    run = vbi.simulate(vbi.Bridge(10.0, 1, 1e10, 5000.0), car, road, speed, 285.0, **options)
    w = 2 * np.pi * speed / wavelength
    s = car.system
    dynamic = s.road_stiffness - w**2 * s.mass + 1j * w * (s.damping + s.contact.T @ (
        s.contact_damping[:, None] * s.contact))  # fmt: skip
    force = s.contact[0] * (s.contact_stiffness[0] + 1j * w * s.contact_damping[0])
    seen = 1.0 if footprint == 0 else np.sinc(footprint / wavelength)
    expected = np.abs(np.linalg.solve(dynamic, force)) * amplitude * seen
    late = (run.position > 200.0) & (run.position < 280.0)
    measured = 0.5 * np.ptp(run.dof_displacement[late], axis=0)
    np.testing.assert_allclose(measured, expected, rtol=3e-3)


# ---------------------------------------------------------------------------- several axles
def fryba_case(vehicle: object, options: dict) -> tuple[np.ndarray, np.ndarray]:
    """Simulated and series midspan deflection of a decoupled truck on a flat road."""
    bridge = vbi.Bridge(25.0, 1, 1.5e10, 9000.0, damping_ratio=0.0)
    system = vbi.vehicles.as_system(vehicle)
    speed, approach = 22.0, 5.0
    road = covering(bridge, vehicle, approach, 0.05)
    run = vbi.simulate(bridge, vehicle, road, speed, approach, coupled=False, dt=2e-4, **options)
    # axle a reaches the bridge when the first axle is offset_a past its start
    entry = (approach + system.offsets - run.position[0]) / speed
    modes = options.get("modes", 1)
    expected = moving_forces_midspan(bridge, list(system.static_loads), list(entry), speed,
                                     modes, run.time)  # fmt: skip
    # the closed form is the N-mode series (the modal model's headline adds the statics
    # the series leaves out)
    simulated = run.series_midspan_displacement if "modes" in options else run.midspan_displacement
    return simulated[:, 0], expected


@MODELS
@pytest.mark.parametrize("kind", ["independent axles", "hs20 without tyres", "convoy"])
def test_several_constant_forces_follow_the_modal_series(options: dict, kind: str) -> None:
    """Decoupled bilateral axles on a flat road press with their static loads: the bridge
    sees constant forces entering at their own times (Fryba's series superposed, 0.5 %).

    The one-coordinate model keeps the first term of the series, the modal model N terms.
    """
    vehicles = {
        "independent axles": IndependentAxles(
            [Axle(0.0, 50e3, 1e6, 1e4), Axle(3.0, 120e3, 2e6, 2e4), Axle(4.3, 120e3, 2e6, 2e4)]
        ),
        "hs20 without tyres": vbi.vehicles.hs20(rear_spacing=9.0, tyres=False),
        "convoy": Convoy([vbi.Vehicle(8e3, 3e5, 0.0), vbi.Vehicle(20e3, 8e5, 0.0)], [11.0]),
    }
    simulated, expected = fryba_case(vehicles[kind], options)
    scale = np.abs(expected).max()
    assert np.abs(simulated - expected).max() < 5e-3 * scale


@MODELS
@pytest.mark.parametrize("vehicle", ["axles", "convoy"])
def test_decoupled_bilateral_axles_superpose(options: dict, vehicle: str) -> None:
    """Decoupled and bilateral, a truck's bridge response is the sum of its axles' alone.

    Each axle alone is a sprung mass starting where it starts in the truck; axle spacings,
    supports and samples fall on one 0.05 m grid, so every run steps through the same nodes.
    """
    bridge = vbi.Bridge(20.0, 2, 5e9, 5000.0)
    masses = [vbi.Vehicle.from_frequency(6e3, 3.0, 0.1), vbi.Vehicle.from_frequency(14e3, 2.2, 0.1)]
    if vehicle == "axles":
        truck = IndependentAxles(
            [Axle(0.0, masses[0].weight, masses[0].stiffness, masses[0].damping),
             Axle(4.0, masses[1].weight, masses[1].stiffness, masses[1].damping)]
        )  # fmt: skip
    else:
        truck = Convoy(masses, [4.0])
    offsets = vbi.vehicles.as_system(truck).offsets
    road = vbi.Profile.iso8608(80.0, 0.05, c10=64e-6, seed=2, start=-4.0)
    speed, start = 18.0, 6.0
    whole = vbi.simulate(bridge, truck, road, speed, start, coupled=False, **options)
    total = np.zeros_like(whole.time)
    for mass, offset in zip(masses, offsets, strict=True):
        own = road.segment(road.start + 4.0 - offset, road.end)
        alone = vbi.simulate(bridge, mass, own, speed, start, coupled=False, dt=whole.dt,
                             free_vibration=(4.0 - offset) / speed, **options)  # fmt: skip
        assert alone.time.size == whole.time.size
        total += alone.midspan_displacement[:, 0]
    scale = np.abs(total).max()
    np.testing.assert_allclose(whole.midspan_displacement[:, 0], total, atol=1e-9 * scale)
