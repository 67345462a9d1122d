"""Gauge records made from a crossing: the clock, the drift and the noise are what was asked."""

from __future__ import annotations

import numpy as np
import pytest

from vbi_lib import monitoring as mon


def test_record_from_crossing_resamples_and_adds_drift_and_noise() -> None:
    from types import SimpleNamespace

    t = np.linspace(0.0, 10.0, 5001)
    speed, start = 5.0, 20.0  # the wheel reaches the bridge at t = 4 s
    fake = SimpleNamespace(
        time=t,
        position=speed * t,
        bridge_start=start,
        midspan_displacement=np.sin(0.7 * t)[:, None],
    )
    clock, record = mon.record_from_crossing(fake, 50.0, lead_s=1.0)
    assert clock[0] == 0.0 and clock[1] == pytest.approx(0.02)
    np.testing.assert_allclose(record, np.sin(0.7 * (clock + 3.0)), atol=1e-5)
    _, drifted = mon.record_from_crossing(fake, 50.0, lead_s=1.0, drift=0.5)
    assert drifted[-1] - record[-1] == pytest.approx(0.5)
    assert drifted[0] == pytest.approx(record[0])
    _, noisy = mon.record_from_crossing(fake, 50.0, lead_s=1.0, noise_std=0.1, seed=4)
    assert np.std(noisy - record) == pytest.approx(0.1, rel=0.1)
    with pytest.raises(ValueError, match="response has 3 values"):
        mon.record_from_crossing(fake, 50.0, response=[1.0, 2.0, 3.0])
