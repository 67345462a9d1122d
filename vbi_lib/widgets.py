"""Interactive what-if explorers for Jupyter (ipywidgets).

Each explorer is a small object holding its controls and a figure; ``explorer.widget`` is what
you display, ``explorer.update()`` recomputes from the current control values (the controls
call it when they change), and ``explorer.result`` holds the last computation so that it can
be inspected or tested without a browser.

In a notebook: ``CrossingExplorer().widget`` (one crossing) or ``SpeedExplorer().widget``
(DAF against speed).  The controls describe a :class:`Scenario` in engineering units:

>>> from vbi_lib.widgets import Scenario
>>> round(Scenario(span_ft=100, bridge_frequency_hz=3.0).bridge().first_frequency_hz, 6)
3.0
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from . import amplification
from . import units as u
from .bridges import Bridge
from .models import Crossing, simulate, simulate_many
from .profiles import Profile
from .vehicles import Vehicle

_ISO_CLASSES = ["A", "B", "C", "D", "E"]


@dataclass(frozen=True)
class Scenario:
    """The explorer's inputs in engineering units (the controls' values)."""

    span_ft: float = 100.0
    n_spans: int = 1
    bridge_frequency_hz: float = 3.0
    bridge_mass_kip_per_ft: float = 4.6
    bridge_damping: float = 0.01
    truck_weight_kip: float = 77.2
    truck_frequency_hz: float = 3.5
    truck_damping: float = 0.10
    speed_mph: float = 41.0
    iso_class: str = "C"
    seed: int = 1
    approach_ft: float = 320.0

    def bridge(self) -> Bridge:
        mass = self.bridge_mass_kip_per_ft * u.kip / u.ft / u.g
        return Bridge.from_frequency(
            self.span_ft * u.ft, self.n_spans, mass, self.bridge_frequency_hz, self.bridge_damping
        )

    def vehicle(self) -> Vehicle:
        mass = self.truck_weight_kip * u.kip / u.g
        return Vehicle.from_frequency(mass, self.truck_frequency_hz, self.truck_damping)

    def profile(self) -> Profile:
        length = (self.approach_ft + self.n_spans * self.span_ft) * u.ft + 1.0
        road = Profile.iso8608(length, 1 * u.inch, iso_class=self.iso_class, seed=self.seed)
        return Profile(road.x, road.elevation - road.elevation[0], name=road.name)


def _controls() -> dict[str, Any]:
    import ipywidgets as w

    def slider(value, low, high, step, label):  # noqa: ANN001, ANN202
        return w.FloatSlider(
            value=value, min=low, max=high, step=step, description=label, continuous_update=False
        )

    defaults = Scenario()
    return {
        "span_ft": slider(defaults.span_ft, 20, 200, 5, "span [ft]"),
        "n_spans": w.Dropdown(options=[1, 2], value=1, description="spans"),
        "bridge_frequency_hz": slider(defaults.bridge_frequency_hz, 1, 12, 0.1, "bridge f1 [Hz]"),
        "truck_frequency_hz": slider(defaults.truck_frequency_hz, 1, 12, 0.1, "truck f [Hz]"),
        "truck_weight_kip": slider(defaults.truck_weight_kip, 10, 150, 1, "truck [kip]"),
        "speed_mph": slider(defaults.speed_mph, 5, 80, 1, "speed [mph]"),
        "iso_class": w.Dropdown(options=_ISO_CLASSES, value="C", description="ISO class"),
        "seed": w.IntSlider(value=1, min=0, max=50, description="road seed"),
    }


class CrossingExplorer:
    """One crossing: midspan deflection and contact force as you move the sliders.

    Attributes
    ----------
    controls
        The ipywidgets controls by name (units in their labels).
    widget
        The box to display.
    result
        The last :class:`~vbi_lib.simulation.Crossing`.
    """

    def __init__(self) -> None:
        import ipywidgets as w

        self.controls = _controls()
        self.output = w.Output()
        self.summary = w.HTML()
        self.result: Crossing | None = None
        for control in self.controls.values():
            control.observe(lambda _change: self.update(), names="value")
        left = w.VBox(list(self.controls.values()))
        self.widget = w.HBox([left, w.VBox([self.summary, self.output])])
        self.update()

    def scenario(self) -> Scenario:
        """The :class:`Scenario` of the current control values."""
        return Scenario(**{name: control.value for name, control in self.controls.items()})

    def update(self) -> Crossing:
        """Recompute and redraw; returns the crossing."""
        import matplotlib.pyplot as plt

        scenario = self.scenario()
        bridge = scenario.bridge()
        crossing = simulate(
            bridge,
            scenario.vehicle(),
            scenario.profile(),
            scenario.speed_mph * u.mph,
            scenario.approach_ft * u.ft,
        )
        self.result = crossing
        dafs = ", ".join(f"{d:.2f}" for d in crossing.daf)
        code = float(amplification.aashto_lrfd_allowance()) + 1
        self.summary.value = (
            f"<b>DAF {dafs}</b> (AASHTO LRFD design value {code:.2f}); "
            f"peak contact force {crossing.contact_force_amplification:.2f} x weight"
        )
        self.output.clear_output(wait=True)
        with self.output:
            fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 4.5), sharex=True)
            crossing.plot(ax=top)
            top.set_xlabel("")
            x = crossing.position - crossing.bridge_start
            bottom.plot(x, crossing.contact_force / crossing.vehicle.weight)
            bottom.axvspan(0, bridge.length, color="0.92", zorder=0)
            bottom.set_xlabel("truck position from the start of the bridge [m]")
            bottom.set_ylabel("contact force / weight [-]")
            fig.tight_layout()
            plt.show()
        return crossing


class SpeedExplorer:
    """DAF against speed for the current bridge, truck and road (many crossings at once)."""

    def __init__(self, speeds_mph: np.ndarray | None = None) -> None:
        import ipywidgets as w

        self.speeds_mph = np.linspace(10, 80, 36) if speeds_mph is None else np.asarray(speeds_mph)
        self.controls = _controls()
        del self.controls["speed_mph"]
        self.output = w.Output()
        self.result: np.ndarray | None = None
        for control in self.controls.values():
            control.observe(lambda _change: self.update(), names="value")
        self.widget = w.HBox([w.VBox(list(self.controls.values())), self.output])
        self.update()

    def update(self) -> np.ndarray:
        """Recompute the DAF of every span at every speed; returns ``(n_speeds, 2)``."""
        import matplotlib.pyplot as plt

        values = {name: control.value for name, control in self.controls.items()}
        scenario = Scenario(**values)
        bridge = scenario.bridge()
        batch = simulate_many(
            bridge,
            scenario.vehicle(),
            scenario.profile(),
            self.speeds_mph * u.mph,
            scenario.approach_ft * u.ft,
        )
        self.result = batch.daf
        self.output.clear_output(wait=True)
        with self.output:
            fig, ax = plt.subplots(figsize=(6.5, 3.5))
            for j in range(bridge.n_spans):
                ax.plot(self.speeds_mph, batch.daf[:, j], "o-", ms=3, label=f"span {j + 1}")
            ax.axhline(1.33, color="k", ls="--", label="AASHTO LRFD 1.33")
            ax.set_xlabel("speed [mph]")
            ax.set_ylabel("DAF [-]")
            ax.legend()
            plt.show()
        return batch.daf
