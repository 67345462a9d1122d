"""The explorers' controls: ipywidgets that refuse bad values with a sentence, not a traceback.

Each control sets one parameter (its ``parameter`` attribute, the key of the explorer's
``controls`` dict and, for the crossing's parameters, a field of
:class:`~vbi_lib.widgets.Scenario`).  Plain ipywidgets accept a NaN in a slider and answer a
wrong choice with traitlets' ``Invalid selection: value not found``; these subclasses instead

* refuse a value that is not a finite number, not a whole number where one is needed, or not
  one of the choices, raising :class:`ControlValueError` (a ``ValueError``) whose message names
  the parameter, the value and what is allowed; the control keeps its value;
* clamp a number outside the slider's range to the nearest end, as ipywidgets does, but say so;

and in both cases call the functions in ``control.listeners`` with the sentence, so that the
explorer can show it next to its result.  Messages are in the control's unit.  A start value
outside a control's range is refused when the control is made (:func:`make_controls`).

Damping ratios and the quarter car's unsprung share are :class:`PercentControl` s: their
``value`` is a fraction (the :class:`~vbi_lib.widgets.Scenario`'s), but the box beside the
slider shows and takes percent, so typing ``1`` means 1 %.  Every control carries a line of
help (:data:`HELP`) as its tooltip; ``control.box`` is the widget to lay out.

>>> span = make_controls(["span_ft"])["span_ft"]
>>> span.value = float("nan")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
vbi_lib.widgets.controls.ControlValueError: span_ft=nan must be a finite number from 20 ...
>>> span.value = 500.0  # clamped, and said so to span.listeners
>>> span.value
250.0
>>> damping = make_controls(["bridge_damping"])["bridge_damping"]
>>> damping.text.value = 3.0  # the box takes percent
>>> damping.value
0.03
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable, Iterable
from typing import Any

import ipywidgets as w
from traitlets import CFloat, CInt, TraitError, Tuple, Unicode, validate

from .scenario import (
    MAX_MODES,
    MAX_ROAD_SHIFT_FT,
    MAX_UNSPRUNG_FRACTION,
    ROADS,
    VEHICLE_TYPES,
    Scenario,
)

__all__ = ["HELP", "SPECS", "ControlValueError", "PercentControl", "make_controls"]


class ControlValueError(TraitError, ValueError):
    """A control refused a value; the message names the parameter and what is allowed."""


def _tell(control: Any, message: str) -> None:
    for listener in list(getattr(control, "listeners", ())):
        listener(message)


def _refuse(control: Any, value: object, allowed: str) -> ControlValueError:
    keeps = control.value
    shown = _shown(control, keeps) if isinstance(keeps, float) else repr(keeps)
    message = f"{control.parameter}={value!r} must be {allowed}; the control keeps {shown}"
    _tell(control, message)
    return ControlValueError(message)


def _shown(control: Any, value: float) -> str:
    """A value as the control shows it: ``3 %`` for a percent control, ``120 ft``, ``0.5``."""
    if getattr(control, "percent", False):
        return f"{value * 100:g} %"
    unit = f" {control.unit}" if control.unit else ""
    return f"{value:g}{unit}"


def _range_text(control: Any, whole: bool = False) -> str:
    kind = "a whole number" if whole else "a finite number"
    if getattr(control, "percent", False):
        return f"{kind} from {control.min * 100:g} to {control.max * 100:g} %"
    unit = f" {control.unit}" if control.unit else ""
    return f"{kind} from {control.min:g} to {control.max:g}{unit}"


class _Number(CFloat):
    """A float trait whose type errors name the control's parameter."""

    def validate(self, obj: Any, value: Any) -> float:
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise _refuse(obj, value, _range_text(obj))
        return float(value)


class _Whole(CInt):
    """An int trait that refuses text, NaN and numbers with a fractional part."""

    def validate(self, obj: Any, value: Any) -> int:
        ok = isinstance(value, int) and not isinstance(value, bool)
        if not ok and isinstance(value, float) and math.isfinite(value) and value.is_integer():
            value, ok = int(value), True
        if not ok:
            raise _refuse(obj, value, _range_text(obj, whole=True))
        return int(value)


class _Pair(Tuple):
    """A (low, high) trait whose type errors name the control's parameter."""

    def validate(self, obj: Any, value: Any) -> tuple:
        pair = tuple(value) if isinstance(value, tuple | list) else ()
        if len(pair) != 2 or not all(
            isinstance(v, numbers.Real) and not isinstance(v, bool) for v in pair
        ):
            raise _refuse(obj, value, "two finite numbers, low < high")
        return (float(pair[0]), float(pair[1]))


class _Text(Unicode):
    def validate(self, obj: Any, value: Any) -> str:
        if not isinstance(value, str):
            raise _refuse(obj, value, "text")
        return value


class _Control:
    """What every control adds: the parameter it sets, its unit and who hears its refusals.

    Comes first among a control's bases, so that it takes ``parameter`` and ``unit`` and
    hands the other keywords to the ipywidgets class.
    """

    parameter: str = ""
    unit: str = ""
    percent: bool = False

    def __init__(self, parameter: str, unit: str = "", **kwargs: Any) -> None:
        self.parameter = parameter
        self.unit = unit
        self.listeners: list[Callable[[str], None]] = []
        kwargs.setdefault("tooltip", HELP.get(parameter, ""))
        super().__init__(**kwargs)
        self.add_class(f"vbi-control-{parameter}")
        #: The widget to lay out (the control itself, or the slider and its box).
        self.box: Any = self


def _clamped(control: Any, value: float) -> float:
    if not math.isfinite(value):
        raise _refuse(control, value, _range_text(control))
    if control.min <= value <= control.max:
        return value
    clamped = min(max(value, control.min), control.max)
    scale = 100.0 if control.percent else 1.0
    _tell(
        control,
        f"{control.parameter}={_shown(control, value)} is outside the control's range "
        f"{control.min * scale:g} to {_shown(control, control.max)}; it was set to "
        f"{_shown(control, clamped)}",
    )
    return clamped


class FloatControl(_Control, w.FloatSlider):
    """A float slider for one parameter: NaN refused, values outside its range clamped."""

    value = _Number(0.0).tag(sync=True)

    @validate("value")
    def _validate_value(self, proposal: Any) -> float:
        return _clamped(self, proposal["value"])


class PercentControl(FloatControl):
    """A fraction shown and typed as a percent: the slider holds the fraction (``value``), the
    box beside it (``text``) shows and takes percent, so ``1`` typed means 1 %."""

    percent = True

    def __init__(self, parameter: str, unit: str = "", **kwargs: Any) -> None:
        super().__init__(parameter, unit, readout=False, **kwargs)
        self.text = w.FloatText(
            value=round(self.value * 100, 6),
            step=round(self.step * 100, 6),
            layout=w.Layout(width="6em"),
            tooltip=self.tooltip,
        )
        self.text.add_class(f"vbi-percent-{parameter}")
        self._syncing = False
        self.text.observe(self._typed, names="value")
        self.observe(self._moved, names="value")
        self.box = w.HBox([self, self.text, w.Label("%")])
        self.box.add_class(f"vbi-control-{parameter}-box")

    def _typed(self, change: dict[str, Any]) -> None:
        if self._syncing:
            return
        try:
            self.value = change["new"] / 100.0
        except ControlValueError:
            pass  # said to the listeners; the box shows the value kept below
        finally:
            self._sync_text()

    def _moved(self, change: dict[str, Any]) -> None:
        self._sync_text()

    def _sync_text(self) -> None:
        self._syncing = True
        try:
            self.text.value = round(self.value * 100, 6)
        finally:
            self._syncing = False


class IntControl(_Control, w.IntSlider):
    """A whole-number slider for one parameter."""

    value = _Whole(0).tag(sync=True)

    @validate("value")
    def _validate_value(self, proposal: Any) -> int:
        return int(_clamped(self, proposal["value"]))


class ChoiceControl(_Control, w.Dropdown):
    """A drop-down list for one parameter; a value not offered is refused by name."""

    @validate("value")
    def _validate_value(self, proposal: Any) -> Any:
        return _offered(self, proposal["value"])


class FlagControl(_Control, w.ToggleButtons):
    """Two buttons for a yes/no option (the values are ``True`` and ``False``)."""

    @validate("value")
    def _validate_value(self, proposal: Any) -> Any:
        return _offered(self, proposal["value"])


def _offered(control: Any, value: Any) -> Any:
    values = [v for _, v in control.options] if control.options else []
    for option in values:
        if type(option) is type(value) and option == value:
            return option
    listing = ", ".join(repr(v) for v in values)
    raise _refuse(control, value, f"one of {listing}")


class TextControl(_Control, w.Text):
    """A line of text for one parameter (sent when the user presses Enter or leaves it)."""

    value = _Text("").tag(sync=True)


class RangeControl(_Control, w.FloatRangeSlider):
    """A (low, high) pair of one parameter, both finite, inside the range, low < high."""

    value = _Pair(default_value=(0.0, 1.0)).tag(sync=True)

    @validate("value")
    def _validate_value(self, proposal: Any) -> tuple[float, float]:
        low, high = proposal["value"]
        if not (math.isfinite(low) and math.isfinite(high) and low < high):
            raise _refuse(self, (low, high), "two finite numbers, low < high")
        return (_clamped(self, low), _clamped(self, high))


# ------------------------------------------------------------------------------ specs
_D = Scenario()
_SLIDER = {"continuous_update": False, "style": {"description_width": "12em"}}


def _float(
    label: str, unit: str, low: float, high: float, step: float, kind: type = FloatControl,
    **extra: Any,
) -> dict:  # fmt: skip
    return {
        "kind": kind,
        "unit": unit,
        "description": label,
        "min": low,
        "max": high,
        "step": step,
        **_SLIDER,
        **extra,
    }


def _int(label: str, low: int, high: int, **extra: Any) -> dict:
    return {"kind": IntControl, "description": label, "min": low, "max": high, **_SLIDER, **extra}


def _choice(label: str, options: list[tuple[str, Any]], kind: type = ChoiceControl) -> dict:
    return {
        "kind": kind,
        "description": label,
        "options": options,
        "style": {"description_width": "12em"},
    }


#: Every control the explorers use, by parameter: its widget class and settings.
SPECS: dict[str, dict[str, Any]] = {
    "span_ft": _float("span [ft]", "ft", 20, 250, 5),
    "n_spans": _choice("spans", [("1 (simple span)", 1), ("2 (continuous)", 2)]),
    "bridge_frequency_hz": _float("bridge f₁ [Hz]", "Hz", 0.5, 15, 0.05),
    "bridge_weight_kip_per_ft": _float("bridge weight [kip/ft]", "kip/ft", 0.5, 20, 0.1),
    "bridge_damping": _float("bridge damping [%]", "", 0, 0.1, 0.0025, kind=PercentControl),
    "truck_weight_kip": _float("truck weight [kip]", "kip", 5, 160, 0.5),
    "truck_frequency_hz": _float("truck frequency [Hz]", "Hz", 0.5, 15, 0.05),
    # up to 250 %: above 100 % the suspension is overdamped (VBI-2D's verification vehicle:
    # 209 %), taken and noted above the intended 50 %
    "truck_damping": _float("truck damping [%]", "", 0, 2.5, 0.01, kind=PercentControl),
    "vehicle_type": _choice("truck model", [(label, key) for key, label in VEHICLE_TYPES.items()]),
    # the soft range of RANGES["vehicle_frequency"] tops out at 50 Hz; trucks hop at 8-15 Hz
    "axle_hop_hz": _float("axle hop [Hz]", "Hz", 2, 50, 0.5),
    "unsprung_fraction": _float(
        "unsprung share [%]", "", 0.02, MAX_UNSPRUNG_FRACTION, 0.01, kind=PercentControl
    ),
    "speed_mph": _float("speed [mph]", "mph", 5, 100, 1),
    "road": _choice("road", [(label, key) for key, label in ROADS.items()]),
    "iso_class": _choice("ISO 8608 class", [(c, c) for c in "ABCDEFGH"]),
    "c10_e6": _float("C10 [10⁻⁶ m³]", "1e-6 m^3", 1, 5000, 1),
    "waviness": _float("waviness w", "", 1.5, 4, 0.1),
    "seed": _int("road seed", 0, 99),
    "wavelength_ft": _float("wavelength [ft]", "ft", 2, 200, 1),
    "amplitude_in": _float("amplitude [in]", "in", 0, 2, 0.05),
    "bump_height_in": _float("bump height [in]", "in", -3, 3, 0.1),
    "bump_width_ft": _float("bump length [ft]", "ft", 0.5, 30, 0.5),
    "bump_position_ft": _float("bump at [ft from support 1]", "ft", -100, 500, 1),
    "profile_path": {
        "kind": TextControl,
        "description": "profile file",
        "placeholder": "path of a two-column file",
        "continuous_update": False,
        "style": {"description_width": "12em"},
    },
    "profile_unit": _choice("file unit", [(n, n) for n in ("in", "ft", "mm", "m")]),
    "road_shift_ft": _float("road shifted by [ft]", "ft", 0, MAX_ROAD_SHIFT_FT, 1),
    "approach_ft": _float("approach [ft]", "ft", 0, 400, 5),
    "modes": _int("beam modes", 1, MAX_MODES),
    "coupled": _choice(
        "bridge and truck", [("coupled", True), ("decoupled", False)], kind=FlagControl
    ),
    # sweeps
    "speed_range_mph": {
        "kind": RangeControl,
        "unit": "mph",
        "description": "speeds [mph]",
        "min": 5,
        "max": 120,
        "step": 1,
        **_SLIDER,
    },
    "n_speeds": _int("number of speeds", 3, 80),
    "ratio_range": {
        "kind": RangeControl,
        "unit": "",
        "description": "truck f / bridge f₁",
        "min": 0.2,
        "max": 4.0,
        "step": 0.05,
        **_SLIDER,
    },
    "n_ratios": _int("number of ratios", 3, 40),
}

#: One line of help for every control, by parameter (the controls' tooltips, and the static
#: book's explorers).
HELP: dict[str, str] = {
    "span_ft": "Length of each span, from support to support.",
    "n_spans": "One simple span, or two equal spans continuous over the middle support.",
    "bridge_frequency_hz": "The bridge's first natural frequency; with its weight it sets EI.",
    "bridge_weight_kip_per_ft": "The bridge's weight per length along the truck's path.",
    "bridge_damping": "The bridge's damping, percent of critical, in every mode.",
    "vehicle_type": "The study's sprung mass, or a quarter car whose tyre can leave the road.",
    "truck_weight_kip": "The truck's whole weight (its mass is the weight over g).",
    "truck_frequency_hz": "The truck's body bounce on its suspension, undamped.",
    "truck_damping": "The suspension's damping, percent of critical (from 100 %: overdamped).",
    "axle_hop_hz": "The quarter car's axle bouncing between suspension and tyre.",
    "unsprung_fraction": "Percent of the quarter car's weight below the suspension.",
    "speed_mph": "The truck's constant speed over the approach and the bridge.",
    "road": "The road the truck drives: flat, one wave, one bump, or an ISO 8608 random road.",
    "iso_class": "ISO 8608 roughness class, A (smooth) to H; E and beyond are very rough.",
    "c10_e6": "ISO 8608 roughness G_d at 0.1 cycle/m, in 1e-6 m^3 (class A is 16).",
    "waviness": "How fast the road's spectrum falls with frequency (ISO 8608: 2).",
    "seed": "Which random road of that roughness: the same seed, the same road.",
    "wavelength_ft": "Length of one wave of the harmonic road.",
    "amplitude_in": "Half the height of the harmonic road's waves.",
    "bump_height_in": "Height of the bump (negative: a dip).",
    "bump_width_ft": "Length of the bump at its base.",
    "bump_position_ft": "Where the bump's crest is, from the first support (negative: before it).",
    "profile_path": "A measured profile: two columns, station and elevation, in the unit below.",
    "profile_unit": "Unit of the profile file's stations and elevations.",
    "road_shift_ft": "Slide the road back under the bridge by this much.",
    "approach_ft": "Road before the first support; the truck starts at rest at its start.",
    "modes": "1: the study's one-coordinate model; more: that many exact beam modes.",
    "coupled": "Coupled: the bridge's motion moves the wheel; decoupled ignores it.",
    "speed_range_mph": "The lowest and the highest speed of the sweep.",
    "n_speeds": "How many speeds the sweep runs, evenly spaced.",
    "ratio_range": "The lowest and highest truck frequency over the bridge's first frequency.",
    "n_ratios": "How many frequency ratios the map runs, evenly spaced.",
}

#: Default values of the sweep controls (the crossing's come from :class:`Scenario`).
SWEEP_DEFAULTS: dict[str, Any] = {
    "speed_range_mph": (10.0, 80.0),
    "n_speeds": 36,
    "ratio_range": (0.5, 2.0),
    "n_ratios": 13,
}

#: Which truck parameters each vehicle type adds to weight, frequency and damping (the others
#: are hidden).
VEHICLE_PARAMETERS = {
    "sprung-mass": (),
    "quarter-car": ("unsprung_fraction", "axle_hop_hz"),
}

#: Which road parameters each road kind uses (the others are hidden).
ROAD_PARAMETERS = {
    "flat": (),
    "harmonic": ("wavelength_ft", "amplitude_in"),
    "bump": ("bump_height_in", "bump_width_ft", "bump_position_ft"),
    "iso-class": ("iso_class", "seed"),
    "iso-c10": ("c10_e6", "waviness", "seed"),
    "measured": ("profile_path", "profile_unit"),
}


def _check_start(key: str, kind: type, unit: str, spec: dict[str, Any], start: Any) -> None:
    """Refuse a start value outside a slider's range (the slider would clamp it unsaid)."""
    if "min" not in spec or not issubclass(kind, FloatControl | IntControl | RangeControl):
        return
    low, high = spec["min"], spec["max"]
    numbers_ = start if isinstance(start, tuple | list) else (start,)
    if not all(isinstance(v, numbers.Real) and not isinstance(v, bool) for v in numbers_):
        return  # the control's own check names the parameter
    if all(math.isfinite(v) and low <= v <= high for v in numbers_):
        return
    if issubclass(kind, PercentControl):
        given = ", ".join(f"{v * 100:g} %" for v in numbers_)
        allowed = f"from {low * 100:g} to {high * 100:g} %"
    else:
        suffix = f" {unit}" if unit else ""
        given = ", ".join(f"{v:g}{suffix}" for v in numbers_)
        allowed = f"from {low:g} to {high:g}{suffix}"
    raise ControlValueError(
        f"{key}={start!r} ({given}) is outside the control's range {allowed}: start the "
        "explorer inside it"
    )


def make_controls(keys: Iterable[str], values: dict[str, Any] | None = None) -> dict[str, Any]:
    """The controls for ``keys`` (parameters of :data:`SPECS`), at the given start values.

    Start values default to :class:`Scenario`'s and :data:`SWEEP_DEFAULTS`; a start value
    that is not a number, not offered, or outside a control's range is refused
    (:class:`ControlValueError`, in the control's unit), never clamped.

    Raises
    ------
    ValueError
        A key that is not a parameter of :data:`SPECS`; a start value the control refuses.
    """
    values = dict(values or {})
    controls = {}
    for key in keys:
        if key not in SPECS:
            raise ValueError(f"{key!r} is not an explorer parameter; use one of {list(SPECS)}")
        spec = dict(SPECS[key])
        kind = spec.pop("kind")
        unit = spec.pop("unit", "")
        start = values.pop(key, SWEEP_DEFAULTS.get(key, getattr(_D, key, None)))
        _check_start(key, kind, unit, spec, start)
        control = kind(key, unit, value=start, layout=w.Layout(width="27em"), **spec)
        controls[key] = control
    if values:
        raise ValueError(f"{sorted(values)} are not controls of this explorer; use {list(keys)}")
    return controls
