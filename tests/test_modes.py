"""Exact beam modes and static influence lines against published roots and beam statics."""

from __future__ import annotations

import math

import numpy as np
import pytest
from problems import flat

import vbi_lib as vbi
from vbi_lib.closed_forms import point_load_statics
from vbi_lib.modes import beam_modes, propped_cantilever_roots, static_deflection_line


def test_propped_cantilever_roots_match_published_values() -> None:
    # tan(z) = tanh(z): 3.9266, 7.0686, 10.2102, 13.3518 (Blevins, Table 8-1)
    assert propped_cantilever_roots(4) == pytest.approx(
        [3.9266, 7.0686, 10.2102, 13.3518], abs=1e-4
    )
    z = propped_cantilever_roots(20)
    assert np.tan(z) == pytest.approx(np.tanh(z), abs=1e-9)


def test_two_equal_spans_first_frequency_ratio_is_1_562() -> None:
    bridge = vbi.Bridge(30.0, 2, 1e10, 5000.0)
    f = beam_modes(bridge, 4).frequencies_hz
    assert f[0] == pytest.approx(bridge.first_frequency_hz, rel=1e-12)
    assert f[1] / f[0] == pytest.approx((3.9266 / math.pi) ** 2, rel=1e-4)
    assert f[1] / f[0] == pytest.approx(1.562, abs=5e-4)
    assert np.all(np.diff(f) > 0)


def test_simple_span_frequencies_grow_as_n_squared() -> None:
    bridge = vbi.Bridge(30.0, 1, 1e10, 5000.0)
    f = beam_modes(bridge, 6).frequencies_hz
    assert f / f[0] == pytest.approx(np.arange(1, 7) ** 2, rel=1e-12)


@pytest.mark.parametrize("n_spans", [1, 2])
def test_modes_are_mass_normalised_and_orthogonal(n_spans: int) -> None:
    """Quadrature of m phi_m phi_n and EI phi_m'' phi_n'' (the beam's own energy products)."""
    bridge = vbi.Bridge(20.0, n_spans, 3e9, 4000.0)
    modes = beam_modes(bridge, 8)
    x = np.linspace(0.0, bridge.length, 40001)
    phi = modes.shape(x)
    mass = bridge.mass_per_length * np.trapezoid(phi[:, :, None] * phi[:, None, :], x, axis=0)
    assert mass == pytest.approx(np.eye(8), abs=1e-6)
    curv = modes.curvature(x)
    stiffness = bridge.EI * np.trapezoid(curv[:, :, None] * curv[:, None, :], x, axis=0)
    assert stiffness / np.outer(modes.omega, modes.omega) == pytest.approx(np.eye(8), abs=1e-5)
    # boundary conditions: zero deflection at every support, zero curvature at the ends
    supports = bridge.span * np.arange(n_spans + 1)
    assert modes.shape(supports) == pytest.approx(np.zeros((n_spans + 1, 8)), abs=1e-10)
    ends = np.array([0.0, bridge.length])
    scale = np.abs(modes.curvature(x)).max()
    assert modes.curvature(ends) / scale == pytest.approx(np.zeros((2, 8)), abs=1e-9)


def test_slope_is_the_derivative_of_the_shape() -> None:
    modes = beam_modes(vbi.Bridge(20.0, 2, 3e9, 4000.0), 6)
    x = np.linspace(0.3, 39.7, 50)
    h = 1e-6
    numeric = (modes.shape(x + h) - modes.shape(x - h)) / (2 * h)
    assert modes.slope(x) == pytest.approx(numeric, rel=1e-6, abs=1e-9)


# ---------------------------------------------------------------------------- statics
def test_static_deflection_converges_to_the_exact_beam_values() -> None:
    force = 1e5
    one = vbi.Bridge(20.0, 1, 3e9, 4000.0)
    two = vbi.Bridge(20.0, 2, 3e9, 4000.0)
    exact_one = point_load_statics(10.0, 10.0, 20.0, 3e9, 1, force).deflection  # (38)
    exact_two = point_load_statics(10.0, 10.0, 20.0, 3e9, 2, force).deflection  # (64)
    errors = []
    for n in (1, 3, 9, 27, 81):
        d1 = static_deflection_line(one, force, n, [10.0])[0, 0]
        d2 = static_deflection_line(two, force, n, [10.0])[0, 0]
        errors.append((abs(d1 / exact_one - 1), abs(d2 / exact_two - 1)))
    errors = np.array(errors)
    assert errors[0, 0] == pytest.approx(1 - 96 / math.pi**4, rel=1e-9)  # (39)
    assert errors[0, 1] == pytest.approx(1 - 1536 / (23 * math.pi**4), rel=1e-9)  # (65)
    assert np.all(np.diff(errors, axis=0) < 0)
    assert errors[-1].max() < 1e-5


def test_largest_static_deflection_is_the_maximum_of_the_influence_line() -> None:
    bridge = vbi.Bridge(20.0, 2, 3e9, 4000.0)
    truck = vbi.Vehicle(1e4, 1e6, 0.0)
    run = vbi.simulate(bridge, truck, flat(bridge, 5.0, 0.5), 10.0, 5.0, model="modal", modes=60)
    a = np.linspace(0.0, 20.0, 20001)
    exact = point_load_statics(10.0, a, 20.0, 3e9, 2, truck.weight).deflection.max()
    assert run.static_deflection == pytest.approx(exact, rel=2e-5)
    # the maximum lies off midspan and exceeds 23 P L^3 / 1536 EI by about a quarter percent
    assert exact / bridge.exact_static_deflection(truck.weight) == pytest.approx(1.0025, abs=5e-4)
