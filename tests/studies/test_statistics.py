"""Statistics of study results: characteristic values with their confidence intervals."""

from __future__ import annotations

import numpy as np
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
