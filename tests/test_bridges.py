"""Bridges of the one-coordinate model against the study's numbers and the beam formulas.

References: the study's Table 2.15.1 beam; equations (36)-(39), (62)-(65) of
model-equations.md; exact beam statics for ``reference_beam``.  (The constructors against the
printed Tables 2.13.x and 2.15.x are in ``test_study_data.py``.)
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.modes import static_deflection_line

LB_IN = u.lbf / u.inch
LB_IN2 = u.lbf * u.inch**2


def test_table_2_15_1_beam_is_the_140_ft_bridge() -> None:
    bridge = vbi.Bridge(140 * u.ft, 1, 2.196e13 * LB_IN2, 7283.3 * u.lbf / u.ft / u.g)
    assert round(bridge.first_frequency_hz, 2) == 2.08
    assert bridge.mass_per_span / u.slinch == pytest.approx(2641.0, rel=2e-4)


def test_shape_function_errors_39_65() -> None:
    assert round(vbi.shape_function_error(1), 4) == 0.0145
    assert round(vbi.shape_function_error(2), 3) == 0.314
    bridge = vbi.Bridge(25.0, 2, 1e10, 5000.0)
    ratio = bridge.static_deflection(1e5) / bridge.exact_static_deflection(1e5)
    assert ratio == pytest.approx(1 - vbi.shape_function_error(2))


def test_generalised_properties_36_37_62_63() -> None:
    L, ei, mbar = 20.0, 3e9, 4000.0
    for n in (1, 2):
        b = vbi.Bridge(L, n, ei, mbar, 0.02)
        assert b.generalized_mass == pytest.approx(n * mbar * L / 2)
        assert b.generalized_stiffness == pytest.approx(n * math.pi**4 * ei / (2 * L**3))
        assert b.circular_frequency == pytest.approx(math.pi**2 * math.sqrt(ei / (mbar * L**4)))
        assert b.generalized_damping == pytest.approx(
            2 * 0.02 * b.circular_frequency * n * mbar * L / 2
        )
    one, two = vbi.Bridge(L, 1, ei, mbar), vbi.Bridge(L, 2, ei, mbar)
    assert one.static_deflection(1.0) == pytest.approx(2 * L**3 / (math.pi**4 * ei))
    assert two.static_deflection(1.0) == pytest.approx(L**3 / (math.pi**4 * ei))


def test_reference_beam_matches_midspan_stiffness_and_frequency() -> None:
    k_mid = 721006 * u.lbf / u.inch
    for n_spans in (1, 2):
        beam = vbi.reference_beam(40 * u.ft, n_spans, k_mid, 9.98)
        assert beam.first_frequency_hz == pytest.approx(9.98, rel=1e-12)
        flexibility = static_deflection_line(beam, 1.0, 200, [beam.span / 2])[0, 0]
        assert 1 / flexibility == pytest.approx(k_mid, rel=1e-6)


# ----------------------------------------------------------------------------- bad input
@pytest.mark.parametrize(
    ("build", "message"),
    [
        (lambda: vbi.Bridge(-1.0, 1, 1e9, 1e3), "span=-1.0"),
        (lambda: vbi.Bridge(10.0, 3, 1e9, 1e3), "n_spans=3"),
        (lambda: vbi.Bridge(10.0, 1, 0.0, 1e3), "EI=0.0"),
        (lambda: vbi.Bridge(10.0, 1, 1e9, -5.0), "mass_per_length=-5.0"),
        (
            lambda: vbi.Bridge(10.0, 1, 1e9, 1e3, damping_ratio=1.0),
            r"damping_ratio=1.0 is outside \[0, 1\)",
        ),
        (lambda: vbi.Bridge(10.0, 1, 1e9, 1e3, damping_ratio=-0.1), "damping_ratio=-0.1"),
        (lambda: vbi.Vehicle(0.0, 1e6, 1e3), "mass=0.0"),
        (lambda: vbi.Vehicle(1e4, -1e6, 1e3), "stiffness=-1000000.0"),
        (lambda: vbi.Vehicle.from_frequency(1e4, 3.0, 1.2, damped=True), "damping_ratio=1.2"),
        (lambda: vbi.Vehicle.from_frequency(1e4, 3.0, -0.2), "damping_ratio=-0.2"),
        (lambda: vbi.Profile([0.0, 1.0, 1.0], [0.0, 0.0, 0.0]), "strictly increasing"),
        (lambda: vbi.Profile([0.0, np.nan, 2.0], [0.0, 0.0, 0.0]), r"profile x\[1\]=nan"),
        (lambda: vbi.Profile([0.0], [0.0]), "at least two samples"),
        (lambda: vbi.Profile([0.0, 1.0], [0.0]), "one elevation per station"),
    ],
)
def test_bad_parameters_are_named(build, message: str) -> None:  # noqa: ANN001
    with pytest.raises(ValueError, match=message):
        build()
