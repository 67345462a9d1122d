"""The study's one-coordinate model (RK4) against an independent solver and its own numerics.

References: a tight-tolerance ``solve_ivp`` (DOP853) solution of the same equations, the
fourth-order convergence of RK4, the energy balance of the undamped system, and the study's
forward Euler scheme (which must come out inflated).
"""

from __future__ import annotations

import numpy as np
import pytest
from problems import CASES, build_case

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.models.reference import reference_daf, study_explicit_euler_daf


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


def test_state_matrices_are_those_of_the_study() -> None:
    """A, B, f of (51)-(58) written out from the equations of motion."""
    bridge = vbi.Bridge(20.0, 1, 1e10, 5000.0, damping_ratio=0.02)
    truck = vbi.Vehicle(1e4, 4e6, 2e4)
    psi, dpsi, v = 0.7, 0.11, 20.0
    A, B, f = vbi.state_matrices(bridge, truck, v, psi, dpsi)
    m, k, c = truck.mass, truck.stiffness, truck.damping
    mb, kb, cb = bridge.generalized_mass, bridge.generalized_stiffness, bridge.generalized_damping
    kappa, gamma = k * psi + c * v * dpsi, c * psi
    expected = np.array(
        [
            [0, 1, 0, 0],
            [-k / m, -c / m, kappa / m, gamma / m],
            [0, 0, 0, 1],
            [psi * k / mb, psi * c / mb, -(kb + psi * kappa) / mb, -(cb + psi * gamma) / mb],
        ]
    )
    np.testing.assert_allclose(A, expected, rtol=1e-14)
    np.testing.assert_allclose(B[[1, 3]], [[k / m, c / m], [-psi * k / mb, -psi * c / mb]])
    np.testing.assert_allclose(f, [0, 0, 0, -psi * m * u.g / mb])
    A0, _, _ = vbi.state_matrices(bridge, truck, v, psi, dpsi, coupled=False)
    assert A0[1, 2] == A0[1, 3] == 0.0


def test_highest_frequency_is_the_largest_eigenvalue_of_the_state_matrix() -> None:
    """The compiled quartic solver against numpy's eigenvalues of A (51)-(58), psi = i/4."""
    import math

    from vbi_lib.models.one_coordinate import highest_circular_frequency, state_matrices

    rng = np.random.default_rng(8)
    for trial in range(300):
        bridge = vbi.Bridge(rng.uniform(5.0, 60.0), int(rng.integers(1, 3)),
                            10 ** rng.uniform(8.0, 11.0), rng.uniform(500.0, 2e4),
                            damping_ratio=rng.uniform(0.0, 0.1))  # fmt: skip
        damping = 0.0 if trial % 3 == 0 else rng.uniform(0.0, 0.9)
        truck = vbi.Vehicle.from_frequency(rng.uniform(1e3, 6e4), rng.uniform(0.5, 15.0), damping)
        rate = rng.uniform(1.0, 40.0)
        coupled, convective = bool(trial % 2), bool(trial % 5)
        expected = 0.0
        for psi in np.linspace(0.0, 1.0, 5):
            slope = math.pi / bridge.span * math.sqrt(1.0 - psi**2)
            A, _, _ = state_matrices(bridge, truck, rate, psi, slope, coupled, convective)
            expected = max(expected, np.abs(np.linalg.eigvals(A)).max())
        got = highest_circular_frequency(bridge, truck, rate, coupled, convective)
        assert got == pytest.approx(expected, rel=1e-12)


def test_highest_frequency_when_truck_and_bridge_have_one_frequency() -> None:
    """A double root of the decoupled quartic (both methods lose half the digits there)."""
    from vbi_lib.models.one_coordinate import highest_circular_frequency

    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0, damping_ratio=0.02)
    truck = vbi.Vehicle.from_frequency(3e4, bridge.first_frequency_hz, 0.02)
    omega = highest_circular_frequency(bridge, truck, 20.0, coupled=False)
    assert omega == pytest.approx(2 * np.pi * bridge.first_frequency_hz, rel=1e-7)
