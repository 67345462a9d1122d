"""The compiled node grid against a construction written here with numpy (sets and interp).

One axle without a footprint (the study's sprung mass, the lane kernels) has its grid
walked by compiled code; it must be the set construction's number for number, on bridges
of any spans and wherever the bridge's ends fall among the samples.
"""

from __future__ import annotations

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib.models.grid import MAX_NODES, node_grid


def numpy_grid(bridge, profile, speed, bridge_start, dt, stop):  # noqa: ANN001, ANN201
    """The grid's definition, with set operations: samples before ``stop``, supports, stop;
    points closer than 1e-12 max(1, |stop|) to the point before them dropped; gaps longer
    than ``speed * dt`` cut into equal steps; elevations from ``np.interp``."""
    supports = bridge_start + np.array(bridge.supports)
    inside = profile.x[(profile.x > profile.start) & (profile.x < stop)]
    supports = supports[supports >= profile.start]
    points = np.union1d(np.concatenate(([profile.start], inside, supports)), [stop])
    points = points[points <= stop]
    keep = np.concatenate(([True], np.diff(points) > 1e-12 * max(1.0, abs(stop))))
    points = points[keep]
    gaps = np.diff(points)
    pieces = np.maximum(1, np.ceil(gaps / (speed * dt) - 1e-9)).astype(np.int64)
    x = [a + j * (gap / count) for a, gap, count in zip(points[:-1], gaps, pieces, strict=True)
         for j in range(count)]  # fmt: skip
    x = np.array(x + [points[-1]])
    middle = 0.5 * (x[:-1] + x[1:]) - bridge_start
    span_of_step = np.zeros(x.size, dtype=np.int64)
    inside_bridge = (middle > 0) & (middle < bridge.length)
    # span j + 1 from support j on (side="right": a step starting on a support is after it)
    edges = np.array(bridge.supports)
    span_of_step[:-1] = np.where(inside_bridge, np.searchsorted(edges, middle, side="right"), 0)
    dt_max = float((gaps / pieces).max() / speed)
    return x, np.interp(x, profile.x, profile.elevation), span_of_step, dt_max


def random_case(rng: np.random.Generator, trial: int):  # noqa: ANN201
    n = int(rng.integers(60, 300))  # some 15 m or more: spans of at least 1 m fit
    x = np.cumsum(rng.uniform(0.01, 0.5, n))
    if trial % 3 == 0:  # samples on a round grid: supports often fall on a sample
        x = np.unique(np.round(x, 2))
    x = x - x[0] + rng.uniform(-5.0, 5.0)
    profile = vbi.Profile(x, rng.normal(0.0, 0.01, x.size))
    n_spans = int(rng.integers(1, 5))
    if trial % 2:  # a continuous beam of unequal spans
        lengths = rng.uniform(0.05, 0.2, n_spans) * profile.length
        if trial % 3 == 0:  # whole numbers of samples: the supports fall on samples
            lengths = np.round(lengths / 0.01) * 0.01
        lengths = np.maximum(1.0, lengths)  # the shortest span a Bridge takes
        bridge = vbi.Bridge.continuous(list(lengths), EI=1e8, mass_per_length=1e3)
    else:
        n_spans = min(n_spans, 2)
        bridge = vbi.Bridge(rng.uniform(0.2, 0.45) * profile.length / n_spans, n_spans, 1e8, 1e3)
    room = profile.length - bridge.length
    start = profile.start + rng.uniform(0.0, room)
    if trial % 5 == 0:  # the bridge starting on a sample
        start = x[np.searchsorted(x, start)]
    if trial % 7 == 0:  # a support a hair after a sample: dropped as a duplicate
        start = x[np.searchsorted(x, start)] + 1e-13
    speed = rng.uniform(1.0, 30.0)
    dt = np.inf if trial % 4 == 0 else rng.uniform(1e-4, 0.05)
    stop = start + bridge.length
    if trial % 6 == 0:  # free vibration after the bridge
        stop = min(profile.end, stop + rng.uniform(0.0, 5.0))
    return bridge, profile, speed, start, dt, stop


@pytest.mark.parametrize("seed", range(4))
def test_compiled_grid_is_the_set_construction(seed: int) -> None:
    rng = np.random.default_rng(seed)
    checked = 0
    for trial in range(60):
        case = random_case(rng, trial)
        if case[3] + case[0].length > case[1].end:
            continue
        checked += 1
        x, elevation, span_of_step, dt_max = numpy_grid(*case)
        sprung_mass = vbi.Vehicle(1e4, 1e6, 1e3).system  # one axle, no footprint
        for grid in (node_grid(*case), node_grid(*case, vehicle=sprung_mass)):
            np.testing.assert_array_equal(grid.x, x)
            np.testing.assert_array_equal(grid.elevation, elevation)
            np.testing.assert_array_equal(grid.span_of_step, span_of_step)
            np.testing.assert_array_equal(grid.road, elevation[None, :])
            np.testing.assert_array_equal(grid.axle_span, span_of_step[None, :])
            assert grid.dt_max == dt_max
    assert checked > 50


def test_a_bridge_that_ends_on_a_sample_ends_the_grid_there() -> None:
    """The run's last node is the bridge's end even where samples go on after it."""
    road = vbi.Profile(np.arange(0.0, 80.01, 0.02), np.zeros(4001))
    bridge = vbi.Bridge(20.0, 1, 3e9, 4000.0)
    for dt in (0.004, np.inf):
        case = (bridge, road, 12.0, 30.0, dt, 50.0)
        grid = node_grid(*case)
        x, elevation, span_of_step, dt_max = numpy_grid(*case)
        assert grid.x[-1] == 50.0
        np.testing.assert_array_equal(grid.x, x)
        np.testing.assert_array_equal(grid.span_of_step, span_of_step)


def test_a_step_that_would_need_too_many_nodes_is_refused() -> None:
    bridge = vbi.Bridge(20.0, 1, 1e9, 1e3)
    road = vbi.Profile.flat(30.0, 0.1)
    with pytest.raises(ValueError, match=r"dt=1e-09 s at speed=10.0 m/s .* time steps"):
        node_grid(bridge, road, 10.0, 5.0, 1e-9, 25.0)
    assert 30.0 / (10.0 * 1e-9) > MAX_NODES
