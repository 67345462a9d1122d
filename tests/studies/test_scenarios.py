"""Scenario tables: the study's parametric sets, grids, Monte Carlo draws and checks before work."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from study_helpers import CountingExecutor, small_study

import vbi_lib as vbi
from vbi_lib import studies, study_data
from vbi_lib import units as u


def test_parameter_builders_reproduce_tables_2_15_3_and_2_15_4() -> None:
    """The study's printed EI (Table 2.15.3) and k (Table 2.15.4)."""
    printed_ei = study_data.table_2_15_3()["EI_lbf_in2"]  # lb in^2
    printed_k = study_data.table_2_15_4()["k_lbf_per_in"]  # lb/in
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
    with pytest.raises(ValueError, match="exactly one of c10"):
        studies.ISOProfile(100.0, 0.025)
