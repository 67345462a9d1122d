"""DAF and contact force against speed, with the forcing frequency and the codes' allowances.

The truck drives the same bridge and road at each speed of ``speed_range_mph``
(``n_speeds`` values, evenly spaced).  The top axis gives the forcing frequency: ``v / lambda``
on a harmonic road of wavelength ``lambda`` (the study, Figure 2.15.7: the bridge responds most
where it matches the bridge's frequency, the truck where it matches the truck's), otherwise
the load-passage frequency ``v / 2L`` of a moving force on a span ``L`` (Frýba's speed
parameter times the bridge's frequency).
"""

from __future__ import annotations

import numpy as np

from .. import display
from .. import units as u
from ..models import BatchResult
from ..vehicles import as_system
from .base import Explorer
from .readouts import code_allowances, largest_daf, sweep_html
from .scenario import Scenario
from .sweeps import run_in_chunks

__all__ = ["SpeedExplorer"]

_CODE_STYLES = {"AASHTO LRFD": "--", "AASHTO Standard": "-.", "OHBDC 1983": ":"}


class SpeedExplorer(Explorer):
    """DAF and contact-force amplification against speed (many crossings, drawn as they run).

    Parameters
    ----------
    **values
        Start values of controls by parameter: the fields of :class:`Scenario` but
        ``speed_mph``, and ``speed_range_mph`` (low, high) and ``n_speeds``.

    Attributes
    ----------
    controls, widget
        The controls by parameter; the box to display.
    result
        The last :class:`~vbi_lib.BatchResult` (one row per speed), or ``None``.

    Examples
    --------
    >>> from vbi_lib import units as u
    >>> explorer = SpeedExplorer(road="flat", speed_range_mph=(20, 60), n_speeds=5)
    >>> (explorer.result.speed / u.mph).round(1).tolist()
    [20.0, 30.0, 40.0, 50.0, 60.0]
    """

    parameters = tuple(p for p in Scenario.__dataclass_fields__ if p != "speed_mph") + (
        "speed_range_mph",
        "n_speeds",
    )
    defaults = {"road": "harmonic"}
    kind = "speed"
    #: Seconds between two progressive redraws of a long sweep.
    render_interval = 0.25

    def _report_setting(self) -> tuple[dict, list[float]]:
        """The sweep's lowest and highest speeds, and that of its largest DAF with contact."""
        values = dict(self.values())
        low, high = values.pop("speed_range_mph")
        speeds = [low, high]
        result = self.result
        if result is not None:
            daf = largest_daf(result.daf)
            kept = np.isfinite(daf) & ~result.lost_contact
            if kept.any():
                best = int(np.flatnonzero(kept)[np.argmax(daf[kept])])
                speeds.append(round(float(result.speed[best] / u.mph), 6))
        values["speed_mph"] = speeds[-1]
        return values, speeds

    def speeds(self) -> np.ndarray:
        """The speeds of the sweep [m/s]."""
        low, high = self.controls["speed_range_mph"].value
        return np.linspace(low, high, self.controls["n_speeds"].value) * u.mph

    # ------------------------------------------------------------------ figure
    def _setup_figure(self) -> None:
        figure = self.view.figure
        top, bottom = self.axes = figure.subplots(2, 1, sharex=True)
        figure.subplots_adjust(left=0.1, right=0.77, top=0.88, bottom=0.1, hspace=0.1)
        self.daf_lines = [top.plot([], [], "o-", ms=3, label=f"span {j + 1}")[0] for j in (0, 1)]
        self.lost_daf = top.plot([], [], "x", color="k", ms=7, label="contact lost")[0]
        self.code_lines = {
            name: top.axhline(1.0, color="0.3", lw=1, ls=style, label=name)
            for name, style in _CODE_STYLES.items()
        }
        self.resonances = [
            ax.axvline(0.0, color=color, lw=0.8, alpha=0.6, label=label if ax is top else None)
            for ax in self.axes
            for color, label in (("C0", "v/λ = bridge f₁"), ("C2", "v/λ = truck f"))
        ]
        top.set_ylabel("DAF [-]")
        self._legend_key: tuple | None = None
        self.largest = bottom.plot([], [], "o-", ms=3, color="C3", label="largest")[0]
        self.smallest = bottom.plot([], [], "o-", ms=3, color="C4", label="smallest")[0]
        self.lost_contact_marks = bottom.plot([], [], "x", color="k", ms=7)[0]
        bottom.axhline(0.0, color="k", lw=0.8)
        bottom.set_ylabel("contact force / weight [-]")
        bottom.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
        self._frequency_per_speed = 1.0
        self.frequency_axis = top.secondary_xaxis(
            "top",
            functions=(
                lambda v: v * self._frequency_per_speed,
                lambda f: f / self._frequency_per_speed,
            ),
        )
        self._empty = figure.text(0.45, 0.5, "", ha="center", va="center", fontsize=12)

    # ------------------------------------------------------------------ compute and show
    def _compute(self) -> BatchResult:
        scenario = self.scenario()
        profile = scenario.profile()
        bridge = scenario.bridge()
        vehicle = scenario.vehicle()
        self._context = (scenario, bridge, vehicle)
        return run_in_chunks(
            bridge,
            vehicle,
            profile,
            self.speeds(),
            scenario.bridge_start(profile),
            scenario.simulate_options(),
            progress=lambda partial, done: self._draw(partial, done),
            interval=self.render_interval,
        )

    def _show(self, result: BatchResult) -> None:
        self._draw(result, None)

    def _draw(self, result: BatchResult, done: int | None) -> None:
        scenario, bridge, vehicle = self._context
        speed_unit = display.value(1.0, "speed")  # display units per m/s
        v = result.speed * speed_unit
        lost = result.lost_contact
        top, bottom = self.axes
        for j, line in enumerate(self.daf_lines):
            line.set_data(v, result.daf[:, j])
            line.set_visible(j < bridge.n_spans)
        worst = largest_daf(result.daf)
        self.lost_daf.set_data(v[lost], worst[lost])
        for name, value in code_allowances(bridge).items():
            self.code_lines[name].set_ydata([value, value])
        self.largest.set_data(v, result.contact_force_amplification)
        self.smallest.set_data(v, result.min_contact_force_ratio)
        self.lost_contact_marks.set_data(v[lost], result.min_contact_force_ratio[lost])
        wavelength = scenario.wavelength()
        if wavelength is not None:
            # forcing frequency v / lambda; resonance where it meets f1 or the truck's frequency
            self._frequency_per_speed = 1.0 / (wavelength * speed_unit)
            self.frequency_axis.set_xlabel("forcing frequency v / wavelength [Hz]")
            # the truck's lowest frequency on a rigid road: truck_frequency_hz for the sprung
            # mass, the coupled body bounce for the quarter car (its tyre softens it)
            truck_hz = float(as_system(vehicle).frequencies_hz[0])
            at = [f * wavelength * speed_unit for f in (bridge.first_frequency_hz, truck_hz)]
        else:
            self._frequency_per_speed = 1.0 / (2.0 * bridge.span * speed_unit)
            self.frequency_axis.set_xlabel("load-passage frequency v / 2L [Hz]")
            at = []
        for k, line in enumerate(self.resonances):
            inside = len(at) == 2 and v.min() <= at[k % 2] <= v.max()
            line.set_visible(inside)
            if inside:
                line.set_xdata([at[k % 2], at[k % 2]])
        bottom.set_xlabel(display.label("speed", "speed"))
        legend_key = (*(line.get_visible() for line in top.lines), bool(lost.any()))
        if legend_key != self._legend_key:
            # the legend lists only what is drawn
            handles = [h for h in top.lines if h.get_visible() and h.get_label()[0] != "_"]
            if not lost.any():
                handles.remove(self.lost_daf)
            top.legend(
                handles=handles,
                loc="upper left",
                bbox_to_anchor=(1.01, 1.0),
                fontsize=8,
                frameon=False,
            )
            self._legend_key = legend_key
        for ax in self.axes:
            ax.relim(visible_only=True)
            ax.autoscale_view()
        self._empty.set_text("")
        self.view.render()
        self.readout.value = sweep_html(
            result.daf,
            result.min_contact_force_ratio,
            bridge,
            lambda i: "at " + display.fmt(result.speed[i], "speed"),
            scenario.model_text(),
            done,
            result.flight_fraction,
            outside=bool(self.outside_inputs),
        )

    def _blank(self) -> None:
        for line in [
            *self.daf_lines,
            self.lost_daf,
            self.largest,
            self.smallest,
            self.lost_contact_marks,
        ]:
            line.set_data([], [])
        self._empty.set_text("no result for these settings")
