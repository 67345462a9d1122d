"""The frame every explorer shares: controls, a readout, a note line and one figure.

An explorer recomputes when a control changes (:meth:`Explorer.update`).  If the controls
describe no valid crossing (a file that cannot be read, a road too short for the bridge), the
readout says why and shows no number, ``result`` becomes ``None`` and the figure is emptied,
so what is on the page always matches the controls.  A value a control refuses or clamps is
explained on the note line (see :mod:`vbi_lib.widgets.controls`), and so is an input the
model accepts but was not made for (an :class:`~vbi_lib.OutsideValidityWarning`: a speed
above 150 km/h, an ISO class beyond E), and so is how the road was completed (a measured deck
one or two samples short of the far support).  **Reset** puts every control back to the value
the explorer started with.
"""

from __future__ import annotations

import base64
import html
import tempfile
import warnings
from pathlib import Path
from typing import Any, ClassVar

import ipywidgets as w

from ..validity import OutsideValidityWarning
from .controls import ROAD_PARAMETERS, VEHICLE_PARAMETERS, make_controls
from .figure import FigureImage
from .readouts import error_html, notice_html
from .report_file import ReportFiles, report_files, write_report_files
from .scenario import Scenario

__all__ = ["Explorer"]

_SCENARIO_FIELDS = set(Scenario.__dataclass_fields__)

#: The panel's sections and the parameters in each, in the order shown.
SECTIONS = {
    "Bridge": (
        "span_ft",
        "n_spans",
        "bridge_frequency_hz",
        "bridge_weight_kip_per_ft",
        "bridge_damping",
    ),
    "Truck": (
        "vehicle_type",
        "truck_weight_kip",
        "truck_frequency_hz",
        "truck_damping",
        "unsprung_fraction",
        "axle_hop_hz",
    ),
    "Speed": ("speed_mph", "speed_range_mph", "n_speeds"),
    "Truck-to-bridge frequency ratio": ("ratio_range", "n_ratios"),
    "Road": (
        "road",
        "iso_class",
        "c10_e6",
        "waviness",
        "seed",
        "wavelength_ft",
        "amplitude_in",
        "bump_height_in",
        "bump_width_ft",
        "bump_position_ft",
        "profile_path",
        "profile_unit",
        "road_shift_ft",
        "approach_ft",
    ),
    "Model": ("modes", "coupled"),
}


class Explorer:
    """Base class: subclasses list their ``parameters`` and compute, draw and describe.

    Attributes
    ----------
    controls
        The controls by the parameter each sets.
    widget
        The box to display.
    result
        The last result, or ``None`` when the controls describe no valid crossing.
    error
        Why there is no result (the readout's sentence), else ``None``.
    """

    parameters: ClassVar[tuple[str, ...]] = ()
    #: What the explorer shows, in file names: ``crossing``, ``speed`` or ``frequency``.
    kind: ClassVar[str] = "explorer"
    #: Start values that differ from :class:`Scenario`'s for this explorer.
    defaults: ClassVar[dict[str, Any]] = {}
    figure_size: ClassVar[tuple[float, float]] = (7.2, 4.6)

    def __init__(self, **values: Any) -> None:
        self.result: Any = None
        self.error: str | None = None
        self.controls = make_controls(self.parameters, {**self.defaults, **values})
        self.readout = w.HTML()
        self.notice = w.HTML()
        self.view = FigureImage(self.figure_size)
        self._holding = False
        self._fresh_notice = False
        self._control_note: str | None = None  # a control's sentence in this change
        self._outside_said = False  # the note line shows inputs outside their ranges
        #: The last result's inputs outside their intended ranges, one sentence each.
        self.outside_inputs: list[str] = []
        #: The values the explorer started with (what **Reset** goes back to).
        self.start_values = self.values()
        self.reset_button = w.Button(
            description="Reset", tooltip="Put every control back to its start value"
        )
        self.reset_button.add_class("vbi-reset")
        self.reset_button.on_click(lambda _button: self.reset())
        self.report_button = w.Button(
            description="Report parameters",
            tooltip="Write this setting as a parameter file that vbi-report accepts",
        )
        self.report_button.add_class("vbi-report")
        self.report_button.on_click(lambda _button: self._offer_report_files())
        #: Links to download the last report parameter files (data: URLs, no server needed).
        self.report_links = w.HTML()
        self._uploads = tempfile.TemporaryDirectory(prefix="vbi-profiles-")
        self.upload = w.FileUpload(
            accept=".csv,.txt,.dat,.prn", multiple=False, description="upload profile"
        )
        self.upload.observe(self._uploaded, names="value")
        for control in self.controls.values():
            control.listeners.append(self._note)
            control.observe(self._changed, names="value")
        self._setup_figure()
        self.widget = w.HBox(
            [self._panel(), w.VBox([self.readout, self.notice, *self._extras(), self.view.widget])]
        )
        self.widget.add_class("vbi-explorer")
        self._show_used_controls()
        self.update()

    # ------------------------------------------------------------------ for subclasses
    def _setup_figure(self) -> None:
        """Create the figure's axes and artists (once)."""

    def _extras(self) -> list[Any]:
        """Widgets shown between the readout and the figure (a button, a progress bar)."""
        return []

    def _compute(self) -> Any:
        """Compute the result of the current controls (may raise ``ValueError``/``TypeError``)."""
        raise NotImplementedError

    def _show(self, result: Any) -> None:
        """Draw ``result`` and write the readout."""
        raise NotImplementedError

    def _blank(self) -> None:
        """Empty the figure (there is no result)."""

    # ------------------------------------------------------------------ public
    def values(self) -> dict[str, Any]:
        """The controls' current values, by parameter."""
        return {name: control.value for name, control in self.controls.items()}

    def report_files(self, name: str | None = None) -> ReportFiles:
        """The current setting as a report parameter file ``vbi-report`` accepts as it is.

        See :mod:`vbi_lib.widgets.report_file`: today's report keys; a road the report cannot
        generate is written as the deck profile beside it.  ``name`` is the file's name
        without ``.yaml`` (default ``vbi-<kind>``).

        Raises
        ------
        ValueError
            Controls that describe no crossing, or a setting the report cannot take (the
            message names the control to change).
        """
        values, speeds = self._report_setting()
        scenario = Scenario(**{k: v for k, v in values.items() if k in _SCENARIO_FIELDS})
        road = None
        if not (scenario.road == "iso-class" and scenario.road_shift_ft == 0):
            profile = scenario.profile()
            road = (profile, scenario.bridge_start(profile))
        return report_files(values, speeds, road, name or f"vbi-{self.kind}")

    def write_report_parameters(self, folder: str | Path, name: str | None = None) -> list[Path]:
        """Write :meth:`report_files` into ``folder``; returns the paths (parameters first)."""
        return write_report_files(self.report_files(name), folder)

    def _report_setting(self) -> tuple[dict[str, Any], list[float]]:
        """The values and speeds [mph] the report parameter file describes."""
        values = self.values()
        return values, [values["speed_mph"]]

    def _offer_report_files(self) -> None:
        try:
            files = self.report_files()
        except (ValueError, TypeError) as exc:
            self.report_links.value = notice_html(str(exc))
            return
        links = " ".join(
            f'<a download="{html.escape(f.name)}" href="data:text/plain;charset=utf-8;base64,'
            f'{base64.b64encode(f.text.encode()).decode()}">{html.escape(f.name)}</a>'
            for f in files.files
        )
        self.report_links.value = (
            f'<div class="vbi-report-files">Download {links}. {html.escape(files.note)}</div>'
        )

    def reset(self) -> Any:
        """Every control back to its start value, one recomputation; returns :attr:`result`."""
        return self.set(**self.start_values)

    def scenario(self) -> Scenario:
        """The :class:`Scenario` of the controls (fields without a control keep the default).

        Raises
        ------
        ValueError, TypeError
            The controls' values do not make a valid scenario.
        """
        return Scenario(**{k: v for k, v in self.values().items() if k in _SCENARIO_FIELDS})

    def set(self, **values: Any) -> Any:
        """Set several controls at once and recompute once; returns :attr:`result`.

        Raises
        ------
        ValueError
            An unknown parameter, or a value a control refuses (the controls set before it
            keep their new values and the explorer recomputes).
        """
        unknown = sorted(set(values) - set(self.controls))
        if unknown:
            raise ValueError(
                f"{unknown} are not controls of this explorer; use {list(self.controls)}"
            )
        self._holding = True
        try:
            for name, value in values.items():
                self.controls[name].value = value
        finally:
            self._holding = False
            self._show_used_controls()
            self.update()
        return self.result

    def update(self) -> Any:
        """Recompute from the controls and redraw; returns :attr:`result` (``None`` if invalid).

        Inputs outside their intended ranges are said on the note line, not as warnings.
        """
        try:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", OutsideValidityWarning)
                result = self._compute()
        except (ValueError, TypeError) as exc:
            self.result, self.error = None, str(exc)
            self.readout.value = error_html(self.error)
            self._blank()
            self.view.render()
            return None
        self.result, self.error = result, None
        outside = []
        for item in caught:
            if issubclass(item.category, OutsideValidityWarning):
                outside.append(str(item.message))
            else:  # not ours to handle: pass it on
                warnings.warn_explicit(item.message, item.category, item.filename, item.lineno)
        self.outside_inputs = outside
        self._say_outside(outside, self._road_notes())
        self._show(result)
        return result

    # ------------------------------------------------------------------ plumbing
    def _note(self, message: str) -> None:
        self.notice.value = notice_html(message)
        self._fresh_notice = True
        self._control_note = message

    def _road_notes(self) -> list[str]:
        """How the road was completed (a measured deck a sample or two short), for the notes."""
        try:
            return self.scenario().road_notes()
        except (ValueError, TypeError):
            return []

    def _say_outside(self, outside: list[str], notes: list[str] | None = None) -> None:
        """Put the inputs outside their intended ranges (and the road's notes) on the note
        line, after any sentence a control said in this change; take them away when the
        inputs are back inside."""
        control, self._control_note = self._control_note, None
        outside = [*outside, *(notes or [])]
        if outside:
            sentences = ([control] if control else []) + list(dict.fromkeys(outside))
            self.notice.value = notice_html(" ".join(_sentence(s) for s in sentences))
            self._outside_said = True
        elif self._outside_said:
            self._outside_said = False
            if control is None:
                self.notice.value = ""

    def _changed(self, change: dict[str, Any]) -> None:
        if not self._fresh_notice:
            self.notice.value = ""
        self._fresh_notice = False
        if self._holding:
            return
        if change["owner"] in (self.controls.get("road"), self.controls.get("vehicle_type")):
            self._show_used_controls()
        self._moved()

    def _moved(self) -> None:
        """A control moved (not inside :meth:`set`): recompute at once."""
        self.update()

    def _uploaded(self, change: dict[str, Any]) -> None:
        if not change["new"] or "profile_path" not in self.controls:
            return
        item = change["new"][0]
        path = Path(self._uploads.name) / Path(item["name"]).name
        path.write_bytes(bytes(item["content"]))
        self.set(road="measured", profile_path=str(path))

    def _show_used_controls(self) -> None:
        """Show the road's and the truck's parameters the chosen kinds use; hide the others."""
        for key, groups in (("road", ROAD_PARAMETERS), ("vehicle_type", VEHICLE_PARAMETERS)):
            if key not in self.controls:
                continue
            used = set(groups[self.controls[key].value])
            for name in {p for group in groups.values() for p in group}:
                if name in self.controls:
                    self.controls[name].box.layout.display = "" if name in used else "none"
            if key == "road":
                self.upload.layout.display = "" if "profile_path" in used else "none"

    def _panel(self) -> w.VBox:
        rows: list[Any] = [w.HBox([self.reset_button, self.report_button]), self.report_links]
        for title, names in SECTIONS.items():
            present = [self.controls[n].box for n in names if n in self.controls]
            if not present:
                continue
            rows.append(w.HTML(f"<b>{title}</b>"))
            rows.extend(present)
            if title == "Road" and "profile_path" in self.controls:
                rows.insert(rows.index(self.controls["profile_path"].box) + 1, self.upload)
        return w.VBox(rows, layout=w.Layout(min_width="28em"))


def _sentence(text: str) -> str:
    """``text`` ending with a full stop, so that sentences joined on the note line read."""
    text = text.strip()
    return text if text.endswith((".", "!", "?")) else text + "."
