"""Crossings of bridges continuous over three or more spans (model='modal').

References: the node grid's own definition (a node at every support, the span of each step
from the supports); the kernel's peak tracking of both midspans (the history rule gives the
same); a crawl, whose DAF is one; symmetry.
"""

from __future__ import annotations

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib.models.base import S_PEAK, SUMMARY_SIZE, node_grid, peaks_of
from vbi_lib.models.modal import Modal
from vbi_lib.models.one_coordinate import OneCoordinate
from vbi_lib.models.reference import reference_daf

EI, MBAR = 3e9, 4000.0
THREE = vbi.Bridge.continuous([18.0, 24.0, 15.0], EI=EI, mass_per_length=MBAR)


def test_every_support_is_a_node_and_each_step_knows_its_span() -> None:
    road = vbi.Profile.harmonic(80.0, 0.07, 5.0, 0.002)
    grid = node_grid(THREE, road, 20.0, 11.0, 1e-3, 11.0 + THREE.length)
    supports = 11.0 + np.array(THREE.supports)
    assert np.all(np.min(np.abs(grid.x[:, None] - supports[None, :]), axis=0) < 1e-12)
    middle = 0.5 * (grid.x[:-1] + grid.x[1:])
    expected = np.zeros(middle.size, dtype=int)
    for j in range(3):
        expected[(middle > supports[j]) & (middle < supports[j + 1])] = j + 1
    np.testing.assert_array_equal(grid.span_of_step[:-1], expected)


def test_span_peaks_from_the_histories_equal_the_kernel_s() -> None:
    """One rule, two places: the one-coordinate kernel tracks both midspans at every step;
    the history rule (three or more spans, the modal model) must give the same peaks."""
    truck = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    road = vbi.Profile.harmonic(90.0, 0.05, 6.0, 0.003)
    bridge = vbi.Bridge(20.0, 2, EI, MBAR)
    setup = OneCoordinate(bridge, truck, 20.0, 25.0, coupled=True, convective=True, modes=None)
    grid = node_grid(bridge, road, 20.0, 25.0, 1e-3, 25.0 + bridge.length)
    summary, contact, fields, _ = setup.integrate(grid)
    assert summary.size == SUMMARY_SIZE
    history = setup.midspan_history({**fields, "axle_contact_force": contact}, grid)
    peaks = peaks_of(*history, grid.x, 20.0)
    assert peaks.size == 2 and (peaks > 0).all()
    np.testing.assert_allclose(peaks, summary[S_PEAK : S_PEAK + 2], rtol=1e-12)


def test_single_and_batch_runs_agree_for_any_spans() -> None:
    truck = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    road = vbi.Profile.harmonic(90.0, 0.05, 6.0, 0.003)
    bridges = [THREE, vbi.Bridge(20.0, 2, EI, MBAR), vbi.Bridge.continuous([12.0, 16.0],
               EI=EI, mass_per_length=MBAR)]  # fmt: skip
    batch = vbi.simulate_many(bridges, truck, road, [18.0, 22.0, 25.0], 25.0, model="modal",
                              modes=[6, 4, 5])  # fmt: skip
    assert batch.daf.shape == (3, 3)
    for i, (bridge, speed, modes) in enumerate(zip(bridges, [18.0, 22.0, 25.0], [6, 4, 5],
                                                   strict=True)):  # fmt: skip
        single = vbi.simulate(bridge, truck, road, speed, 25.0, model="modal", modes=modes)
        np.testing.assert_allclose(batch.daf[i, : bridge.n_spans], single.daf, rtol=1e-12)
        assert np.isnan(batch.daf[i, bridge.n_spans :]).all()
        assert batch.contact_force_amplification[i] == pytest.approx(
            single.contact_force_amplification, rel=1e-12
        )
    assert list(batch.to_dataframe().columns[1:4]) == ["daf span 1", "daf span 2", "daf span 3"]


def test_a_crawl_over_three_unequal_spans_has_a_daf_of_one_on_every_span() -> None:
    """Each span divides by its own static deflection (the spans differ in stiffness)."""
    bridge = vbi.Bridge.continuous([18.0, 24.0, 15.0], EI=EI, mass_per_length=MBAR,
                                   damping_ratio=0.05)  # fmt: skip
    truck = vbi.Vehicle(1e4, 1e6, 0.0)
    run = vbi.simulate(bridge, truck, vbi.Profile.flat(bridge.length + 1.0, 0.02), 0.1, 1.0,
                       model="modal", modes=10, coupled=False, dt=0.2)  # fmt: skip
    np.testing.assert_allclose(run.daf, 1.0, atol=2e-3)
    # the static deflection is the exact beam's whatever the modes (the mode-acceleration
    # headline's); the sections' static envelope is the same beam's
    exact = -run.sections(bridge.midspans).static.minimum[0]
    for modes in (1, 10):
        setup = Modal(bridge, truck, 0.1, 1.0, coupled=False, convective=True, modes=modes)
        np.testing.assert_allclose(setup.span_static_deflections(), exact, rtol=1e-9)


def test_three_equal_spans_respond_symmetrically() -> None:
    """A flat-road crawl forward over a symmetric bridge: spans 1 and 3 alike."""
    bridge = vbi.Bridge.continuous([20.0, 20.0, 20.0], EI=EI, mass_per_length=MBAR,
                                   damping_ratio=0.05)  # fmt: skip
    truck = vbi.Vehicle(1e4, 1e6, 0.0)
    run = vbi.simulate(bridge, truck, vbi.Profile.flat(61.0, 0.05), 0.1, 1.0, model="modal",
                       modes=9, coupled=False, dt=0.5)  # fmt: skip
    assert run.daf[0] == pytest.approx(run.daf[2], abs=1e-3)
    statics = run.sections(bridge.midspans).static
    assert statics.minimum[0, 0] == pytest.approx(statics.minimum[0, 2], rel=1e-9)
    assert statics.maximum[1, 0] == pytest.approx(statics.maximum[1, 2], rel=1e-9)


def test_the_one_coordinate_model_refuses_other_layouts() -> None:
    truck = vbi.Vehicle(1e4, 1e6, 0.0)
    road = vbi.Profile.flat(80.0, 0.05)
    with pytest.raises(ValueError, match=r"spans \(18.0, 24.0, 15.0\) m.*model='modal'"):
        vbi.simulate(THREE, truck, road, 20.0, 5.0)
    with pytest.raises(ValueError, match="crossing 0: the one-coordinate model"):
        vbi.simulate_many(THREE, truck, road, 20.0, 5.0)
    with pytest.raises(NotImplementedError, match="model='modal'"):
        reference_daf(THREE, truck, road, 20.0, 5.0)
