"""The three contacts of the study's truck, compared crossing by crossing.

References: physics, not captured numbers.  A contact that can lift off is the bilateral
contact as long as the force stays compressive (and the two run on different kernels); a
quarter car whose axle is light and whose tyre is stiff tends to the sprung mass it carries;
a bump that throws the truck off the road makes the bilateral force tensile and the others
fly; a converged integrator changes a smooth crossing's DAF by far less than 1 % when its
step is halved.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib.tyre_contact import IDEALISATIONS, compare_contact, contact_variants

BRIDGE = vbi.Bridge(20.0, 1, 4e9, 6000.0)
TRUCK = vbi.Vehicle.from_frequency(2e4, 4.0, 0.1)
GENTLE = vbi.Profile.harmonic(70.0, 0.02, 5.0, 0.002)
BUMP = vbi.Profile.bump(70.0, 0.02, position=45.0, height=0.04, width=1.0)


def test_variants_are_the_same_truck_with_other_contacts() -> None:
    cars = contact_variants(TRUCK, unsprung_fraction=0.1, tyre_stiffness_ratio=10.0)
    assert list(cars) == list(IDEALISATIONS)
    assert cars["bilateral"] is TRUCK
    lift, sprung = cars["lift-off"], TRUCK.system
    for name in ("mass", "stiffness", "damping", "contact", "static_loads", "contact_stiffness",
                 "contact_damping", "footprint"):  # fmt: skip
        np.testing.assert_array_equal(getattr(lift, name), getattr(sprung, name))
    assert lift.unilateral.tolist() == [True] and sprung.unilateral.tolist() == [False]
    car = cars["quarter car"]
    assert car.sprung_mass == TRUCK.mass and car.unsprung_mass == pytest.approx(0.1 * TRUCK.mass)
    assert car.suspension_stiffness == TRUCK.stiffness
    assert car.suspension_damping == TRUCK.damping
    assert car.tyre_stiffness == pytest.approx(10.0 * TRUCK.stiffness)
    assert car.unilateral and car.footprint == vbi.vehicles.DEFAULT_FOOTPRINT
    assert car.weight == pytest.approx(1.1 * TRUCK.weight)


def test_lift_off_is_the_bilateral_contact_while_it_stays_compressive() -> None:
    """Same equations while R > 0: the general kernel reproduces the sprung-mass kernel."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no contact loss, so no warning
        result = compare_contact(BRIDGE, TRUCK, GENTLE, [12.0, 20.0], 40.0, footprint=0.0)
    assert not result.lost_contact.any()
    assert (result.min_contact_force_ratio > 0.2).all()
    np.testing.assert_allclose(result.daf[:, :, 1], result.daf[:, :, 0], rtol=1e-6)
    assert (result.daf > 1.1).all()  # the road does excite the bridge


def test_quarter_car_tends_to_the_sprung_mass() -> None:
    """A light axle on a stiff tyre: the quarter car becomes the study's sprung mass."""
    gaps = []
    for fraction, ratio in ((0.03, 30.0), (0.005, 250.0)):  # axle hop 160, 900 Hz
        result = compare_contact(BRIDGE, TRUCK, GENTLE, [12.0, 20.0], 40.0, footprint=0.0,
                                 unsprung_fraction=fraction, tyre_stiffness_ratio=ratio,
                                 step_factors=(1.0,))  # fmt: skip
        gaps.append(np.abs(result.daf[0, :, 2] / result.daf[0, :, 0] - 1.0).max())
    assert gaps[1] < 2e-3
    assert gaps[1] < gaps[0] / 2


def test_a_bump_throws_the_truck_off_the_road() -> None:
    with pytest.warns(vbi.ContactLossWarning, match="2 of 2 crossings lost contact"):
        result = compare_contact(BRIDGE, TRUCK, BUMP, [15.0, 25.0], 40.0)
    first = np.s_[0, :, :]
    assert result.outside_validity[first][:, 0].all()  # bilateral: tension, outside validity
    assert (result.min_contact_force_ratio[first][:, 0] < 0).all()
    for k in (1, 2):  # the others fly: no tension, a share of the time in the air
        assert not result.outside_validity[first][:, k].any()
        assert (result.min_contact_force_ratio[first][:, k] == 0.0).all()
        assert (result.flight_fraction[first][:, k] > 0.0).all()
    assert (result.flight_fraction[first][:, 0] == 0.0).all()
    assert result.lost_contact.all()
    table = result.summary()
    assert table.loc[("bilateral", 1.0), "outside validity"] == 2
    assert table.loc[("lift-off", 1.0), "lost contact"] == 2
    assert np.isnan(table.loc[("lift-off", 1.0), "worst DAF, contact kept"])
    assert "lost contact 2, 2, 2" in repr(result)


def test_each_crossing_is_rerun_at_half_its_own_step() -> None:
    result = compare_contact(BRIDGE, TRUCK, GENTLE, [12.0, 20.0], 40.0)
    assert result.step_factors == (1.0, 0.5)
    np.testing.assert_allclose(result.dt[1], 0.5 * result.dt[0], rtol=1e-9)
    assert len(np.unique(result.dt[0])) > 1  # the crossings had different default steps
    np.testing.assert_allclose(result.daf[1], result.daf[0], rtol=1e-3)  # converged
    sensitivity = result.step_sensitivity()
    assert list(sensitivity.index.get_level_values(0)) == list(IDEALISATIONS)
    assert (sensitivity["largest change [%]"] < 0.1).all()
    assert (sensitivity["changed by > 1 %"] == 0).all()


def test_summary_counts_and_statistics() -> None:
    with pytest.warns(vbi.ContactLossWarning):
        result = compare_contact(BRIDGE, TRUCK, [GENTLE, BUMP, GENTLE], [12.0, 25.0, 20.0], 40.0)
    table = result.summary()
    assert table.shape[0] == 6 and (table["crossings"] == 3).all()
    for k, name in enumerate(IDEALISATIONS):
        row = table.loc[(name, 1.0)]
        daf = result.daf[0, :, k]
        assert row["worst DAF"] == daf.max() and row["mean DAF"] == pytest.approx(daf.mean())
        assert row["median DAF"] == daf[np.argsort(daf)[1]]
        assert row["lost contact"] == 1 and row["lost contact [%]"] == pytest.approx(100 / 3)
        assert row["worst DAF, contact kept"] == max(daf[0], daf[2])
    frame = result.to_dataframe()
    assert len(frame) == 2 * 3 * 3
    assert frame["lost contact"].sum() == 2 * 3  # the bump crossing, at both steps
    each = result.crossings()
    assert each.shape == (3, 6) and each.index.name == "crossing"
    np.testing.assert_array_equal(each["DAF, lift-off"], result.daf[0, :, 1])
    assert each.loc[1, "min F_c / P, bilateral"] < 0 < each.loc[1, "in the air [%], lift-off"]
    assert each.loc[0, "in the air [%], quarter car"] == 0.0
    with pytest.raises(IndexError, match="step=2 must index step_factors"):
        result.crossings(2)


def test_plots_label_their_axes() -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    result = compare_contact(BRIDGE, TRUCK, GENTLE, [12.0, 20.0], 40.0)
    ax = result.plot()
    assert "bilateral" in ax.get_xlabel() and ax.get_legend() is not None
    ax = result.plot(kind="step")
    assert "0.5" in ax.get_ylabel()
    plt.close("all")
    with pytest.raises(ValueError, match="kind='contact' is not known"):
        result.plot(kind="contact")


def test_bad_input_is_named() -> None:
    car = vbi.QuarterCar.from_vehicle(TRUCK, 2e3, 1e8)
    with pytest.raises(TypeError, match=r"vehicles\[1\]: vehicle must be the study's sprung"):
        compare_contact(BRIDGE, [TRUCK, car], GENTLE, 12.0, 40.0)
    with pytest.raises(ValueError, match=r"step_factors=\(1.0, 2.0\) must be"):
        compare_contact(BRIDGE, TRUCK, GENTLE, 12.0, 40.0, step_factors=(1.0, 2.0))
    with pytest.raises(ValueError, match="step factor=-0.5 must be a finite number"):
        compare_contact(BRIDGE, TRUCK, GENTLE, 12.0, 40.0, step_factors=(1.0, -0.5))
    with pytest.raises(ValueError, match="unsprung_fraction=0 must be"):
        contact_variants(TRUCK, unsprung_fraction=0)
    with pytest.raises(ValueError, match="list arguments must have one length"):
        compare_contact(BRIDGE, TRUCK, GENTLE, [12.0, 15.0], [40.0, 40.0, 40.0])
    single = compare_contact(BRIDGE, TRUCK, GENTLE, 12.0, 40.0, step_factors=(1.0,))
    with pytest.raises(ValueError, match="holds one step"):
        single.step_sensitivity()
