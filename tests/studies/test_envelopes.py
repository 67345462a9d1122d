"""Studies of continuous bridges and responses at sections: rows equal single crossings,
envelopes are the extremes of the rows, and crossings outside validity are left out."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from study_helpers import CountingExecutor

import vbi_lib as vbi
from vbi_lib import studies
from vbi_lib.roughness import iri

EI, MBAR = 3e9, 4000.0
THREE = vbi.Bridge.continuous([12.0, 16.0, 12.0], EI=EI, mass_per_length=MBAR)
ONE = vbi.Bridge(16.0, 1, EI, MBAR)
TRUCK = vbi.Vehicle.from_frequency(1.5e4, 3.0, 0.1)
ROAD = studies.HarmonicProfile(60.0, 0.05, 5.0, 0.002)
SECTIONS = [6.0, 12.0]


def study() -> pd.DataFrame:
    return studies.grid({"three": THREE, "one": ONE}, TRUCK, ROAD, [12.0, 24.0], 15.0,
                        model="modal", modes=5)  # fmt: skip


def test_section_columns_equal_single_crossings() -> None:
    table = study()
    result = studies.run(table, "serial", sections=SECTIONS)
    assert result["section_2"].tolist() == [12.0] * 4
    for i in range(len(table)):
        row = table.iloc[i]
        crossing = vbi.simulate(row.bridge, row.vehicle, row.profile.build(), row.speed,
                                row.bridge_start, model="modal", modes=5)  # fmt: skip
        sections = crossing.sections(SECTIONS)
        got = result.iloc[i]
        for k in (1, 2):
            assert got[f"moment_max_{k}"] == pytest.approx(sections.maximum[1, k - 1], rel=1e-12)
            assert got[f"shear_min_{k}"] == pytest.approx(sections.minimum[2, k - 1], rel=1e-12)
            assert got[f"moment_static_min_{k}"] == pytest.approx(
                sections.static.minimum[1, k - 1], rel=1e-12
            )
            assert got[f"shear_at_moment_max_{k}"] == pytest.approx(
                sections.coincident("moment", "max", "shear")[k - 1], rel=1e-12
            )
            daf = sections.daf[0, k - 1]
            assert got[f"displacement_daf_{k}"] == pytest.approx(daf, rel=1e-12, nan_ok=True)
        n = row.bridge.n_spans
        np.testing.assert_allclose(got[[f"daf_{j}" for j in range(1, n + 1)]].to_numpy(float),
                                   crossing.daf, rtol=1e-12)  # fmt: skip
    # the same study without sections runs in the batch kernels and gives the same DAFs
    plain = studies.run(table, "serial")
    assert "section_1" not in plain.columns
    np.testing.assert_allclose(
        plain.filter(like="daf_").to_numpy(float),
        result.filter(regex=r"^daf_\d$").to_numpy(float),
        rtol=1e-12,
    )


def test_continuous_bridges_get_a_daf_column_per_span_and_iri_per_span() -> None:
    result = studies.run(study(), "serial", iri=True)
    assert list(result.filter(regex=r"^daf_\d$").columns) == ["daf_1", "daf_2", "daf_3"]
    assert result["daf"].tolist() == result[["daf_1", "daf_2", "daf_3"]].max(axis=1).tolist()
    three = result[result.bridge_name == "three"].iloc[0]
    road = ROAD.build()
    supports = 15.0 + np.array(THREE.supports)
    for j in range(3):
        expected = iri(road.segment(supports[j], supports[j + 1])).iri
        assert three[f"iri_{j + 1}"] == pytest.approx(expected, rel=1e-12)
    assert three.bridge_span == 16.0 and three.bridge_n_spans == 3
    label = result[result.bridge_name == "three"].index[0]
    unnamed = studies.run(study().drop(columns="bridge_name"), "serial")
    assert unnamed.loc[label, "bridge_name"].startswith("12 + 16 + 12 m, ")


def test_envelope_takes_the_extremes_of_the_rows() -> None:
    result = studies.run(study(), "serial", sections=SECTIONS)
    env = studies.envelope(result, by="bridge_name")
    assert len(env) == 2 * 2 * 3
    for (name, section, effect), row in env.set_index(
        ["bridge_name", "section", "effect"]
    ).iterrows():
        rows = result[result.bridge_name == name]
        k = SECTIONS.index(section) + 1
        assert row.maximum == rows[f"{effect}_max_{k}"].max()
        assert row.minimum == rows[f"{effect}_min_{k}"].min()
        assert row.crossing_of_maximum == rows[f"{effect}_max_{k}"].idxmax()
        assert row.crossings == 2 and row.excluded_lost_contact == 0


def test_envelope_leaves_out_crossings_that_lost_contact() -> None:
    rough = studies.HarmonicProfile(60.0, 0.02, 2.0, 0.03)
    truck = vbi.Vehicle.from_frequency(1e4, 3.0, 0.05)
    roads = {"smooth": ROAD, "rough": rough}
    table = studies.grid(ONE, truck, roads, 15.0, 15.0, model="modal", modes=4)
    with pytest.warns(vbi.ContactLossWarning):
        result = studies.run(table, "serial", sections=[8.0])
    assert result["lost_contact"].tolist() == [False, True]
    env = studies.envelope(result)
    assert (env.crossings == 1).all() and (env.excluded_lost_contact == 1).all()
    moment = env.set_index("effect").loc["moment"]
    assert moment.maximum == result.loc[0, "moment_max_1"]
    every = studies.envelope(result, include_lost_contact=True).set_index("effect")
    assert every.loc["moment", "maximum"] == result["moment_max_1"].max()


def test_sections_off_a_bridge_are_refused_before_any_work() -> None:
    executor = CountingExecutor()
    with pytest.raises(ValueError, match=r"station 20 m lies beyond the end .* rows 2, 3"):
        studies.run(study(), executor, sections=[5.0, 20.0])
    assert executor.submitted == 0
    with pytest.raises(ValueError, match="sections=\\[-1.0\\]"):
        studies.run(study(), "serial", sections=[-1.0])
    with pytest.raises(ValueError, match="no section columns"):
        studies.envelope(studies.run(study(), "serial"))
    with pytest.raises(ValueError, match="by='bridge'"):
        studies.envelope(studies.run(study(), "serial", sections=[5.0]), by="bridge")
