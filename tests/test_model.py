"""The two-degree-of-freedom model against the study's tables and independent physics.

References: the study's printed Tables 2.13.1, 2.13.8-2.13.10, 2.15.1, 2.15.3, 2.15.4; the
closed-form one-mode response to a moving constant force (Fryba); the steady-state
transmissibility of a base-excited sprung mass; free decay of a damped oscillator; a
tight-tolerance solve_ivp solution of the same equations.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.simulation import reference_daf, study_explicit_euler_daf

LB_IN = u.lbf / u.inch
LB_IN2 = u.lbf * u.inch**2

# Table 2.13.8: span ft, N, f1 Hz, K_mid lb/in -> EI lb in^2, mass per span slinch
TABLE_2_13_8 = [
    (40, 1, 9.95, 587723, 1.354e12, 305.16),
    (40, 1, 9.95, 524293, 1.208e12, 272.22),
    (40, 2, 9.98, 721006, 8.186e11, 183.37),
    (40, 2, 9.98, 661235, 7.507e11, 168.16),
    (100, 1, 3.99, 497527, 1.791e13, 1606.46),
    (100, 1, 3.99, 639676, 2.303e13, 2065.44),
    (100, 1, 3.99, 667262, 2.402e13, 2154.51),
    (100, 2, 3.99, 668815, 1.186e13, 1064.14),
    (100, 2, 3.99, 822043, 1.458e13, 1307.94),
    (100, 2, 3.99, 837570, 1.486e13, 1332.65),
    (140, 1, 2.08, 222278, 2.196e13, 2641.00),
    (140, 2, 2.08, 246992, 1.202e13, 1446.09),
]


@pytest.mark.parametrize("row", TABLE_2_13_8, ids=lambda r: f"{r[0]}ft-{r[1]}span-{r[3]}")
def test_table_2_13_8_beams_from_midspan_stiffness(row: tuple) -> None:
    span_ft, n_spans, f1, k_mid, ei, mass = row
    bridge = vbi.Bridge.from_midspan_stiffness(span_ft * u.ft, n_spans, k_mid * LB_IN, f1)
    assert f"{bridge.EI / LB_IN2:.3e}" == f"{ei:.3e}"
    assert round(bridge.mass_per_span / u.slinch, 2) == pytest.approx(mass, abs=0.006)
    assert bridge.first_frequency_hz == pytest.approx(f1, rel=1e-12)


@pytest.mark.parametrize(
    ("f_damped", "k", "c"),
    [(10.5, 8.7929e5, 2652.23), (4.5, 1.6150e5, 1136.67), (2.5, 4.9846e4, 631.48)],
)
def test_table_2_13_9_vehicles_from_damped_frequency(f_damped: float, k: float, c: float) -> None:
    vehicle = vbi.Vehicle.from_frequency(200 * u.slinch, f_damped, 0.10, damped=True)
    assert f"{vehicle.stiffness / LB_IN:.4e}" == f"{k:.4e}"
    assert round(vehicle.damping / LB_IN, 2) == pytest.approx(c, abs=0.006)
    assert vehicle.damped_frequency_hz == pytest.approx(f_damped)
    assert vehicle.damping_ratio == pytest.approx(0.10)


def test_table_2_13_10_vehicle_from_undamped_frequency() -> None:
    vehicle = vbi.Vehicle.from_frequency(200 * u.slinch, 2.8, 0.20)
    assert round(vehicle.stiffness / LB_IN, 1) == pytest.approx(61902.2, abs=0.06)
    assert round(vehicle.damping / LB_IN, 2) == pytest.approx(1407.43, abs=0.006)
    assert vehicle.frequency_hz == pytest.approx(2.8)


@pytest.mark.parametrize(("f1", "ei"), [(2, 5.603e12), (3, 1.261e13), (4, 2.241e13), (5, 3.502e13)])
def test_table_2_15_3_bridges(f1: float, ei: float) -> None:
    bridge = vbi.Bridge.from_frequency(100 * u.ft, 1, 2000 * u.slinch / (100 * u.ft), f1)
    assert f"{bridge.EI / LB_IN2:.3e}" == f"{ei:.3e}"


@pytest.mark.parametrize(("f", "k"), [(2, 31582.7), (3, 71061.2), (4, 126330.9), (5, 197392.1)])
def test_table_2_15_4_trucks(f: float, k: float) -> None:
    vehicle = vbi.Vehicle.from_frequency(200 * u.slinch, f, 0.10)
    assert round(vehicle.stiffness / LB_IN, 1) == pytest.approx(k, abs=0.06)


def test_table_2_13_1_frequencies() -> None:
    bridge = vbi.Bridge(100 * u.ft, 1, 7.5e12 * LB_IN2, 4.6 * u.kip / u.ft / u.g)
    vehicle = vbi.Vehicle(100 * u.slinch, 63165.5 * LB_IN, 0.0)
    assert round(bridge.first_frequency_hz, 2) == 3.00
    assert round(vehicle.frequency_hz, 2) == 4.00


def test_table_2_15_1_beam_is_the_140_ft_bridge() -> None:
    bridge = vbi.Bridge(140 * u.ft, 1, 2.196e13 * LB_IN2, 7283.3 * u.lbf / u.ft / u.g)
    assert round(bridge.first_frequency_hz, 2) == 2.08
    assert bridge.mass_per_span / u.slinch == pytest.approx(2641.0, rel=2e-4)


def test_shape_function_errors_39_65() -> None:
    assert round(vbi.shape_function_error(1), 4) == 0.0145
    assert round(vbi.shape_function_error(2), 3) == 0.314
    bridge = vbi.Bridge(25.0, 2, 1e10, 5000.0)
    ratio = bridge.static_deflection(1e5) / bridge.exact_static_deflection(1e5)
    assert ratio == pytest.approx(1 - vbi.shape_function_error(2))


def test_generalised_properties_36_37_62_63() -> None:
    L, ei, mbar = 20.0, 3e9, 4000.0
    for n in (1, 2):
        b = vbi.Bridge(L, n, ei, mbar, 0.02)
        assert b.generalized_mass == pytest.approx(n * mbar * L / 2)
        assert b.generalized_stiffness == pytest.approx(n * math.pi**4 * ei / (2 * L**3))
        assert b.circular_frequency == pytest.approx(math.pi**2 * math.sqrt(ei / (mbar * L**4)))
        assert b.generalized_damping == pytest.approx(
            2 * 0.02 * b.circular_frequency * n * mbar * L / 2
        )
    one, two = vbi.Bridge(L, 1, ei, mbar), vbi.Bridge(L, 2, ei, mbar)
    assert one.static_deflection(1.0) == pytest.approx(2 * L**3 / (math.pi**4 * ei))
    assert two.static_deflection(1.0) == pytest.approx(L**3 / (math.pi**4 * ei))


# ----------------------------------------------------------------------------- physics
def fryba_one_mode_peak(alpha: float) -> float:
    """Peak of (sin(w t) - alpha sin(w1 t)) / (1 - alpha^2) while the force is on the span."""
    t = np.linspace(0.0, 1.0, 400_001)  # fraction of the crossing time
    wt = np.pi * t  # omega t, omega = pi v / L
    if abs(alpha - 1.0) < 1e-12:
        return float(np.max((np.sin(wt) - wt * np.cos(wt)) / 2))
    return float(np.max((np.sin(wt) - alpha * np.sin(wt / alpha)) / (1 - alpha**2)))


@pytest.mark.parametrize("alpha", [0.1, 0.25, 0.5, 0.617, 0.8, 1.0, 2.0])
def test_decoupled_flat_profile_is_moving_constant_force(alpha: float) -> None:
    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0, damping_ratio=0.0)
    vehicle = vbi.Vehicle.from_frequency(2e4, 2.0, 0.1)
    speed = alpha * 2 * bridge.first_frequency_hz * bridge.span
    road = vbi.Profile.flat(50.0, 0.05)
    crossing = vbi.simulate(bridge, vehicle, road, speed, 10.0, coupled=False)
    assert crossing.daf[0] == pytest.approx(fryba_one_mode_peak(alpha), rel=2e-6)


def test_moving_force_peak_1_7685_at_alpha_0_617() -> None:
    assert fryba_one_mode_peak(0.617) == pytest.approx(1.7685, abs=5e-5)


def test_crawl_gives_daf_one_on_both_spans() -> None:
    bridge = vbi.Bridge(20.0, 2, 8e9, 6000.0)
    vehicle = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    crossing = vbi.simulate(bridge, vehicle, vbi.Profile.flat(45.0, 0.5), 0.05, 4.0)
    np.testing.assert_allclose(crossing.daf, 1.0, atol=2e-3)


def test_very_stiff_heavy_bridge_gives_daf_one() -> None:
    """As the bridge stiffens (alpha = v / (2 f1 L) -> 0) the DAF tends to 1."""
    vehicle = vbi.Vehicle.from_frequency(3e4, 3.0, 0.1)
    excess = []
    for ei in (1e14, 1e15, 1e16, 1e17):  # f1 from 17 Hz to 550 Hz; 30 times the truck's mass
        stiff = vbi.Bridge(30.0, 1, ei, 3e4)
        crossing = vbi.simulate(stiff, vehicle, vbi.Profile.flat(60.0, 0.05), 25.0, 20.0)
        excess.append(crossing.daf[0] - 1.0)
    assert all(a > b for a, b in zip(excess, excess[1:], strict=False))
    assert 0 <= excess[-1] < 2e-3


def test_sprung_mass_on_rigid_road_follows_transmissibility() -> None:
    """Steady state on a harmonic road: |u_v / Y| = |k + i c w| / |k - m w^2 + i c w|."""
    vehicle = vbi.Vehicle.from_frequency(1.5e4, 2.5, 0.15)
    wavelength, amplitude, speed = 8.0, 0.004, 15.0
    road = vbi.Profile.harmonic(400.0, 0.02, wavelength, amplitude)
    bridge = vbi.Bridge(10.0, 1, 1e10, 5000.0)
    crossing = vbi.simulate(bridge, vehicle, road, speed, 380.0)
    w = 2 * np.pi * speed / wavelength
    m, k, c = vehicle.mass, vehicle.stiffness, vehicle.damping
    expected = amplitude * abs((k + 1j * c * w) / (k - m * w**2 + 1j * c * w))
    late = (crossing.position > 250.0) & (crossing.position < 370.0)
    measured = 0.5 * np.ptp(crossing.vehicle_displacement[late])
    assert measured == pytest.approx(expected, rel=2e-3)


def test_free_vibration_decays_at_the_bridge_damping() -> None:
    zeta = 0.03
    bridge = vbi.Bridge(25.0, 1, 1e10, 5000.0, damping_ratio=zeta)
    vehicle = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    crossing = vbi.simulate(
        bridge, vehicle, vbi.Profile.flat(40.0, 0.05), 20.0, 10.0, free_vibration=3.0
    )
    after = crossing.position > bridge.length + 10.0 + 1e-9
    z = crossing.bridge_coordinate[after]
    peaks = [z[i] for i in range(1, z.size - 1) if z[i] > z[i - 1] and z[i] >= z[i + 1]]
    ratio = np.log(peaks[0] / peaks[5]) / 5
    assert ratio == pytest.approx(2 * np.pi * zeta / np.sqrt(1 - zeta**2), rel=2e-3)
    period = np.diff(
        crossing.time[after][
            [i for i in range(1, z.size - 1) if z[i] > z[i - 1] and z[i] >= z[i + 1]]
        ]
    )
    damped_f = bridge.first_frequency_hz * np.sqrt(1 - zeta**2)
    assert 1 / period.mean() == pytest.approx(damped_f, rel=1e-3)


# ----------------------------------------------------------------------------- numerics
def rough_profile(length: float, spacing: float, c10: float, seed: int) -> vbi.Profile:
    """An ISO-8608-like road (w = 2) made here, independent of the library's generator."""
    rng = np.random.default_rng(seed)
    x = np.arange(0.0, length + 1e-9, spacing)
    n = np.arange(0.011, 2.83, 0.5 / length)
    amplitude = np.sqrt(2 * c10 * (n / 0.1) ** -2.0 * (n[1] - n[0]))
    phase = rng.uniform(0, 2 * np.pi, n.size)
    elevation = (amplitude[:, None] * np.cos(2 * np.pi * n[:, None] * x + phase[:, None])).sum(0)
    return vbi.Profile(x, elevation - elevation[0])


CASES = {
    "40ft-10Hz-one-span": (40, 1, 587723, 9.95, 10.5),
    "100ft-4Hz-two-spans": (100, 2, 668815, 3.99, 4.5),
}


def build_case(name: str) -> tuple[vbi.Bridge, vbi.Vehicle, vbi.Profile, float, float]:
    span_ft, n_spans, k_mid, f1, fv = CASES[name]
    bridge = vbi.Bridge.from_midspan_stiffness(span_ft * u.ft, n_spans, k_mid * LB_IN, f1)
    vehicle = vbi.Vehicle.from_frequency(200 * u.slinch, fv, 0.10, damped=True)
    approach = 20.0
    road = rough_profile(approach + bridge.length + 1.0, 1 * u.inch, 300e-6, seed=n_spans)
    return bridge, vehicle, road, 720 * u.inch, approach


@pytest.mark.parametrize("name", CASES)
@pytest.mark.parametrize("convective", [True, False])
def test_agrees_with_tight_solve_ivp_on_rough_profile(name: str, convective: bool) -> None:
    bridge, vehicle, road, speed, start = build_case(name)
    crossing = vbi.simulate(bridge, vehicle, road, speed, start, convective=convective)
    reference = reference_daf(bridge, vehicle, road, speed, start, convective=convective, rtol=1e-9)
    np.testing.assert_allclose(crossing.daf, reference, rtol=2e-3)


@pytest.mark.parametrize("name", CASES)
def test_default_step_is_converged(name: str) -> None:
    bridge, vehicle, road, speed, start = build_case(name)
    coarse = vbi.simulate(bridge, vehicle, road, speed, start)
    fine = vbi.simulate(bridge, vehicle, road, speed, start, dt=coarse.dt / 2)
    np.testing.assert_allclose(fine.daf, coarse.daf, rtol=1e-3)
    assert "dt picked" in coarse.notes[0]


def test_rk4_converges_at_fourth_order() -> None:
    bridge, vehicle, road, speed, start = build_case("40ft-10Hz-one-span")
    road = road.resampled(0.25)  # coarse profile so the step is set by dt, not the samples
    exact = vbi.simulate(bridge, vehicle, road, speed, start, dt=2e-5).bridge_coordinate[-1]
    runs = [vbi.simulate(bridge, vehicle, road, speed, start, dt=dt) for dt in (4e-3, 2e-3)]
    errors = [abs(run.bridge_coordinate[-1] - exact) for run in runs]
    order = np.log(errors[0] / errors[1]) / np.log(runs[0].dt / runs[1].dt)
    assert 3.6 < order < 4.4


def test_forward_euler_inflates_daf_on_a_stiff_span() -> None:
    bridge, vehicle, road, speed, start = build_case("40ft-10Hz-one-span")
    euler = study_explicit_euler_daf(bridge, vehicle, road, speed, start, convective=False)
    accurate = reference_daf(bridge, vehicle, road, speed, start, convective=False, rtol=1e-8)
    assert euler[0] > 1.05 * accurate[0]


def test_simulate_many_matches_simulate() -> None:
    bridge, vehicle, road, speed, start = build_case("100ft-4Hz-two-spans")
    one = vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * LB_IN, 3.99)
    batch = vbi.simulate_many([bridge, one], vehicle, road, [speed, 0.8 * speed], start)
    first = vbi.simulate(bridge, vehicle, road, speed, start)
    second = vbi.simulate(one, vehicle, road, 0.8 * speed, start)
    np.testing.assert_allclose(batch.daf[0], first.daf, rtol=1e-12)
    assert batch.daf[1, 0] == pytest.approx(second.daf[0], rel=1e-12)
    assert np.isnan(batch.daf[1, 1])
    assert batch.contact_force_amplification[1] == pytest.approx(
        second.contact_force_amplification, rel=1e-9
    )


def test_two_span_sign_convention() -> None:
    """Span 2 deflects opposite to z_b; a load on span 1 lifts span 2."""
    bridge = vbi.Bridge(20.0, 2, 8e9, 6000.0)
    vehicle = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    crossing = vbi.simulate(bridge, vehicle, vbi.Profile.flat(45.0, 0.1), 0.2, 4.0)
    on_span_1 = (crossing.position > 4.0 + 9.0) & (crossing.position < 4.0 + 11.0)
    assert (crossing.midspan_displacement[on_span_1, 0] < 0).all()
    assert (crossing.midspan_displacement[on_span_1, 1] > 0).all()


# ----------------------------------------------------------------------------- bad input
@pytest.mark.parametrize(
    ("build", "message"),
    [
        (lambda: vbi.Bridge(-1.0, 1, 1e9, 1e3), "span=-1.0"),
        (lambda: vbi.Bridge(10.0, 3, 1e9, 1e3), "n_spans=3"),
        (lambda: vbi.Bridge(10.0, 1, 0.0, 1e3), "EI=0.0"),
        (lambda: vbi.Bridge(10.0, 1, 1e9, -5.0), "mass_per_length=-5.0"),
        (
            lambda: vbi.Bridge(10.0, 1, 1e9, 1e3, damping_ratio=1.0),
            r"damping_ratio=1.0 is outside \[0, 1\)",
        ),
        (lambda: vbi.Bridge(10.0, 1, 1e9, 1e3, damping_ratio=-0.1), "damping_ratio=-0.1"),
        (lambda: vbi.Vehicle(0.0, 1e6, 1e3), "mass=0.0"),
        (lambda: vbi.Vehicle(1e4, -1e6, 1e3), "stiffness=-1000000.0"),
        (lambda: vbi.Vehicle.from_frequency(1e4, 3.0, 1.2), "damping_ratio=1.2"),
        (lambda: vbi.Profile([0.0, 1.0, 1.0], [0.0, 0.0, 0.0]), "strictly increasing"),
        (lambda: vbi.Profile([0.0, np.nan, 2.0], [0.0, 0.0, 0.0]), r"profile x\[1\]=nan"),
        (lambda: vbi.Profile([0.0], [0.0]), "at least two samples"),
        (lambda: vbi.Profile([0.0, 1.0], [0.0]), "one elevation per station"),
    ],
)
def test_bad_parameters_are_named(build, message: str) -> None:  # noqa: ANN001
    with pytest.raises(ValueError, match=message):
        build()


def test_bad_crossing_inputs_are_named() -> None:
    bridge = vbi.Bridge(20.0, 1, 8e9, 6000.0)
    vehicle = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    road = vbi.Profile.flat(30.0, 0.1)
    with pytest.raises(ValueError, match="speed=0"):
        vbi.simulate(bridge, vehicle, road, 0, 5.0)
    with pytest.raises(ValueError, match="speed=-3.0"):
        vbi.simulate(bridge, vehicle, road, -3.0, 5.0)
    with pytest.raises(ValueError, match="does not cover"):
        vbi.simulate(bridge, vehicle, road, 20.0, 15.0)
    with pytest.raises(ValueError, match="does not cover"):
        vbi.simulate(bridge, vehicle, road.shifted(1.0), 20.0, 0.5)
    with pytest.raises(ValueError, match="crossing 1: the profile"):
        vbi.simulate_many(bridge, vehicle, road, 20.0, [5.0, 15.0])


def test_modes_dispatch_to_the_many_mode_model() -> None:
    bridge, vehicle, road, speed, start = build_case("100ft-4Hz-two-spans")
    from vbi_lib.modal import simulate_modal

    direct = simulate_modal(bridge, vehicle, road, speed, start, 5)
    via = vbi.simulate(bridge, vehicle, road, speed, start, modes=5)
    np.testing.assert_allclose(via.daf, direct.daf, rtol=1e-12)
    with pytest.raises(ValueError, match="modes=0"):
        vbi.simulate(bridge, vehicle, road, speed, start, modes=0)


def test_simulate_many_with_modes_matches_simulate() -> None:
    bridge, vehicle, road, speed, start = build_case("40ft-10Hz-one-span")
    batch = vbi.simulate_many(bridge, vehicle, road, [speed, 0.9 * speed], start, modes=[1, 3])
    assert batch.daf[0, 0] == pytest.approx(
        vbi.simulate(bridge, vehicle, road, speed, start).daf[0], rel=2e-3
    )
    three = vbi.simulate(bridge, vehicle, road, 0.9 * speed, start, modes=3)
    assert batch.daf[1, 0] == pytest.approx(three.daf[0], rel=1e-9)


@pytest.mark.parametrize("convective", [True, False])
def test_energy_bookkeeping_without_damping(convective: bool) -> None:
    """With no damping, the system's energy changes only by the power of the moving load.

    From the equations of motion on a flat road (c_v = c* = 0, r = psi z_b):
    dE/dt = F v psi' z_b - m_v g psi dz_b/dt, E = 1/2 m_v u'^2 + 1/2 k_v (r - u)^2
    + 1/2 m* z'^2 + 1/2 k* z^2.  The convective term only enters through the damper, so
    without damping both settings must satisfy the same balance.
    """
    bridge = vbi.Bridge(25.0, 1, 6e9, 5000.0, damping_ratio=0.0)
    vehicle = vbi.Vehicle.from_frequency(3e4, 2.2, 0.0)
    run = vbi.simulate(
        bridge, vehicle, vbi.Profile.flat(40.0, 0.01), 22.0, 10.0, convective=convective
    )
    on = run.on_bridge
    x = run.position[on] - run.bridge_start
    k = np.pi / bridge.span
    psi, dpsi = np.sin(k * x), k * np.cos(k * x)
    z, zd = run.bridge_coordinate[on], run.bridge_velocity[on]
    u_v, ud = run.vehicle_displacement[on], run.vehicle_velocity[on]
    force = run.contact_force[on] - vehicle.weight
    # the suspension force follows from the states; check it, then use the states alone
    np.testing.assert_allclose(
        force, vehicle.stiffness * (psi * z - u_v), atol=1e-6 * vehicle.weight
    )
    energy = (
        0.5 * vehicle.mass * ud**2
        + 0.5 * vehicle.stiffness * (psi * z - u_v) ** 2
        + 0.5 * bridge.generalized_mass * zd**2
        + 0.5 * bridge.generalized_stiffness * z**2
    )
    power = force * run.speed * dpsi * z - vehicle.mass * u.g * psi * zd
    t = run.time[on]
    work = np.concatenate(([0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(t))))
    scale = vehicle.weight * bridge.static_deflection(vehicle.weight)
    np.testing.assert_allclose(energy - energy[0], work, atol=2e-4 * scale)
