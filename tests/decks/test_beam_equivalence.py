"""A deck of one girder under a slab of almost nothing is the beam (issue 26).

Its beam-like modes (those that carry the girder; the slab's own modes, of almost no mass
and stiffness, barely move it) have the exact
Euler-Bernoulli frequencies of vbi_lib's beam (vbi_lib.modes, the continuous beam's exact
modes) to 1e-6, on one span, two equal spans and two unequal ones; its static deflection is
the beam's (three-moment equation, written here); and a crossing run on the deck's path
tables equals one run on the beam's exact modes, through the tests' reference integrator.
"""

from __future__ import annotations

import warnings

import deck_crossing as dc
import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib.decks import Deck, Girders, WheelPath
from vbi_lib.modes import beam_modes

EI, MBAR = 2.0e10, 6000.0
WIDTH = 2.0


def one_girder_deck(spans: list[float], resolution: tuple[int, int] = (12, 4)) -> Deck:
    """A girder on the centre line of a 1 mm slab of 1 kg/m^3 (its mass 4e-7 of the girder's)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.OutsideValidityWarning)
        return Deck(
            tuple(spans),
            WIDTH,
            0.001,
            1e9,
            0.3,
            1.0,
            girders=Girders(1, EI=EI, mass_per_length=MBAR),
            resolution=resolution,
        )


@pytest.mark.parametrize("spans", [[20.0], [20.0, 20.0], [18.0, 26.0]])
def test_one_girder_deck_has_the_beam_s_exact_frequencies(spans: list[float]) -> None:
    deck = one_girder_deck(spans)
    bridge = vbi.Bridge.continuous(spans, EI=EI, mass_per_length=MBAR)
    exact = beam_modes(bridge, 6).frequencies_hz
    modes = deck.modes(int(np.prod(deck.functions)))  # every mode: slab modes lie below
    # the slab's own modes barely move the girder; the beam's carry it with their full
    # mass-normalised amplitude (about sqrt(2 / (mbar L)) at a crest)
    x = np.linspace(0.02, 0.98, 49) * deck.length
    on_girder = np.abs(modes.shape(x, WIDTH / 2)).max(axis=0)
    straight = on_girder > 0.3 * np.sqrt(2.0 / (MBAR * deck.length))
    beam_like = modes.frequencies_hz[straight]
    assert beam_like[:6] == pytest.approx(exact, rel=1e-6)


def three_moment_deflection(spans: list[float], load: float, response: float) -> float:
    """Deflection at ``response`` under a unit load at ``load`` on a continuous beam [m/N].

    Flexibility method: the simply supported beam over the whole length, with the interior
    supports as redundant reactions (a small independent check, written out here).
    """
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    length = supports[-1]

    def simple(a: float, x: float) -> float:  # unit load at a, deflection at x, span length
        b = length - a
        if x <= a:
            return b * x * (length**2 - b**2 - x**2) / (6 * EI * length)
        return a * (length - x) * (length**2 - a**2 - (length - x) ** 2) / (6 * EI * length)

    inner = supports[1:-1]
    if inner.size == 0:
        return simple(load, response)
    f = np.array([[simple(a, x) for a in inner] for x in inner])
    rhs = np.array([simple(load, x) for x in inner])
    reactions = np.linalg.solve(f, rhs)
    return simple(load, response) - sum(
        r * simple(a, response) for r, a in zip(reactions, inner, strict=True)
    )


@pytest.mark.parametrize("spans", [[20.0], [18.0, 26.0]])
def test_one_girder_deck_deflects_as_the_beam(spans: list[float]) -> None:
    """The full-basis static flexibility: converges to the exact beam as functions are added."""
    deck = one_girder_deck(spans, resolution=(60, 2))
    modes = deck.modes(1)
    loads = [(0.3 * spans[0], 1.0), (0.47 * sum(spans), 1.0), (0.81 * sum(spans), 1.0)]
    responses = [(0.5 * spans[0], 1.0), (0.77 * sum(spans), 1.0)]
    flexibility = modes.static_flexibility(loads, responses)
    exact = np.array(
        [[three_moment_deflection(spans, a[0], r[0]) for a in loads] for r in responses]
    )
    assert flexibility == pytest.approx(exact, rel=2e-5)
    # Maxwell: the deflection at r under a load at a is the deflection at a under a load at r
    assert modes.static_flexibility(responses, loads) == pytest.approx(flexibility.T, rel=1e-10)


def test_a_crossing_on_the_one_girder_deck_is_the_beam_s() -> None:
    """The path tables and the beam's modes, through one integrator: the same DAF to 1e-6."""
    spans = [20.0]
    deck = one_girder_deck(spans, resolution=(100, 2))
    bridge = vbi.Bridge.continuous(spans, EI=EI, mass_per_length=MBAR)
    modes = deck.modes(200)
    x = np.linspace(0.02, 0.98, 49) * deck.length
    on_girder = np.abs(modes.shape(x, WIDTH / 2)).max(axis=0)
    straight = on_girder > 0.3 * np.sqrt(2.0 / (MBAR * deck.length))
    keep = np.flatnonzero(straight)[:4]
    path = WheelPath(WIDTH / 2, track=0.0)
    tables = modes.path_tables(path, [(10.0, WIDTH / 2)])
    deck_data = dc.BridgeData(
        tables.stations,
        tables.shape[:, keep],
        tables.slope[:, keep],
        tables.omega[keep],
        tables.damping_ratio[keep],
        tables.response_shape[:, keep],
        tables.static_flexibility,
        tables.static_flexibility
        - (tables.response_shape[:, keep] / tables.omega[keep] ** 2) @ tables.shape[:, keep].T,
        tables.entry,
        tables.exit,
    )
    beam = dc.beam_data(bridge, 4, [10.0], spacing=0.05, full_modes=200)
    x = np.arange(0.0, 60.0, 0.02)
    road = (x, 0.003 * np.sin(2 * np.pi * x / 4.7) + 0.001 * np.sin(2 * np.pi * x / 1.3))
    truck = (4000.0, 4000.0 * (2 * np.pi * 5.0) ** 2, 2 * 0.1 * 4000.0 * 2 * np.pi * 5.0)
    on_deck = dc.crossing(deck_data, truck, road, 20.0, 30.0)
    on_beam = dc.crossing(beam, truck, road, 20.0, 30.0)
    assert on_deck["daf"] == pytest.approx(on_beam["daf"], rel=1e-6)
    assert on_deck["daf"][0] > 1.05  # the road does excite it: not a trivial agreement
