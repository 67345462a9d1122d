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

from vbi_lib.beam_statics import continuous_statics, field_envelope, static_envelope, support_face
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


def fe_influence(beam: Beam, loads_at: np.ndarray, sections: np.ndarray, side: str):
    """FE influence lines ``(3, n_loads, n_s)``: deflection (up), moment, and the shear on
    face ``side`` of each section, by statics from the FE support reactions (written here,
    so that the right face, which ``Beam.influence`` does not give, is independent too)."""
    from scipy.sparse.linalg import splu

    free = beam.free
    lu = splu(beam.K[free][:, free].tocsc())
    rhs = np.zeros((beam.K.shape[0], loads_at.size))
    rhs[[2 * beam.node(a) for a in loads_at], np.arange(loads_at.size)] = 1.0
    d = np.zeros_like(rhs)
    d[free] = lu.solve(rhs[free])
    reactions = -(beam.K @ d - rhs)[beam.fixed]  # (n_supports, n_loads)
    w = d[[2 * beam.node(x) for x in sections]].T
    x, a = sections[None, :], loads_at[:, None]
    length = beam.supports[-1]
    if side == "left":  # forces strictly left of the section, and at x = 0 the support's
        behind = (a < x) | ((x == 0) & (a == 0))
        support_behind = [(s < x) | ((s == 0) & (x == 0)) for s in beam.supports]
    else:  # forces at or left of the section, but not the far end's
        behind = (a <= x) & ~((x == length) & (a == length))
        support_behind = [(s <= x) & ~((s == length) & (x == length)) for s in beam.supports]
    moment = -np.where(a < x, x - a, 0.0)
    shear = -np.where(behind, 1.0, 0.0)
    for r, s, passed in zip(reactions, beam.supports, support_behind, strict=True):
        moment = moment + r[:, None] * np.where(s < x, x - s, 0.0)
        shear = shear + r[:, None] * np.where(passed, 1.0, 0.0)
    return np.stack([-w, moment, shear])


@pytest.mark.parametrize("side", ["left", "right"])
def test_both_faces_of_every_support_match_a_finite_element_beam(side: str) -> None:
    spans = LAYOUTS[1]
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    loads = np.unique(np.concatenate([np.linspace(0.0, supports[-1], 40), supports]))
    beam = fe_beam(spans, np.concatenate([supports, loads]))
    expected = fe_influence(beam, loads, supports, side)
    got = continuous_statics(supports[None, :], loads[:, None], spans, EI, side=side)
    for ours, theirs in zip((-got.deflection, got.moment, got.shear), expected, strict=True):
        np.testing.assert_allclose(ours, theirs, rtol=1e-6, atol=1e-9 * np.abs(theirs).max())
    # the faces differ by the support's reaction less a load standing on it; the reactions
    # carry the load (vertical equilibrium)
    left = continuous_statics(supports[None, 1:-1], loads[:, None], spans, EI).shear
    right = continuous_statics(supports[None, 1:-1], loads[:, None], spans, EI, side="right")
    on_support = loads[:, None] == supports[None, 1:-1]
    reactions = (right.shear - left + on_support).sum(axis=1)
    reactions += continuous_statics(0.0, loads, spans, EI, side="right").shear + (loads == 0)
    reactions -= continuous_statics(supports[-1], loads, spans, EI).shear - (loads == supports[-1])
    np.testing.assert_allclose(reactions, 1.0, atol=1e-12)


def fe_crawl(spans, loads, offsets, sections, side, direction, step=0.1):  # noqa: ANN001, ANN201
    """Brute-force envelope over every axle position on a ``step`` grid that holds the
    sections, the supports and the axle spacings (so every kink of the influence lines), FE
    influence lines there; the shear's other one-sided value with an axle over a section
    (the shear jumps by the axle's load there) is added by hand."""
    length = float(np.sum(spans))
    positions = step * np.arange(int(round(length / step)) + 1)
    beam = fe_beam(spans, np.concatenate([positions, sections]))
    lines = fe_influence(beam, positions, sections, side)  # (3, n_positions, n_s)
    shift = np.round(np.asarray(offsets) / step).astype(int)
    # forward: axle i at p - o_i; backward (turned round): at p + o_i, p the front axle
    sign = -1 if direction == "forward" else 1
    first = np.arange(-shift.max(), positions.size + shift.max())
    total = np.zeros((3, first.size, len(sections)))
    jump = np.zeros((first.size, len(sections)))
    for load, k in zip(loads, shift, strict=True):
        at = first + sign * k
        on = (at >= 0) & (at < positions.size)
        total[:, on] += load * lines[:, at[on]]
        for i, x in enumerate(sections):
            jump[(at == int(round(x / step))), i] += load
    # the other one-sided limit: passing the section takes the load off a left face's
    # shear and puts it on a right face's (at the ends, the one face on the beam)
    faces = np.where(sections == 0.0, "right", np.where(sections == length, "left", side))
    other = total[2] + np.where(faces == "left", -1.0, 1.0) * jump
    maximum, minimum = total.max(axis=1), total.min(axis=1)
    maximum[2] = np.maximum(maximum[2], other.max(axis=0))
    minimum[2] = np.minimum(minimum[2], other.min(axis=0))
    return maximum, minimum, np.abs(total).max(axis=(1, 2))


@pytest.mark.parametrize("spans", LAYOUTS[:2])
@pytest.mark.parametrize(("side", "direction"), [("left", "forward"), ("right", "backward")])
def test_axle_group_envelope_matches_a_finite_element_crawl(
    spans: list[float], side: str, direction: str
) -> None:
    """Three axles (an HS20 truck's 35.6, 142.3, 142.3 kN, about 4.3 m apart) crawl over
    the FE beam, one way or the other, with the shear on either face of the supports."""
    loads = np.array([35.6e3, 142.3e3, 142.3e3])
    offsets = np.array([0.0, 4.3, 8.6])
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    step = 0.1  # every support and spacing is a whole number of steps
    inside = np.array([0.25, 0.5, 0.75]) * spans[1] + spans[0]
    sections = np.concatenate([np.round(inside / step) * step, supports, [0.4 * spans[0]]])
    brute_max, brute_min, scale = fe_crawl(spans, loads, offsets, sections, side, direction)
    env = static_envelope(spans, EI, sections, loads, offsets, side=side, direction=direction)
    # never inside the brute force (the envelope is exact between its grid points; the FE
    # beam of 10 cm elements rounds to some 1e-7 of the largest value) ...
    assert np.all(env.maximum >= brute_max - 1e-6 * scale[:, None])
    assert np.all(env.minimum <= brute_min + 1e-6 * scale[:, None])
    # ... and equal to it: exactly where the extreme sits at a kink on the grid; a smooth
    # extreme between grid points (deflections, moments over supports) the grid misses by
    # about (step / 2)^2 |f''| / 2, some 1e-5 of the value here
    for e in range(3):
        tolerance = {"rtol": 1e-4, "atol": 1e-6 * scale[e]}
        np.testing.assert_allclose(env.maximum[e], brute_max[e], **tolerance)
        np.testing.assert_allclose(env.minimum[e], brute_min[e], **tolerance)
    inner = [support_face(x, supports, side) for x in sections]
    assert env.faces == tuple(inner) and env.direction == direction


def test_both_directions_keep_the_larger_and_say_which() -> None:
    spans, loads, offsets = LAYOUTS[0], [35.6e3, 142.3e3, 142.3e3], [0.0, 4.28, 8.56]
    x = np.linspace(0.0, float(np.sum(spans)), 23)
    one = static_envelope(spans, EI, x, loads, offsets, direction="forward")
    other = static_envelope(spans, EI, x, loads, offsets, direction="backward")
    both = static_envelope(spans, EI, x, loads, offsets, direction="both")
    np.testing.assert_array_equal(both.maximum, np.maximum(one.maximum, other.maximum))
    np.testing.assert_array_equal(both.minimum, np.minimum(one.minimum, other.minimum))
    back = both.maximum_direction == "backward"
    assert back.any() and not back.all()
    np.testing.assert_array_equal(both.maximum_at[back], other.maximum_at[back])
    # the turned truck is the mirror image: its envelope at x is the forward one at L - x
    mirror = static_envelope(spans[::-1], EI, x[::-1].max() - x, loads, offsets)
    np.testing.assert_allclose(other.maximum[1], mirror.maximum[1], rtol=1e-10, atol=1e-6)


def test_the_whole_field_holds_both_faces_of_each_support() -> None:
    spans, loads, offsets = LAYOUTS[0], [35.6e3, 142.3e3, 142.3e3], [0.0, 4.28, 8.56]
    env = field_envelope(spans, EI, loads, offsets, count=101)
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    for s in supports[1:-1]:
        at = np.flatnonzero(env.sections == s)
        assert [env.faces[i] for i in at] == ["left", "right"]
        for i, side in zip(at, ("left", "right"), strict=True):
            alone = static_envelope(spans, EI, s, loads, offsets, side=side, direction="both")
            np.testing.assert_allclose(env.maximum[:, i], alone.maximum[:, 0], rtol=1e-12)
    assert env.faces[0] == "right" and env.faces[-1] == "left"
    assert sum(face == "" for face in env.faces) == env.sections.size - 6


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
    with pytest.raises(ValueError, match="side='top' must be one of 'left', 'right'"):
        continuous_statics(1.0, 1.0, [10.0], EI, side="top")
    with pytest.raises(ValueError, match="direction='up' must be one of 'forward'"):
        static_envelope([10.0], EI, [5.0], direction="up")


def test_the_point_load_statics_are_found_where_they_were() -> None:
    """Chapters, models and studies import continuous_statics from vbi_lib.beam_statics."""
    import vbi_lib.beam_influence as influence
    import vbi_lib.beam_statics as statics

    assert statics.continuous_statics is influence.continuous_statics
    assert statics.support_face is influence.support_face and statics.SIDES == ("left", "right")
