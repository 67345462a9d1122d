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


def test_a_trend_is_not_a_natural_frequency() -> None:
    """A tail that only drifts (power largest at the lowest frequency) gives no f1."""
    t = np.arange(0.0, 12.0, 1.0 / FS)
    with pytest.raises(ValueError, match="a trend, not a vibration"):
        mon.estimate_first_frequency(1e-3 * t**2, FS, tail_fraction=0.5)
    with_mode = 1e-3 * t**2 + 0.05 * np.sin(2 * np.pi * 3.7 * t)
    assert mon.estimate_first_frequency(with_mode, FS, tail_fraction=0.5) == pytest.approx(
        3.7, rel=0.01
    )


def test_noise_level_of_a_smooth_signal_with_noise() -> None:
    """White noise of std s read through a slow signal, a kink and a few spikes."""
    t = np.arange(0.0, 20.0, 1.0 / FS)
    smooth = np.sin(2 * np.pi * 0.4 * t) + np.abs(t - 10.0)  # a kink at 10 s
    noise = 0.02 * np.random.default_rng(8).standard_normal(t.size)
    spiky = smooth + noise
    spiky[::500] += 1.0  # eight outliers
    # the median-based estimate from 4000 samples scatters by about 2.3 % (1 sigma)
    assert mon.noise_std(spiky) == pytest.approx(0.02, rel=0.1)
    assert mon.noise_std(smooth) < 1e-4
