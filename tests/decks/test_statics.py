"""A deck's statics under the study's twin loads, against an independent plate FE.

The reference is the BFS plate finite-element model of ``deck_fe.py`` (written for these
tests), meshed through the loads, girders, edge beams and diaphragms, and given the same
physical deck: the slab's D computed here, each girder's rigidity net of the slab over its
tributary width (computed here by the midpoint rule), the edge beams and diaphragms as
given.  Its mesh is converged: halving the elements changes these deflections by < 2e-5.
"""

from __future__ import annotations

import deck_fe
import numpy as np
import pytest

from vbi_lib import units as u
from vbi_lib.decks import WheelPath, axle_deflection, fit_to_path, midspan_stiffness
from vbi_lib.decks.study import STUDY_PATHS, study_deck

HALF_TRACK = 3 * u.ft


def fe_twin_deflection(deck, path_y: float, girder_y: float, span: int = 1) -> float:  # noqa: ANN001
    """Girder deflection at midspan of ``span`` under 1 N shared by loads 3 ft either side of
    the path at that midspan [m]."""
    length, width, t = deck.length, deck.width, deck.tangent
    D = deck.E * deck.thickness**3 / (12 * (1 - deck.poisson**2))
    ys = list(deck.girder_positions)
    bounds = [0.0] + [0.5 * (a + b) for a, b in zip(ys[:-1], ys[1:], strict=True)] + [width]
    lines = [
        deck_fe.Line(y, ei - D * (bounds[g + 1] - bounds[g]), gj, m)
        for g, (y, ei, gj, m) in enumerate(
            zip(ys, deck.girder_rigidities, deck.girder_torsion, deck.girder_masses, strict=True)
        )
    ]
    if deck.edge_beams is not None:
        right, left = deck.edge_beams
        lines += [
            deck_fe.Line(right.offset, right.EI, right.GJ, right.mass_per_length),
            deck_fe.Line(width - left.offset, left.EI, left.GJ, left.mass_per_length),
        ]
    supports = list(deck.supports)
    middle = 0.5 * (supports[span - 1] + supports[span])
    wheels_y = [path_y - HALF_TRACK, path_y + HALF_TRACK]
    wheels_a = [middle - t * (y - path_y) for y in wheels_y]  # on the line square to the path
    crosses = []
    if deck.diaphragms is not None:
        crosses = [
            deck_fe.Cross(s, ys[0], ys[-1], deck.diaphragms.EI, deck.diaphragms.mass_per_length)
            for s in deck.diaphragm_stations
        ]
    a = deck_fe.grid(length, supports + wheels_a + [middle] + [c.position for c in crosses],
                     16 * deck.n_spans)  # fmt: skip
    b = deck_fe.grid(width, ys + [line.position for line in lines] + wheels_y, 20)
    fe = deck_fe.PlateFE(a, b, D, deck.poisson, deck.density * deck.thickness, t, supports,
                         lines, crosses)  # fmt: skip
    state = fe.static([(wheels_a[0], wheels_y[0], 0.5), (wheels_a[1], wheels_y[1], 0.5)])
    return fe.deflection(state, middle, girder_y)


CASES = [
    (40, 1, 1, None),
    (40, 1, 2, None),
    (40, 1, 1, "left"),
    (40, 1, 2, "right"),
    (40, 2, 1, None),
    (100, 1, 1, None),
]


@pytest.mark.parametrize(("span_ft", "n_spans", "path", "hand"), CASES)
def test_twin_load_deflection_matches_an_independent_plate_fe(
    span_ft: int, n_spans: int, path: int, hand: str | None
) -> None:
    deck = study_deck(span_ft, n_spans, hand)
    where = STUDY_PATHS[(span_ft, n_spans, path)]
    wheel_path = WheelPath.from_girder(deck, where.distance)
    girder_y = deck.girder_y(where.girder)
    ritz = axle_deflection(deck, wheel_path, deck.midspans[0], [(deck.midspans[0], girder_y)])[0]
    reference = fe_twin_deflection(deck, wheel_path.offset, girder_y)
    assert ritz == pytest.approx(reference, rel=5e-3)


def test_midspan_stiffness_is_the_inverse_twin_load_deflection() -> None:
    deck = study_deck(40, 1)
    path = WheelPath.from_girder(deck, 16 * u.ft)
    k = midspan_stiffness(deck, path, girder=3)
    d = axle_deflection(deck, path, deck.midspans[0], [(deck.midspans[0], deck.girder_y(3))])
    assert k * d[0] == pytest.approx(1.0, rel=1e-12)
    # the other way along the same path: the same midspan, the same stiffness
    back = WheelPath(path.offset, path.track, -1)
    assert midspan_stiffness(deck, back, girder=3) == pytest.approx(k, rel=1e-10)


@pytest.mark.parametrize("hand", [None, "left"])
def test_a_deck_fitted_to_k_mid_and_f1_has_them(hand: str | None) -> None:
    """Two scalars, as the study's beam is fitted (82)-(84): its K_mid and f1 are the row's,
    its mode shapes the drawn deck's (scaled), its frequency ratios unchanged."""
    drawn = study_deck(40, 1, hand)
    path = WheelPath.from_girder(drawn, 84 * u.inch)
    k_mid = 587723 * u.lbf / u.inch
    fitted = fit_to_path(drawn, k_mid, 9.95, path, girder=2)
    assert midspan_stiffness(fitted, path, girder=2) == pytest.approx(k_mid, rel=1e-12)
    assert fitted.first_frequency_hz() == pytest.approx(9.95, rel=1e-12)
    ratio = drawn.frequencies_hz(8) / drawn.frequencies_hz(1)[0]
    assert fitted.frequencies_hz(8) / 9.95 == pytest.approx(ratio, rel=1e-12)
    points = [(3.0, 4.0), (6.1, 9.0), (10.0, 12.0)]
    scale = np.sqrt(fitted.density / drawn.density)
    shapes = fitted.modes(4).shape(*np.array(points).T) * scale
    assert np.abs(shapes) == pytest.approx(np.abs(drawn.modes(4).shape(*np.array(points).T)),
                                           rel=1e-12)  # fmt: skip
