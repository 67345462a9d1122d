"""A study keeps every validity field of every crossing, whatever options it runs with.

Reference: :func:`vbi_lib.simulate` of each crossing alone.  A small matrix (the study's
sprung mass, a quarter car that flies, an HS20 on its tyres; one, two and three spans; both
models where they apply; two speeds over a bump) runs through :func:`vbi_lib.studies.run`
with and without ``sections``, serially, on a process pool and on a Dask LocalCluster; each
row's contact flags (``outside_validity``, ``lost_contact``) must be the crossing's, its
fractions and smallest contact force equal to rounding, and its notes columns the same
whatever the options.  :func:`~vbi_lib.studies.envelope` leaves out exactly the crossings
that lost contact.  About 40 s on a loaded 2-core machine (a pool and a cluster start).
"""

from __future__ import annotations

import concurrent.futures as cf
import multiprocessing
import warnings

import numpy as np
import pandas as pd
import pytest

import vbi_lib as vbi
from vbi_lib import studies
from vbi_lib.vehicles import hs20

START = 40.0
SECTION = 5.0
FLAGS = ["outside_validity", "lost_contact"]
FRACTIONS = ["flight_fraction", "tension_fraction", "min_contact_force_ratio"]
NOTES = ["bridge_notes", "vehicle_notes", "profile_notes"]


def _matrix() -> pd.DataFrame:
    bridges = {
        "1 span": vbi.Bridge(16.0, 1, 2e9, 5e3),
        "2 spans": vbi.Bridge(16.0, 2, 2e9, 5e3),
        "3 spans": vbi.Bridge.continuous([12.0, 16.0, 12.0], EI=2e9, mass_per_length=5e3),
    }
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.OutsideValidityWarning)  # a 0.6 m footprint
        vehicles = {
            "sprung mass": vbi.Vehicle.from_frequency(2e4, 3.0, 0.05),
            "quarter car": vbi.QuarterCar.from_frequencies(4e3, 500.0, 1.5, 12.0, footprint=0.0),
            "HS20": hs20(footprint=0.6),
        }
    road = vbi.Profile.bump(START + 100.0, 0.02, position=START + 2.0, height=0.08, width=0.3)
    rows = []
    for b_name, bridge in bridges.items():
        for v_name, vehicle in vehicles.items():
            for model in ("one-coordinate", "modal"):
                if model == "one-coordinate" and bridge.n_spans > 2:
                    continue
                for speed in (10.0, 25.0):
                    rows.append({
                        "bridge": bridge, "vehicle": vehicle, "profile": road, "speed": speed,
                        "bridge_start": START, "model": model,
                        "modes": 4 if model == "modal" else None,
                        "bridge_name": b_name, "vehicle_name": v_name,
                    })  # fmt: skip
    table = pd.DataFrame(rows)
    table["modes"] = pd.Series([r["modes"] for r in rows], dtype=object)  # ints and None
    return table


@pytest.fixture(scope="module")
def matrix() -> tuple[pd.DataFrame, pd.DataFrame]:
    """The scenarios and, per row, the validity fields of ``vbi.simulate`` alone."""
    table = _matrix()
    direct = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.VbiWarning)
        for row in table.itertuples():
            modes = int(row.modes) if row.model == "modal" else None
            run = vbi.simulate(row.bridge, row.vehicle, row.profile, row.speed, row.bridge_start,
                               model=row.model, modes=modes)  # fmt: skip
            direct.append({name: getattr(run, name) for name in FLAGS + FRACTIONS})
    return table, pd.DataFrame(direct)


@pytest.fixture(scope="module")
def executors():  # noqa: ANN201 - a generator of executors by name
    """Serial, a spawned process pool and a Dask LocalCluster, each started once."""
    distributed = pytest.importorskip("dask.distributed")
    pool = cf.ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn"))
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    client = distributed.Client(cluster)
    try:
        yield {"serial": "serial", "process pool": pool, "dask": client.get_executor()}
    finally:
        client.close()
        cluster.close()
        pool.shutdown(cancel_futures=True)


def test_the_matrix_has_every_kind_of_validity() -> None:
    """The matrix must hold tension, flight and neither, or the test below proves little."""
    table = _matrix()
    assert len(table) == 30 and set(table.model) == {"one-coordinate", "modal"}


def test_every_option_keeps_the_crossings_validity_fields(matrix, executors) -> None:  # noqa: ANN001
    table, direct = matrix
    assert direct["outside_validity"].any() and not direct["outside_validity"].all()
    assert (direct["flight_fraction"] > 0).any()
    assert (~direct["lost_contact"]).any()
    seen = {}
    for name, executor in executors.items():
        for sections in (None, [SECTION]):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", vbi.VbiWarning)
                result = studies.run(table, executor, chunk_size=4, sections=sections)
            where = f"{name}, sections={sections}"
            for flag in FLAGS:
                assert result[flag].tolist() == direct[flag].tolist(), (where, flag)
            for field in FRACTIONS:
                np.testing.assert_allclose(result[field], direct[field], rtol=1e-9, atol=1e-12,
                                           err_msg=f"{where}: {field}")  # fmt: skip
            seen[where] = result[NOTES + FLAGS + FRACTIONS]
            if sections is not None:
                envelope = studies.envelope(result, by="bridge_name")
                lost = direct["lost_contact"].groupby(table["bridge_name"]).sum()
                excluded = envelope.groupby("bridge_name")["excluded_lost_contact"].first()
                pd.testing.assert_series_equal(excluded, lost, check_names=False)
    first = next(iter(seen.values()))
    for where, columns in seen.items():
        pd.testing.assert_frame_equal(columns, first, obj=where)
    # the HS20's tyres touch the road over 0.6 m, more than the intended 0.5 m
    truck = table["vehicle_name"] == "HS20"
    assert first["vehicle_notes"][truck].str.contains("axle 3: footprint=0.6").all()
    assert first["vehicle_notes"][~truck].isna().all()
    assert first["bridge_notes"].isna().all() and first["profile_notes"].isna().all()
