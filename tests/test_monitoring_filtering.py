"""The zero-phase low-pass and the first-frequency estimate, against signals of known content."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal as sps

from vbi_lib import monitoring as mon

FS = 200.0


def test_filter_is_zero_phase() -> None:
    t = np.arange(0.0, 20.0, 1.0 / FS)
    slow = np.sin(2 * np.pi * 0.3 * t)
    filtered = mon.lowpass(slow + 0.5 * np.sin(2 * np.pi * 15 * t), FS, 2.0)
    middle = slice(int(3 * FS), int(17 * FS))
    np.testing.assert_allclose(filtered[middle], slow[middle], atol=2e-3)
    # a symmetric pulse keeps its peak time; a one-way filter would delay it
    pulse = np.exp(-0.5 * ((t - 10.0) / 0.3) ** 2)
    assert t[np.argmax(mon.lowpass(pulse, FS, 1.0))] == pytest.approx(10.0, abs=0.5 / FS)
    one_way = sps.sosfilt(sps.butter(4, 1.0, fs=FS, output="sos"), pulse)
    assert t[np.argmax(one_way)] > 10.1


def test_first_frequency_from_the_tail() -> None:
    t = np.arange(0.0, 12.0, 1.0 / FS)
    tail = np.exp(-0.25 * t) * np.sin(2 * np.pi * 3.7 * t + 0.4)
    record = np.concatenate([np.zeros(400), tail])
    assert mon.estimate_first_frequency(record, FS, tail_fraction=0.5) == pytest.approx(
        3.7, rel=0.005
    )
