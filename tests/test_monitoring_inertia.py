"""Strain versus displacement amplification (study 19-31) against beam statics and closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from vbi_lib import monitoring as mon
from vbi_lib.closed_forms import point_load_statics


def test_first_mode_coefficients_are_the_closed_forms() -> None:
    assert mon.DISPLACEMENT_INERTIA_COEFFICIENT == pytest.approx(0.4927671, rel=1e-6)
    assert mon.STRAIN_INERTIA_COEFFICIENT == pytest.approx(0.4052847, rel=1e-6)
    assert float(mon.displacement_daf(1.0, 1.0)) == pytest.approx(1.0 + 48 / math.pi**4)
    assert float(mon.strain_daf(1.0, 1.0)) == pytest.approx(1.0 + 4 / math.pi**2)


def test_ratio_of_extra_terms_is_twelve_over_pi_squared() -> None:
    # (28): 1.216, whatever A_v and r
    assert mon.extra_amplification_ratio(1) == pytest.approx(1.2158542, rel=1e-6)
    r = np.array([0.05, 0.3, 2.0])
    extra_d = mon.displacement_daf(1.17, r) - 1.17
    extra_s = mon.strain_daf(1.17, r) - 1.17
    np.testing.assert_allclose(extra_d / extra_s, 12 / math.pi**2, rtol=1e-12)
    assert np.all(extra_d > extra_s)


@pytest.mark.parametrize("n", [1, 2, 3, 5, 7])
def test_mode_n_ratio(n: int) -> None:
    assert mon.extra_amplification_ratio(n) == pytest.approx(12 / (n**2 * math.pi**2))


def _midspan_by_superposition(n: int, span: float = 7.0) -> tuple[float, float]:
    """Midspan deflection x EI and moment of a simply supported beam under sin(n pi x / L).

    Integrates the midspan influence lines of a point load (closed_forms.point_load_statics,
    itself checked against a beam finite-element model), an independent route to the inertia
    terms of (20), (22).
    """
    # Gauss-Legendre on each half (the influence lines are smooth there): exact to rounding
    nodes, weights = np.polynomial.legendre.leggauss(40)
    w = m = 0.0
    for lo, hi in ((0.0, span / 2), (span / 2, span)):
        a = lo + (hi - lo) * (nodes + 1) / 2
        c = weights * (hi - lo) / 2 * np.sin(n * math.pi * a / span)
        lines = point_load_statics(span / 2, a, span, EI=1.0)
        w += float(c @ lines.deflection)
        m += float(c @ lines.moment)
    return w, m


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_inertia_terms_match_beam_statics(n: int) -> None:
    span, beam_mass, acceleration, force = 7.0, 1.0, 1.0, 1.0
    w_unit, m_unit = _midspan_by_superposition(n, span)
    q = beam_mass * acceleration / span  # load amplitude (24)
    midspan = point_load_statics(span / 2, span / 2, span, EI=1.0, force=force)
    w_point = float(midspan.deflection)  # (19) times EI: P L^3 / 48
    m_point = float(midspan.moment)  # (21) over c / I: P L / 4
    r = mon.inertia_ratio(beam_mass, acceleration, force)
    assert float(mon.displacement_daf(0.0, r, modes=n)) == pytest.approx(
        q * w_unit / w_point, rel=1e-9, abs=1e-12
    )
    assert float(mon.strain_daf(0.0, r, modes=n)) == pytest.approx(
        q * m_unit / m_point, rel=1e-9, abs=1e-12
    )


def test_several_modes_sum_term_by_term() -> None:
    r = np.array([[0.4, 0.3, -0.2], [0.1, 0.0, 0.5]])
    modes = [1, 2, 3]
    d = 1.05 + 48 / math.pi**4 * (r[:, 0] - r[:, 2] / 81)
    s = 1.05 + 4 / math.pi**2 * (r[:, 0] - r[:, 2] / 9)
    np.testing.assert_allclose(mon.displacement_daf(1.05, r, modes), d, rtol=1e-12)
    np.testing.assert_allclose(mon.strain_daf(1.05, r, modes), s, rtol=1e-12)


def test_algebra_rejects_bad_input() -> None:
    with pytest.raises(ValueError, match="one ratio per mode"):
        mon.displacement_daf(1.0, [0.1, 0.2], modes=[1, 2, 3])
    with pytest.raises(ValueError, match="modes"):
        mon.strain_daf(1.0, 0.1, modes=0)
    with pytest.raises(ValueError, match="beam_mass"):
        mon.inertia_ratio(-1.0, 0.1, 1.0)
    with pytest.raises(ValueError, match="inertia_ratio"):
        mon.strain_daf(1.0, float("nan"))
