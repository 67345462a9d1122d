"""What :func:`vbi_lib.monitoring.daf_from_record` returns: one result per recorded event.

:class:`RecordDAF` holds one event's DAF, the quasi-static estimate it was divided by, the
method that made that estimate (low-pass filter, influence-line fit or crawl run) and a
sentence on why that method was used and whether the number is doubtful.  :class:`RecordDAFs`
gathers the events of one call (one record or many) and exports them as a table.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .. import display

if TYPE_CHECKING:
    from matplotlib.axes import Axes

#: The three ways :func:`daf_from_record` estimates the quasi-static response.
METHODS = ("filter", "influence-line", "crawl")

_QUASI_STATIC_LABEL = {
    "filter": "low-passed record",
    "influence-line": "influence-line fit",
    "crawl": "crawl run",
}


@dataclass(frozen=True, eq=False)
class RecordDAF:
    """One recorded event's DAF and how its quasi-static response was estimated.

    Attributes
    ----------
    daf
        ``peak / quasi_static_peak`` [-].
    peak
        Extreme of the (baseline-corrected) record in its loading direction, with its sign.
    quasi_static_peak
        Extreme of the quasi-static estimate, same direction and sign.
    method
        ``"filter"`` (zero-phase low-pass), ``"influence-line"`` (the beam's influence line
        of the axles fitted to the record) or ``"crawl"`` (a crawl run of the vehicle).
    how_chosen
        Sentences on why this method, where its inputs came from, and any doubt.
    doubtful
        ``True`` when the estimate should not be trusted as it stands (``how_chosen`` says
        why); a ``UserWarning`` was issued too.
    sample_rate_hz
        Sampling rate of the record [Hz].
    speed
        Vehicle speed [m/s], given or fitted; ``None`` if unknown.
    loading_frequency_hz
        ``speed / span`` [Hz], or ``None`` if either is unknown.
    cutoff_hz
        Cut-off of the low-pass [Hz] (method ``"filter"``), else ``None``.
    first_frequency_hz
        First natural frequency [Hz] (given or estimated), or ``None`` if not used.
    arrival_s
        Fitted time [s] from the start of the record at which the vehicle's first axle
        reaches the bridge (``"influence-line"``); for ``"crawl"`` the time at which the
        start of the crawl record lines up; ``None`` for ``"filter"``.
    fit_residual
        RMS of the fit's slow residual while the vehicle is on the bridge, over the
        quasi-static peak [-] (fitted methods only): large when the shape does not match
        the record (wrong geometry or axles, several vehicles).
    response, quasi_static
        The baseline-corrected record whose peak was taken (noise-filtered if asked) and the
        quasi-static estimate, one value per sample (the record's unit); kept for
        :meth:`plot`.
    """

    daf: float
    peak: float
    quasi_static_peak: float
    method: str
    how_chosen: str
    doubtful: bool
    sample_rate_hz: float
    speed: float | None = None
    loading_frequency_hz: float | None = None
    cutoff_hz: float | None = None
    first_frequency_hz: float | None = None
    arrival_s: float | None = None
    fit_residual: float | None = None
    response: np.ndarray = field(default=None, repr=False)
    quasi_static: np.ndarray = field(default=None, repr=False)

    def summary(self) -> dict[str, object]:
        """The scalar fields (everything but the two signals) as a dict, for a table row."""
        return {name: getattr(self, name) for name in SUMMARY_FIELDS}

    def plot(self, ax: Axes | None = None, scale: float = 1.0, unit: str = "") -> Axes:
        """The record, its quasi-static estimate and the two peaks against time.

        ``scale`` multiplies the values and ``unit`` labels them (for example ``1e3`` and
        ``"mm"`` for a displacement record in metres).
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        time = np.arange(self.response.size) / self.sample_rate_hz
        label = _QUASI_STATIC_LABEL[self.method]
        if self.cutoff_hz is not None:
            label = f"low-passed at {self.cutoff_hz:.3g} Hz"
        ax.plot(time, self.response * scale, color="0.55", lw=0.7, label="record")
        ax.plot(time, self.quasi_static * scale, "C3", lw=1.6, label=label)
        ax.axhline(self.peak * scale, color="0.3", ls=":", lw=0.8, label="peak")
        ax.axhline(self.quasi_static_peak * scale, color="C3", ls="--", lw=0.8)
        flag = " (doubtful)" if self.doubtful else ""
        ax.set_title(f"DAF {self.daf:.3f} by {self.method}{flag}", fontsize="medium")
        ax.set_xlabel("time from the start of the record [s]")
        ax.set_ylabel(f"record [{unit}]" if unit else "record")
        ax.legend(fontsize="small", loc="best")
        return ax

    def __repr__(self) -> str:
        flag = ", doubtful" if self.doubtful else ""
        parts = []
        if self.method == "filter":
            f1 = "?" if self.first_frequency_hz is None else f"{self.first_frequency_hz:.3g} Hz"
            fl = "?" if self.loading_frequency_hz is None else f"{self.loading_frequency_hz:.3g} Hz"
            parts.append(f"cut-off {self.cutoff_hz:.3g} Hz, f1 {f1}, loading {fl}")
        else:
            if self.speed is not None:
                parts.append(f"speed {display.short(self.speed, 'speed', 3)}")
            parts.append(f"fit residual {self.fit_residual:.1%}")
        return (
            f"RecordDAF(DAF {self.daf:.3f} by {self.method}{flag}: peak {self.peak:.4g} / "
            f"quasi-static {self.quasi_static_peak:.4g}; {', '.join(parts)})"
        )


SUMMARY_FIELDS = (
    "daf",
    "method",
    "doubtful",
    "peak",
    "quasi_static_peak",
    "speed",
    "loading_frequency_hz",
    "cutoff_hz",
    "first_frequency_hz",
    "arrival_s",
    "fit_residual",
    "how_chosen",
)


@dataclass(frozen=True, eq=False)
class RecordDAFs:
    """What :func:`daf_from_record` returns for one record or many: one entry per event.

    ``result[i]`` (or iterating) gives event ``i``'s :class:`RecordDAF`; ``result.item()``
    gives the only event of a single record (and refuses a result holding several, so a
    forgotten event is never read silently).  The per-event numbers are also arrays over the
    events: ``result.daf``, ``result.doubtful``, ``result.method``; :meth:`to_dataframe` puts
    every scalar field in a table with one row per event.

    Attributes
    ----------
    events
        One :class:`RecordDAF` per event, in the order given.

    Examples
    --------
    Two events: a 1 s half-sine pulse alone (true DAF 1.0), and with a 6 Hz ring of amplitude
    0.3 cresting with it (true DAF 1.3); a smooth record, so the low-pass filter is used:

    >>> import numpy as np
    >>> from vbi_lib.monitoring import daf_from_record
    >>> t = np.arange(-2.0, 8.0, 1 / 200.0)
    >>> pulse = np.where((t > 0) & (t < 1), np.sin(np.pi * t), 0.0)
    >>> ring = 0.3 * np.exp(-0.3 * np.abs(t - 0.5)) * np.cos(2 * np.pi * 6 * (t - 0.5))
    >>> result = daf_from_record([pulse, pulse + ring], 200.0, speed=30.0, span=30.0,
    ...                          first_frequency_hz=6.0, response="deflection")
    >>> result
    RecordDAFs(2 events: DAF 1.002, 1.302)
    >>> len(result), result.daf.round(2).tolist()
    (2, [1.0, 1.3])
    >>> table = result.to_dataframe()
    >>> table[["daf", "method", "cutoff_hz", "doubtful"]].round(2)  # doctest: +NORMALIZE_WHITESPACE
            daf  method  cutoff_hz  doubtful
    event
    0       1.0  filter       2.45     False
    1       1.3  filter       2.45     False
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
        """``True`` for each event whose estimate is doubtful, shape ``(n_events,)``."""
        return np.array([event.doubtful for event in self.events], dtype=bool)

    @property
    def method(self) -> np.ndarray:
        """The method used for each event (``"filter"``, ...), shape ``(n_events,)``."""
        return np.array([event.method for event in self.events], dtype=object)

    def to_dataframe(self) -> pd.DataFrame:
        """The scalar fields of every event as a table, one row per event (index ``event``).

        Columns ``daf``, ``method``, ``doubtful``, ``peak``, ``quasi_static_peak``, ``speed``,
        ``loading_frequency_hz``, ``cutoff_hz``, ``first_frequency_hz``, ``arrival_s``,
        ``fit_residual`` (NaN where a method does not use them) and ``how_chosen``.
        """
        rows = [event.summary() for event in self.events]
        return pd.DataFrame(rows, columns=list(SUMMARY_FIELDS)).rename_axis("event")

    def plot(self, ax: Axes | None = None, event: int | None = None, **kwargs) -> Axes:  # noqa: ANN003
        """Plot one event's record and quasi-static estimate, or the DAF of every event.

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
            hollow = {"mfc": "none", "color": "C0", "label": "doubtful estimate"}
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


__all__ = ["METHODS", "SUMMARY_FIELDS", "RecordDAF", "RecordDAFs"]
