"""AASHTO's design vehicles, permit vehicles and the governing rear axle spacing.

References: AASHTO LRFD Bridge Design Specifications 3.6.1.2.2 (design truck: 8, 32 and 32
kip; 14 ft, then 14 to 30 ft) and 3.6.1.2.3 (design tandem: 2 x 25 kip, 4 ft), written here
as numbers; the closed-form influence line of the moment over the middle support of two
equal spans, ``M = -P a (L^2 - a^2) / (4 L^2)`` with ``a`` from the load's end support
(three-moment equation; e.g. Timoshenko & Young, *Theory of Structures*), crawled by brute
force.
"""

from __future__ import annotations

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.vehicles import (
    governing_rear_spacing,
    hl93_tandem,
    hl93_truck,
    hs20,
    permit_vehicle,
)

KIP, FT = 4448.2216152605, 0.3048


@pytest.mark.parametrize("make", [hs20, hl93_truck])
@pytest.mark.parametrize("rear", [14, 22.5, 30])
def test_the_design_truck_has_aashtos_axles(make, rear: float) -> None:  # noqa: ANN001
    truck = make(rear * FT)
    system = vbi.vehicles.as_system(truck)
    np.testing.assert_allclose(system.static_loads, np.array([8, 32, 32]) * KIP, rtol=1e-12)
    np.testing.assert_allclose(system.offsets, np.array([0, 14, 14 + rear]) * FT, rtol=1e-12)
    assert f"{rear:g} ft rear spacing" in truck.name
    with pytest.raises(ValueError, match=r"rear_spacing=.* is outside AASHTO's 14 to 30 ft"):
        make(31 * FT)


@pytest.mark.parametrize("body", ["independent", "rigid"])
@pytest.mark.parametrize("tyres", [True, False])
def test_the_design_tandem_is_two_25_kip_axles_4_ft_apart(body: str, tyres: bool) -> None:
    tandem = hl93_tandem(body=body, tyres=tyres)
    system = vbi.vehicles.as_system(tandem)
    np.testing.assert_allclose(system.static_loads, [25 * KIP, 25 * KIP], rtol=1e-12)
    np.testing.assert_allclose(system.offsets, [0.0, 4 * FT], rtol=1e-12)
    assert system.has_unilateral == tyres
    # it runs: a crawl over a simple span has a DAF of one
    bridge = vbi.Bridge(20.0, 1, 4e9, 6000.0)
    road = vbi.Profile.flat(45.0, 0.05, start=-5.0)
    run = vbi.simulate(bridge, tandem, road, 1.0, 10.0, model="modal", modes=4)
    assert run.sections([10.0]).daf[1, 0] == pytest.approx(1.0, abs=0.01)


def test_a_permit_vehicle_takes_any_axles() -> None:
    loads = np.array([12, 34, 34, 34, 34]) * KIP
    spacings = np.array([14, 4, 30, 4]) * FT
    truck = permit_vehicle(loads, spacings, name="five-axle permit")
    system = vbi.vehicles.as_system(truck)
    np.testing.assert_allclose(system.static_loads, loads, rtol=1e-12)
    np.testing.assert_allclose(system.offsets, np.concatenate([[0], np.cumsum(spacings)]))
    assert truck.name.startswith("five-axle permit (")
    # a light axle carries at most 15 % of its load as unsprung mass
    light = permit_vehicle([2 * KIP, 20 * KIP], [10 * FT])
    assert light.axles[0].tyre.unsprung_mass == pytest.approx(0.15 * 2 * KIP / u.g)
    # one axle alone
    assert vbi.vehicles.as_system(permit_vehicle([20 * KIP], [])).n_axles == 1


@pytest.mark.parametrize(
    ("loads", "spacings", "error", "message"),
    [
        ([10e3, 20e3], [], ValueError, r"axle_spacings=\[\] must hold 1 values, got 0"),
        ([10e3, 20e3], [0.0], ValueError, r"axle_spacings\[0\]=0.0 must be a distance > 0"),
        ("10 kN", [], TypeError, r"axle_loads='10 kN' must be a list of numbers"),
        ([10e3, "x"], [3.0], TypeError, r"axle_loads\[1\]='x' must be a number"),
        ([], [], ValueError, r"axle_loads=\[\] must hold 1 to 20 values"),
        ([10e3, 20e3], [150.0], ValueError, r"offset=150.0 must be from 0 to 100 m"),
    ],
)
def test_bad_axles_are_refused_by_name(loads, spacings, error, message) -> None:  # noqa: ANN001
    with pytest.raises(error, match=message):
        permit_vehicle(loads, spacings)


def two_span_support_moment(span: float, rear: float) -> float:
    """Largest negative moment over the middle support of two equal spans under the design
    truck with ``rear`` spacing, crawled in 1 mm steps, from the closed-form influence line
    (both directions: the truck and its mirror image)."""
    loads = np.array([8, 32, 32]) * KIP
    offsets = np.array([0.0, 14 * FT, 14 * FT + rear])

    def line(x: np.ndarray) -> np.ndarray:  # x from the first support, 0 to 2 L
        a = np.where(x <= span, x, 2 * span - x)  # from the load's own end support
        inside = (x >= 0) & (x <= 2 * span)
        return np.where(inside, -a * (span**2 - a**2) / (4 * span**2), 0.0)

    first = np.arange(0.0, 2 * span + offsets[-1], 1e-3)
    forward = sum(p * line(first - o) for p, o in zip(loads, offsets, strict=True))
    backward = sum(p * line(first + o - offsets[-1]) for p, o in zip(loads, offsets, strict=True))
    return float(min(forward.min(), backward.min()))


@pytest.mark.parametrize("span_ft", [20, 30, 40])
def test_the_governing_rear_spacing_is_the_brute_force_one(span_ft: float) -> None:
    span = span_ft * FT
    found = governing_rear_spacing([span, span], 1e10, [span])
    spacings = np.arange(14, 30.25, 0.5) * FT
    brute = np.array([two_span_support_moment(span, s) for s in spacings])
    np.testing.assert_allclose(found.extreme[:, 1, 0], brute, rtol=1e-6)
    assert found.governing[1, 0] == pytest.approx(spacings[np.argmin(brute)])
    assert found.value[1, 0] == pytest.approx(brute.min(), rel=1e-6)
    # midspan positive moment: the axles close together
    midspan = governing_rear_spacing([span, span], 1e10, [span / 2]).governing[1, 0]
    assert midspan == pytest.approx(14 * FT)
    table = found.to_dataframe()
    assert list(table.effect) == ["displacement", "moment", "shear"]


def test_a_spacing_range_outside_aashtos_is_refused() -> None:
    with pytest.raises(ValueError, match=r"high=.* is outside AASHTO's 14 to 30 ft"):
        governing_rear_spacing([20.0], 1e10, [10.0], 14 * FT, 40 * FT)
    with pytest.raises(ValueError, match=r"high=.* must not be below low"):
        governing_rear_spacing([20.0], 1e10, [10.0], 20 * FT, 16 * FT)
