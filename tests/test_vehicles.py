"""Sprung-mass trucks against the study's Tables 2.13.9, 2.13.10 and 2.15.4 (equation 85)."""

from __future__ import annotations

import pytest

import vbi_lib as vbi
from vbi_lib import units as u

LB_IN = u.lbf / u.inch


@pytest.mark.parametrize(
    ("f_damped", "k", "c"),
    [(10.5, 8.7929e5, 2652.23), (4.5, 1.6150e5, 1136.67), (2.5, 4.9846e4, 631.48)],
)
def test_table_2_13_9_vehicles_from_damped_frequency(f_damped: float, k: float, c: float) -> None:
    vehicle = vbi.Vehicle.from_frequency(200 * u.slinch, f_damped, 0.10, damped=True)
    assert f"{vehicle.stiffness / LB_IN:.4e}" == f"{k:.4e}"
    assert round(vehicle.damping / LB_IN, 2) == pytest.approx(c, abs=0.006)
    assert vehicle.damped_frequency_hz == pytest.approx(f_damped)
    assert vehicle.damping_ratio == pytest.approx(0.10)


def test_table_2_13_10_vehicle_from_undamped_frequency() -> None:
    vehicle = vbi.Vehicle.from_frequency(200 * u.slinch, 2.8, 0.20)
    assert round(vehicle.stiffness / LB_IN, 1) == pytest.approx(61902.2, abs=0.06)
    assert round(vehicle.damping / LB_IN, 2) == pytest.approx(1407.43, abs=0.006)
    assert vehicle.frequency_hz == pytest.approx(2.8)


@pytest.mark.parametrize(("f", "k"), [(2, 31582.7), (3, 71061.2), (4, 126330.9), (5, 197392.1)])
def test_table_2_15_4_trucks(f: float, k: float) -> None:
    vehicle = vbi.Vehicle.from_frequency(200 * u.slinch, f, 0.10)
    assert round(vehicle.stiffness / LB_IN, 1) == pytest.approx(k, abs=0.06)
