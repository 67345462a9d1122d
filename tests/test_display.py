"""Display units: one choice for the session, applied by every formatter and label."""

from __future__ import annotations

import pytest

from vbi_lib import display
from vbi_lib import units as u


@pytest.fixture(autouse=True)
def back_to_si():  # noqa: ANN201
    yield
    display.set_units("SI")


def test_us_customary_with_si_alongside() -> None:
    display.set_units("US")
    assert display.fmt(100 * u.ft, "length") == "100 ft (30.5 m)"
    assert display.fmt(60 * u.mph, "speed") == "60 mph (96.6 km/h)"
    assert display.label("deflection", "deflection") == "deflection [in]"
    assert display.value(1 * u.kip, "force") == pytest.approx(1.0)


def test_si_with_us_alongside_and_without() -> None:
    display.set_units("SI")
    assert display.fmt(30.48, "length") == "30.5 m (100 ft)"
    display.set_units("SI", alongside=False)
    assert display.fmt(30.48, "length") == "30.5 m"
    assert display.fmt(0.05, "damping_ratio") == "5 %"


def test_every_system_defines_every_quantity() -> None:
    for system in display.SYSTEMS.values():
        assert set(system.units) == set(display.QUANTITIES)


def test_unknown_choices_are_named() -> None:
    with pytest.raises(ValueError, match="system='metric'"):
        display.set_units("metric")
    with pytest.raises(ValueError, match="quantity='lenght'"):
        display.symbol("lenght")
