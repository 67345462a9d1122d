"""The lane kernels (crossings on the SIMD lanes) give simulate's numbers, crossing by crossing.

The reference is :func:`vbi.simulate`, the per-crossing kernels; the lane kernels evaluate
the same equations in another order of floating-point operations, so the summaries agree
to rounding: the tests hold them to 1e-10.  Batches mix what blocks of lanes must cope
with: crossings of different lengths and steps (masked lanes), one and two spans, coupled
and decoupled, convective on and off, several numbers of modes, more crossings than lanes.
"""

from __future__ import annotations

import math
import warnings

import numba
import numpy as np
import pytest
from problems import CASES, LB_IN, build_case, rough_profile

import vbi_lib as vbi
from vbi_lib.models import base, lanes

RTOL = 1e-10
LANE_MODELS = {
    "one-coordinate": {},
    "modal-1": {"model": "modal", "modes": 1},
    "modal-3": {"model": "modal", "modes": 3},
    "modal-5": {"model": "modal", "modes": 5},
}


def assert_batch_equals_singles(batch: vbi.BatchResult, singles: list[vbi.Crossing]) -> None:
    """Every summary of the batch equals the single crossing's, to RTOL."""
    assert len(batch) == len(singles)
    for i, one in enumerate(singles):
        n = one.bridge.n_spans
        np.testing.assert_allclose(batch.daf[i, :n], one.daf, rtol=RTOL, err_msg=f"crossing {i}")
        assert np.isnan(batch.daf[i, n:]).all()
        on = one.on_bridge
        largest = one.contact_force[on].max() / one.vehicle.weight
        assert batch.contact_force_amplification[i] == pytest.approx(largest, rel=RTOL)
        at = one.position[on][np.argmax(one.contact_force[on])]
        assert batch.peak_contact_position[i] == pytest.approx(at, rel=RTOL)
        assert batch.min_contact_force_ratio[i] == pytest.approx(
            one.min_contact_force_ratio, rel=RTOL, abs=RTOL
        )
        assert batch.tension_fraction[i] == pytest.approx(one.tension_fraction, abs=RTOL)
        assert batch.dt[i] == pytest.approx(one.dt, rel=1e-14)


def run_both(bridges, vehicles, roads, speeds, starts, options, **flags):  # noqa: ANN001, ANN003, ANN201
    """The batch and the single crossings of the same inputs (lists of equal length)."""
    n = len(speeds)
    expand = {k: v if isinstance(v, list) else [v] * n for k, v in flags.items()}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        batch = vbi.simulate_many(bridges, vehicles, roads, speeds, starts, **flags, **options)
        singles = [
            vbi.simulate(
                bridges[i],
                vehicles[i],
                roads[i],
                speeds[i],
                starts[i],
                **{k: v[i] for k, v in expand.items()},
                **options,
            )  # fmt: skip
            for i in range(n)
        ]
    return batch, singles


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("options", LANE_MODELS.values(), ids=LANE_MODELS.keys())
@pytest.mark.parametrize("coupled", [True, False])
@pytest.mark.parametrize("convective", [True, False])
def test_lanes_equal_simulate(case: str, options: dict, coupled: bool, convective: bool) -> None:
    """Rough road, study truck; speeds 0.5 to 1.3 times 720 in/s, the bridge moved about."""
    bridge, vehicle, road, speed, start = build_case(case)
    speeds = list(speed * np.array([0.5, 0.8, 1.0, 1.3]))
    starts = list(start + np.array([0.0, -3.0, 0.37, -7.1]))
    n = len(speeds)
    batch, singles = run_both([bridge] * n, [vehicle] * n, [road] * n, speeds, starts,
                              options, coupled=coupled, convective=convective)  # fmt: skip
    assert len({one.time.size for one in singles}) > 1  # lanes stop at different steps
    assert_batch_equals_singles(batch, singles)


@pytest.mark.parametrize("options", LANE_MODELS.values(), ids=LANE_MODELS.keys())
def test_a_mixed_batch_larger_than_a_block(options: dict) -> None:
    """Forty crossings: spans, roads, starts, speeds and options all vary (padded blocks)."""
    rng = np.random.default_rng(12)
    designs = [
        vbi.Bridge.from_midspan_stiffness(40 * 0.3048, 1, 587723 * LB_IN, 9.95),
        vbi.Bridge.from_midspan_stiffness(100 * 0.3048, 2, 668815 * LB_IN, 3.99),
        vbi.Bridge(18.0, 2, 6e9, 5000.0, damping_ratio=0.03),
    ]
    trucks = [vbi.Vehicle.from_frequency(3e4, 3.0, 0.1), vbi.Vehicle(2e4, 2e6, 0.0)]
    roads = [rough_profile(110.0, 0.0254, 100e-6, seed=s) for s in range(3)]
    roads.append(vbi.Profile.harmonic(120.0, 0.1, 6.0, 0.004))  # coarser than the steps
    n = 40
    bridges = [designs[k] for k in rng.integers(0, 3, n)]
    vehicles = [trucks[k] for k in rng.integers(0, 2, n)]
    profiles = [roads[k] for k in rng.integers(0, 4, n)]
    starts = list(rng.uniform(0.0, 40.0, n))
    speeds = list(rng.uniform(8.0, 30.0, n))
    coupled = [bool(c) for c in rng.integers(0, 2, n)]
    batch, singles = run_both(bridges, vehicles, profiles, speeds, starts, options,
                              coupled=coupled)  # fmt: skip
    assert vbi.models.lanes.LANES < n
    assert_batch_equals_singles(batch, singles)


def test_modal_blocks_mix_numbers_of_modes_and_spans() -> None:
    bridges = [vbi.Bridge(20.0, 1, 3e9, 4000.0), vbi.Bridge(15.0, 2, 2e9, 3000.0)] * 9
    modes = [1, 3, 5, 2, 4, 6] * 3
    truck = vbi.Vehicle.from_frequency(1e4, 4.0, 0.1)
    road = rough_profile(80.0, 0.02, 64e-6, seed=4)
    n = len(modes)
    speeds = list(np.linspace(12.0, 28.0, n))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        batch = vbi.simulate_many(bridges, truck, road, speeds, 30.0, model="modal", modes=modes)
        singles = [
            vbi.simulate(b, truck, road, v, 30.0, model="modal", modes=m)
            for b, v, m in zip(bridges, speeds, modes, strict=True)
        ]
    assert_batch_equals_singles(batch, singles)


UNEQUAL = [
    vbi.Bridge.continuous([12.0, 16.5], EI=2e9, mass_per_length=3000.0, damping_ratio=0.02),
    vbi.Bridge.continuous([21.0, 14.0], EI=5e9, mass_per_length=4500.0),
]


@pytest.mark.parametrize("modes", [1, 3, 5])
@pytest.mark.parametrize("coupled", [True, False])
@pytest.mark.parametrize("convective", [True, False])
def test_modal_lanes_on_two_unequal_spans(modes: int, coupled: bool, convective: bool) -> None:
    """The general mode form (a sin ks + b cos ks + c e^-ks + d e^-k(L_j - s)) in the lanes,
    each span with its own coefficients and static deflection, one and two spans mixed."""
    truck = vbi.Vehicle.from_frequency(1.5e4, 3.5, 0.1)
    road = rough_profile(90.0, 0.0254, 64e-6, seed=7)
    bridges = [*UNEQUAL, vbi.Bridge(18.0, 1, 3e9, 4000.0)] * 2
    n = len(bridges)
    speeds = list(np.linspace(10.0, 30.0, n))
    starts = list(np.linspace(22.0, 31.0, n))
    batch, singles = run_both(bridges, [truck] * n, [road] * n, speeds, starts,
                              {"model": "modal", "modes": modes}, coupled=coupled,
                              convective=convective)  # fmt: skip
    assert_batch_equals_singles(batch, singles)


def test_a_batch_of_everything_equals_its_single_crossings() -> None:
    """Lanes, general vehicles and bridges of three spans in one call: each crossing is
    simulate's, and the spans beyond the summary's two peak slots are not lost."""
    three = vbi.Bridge.continuous([14.0, 18.0, 12.0], EI=3e9, mass_per_length=4000.0)
    truck = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    car = vbi.QuarterCar.from_frequencies(4000.0, 500.0, 1.5, 12.0, 0.1, 0.02)
    road = rough_profile(100.0, 0.05, 16e-6, seed=2)
    bridges = [three, UNEQUAL[0], three, vbi.Bridge(20.0, 2, 3e9, 4000.0), UNEQUAL[1]]
    vehicles = [truck, truck, car, car, truck]
    speeds = [12.0, 15.0, 18.0, 21.0, 24.0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        batch = vbi.simulate_many(bridges, vehicles, road, speeds, 30.0, model="modal", modes=4)
        singles = [vbi.simulate(b, v, road, s, 30.0, model="modal", modes=4)
                   for b, v, s in zip(bridges, vehicles, speeds, strict=True)]  # fmt: skip
    assert batch.daf.shape == (5, 3)
    for i, one in enumerate(singles):
        n = one.bridge.n_spans
        np.testing.assert_allclose(batch.daf[i, :n], one.daf, rtol=RTOL, err_msg=f"crossing {i}")
        assert np.isfinite(batch.daf[i, :n]).all() and np.isnan(batch.daf[i, n:]).all()
        assert batch.min_contact_force_ratio[i] == pytest.approx(
            one.min_contact_force_ratio, rel=RTOL
        )
        assert batch.flight_fraction[i] == pytest.approx(one.flight_fraction, abs=RTOL)
        assert batch.dt[i] == pytest.approx(one.dt, rel=1e-14)


def test_study_runner_rows_equal_simulate() -> None:
    """studies.run hands its chunks to the lane kernels: rows equal single crossings."""
    from vbi_lib import studies

    bridge, vehicle, road, speed, start = build_case("100ft-4Hz-two-spans")
    table = studies.grid(bridge, vehicle, road, [0.7 * speed, speed], start, model="modal",
                         modes=[1, 4], coupled=[True, False])  # fmt: skip
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        result = studies.run(table, "serial", chunk_size=3)
        for i in range(len(table)):
            row = table.iloc[i]
            one = vbi.simulate(bridge, vehicle, road, row.speed, start, model="modal",
                               modes=int(row.modes), coupled=row.coupled)  # fmt: skip
            assert result["daf_1"].iloc[i] == pytest.approx(one.daf[0], rel=RTOL)
            assert result["daf_2"].iloc[i] == pytest.approx(one.daf[1], rel=RTOL)
            assert result["min_contact_force_ratio"].iloc[i] == pytest.approx(
                one.min_contact_force_ratio, rel=RTOL
            )


@pytest.mark.parametrize("options", [{}, {"model": "modal", "modes": 3}], ids=["2dof", "modal"])
def test_other_vehicles_take_the_general_kernel_and_agree(options: dict) -> None:
    """The sprung mass as a general VehicleSystem runs the model's general kernel, one
    crossing per task: an independent integration of the same equations."""
    bridge, vehicle, road, speed, start = build_case("40ft-10Hz-one-span")
    speeds = [0.6 * speed, speed]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        lanes_ = vbi.simulate_many(bridge, vehicle, road, speeds, start, **options)
        general = vbi.simulate_many(bridge, vehicle.system, road, speeds, start, **options)
        mixed = vbi.simulate_many(bridge, [vehicle, vehicle.system], road, speeds, start,
                                  **options)  # fmt: skip
    np.testing.assert_allclose(general.daf[:, 0], lanes_.daf[:, 0], rtol=RTOL)
    np.testing.assert_allclose(general.min_contact_force_ratio, lanes_.min_contact_force_ratio,
                               rtol=RTOL)  # fmt: skip
    np.testing.assert_array_equal(mixed.daf[0], lanes_.daf[0])
    np.testing.assert_array_equal(mixed.daf[1], general.daf[1])


def test_one_and_two_threads_give_the_same_table() -> None:
    bridge, vehicle, road, speed, start = build_case("100ft-4Hz-two-spans")
    speeds = list(speed * np.linspace(0.5, 1.5, 101))  # enough blocks for the threaded path
    before = numba.get_num_threads()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", vbi.ContactLossWarning)
            numba.set_num_threads(1)
            one = vbi.simulate_many(bridge, vehicle, road, speeds, start)
            numba.set_num_threads(min(2, numba.config.NUMBA_NUM_THREADS))
            two = vbi.simulate_many(bridge, vehicle, road, speeds, start)
    finally:
        numba.set_num_threads(before)
    np.testing.assert_array_equal(one.daf, two.daf)
    np.testing.assert_array_equal(one.min_contact_force_ratio, two.min_contact_force_ratio)


def test_default_steps_of_a_batch_are_each_crossings_own() -> None:
    """Thousands of distinct damped crossings take the threaded path; each equals its own."""
    bridge, vehicle, road, speed, start = build_case("40ft-10Hz-one-span")
    speeds = np.linspace(5.0, 30.0, 5000)  # > 4096 distinct rows: the threaded path
    steps = vbi.models.OneCoordinate.default_time_steps(
        vbi.models.batch_inputs.batch_of(
            vbi.models.OneCoordinate,
            {
                "bridges": bridge,
                "vehicles": vehicle,
                "profiles": road,
                "speeds": speeds,
                "bridge_starts": start,
                "coupled": True,
                "convective": True,
                "modes": None,
            },
        )  # fmt: skip
    )
    single = [vbi.models.one_coordinate.default_time_step(bridge, vehicle, s) for s in speeds]
    np.testing.assert_array_equal(steps, single)


# ---------------------------------------------------------------------------- building blocks
@numba.njit
def _sincos_many(theta, sine, cosine):
    for i in range(theta.size):
        sine[i], cosine[i] = lanes.sincos(theta[i])


@pytest.mark.parametrize("largest", [1.0, 50.0, 1e4])
def test_branch_free_sincos_is_within_an_ulp_of_the_c_library(largest: float) -> None:
    theta = np.random.default_rng(3).uniform(-largest, largest, 20_000)
    theta[:4] = [0.0, math.pi / 4, math.pi / 2, -math.pi]
    sine, cosine = np.empty_like(theta), np.empty_like(theta)
    _sincos_many(theta, sine, cosine)
    np.testing.assert_allclose(sine, [math.sin(t) for t in theta], rtol=0, atol=2.3e-16)
    np.testing.assert_allclose(cosine, [math.cos(t) for t in theta], rtol=0, atol=2.3e-16)


def test_pi_over_two_head_is_short_enough_for_exact_products() -> None:
    head = lanes.PIO2_HEAD
    assert head * 2**32 == int(head * 2**32)  # 33 significant bits
    assert abs(head + lanes.PIO2_TAIL - math.pi / 2) < 1e-16


def test_peak_inside_a_step_survives_a_vanishing_cubic_term() -> None:
    """Hermite data that are nearly a parabola: the cubic coefficient is rounding noise.

    The textbook root formula cancelled there and missed the minimum by 1e-5 relative; the
    reference is the minimum of the interpolant sampled densely (written out here).
    """
    a0, a1 = -0.023233760920101165, -0.023181120239243194
    v0, v1, h = -0.00970012852138768, 0.08550270895687337, 0.0013888888888887601
    t = np.linspace(0.0, 1.0, 2_000_001)
    m0, m1 = h * v0, h * v1
    cubic = (2 * a0 + m0 - 2 * a1 + m1) * t**3 + (-3 * a0 - 2 * m0 + 3 * a1 - m1) * t**2
    dense = float((cubic + m0 * t + a0).min())
    assert base.downward_peak(a0, a1, v0, v1, h) == pytest.approx(-dense, rel=1e-13)


@numba.njit
def _exp_many(x, out):
    bits = np.empty(x.size, np.int64)
    parts = np.empty(x.size)
    for i in range(x.size):
        parts[i], n = lanes.exp_parts(x[i])
        bits[i] = lanes.power_of_two_bits(n)
    scales = bits.view(np.float64)
    for i in range(x.size):
        out[i] = parts[i] * scales[i]


def test_branch_free_exp_is_within_an_ulp_or_two_of_the_c_library() -> None:
    x = np.concatenate((np.random.default_rng(4).uniform(-700.0, 700.0, 20_000), [0.0, -1e-300]))
    out = np.empty_like(x)
    _exp_many(x, out)
    np.testing.assert_allclose(out, [math.exp(v) for v in x], rtol=4.5e-16, atol=0)
    assert abs(lanes.LN2_HEAD + lanes.LN2_TAIL - math.log(2.0)) < 1e-16
