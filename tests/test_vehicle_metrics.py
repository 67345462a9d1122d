"""The study's vehicle-only metric against the decoupled simulation and closed forms."""

from __future__ import annotations

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.closed_forms import contact_force_transmissibility
from vbi_lib.vehicle_metrics import contact_force_amplification, quarter_car_contact_force

TRUCK = vbi.Vehicle.from_frequency(200 * u.slinch, 2.8, 0.20)
SPEED = 720 * u.inch


def test_rigid_road_contact_force_matches_the_decoupled_simulation() -> None:
    road = vbi.Profile.iso8608(650 * u.ft, 1 * u.inch, c10=600e-6, waviness=2, seed=2)
    bridge = vbi.Bridge(100 * u.ft, 1, 1e10, 1e4)
    crossing = vbi.simulate(bridge, TRUCK, road, SPEED, 320 * u.ft, coupled=False)
    time, after, _ = quarter_car_contact_force(road, TRUCK, SPEED)
    inside = road.x < crossing.position[-1] - 1e-9
    index = np.searchsorted(crossing.position, road.x[inside] - 1e-9)
    same = np.abs(crossing.position[index] - road.x[inside]) < 1e-9
    assert same.sum() > 4000
    reference = crossing.contact_force[index[same]] - TRUCK.weight
    np.testing.assert_allclose(after[inside][same], reference, atol=1e-6 * TRUCK.weight)
    np.testing.assert_allclose(time[inside][same], crossing.time[index[same]], rtol=1e-12)


def test_contact_force_on_a_long_sine_is_the_steady_state_closed_form() -> None:
    """Base excitation: |F| = k Y r^2 T_d (closed_forms.contact_force_transmissibility)."""
    wavelength, amplitude = 30 * u.ft, 5e-3
    road = vbi.Profile.harmonic(400.0, 0.02, wavelength=wavelength, amplitude=amplitude)
    _, after, before = quarter_car_contact_force(road, TRUCK, SPEED)
    # the sampled road is piecewise linear, so the force jumps by c * (change of slope) at
    # each sample; the mean of the two sides is the force of the smooth sine to O(h^2)
    force = 0.5 * (after + before)
    ratio = SPEED / wavelength / TRUCK.frequency_hz
    force_ratio = contact_force_transmissibility(ratio, TRUCK.damping_ratio)
    expected = TRUCK.stiffness * amplitude * force_ratio
    late = road.x > 200.0
    assert np.abs(force[late]).max() == pytest.approx(expected, rel=1e-4)
    assert np.abs(after[late]).max() == pytest.approx(expected, rel=3e-3)


def test_window_of_a_steady_sine_force() -> None:
    """Amplification = max over the span of (W + F(t)) sin(pi xi / L) / W, F from closed form."""
    wavelength, amplitude, span, start = 30 * u.ft, 5e-3, 100 * u.ft, 300.0
    road = vbi.Profile.harmonic(400.0, 0.01, wavelength=wavelength, amplitude=amplitude)
    result = contact_force_amplification(road, TRUCK, SPEED, start, span)
    m, k, c = TRUCK.mass, TRUCK.stiffness, TRUCK.damping
    w = 2 * np.pi * SPEED / wavelength
    # steady state: u = Y H sin(w t) with H = (k + i c w)/(k - m w^2 + i c w); F = m u''
    h = (k + 1j * c * w) / (k - m * w**2 + 1j * c * w)
    x = np.linspace(start, start + span, 200001)
    phase = 2 * np.pi * x / wavelength
    force = -m * w**2 * amplitude * np.imag(h * np.exp(1j * phase))
    windowed = (TRUCK.weight + force) * np.sin(np.pi * (x - start) / span) / TRUCK.weight
    # the force of the piecewise-linear road jumps at samples (first order in the spacing)
    assert result.amplification[0] == pytest.approx(windowed.max(), rel=5e-4)
    assert result.peak_position[0] == pytest.approx(x[np.argmax(windowed)], abs=0.05)
    dynamic = contact_force_amplification(road, TRUCK, SPEED, start, span, dynamic_only=True)
    expected = (force * np.sin(np.pi * (x - start) / span)).max() / TRUCK.weight
    assert dynamic.amplification[0] == pytest.approx(expected, rel=3e-3)


def test_a_smooth_road_gives_one_on_every_span() -> None:
    road = vbi.Profile.flat(600 * u.ft, 1 * u.inch)
    result = contact_force_amplification(road, TRUCK, SPEED, 320 * u.ft, 40 * u.ft, n_spans=3)
    np.testing.assert_allclose(result.amplification, 1.0, atol=1e-12)
    np.testing.assert_allclose(result.peak_position, 320 * u.ft + (np.arange(3) + 0.5) * 40 * u.ft)


def test_contact_force_amplification_checks_its_bridge() -> None:
    road = vbi.Profile.flat(100.0, 0.05)
    with pytest.raises(ValueError, match="must lie on the profile"):
        contact_force_amplification(road, TRUCK, SPEED, 80.0, 30.0)
    with pytest.raises(ValueError, match="n_spans=0"):
        contact_force_amplification(road, TRUCK, SPEED, 10.0, 30.0, n_spans=0)
    with pytest.raises(ValueError, match="speed"):
        contact_force_amplification(road, TRUCK, -1.0, 10.0, 30.0)
