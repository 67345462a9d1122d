r"""DAF of recorded events in service: the peak over a quasi-static estimate (study eq. 17).

A gauge on a bridge in service records every vehicle that crosses; no crawl run gives the
static response :math:`Q_{sta}` of the study's definition (17), so it is estimated from the
record.  :func:`daf_from_record` returns ``DAF = peak / quasi-static peak`` with one of three
estimates (the study's section on operational monitoring and load testing):

``"filter"``
    The record low-passed with a zero-phase Butterworth filter
    (:func:`vbi_lib.monitoring.lowpass`), the method the study describes.  The cut-off must
    lie between the loading frequency ``f_load = speed / span`` and the first natural
    frequency ``f_1``; by default :math:`\sqrt{f_{load} f_1}`.  Good for smooth records
    (deflection).  It rounds off a kink: a strain, stress or moment record has one wherever
    an axle passes the gauge, and there the filtered peak is too low and the DAF several per
    cent too high even without any vibration.  When the loading is as fast as the bridge no
    cut-off separates them and the DAF is overestimated.
``"influence-line"``
    The beam's influence line of the response at the gauge, summed over the vehicle's axles,
    fitted to the record by least squares over scale, baseline, arrival time and (if not
    given) speed (:mod:`vbi_lib.monitoring.influence`; the bridge weigh-in-motion algorithm of
    Moses 1979 with the axle loads in known ratios).  It keeps the kink; it needs the
    geometry (span, number of spans, gauge section, axle spacings) and assumes ideal supports.
``"crawl"``
    A crawl run of the same vehicle (a load test), stretched to the record's speed, lined up
    with it by least squares and used as it is (scale 1).

``method="auto"`` takes the crawl run when one is given, the influence-line fit for a kinked
record (``response`` strain, stress or moment) when the span is known, and the filter
otherwise.  Every result says which method was used and why, and is flagged ``doubtful``
(with a ``UserWarning``) when its assumptions are in doubt:

* a filter on a kinked record, a cut-off squeezed between the two frequencies, or a
  quasi-static event longer than :data:`MAX_EVENT_PASSAGES` passages (drift, several
  vehicles);
* a fit whose slow residual exceeds :data:`MAX_FIT_RESIDUAL`,
  :data:`MAX_FIT_RESIDUAL_SPEED_SEARCHED` when the speed was searched (wrong span, section or
  number of spans, several vehicles, a truck bouncing through a short span) or
  :data:`MAX_CRAWL_RESIDUAL` for a crawl run (another vehicle or path); a fitted speed on the
  edge of its range; a first frequency less than :data:`MIN_FREQUENCY_RATIO` times the
  loading frequency (not for a crawl run);
* noise that can raise the peak by more than :data:`NOISE_PEAK_TOLERANCE`, or a DAF above
  :data:`MAX_PLAUSIBLE_DAF`.

Both peaks are read on the record's own clock, so sampling clips a kinked peak in the record
and in the fitted estimate alike.  A record that cannot hold an event (NaN or infinite
samples, a constant record, an event that does not stand :data:`MIN_EVENT_SNR` times above the
noise) raises a ``ValueError`` rather than returning a number.

Limits: each record must start before the vehicle arrives and end after it has left (with
free vibration after it for the filter's first-frequency estimate); one vehicle per event.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence

import numpy as np

from .. import _validation as check
from .filtering import DEFAULT_FILTER_ORDER, _record, lowpass, noise_std
from .influence import (
    KINKED_RESPONSES,
    Axles,
    axle_shape,
    check_response,
    crawl_shape,
)
from .quasi_static import (
    MAX_CRAWL_RESIDUAL,
    MAX_FIT_RESIDUAL,
    MAX_FIT_RESIDUAL_SPEED_SEARCHED,
    MIN_FREQUENCY_RATIO,
    MIN_SAMPLES_PER_CYCLE,
    check_sampling,
    event_width,
    filter_estimate,
    fit_estimate,
)
from .record_results import METHODS, RecordDAF, RecordDAFs

#: An event's quasi-static peak must be at least this many times the record's noise level.
MIN_EVENT_SNR = 5.0
#: Largest rise of the peak that three noise standard deviations may cause before the estimate
#: is flagged (pass ``noise_cutoff_hz`` to smooth the record first).
NOISE_PEAK_TOLERANCE = 0.03
#: Largest DAF reported without doubt: above it the record rarely holds one vehicle's passage.
MAX_PLAUSIBLE_DAF = 2.0
#: Longest quasi-static event the filter accepts without doubt, in passages ``span / speed``.
MAX_EVENT_PASSAGES = 4.0


def _checked(name: str, values: object) -> np.ndarray:
    """A record with finite samples that is not constant."""
    x = _record(name, values)
    if x.size < 3:
        raise ValueError(f"{name} has {x.size} samples: a record needs many more")
    spread = float(np.ptp(x))
    if spread <= 1e-9 * float(np.max(np.abs(x))) or spread == 0.0:
        raise ValueError(
            f"{name} is constant (every sample is {x[0]:g}): it holds no event; check the "
            "gauge and the trigger"
        )
    return x


def _one_record(x: np.ndarray, fs: float, name: str, plan: dict, event: dict) -> RecordDAF:
    """The DAF of one event by the planned method (``plan``: shared; ``event``: its own)."""
    x = _checked(name, x)
    method, notes, doubtful = plan["method"], list(plan["notes"]), plan["doubtful"]
    speed, span = event["speed"], plan["span"]
    first = event["first_frequency_hz"]
    if first is not None:
        first = check.positive("first_frequency_hz", first)
        check_sampling(fs, first)
        notes.append("f1 given")
    loading = None if (speed is None or span is None) else speed / span
    extra = {"speed": speed, "loading_frequency_hz": loading, "first_frequency_hz": first}
    if method == "filter":
        quasi_static, baseline, doubt, found = filter_estimate(
            x,
            fs,
            plan["cutoff_hz"],
            first,
            loading,
            plan["order"],
            plan["baseline_fraction"],
            plan["tail_fraction"],
            notes,
        )
    else:
        if method == "crawl":
            shape = plan["shape"]
        else:
            shape = axle_shape(*plan["geometry"], event["axles"])
        quasi_static, baseline, doubt, found = fit_estimate(
            x,
            fs,
            shape,
            speed,
            span,
            plan["crawl_speed"],
            method == "crawl",
            first,
            plan["tail_fraction"],
            notes,
        )
    extra.update(found)
    doubtful = doubtful or doubt
    response = x - baseline
    noise_cutoff = plan["noise_cutoff_hz"]
    if noise_cutoff is not None:
        floor = extra.get("cutoff_hz") or extra["loading_frequency_hz"] or 0.0
        if noise_cutoff <= floor:
            raise ValueError(
                f"noise_cutoff_hz={noise_cutoff!r} must be above "
                + ("cutoff_hz" if method == "filter" else "the loading frequency")
                + f" {floor:g} Hz"
            )
        response = lowpass(response, fs, noise_cutoff, plan["order"])
        notes.append(f"noise removed above {noise_cutoff:.3g} Hz before taking the peak")
        if method != "filter":  # smooth the fitted estimate alike, so a kink is clipped alike
            quasi_static = lowpass(quasi_static, fs, noise_cutoff, plan["order"])
    polarity = 1.0 if quasi_static.max() >= -quasi_static.min() else -1.0
    quasi_static_peak = float(np.max(polarity * quasi_static))
    noise = noise_std(x)
    if quasi_static_peak <= 0 or quasi_static_peak < MIN_EVENT_SNR * noise:
        ratio = quasi_static_peak / noise if noise > 0 else 0.0
        raise ValueError(
            f"{name} holds no event that stands out of the noise: its quasi-static peak "
            f"{quasi_static_peak:.3g} is {ratio:.2g} times the noise level {noise:.3g} (at "
            f"least {MIN_EVENT_SNR:g} needed; method {method!r}); is there a vehicle in it?"
        )
    if method == "filter" and loading is not None:
        width = event_width(polarity * quasi_static, fs)
        if width > MAX_EVENT_PASSAGES / loading:
            doubtful = True
            notes.append(
                f"the quasi-static event lasts {width:.3g} s above half its peak, more than "
                f"{MAX_EVENT_PASSAGES:g} passages of span / speed ({1 / loading:.3g} s): drift, "
                "a shift of the gauge's zero or several vehicles, not one passage"
            )
    peak = float(np.max(polarity * response))
    if peak <= 0:
        raise ValueError(
            f"{name} never reaches the direction of its quasi-static response once the "
            "baseline is removed: no event to measure"
        )
    if peak / quasi_static_peak > MAX_PLAUSIBLE_DAF:
        doubtful = True
        notes.append(
            f"DAF {peak / quasi_static_peak:.3g} above {MAX_PLAUSIBLE_DAF:g}: check that the "
            "record holds one vehicle's passage and not vibration alone"
        )
    # white noise left in the response: all of it, or the share below the noise cut-off
    left = noise if noise_cutoff is None else noise * math.sqrt(min(1.0, 2 * noise_cutoff / fs))
    if 3.0 * left > NOISE_PEAK_TOLERANCE * quasi_static_peak:
        doubtful = True
        notes.append(
            f"noise (std {left:.3g}, {left / quasi_static_peak:.1%} of the quasi-static peak"
            f"{'' if noise_cutoff is None else ' below the noise cut-off'}) can raise the peak "
            f"by up to {3 * left / quasi_static_peak:.0%}: pass "
            + ("noise_cutoff_hz" if noise_cutoff is None else "a lower noise_cutoff_hz")
        )
    if doubtful:
        warnings.warn(f"{name}: " + "; ".join(notes), stacklevel=3)
    response.setflags(write=False)
    quasi_static.setflags(write=False)
    return RecordDAF(
        daf=peak / quasi_static_peak,
        peak=polarity * peak,
        quasi_static_peak=polarity * quasi_static_peak,
        method=method,
        how_chosen="; ".join(notes),
        doubtful=bool(doubtful),
        sample_rate_hz=fs,
        response=response,
        quasi_static=quasi_static,
        **extra,
    )


def _per_event(name: str, value: object, n: int) -> list:
    if value is None or np.ndim(value) == 0:
        return [value] * n
    values = list(value)
    if len(values) != n:
        raise ValueError(f"{name} has {len(values)} values for {n} events")
    return values


def _choose_method(
    method: str, response: str | None, span: float | None, has_crawl: bool
) -> tuple[str, str, bool]:
    """The method, a sentence on why, and whether that choice alone makes the DAF doubtful."""
    if method not in ("auto", *METHODS):
        raise ValueError(f"method={method!r} must be 'auto', " + ", ".join(map(repr, METHODS)))
    if response is not None:
        check_response(response)
    kinked = response in KINKED_RESPONSES
    if has_crawl and method not in ("auto", "crawl"):
        raise ValueError(f"crawl is used only by method='crawl' or 'auto', not {method!r}")
    if method == "crawl" and not has_crawl:
        raise ValueError("method='crawl' needs crawl=<a crawl run of the same vehicle>")
    if method == "influence-line" and (span is None or response is None):
        raise ValueError(
            "method='influence-line' needs span and response ('strain', 'stress', 'moment' "
            f"or 'deflection'); got span={span!r}, response={response!r}"
        )
    if method == "auto":
        if has_crawl:
            return "crawl", "crawl run given: it is the static response (auto)", False
        if kinked and span is not None:
            return "influence-line", f"a {response} record has kinks, span known (auto)", False
        method, why = "filter", "auto"
    else:
        why = "asked"
    if method == "filter" and kinked:
        return (
            "filter",
            f"filter ({why}) on a {response} record: it rounds off the kink where an axle "
            "passes the gauge and reads the DAF high by several per cent; give span (and "
            "section, axles) for method 'influence-line'",
            True,
        )
    if method == "filter" and response is None:
        return "filter", f"filter ({why}; response not given: assumed smooth)", False
    if method == "filter":
        return "filter", f"filter ({why}) on a smooth {response} record", False
    return method, f"method {method!r} asked", False


def daf_from_record(
    signal: np.ndarray | Sequence[np.ndarray],
    sample_rate_hz: float,
    cutoff_hz: float | None = None,
    *,
    method: str = "auto",
    response: str | None = None,
    speed: float | Sequence[float] | None = None,
    span: float | None = None,
    n_spans: int = 1,
    section: float | None = None,
    axles: Axles | Sequence[Axles] | None = None,
    crawl: np.ndarray | None = None,
    crawl_speed: float | None = None,
    crawl_sample_rate_hz: float | None = None,
    first_frequency_hz: float | Sequence[float] | None = None,
    order: int = DEFAULT_FILTER_ORDER,
    baseline_fraction: float = 0.05,
    tail_fraction: float = 0.3,
    noise_cutoff_hz: float | None = None,
) -> RecordDAFs:
    """DAF of recorded events: the peak of each record over its quasi-static peak.

    The module docstring describes the three estimates.  ``method="auto"`` uses a crawl run
    if given, else the influence-line fit for a strain, stress or moment record when
    ``span`` is known, else the low-pass filter.  With the filter, a straight baseline
    through the filtered record's first and last ``baseline_fraction`` is taken off (drift,
    offsets) and ``cutoff_hz=None`` puts the cut-off at ``sqrt(f_load f_1)``, between the
    loading frequency ``f_load = speed / span`` and the first natural frequency ``f_1``
    (given, or the Welch peak of the record's free-vibration tail,
    :func:`estimate_first_frequency`).  The fits take off the straight baseline they fit.
    The loading direction is the sign of the quasi-static estimate's larger excursion
    (tension strain up, deflection down: either works).

    Parameters
    ----------
    signal
        One record (1-D array), or several events: a list of 1-D arrays or a 2-D array with
        one event per row.  Each record should start before the vehicle arrives and end
        after it has left (the filter wants ``tail_fraction`` of free vibration at the end).
    sample_rate_hz
        Sampling rate [Hz]; at least ``MIN_SAMPLES_PER_CYCLE`` times the first frequency.
    cutoff_hz
        Cut-off of the low-pass [Hz] (method ``"filter"`` only); ``None`` chooses it.
    method
        ``"auto"``, ``"filter"``, ``"influence-line"`` or ``"crawl"``.
    response
        What the gauge records: ``"strain"``, ``"stress"``, ``"moment"`` (kinked) or
        ``"deflection"`` (smooth); ``None`` if not known (the filter then assumes smooth).
    speed
        Vehicle speed [m/s], one value or one per event; with ``span`` it gives the loading
        frequency.  The fits search it (1 to 60 m/s) when it is not given.
    span
        Length of each span [m].
    n_spans
        1 (simple span) or 2 (two equal continuous spans), for the influence line.
    section
        The gauge's distance from the support where vehicles enter [m]; default midspan of
        the first span.
    axles
        The vehicle's axles (:class:`Axles`), one for all events or one per event; default a
        single axle.
    crawl
        A crawl run of the same vehicle over the same gauge (1-D record, same unit), for
        method ``"crawl"``; its baseline is taken off as for the filter.
    crawl_speed
        Speed of the crawl run [m/s]; without it the stretch from crawl to record is fitted.
    crawl_sample_rate_hz
        Sampling rate of the crawl run [Hz]; default ``sample_rate_hz``.
    first_frequency_hz
        First natural frequency [Hz], one value or one per event; ``None`` estimates it when
        the filter's cut-off is to be chosen.
    order
        Butterworth order of the one-way filters (the zero-phase filter doubles it).
    baseline_fraction
        Fraction of the record (and crawl run) at each end that defines the filter's
        baseline; 0 keeps the record's own zero.
    tail_fraction
        Fraction at the end of the record used to estimate the first frequency.
    noise_cutoff_hz
        If given, the record is low-passed at this frequency (above the filter's cut-off or
        the loading frequency, typically a few times ``f_1``) before its peak is taken, so
        sensor noise does not inflate the peak; a fitted estimate is smoothed alike.

    Returns
    -------
    RecordDAFs
        One entry per event (a single record is one event), whatever was given:
        ``result.item()`` is the :class:`RecordDAF` of a single record, ``result[i]`` that of
        event ``i``, ``result.daf`` the DAFs as an array and ``result.to_dataframe()`` one
        row per event.  Each entry's ``method`` and ``how_chosen`` say how its estimate was
        made; ``doubtful`` marks the ones not to trust as they stand (with a ``UserWarning``).

    Raises
    ------
    ValueError
        NaN or infinite samples, a constant record, no event standing out of the noise, a
        record shorter than the vehicle's passage or the filter, a sample rate too low for
        the first frequency, a cut-off at or above the Nyquist frequency, a section off the
        bridge, an unknown method or response, or a method without what it needs.

    Examples
    --------
    A strain record without any vibration: one axle crossing a 30 m simple span at 25 m/s,
    a 200 Hz gauge at midspan.  The influence-line fit finds DAF 1; the filter rounds off
    the kink and reads 10 % high (and says so):

    >>> import numpy as np
    >>> from vbi_lib.monitoring import influence_line
    >>> fs, v, span = 200.0, 25.0, 30.0
    >>> t = np.arange(0.0, 8.0, 1 / fs)
    >>> strain = 1e-6 * influence_line(v * (t - 1.003), 15.0, span)   # arrives at 1.003 s
    >>> fit = daf_from_record(strain, fs, speed=v, span=span, response="strain").item()
    >>> fit.method, round(fit.daf, 4), round(fit.arrival_s, 4), fit.doubtful
    ('influence-line', 1.0, 1.003, False)
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     low = daf_from_record(strain, fs, speed=v, span=span, response="strain",
    ...                           method="filter", first_frequency_hz=4.0).item()
    >>> round(low.daf, 2), low.doubtful
    (1.1, True)

    A deflection record with a 6 Hz vibration of 0.2 that crests with the 1 s half-sine
    passage: the true DAF is 1.2, and the filter finds it:

    >>> t = np.arange(-2.0, 8.0, 1 / fs)
    >>> pulse = np.where((t > 0) & (t < 1), np.sin(np.pi * t), 0.0)
    >>> ring = 0.2 * np.exp(-0.3 * np.abs(t - 0.5)) * np.cos(2 * np.pi * 6 * (t - 0.5))
    >>> event = daf_from_record(-(pulse + ring), fs, speed=30.0, span=30.0,
    ...                         response="deflection").item()
    >>> round(event.daf, 2), round(event.first_frequency_hz, 1), round(event.cutoff_hz, 2)
    (1.2, 6.0, 2.45)
    """
    fs = check.positive("sample_rate_hz", sample_rate_hz)
    if not (0.0 <= check.number("baseline_fraction", baseline_fraction) < 0.5):
        raise ValueError(f"baseline_fraction={baseline_fraction!r} must be in [0, 0.5)")
    if not (0.0 < check.number("tail_fraction", tail_fraction) <= 1.0):
        raise ValueError(f"tail_fraction={tail_fraction!r} must be in (0, 1]")
    check.integer("order", order, low=1, high=12)
    if span is not None:
        span = check.positive("span", span)
    method, reason, doubtful = _choose_method(method, response, span, crawl is not None)
    if cutoff_hz is not None and method != "filter":
        raise ValueError(
            f"cutoff_hz={cutoff_hz!r} is used only by method 'filter' (this record uses "
            f"{method!r}): drop it or pass method='filter'"
        )
    plan = {
        "method": method,
        "notes": [reason],
        "doubtful": doubtful,
        "span": span,
        "cutoff_hz": cutoff_hz,
        "order": order,
        "baseline_fraction": float(baseline_fraction),
        "tail_fraction": tail_fraction,
        "noise_cutoff_hz": None
        if noise_cutoff_hz is None
        else check.positive("noise_cutoff_hz", noise_cutoff_hz),
        "crawl_speed": None if crawl_speed is None else check.positive("crawl_speed", crawl_speed),
    }
    unused = {"section": section, "axles": axles} if method != "influence-line" else {}
    for name, value in unused.items():
        if value is not None:
            raise ValueError(
                f"{name}={value!r} is used only by method 'influence-line' (this record uses "
                f"{method!r}: give span and response='strain', 'stress' or 'moment', or "
                "method='influence-line')"
            )
    if method == "influence-line":
        n_spans = check.n_spans(n_spans)
        if section is None:
            section = span / 2.0
            plan["notes"].append("gauge at midspan of span 1 (section not given)")
        plan["geometry"] = (check.number("section", section), span, n_spans, response)
    if method == "crawl":
        crawl_fs = fs if crawl_sample_rate_hz is None else crawl_sample_rate_hz
        crawl_fs = check.positive("crawl_sample_rate_hz", crawl_fs)
        plan["shape"] = crawl_shape(
            _checked("crawl", crawl), crawl_fs, plan["crawl_speed"], float(baseline_fraction)
        )
    # a list of records of different lengths is several events (np.ndim of the whole list
    # would try to make it one array and fail)
    if isinstance(signal, list | tuple):
        several = len(signal) > 0 and all(np.ndim(event) >= 1 for event in signal)
    else:
        several = np.ndim(signal) == 2
    events = list(signal) if several else [signal]
    n = len(events)
    if n == 0:
        raise ValueError("signal is an empty list: give at least one record")
    per_event = {
        "speed": _per_event("speed", speed, n),
        "first_frequency_hz": _per_event("first_frequency_hz", first_frequency_hz, n),
        "axles": _per_event("axles", axles, n),
    }
    results = []
    for i, record in enumerate(events):
        event = {key: values[i] for key, values in per_event.items()}
        if event["speed"] is not None:
            event["speed"] = check.positive("speed", event["speed"])
        name = f"signal[{i}]" if several else "signal"
        results.append(_one_record(record, fs, name, plan, event))
    return RecordDAFs(tuple(results))


__all__ = [
    "MAX_CRAWL_RESIDUAL",
    "MAX_EVENT_PASSAGES",
    "MAX_FIT_RESIDUAL",
    "MAX_FIT_RESIDUAL_SPEED_SEARCHED",
    "MAX_PLAUSIBLE_DAF",
    "MIN_EVENT_SNR",
    "MIN_FREQUENCY_RATIO",
    "MIN_SAMPLES_PER_CYCLE",
    "NOISE_PEAK_TOLERANCE",
    "daf_from_record",
]
