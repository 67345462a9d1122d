r"""DAF of recorded events in service, estimated by low-pass filtering.

A gauge on a bridge in service records every truck that crosses; no crawl run gives the
static response.  :func:`daf_from_record` estimates the quasi-static part of each recorded
event with a zero-phase Butterworth low-pass (:func:`vbi_lib.monitoring.lowpass`) and
returns ``DAF = peak / quasi-static peak``, the study's definition (17) with the filtered
record standing for :math:`R_{sta}`.  The cut-off must lie between the loading frequency
``f_load = speed / span`` and the first natural frequency ``f_1``; by default it is
:math:`\sqrt{f_{load} f_1}`, midway on a log scale.  When the loading is faster than the first
frequency no cut-off separates them and the estimate is biased high: the result says so
(``doubtful``, and a ``UserWarning``).

Limits: each record must start before the vehicle arrives and end with the bridge vibrating
freely after it has left; one vehicle per event.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from .. import _validation as check
from .filtering import DEFAULT_FILTER_ORDER, _record, estimate_first_frequency, lowpass

#: Fewest samples per period of the first natural frequency :func:`daf_from_record` accepts.
#: Ten samples a cycle catch a sinusoid's crest to within ``1 - cos(18 deg)`` = 4.9 %.
MIN_SAMPLES_PER_CYCLE = 10


@dataclass(frozen=True, eq=False)
class RecordDAF:
    """One recorded event's DAF, estimated by low-pass filtering (an entry of RecordDAFs).

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
    doubtful
        ``True`` when the cut-off does not separate the loading frequency from the first
        frequency well (the estimate is biased; ``how_chosen`` says why).
    sample_rate_hz
        Sampling rate of the record [Hz].
    response, quasi_static
        The baseline-corrected record whose peak was taken (noise-filtered if asked) and its
        low-passed copy, one value per sample (the record's unit); kept for :meth:`plot`.
    """

    daf: float
    peak: float
    quasi_static_peak: float
    cutoff_hz: float
    first_frequency_hz: float | None
    loading_frequency_hz: float | None
    how_chosen: str
    doubtful: bool
    sample_rate_hz: float
    response: np.ndarray = field(repr=False)
    quasi_static: np.ndarray = field(repr=False)

    def summary(self) -> dict[str, object]:
        """The scalar fields (everything but the two signals) as a dict, for a table row."""
        return {name: getattr(self, name) for name in _SUMMARY_FIELDS}

    def plot(self, ax=None, scale: float = 1.0, unit: str = ""):  # noqa: ANN001, ANN201
        """The record, its quasi-static (low-passed) part and the two peaks against time.

        ``scale`` multiplies the values and ``unit`` labels them (for example ``1e3`` and
        ``"mm"`` for a displacement record in metres).
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        time = np.arange(self.response.size) / self.sample_rate_hz
        ax.plot(time, self.response * scale, color="0.55", lw=0.7, label="record")
        ax.plot(
            time,
            self.quasi_static * scale,
            "C3",
            lw=1.6,
            label=f"low-passed at {self.cutoff_hz:.3g} Hz",
        )
        ax.axhline(self.peak * scale, color="0.3", ls=":", lw=0.8, label="peak")
        ax.axhline(self.quasi_static_peak * scale, color="C3", ls="--", lw=0.8)
        flag = " (doubtful)" if self.doubtful else ""
        ax.set_title(f"DAF {self.daf:.3f}{flag}", fontsize="medium")
        ax.set_xlabel("time from the start of the record [s]")
        ax.set_ylabel(f"record [{unit}]" if unit else "record")
        ax.legend(fontsize="small", loc="best")
        return ax

    def __repr__(self) -> str:
        f1 = "?" if self.first_frequency_hz is None else f"{self.first_frequency_hz:.3g} Hz"
        fl = "?" if self.loading_frequency_hz is None else f"{self.loading_frequency_hz:.3g} Hz"
        flag = ", doubtful" if self.doubtful else ""
        return (
            f"RecordDAF(DAF {self.daf:.3f}{flag}: peak {self.peak:.4g} / quasi-static "
            f"{self.quasi_static_peak:.4g}; cut-off {self.cutoff_hz:.3g} Hz, f1 {f1}, "
            f"loading {fl})"
        )


_SUMMARY_FIELDS = (
    "daf",
    "peak",
    "quasi_static_peak",
    "cutoff_hz",
    "first_frequency_hz",
    "loading_frequency_hz",
    "doubtful",
    "how_chosen",
)


@dataclass(frozen=True, eq=False)
class RecordDAFs:
    """What :func:`daf_from_record` returns for one record or many: one entry per event.

    ``result[i]`` (or iterating) gives event ``i``'s :class:`RecordDAF`; ``result.item()``
    gives the only event of a single record (and refuses a result holding several, so a
    forgotten event is never read silently).  The per-event numbers are also arrays over the
    events: ``result.daf``, ``result.doubtful``; :meth:`to_dataframe` puts every scalar field
    in a table with one row per event.

    Attributes
    ----------
    events
        One :class:`RecordDAF` per event, in the order given.

    Examples
    --------
    Two events: a 1 s half-sine pulse alone (true DAF 1.0), and with a 6 Hz ring of amplitude
    0.3 cresting with it (true DAF 1.3):

    >>> import numpy as np
    >>> t = np.arange(-2.0, 8.0, 1 / 200.0)
    >>> pulse = np.where((t > 0) & (t < 1), np.sin(np.pi * t), 0.0)
    >>> ring = 0.3 * np.exp(-0.3 * np.abs(t - 0.5)) * np.cos(2 * np.pi * 6 * (t - 0.5))
    >>> result = daf_from_record([pulse, pulse + ring], 200.0, speed=30.0, span=30.0,
    ...                          first_frequency_hz=6.0)
    >>> result
    RecordDAFs(2 events: DAF 1.002, 1.302)
    >>> len(result), result.daf.round(2).tolist()
    (2, [1.0, 1.3])
    >>> table = result.to_dataframe()
    >>> table[["daf", "cutoff_hz", "doubtful"]].round(2)  # doctest: +NORMALIZE_WHITESPACE
            daf  cutoff_hz  doubtful
    event
    0       1.0       2.45     False
    1       1.3       2.45     False
    """

    events: tuple[RecordDAF, ...]

    def __len__(self) -> int:
        return len(self.events)

    def __getitem__(self, index: int) -> RecordDAF:
        return self.events[index]

    def __iter__(self) -> Iterator[RecordDAF]:
        return iter(self.events)

    def item(self) -> RecordDAF:
        """The estimate of the only event; ``ValueError`` if the result holds several."""
        if len(self.events) != 1:
            raise ValueError(
                f"the result holds {len(self.events)} events; item() is for one record: "
                "index it (result[i]) or use result.to_dataframe()"
            )
        return self.events[0]

    @property
    def daf(self) -> np.ndarray:
        """DAF of each event [-], shape ``(n_events,)``."""
        return np.array([event.daf for event in self.events])

    @property
    def doubtful(self) -> np.ndarray:
        """``True`` for each event whose cut-off was a doubtful choice, shape ``(n_events,)``."""
        return np.array([event.doubtful for event in self.events], dtype=bool)

    def to_dataframe(self) -> pd.DataFrame:
        """The scalar fields of every event as a table, one row per event (index ``event``).

        Columns ``daf``, ``peak``, ``quasi_static_peak``, ``cutoff_hz``,
        ``first_frequency_hz``, ``loading_frequency_hz`` (NaN when not known), ``doubtful``
        and ``how_chosen``.
        """
        rows = [event.summary() for event in self.events]
        return pd.DataFrame(rows, columns=list(_SUMMARY_FIELDS)).rename_axis("event")

    def plot(self, ax=None, event: int | None = None, **kwargs):  # noqa: ANN001, ANN003, ANN201
        """Plot one event's record and quasi-static part, or the DAF of every event.

        With ``event=i`` (or a single event) :meth:`RecordDAF.plot` of that event (keywords
        passed on); with several events and ``event=None`` the DAF of each event against its
        number, doubtful ones hollow.
        """
        import matplotlib.pyplot as plt

        if event is not None or len(self.events) == 1:
            return self.events[0 if event is None else event].plot(ax=ax, **kwargs)
        if ax is None:
            _, ax = plt.subplots(figsize=(6, 3))
        index = np.arange(len(self.events))
        sure = ~self.doubtful
        ax.plot(index[sure], self.daf[sure], "o", ms=4, color="C0", label="DAF")
        if (~sure).any():
            hollow = {"mfc": "none", "color": "C0", "label": "doubtful cut-off"}
            ax.plot(index[~sure], self.daf[~sure], "o", ms=4, **hollow)
        ax.set_xlabel("event")
        ax.set_ylabel("DAF [-]")
        ax.legend(fontsize="small", loc="best")
        return ax

    def __repr__(self) -> str:
        n = len(self.events)
        if n == 1:
            return f"RecordDAFs(1 event: {self.events[0]!r})"
        shown = ", ".join(f"{d:.3f}" for d in self.daf[:6])
        more = ", ..." if n > 6 else ""
        count = int(self.doubtful.sum())
        flag = f"; {count} doubtful" if count else ""
        return f"RecordDAFs({n} events: DAF {shown}{more}{flag})"


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
    if response is x:
        response = x.copy()  # never keep a view of the caller's array
    response.setflags(write=False)
    filtered.setflags(write=False)
    return RecordDAF(
        daf=peak / quasi_static,
        peak=polarity * peak,
        quasi_static_peak=polarity * quasi_static,
        cutoff_hz=float(cutoff),
        first_frequency_hz=None if first is None else float(first),
        loading_frequency_hz=loading,
        how_chosen="; ".join(notes),
        doubtful=bool(doubtful),
        sample_rate_hz=fs,
        response=response,
        quasi_static=filtered,
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
) -> RecordDAFs:
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
    RecordDAFs
        One entry per event (a single record is one event), whatever was given:
        ``result.item()`` is the :class:`RecordDAF` of a single record, ``result[i]`` that of
        event ``i``, ``result.daf`` the DAFs as an array and ``result.to_dataframe()`` one
        row per event.  ``doubtful`` marks events whose cut-off could not separate the
        loading from the first frequency (a ``UserWarning`` is issued too).

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
    >>> event = daf_from_record(-(pulse + ring), fs, speed=30.0, span=30.0).item()
    >>> round(event.daf, 2), round(event.first_frequency_hz, 1), round(event.cutoff_hz, 2)
    (1.2, 6.0, 2.45)
    >>> event.doubtful
    False
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
    return RecordDAFs(tuple(results))


__all__ = ["MIN_SAMPLES_PER_CYCLE", "RecordDAF", "RecordDAFs", "daf_from_record"]
