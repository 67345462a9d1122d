"""Study runner: physics references, agreement with single crossings, executors, bad input."""

from __future__ import annotations

import concurrent.futures as cf
import math
import multiprocessing
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import vbi_lib as vbi
from vbi_lib import studies
from vbi_lib import units as u

RESULT_COLUMNS = ["daf_1", "daf_2", "contact_force_amplification", "peak_contact_position"]


class CountingExecutor(cf.Executor):
    """Runs tasks in this process and counts them (to prove no work started)."""

    def __init__(self) -> None:
        self.submitted = 0

    def submit(self, fn, /, *args, **kwargs):  # noqa: ANN001, ANN201
        self.submitted += 1
        future: cf.Future = cf.Future()
        future.set_result(fn(*args, **kwargs))
        return future


def small_study() -> pd.DataFrame:
    """Mixed grid: one- and two-span bridges, two trucks, harmonic and ISO roads, offsets."""
    bridges = {
        "one span": vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * u.lbf / u.inch, 3.99),
        "two spans": vbi.Bridge.from_midspan_stiffness(
            100 * u.ft, 2, 668815 * u.lbf / u.inch, 3.99
        ),
    }
    trucks = studies.parametric_trucks((2.5, 4.0))
    length = 200 * u.ft + 200 * u.ft + 10 * u.ft
    profiles = {
        "harmonic": studies.HarmonicProfile(length, 1 * u.inch, 30 * u.ft, 0.25 * u.inch),
        "iso": studies.ISOProfile(length, 1 * u.inch, c10=300e-6, seed=7),
    }
    return studies.grid(
        bridges,
        trucks,
        profiles,
        [15.0, 25.0],
        200 * u.ft,
        profile_offsets=[0.0, 10 * u.ft],
        coupled=[True, False],
    )


# ---------------------------------------------------------------------------- references
def test_parameter_builders_reproduce_tables_2_15_3_and_2_15_4() -> None:
    """The study's printed EI (Table 2.15.3) and k (Table 2.15.4)."""
    printed_ei = [5.603e12, 1.261e13, 2.241e13, 3.502e13]  # lb in^2
    printed_k = [31582.7, 71061.2, 126330.9, 197392.1]  # lb/in
    bridges = list(studies.parametric_bridges().values())
    trucks = list(studies.parametric_trucks().values())
    for bridge, ei, f in zip(bridges, printed_ei, (2, 3, 4, 5), strict=True):
        assert bridge.EI / (u.lbf * u.inch**2) == pytest.approx(ei, rel=1e-3)
        assert bridge.mass_per_length * bridge.span / u.slinch == pytest.approx(2000)
        assert bridge.first_frequency_hz == pytest.approx(f)
        assert bridge.damping_ratio == 0.01
    for truck, k in zip(trucks, printed_k, strict=True):
        assert truck.stiffness / (u.lbf / u.inch) == pytest.approx(k, abs=0.1)
        assert truck.mass / u.slinch == pytest.approx(200)
        assert truck.damping_ratio == pytest.approx(0.10)


def moving_force_daf(alpha: float) -> float:
    """Closed form one-mode peak under a constant force (Fryba), undamped, over the crossing.

    ``w/w0 = (sin(w t) - alpha sin(w1 t)) / (1 - alpha^2)``, ``w = pi v / L``,
    ``alpha = w / w1``; the largest value while the force is on the span.
    """
    tau = np.linspace(0.0, math.pi, 400001)  # w t from 0 to pi
    w = (np.sin(tau) - alpha * np.sin(tau / alpha)) / (1.0 - alpha**2)
    return float(w.max())


def test_decoupled_flat_crossing_is_the_moving_force_closed_form() -> None:
    bridge = vbi.Bridge(30.0, 1, 1.2e10, 9000.0, damping_ratio=0.0)
    truck = vbi.Vehicle.from_frequency(2.0e4, 3.0, 0.1)
    f1 = bridge.first_frequency_hz
    alphas = np.array([0.1, 0.25, 0.617, 0.9])
    speeds = alphas * 2.0 * f1 * bridge.span
    table = studies.grid(
        bridge, truck, studies.FlatProfile(60.0, 0.02), list(speeds), 20.0, coupled=False
    )
    result = studies.run(table, "serial")
    expected = [moving_force_daf(a) for a in alphas]
    np.testing.assert_allclose(result["daf_1"], expected, rtol=2e-4)
    # the reference sheet's printed peak at alpha = 0.617
    assert result["daf_1"].iloc[2] == pytest.approx(1.7685, abs=2e-3)
    # the contact force of a truck on a flat road, decoupled, is its weight
    np.testing.assert_allclose(result["contact_force_amplification"], 1.0, atol=1e-12)


# ---------------------------------------------------------------------------- consistency
def shifted_road(profile: vbi.Profile, offset: float) -> vbi.Profile:
    """Independent construction of the road slid back by ``offset`` (a whole number of steps)."""
    x = profile.x[profile.x <= profile.end - offset + 1e-9]
    return vbi.Profile(x, profile.elevation_at(x + offset))


def test_rows_agree_with_single_simulate_calls() -> None:
    table = small_study()
    result = studies.run(table, "serial")
    assert len(result) == 2 * 2 * 2 * 2 * 2 * 2
    for i in range(len(table)):
        row = table.iloc[i]
        road = shifted_road(row.profile.build(), row.profile_offset)
        crossing = vbi.simulate(
            row.bridge, row.vehicle, road, row.speed, row.bridge_start, coupled=row.coupled
        )
        got = result.iloc[i]
        n = row.bridge.n_spans
        np.testing.assert_allclose(got[["daf_1", "daf_2"]].to_numpy(float)[:n], crossing.daf,
                                   rtol=1e-9)  # fmt: skip
        if n == 1:
            assert np.isnan(got["daf_2"])
        assert got["daf"] == pytest.approx(crossing.daf.max(), rel=1e-9)
        assert got["contact_force_amplification"] == pytest.approx(
            crossing.contact_force_amplification, rel=1e-9
        )
        assert got["bridge_f1_hz"] == pytest.approx(row.bridge.first_frequency_hz)
        assert got["vehicle_f_hz"] == pytest.approx(row.vehicle.frequency_hz)
        assert got["peak_contact_time"] == pytest.approx(
            (got["peak_contact_position"] - road.start) / row.speed
        )


def test_modes_column_dispatches_to_the_many_mode_model() -> None:
    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    truck = vbi.Vehicle.from_frequency(3e4, 3.0, 0.1)
    road = vbi.Profile.harmonic(130.0, 0.05, 9.0, 0.005)
    table = studies.grid(bridge, truck, road, 20.0, 100.0, modes=[1, 3])
    try:
        from vbi_lib.modal import simulate_modal
    except ImportError:
        with pytest.raises(NotImplementedError, match="simulate_modal_many"):
            studies.run(table, "serial")
        return
    result = studies.run(table, "serial")
    assert result["daf_1"].iloc[0] == pytest.approx(
        vbi.simulate(bridge, truck, road, 20.0, 100.0).daf[0], rel=1e-9
    )
    assert result["daf_1"].iloc[1] == pytest.approx(
        simulate_modal(bridge, truck, road, 20.0, 100.0, 3).daf[0], rel=1e-6
    )


def test_iri_on_request_is_the_iri_of_each_span() -> None:
    road = vbi.Profile.iso8608(130.0, 0.025, c10=64e-6, seed=3)
    bridges = [vbi.Bridge(30.0, 1, 2e10, 8000.0), vbi.Bridge(30.0, 2, 2e10, 8000.0)]
    table = studies.grid(bridges, vbi.Vehicle.from_frequency(3e4, 3.0), road, 20.0, 60.0)
    result = studies.run(table, "serial", iri=True)
    assert result["iri_1"].iloc[0] == pytest.approx(vbi.iri(road.segment(60.0, 90.0)))
    assert np.isnan(result["iri_2"].iloc[0])
    both = vbi.iri(road.segment(60.0, 120.0), segment_length=30.0).iri
    np.testing.assert_allclose(result[["iri_1", "iri_2"]].iloc[1], both[:2])


# ---------------------------------------------------------------------------- executors
def test_same_table_whatever_the_executor_and_chunking() -> None:
    table = small_study()
    serial = studies.run(table, "serial")
    pieces = studies.run(table, CountingExecutor(), chunk_size=3)
    pd.testing.assert_frame_equal(serial, pieces)
    context = multiprocessing.get_context("spawn")
    with cf.ProcessPoolExecutor(2, mp_context=context) as pool:
        pooled = studies.run(table, pool, chunk_size=5)
    pd.testing.assert_frame_equal(serial, pooled)
    try:
        default = studies.run(table, studies.default_executor(2))
    finally:
        studies.shutdown_default_executor()
    pd.testing.assert_frame_equal(serial, default)


def test_chunking_does_not_change_the_table() -> None:
    table = small_study()
    pd.testing.assert_frame_equal(
        studies.run(table, "serial"), studies.run(table, "serial", chunk_size=1)
    )


def test_a_recipe_is_built_once_per_process(monkeypatch: pytest.MonkeyPatch) -> None:
    calls = []
    original = vbi.Profile.harmonic.__func__

    def counting(cls, *args, **kwargs):  # noqa: ANN001, ANN002, ANN003, ANN202
        calls.append(args)
        return original(cls, *args, **kwargs)

    monkeypatch.setattr(vbi.Profile, "harmonic", classmethod(counting))
    studies._build.cache_clear()
    road = studies.HarmonicProfile(150.0, 0.05, 9.0, 0.004)
    table = studies.grid(
        vbi.Bridge(30.0, 1, 2e10, 8000.0),
        vbi.Vehicle.from_frequency(3e4, 3.0),
        road,
        list(np.linspace(10.0, 30.0, 12)),
        100.0,
        profile_offsets=[0.0, 5.0],
    )
    studies.run(table, "serial", chunk_size=5)
    assert len(calls) == 1


def test_dask_cluster_gives_the_serial_table() -> None:
    distributed = pytest.importorskip("dask.distributed")
    table = small_study()
    serial = studies.run(table, "serial")
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        on_dask = studies.run(table, client.get_executor(), chunk_size=4)
    pd.testing.assert_frame_equal(serial, on_dask)


# ---------------------------------------------------------------------------- Monte Carlo
def test_monte_carlo_is_repeatable_and_draws_inside_the_ranges() -> None:
    bridge = vbi.Bridge.from_frequency(100 * u.ft, 1, 2000 * u.slinch / (100 * u.ft), 3.0)
    trucks = studies.parametric_trucks((2.0, 3.0, 4.0))
    kwargs = dict(
        speed_range=(20.0, 30.0),
        c10_range=(16e-6, 256e-6),
        waviness=(2.0, 3.0),
        offset_range=(0.0, 5.0),
        n_profiles=6,
    )
    a = studies.monte_carlo(bridge, trucks, 24, seed=11, **kwargs)
    b = studies.monte_carlo(bridge, trucks, 24, seed=11, **kwargs)
    c = studies.monte_carlo(bridge, trucks, 24, seed=12, **kwargs)
    assert a["speed"].between(20.0, 30.0).all() and a["profile_offset"].between(0, 5).all()
    c10 = np.array([p.c10 for p in a["profile"]])
    assert ((c10 >= 16e-6) & (c10 <= 256e-6)).all()
    assert a["profile"].nunique() <= 6 and set(a["vehicle_name"]) <= set(trucks)
    ra = studies.run(a, "serial", chunk_size=5)
    rb = studies.run(b, CountingExecutor(), chunk_size=7)
    pd.testing.assert_frame_equal(ra, rb)
    assert not np.allclose(ra["daf"], studies.run(c, "serial")["daf"])


def test_characteristic_values_cover_known_quantiles() -> None:
    """On normal samples the intervals hold the true mean and percentiles about 95 % of the time."""
    rng = np.random.default_rng(5)
    true = {"mean": 0.0, "p95": 1.6448536, "p99": 2.3263479}
    hits = dict.fromkeys(true, 0)
    trials = 300
    for _ in range(trials):
        table = studies.characteristic_values(rng.standard_normal(400), allowance=1.0)
        for key, value in true.items():
            hits[key] += table.loc[key, "lower"] <= value <= table.loc[key, "upper"]
    for key in true:
        assert 0.91 <= hits[key] / trials <= 0.995, (key, hits[key])
    x = rng.standard_normal(100000)
    table = studies.characteristic_values(x + 1.0, allowance=0.33)
    assert table.loc["P(DAF > 1.33)", "estimate"] == pytest.approx(0.3707, abs=0.005)
    assert table.loc["p95", "estimate"] == pytest.approx(2.6449, abs=0.02)


def test_characteristic_values_refuse_nan() -> None:
    with pytest.raises(ValueError, match="NaN"):
        studies.characteristic_values([1.1, np.nan, 1.2])


# ---------------------------------------------------------------------------- saving
@pytest.mark.parametrize("suffix", [".parquet", ".csv"])
def test_save_and_load_round_trip(tmp_path: Path, suffix: str) -> None:
    result = studies.run(small_study().iloc[:6], "serial")
    path = studies.save(result, tmp_path / f"study{suffix}")
    back = studies.load(path)
    pd.testing.assert_frame_equal(
        result.reset_index(drop=True), back, check_dtype=suffix == ".parquet"
    )


def test_a_failed_save_leaves_no_file(tmp_path: Path) -> None:
    table = small_study().iloc[:2]  # holds Bridge objects: not writable as Parquet
    with pytest.raises(Exception):  # noqa: B017, PT011 - pyarrow's own error
        studies.save(table, tmp_path / "bad.parquet")
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(ValueError, match="parquet"):
        studies.save(table, tmp_path / "bad.xlsx")


# ---------------------------------------------------------------------------- bad input
def test_empty_grid_is_refused_before_work() -> None:
    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    truck = vbi.Vehicle.from_frequency(3e4, 3.0)
    with pytest.raises(ValueError, match="'speed' is empty"):
        studies.grid(bridge, truck, studies.FlatProfile(130.0, 0.05), [], 100.0)
    pool = CountingExecutor()
    with pytest.raises(ValueError, match="empty"):
        studies.run(pd.DataFrame(columns=list(studies.REQUIRED_COLUMNS)), pool)
    assert pool.submitted == 0


def test_short_profile_names_the_rows_before_work() -> None:
    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    truck = vbi.Vehicle.from_frequency(3e4, 3.0)
    table = studies.grid(
        bridge, truck, studies.FlatProfile(140.0, 0.05), [10.0, 20.0], [100.0, 105.0, 115.0]
    )
    pool = CountingExecutor()
    with pytest.raises(ValueError, match=r"rows 2, 5: the profile \(stations 0 to 140 m\)"):
        studies.run(table, pool)
    assert pool.submitted == 0
    slid = studies.grid(
        bridge, truck, studies.FlatProfile(140.0, 0.05), 10.0, 100.0, profile_offsets=[5.0, 15.0]
    )
    with pytest.raises(ValueError, match="row 1: the profile"):
        studies.run(slid, pool)
    assert pool.submitted == 0


def test_unknown_columns_and_bad_values_are_named() -> None:
    table = small_study().iloc[:4].copy()
    pool = CountingExecutor()
    with pytest.raises(ValueError, match=r"unknown columns \['sped'\]"):
        studies.run(table.rename(columns={"speed": "sped"}), pool)
    with pytest.raises(ValueError, match="lacks the required columns"):
        studies.run(table.drop(columns="bridge_start"), pool)
    bad = table.copy()
    bad.loc[1, "speed"] = -3.0
    bad.loc[2, "vehicle"] = "truck"
    bad.loc[3, "profile_offset"] = -1.0
    with pytest.raises(ValueError) as info:
        studies.run(bad, pool)
    message = str(info.value)
    assert "row 1: speed" in message
    assert "row 2: vehicle is not a vbi.Vehicle" in message
    assert "row 3: profile_offset" in message
    assert pool.submitted == 0
    with pytest.raises(ValueError, match="unknown axes"):
        studies.grid(1, 2, 3, 4, 5, speeeds=[1.0])
    with pytest.raises(ValueError, match="exactly one of c10 and iso_class"):
        studies.ISOProfile(100.0, 0.025)
