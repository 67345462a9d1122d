"""One crossing, live: the bridge's midspan response and the tyre's contact force.

Every control of a :class:`~vbi_lib.widgets.Scenario` (bridge, truck and its type, speed,
road, model) is offered; a change runs one :func:`vbi_lib.simulate` (a few milliseconds) and
updates the two curves' data in a figure built once, so an update costs one Agg draw, not a
new figure.
"""

from __future__ import annotations

import warnings

import numpy as np
from matplotlib.patches import Rectangle

from .. import display
from ..models import Crossing, simulate
from ..validity import ContactLossWarning
from .base import Explorer
from .readouts import crossing_html
from .scenario import Scenario

__all__ = ["CrossingExplorer"]


class CrossingExplorer(Explorer):
    """One crossing: midspan response and contact force as the controls move.

    Parameters
    ----------
    **values
        Start values of controls by parameter (fields of :class:`Scenario`), e.g.
        ``CrossingExplorer(speed_mph=55, road="flat")``.

    Attributes
    ----------
    controls
        Every field of :class:`Scenario`, by name.
    widget
        The box to display.
    result
        The last :class:`~vbi_lib.Crossing`, or ``None`` when the controls describe no valid
        crossing (then ``error`` says why).

    Raises
    ------
    ValueError
        A start value that no control accepts.

    Examples
    --------
    >>> explorer = CrossingExplorer(road="flat", speed_mph=30)
    >>> explorer.result.lost_contact, explorer.result.daf.shape
    (False, (1,))
    """

    parameters = tuple(Scenario.__dataclass_fields__)
    kind = "crossing"

    def _setup_figure(self) -> None:
        self.axes = self.view.figure.subplots(2, 1, sharex=True)
        self.view.figure.subplots_adjust(left=0.11, right=0.98, top=0.97, bottom=0.1, hspace=0.08)
        self._layout: tuple | None = None
        self._empty = self.view.figure.text(0.5, 0.5, "", ha="center", va="center", fontsize=12)

    def _compute(self) -> Crossing:
        scenario = self.scenario()
        profile = scenario.profile()
        with warnings.catch_warnings():
            # the readout says so in words next to the DAF
            warnings.simplefilter("ignore", ContactLossWarning)
            return simulate(
                scenario.bridge(),
                scenario.vehicle(),
                profile,
                scenario.speed,
                scenario.bridge_start(profile),
                **scenario.simulate_options(),
            )

    def _show(self, crossing: Crossing) -> None:
        top, bottom = self.axes
        n = crossing.bridge.n_spans
        layout = (n, display.current().name)
        x = display.value(crossing.position - crossing.bridge_start, "length")
        y = crossing.midspan_displacement / crossing.static_deflection
        if layout != self._layout:
            # first result, or another number of spans or display units: plot afresh
            for ax in self.axes:
                ax.clear()
            crossing.plot(ax=top, kind="displacement")
            crossing.plot(ax=bottom, kind="contact")
            top.set_xlabel("")
            top.set_ylabel("midspan displacement\n/ static deflection [-]")
            self.view.set_dynamic([*top.lines[:n], bottom.lines[0]])
            self._layout = layout
        for j in range(n):
            top.lines[j].set_data(x, y[:, j])
        bottom.lines[0].set_data(x, crossing.contact_force_ratio)
        length = display.value(crossing.bridge.length, "length")
        for ax in self.axes:
            band = _bridge_band(ax)
            if band.get_width() != length:
                band.set_width(length)
                self.view.invalidate()
        # limits from the data (relim() would walk the band's path each time); the y limits
        # stay while the curves fit them well, so that most updates redraw only the curves
        top.set_xlim(*_padded(x[0], x[-1], 0.02))
        top.set_ylim(*_kept(top.get_ylim(), np.min(y), np.max(y)))
        ratio = crossing.contact_force_ratio
        bottom.set_ylim(*_kept(bottom.get_ylim(), min(ratio.min(), 0.0), ratio.max()))
        if self._empty.get_text():
            self._empty.set_text("")
            self.view.invalidate()
        self.view.render()
        # the readout last: when it changes on the page, the new figure is already there
        scenario = self.scenario()
        self.readout.value = crossing_html(
            crossing,
            scenario.road_text(),
            scenario.model_text(),
            scenario.vehicle_text(crossing.vehicle),
            outside=bool(self.outside_inputs),
        )

    def _blank(self) -> None:
        for ax in self.axes:
            for line in ax.lines:
                line.set_data([], [])
        self._empty.set_text("no result for these settings")
        self.view.invalidate()


def _bridge_band(ax) -> Rectangle:  # noqa: ANN001
    """The shaded band :meth:`Crossing.plot` draws over the bridge."""
    return next(p for p in ax.patches if isinstance(p, Rectangle))


def _padded(low: float, high: float, margin: float = 0.05) -> tuple[float, float]:
    """Axis limits with a margin on each side (a fraction of the range)."""
    pad = margin * (high - low) if high > low else 0.5 * max(abs(high), 1.0)
    return float(low - pad), float(high + pad)


def _kept(limits: tuple[float, float], low: float, high: float) -> tuple[float, float]:
    """The current limits if the data fit inside and fill at least half; else new ones."""
    fits = limits[0] <= low and high <= limits[1]
    if fits and high - low >= 0.5 * (limits[1] - limits[0]):
        return limits
    return _padded(low, high, 0.15)
