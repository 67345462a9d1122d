"""Strict reading of quantities: one finite number, one unit pint knows, the right dimension."""

from __future__ import annotations

import pytest

from vbi_lib import units as u


@pytest.mark.parametrize(
    ("text", "kind", "si"),
    [
        ("140 ft", "length", 140 * 0.3048),
        ("  42.5   m ", "length", 42.5),
        ("200 lbf*s**2/in", "mass", 200 * 4.4482216152605 / 0.0254),
        ("200 slinch", "mass", 200 * 4.4482216152605 / 0.0254),
        ("35 t", "mass", 35000.0),
        ("7.5e12 lbf in**2", "flexural_rigidity", 7.5e12 * 4.4482216152605 * 0.0254**2),
        ("222278 lbf/in", "stiffness", 222278 * 4.4482216152605 / 0.0254),
        ("70 km/h", "speed", 70 / 3.6),
        ("-3 ft", "length", -0.9144),
        (".5 Hz", "frequency", 0.5),
        ("2 %", "dimensionless", 0.02),
    ],
)
def test_one_number_and_one_unit_is_read(text: str, kind: str, si: float) -> None:
    reading = u.read_quantity(text, kind, name="x")
    assert reading.si == pytest.approx(si, rel=1e-12)
    assert reading.text == " ".join(text.split())


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("100,5 ft", "x='100,5 ft' has a comma in its number.*'100.5 ft' or '1005 ft'"),
        ("30; 45 mph", "x='30; 45 mph' holds a comma or semicolon"),
        ("30 mph, 45 mph", "holds a comma or semicolon.*YAML list"),
        ("30 45 mph", "x='30 45 mph' holds more than one number"),
        ("3 m2", "holds more than one number"),
        ("nan mph", "x='nan mph' is not a finite number"),
        ("-inf mph", "is not a finite number"),
        ("1e999 mph", "x='1e999 mph' is not a finite number"),
        ("45", "x='45' has no unit"),
        ("", "x='' is empty"),
        ("fast", "x='fast' does not start with a number"),
        ("45 mqh", "'mqh' is not a unit pint knows"),
        ("45 kg", "x='45 kg' has units 'kg' but a speed"),
    ],
)
def test_anything_else_is_refused_with_its_name(text: str, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        u.read_quantity(text, "speed", name="x")


@pytest.mark.parametrize("value", [45, 4.5, None, True, ["45 mph"]])
def test_a_quantity_must_be_text(value: object) -> None:
    with pytest.raises(ValueError, match=r"must be text with one number and one unit"):
        u.read_quantity(value, "speed", name="x")


def test_parse_is_strict_on_text_and_passes_si_numbers() -> None:
    assert u.parse(3.5, "frequency") == 3.5
    with pytest.raises(ValueError, match="comma"):
        u.parse("100,5 ft", "length", name="span")
    with pytest.raises(ValueError, match="not a finite number"):
        u.parse(float("nan"), "length", name="span")
