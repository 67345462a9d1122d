"""DAF from load tests (study 17): crawl or parked static response against runs at speed."""

from __future__ import annotations

import numpy as np
import pytest

from vbi_lib import monitoring as mon


def _influence(n: int = 201) -> np.ndarray:
    return np.sin(np.pi * np.linspace(0.0, 1.0, n))


def test_load_test_per_gauge_and_speed() -> None:
    line = _influence()
    wobble = np.sin(np.pi * np.linspace(0.0, 1.0, line.size))
    static_runs = {
        "strain": [120e-6 * line, 122e-6 * line],  # tension, two crawl runs: mean 121e-6
        "deflection": -3.0,  # parked truck, mm down
    }
    dynamic_runs = {
        10.0: {"strain": 121e-6 * line * (1 + 0.10 * wobble), "deflection": -3.0 * line * 1.2},
        25.0: {"strain": [121e-6 * line * (1 + 0.30 * wobble), 121e-6 * line * (1 + 0.2 * wobble)]},
    }
    table = mon.daf_from_load_test(static_runs, dynamic_runs)
    assert len(table) == 4
    got = table.set_index(["gauge", "speed", "run"])["daf"]
    assert got[("strain", 10.0, 0)] == pytest.approx(1.10, rel=1e-4)
    assert got[("deflection", 10.0, 0)] == pytest.approx(1.20, rel=1e-12)
    assert got[("strain", 25.0, 0)] == pytest.approx(1.30, rel=1e-4)
    assert got[("strain", 25.0, 1)] == pytest.approx(1.20, rel=1e-4)
    assert table.set_index(["gauge", "speed", "run"])["static"][("strain", 10.0, 0)] == (
        pytest.approx(121e-6)
    )
    worst = table.groupby(["gauge", "speed"])["daf"].max()
    assert worst[("strain", 25.0)] == pytest.approx(1.30, rel=1e-4)


def test_load_test_zeroing_and_errors() -> None:
    line = np.concatenate([np.zeros(20), _influence()]) + 0.5  # offset gauge
    table = mon.daf_from_load_test({"G": line}, {5.0: {"G": 1.1 * (line - 0.5) + 0.5}}, 20)
    assert table["daf"].iloc[0] == pytest.approx(1.1)
    with pytest.raises(ValueError, match="no static response"):
        mon.daf_from_load_test({"G": line}, {5.0: {"H": line}})
    with pytest.raises(ValueError, match="mixed sign"):
        mon.daf_from_load_test({"G": [_influence(), -_influence()]}, {5.0: {"G": line}})
    bad = _influence()
    bad[3] = np.nan
    with pytest.raises(ValueError, match="not a finite number"):
        mon.daf_from_load_test({"G": _influence()}, {5.0: {"G": bad}})
    with pytest.raises(ValueError, match="static_runs is empty"):
        mon.daf_from_load_test({}, {5.0: {"G": line}})
