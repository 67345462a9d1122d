r"""Frequency matching: the DAF over the truck-to-bridge frequency ratio and the speed.

The study's parametric study (Figure 2.15.8) drove trucks of 2 to 5 Hz over bridges of 2 to
5 Hz on a harmonic road and found the bridge most excited when the road's forcing frequency
``v / lambda`` matches the bridge's frequency and the truck's frequency is slightly higher.
:class:`FrequencyExplorer` maps that plane for any bridge and road: one crossing per cell,
truck frequency ``ratio * f1``, every other input from the controls.  The map is computed on
a button (it is hundreds of crossings) and fills in progressively.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import ipywidgets as w
import numpy as np
import pandas as pd

from .. import display
from .. import units as u
from ..models import BatchResult
from ..validity import ContactFlags
from .base import Explorer
from .readouts import largest_daf, sweep_html
from .scenario import Scenario
from .sweeps import run_in_chunks

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["FrequencyExplorer", "FrequencyMap"]


@dataclass(frozen=True, eq=False, kw_only=True)
class FrequencyMap(ContactFlags):
    """DAF of one crossing per (speed, frequency ratio) cell.

    Attributes
    ----------
    model
        The crossing model's name.
    bridge_frequency_hz
        The bridge's first frequency ``f1`` [Hz].
    ratio
        Truck bounce frequency over ``f1``, shape ``(n_ratios,)``.
    speed
        Speeds [m/s], shape ``(n_speeds,)``.
    daf
        ``(n_speeds, n_ratios, 2)`` DAF of each span (NaN for a missing second span, or a
        cell not computed yet).
    contact_force_amplification, min_contact_force_ratio, tension_fraction, flight_fraction
        The contact checks of each cell, ``(n_speeds, n_ratios)`` (``flight_fraction``: the
        time on the bridge a quarter car's tyre was off the road; zeros for the sprung mass).
    """

    model: str
    bridge_frequency_hz: float
    ratio: np.ndarray
    speed: np.ndarray
    daf: np.ndarray
    contact_force_amplification: np.ndarray
    min_contact_force_ratio: np.ndarray
    tension_fraction: np.ndarray
    flight_fraction: np.ndarray | None = None

    def __post_init__(self) -> None:
        if self.flight_fraction is None:
            object.__setattr__(self, "flight_fraction", np.zeros_like(self.tension_fraction))

    @classmethod
    def from_batch(
        cls, batch: BatchResult, ratio: np.ndarray, speed: np.ndarray, bridge_frequency_hz: float
    ) -> FrequencyMap:
        """Reshape a batch run speed by speed, all ratios at each speed, into a map."""
        shape = (speed.size, ratio.size)
        return cls(
            model=batch.model,
            bridge_frequency_hz=float(bridge_frequency_hz),
            ratio=np.asarray(ratio, dtype=float),
            speed=np.asarray(speed, dtype=float),
            daf=batch.daf.reshape(*shape, 2),
            contact_force_amplification=batch.contact_force_amplification.reshape(shape),
            min_contact_force_ratio=batch.min_contact_force_ratio.reshape(shape),
            tension_fraction=batch.tension_fraction.reshape(shape),
            flight_fraction=batch.flight_fraction.reshape(shape),
        )

    @property
    def truck_frequency_hz(self) -> np.ndarray:
        """Truck frequency of each column [Hz], ``(n_ratios,)``."""
        return self.ratio * self.bridge_frequency_hz

    @property
    def largest_daf(self) -> np.ndarray:
        """The larger DAF of the spans in each cell, ``(n_speeds, n_ratios)``."""
        return largest_daf(self.daf.reshape(-1, 2)).reshape(self.daf.shape[:2])

    def to_dataframe(self) -> pd.DataFrame:
        """One row per cell: speed (display units), ratio, truck frequency, DAFs, contact."""
        v, r = np.meshgrid(self.speed, self.ratio, indexing="ij")
        return pd.DataFrame(
            {
                display.label("speed", "speed"): display.value(v.ravel(), "speed"),
                "frequency ratio": r.ravel(),
                "truck frequency [Hz]": r.ravel() * self.bridge_frequency_hz,
                "daf span 1": self.daf[..., 0].ravel(),
                "daf span 2": self.daf[..., 1].ravel(),
                "contact force amplification": self.contact_force_amplification.ravel(),
                "min contact force ratio": self.min_contact_force_ratio.ravel(),
                "flight fraction": self.flight_fraction.ravel(),
                "lost contact": self.lost_contact.ravel(),
            }
        )

    def plot(self, ax: Axes | None = None, colorbar: bool = True) -> Axes:
        """Heat map of the larger span DAF; cells that lost contact are marked with crosses.

        Returns
        -------
        matplotlib.axes.Axes
            The image is ``ax.images[0]``; the crosses are the line with ``gid="lost"``.
        """
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6.5, 4))
        image = ax.imshow(
            self.largest_daf,
            origin="lower",
            aspect="auto",
            extent=_extent(self.ratio, self.speed),
            cmap="viridis",
        )
        r, v = _lost_points(self)
        ax.plot(r, v, "x", color="w", ms=6, mew=1.5, gid="lost")
        ax.set_xlabel("truck frequency / bridge first frequency [-]")
        ax.set_ylabel(display.label("speed", "speed"))
        if colorbar:
            ax.figure.colorbar(image, ax=ax, label="DAF [-]")
        return ax


def _edges(values: np.ndarray) -> tuple[float, float]:
    step = (values[-1] - values[0]) / max(values.size - 1, 1)
    return values[0] - step / 2, values[-1] + step / 2


def _extent(ratio: np.ndarray, speed: np.ndarray) -> tuple[float, float, float, float]:
    v = display.value(speed, "speed")
    return (*_edges(ratio), *_edges(v))


def _lost_points(result: FrequencyMap) -> tuple[np.ndarray, np.ndarray]:
    lost = result.lost_contact
    v, r = np.meshgrid(display.value(result.speed, "speed"), result.ratio, indexing="ij")
    return r[lost], v[lost]


class FrequencyExplorer(Explorer):
    """DAF over the truck-to-bridge frequency ratio and the speed, as a heat map.

    The map is computed when the explorer opens and when **Compute map** is pressed (or on
    :meth:`update` / :meth:`set`); changing a control first marks the map as out of date.

    Parameters
    ----------
    **values
        Start values of controls by parameter: the fields of :class:`Scenario` but
        ``truck_frequency_hz`` and ``speed_mph``, and ``ratio_range``, ``n_ratios``,
        ``speed_range_mph`` and ``n_speeds``.  For the quarter car the ratio is of its body
        frequency on a rigid tyre (``truck_frequency_hz``); its axle hop stays
        ``axle_hop_hz``, which must stay above the body's limit at every ratio.

    Attributes
    ----------
    controls, widget
        The controls by parameter; the box to display.
    result
        The last :class:`FrequencyMap`, or ``None``.

    Examples
    --------
    >>> explorer = FrequencyExplorer(n_ratios=3, n_speeds=3, ratio_range=(0.5, 1.5))
    >>> explorer.result.daf.shape, explorer.result.ratio.tolist()
    ((3, 3, 2), [0.5, 1.0, 1.5])
    """

    parameters = tuple(
        p for p in Scenario.__dataclass_fields__ if p not in ("speed_mph", "truck_frequency_hz")
    ) + ("ratio_range", "n_ratios", "speed_range_mph", "n_speeds")
    defaults = {"road": "harmonic", "n_speeds": 15, "speed_range_mph": (20.0, 90.0)}
    kind = "frequency"
    #: Seconds between two progressive redraws of the map.
    render_interval = 0.25

    def _report_setting(self) -> tuple[dict, list[float]]:
        """The map's cell of the largest DAF that kept contact (else its first): its truck
        frequency and speed."""
        values = dict(self.values())
        ratio, speed = self.grid()
        row, col = 0, 0
        result = self.result
        if result is not None:
            largest = np.where(result.lost_contact, np.nan, result.largest_daf)
            if np.isfinite(largest).any():
                row, col = np.unravel_index(np.nanargmax(largest), largest.shape)
        values["truck_frequency_hz"] = round(float(ratio[col] * values["bridge_frequency_hz"]), 6)
        values["speed_mph"] = round(float(speed[row] / u.mph), 6)
        return values, [values["speed_mph"]]

    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """The frequency ratios and the speeds [m/s] of the map."""
        low, high = self.controls["ratio_range"].value
        ratio = np.linspace(low, high, self.controls["n_ratios"].value)
        low, high = self.controls["speed_range_mph"].value
        return ratio, np.linspace(low, high, self.controls["n_speeds"].value) * u.mph

    def scenario(self) -> Scenario:
        """The controls' :class:`Scenario`, its truck at the lowest frequency ratio.

        The map sets the truck's frequency cell by cell; the scenario carries the lowest, so
        that a quarter car is checked against the first column rather than a frequency the
        map never runs (the other columns are checked when the map is computed).
        """
        values = self.values()
        low = values["ratio_range"][0] * values["bridge_frequency_hz"]
        fields = {k: v for k, v in values.items() if k in Scenario.__dataclass_fields__}
        return Scenario(**fields, truck_frequency_hz=low)

    def _extras(self) -> list[w.Widget]:
        self.button = w.Button(description="Compute map", button_style="primary")
        self.button.add_class("vbi-compute")
        self.button.on_click(lambda _button: self.update())
        return [self.button]

    def _setup_figure(self) -> None:
        figure = self.view.figure
        self.ax = figure.add_axes((0.11, 0.11, 0.68, 0.85))
        self.cax = figure.add_axes((0.82, 0.11, 0.03, 0.85))
        self.image = None
        style = {"color": "w", "lw": 1, "ls": "--", "alpha": 0.8}
        self.bridge_resonance = self.ax.plot([], [], label="v/λ = bridge f₁", **style)[0]
        self.truck_resonance = self.ax.plot([], [], label="v/λ = truck f", **{**style, "ls": ":"})[
            0
        ]
        self.resonance_legend = self.ax.legend(
            handles=[self.bridge_resonance, self.truck_resonance],
            loc="lower right",
            fontsize=8,
            facecolor="0.3",
            labelcolor="w",
            framealpha=0.6,
        )
        self._empty = figure.text(0.45, 0.5, "", ha="center", va="center", fontsize=12)

    def _compute(self) -> FrequencyMap:
        scenario = self.scenario()
        profile = scenario.profile()
        bridge = scenario.bridge()
        ratio, speed = self.grid()
        vehicles = []
        for r in ratio:
            try:
                truck = scenario.replace(truck_frequency_hz=r * bridge.first_frequency_hz)
            except ValueError as exc:  # a quarter car's axle hop too low for this body
                raise ValueError(f"at the frequency ratio {r:.2f}: {exc}") from None
            vehicles.append(truck.vehicle())
        self._context = (scenario, bridge)

        def as_map(batch: BatchResult) -> FrequencyMap:
            return FrequencyMap.from_batch(batch, ratio, speed, bridge.first_frequency_hz)

        batch = run_in_chunks(
            bridge,
            vehicles * speed.size,
            profile,
            np.repeat(speed, ratio.size),
            scenario.bridge_start(profile),
            scenario.simulate_options(),
            progress=lambda partial, done: self._draw(as_map(partial), done),
            interval=self.render_interval,
        )
        return as_map(batch)

    def _show(self, result: FrequencyMap) -> None:
        self._draw(result, None)

    def _draw(self, result: FrequencyMap, done: int | None) -> None:
        scenario, bridge = self._context
        values = result.largest_daf
        if self.image is None:
            result.plot(ax=self.ax, colorbar=False)
            self.image = self.ax.images[0]
            self.view.figure.colorbar(self.image, cax=self.cax, label="DAF [-]")
        else:
            self.image.set_data(values)
            self.image.set_extent(_extent(result.ratio, result.speed))
            self.ax.set_ylabel(display.label("speed", "speed"))
        finite = values[np.isfinite(values)]
        if finite.size:
            self.image.set_clim(finite.min(), max(finite.max(), finite.min() + 1e-6))
        lost = next(line for line in self.ax.lines if line.get_gid() == "lost")
        lost.set_data(*_lost_points(result))
        self._resonances(scenario, bridge, result)
        self._empty.set_text("")

        def where(i: int) -> str:
            row, col = divmod(i, result.ratio.size)
            return (
                f"at {display.fmt(result.speed[row], 'speed')} with a truck of "
                f"{result.truck_frequency_hz[col]:.2f} Hz (ratio {result.ratio[col]:.2f})"
            )

        self.view.render()
        self.readout.value = sweep_html(
            result.daf.reshape(-1, 2),
            result.min_contact_force_ratio.ravel(),
            bridge,
            where,
            scenario.model_text(),
            done,
            result.flight_fraction.ravel(),
            outside=bool(self.outside_inputs),
        )

    def _resonances(self, scenario: Scenario, bridge: object, result: FrequencyMap) -> None:
        """On a harmonic road: where ``v / lambda`` meets f1 (dashed) and the truck (dotted)."""
        wavelength = scenario.wavelength()
        self.resonance_legend.set_visible(wavelength is not None)
        if wavelength is None:
            self.bridge_resonance.set_data([], [])
            self.truck_resonance.set_data([], [])
            return
        r = result.ratio[[0, -1]]
        f1 = result.bridge_frequency_hz
        v_bridge = display.value(f1 * wavelength, "speed")
        self.bridge_resonance.set_data(r, [v_bridge, v_bridge])
        self.truck_resonance.set_data(r, display.value(r * f1 * wavelength, "speed"))
        low, high = self.image.get_extent()[2:]
        self.ax.set_ylim(low, high)

    def _blank(self) -> None:
        if self.image is not None:
            self.image.set_data(np.full((1, 1), np.nan))
            for line in self.ax.lines:
                line.set_data([], [])
        self._empty.set_text("no result for these settings")

    def _moved(self) -> None:
        """Controls moved: check them at once, and say the map is for the previous settings."""
        try:
            self.scenario().profile()
            self.grid()
        except (ValueError, TypeError) as exc:
            self.result, self.error = None, str(exc)
            self.update()  # shows the reason and empties the map
            return
        if self.result is None:
            self.readout.value = (
                '<div class="vbi-readout vbi-stale">Press <b>Compute map</b> to map these '
                "settings.</div>"
            )
            return
        stale = (
            '<div class="vbi-stale" style="color:#8a5a00"><b>The controls changed:</b> '
            "press <b>Compute map</b>; the map below is for the previous settings.</div>"
        )
        if "vbi-stale" not in self.readout.value:
            self.readout.value = stale + self.readout.value
