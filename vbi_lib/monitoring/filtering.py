"""Filtering a gauge record: a zero-phase low-pass and the first frequency of its free vibration.

Two signal-processing steps behind :func:`vbi_lib.monitoring.daf_from_record`:

* :func:`lowpass`: a Butterworth low-pass run forward and backward
  (``scipy.signal.sosfiltfilt``), so the quasi-static part of a record keeps the timing of
  its peak; the magnitude response is the Butterworth's squared;
* :func:`estimate_first_frequency`: the first natural frequency from the free vibration at
  the end of a record, the peak of its Welch power spectral density (``scipy.signal.welch``).

and a robust estimate of a record's white-noise level (:func:`noise_std`).  The filter and
the first-frequency estimate refuse records with gaps (NaN or infinite samples), records too
short for the filter to settle, and spectra without a clear peak, with a message that says
what to do.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import signal as _signal

from .. import _validation as check

#: Fewest periods of the cut-off frequency a record must span for the filter to settle.
MIN_CUTOFF_PERIODS = 3.0
#: Butterworth order of the low-pass (applied forward and backward: 8th-order roll-off).
DEFAULT_FILTER_ORDER = 4


def _record(name: str, values: object) -> np.ndarray:
    array = check.real_array(name, values)
    if array.ndim != 1:
        raise ValueError(f"{name} must be one-dimensional, got shape {array.shape}")
    bad = ~np.isfinite(array)
    if bad.any():
        index = int(np.flatnonzero(bad)[0])
        raise ValueError(
            f"{name}[{index}]={float(array[index])!r} is not a finite number "
            f"({int(bad.sum())} of {array.size} samples are NaN or infinite); "
            "fill or trim the gaps before estimating the DAF"
        )
    return array


def _lowpass_sos(cutoff_hz: float, sample_rate_hz: float, order: int) -> np.ndarray:
    nyquist = sample_rate_hz / 2.0
    if cutoff_hz >= nyquist:
        raise ValueError(
            f"cutoff_hz={cutoff_hz!r} is at or above the Nyquist frequency {nyquist:g} Hz "
            f"of sample_rate_hz={sample_rate_hz!r}; choose a cut-off below {nyquist:g} Hz"
        )
    order = check.integer("order", order, low=1, high=12)
    return _signal.butter(order, cutoff_hz, btype="low", fs=sample_rate_hz, output="sos")


def lowpass(
    signal: np.ndarray,
    sample_rate_hz: float,
    cutoff_hz: float,
    order: int = DEFAULT_FILTER_ORDER,
) -> np.ndarray:
    """Zero-phase Butterworth low-pass of a record (``scipy.signal.sosfiltfilt``).

    Filtering forward and backward cancels the phase shift, so the filtered peak stays at the
    time of the true peak; the magnitude response is the Butterworth's squared.

    Parameters
    ----------
    signal
        Record, one sample per ``1 / sample_rate_hz`` seconds (any unit).
    sample_rate_hz
        Sampling rate [Hz].
    cutoff_hz
        -3 dB frequency of the one-way filter [Hz], below the Nyquist frequency.
    order
        Butterworth order of the one-way filter.

    Raises
    ------
    ValueError
        NaN or infinite samples, a cut-off at or above Nyquist, or a record shorter than
        ``MIN_CUTOFF_PERIODS`` periods of the cut-off.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0, 10, 0.01)
    >>> y = lowpass(np.sin(2 * np.pi * 0.2 * t) + np.sin(2 * np.pi * 20 * t), 100.0, 2.0)
    >>> bool(np.abs(y - np.sin(2 * np.pi * 0.2 * t))[200:800].max() < 1e-3)
    True
    """
    x = _record("signal", signal)
    fs = check.positive("sample_rate_hz", sample_rate_hz)
    fc = check.positive("cutoff_hz", cutoff_hz)
    sos = _lowpass_sos(fc, fs, order)
    padlen = 3 * (2 * len(sos) + 1)
    needed = max(int(math.ceil(MIN_CUTOFF_PERIODS * fs / fc)), padlen + 1)
    if x.size < needed:
        raise ValueError(
            f"the record has {x.size} samples ({x.size / fs:.3g} s) but a {fc:g} Hz cut-off "
            f"needs at least {needed} ({needed / fs:.3g} s, {MIN_CUTOFF_PERIODS:g} periods of "
            "the cut-off); record a longer window or raise cutoff_hz"
        )
    return _signal.sosfiltfilt(sos, x)


def estimate_first_frequency(
    signal: np.ndarray, sample_rate_hz: float, tail_fraction: float = 0.3
) -> float:
    """First natural frequency [Hz] from the free-vibration tail of a record (Welch peak).

    The last ``tail_fraction`` of the record (after the vehicle has left) is detrended and its
    power spectral density estimated with ``scipy.signal.welch`` (Hann segments of half the
    tail, half overlapping, zero-padded 16 times); the frequency of the largest peak above two
    frequency bins of a segment is returned, refined by a parabola through the peak and its
    neighbours (on the log power).  A spectrum largest at its lowest usable frequency is a
    trend (drift, the end of the passage), not a vibration, and is refused.

    Raises
    ------
    ValueError
        Tail shorter than 64 samples, no peak that stands twenty times above the median
        power (white noise alone stays below 8), or power largest at the lowest usable
        frequency (no free vibration to measure: pass the frequency yourself).

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0, 20, 0.005)
    >>> tail = np.exp(-0.2 * t) * np.sin(2 * np.pi * 3.3 * t)
    >>> round(estimate_first_frequency(tail, 200.0, tail_fraction=1.0), 2)
    3.3
    """
    x = _record("signal", signal)
    fs = check.positive("sample_rate_hz", sample_rate_hz)
    if not (0.0 < check.number("tail_fraction", tail_fraction) <= 1.0):
        raise ValueError(f"tail_fraction={tail_fraction!r} must be in (0, 1]")
    n_tail = int(round(x.size * float(tail_fraction)))
    if n_tail < 64:
        raise ValueError(
            f"the free-vibration tail has {n_tail} samples (tail_fraction={tail_fraction!r} of "
            f"{x.size}); it needs at least 64 to estimate the first frequency: record a longer "
            "tail or pass first_frequency_hz"
        )
    tail = _signal.detrend(x[-n_tail:], type="linear")
    nperseg = n_tail // 2
    freq, power = _signal.welch(tail, fs=fs, window="hann", nperseg=nperseg, nfft=16 * nperseg)
    floor = 2.0 * fs / nperseg
    usable = freq > floor
    if not usable.any() or power[usable].max() <= 0:
        raise ValueError("the record's tail holds no vibration to measure; pass first_frequency_hz")
    index = int(np.flatnonzero(usable)[np.argmax(power[usable])])
    if power[index] < 20.0 * np.median(power[usable]):
        raise ValueError(
            "no clear natural frequency in the record's free-vibration tail (the largest "
            "spectral peak is less than twenty times the median power); pass "
            "first_frequency_hz"
        )
    if index == np.flatnonzero(usable)[0] or power[index - 1] >= power[index]:
        raise ValueError(
            "no clear natural frequency in the record's free-vibration tail (its power is "
            f"largest at the lowest frequency it resolves, {freq[index]:.3g} Hz: a trend, not "
            "a vibration); pass first_frequency_hz"
        )
    if 0 < index < freq.size - 1:
        a, b, c = np.log(power[index - 1 : index + 2] + 1e-300)
        denominator = a - 2.0 * b + c
        shift = 0.5 * (a - c) / denominator if denominator != 0 else 0.0
        return float(freq[index] + shift * (freq[1] - freq[0]))
    return float(freq[index])


def noise_std(signal: np.ndarray) -> float:
    """Standard deviation of a record's white noise, from its second differences (robust).

    White noise of standard deviation ``s`` gives second differences of standard deviation
    ``sqrt(6) s``, while a smooth signal sampled many times per cycle gives almost none; the
    median absolute deviation (times 1.4826, its ratio to the standard deviation of a normal
    distribution) ignores the few large differences at kinks and at the crests of fast
    vibrations.  A record sampled ten times per cycle of a vibration of amplitude ``A`` reads
    about ``0.1 A`` from the vibration alone: an upper bound on the noise, not an estimate.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0, 20, 0.005)
    >>> noise = np.random.default_rng(0).standard_normal(t.size)
    >>> noisy = np.sin(2 * np.pi * 0.5 * t) + 0.01 * noise
    >>> round(noise_std(noisy), 3)
    0.01
    """
    x = _record("signal", signal)
    if x.size < 3:
        raise ValueError(f"the record has {x.size} samples; the noise level needs at least 3")
    second = np.diff(x, 2)
    deviation = np.median(np.abs(second - np.median(second)))
    return float(1.4826 * deviation / math.sqrt(6.0))


def without_straight_baseline(values: np.ndarray, fraction: float) -> np.ndarray:
    """``values`` minus the straight line through the medians of its two end fractions.

    The line passes through the median of the first and of the last ``fraction`` of the
    samples (at least one each), placed at the middle of each; ``fraction = 0`` returns a
    copy unchanged.  Offsets and a steady drift of a gauge go; an event in between stays.
    """
    values = np.asarray(values, dtype=float)
    if fraction <= 0:
        return values.copy()
    n_end = max(1, int(round(fraction * values.size)))
    t = np.arange(values.size, dtype=float)
    t0, t1 = (n_end - 1) / 2.0, values.size - 1 - (n_end - 1) / 2.0
    y0, y1 = np.median(values[:n_end]), np.median(values[-n_end:])
    return values - (y0 + (y1 - y0) * (t - t0) / (t1 - t0))


__all__ = [
    "DEFAULT_FILTER_ORDER",
    "MIN_CUTOFF_PERIODS",
    "estimate_first_frequency",
    "lowpass",
    "noise_std",
    "without_straight_baseline",
]
