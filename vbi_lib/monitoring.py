r"""Measuring amplification in the field: strain versus displacement, filtering, load tests.

Three tools for the study's chapter on in-situ measurement.

**Strain versus displacement (equations 19-31).**  A simply supported beam carries a vehicle
force :math:`A_v P` at midspan and, while it vibrates, the inertia of its own mass.  In mode
:math:`n` that inertia is the distributed load
:math:`(m_b A_n / L) \sin(n \pi x / L)` (23)-(24) with :math:`m_b` the beam's mass and
:math:`A_n` the modal acceleration amplitude.  Adding the two static solutions and dividing by
the point-load solutions :math:`P L^3 / 48 EI` (19) and :math:`P L / 4` (21) gives, with
:math:`r_n = m_b A_n / P`,

.. math::
    DAF_d = A_v + \sum_n \frac{48\, r_n \sin(n\pi/2)}{n^4 \pi^4}, \qquad
    DAF_s = A_v + \sum_n \frac{4\, r_n \sin(n\pi/2)}{n^2 \pi^2}

(25)-(27) for the first mode, (29)-(30) in general.  The extra terms stand in the ratio
:math:`12 / (n^2 \pi^2)` (28), (31): 1.216 for the first mode, so a displacement gauge reads
more amplification than a strain gauge whenever the first mode vibrates.

**Operational monitoring.**  :func:`daf_from_record` estimates the quasi-static part of a
recorded event with a zero-phase Butterworth low-pass (``scipy.signal.sosfiltfilt``) and
returns peak / filtered peak.  The cut-off must lie between the loading frequency
``speed / span`` and the first natural frequency; when the loading is faster than the first
frequency no cut-off separates them and the estimate is biased high.

**Load tests.**  :func:`daf_from_load_test` divides peaks of runs at speed by the static
response from crawl runs or a parked truck, per gauge and per speed.

Limits: the algebra is for a simply supported beam and a point load at midspan; the filter
assumes each record starts before the vehicle arrives and ends with the bridge vibrating
freely after it has left.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy import signal as _signal

from . import _validation as check

#: Displacement coefficient of the first-mode inertia term, ``48 / pi^4`` (26).
DISPLACEMENT_INERTIA_COEFFICIENT = 48.0 / math.pi**4
#: Strain (stress, moment) coefficient of the first-mode inertia term, ``4 / pi^2`` (27).
STRAIN_INERTIA_COEFFICIENT = 4.0 / math.pi**2

#: Fewest samples per period of the first natural frequency :func:`daf_from_record` accepts.
#: Ten samples a cycle catch a sinusoid's crest to within ``1 - cos(18 deg)`` = 4.9 %.
MIN_SAMPLES_PER_CYCLE = 10
#: Fewest periods of the cut-off frequency a record must span for the filter to settle.
MIN_CUTOFF_PERIODS = 3.0
#: Butterworth order of the low-pass (applied forward and backward: 8th-order roll-off).
DEFAULT_FILTER_ORDER = 4


# ---------------------------------------------------------------------------- algebra
def inertia_ratio(beam_mass: float, acceleration: float | np.ndarray, force: float) -> np.ndarray:
    """``r = m_b A / P``: peak inertia force of the beam over the vehicle weight (25)-(27).

    Parameters
    ----------
    beam_mass
        Total mass of the (simply supported) beam ``m_b`` [kg].
    acceleration
        Modal acceleration amplitude ``A`` (midspan for mode 1) [m/s^2]; an array for several
        modes.
    force
        Vehicle weight ``P`` [N].

    Examples
    --------
    >>> float(inertia_ratio(50_000.0, 0.5, 250_000.0))
    0.1
    """
    beam_mass = check.positive("beam_mass", beam_mass)
    force = check.positive("force", force)
    acceleration = np.asarray(acceleration, dtype=float)
    if not np.all(np.isfinite(acceleration)):
        raise ValueError(f"acceleration={acceleration!r} must be finite")
    return beam_mass * acceleration / force


def _mode_numbers(modes: int | Sequence[int]) -> np.ndarray:
    numbers = np.atleast_1d(np.asarray(modes))
    if numbers.ndim != 1 or numbers.size == 0 or not np.issubdtype(numbers.dtype, np.integer):
        raise ValueError(f"modes={modes!r} must be a mode number or a list of them (1, 2, ...)")
    if np.any(numbers < 1):
        raise ValueError(f"modes={modes!r} must hold mode numbers >= 1")
    return numbers.astype(int)


def _sin_half_pi(n: np.ndarray) -> np.ndarray:
    """``sin(n pi / 2)`` exactly for integers: 0 for even n, +1/-1 alternating for odd n."""
    return np.where(n % 2 == 0, 0.0, np.where(n % 4 == 1, 1.0, -1.0))


def _inertia_terms(
    ratio: float | np.ndarray, modes: int | Sequence[int], power: int, coefficient: float
) -> np.ndarray:
    numbers = _mode_numbers(modes)
    ratio = np.asarray(ratio, dtype=float)
    if not np.all(np.isfinite(ratio)):
        raise ValueError(f"inertia_ratio={ratio!r} must be finite")
    weights = coefficient * _sin_half_pi(numbers) / (numbers.astype(float) ** power)
    if np.ndim(modes) == 0:
        return ratio * weights[0]
    if ratio.ndim == 0 or ratio.shape[-1] != numbers.size:
        raise ValueError(
            f"inertia_ratio has shape {ratio.shape}; with modes={list(numbers)} its last axis "
            f"must hold one ratio per mode ({numbers.size})"
        )
    return ratio @ weights


def displacement_daf(
    vehicle_amplification: float | np.ndarray,
    inertia_ratio: float | np.ndarray,
    modes: int | Sequence[int] = 1,
) -> np.ndarray:
    """Midspan displacement amplification with the beam's own inertia (26), (29).

    ``DAF_d = A_v + sum_n 48 r_n sin(n pi / 2) / (n^4 pi^4)``.

    Parameters
    ----------
    vehicle_amplification
        ``A_v``: the vehicle's contact force over its weight [-].
    inertia_ratio
        ``r_n = m_b A_n / P`` [-]; with ``modes`` a list, the last axis holds one ratio per
        mode.
    modes
        Mode number (default 1) or list of mode numbers; even modes add nothing at midspan.

    Examples
    --------
    >>> round(float(displacement_daf(1.1, 0.5)), 4)   # 1.1 + 0.5 * 48 / pi^4
    1.3464
    """
    terms = _inertia_terms(inertia_ratio, modes, 4, 48.0 / math.pi**4)
    return np.asarray(vehicle_amplification, dtype=float) + terms


def strain_daf(
    vehicle_amplification: float | np.ndarray,
    inertia_ratio: float | np.ndarray,
    modes: int | Sequence[int] = 1,
) -> np.ndarray:
    """Midspan strain (stress, moment) amplification with the beam's own inertia (27), (30).

    ``DAF_s = A_v + sum_n 4 r_n sin(n pi / 2) / (n^2 pi^2)``; arguments as for
    :func:`displacement_daf`.

    Examples
    --------
    >>> round(float(strain_daf(1.1, 0.5)), 4)   # 1.1 + 0.5 * 4 / pi^2
    1.3026
    """
    terms = _inertia_terms(inertia_ratio, modes, 2, 4.0 / math.pi**2)
    return np.asarray(vehicle_amplification, dtype=float) + terms


def extra_amplification_ratio(mode: int = 1) -> float:
    """Displacement over strain extra amplification of mode ``n``: ``12 / (n^2 pi^2)`` (28), (31).

    Above 1 only for the first mode: the higher odd modes add more to strain than to
    displacement.

    Examples
    --------
    >>> round(extra_amplification_ratio(1), 3), round(extra_amplification_ratio(3), 4)
    (1.216, 0.1351)
    """
    n = int(_mode_numbers(mode)[0])
    if np.ndim(mode) != 0:
        raise ValueError(f"mode={mode!r} must be a single mode number")
    return 12.0 / (n**2 * math.pi**2)


def plot_extra_amplification(max_ratio: float = 1.0, ax=None):  # noqa: ANN001, ANN201
    """Figure 2.11.1: amplification added by the first mode's inertia against ``r``."""
    import matplotlib.pyplot as plt

    max_ratio = check.positive("max_ratio", max_ratio)
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 3.6))
    r = np.linspace(0.0, max_ratio, 201)
    ax.plot(r, displacement_daf(0.0, r), label=r"displacement, $48 r / \pi^4$")
    ax.plot(r, strain_daf(0.0, r), label=r"strain, stress, moment, $4 r / \pi^2$")
    ax.set_xlabel(r"bridge inertia over vehicle weight $r = m_b A_{max} / P$ [-]")
    ax.set_ylabel("extra amplification [-]")
    ax.legend(loc="upper left")
    ax.grid(alpha=0.3)
    return ax


# ---------------------------------------------------------------------------- filtering
def _record(name: str, values: object) -> np.ndarray:
    array = np.asarray(values, dtype=float)
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
    if not (isinstance(order, int | np.integer) and 1 <= order <= 12):
        raise ValueError(f"order={order!r} must be an integer from 1 to 12")
    return _signal.butter(int(order), cutoff_hz, btype="low", fs=sample_rate_hz, output="sos")


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
    neighbours (on the log power).

    Raises
    ------
    ValueError
        Tail shorter than 64 samples, or no peak that stands twenty times above the median
        power (white noise alone stays below 8; no free vibration to measure: pass the
        frequency yourself).

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
    if not (0.0 < float(tail_fraction) <= 1.0):
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
    if 0 < index < freq.size - 1:
        a, b, c = np.log(power[index - 1 : index + 2] + 1e-300)
        denominator = a - 2.0 * b + c
        shift = 0.5 * (a - c) / denominator if denominator != 0 else 0.0
        return float(freq[index] + shift * (freq[1] - freq[0]))
    return float(freq[index])


@dataclass(frozen=True)
class RecordDAF:
    """The DAF of one recorded event estimated by low-pass filtering.

    Attributes
    ----------
    daf
        ``peak / quasi_static_peak`` [-].
    peak
        Extreme of the (baseline-corrected) record in its loading direction, with its sign.
    quasi_static_peak
        Extreme of the low-passed record, same direction and sign.
    cutoff_hz
        Cut-off of the low-pass [Hz].
    first_frequency_hz
        First natural frequency used [Hz] (given or estimated), or ``None`` if not needed.
    loading_frequency_hz
        ``speed / span`` [Hz], or ``None`` if speed and span were not given.
    how_chosen
        One sentence on where the cut-off and the first frequency came from, and any doubt.
    """

    daf: float
    peak: float
    quasi_static_peak: float
    cutoff_hz: float
    first_frequency_hz: float | None
    loading_frequency_hz: float | None
    how_chosen: str

    def __repr__(self) -> str:
        f1 = "?" if self.first_frequency_hz is None else f"{self.first_frequency_hz:.3g} Hz"
        fl = "?" if self.loading_frequency_hz is None else f"{self.loading_frequency_hz:.3g} Hz"
        return (
            f"RecordDAF(DAF {self.daf:.3f}: peak {self.peak:.4g} / quasi-static "
            f"{self.quasi_static_peak:.4g}; cut-off {self.cutoff_hz:.3g} Hz, f1 {f1}, "
            f"loading {fl})"
        )


def _choose_cutoff(loading: float | None, first: float) -> tuple[float, str, bool]:
    """The cut-off and a sentence saying why; the flag is True when the choice is doubtful."""
    if loading is None:
        return first / 2.0, "cut-off f1 / 2 (loading frequency unknown: pass speed and span)", False
    if loading >= first:
        return (
            first / 2.0,
            f"loading {loading:.3g} Hz is at or above f1 {first:.3g} Hz: no cut-off separates "
            "them; cut-off f1 / 2 removes part of the static response and inflates the DAF",
            True,
        )
    cutoff = math.sqrt(loading * first)
    note = "cut-off sqrt(loading frequency x f1), midway on a log scale"
    doubtful = first / loading < 4.0
    if doubtful:
        note += (
            f"; f1 / loading = {first / loading:.2g} < 4 leaves little room, expect the "
            "filter to bias the DAF"
        )
    return cutoff, note, doubtful


def _one_record(
    x: np.ndarray,
    fs: float,
    cutoff_hz: float | None,
    first_frequency_hz: float | None,
    loading: float | None,
    order: int,
    baseline_fraction: float,
    tail_fraction: float,
    noise_cutoff_hz: float | None,
    name: str,
) -> RecordDAF:
    x = _record(name, x)
    notes = []
    if first_frequency_hz is not None:
        first = check.positive("first_frequency_hz", first_frequency_hz)
        notes.append("f1 given")
    elif cutoff_hz is None:
        first = estimate_first_frequency(x, fs, tail_fraction)
        notes.append(f"f1 from the Welch peak of the last {tail_fraction:.0%} of the record")
    else:
        first = None
    if first is not None and fs < MIN_SAMPLES_PER_CYCLE * first:
        raise ValueError(
            f"sample_rate_hz={fs!r} is too low for a first frequency of {first:.3g} Hz: "
            f"record at least {MIN_SAMPLES_PER_CYCLE} samples per cycle "
            f"({MIN_SAMPLES_PER_CYCLE * first:.3g} Hz)"
        )
    doubtful = False
    if cutoff_hz is None:
        cutoff, note, doubtful = _choose_cutoff(loading, first)
        notes.insert(0, note)
    else:
        cutoff = check.positive("cutoff_hz", cutoff_hz)
        notes.insert(0, "cut-off given")
        if first is not None and cutoff >= first:
            doubtful = True
            notes.append(f"cut-off at or above f1 {first:.3g} Hz lets the vibration through")
        if loading is not None and cutoff <= loading:
            doubtful = True
            notes.append(
                f"cut-off at or below the loading frequency {loading:.3g} Hz cuts the static "
                "response"
            )
    filtered = lowpass(x, fs, cutoff, order)
    response = x
    if noise_cutoff_hz is not None:
        noise_cutoff = check.positive("noise_cutoff_hz", noise_cutoff_hz)
        if noise_cutoff <= cutoff:
            raise ValueError(
                f"noise_cutoff_hz={noise_cutoff_hz!r} must be above cutoff_hz={cutoff:g}"
            )
        response = lowpass(x, fs, noise_cutoff, order)
        notes.append(f"noise removed above {noise_cutoff:.3g} Hz before taking the peak")
    if baseline_fraction > 0:
        n_end = max(1, int(round(baseline_fraction * x.size)))
        t = np.arange(x.size, dtype=float)
        t0, t1 = (n_end - 1) / 2.0, x.size - 1 - (n_end - 1) / 2.0
        y0, y1 = np.median(filtered[:n_end]), np.median(filtered[-n_end:])
        line = y0 + (y1 - y0) * (t - t0) / (t1 - t0)
        filtered = filtered - line
        response = response - line
    polarity = 1.0 if filtered.max() >= -filtered.min() else -1.0
    quasi_static = float(np.max(polarity * filtered))
    if quasi_static <= 0:
        raise ValueError(f"{name} has no quasi-static response after filtering")
    peak = float(np.max(polarity * response))
    if doubtful:
        warnings.warn(f"{name}: " + "; ".join(notes), stacklevel=3)
    return RecordDAF(
        daf=peak / quasi_static,
        peak=polarity * peak,
        quasi_static_peak=polarity * quasi_static,
        cutoff_hz=float(cutoff),
        first_frequency_hz=None if first is None else float(first),
        loading_frequency_hz=loading,
        how_chosen="; ".join(notes),
    )


def _per_event(name: str, value: object, n: int) -> list:
    if value is None or np.ndim(value) == 0:
        return [value] * n
    values = list(value)
    if len(values) != n:
        raise ValueError(f"{name} has {len(values)} values for {n} events")
    return values


def daf_from_record(
    signal: np.ndarray | Sequence[np.ndarray],
    sample_rate_hz: float,
    cutoff_hz: float | None = None,
    *,
    speed: float | Sequence[float] | None = None,
    span: float | None = None,
    first_frequency_hz: float | Sequence[float] | None = None,
    order: int = DEFAULT_FILTER_ORDER,
    baseline_fraction: float = 0.05,
    tail_fraction: float = 0.3,
    noise_cutoff_hz: float | None = None,
) -> RecordDAF | pd.DataFrame:
    """DAF of recorded events: peak of the record over the peak of its low-passed copy.

    The quasi-static response is the record low-passed with a zero-phase Butterworth filter
    (:func:`lowpass`).  A straight baseline through the filtered record's first and last
    ``baseline_fraction`` is subtracted from both (drift, offsets), the loading direction is
    the sign of the filtered record's largest excursion (tension strain up, deflection down:
    either works) and ``DAF = peak / quasi-static peak`` in that direction.

    With ``cutoff_hz=None`` the cut-off is ``sqrt(f_load f_1)``, between the loading
    frequency ``f_load = speed / span`` and the first natural frequency ``f_1`` (given, or
    the Welch peak of the record's free-vibration tail, :func:`estimate_first_frequency`).
    When ``f_load >= f_1`` the cut-off is ``f_1 / 2``: the filter then removes part of the
    static response and the DAF comes out too high; a ``UserWarning`` says so, as it does
    for any cut-off within a factor 2 of either frequency.

    Parameters
    ----------
    signal
        One record (1-D array), or several events: a list of 1-D arrays or a 2-D array with
        one event per row.  Each record should start before the vehicle arrives and end
        with ``tail_fraction`` of free vibration after it has left.
    sample_rate_hz
        Sampling rate [Hz]; at least ``MIN_SAMPLES_PER_CYCLE`` times the first frequency.
    cutoff_hz
        Cut-off of the low-pass [Hz]; ``None`` chooses it as above.
    speed
        Vehicle speed [m/s], one value or one per event; with ``span`` it gives the loading
        frequency.
    span
        Span length [m].
    first_frequency_hz
        First natural frequency [Hz], one value or one per event; ``None`` estimates it when
        the cut-off is to be chosen.
    order
        Butterworth order of the one-way filter (the zero-phase filter doubles it).
    baseline_fraction
        Fraction of the record at each end that defines the baseline; 0 keeps the record's
        own zero.
    tail_fraction
        Fraction at the end of the record used to estimate the first frequency.
    noise_cutoff_hz
        If given, the record itself is low-passed at this frequency (above the cut-off,
        typically a few times ``f_1``) before its peak is taken, so sensor noise does not
        inflate the peak.

    Returns
    -------
    RecordDAF
        For one record.
    pandas.DataFrame
        For several: one row per event with the fields of :class:`RecordDAF`.

    Raises
    ------
    ValueError
        NaN or infinite samples, a record too short for the filter, a sample rate too low
        for the first frequency, a cut-off at or above the Nyquist frequency, or a record
        without a quasi-static response.

    Examples
    --------
    A 1 s half-sine pulse of height 1 plus a 6 Hz vibration of amplitude 0.2 that crests with
    it: the true DAF is 1.2.

    >>> import numpy as np
    >>> fs = 200.0
    >>> t = np.arange(-2.0, 8.0, 1 / fs)
    >>> pulse = np.where((t > 0) & (t < 1), np.sin(np.pi * t), 0.0)
    >>> ring = 0.2 * np.exp(-0.3 * np.abs(t - 0.5)) * np.cos(2 * np.pi * 6 * (t - 0.5))
    >>> result = daf_from_record(-(pulse + ring), fs, speed=30.0, span=30.0)
    >>> round(result.daf, 2), round(result.first_frequency_hz, 1), round(result.cutoff_hz, 2)
    (1.2, 6.0, 2.45)
    """
    fs = check.positive("sample_rate_hz", sample_rate_hz)
    if not (0.0 <= float(baseline_fraction) < 0.5):
        raise ValueError(f"baseline_fraction={baseline_fraction!r} must be in [0, 0.5)")
    if span is not None:
        span = check.positive("span", span)
    several = np.ndim(signal) == 2 or (
        isinstance(signal, list | tuple)
        and len(signal) > 0
        and all(np.ndim(event) >= 1 for event in signal)
    )
    events = list(signal) if several else [signal]
    n = len(events)
    if n == 0:
        raise ValueError("signal is an empty list: give at least one record")
    speeds = _per_event("speed", speed, n)
    firsts = _per_event("first_frequency_hz", first_frequency_hz, n)
    results = []
    for i, (record, v, f1) in enumerate(zip(events, speeds, firsts, strict=True)):
        loading = None
        if v is not None and span is not None:
            loading = check.positive("speed", v) / span
        results.append(
            _one_record(
                record,
                fs,
                cutoff_hz,
                f1,
                loading,
                order,
                float(baseline_fraction),
                tail_fraction,
                noise_cutoff_hz,
                f"signal[{i}]" if several else "signal",
            )
        )
    if not several:
        return results[0]
    return pd.DataFrame([r.__dict__ for r in results]).rename_axis("event")


# ---------------------------------------------------------------------------- synthetic records
def record_from_crossing(
    crossing: object,
    sample_rate_hz: float,
    response: np.ndarray | None = None,
    lead_s: float = 1.0,
    noise_std: float = 0.0,
    drift: float = 0.0,
    seed: int | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """A gauge record made from a simulated crossing: resampled, with noise and drift.

    The response is interpolated (linearly) onto a uniform clock at ``sample_rate_hz`` that
    starts ``lead_s`` seconds before the wheel reaches the bridge and ends with the crossing
    (simulate with ``free_vibration`` to give the record a free-vibration tail).  White
    Gaussian noise of standard deviation ``noise_std`` and a baseline that wanders by
    ``drift`` along a parabola, ``drift (t / T)^2``, imitate a real gauge.

    Parameters
    ----------
    crossing
        A :class:`vbi_lib.Crossing` or :class:`vbi_lib.modal.ModalCrossing` (anything with
        ``time``, ``position``, ``bridge_start`` and ``midspan_displacement``).
    sample_rate_hz
        Sampling rate of the record [Hz].
    response
        History to record, one value per ``crossing.time`` (e.g. ``crossing.moment_at(x)``);
        default the midspan displacement of span 1 [m].
    lead_s
        Seconds of record before the wheel reaches the bridge.
    noise_std, drift
        Noise standard deviation and total baseline drift, in the response's unit.
    seed
        Seed of ``numpy.random.default_rng`` for the noise.

    Returns
    -------
    time, record
        Time from the start of the record [s] and the samples.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> bridge = vbi.Bridge.from_frequency(30.0, 1, 10_000.0, 4.0)
    >>> truck = vbi.Vehicle.from_frequency(30_000.0, 3.0, 0.1)
    >>> run = vbi.simulate(bridge, truck, vbi.Profile.flat(80.0, 0.1), 20.0, 40.0,
    ...                    free_vibration=4.0)
    >>> t, y = record_from_crossing(run, 100.0)
    >>> round(float(t[1] - t[0]), 3), round(float(t[-1]), 1)   # 1 s lead + 1.5 s on + 4 s tail
    (0.01, 6.5)
    """
    fs = check.positive("sample_rate_hz", sample_rate_hz)
    lead_s = check.non_negative("lead_s", lead_s)
    noise_std = check.non_negative("noise_std", noise_std)
    drift = float(drift)
    if not math.isfinite(drift):
        raise ValueError(f"drift={drift!r} must be a finite number")
    time = np.asarray(crossing.time, dtype=float)
    if response is None:
        values = np.asarray(crossing.midspan_displacement, dtype=float)[:, 0]
    else:
        values = _record("response", response)
        if values.size != time.size:
            raise ValueError(
                f"response has {values.size} values but the crossing has {time.size} time steps"
            )
    entry = float(np.interp(crossing.bridge_start, crossing.position, time))
    start = max(time[0], entry - lead_s)
    clock = np.arange(start, time[-1] + 0.5 / fs, 1.0 / fs)
    clock = clock[clock <= time[-1]]
    record = np.interp(clock, time, values)
    span = clock[-1] - clock[0]
    if drift:
        record = record + drift * ((clock - clock[0]) / span) ** 2
    if noise_std:
        record = record + noise_std * np.random.default_rng(seed).standard_normal(record.size)
    return clock - clock[0], record


# ---------------------------------------------------------------------------- load tests
def _runs(name: str, value: object) -> list[np.ndarray]:
    """A record, a list of records, or a single number (a parked-truck reading)."""
    if isinstance(value, list | tuple):
        runs = list(value)
    elif np.ndim(value) == 2:
        runs = list(np.asarray(value, dtype=float))
    else:
        runs = [value]
    if not runs:
        raise ValueError(f"{name} holds no runs")
    out = []
    for j, run in enumerate(runs):
        label = f"{name}[{j}]" if len(runs) > 1 else name
        array = np.atleast_1d(np.asarray(run, dtype=float))
        out.append(_record(label, array))
    return out


def daf_from_load_test(
    static_runs: Mapping[str, object],
    dynamic_runs: Mapping[float, Mapping[str, object]],
    zero_samples: int = 0,
) -> pd.DataFrame:
    """DAF per gauge, speed and run from a load test with the bridge closed to traffic.

    The static response of each gauge is the mean, over its crawl runs, of each run's
    extreme (or a parked-truck reading given as a number); its sign sets the gauge's loading
    direction.  Each run at speed gives ``DAF = dynamic peak / static response``, the peak
    taken in the same direction.

    Parameters
    ----------
    static_runs
        ``{gauge: record, list of records, or a number}`` from crawl runs or a parked truck.
    dynamic_runs
        ``{speed: {gauge: record or list of records}}`` from runs at speed; speed in m/s
        (any label works, it is copied to the table).
    zero_samples
        If > 0, each record is zeroed by the mean of its first ``zero_samples`` samples
        (taken before the truck arrives); parked-truck numbers are used as given.

    Returns
    -------
    pandas.DataFrame
        Columns ``gauge, speed, run, static, dynamic_peak, daf``; use
        ``.groupby(["gauge", "speed"]).daf.max()`` for the largest per gauge and speed.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> crawl = -2.0 * np.sin(np.pi * t)                  # deflection, mm, downward
    >>> fast = crawl * (1 + 0.25 * np.sin(np.pi * t))     # crests 25 % higher at midspan
    >>> table = daf_from_load_test({"G1": crawl}, {20.0: {"G1": fast}})
    >>> table[["gauge", "speed", "static", "dynamic_peak", "daf"]].to_dict("records")
    [{'gauge': 'G1', 'speed': 20.0, 'static': -2.0, 'dynamic_peak': -2.5, 'daf': 1.25}]
    """
    zero_samples = int(zero_samples)
    if zero_samples < 0:
        raise ValueError(f"zero_samples={zero_samples!r} must be >= 0")
    if not static_runs:
        raise ValueError("static_runs is empty: give at least one gauge's crawl run or reading")

    def zeroed(run: np.ndarray, label: str) -> np.ndarray:
        if zero_samples == 0 or run.size == 1:
            return run
        if run.size <= zero_samples:
            raise ValueError(
                f"{label} has {run.size} samples, not more than zero_samples={zero_samples}"
            )
        return run - run[:zero_samples].mean()

    static = {}
    for gauge, value in static_runs.items():
        peaks = []
        for j, run in enumerate(_runs(f"static_runs[{gauge!r}]", value)):
            run = zeroed(run, f"static_runs[{gauge!r}][{j}]")
            peaks.append(run[np.argmax(np.abs(run))])
        response = float(np.mean(peaks))
        if response == 0 or np.any(np.sign(peaks) != np.sign(response)):
            raise ValueError(
                f"static_runs[{gauge!r}] gives static peaks {peaks} that are zero or of mixed "
                "sign; check the gauge's zero and sign"
            )
        static[gauge] = response
    rows = []
    for speed, gauges in dynamic_runs.items():
        for gauge, value in gauges.items():
            if gauge not in static:
                raise ValueError(
                    f"dynamic_runs[{speed!r}] has gauge {gauge!r} with no static response; "
                    f"static_runs has {sorted(static)}"
                )
            direction = math.copysign(1.0, static[gauge])
            for j, run in enumerate(_runs(f"dynamic_runs[{speed!r}][{gauge!r}]", value)):
                run = zeroed(run, f"dynamic_runs[{speed!r}][{gauge!r}][{j}]")
                peak = direction * float(np.max(direction * run))
                rows.append(
                    {
                        "gauge": gauge,
                        "speed": speed,
                        "run": j,
                        "static": static[gauge],
                        "dynamic_peak": peak,
                        "daf": peak / static[gauge],
                    }
                )
    if not rows:
        raise ValueError("dynamic_runs holds no runs at speed")
    return pd.DataFrame(rows)
