"""The study runner: rows equal single crossings, whatever the executor, chunking or model."""

from __future__ import annotations

import concurrent.futures as cf
import multiprocessing
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from study_helpers import CountingExecutor, small_study

import vbi_lib as vbi
from vbi_lib import studies
from vbi_lib import units as u
from vbi_lib.closed_forms import moving_force_peak

RESULT_COLUMNS = ["daf_1", "daf_2", "contact_force_amplification", "peak_contact_position"]


def test_decoupled_flat_crossing_is_the_moving_force_closed_form() -> None:
    # f1 = 1.65 Hz, so that alpha = 0.9 is a speed a vehicle can have (89 m/s)
    bridge = vbi.Bridge(30.0, 1, 8e9, 9000.0, damping_ratio=0.0)
    truck = vbi.Vehicle.from_frequency(2.0e4, 3.0, 0.1)
    f1 = bridge.first_frequency_hz
    alphas = np.array([0.1, 0.25, 0.617, 0.9])
    speeds = alphas * 2.0 * f1 * bridge.span
    table = studies.grid(
        bridge, truck, studies.FlatProfile(60.0, 0.02), list(speeds), 20.0, coupled=False
    )
    result = studies.run(table, "serial")
    expected = moving_force_peak(alphas, modes=1)
    np.testing.assert_allclose(result["daf_1"], expected, rtol=2e-4)
    # the reference sheet's printed peak at alpha = 0.617
    assert result["daf_1"].iloc[2] == pytest.approx(1.7685, abs=2e-3)
    # the contact force of a truck on a flat road, decoupled, is its weight
    np.testing.assert_allclose(result["contact_force_amplification"], 1.0, atol=1e-12)


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


def test_model_column_dispatches_to_each_model() -> None:
    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    truck = vbi.Vehicle.from_frequency(3e4, 3.0, 0.1)
    road = vbi.Profile.harmonic(130.0, 0.05, 9.0, 0.005)
    table = pd.concat(
        [
            studies.grid(bridge, truck, road, 20.0, 100.0),
            studies.grid(bridge, truck, road, 20.0, 100.0, model="modal", modes=[1, 3]),
        ],
        ignore_index=True,
    )
    result = studies.run(table, "serial")
    assert result["model"].tolist() == ["one-coordinate", "modal", "modal"]
    assert result["modes"].isna().tolist() == [True, False, False]
    assert result["daf_1"].iloc[0] == pytest.approx(
        vbi.simulate(bridge, truck, road, 20.0, 100.0).daf[0], rel=1e-12
    )
    for row, modes in ((1, 1), (2, 3)):
        single = vbi.simulate(bridge, truck, road, 20.0, 100.0, model="modal", modes=modes)
        assert result["daf_1"].iloc[row] == pytest.approx(single.daf[0], rel=1e-12)


def test_contact_columns_flag_crossings_outside_validity() -> None:
    bridge = vbi.Bridge.from_midspan_stiffness(40 * u.ft, 1, 587723 * u.lbf / u.inch, 9.95)
    truck = vbi.Vehicle.from_frequency(200 * u.slinch, 10.5, 0.1, damped=True)
    road = studies.ISOProfile(40.0, 0.0254, c10=4e-3, seed=3)
    table = studies.grid(bridge, truck, [road, studies.FlatProfile(40.0, 0.0254)], 20.0, 20.0)
    with pytest.warns(vbi.ContactLossWarning, match="1 of 2 crossings lost contact"):
        result = studies.run(table, "serial")
    assert result["lost_contact"].tolist() == [True, False]
    single = vbi.simulate(bridge, truck, road.build(), 20.0, 20.0)  # warns too
    assert result["min_contact_force_ratio"].iloc[0] == pytest.approx(
        single.min_contact_force_ratio, rel=1e-12
    )
    assert result["tension_fraction"].iloc[0] == pytest.approx(single.tension_fraction)
    assert result["tension_fraction"].iloc[1] == 0.0


def test_iri_on_request_is_the_iri_of_each_span() -> None:
    road = vbi.Profile.iso8608(130.0, 0.025, c10=64e-6, seed=3)
    bridges = [vbi.Bridge(30.0, 1, 2e10, 8000.0), vbi.Bridge(30.0, 2, 2e10, 8000.0)]
    table = studies.grid(bridges, vbi.Vehicle.from_frequency(3e4, 3.0), road, 20.0, 60.0)
    result = studies.run(table, "serial", iri=True)
    assert result["iri_1"].iloc[0] == pytest.approx(vbi.iri(road.segment(60.0, 90.0)).iri)
    assert np.isnan(result["iri_2"].iloc[0])
    both = vbi.iri(road.segment(60.0, 120.0), segment_length=30.0).segment_iri
    np.testing.assert_allclose(result[["iri_1", "iri_2"]].iloc[1], both[:2])


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
    studies.recipes._build.cache_clear()
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


def test_a_study_may_hold_any_vehicle() -> None:
    """Rows of quarter cars, HS20 trucks and the sprung mass equal single crossings."""
    import warnings

    bridge = vbi.Bridge(20.0, 1, 8e9, 6000.0)
    trucks = {
        "sprung": vbi.Vehicle.from_frequency(2e4, 3.0, 0.1),
        "quarter": vbi.QuarterCar.from_frequencies(4000.0, 500.0, 1.5, 12.0, 0.1, 0.02),
        "hs20": vbi.vehicles.hs20(),
    }
    road = studies.ISOProfile(60.0, 0.02, iso_class="D", seed=3)
    models = ["one-coordinate", "modal"]
    table = studies.grid(bridge, trucks, road, [15.0, 25.0], 15.0, model=models)
    table.loc[table.model == "modal", "modes"] = 3
    result = studies.run(table, "serial")
    assert result["vehicle_axles"].tolist() == [1, 1, 1, 1, 1, 1, 1, 1, 3, 3, 3, 3]
    assert result.loc[result.vehicle_name == "hs20", "vehicle_stiffness"].isna().all()
    for i in range(len(table)):
        row = table.iloc[i]
        options = {"model": row.model, "modes": None if row.model != "modal" else 3}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", vbi.ContactLossWarning)
            crossing = vbi.simulate(bridge, row.vehicle, road.build(), row.speed, 15.0, **options)
        got = result.iloc[i]
        assert got["daf_1"] == pytest.approx(crossing.daf[0], rel=1e-9)
        assert got["flight_fraction"] == pytest.approx(crossing.flight_fraction, abs=1e-12)
        assert got["lost_contact"] == crossing.lost_contact
        assert got["outside_validity"] == crossing.outside_validity
    with pytest.raises(ValueError, match="vehicle wheelbase 8.5344 m"):
        studies.run(studies.grid(bridge, trucks["hs20"], studies.FlatProfile(30.0, 0.05), 20.0,
                                 5.0), "serial")  # fmt: skip


def test_a_road_slid_back_is_the_segment_shifted_number_for_number() -> None:
    """The runner's one-copy road equals Profile.segment(...).shifted(...) bit for bit."""
    from vbi_lib.studies.chunks import _road

    rng = np.random.default_rng(5)
    for trial in range(200):
        x = np.cumsum(rng.uniform(0.01, 1.0, 50))
        if trial % 3 == 0:  # round stations: the cut often falls on a sample
            x = np.unique(np.round(x, 1))
        profile = vbi.Profile(x, rng.normal(size=x.size))
        offset = rng.uniform(0.0, 0.9 * profile.length)
        if trial % 4 == 0:
            offset = float(x[rng.integers(1, x.size - 1)] - x[0])
        expected = profile.segment(profile.start + offset, profile.end).shifted(-offset)
        road = _road(profile, offset)
        np.testing.assert_array_equal(road.x, expected.x)
        np.testing.assert_array_equal(road.elevation, expected.elevation)
