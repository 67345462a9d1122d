"""Statics of continuous beams against a beam finite-element model, closed forms and statics.

References: the FE beam of ``tests/beam_fe.py`` (Hermite cubics, exact at the nodes for
nodal loads; moments and shears by statics from its support reactions); the closed forms
of one span and two equal spans (:func:`vbi_lib.closed_forms.point_load_statics`, itself
checked against the FE model in ``test_closed_forms.py``); Maxwell's reciprocity; the
textbook simple-span envelopes ``P x (L - x) / L``.
"""

from __future__ import annotations

import numpy as np
import pytest
from beam_fe import Beam

from vbi_lib.beam_statics import continuous_statics, static_envelope
from vbi_lib.closed_forms import point_load_statics

EI = 3e9
LAYOUTS = [[18.0, 27.5, 22.0], [15.0, 21.0, 21.0, 12.5], [10.0, 31.0]]


def fe_beam(spans: list[float], required: np.ndarray) -> Beam:
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    return Beam(supports, required, EI, element=0.5)


@pytest.mark.parametrize("spans", LAYOUTS)
def test_point_loads_match_a_finite_element_beam(spans: list[float]) -> None:
    length = float(np.sum(spans))
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    sections = np.unique(np.concatenate([supports, length * np.array([0.07, 0.33, 0.5, 0.81])]))
    loads = np.unique(np.concatenate([supports, length * np.array([0.13, 0.33, 0.62, 0.95])]))
    beam = fe_beam(spans, np.concatenate([sections, loads]))
    w, m, v = beam.influence(loads, sections)
    got = continuous_statics(sections[None, :], loads[:, None], spans, EI)
    scale_w = np.abs(w).max()
    np.testing.assert_allclose(got.deflection, w, rtol=1e-6, atol=1e-9 * scale_w)
    np.testing.assert_allclose(got.moment, m, rtol=1e-6, atol=1e-9 * length)
    np.testing.assert_allclose(got.shear, v, rtol=1e-6, atol=1e-9)


@pytest.mark.parametrize("n_spans", [1, 2])
def test_one_span_and_two_equal_spans_are_the_closed_forms(n_spans: int) -> None:
    span, force = 12.0, 7e4
    x = np.linspace(0.0, n_spans * span, 97)
    a = np.linspace(0.0, n_spans * span, 61)[:, None]
    got = continuous_statics(x, a, [span] * n_spans, EI, force)
    expected = point_load_statics(x, a, span, EI, n_spans, force)
    for ours, theirs in zip(got, expected, strict=True):
        np.testing.assert_allclose(ours, theirs, rtol=1e-12, atol=1e-12 * np.abs(theirs).max())


def test_reciprocity_and_equilibrium_of_a_four_span_beam() -> None:
    spans = LAYOUTS[1]
    length = float(np.sum(spans))
    x = np.linspace(0.0, length, 71)
    grid = continuous_statics(x[None, :], x[:, None], spans, EI)
    np.testing.assert_allclose(grid.deflection, grid.deflection.T, atol=1e-15)
    # V = dM/dx between kinks; the shear jumps by P under the load
    load = 0.41 * length
    fine = np.linspace(0.0, length, 6001)
    statics = continuous_statics(fine, load, spans, EI)
    kinks = np.concatenate([[load], np.concatenate([[0.0], np.cumsum(spans)])])
    smooth = np.min(np.abs(fine[:, None] - kinks[None, :]), axis=1) > 0.05
    slope = np.gradient(statics.moment, fine)
    np.testing.assert_allclose(slope[smooth], statics.shear[smooth], atol=1e-8)
    jump = continuous_statics([load, load + 1e-9], load, spans, EI).shear
    assert jump[0] - jump[1] == pytest.approx(1.0)


def test_simple_span_envelope_is_the_textbook_one() -> None:
    span, force = 10.0, 1e5
    x = np.array([0.0, 1.3, 2.5, 5.0, 7.7, 10.0])
    env = static_envelope([span], EI, x, force)
    moment, shear, displacement = 1, 2, 0
    np.testing.assert_allclose(env.maximum[moment], force * x * (span - x) / span, atol=1e-6)
    np.testing.assert_allclose(env.minimum[moment], 0.0, atol=1e-9)
    np.testing.assert_allclose(env.maximum[shear, :-1], force * (span - x[:-1]) / span, atol=1e-3)
    np.testing.assert_allclose(env.minimum[shear, 1:], -force * x[1:] / span, atol=1e-3)
    # the largest deflection at a section over load positions, by brute force (1 mm steps)
    a = np.linspace(0.0, span, 10001)[:, None]
    brute = point_load_statics(x[None, :], a, span, EI, 1, force).deflection.max(axis=0)
    np.testing.assert_allclose(env.minimum[displacement], -brute, rtol=1e-7, atol=1e-15)
    assert env.maximum_at[moment, 3] == pytest.approx(5.0)


@pytest.mark.parametrize("spans", LAYOUTS[:2])
def test_axle_group_envelope_matches_a_finite_element_crawl(spans: list[float]) -> None:
    """Three axles (an HS20 truck's 35.6, 142.3, 142.3 kN, about 4.28 m apart) crawl over
    the FE beam.

    Brute force: every axle position on a 0.04 m grid that holds the sections, the supports
    and the axle spacings (so every kink of the influence lines), FE influence lines there.
    """
    loads = np.array([35.6e3, 142.3e3, 142.3e3])
    offsets = np.array([0.0, 4.28, 8.56])
    length = float(np.sum(spans))
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    step = 0.04
    sections = np.round(np.array([0.25, 0.5, 0.75]) * spans[1] + spans[0], 2)
    sections = np.round(np.concatenate([sections, supports[1:2], [0.4 * spans[0]]]) / step)
    sections *= step
    positions = step * np.arange(int(round(length / step)) + 1)
    assert np.isin(np.round(supports / step), np.round(positions / step)).all()
    beam = fe_beam(spans, np.concatenate([positions, sections]))
    w, m, v = beam.influence(positions, sections)
    lines = np.stack([-w, m, v])  # (3, n_positions, n_s), displacement up
    first = np.arange(0, positions.size + int(round(offsets[-1] / step)))
    total = np.zeros((3, first.size, sections.size))
    for load, offset in zip(loads, offsets, strict=True):
        at = first - int(round(offset / step))
        on = (at >= 0) & (at < positions.size)
        total[:, on] += load * lines[:, at[on]]
    # the shear's other one-sided value with an axle over a section: the axle just left of
    # it (the shear jumps by the axle's load there), which no grid position reaches
    lower = total[2].copy()
    for load, offset in zip(loads, offsets, strict=True):
        at = first - int(round(offset / step))
        for i, x in enumerate(sections):
            over = at == int(round(x / step))
            lower[over, i] = np.minimum(lower[over, i], total[2][over, i] - load)
    brute_max = total.max(axis=1)
    brute_min = total.min(axis=1)
    brute_min[2] = lower.min(axis=0)
    env = static_envelope(spans, EI, sections, loads, offsets)
    scale = np.abs(total).max(axis=(1, 2))
    # never inside the brute force (the envelope refines between its grid points) ...
    assert np.all(env.maximum >= brute_max - 1e-7 * scale[:, None])
    assert np.all(env.minimum <= brute_min + 1e-7 * scale[:, None])
    # ... and equal to it: exactly where the extreme sits at a kink on the grid; a smooth
    # extreme between grid points (deflections, moments over supports) the grid misses by
    # about (step / 2)^2 |f''| / 2, some 1e-6 to 1e-5 of the value here
    for e in range(3):
        tolerance = {"rtol": 2e-5, "atol": 1e-7 * scale[e]}
        np.testing.assert_allclose(env.maximum[e], brute_max[e], **tolerance)
        np.testing.assert_allclose(env.minimum[e], brute_min[e], **tolerance)


def test_bad_input_is_refused_with_a_sentence() -> None:
    with pytest.raises(ValueError, match="x=70.0 must lie on the beam, 0 to 67.5 m"):
        continuous_statics(70.0, 1.0, LAYOUTS[0], EI)
    with pytest.raises(ValueError, match="load_position"):
        continuous_statics(1.0, -2.0, LAYOUTS[0], EI)
    with pytest.raises(ValueError, match="spans"):
        continuous_statics(1.0, 1.0, [10.0, 0.0], EI)
    with pytest.raises(ValueError, match="EI"):
        continuous_statics(1.0, 1.0, [10.0], -1.0)
    with pytest.raises(ValueError, match="axle_offsets"):
        static_envelope([10.0], EI, [5.0], [1.0, 2.0], [0.0])
    with pytest.raises(ValueError, match="sections"):
        static_envelope([10.0], EI, [11.0])
