"""A deck's modes: mass-normalised, with the right energies, and the tables along a path.

The checks integrate the physical mass and strain energy of each mode by quadrature written
here, from the shapes and Cartesian derivatives the modes give, not from the Ritz matrices:
kinetic (slab rho h over the plan, girders and edge beams along their lines, diaphragms along
the skewed lines at ds = d(eta) / cos(skew)) and strain energy (Kirchhoff slab in Cartesian
curvatures, the girders' bending and twist).
"""

from __future__ import annotations

import math

import matplotlib
import numpy as np
import pytest

from vbi_lib import units as u
from vbi_lib.decks import WheelPath
from vbi_lib.decks.modes import axle_shape
from vbi_lib.decks.study import study_deck

matplotlib.use("Agg")


@pytest.fixture(scope="module")
def skewed():  # noqa: ANN201
    return study_deck(40, 1, "left").modes(8)


def _plan_quadrature(deck, nx: int = 40, ny: int = 60):  # noqa: ANN001, ANN202
    """Gauss points over the deck (oblique x along, y across; dA = dx dy) and weights."""
    gx, wx = np.polynomial.legendre.leggauss(nx)
    gy, wy = np.polynomial.legendre.leggauss(ny)
    xs, ws = [], []
    for a, b in zip(deck.supports[:-1], deck.supports[1:], strict=True):
        xs.append(a + 0.5 * (b - a) * (gx + 1))
        ws.append(0.5 * (b - a) * wx)
    x, wxx = np.concatenate(xs), np.concatenate(ws)
    y, wyy = 0.5 * deck.width * (gy + 1), 0.5 * deck.width * wy
    grid_x, grid_y = np.meshgrid(x, y, indexing="ij")
    return grid_x.ravel(), grid_y.ravel(), np.outer(wxx, wyy).ravel(), x, wxx


def test_modes_are_mass_normalised_and_orthogonal(skewed) -> None:  # noqa: ANN001
    deck = skewed.deck
    x, y, w, line_x, line_w = _plan_quadrature(deck)
    phi = skewed.shape(x, y)
    mass = deck.density * deck.thickness * (phi * w[:, None]).T @ phi
    for line in deck.line_members():
        along = skewed.shape(line_x, np.full(line_x.size, line.position))
        mass += line.mass_per_length * (along * line_w[:, None]).T @ along
    cosine = math.cos(math.radians(deck.skew))
    low, high = deck.diaphragm_extent
    g, gw = np.polynomial.legendre.leggauss(40)
    eta, weta = low + 0.5 * (high - low) * (g + 1), 0.5 * (high - low) * gw
    for station in deck.diaphragm_stations:
        across = skewed.shape(np.full(eta.size, station), eta)
        mass += deck.diaphragms.mass_per_length / cosine * (across * weta[:, None]).T @ across
    assert mass == pytest.approx(np.eye(skewed.count), abs=1e-8)


def test_each_mode_s_strain_energy_is_its_frequency_squared(skewed) -> None:  # noqa: ANN001
    """2 U = omega^2 for a mass-normalised mode; diaphragms' energy along their lines."""
    deck = skewed.deck
    x, y, w, line_x, line_w = _plan_quadrature(deck)
    wxx = skewed.derivative(x, y, along=2)
    wyy = skewed.derivative(x, y, across=2)
    wxy = skewed.derivative(x, y, along=1, across=1)
    D, nu = deck.flexural_rigidity, deck.poisson
    density = wxx**2 + wyy**2 + 2 * nu * wxx * wyy + 2 * (1 - nu) * wxy**2
    energy = D * (density * w[:, None]).sum(axis=0)
    for line in deck.line_members():
        ys = np.full(line_x.size, line.position)
        bend = skewed.derivative(line_x, ys, along=2)
        twist = skewed.derivative(line_x, ys, along=1, across=1)
        energy += ((line.EI * bend**2 + line.GJ * twist**2) * line_w[:, None]).sum(axis=0)
    # a diaphragm along its skewed line: curvature d2w/ds2 along the unit direction (t, 1) c
    t = deck.tangent
    c = 1.0 / math.sqrt(1 + t * t)
    low, high = deck.diaphragm_extent
    g, gw = np.polynomial.legendre.leggauss(40)
    eta, weta = low + 0.5 * (high - low) * (g + 1), 0.5 * (high - low) * gw
    for station in deck.diaphragm_stations:
        # Cartesian point on the line: x_cart = station + t eta; the library's x is the
        # oblique one, so the point is (station, eta) and its Cartesian Hessian is used
        xs = np.full(eta.size, station)
        h_xx = skewed.derivative(xs, eta, along=2)
        h_xy = skewed.derivative(xs, eta, along=1, across=1)
        h_yy = skewed.derivative(xs, eta, across=2)
        curvature = c * c * (t * t * h_xx + 2 * t * h_xy + h_yy)
        energy += deck.diaphragms.EI * ((curvature**2) * (weta / c)[:, None]).sum(axis=0)
    assert energy == pytest.approx(skewed.omega**2, rel=1e-6)


def test_all_modes_together_are_the_full_static_flexibility() -> None:
    """K^-1 = sum over every mode of c c^T / omega^2: the residual of all modes is zero."""
    from dataclasses import replace

    deck = replace(study_deck(40, 1, "right"), resolution=(8, 12))  # 96 functions, 96 modes
    everything = deck.modes(96)
    points = [(3.0, 4.2), (6.1, 7.4), (9.0, 12.0)]
    loads = [(6.0, 5.0), (2.0, 10.0)]
    full = everything.static_flexibility(loads, points)
    assert everything.modal_flexibility(loads, points) == pytest.approx(full, rel=1e-9)
    # at a point under its own load each mode adds a positive part, the first less than all
    first = np.diagonal(deck.modes(1).static_fraction(points, points)[..., 0])
    assert (first > 0).all() and (first < 1).all()


def test_path_tables_are_the_mean_of_the_wheels_and_their_interpolation(skewed) -> None:  # noqa: ANN001
    deck = skewed.deck
    path = WheelPath.from_girder(deck, 16 * u.ft)
    responses = [(deck.midspans[0], deck.girder_y(3)), (0.3 * deck.length, deck.girder_y(5))]
    tables = skewed.path_tables(path, responses)
    t = deck.tangent
    s = np.linspace(tables.entry, tables.exit, 57)
    wheels = [path.offset - 0.9144, path.offset + 0.9144]
    expected = sum(skewed.shape(s - t * (y - path.offset), np.full(s.size, y)) for y in wheels) / 2
    assert axle_shape(skewed, path, s) == pytest.approx(expected, abs=1e-12)
    # on a skewed deck the wheels meet the support line 2 t (track / 2) apart
    assert tables.entry == pytest.approx(-abs(t) * 0.9144, rel=1e-12)
    shape, slope = tables.interpolate(s)
    scale = np.abs(tables.shape).max()
    assert shape == pytest.approx(expected, abs=1e-4 * scale)
    h = 1e-5
    numeric = (axle_shape(skewed, path, s + h) - axle_shape(skewed, path, s - h)) / (2 * h)
    inside = np.all(np.abs(s[:, None] - path.crossings(deck)[None, :]) > 2 * h, axis=1)
    assert slope[inside] == pytest.approx(numeric[inside], abs=2e-3 * np.abs(numeric).max())
    # residual = full static minus the N-mode static, at every station
    modal = (tables.response_shape / tables.omega**2) @ tables.shape.T
    assert tables.residual_flexibility == pytest.approx(tables.static_flexibility - modal)
    loads = np.array([[tables.stations[40] - t * (y - path.offset), y] for y in wheels])
    direct = skewed.static_flexibility(loads, responses).mean(axis=1)
    assert tables.static_flexibility[:, 40] == pytest.approx(direct, rel=1e-12)


def test_driving_the_other_way_mirrors_the_tables_on_a_square_deck() -> None:
    deck = study_deck(40, 1)
    modes = deck.modes(6)
    ahead = WheelPath.from_girder(deck, 84 * u.inch)
    back = WheelPath(ahead.offset, ahead.track, -1)
    s = np.linspace(0.0, deck.length, 23)
    assert axle_shape(modes, back, s) == pytest.approx(axle_shape(modes, ahead, deck.length - s))
    assert axle_shape(modes, back, s, 1) == pytest.approx(
        -axle_shape(modes, ahead, deck.length - s, 1)
    )


def test_maxwell_reciprocity_between_two_paths(skewed) -> None:  # noqa: ANN001
    a = [(3.3, 2.0), (7.9, 11.5), (5.0, 14.0)]
    b = [(6.0, 6.6), (1.2, 9.0)]
    assert skewed.static_flexibility(a, b) == pytest.approx(skewed.static_flexibility(b, a).T)


def test_repr_and_plot(skewed) -> None:  # noqa: ANN001
    text = repr(skewed)
    assert text.startswith("DeckModes(8 modes of Deck(") and "Hz" in text
    assert "skew 16 deg left-forward" in text
    axes = skewed.plot(3)
    assert len(axes) == 3 and axes[0].get_title().startswith("mode 1:")
    import matplotlib.pyplot as plt

    plt.close("all")
