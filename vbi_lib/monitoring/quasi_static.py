r"""The two quasi-static estimates of :func:`vbi_lib.monitoring.daf_from_record`.

:func:`filter_estimate` low-passes the record (:func:`vbi_lib.monitoring.lowpass`) with a
cut-off between the loading frequency ``f_load = speed / span`` and the first natural
frequency ``f_1``, the method of the study's section on operational monitoring.
:func:`fit_estimate` fits a shape to the record (the beam's influence line of the axles, or a
crawl run; :func:`vbi_lib.monitoring.influence.fit_shape`).  Each returns the quasi-static
estimate and the straight baseline it took off, whether the estimate is in doubt, and the
numbers the result reports, and adds its sentences to the notes it is given.
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validation as check
from .filtering import estimate_first_frequency, lowpass, without_straight_baseline
from .influence import SPEED_BOUNDS, Shape, fit_shape

#: Fewest samples per period of the first natural frequency :func:`daf_from_record` accepts.
#: Ten samples a cycle catch a sinusoid's crest to within ``1 - cos(18 deg)`` = 4.9 %.
MIN_SAMPLES_PER_CYCLE = 10
#: Largest slow residual of a fit (RMS while the vehicle is on the bridge, over the peak).
MAX_FIT_RESIDUAL = 0.03
#: The same when the speed was searched: a stretched shape absorbs part of a mismatch (a truck
#: bouncing through a short span), so its residual understates it.  Both limits were set on
#: simulated crossings of three spans (12, 30 and 43 m) by three trucks at 10-30 m/s.
MAX_FIT_RESIDUAL_SPEED_SEARCHED = 0.02
#: The same for a crawl run, used at scale 1: the slow part of a short span's vibration stays
#: in its residual, so only a clear mismatch (another vehicle or path) is flagged.
MAX_CRAWL_RESIDUAL = 0.15
#: Smallest ratio of the first frequency to the loading frequency taken without doubt.  Below
#: it the filter's cut-off has little room, and for the fit the speed parameter
#: ``alpha = f_load / (2 f1)`` exceeds 0.125: the forced, slow part of the response is then
#: itself amplified by about ``1 / (1 - alpha^2)`` (Fryba) and counted as static.
MIN_FREQUENCY_RATIO = 4.0


def choose_cutoff(loading: float | None, first: float) -> tuple[float, str, bool]:
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
    doubtful = first / loading < MIN_FREQUENCY_RATIO
    if doubtful:
        note += (
            f"; f1 / loading = {first / loading:.2g} < {MIN_FREQUENCY_RATIO:g} leaves little "
            "room, expect the filter to bias the DAF"
        )
    return cutoff, note, doubtful


def filter_estimate(
    x: np.ndarray,
    fs: float,
    cutoff_hz: float | None,
    first: float | None,
    loading: float | None,
    order: int,
    baseline_fraction: float,
    tail_fraction: float,
    notes: list[str],
) -> tuple[np.ndarray, np.ndarray, bool, dict]:
    """Low-passed record and the baseline; the doubt flag; cut-off and f1 for the result."""
    if first is None and cutoff_hz is None:
        first = estimate_first_frequency(x, fs, tail_fraction)
        check_sampling(fs, first)
        notes.append(f"f1 from the Welch peak of the last {tail_fraction:.0%} of the record")
    doubtful = False
    if cutoff_hz is None:
        cutoff, note, doubtful = choose_cutoff(loading, first)
        notes.append(note)
    else:
        cutoff = check.positive("cutoff_hz", cutoff_hz)
        notes.append("cut-off given")
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
    line = np.zeros_like(x)
    if baseline_fraction > 0:
        line = filtered - without_straight_baseline(filtered, baseline_fraction)
    extra = {"cutoff_hz": float(cutoff), "first_frequency_hz": maybe(first)}
    return filtered - line, line, doubtful, extra


def fit_estimate(
    x: np.ndarray,
    fs: float,
    shape: Shape,
    speed: float | None,
    span: float | None,
    crawl_speed: float | None,
    crawl: bool,
    first: float | None,
    tail_fraction: float,
    notes: list[str],
) -> tuple[np.ndarray, np.ndarray, bool, dict]:
    """Fitted quasi-static shape and baseline; the doubt flag; speed, arrival, residual, f1."""
    metres = not crawl or crawl_speed is not None  # the shape's axis is a position in metres
    rate = speed if (metres and speed is not None) else None
    bounds = SPEED_BOUNDS if metres else (shape.extent * fs / x.size, shape.extent * fs / 20.0)
    loading = None if (speed is None or span is None) else speed / span
    if first is None:
        try:
            first = estimate_first_frequency(x, fs, tail_fraction)
        except ValueError:  # no free vibration to speak of: nothing to keep out of the fit
            notes.append("no clear free vibration in the tail: the raw record fitted")
        else:
            check_sampling(fs, first)
            notes.append(f"f1 {first:.3g} Hz from the Welch peak of the record's tail")
    smoothing = None if first is None else first / 2.0
    if smoothing is not None:
        notes.append(f"record and shape compared below f1 / 2 = {smoothing:.3g} Hz")
    fit = fit_shape(
        x,
        fs,
        shape,
        rate,
        bounds,
        scale=1.0 if crawl else None,
        loading_frequency_hz=loading,
        smoothing_hz=smoothing,
    )
    if metres and speed is None:
        speed = fit.rate
    loading = None if (speed is None or span is None) else speed / span
    notes.append(f"{shape.label} fitted by least squares" + (", scale 1" if crawl else ""))
    if not metres:
        notes.append(f"crawl stretched {fit.rate:.4g} times (crawl speed not given)")
    elif rate is None:
        notes.append(f"speed fitted: {speed:.3g} m/s")
    doubtful = False
    if fit.rate_at_bound:
        doubtful = True
        notes.append("the fitted speed lies on the edge of the range searched; give speed")
    duration = shape.extent / fit.rate
    on = (np.arange(x.size) / fs >= fit.arrival_s) & (
        np.arange(x.size) / fs <= fit.arrival_s + duration
    )
    peak = float(np.max(np.abs(fit.model)))
    residual = float(np.sqrt(np.mean(fit.slow_residual[on] ** 2))) / peak if peak > 0 else math.inf
    notes.append(f"slow residual {residual:.1%} of the peak")
    if first is not None and loading is not None and not crawl:
        alpha = loading / (2.0 * first)  # the speed parameter of a moving force (Fryba)
        if alpha**2 > 0.005:
            gain = 1.0 / (1.0 - min(alpha, 0.9) ** 2)
            notes.append(
                f"speed parameter v / (2 f1 L) = {alpha:.2g}: a beam's slow forced response "
                f"is itself amplified by about 1 / (1 - alpha^2) = {gain:.3g}, which the fit "
                "counts as static: the DAF may read low by about as much"
            )
        if first / loading < MIN_FREQUENCY_RATIO:
            doubtful = True
            notes.append(
                f"f1 / loading = {first / loading:.2g} < {MIN_FREQUENCY_RATIO:g}: the "
                "quasi-static and the dynamic response overlap"
            )
    if crawl:
        limit, why = MAX_CRAWL_RESIDUAL, "the record is not this crawl run's vehicle or path"
    else:
        limit = MAX_FIT_RESIDUAL if rate is not None else MAX_FIT_RESIDUAL_SPEED_SEARCHED
        why = (
            "the shape does not match the record (check span, n_spans, section and axles; "
            "one vehicle at a time; a vehicle bouncing through a short span does not keep "
            "one load)"
        )
    if residual > limit:
        doubtful = True
        notes.append(f"above {limit:.0%}: {why}")
    extra = {
        "speed": maybe(speed),
        "loading_frequency_hz": maybe(loading),
        "arrival_s": float(fit.arrival_s),
        "fit_residual": residual,
        "first_frequency_hz": maybe(first),
    }
    return fit.model, fit.baseline, doubtful, extra


def event_width(values: np.ndarray, fs: float) -> float:
    """Time [s] around the largest value during which ``values`` stays above half of it."""
    top = int(np.argmax(values))
    above = values >= 0.5 * values[top]
    below = np.flatnonzero(~above)
    start = below[below < top].max() + 1 if (below < top).any() else 0
    end = below[below > top].min() if (below > top).any() else values.size
    return (end - start) / fs


def maybe(value: float | None) -> float | None:
    """``value`` as a float, or ``None``."""
    return None if value is None else float(value)


def check_sampling(fs: float, first: float) -> None:
    """``ValueError`` unless ``fs`` gives ``MIN_SAMPLES_PER_CYCLE`` samples per cycle of f1."""
    if fs < MIN_SAMPLES_PER_CYCLE * first:
        raise ValueError(
            f"sample_rate_hz={fs!r} is too low for a first frequency of {first:.3g} Hz: "
            f"record at least {MIN_SAMPLES_PER_CYCLE} samples per cycle "
            f"({MIN_SAMPLES_PER_CYCLE * first:.3g} Hz)"
        )


__all__ = [
    "MAX_CRAWL_RESIDUAL",
    "MAX_FIT_RESIDUAL",
    "MAX_FIT_RESIDUAL_SPEED_SEARCHED",
    "MIN_FREQUENCY_RATIO",
    "MIN_SAMPLES_PER_CYCLE",
    "check_sampling",
    "choose_cutoff",
    "event_width",
    "filter_estimate",
    "fit_estimate",
    "maybe",
]
