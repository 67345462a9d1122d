"""Modes of beams continuous over any spans, against published ratios, closed forms and FE.

References: the three-equal-span frequency ratios 1, 1.2815, 1.8713, 4.0 (Blevins,
*Formulas for Natural Frequency and Mode Shape*, beams on equally spaced supports); the
textbook modes of one span and of two equal spans (sine and propped-cantilever families),
written here; a fine beam finite-element model written in ``tests/beam_fe.py``; mass and
stiffness orthogonality by quadrature.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from beam_fe import Beam

import vbi_lib as vbi
from vbi_lib.continuous_beams import count_below, natural_wavenumbers
from vbi_lib.modes import beam_modes, propped_cantilever_roots

EI, MBAR = 4e9, 5000.0
UNEQUAL = [18.0, 27.5, 22.0]
FOUR = [15.0, 21.0, 21.0, 12.5]


def fe_modes(spans: list[float], count: int, element: float = 0.25) -> tuple[np.ndarray, Beam]:
    """FE frequencies and beam, elements no longer than ``element`` [m].

    At 0.25 m the FE frequencies of the first 25 modes are good to about 1e-6: finer
    meshes lose as much to the eigensolver's rounding (the stiffest element's eigenvalues
    grow as ``h^-4``) as they gain in discretisation.
    """
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    beam = Beam(supports, supports, EI, MBAR, element=element)
    return beam.frequencies(count)[0], beam


def test_three_equal_spans_have_blevins_frequency_ratios() -> None:
    bridge = vbi.Bridge.continuous([25.0, 25.0, 25.0], EI=EI, mass_per_length=MBAR)
    f = beam_modes(bridge, 4).frequencies_hz
    single = vbi.Bridge(25.0, 1, EI, MBAR).first_frequency_hz
    assert f / single == pytest.approx([1.0, 1.2815, 1.8713, 4.0], abs=5e-5)
    assert bridge.first_frequency_hz == pytest.approx(single, rel=1e-12)


@pytest.mark.parametrize("spans", [UNEQUAL, FOUR, [10.0, 31.0]])
def test_unequal_spans_match_a_fine_finite_element_beam(spans: list[float]) -> None:
    """Frequencies to 1e-5 (the issue asks for 0.2 %) and mode shapes at the FE nodes."""
    count = 10
    fe_omega, beam = fe_modes(spans, count)
    bridge = vbi.Bridge.continuous(spans, EI=EI, mass_per_length=MBAR)
    modes = beam_modes(bridge, count)
    np.testing.assert_allclose(modes.omega, fe_omega, rtol=1e-5)
    assert bridge.first_frequency_hz == pytest.approx(fe_omega[0] / (2 * math.pi), rel=1e-5)
    # shapes: both mass-normalised, so equal up to the sign
    _, fe_shapes = beam.frequencies(count)
    ours = modes.shape(beam.nodes)
    signs = np.sign(np.sum(ours * fe_shapes, axis=0))
    scale = np.abs(ours).max(axis=0)
    np.testing.assert_allclose(ours, fe_shapes * signs, atol=2e-5 * scale.max())


def test_no_mode_is_missed_or_counted_twice() -> None:
    """The Wittrick-Williams count equals the FE count below any frequency, up to mode 25."""
    spans = FOUR
    fe_omega, _ = fe_modes(spans, 30)
    root = math.sqrt(EI / MBAR)
    fe_k = np.sqrt(fe_omega / root)
    probes = 0.5 * (fe_k[:-1] + fe_k[1:])[:25]  # between consecutive FE roots
    assert [count_below(k, spans) for k in probes] == list(range(1, 26))
    k = natural_wavenumbers(spans, 25)
    assert np.all(np.diff(k) > 0)
    np.testing.assert_allclose(k, fe_k[:25], rtol=1e-5)


def test_one_span_and_two_equal_spans_are_the_textbook_modes() -> None:
    """The general solution reproduces the closed forms to rounding (1e-12)."""
    length = 20.0
    n_modes = 30
    x = np.linspace(0.0, length, 801)
    one = beam_modes(vbi.Bridge(length, 1, EI, MBAR), n_modes)
    n = np.arange(1, n_modes + 1)
    expected = math.sqrt(2 / (MBAR * length)) * np.sin(np.outer(x, n * math.pi / length))
    np.testing.assert_allclose(one.shape(x), expected, rtol=0, atol=1e-12 * expected.max())
    np.testing.assert_allclose(one.omega, (n * math.pi / length) ** 2 * math.sqrt(EI / MBAR),
                               rtol=1e-13)  # fmt: skip

    two = beam_modes(vbi.Bridge(length, 2, EI, MBAR), n_modes)
    xx = np.linspace(0.0, 2 * length, 1601)
    sine = [(k * math.pi / length, "sine") for k in range(1, n_modes + 1)]
    propped = [(z / length, "propped") for z in propped_cantilever_roots(n_modes)]
    families = sorted(sine + propped)[:n_modes]
    np.testing.assert_allclose(two.wavenumber, [k for k, _ in families], rtol=1e-13)
    shapes = two.shape(xx)
    for i, (k, family) in enumerate(families):
        if family == "sine":
            phi = np.sin(k * xx) / math.sqrt(MBAR * length)
        else:
            s = np.where(xx <= length, xx, 2 * length - xx)  # from the nearer outer end
            phi = np.sin(k * s) - math.sin(k * length) * np.sinh(k * s) / np.sinh(k * length)
            phi /= math.sqrt(MBAR * np.trapezoid(phi**2, xx))
        sign = np.sign(shapes[:, i] @ phi)
        assert sign == 1.0  # the same convention: slope positive at the start
        scale = np.abs(phi).max()
        # the propped family is normalised here by the trapezoid rule (error ~1e-7)
        atol = 1e-12 if family == "sine" else 1e-6
        np.testing.assert_allclose(shapes[:, i], phi, rtol=0, atol=atol * scale)


@pytest.mark.parametrize("spans", [UNEQUAL, FOUR])
def test_modes_of_any_layout_are_orthonormal_and_meet_the_supports(spans: list[float]) -> None:
    bridge = vbi.Bridge.continuous(spans, EI=EI, mass_per_length=MBAR)
    modes = beam_modes(bridge, 12)
    x = np.linspace(0.0, bridge.length, 60001)
    phi = modes.shape(x)
    mass = MBAR * np.trapezoid(phi[:, :, None] * phi[:, None, :], x, axis=0)
    np.testing.assert_allclose(mass, np.eye(12), atol=1e-6)
    curvature = modes.curvature(x)
    stiffness = EI * np.trapezoid(curvature[:, :, None] * curvature[:, None, :], x, axis=0)
    np.testing.assert_allclose(stiffness / np.outer(modes.omega, modes.omega), np.eye(12),
                               atol=1e-5)  # fmt: skip
    supports = np.array(bridge.supports)
    assert modes.shape(supports) == pytest.approx(np.zeros((supports.size, 12)), abs=1e-12)
    ends = modes.curvature([0.0, bridge.length]) / np.abs(curvature).max()
    assert ends == pytest.approx(np.zeros((2, 12)), abs=1e-10)
    # slope and moment continuous over the interior supports
    for s in supports[1:-1]:
        for order in (1, 2):
            left = modes.derivative(s - 1e-7, order)
            right = modes.derivative(s + 1e-7, order)
            scale = np.abs(modes.derivative(x[::100], order)).max()
            np.testing.assert_allclose(left, right, atol=1e-5 * scale)


def test_high_modes_stay_accurate() -> None:
    """Mode 60 of a five-span beam: unit mass, zero deflection at the supports."""
    bridge = vbi.Bridge.continuous([20.0, 25.0, 30.0, 25.0, 20.0], EI=EI, mass_per_length=MBAR)
    modes = beam_modes(bridge, 60)
    x = np.linspace(0.0, bridge.length, 200001)
    phi = modes.shape(x)[:, -5:]
    np.testing.assert_allclose(MBAR * np.trapezoid(phi**2, x, axis=0), 1.0, rtol=1e-6)
    assert np.abs(modes.shape(np.array(bridge.supports))).max() < 1e-10 * np.abs(phi).max()


# ---------------------------------------------------------------------------- the bridge
def test_continuous_bridge_layout_and_the_study_beam() -> None:
    bridge = vbi.Bridge.continuous(UNEQUAL, EI=EI, mass_per_length=MBAR, damping_ratio=0.02)
    assert bridge.n_spans == 3 and bridge.span == 27.5 and bridge.spans == tuple(UNEQUAL)
    assert bridge.supports == (0.0, 18.0, 45.5, 67.5)
    assert bridge.midspans == (9.0, 31.75, 56.5)
    assert bridge.length == 67.5
    assert not bridge.study_layout and not bridge.equal_spans
    # one span and two equal spans are the study's bridges, equal and hashed alike
    same = vbi.Bridge.continuous([20.0, 20.0], EI=EI, mass_per_length=MBAR)
    assert same == vbi.Bridge(20.0, 2, EI, MBAR) and hash(same) == hash(
        vbi.Bridge(20.0, 2, EI, MBAR)
    )
    assert beam_modes(same, 4) is beam_modes(vbi.Bridge(20.0, 2, EI, MBAR), 4)
    assert same.study_layout and "2 spans x 20.00 m" in repr(same)
    assert "18.00 + 27.50 + 22.00 m" in repr(bridge)
    # the study's bridges stay plain dataclasses: replace() changes a span as before
    longer = dataclasses.replace(vbi.Bridge(20.0, 2, EI, MBAR), span=25.0)
    assert longer.spans == (25.0, 25.0) and longer.supports == (0.0, 25.0, 50.0)
    stiffer = dataclasses.replace(bridge, EI=2 * EI)
    assert stiffer.spans == bridge.spans and stiffer.EI == 2 * EI


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda b: b.generalized_mass, NotImplementedError, "model='modal'"),
        (lambda b: b.static_deflection(1.0), NotImplementedError, r"spans \(18.0, 27.5, 22.0\)"),
        (lambda b: b.exact_static_deflection(1.0), NotImplementedError, "beam_statics"),
        (lambda b: b.mass_per_span, ValueError, "mass_per_length \\* spans"),
    ],
)
def test_the_study_formulas_refuse_other_layouts(call, error, match: str) -> None:  # noqa: ANN001
    bridge = vbi.Bridge.continuous(UNEQUAL, EI=EI, mass_per_length=MBAR)
    with pytest.raises(error, match=match):
        call(bridge)


def test_bad_layouts_are_named() -> None:
    with pytest.raises(ValueError, match=r"spans\[1\]=-3.0 must be from 1 to 2000 m"):
        vbi.Bridge.continuous([10.0, -3.0], EI=EI, mass_per_length=MBAR)
    with pytest.raises(ValueError, match="one or more span lengths"):
        vbi.Bridge.continuous([], EI=EI, mass_per_length=MBAR)
    with pytest.raises(ValueError, match=r"n_spans=3 .*Bridge.continuous"):
        vbi.Bridge(10.0, 3, EI, MBAR)
    with pytest.raises(ValueError, match="must be the longest span"):
        vbi.Bridge(10.0, 2, EI, MBAR, span_lengths=(10.0, 12.0))
    with pytest.raises(ValueError, match="EI=0.0"):
        vbi.Bridge.continuous([10.0, 12.0], EI=0.0, mass_per_length=MBAR)
    with pytest.raises(ValueError, match="count=0"):
        natural_wavenumbers([10.0], 0)
