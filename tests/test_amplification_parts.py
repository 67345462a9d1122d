"""A section's DAF split into axle forces and bridge inertia.

References: a truck crawling over a flat road (no dynamics: the forces are the whole DAF of
1); the exact statics of one simple span and two equal spans written independently in
:func:`vbi_lib.closed_forms.point_load_statics` (the forces part recomputed from the axle
forces and positions the crossing reports); a truck whose axles have all left the bridge
(no forces, the inertia is the whole response).  What a mode adds: on a simple span under
one axle, mode k's deflection at midspan over the static one, scaled to the same largest
deflection, is 1 and its moment over the static PL/4 is k^2 pi^2 / 12 (closed forms).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib.amplification_parts import (
    amplification_parts,
    amplification_parts_over,
    mode_contributions,
)
from vbi_lib.beam_statics import EFFECTS
from vbi_lib.closed_forms import point_load_statics
from vbi_lib.vehicles import Axle, IndependentAxles

SPAN = 20.0
TRUCK = vbi.Vehicle.from_frequency(2e4, 4.0, 0.1)
TWO_AXLES = IndependentAxles([Axle(0.0, 8e4, 3e6, 3e4), Axle(5.0, 1.6e5, 6e6, 6e4)])


def test_a_crawling_truck_is_all_forces() -> None:
    bridge = vbi.Bridge(SPAN, 2, 4e9, 6000.0)
    run = vbi.simulate(bridge, TWO_AXLES, vbi.Profile.flat(80.0, 0.05), 0.3, 20.0,
                       model="modal", modes=6)  # fmt: skip
    parts = amplification_parts(run, run.sections([0.4 * SPAN, SPAN, 1.5 * SPAN]))
    assert len(parts) == 9 and list(parts.effect.unique()) == list(EFFECTS)
    deflection_over_support = (parts.effect == "displacement") & (parts.section == SPAN)
    assert parts[deflection_over_support][["daf", "forces", "inertia"]].isna().all(axis=None)
    rest = parts[~deflection_over_support]
    np.testing.assert_allclose(rest.daf, 1.0, atol=5e-3)
    np.testing.assert_allclose(rest.forces, 1.0, atol=5e-3)
    np.testing.assert_allclose(rest["force ratio"], 1.0, atol=1e-3)
    np.testing.assert_allclose(rest.inertia, 0.0, atol=5e-3)


@pytest.mark.parametrize("n_spans", [1, 2])
def test_forces_part_from_independent_statics(n_spans: int) -> None:
    """The forces part is sum_i R_i eta(x, a_i) over the static extreme, at the extreme."""
    bridge = vbi.Bridge(SPAN, n_spans, 4e9, 6000.0)
    road = vbi.Profile.iso8608(SPAN * n_spans + 60.0, 0.02, iso_class="B", seed=4)
    run = vbi.simulate(bridge, TWO_AXLES, road, 22.0, 30.0, model="modal", modes=6)
    sections = np.array([0.3, 0.5, 0.9]) * SPAN
    response = run.sections(sections)
    parts = amplification_parts(run, response)
    loads = TWO_AXLES.system.static_loads
    for row in parts.rename(columns={"force ratio": "force_ratio"}).itertuples():
        e = EFFECTS.index(row.effect)
        j = int(np.flatnonzero(sections == row.section)[0])
        k = int(np.argmin(np.abs(run.time - row.time)))
        assert response.history(row.effect)[k, j] == pytest.approx(
            (response.static.maximum if row.sense == "max" else response.static.minimum)[e, j]
            * row.daf
        )
        a = run.axle_position[k] - run.bridge_start
        on = (a >= 0) & (a <= bridge.length)
        total = 0.0
        for force, position in zip(run.axle_contact_force[k, on], a[on], strict=True):
            s = point_load_statics(row.section, position, SPAN, bridge.EI, n_spans, force)
            total += (-s.deflection, s.moment, s.shear)[e]
        static = response.static.maximum if row.sense == "max" else response.static.minimum
        assert row.forces == pytest.approx(total / static[e, j], rel=1e-9, abs=1e-12)
        assert row.daf == pytest.approx(row.forces + row.inertia)
        ratio = run.axle_contact_force[k, on].sum() / loads[on].sum()
        assert row.force_ratio == pytest.approx(ratio)
    assert (parts.inertia.abs() > 1e-3).any()  # the bridge does vibrate


def test_after_the_truck_has_left_it_is_all_inertia() -> None:
    """A very fast force on a simple span: the extremes come in free vibration, in mode 1.

    Then the forces part is zero and the DAFs of the midspan deflection and moment are in
    the ratio of the study's equation 28, 12 / pi^2 (one mode: deflection
    ``phi q`` over ``P L^3 / 48 EI``, moment ``EI (pi / L)^2 phi q`` over ``P L / 4``).
    """
    bridge = vbi.Bridge(SPAN, 1, 4e9, 6000.0, damping_ratio=0.0)
    run = vbi.simulate(bridge, TRUCK, vbi.Profile.flat(40.0, 0.05), 160.0, 20.0,
                       coupled=False, free_vibration=1.0)  # fmt: skip
    parts = amplification_parts(run, run.sections([0.5 * SPAN])).set_index("effect")
    left = (20.0 + SPAN) / 160.0
    for effect in ("displacement", "moment"):
        row = parts.loc[effect]
        assert row.time > left
        assert row.forces == 0.0 and np.isnan(row["force ratio"])
        assert row.inertia == row.daf
    ratio = parts.loc["displacement", "daf"] / parts.loc["moment", "daf"]
    assert ratio == pytest.approx(12 / np.pi**2, rel=1e-6)


def test_bad_input_is_named() -> None:
    bridge = vbi.Bridge(SPAN, 1, 4e9, 6000.0)
    road = vbi.Profile.flat(60.0, 0.05)
    one = vbi.simulate(bridge, TRUCK, road, 10.0, 20.0)
    other = vbi.simulate(bridge, TRUCK, road, 20.0, 20.0)
    with pytest.raises(TypeError, match="crossing must be a vbi Crossing"):
        amplification_parts("run", one.sections([5.0]))
    with pytest.raises(TypeError, match=r"response must be a SectionResponse"):
        amplification_parts(one, one.daf)
    with pytest.raises(ValueError, match="does not belong to crossing"):
        amplification_parts(one, other.sections([5.0]))


def test_what_a_mode_adds_to_a_simple_span() -> None:
    bridge = vbi.Bridge(SPAN, 1, 4e9, 6000.0)
    added = mode_contributions(bridge, TRUCK, [SPAN / 2], modes=3)
    for k in (1, 3):  # odd modes: the largest deflection at midspan
        row = added.loc[SPAN / 2, f"mode {k}"]
        assert row["deflection"] == pytest.approx(1.0, rel=1e-6)
        assert row["moment"] == pytest.approx(k**2 * np.pi**2 / 12, rel=1e-6)
    assert added.loc[SPAN / 2, ("mode 2", "deflection")] == pytest.approx(0.0, abs=1e-9)
    over_support = mode_contributions(vbi.Bridge(SPAN, 2, 4e9, 6000.0), TRUCK, [SPAN], modes=2)
    assert np.isnan(over_support.loc[SPAN, ("mode 1", "deflection")])


def test_the_parts_over_many_crossings_are_those_of_each() -> None:
    bridge = vbi.Bridge(SPAN, 1, 4e9, 6000.0)
    roads = {"a": vbi.Profile.iso8608(60.0, 0.05, iso_class="B", seed=1)}
    many = amplification_parts_over(bridge, TRUCK, roads, [15.0, 20.0], 20.0, [SPAN / 2],
                                    model="modal", modes=4)  # fmt: skip
    with warnings.catch_warnings():  # the class B road lifts this light truck a little
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        run = vbi.simulate(bridge, TRUCK, roads["a"], 20.0, 20.0, model="modal", modes=4)
    one = amplification_parts(run, run.sections([SPAN / 2]))
    mine = many[many.speed == 20.0].reset_index(drop=True)
    np.testing.assert_allclose(
        mine[["daf", "forces", "inertia"]], one[["daf", "forces", "inertia"]]
    )
    assert (mine["road"] == "a").all() and len(many) == 2 * len(one)
    assert (mine["min F_c / P"] == run.min_contact_force_ratio).all()
