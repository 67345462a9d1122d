"""Statistics of study results: characteristic values with their confidence intervals, and
the count of crossings that left the model's validity."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from vbi_lib import studies


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


def _study_table() -> pd.DataFrame:
    """Six crossings of two bridges, written by hand: which lost contact is known."""
    return pd.DataFrame(
        {
            "bridge_name": ["a", "a", "a", "b", "b", "b"],
            "coupled": [True, False, True, True, True, False],
            "daf": [1.4, 2.6, 4.0, 1.1, 2.2, 1.9],
            "min_contact_force_ratio": [0.5, -0.2, -1.5, 0.8, 0.3, -0.1],
            "lost_contact": [False, True, True, False, False, True],
        }
    )


def test_contact_summary_counts_by_hand() -> None:
    table = _study_table()
    whole = studies.contact_summary(table)
    assert list(whole.index) == ["all"]
    row = whole.loc["all"]
    assert row["crossings"] == 6
    assert row["lost contact"] == 3
    assert row["lost contact [%]"] == pytest.approx(50.0)
    assert row["smallest contact force / weight [-]"] == -1.5
    assert row["largest DAF [-]"] == 4.0
    assert row["largest DAF in contact [-]"] == 2.2  # 4.0 and 2.6 lost contact
    assert row["DAF > 2"] == 3  # 2.6, 4.0, 2.2
    assert row["DAF > 2, lost contact"] == 2
    assert whole["crossings"].dtype.kind == "i"  # counts stay whole numbers

    by = studies.contact_summary(table, by="bridge_name", daf_above=1.5)
    assert by.index.name == "bridge_name"
    assert by.loc["a", "DAF > 1.5"] == 2 and by.loc["a", "DAF > 1.5, lost contact"] == 2
    assert by.loc["b", "DAF > 1.5"] == 2 and by.loc["b", "DAF > 1.5, lost contact"] == 1
    assert by.loc["b", "largest DAF in contact [-]"] == 2.2

    two = studies.contact_summary(table, by=["bridge_name", "coupled"])
    assert two.loc[("a", True), "crossings"] == 2
    assert np.isnan(two.loc[("a", False), "largest DAF in contact [-]"])  # all lost contact


def test_contact_summary_agrees_with_a_run() -> None:
    """On a real run, the counts equal the table's own flags (a flat road keeps contact)."""
    import vbi_lib as vbi

    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    truck = vbi.Vehicle.from_frequency(3.0e4, 3.0, 0.1)
    roads = {
        "flat": studies.FlatProfile(130.0, 0.05),
        "wave": studies.HarmonicProfile(130.0, 0.05, 6.0, 0.03),
    }
    with pytest.warns(vbi.ContactLossWarning):
        runs = studies.run(studies.grid(bridge, truck, roads, [10.0, 20.0], 100.0), "serial")
    summary = studies.contact_summary(runs, by="profile_name")
    assert summary.loc["flat", "lost contact"] == 0
    lost = runs.loc[runs["profile_name"] == "wave", "lost_contact"]
    assert summary.loc["wave", "lost contact"] == lost.sum() > 0
    smallest = runs.loc[runs["profile_name"] == "wave", "min_contact_force_ratio"].min()
    assert summary.loc["wave", "smallest contact force / weight [-]"] == smallest < 0


def test_contact_summary_refuses_bad_tables() -> None:
    with pytest.raises(ValueError, match="lost_contact"):
        studies.contact_summary(pd.DataFrame({"daf": [1.0], "min_contact_force_ratio": [0.5]}))
    table = _study_table()
    table.loc[2, "daf"] = np.nan
    with pytest.raises(ValueError, match="NaN"):
        studies.contact_summary(table)
    with pytest.raises(ValueError, match="daf_above"):
        studies.contact_summary(_study_table(), daf_above=-1.0)
