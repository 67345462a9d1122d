"""Impact factor, DAF, code provisions and the sampling rule against hand-computed values."""

from __future__ import annotations

import math

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import amplification as amp
from vbi_lib import units as u


def test_definitions_16_to_18() -> None:
    assert amp.impact_factor(1.33, 1.0) == pytest.approx(0.33)
    assert amp.dynamic_amplification_factor(-0.66, -0.5) == pytest.approx(1.32)
    assert amp.live_load_response(2.0, 0.15) == pytest.approx(2.3)
    # DAF = 1 + IM
    assert amp.dynamic_amplification_factor(7.0, 5.0) == pytest.approx(
        1 + amp.impact_factor(7.0, 5.0)
    )


def test_zero_static_response_is_an_error() -> None:
    with pytest.raises(ValueError, match="static response is zero"):
        amp.dynamic_amplification_factor(1.0, 0.0)


def test_aashto_lrfd_table_3_6_2_1_1() -> None:
    assert amp.aashto_lrfd_allowance() == 0.33
    assert amp.aashto_lrfd_allowance("fatigue and fracture") == 0.15
    assert amp.aashto_lrfd_allowance("deck joints") == 0.75
    with pytest.raises(ValueError, match="component='wheels'"):
        amp.aashto_lrfd_allowance("wheels")


@pytest.mark.parametrize(
    ("span_ft", "expected"),
    [
        (10.0, 0.30),
        (41.0, 0.30),
        (50.0, 50 / 175),
        (100.0, 50 / 225),
        (140.0, 50 / 265),
        (375.0, 0.1),
    ],
)
def test_aashto_standard_impact(span_ft: float, expected: float) -> None:
    assert float(amp.aashto_standard_impact(span_ft * u.ft)) == pytest.approx(expected, rel=1e-12)


def test_aashto_standard_cap_switches_at_41_7_ft() -> None:
    cap_length = (50 / 0.30 - 125) * u.ft
    assert float(amp.aashto_standard_impact(cap_length * 0.999)) == pytest.approx(0.30)
    assert float(amp.aashto_standard_impact(cap_length * 1.01)) < 0.30


@pytest.mark.parametrize(
    ("frequency", "expected"),
    [
        (0.5, 0.20),
        (1.0, 0.20),
        (1.75, 0.30),
        (2.5, 0.40),
        (4.0, 0.40),
        (5.25, 0.325),
        (6.0, 0.25),
        (20.0, 0.25),
    ],
)
def test_ohbdc_1983_curve(frequency: float, expected: float) -> None:
    assert float(amp.ohbdc_1983_allowance(frequency)) == pytest.approx(expected)


def test_code_functions_reject_bad_input() -> None:
    with pytest.raises(ValueError, match="loaded_length"):
        amp.aashto_standard_impact(-3.0)
    with pytest.raises(ValueError, match="first_frequency_hz"):
        amp.ohbdc_1983_allowance(np.nan)


def test_sampling_rule_32() -> None:
    # 20 mph = 352 in/s; 352 / (2 * 15) = 11.733 in
    assert vbi.max_sample_spacing(20 * u.mph, 15.0) / u.inch == pytest.approx(352 / 30)
    assert round(vbi.max_sample_spacing(20 * u.mph, 15.0) / u.inch, 1) == 11.7
    # 32 kph and 15 Hz: 8.889 m/s / 30 = 0.2963 m ("25 cm" in the study)
    assert vbi.max_sample_spacing(32 * u.kph, 15.0) == pytest.approx(32 / 3.6 / 30)
    with pytest.raises(ValueError, match="max_frequency_hz=0"):
        vbi.max_sample_spacing(10.0, 0)


def test_units_are_si_factors() -> None:
    assert u.ft == pytest.approx(0.3048)
    assert u.kip == pytest.approx(4448.2216152605)
    assert u.slinch == pytest.approx(175.126835, rel=1e-8)
    assert u.mph == pytest.approx(0.44704)
    assert u.kph == pytest.approx(1 / 3.6)
    assert u.g == 9.80665
    assert 720 * u.inch / u.mph == pytest.approx(40.909, rel=1e-4)


def test_units_parse_text() -> None:
    assert u.parse("100 ft", "length") == pytest.approx(30.48)
    assert u.parse("65 mph", "speed") == pytest.approx(65 * 0.44704)
    assert u.parse("200 slinch", "mass") == pytest.approx(200 * 175.126835, rel=1e-8)
    assert u.parse("7.5e12 lbf * inch**2", "flexural_rigidity") == pytest.approx(
        7.5e12 * 4.4482216152605 * 0.0254**2
    )
    assert u.parse("587723 lbf/in", "stiffness") == pytest.approx(587723 * 4.4482216152605 / 0.0254)
    assert u.parse(3.5, "frequency") == 3.5
    with pytest.raises(ValueError, match="span='100 kg'.*length"):
        u.parse("100 kg", "length", name="span")
    with pytest.raises(ValueError, match="speed='fast'"):
        u.parse("fast", "speed", name="speed")
    assert math.isclose(u.parse("4.6 kip/ft", "force_per_length"), 4.6 * 4448.2216152605 / 0.3048)
