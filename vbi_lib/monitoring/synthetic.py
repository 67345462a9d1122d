"""Gauge records made from simulated crossings: resampled, with noise and a drifting baseline.

A simulated crossing knows its true DAF (divide by a crawl run); :func:`record_from_crossing`
turns its response into what a gauge would log (a uniform clock at the gauge's sampling rate,
white Gaussian noise, a baseline that wanders), so field methods such as
:func:`vbi_lib.monitoring.daf_from_record` can be checked where a field test cannot.
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validation as check
from .filtering import _record


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
        A :class:`vbi_lib.Crossing` or :class:`vbi_lib.ModalCrossing` (anything with
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


__all__ = ["record_from_crossing"]
