"""Suspensions damped at or above critical: accepted, warned of, and integrated correctly.

A damping ratio of 1 or more is a real suspension (VBI-2D's verification vehicle, 5750 kg on
1595 kN/m and 400 kN s/m, is damped 2.09 times critical).  The reference is an independent
model written here: the sine modes of the simply supported beam and the sprung mass,
coupled through the suspension's spring and damper, integrated by ``scipy``'s ``solve_ivp``
(DOP853, tight tolerances).  Nothing in it comes from the library.

Biggs' beam (model-equations.md, "Published verification cases"): L = 25 m,
EI = 8.323e9 N m^2, mbar = 2303 kg/m, v = 100 km/h, simply supported, undamped.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from problems import BIGGS_BRIDGE, BIGGS_SPEED
from scipy.integrate import solve_ivp

import vbi_lib as vbi
from vbi_lib.models.one_coordinate import state_matrices
from vbi_lib.models.one_coordinate_step import sprung_mass_omega
from vbi_lib.units import g as GRAVITY

MASS, STIFFNESS, DAMPING = 5750.0, 1595e3, 4e5  # VBI-2D's verification vehicle
SPAN, EI, MBAR = 25.0, 8.323e9, 2303.0


def overdamped() -> vbi.Vehicle:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.OutsideValidityWarning)  # asserted below
        return vbi.Vehicle(MASS, STIFFNESS, DAMPING)


def reference(modes: int, times: np.ndarray) -> tuple:
    """The independent model at ``times``: its series and mode-acceleration midspan
    displacements [m, up], contact force [N], and the largest downward deflection of each
    displacement [m] (on a grid 20 times finer).

    Mode n: ``sin(n pi x / L)``, modal mass ``mbar L / 2``, ``omega_n = (n pi / L)^2
    sqrt(EI / mbar)``.  The wheel at ``x = v t`` follows the beam, ``r = sum q_n phi_n``,
    ``dr/dt = sum (qdot_n phi_n + v q_n phi_n')``; the suspension pushes the body up with
    ``F = k (r - u) + c (dr/dt - du/dt)`` and the beam down with ``W + F``.  Beam at rest
    and body in static equilibrium at t = 0, when the wheel is on the first support.
    """
    n = np.arange(1, modes + 1)
    wave = n * math.pi / SPAN
    omega2 = wave**4 * EI / MBAR
    modal_mass = MBAR * SPAN / 2.0
    weight = MASS * GRAVITY
    speed = BIGGS_SPEED

    def force(t: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Suspension force [N] and mode shapes at the wheel, ``y`` of shape (state, times)."""
        u, du, q, dq = y[0], y[1], y[2 : 2 + modes], y[2 + modes :]
        x = speed * np.asarray(t)
        phi = np.sin(wave[:, None] * x)
        dphi = wave[:, None] * np.cos(wave[:, None] * x)
        r = (q * phi).sum(0)
        dr = (dq * phi).sum(0) + speed * (q * dphi).sum(0)
        return STIFFNESS * (r - u) + DAMPING * (dr - du), phi

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        f, phi = force(t, y[:, None])
        out = np.empty_like(y)
        out[0] = y[1]
        out[1] = f[0] / MASS
        out[2 : 2 + modes] = y[2 + modes :]
        out[2 + modes :] = -omega2 * y[2 : 2 + modes] - (weight + f[0]) * phi[:, 0] / modal_mass
        return out

    solution = solve_ivp(rhs, (0.0, times[-1]), np.zeros(2 + 2 * modes), method="DOP853",
                         dense_output=True, rtol=1e-11, atol=1e-14)  # fmt: skip
    assert solution.success
    at_midspan = np.sin(n * math.pi / 2)

    def midspan(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The series and the mode-acceleration midspan displacement at ``t``: the series
        plus ``R (sum_n phi_n(L/2) phi_n(x) / (M_n omega_n^2) - eta(x))``, with the exact
        influence line of a simple span's midspan, ``eta(x) = x (3 L^2 - 4 x^2) / 48 EI``
        for ``x <= L / 2`` (symmetric), and ``R = W + F`` while the wheel is on the span."""
        states = solution.sol(t)
        series = at_midspan @ states[2 : 2 + modes]
        x = np.clip(speed * t, 0.0, SPAN)
        near = np.minimum(x, SPAN - x)
        eta = near * (3 * SPAN**2 - 4 * near**2) / (48 * EI)
        truncated = (at_midspan / (modal_mass * omega2)) @ np.sin(wave[:, None] * x)
        load = np.where(speed * t < SPAN, weight + force(t, states)[0], 0.0)
        return series, series + load * (truncated - eta)

    fine = np.linspace(0.0, times[-1], 20 * times.size)
    series, headline = midspan(times)
    fine_series, fine_headline = midspan(fine)
    states = solution.sol(times)
    return (series, headline, weight + force(times, states)[0], -fine_series.min(),
            -fine_headline.min())  # fmt: skip


# ---------------------------------------------------------------------------- acceptance
def test_an_overdamped_suspension_is_accepted_with_a_warning() -> None:
    with pytest.warns(vbi.OutsideValidityWarning, match="damping_ratio .*=2.088"):
        vehicle = vbi.Vehicle(MASS, STIFFNESS, DAMPING)
    assert vehicle.damping_ratio == pytest.approx(DAMPING / (2 * math.sqrt(STIFFNESS * MASS)))
    assert vehicle.damping_ratio > 2.0
    assert "208.8%" in repr(vehicle)
    # the same vehicle from its undamped frequency and damping ratio
    f = math.sqrt(STIFFNESS / MASS) / (2 * math.pi)
    with pytest.warns(vbi.OutsideValidityWarning):
        again = vbi.Vehicle.from_frequency(MASS, f, vehicle.damping_ratio)
    assert again.damping == pytest.approx(DAMPING, rel=1e-12)


def test_critical_damping_and_more_have_no_damped_frequency() -> None:
    vehicle = overdamped()
    with pytest.raises(ValueError, match=r"damping_ratio=2\.088.*no damped frequency"):
        _ = vehicle.damped_frequency_hz
    with pytest.raises(ValueError, match=r"damped=True with damping_ratio=1\.0"):
        vbi.Vehicle.from_frequency(MASS, 2.6, 1.0, damped=True)
    with pytest.raises(ValueError, match=r"damping_ratio=-0\.1"):
        vbi.Vehicle.from_frequency(MASS, 2.6, -0.1)
    for bad in (math.inf, math.nan):
        with pytest.raises(ValueError, match="damping_ratio"):
            vbi.Vehicle.from_frequency(MASS, 2.6, bad)


def test_quarter_cars_and_trucks_take_overdamped_suspensions() -> None:
    from vbi_lib.vehicles import hs20

    with pytest.warns(vbi.OutsideValidityWarning, match="suspension_damping_ratio=1.5"):
        car = vbi.QuarterCar.from_frequencies(12_000.0, 900.0, 2.5, 11.0, 1.5)
    assert car.suspension_damping == pytest.approx(2 * 1.5 * 12_000.0 * 2 * math.pi * 2.5)
    with pytest.warns(vbi.OutsideValidityWarning, match="tyre_damping_ratio=1.2"):
        vbi.QuarterCar.from_frequencies(12_000.0, 900.0, 2.5, 11.0, 0.1, 1.2)
    with pytest.warns(vbi.OutsideValidityWarning, match="suspension_damping_ratio=2"):
        truck = hs20(suspension_damping_ratio=2.0)
    axle = truck.axles[1]
    zeta = axle.damping / (2 * math.sqrt(axle.stiffness * axle.sprung_load / GRAVITY))
    assert zeta == pytest.approx(2.0, rel=1e-12)
    with pytest.raises(ValueError, match="suspension_damping_ratio=-1"):
        hs20(suspension_damping_ratio=-1.0)


def test_the_default_step_follows_the_fast_real_root() -> None:
    """An overdamped body has a fast real eigenvalue ``-(zeta + sqrt(zeta^2 - 1)) omega``:
    the one-coordinate model's step (largest eigenvalue modulus of its state matrix) must
    see it.  Reference: numpy's eigenvalues of the study's state matrix at the five wheel
    positions the step looks at."""
    vehicle = overdamped()
    omega = sprung_mass_omega(BIGGS_BRIDGE, vehicle, BIGGS_SPEED, True, True)
    largest = 0.0
    for psi in np.linspace(0.0, 1.0, 5):
        dpsi = math.pi / SPAN * math.sqrt(max(0.0, 1.0 - psi**2))
        a = state_matrices(BIGGS_BRIDGE, vehicle, BIGGS_SPEED, psi, dpsi)[0]
        largest = max(largest, float(np.abs(np.linalg.eigvals(a)).max()))
    assert omega == pytest.approx(largest, rel=1e-9)
    zeta, w = vehicle.damping_ratio, vehicle.circular_frequency
    assert omega >= (zeta + math.sqrt(zeta**2 - 1)) * w * 0.999  # the body's fast root


# ---------------------------------------------------------------------------- against solve_ivp
@pytest.mark.parametrize(
    ("options", "modes", "dt", "tolerance"),
    [
        # RK4 on the one-shape beam is the 1-mode reference itself; at the default step
        # (omega_max dt = 0.1) its global error is of order (omega dt)^4 / 120 per radian,
        # about 1e-6 over the crossing's few periods
        ({}, 1, None, 1e-6),
        # Newmark's average acceleration is second order: its period error (omega dt)^2 / 12
        # is 8e-4 at the default omega dt = 0.1, on the dynamic part of the response only;
        # at dt = 1e-5 s it is under 1e-7 for the first two modes
        ({"model": "modal", "modes": 1}, 1, None, 1e-3),
        ({"model": "modal", "modes": 5}, 5, None, 1e-3),
        ({"model": "modal", "modes": 5}, 5, 1e-5, 1e-6),
    ],
    ids=["one-coordinate", "modal-1", "modal-5", "modal-5-fine"],
)
def test_overdamped_vehicle_on_biggs_beam_matches_solve_ivp(
    options: dict, modes: int, dt: float | None, tolerance: float
) -> None:
    """Midspan history, peak and contact force against the independent model.

    Tolerances, relative to the peak midspan deflection and to the weight: as stated for
    each integrator (the reference's own error, rtol 1e-11, is far below).  The peak is
    compared with the reference's on a grid 20 times finer than the model's nodes (the
    model refines its peak inside each step).  The same vehicle damped at 10 % of its
    damping differs from the reference by 9 % of the peak: the test sees the damper.
    """
    vehicle = overdamped()
    road = vbi.Profile.flat(SPAN, 0.05)
    crossing = vbi.simulate(BIGGS_BRIDGE, vehicle, road, BIGGS_SPEED, 0.0, dt=dt, **options)
    series, headline, contact, series_peak, peak = reference(modes, crossing.time)
    if options:  # the modal model: its series, and its mode-acceleration headline
        error = np.abs(crossing.series_midspan_displacement[:, 0] - series).max()
        assert error <= tolerance * series_peak
    else:  # the one-coordinate model is the one-mode series
        headline, peak = series, series_peak
    assert np.abs(crossing.midspan_displacement[:, 0] - headline).max() <= tolerance * peak
    assert np.abs(crossing.contact_force - contact).max() <= tolerance * vehicle.weight
    dynamic_peak = crossing.daf[0] * crossing.static_deflection
    assert dynamic_peak == pytest.approx(peak, rel=max(tolerance, 1e-6))
    # the batch path gives the same DAF (its lane kernel for the study's sprung mass)
    batch = vbi.simulate_many(BIGGS_BRIDGE, vehicle, road, BIGGS_SPEED, 0.0, dt=dt, **options)
    assert batch.daf[0, 0] == pytest.approx(crossing.daf[0], rel=1e-9)


def test_the_one_coordinate_daf_divides_by_w_over_k_star() -> None:
    """The one-coordinate DAF of the overdamped vehicle: the 1-mode reference's peak over the
    one-shape static deflection W / k*, k* = pi^4 EI / (2 L^3) (equations 90-91)."""
    vehicle = overdamped()
    road = vbi.Profile.flat(SPAN, 0.05)
    crossing = vbi.simulate(BIGGS_BRIDGE, vehicle, road, BIGGS_SPEED, 0.0)
    peak = reference(1, crossing.time)[3]  # the one-mode series
    k_star = math.pi**4 * EI / (2 * SPAN**3)
    assert crossing.daf[0] == pytest.approx(peak / (vehicle.weight / k_star), rel=1e-6)
