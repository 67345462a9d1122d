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
explorer can show it next to its result.

>>> span = make_controls(["span_ft"])["span_ft"]
>>> span.value = float("nan")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
vbi_lib.widgets.controls.ControlValueError: span_ft=nan must be a finite number from 20 ...
>>> span.value = 500.0  # clamped, and said so to span.listeners
>>> span.value
250.0
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

__all__ = ["SPECS", "ControlValueError", "make_controls"]


class ControlValueError(TraitError, ValueError):
    """A control refused a value; the message names the parameter and what is allowed."""


def _tell(control: Any, message: str) -> None:
    for listener in list(getattr(control, "listeners", ())):
        listener(message)


def _refuse(control: Any, value: object, allowed: str) -> ControlValueError:
    keeps = control.value
    shown = f"{keeps:g}" if isinstance(keeps, float) else repr(keeps)
    message = f"{control.parameter}={value!r} must be {allowed}; the control keeps {shown}"
    _tell(control, message)
    return ControlValueError(message)


def _range_text(control: Any, whole: bool = False) -> str:
    kind = "a whole number" if whole else "a finite number"
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

    def __init__(self, parameter: str, unit: str = "", **kwargs: Any) -> None:
        self.parameter = parameter
        self.unit = unit
        self.listeners: list[Callable[[str], None]] = []
        super().__init__(**kwargs)
        self.add_class(f"vbi-control-{parameter}")


def _clamped(control: Any, value: float) -> float:
    if not math.isfinite(value):
        raise _refuse(control, value, _range_text(control))
    if control.min <= value <= control.max:
        return value
    clamped = min(max(value, control.min), control.max)
    unit = f" {control.unit}" if control.unit else ""
    _tell(
        control,
        f"{control.parameter}={value:g} is outside the control's range {control.min:g} to "
        f"{control.max:g}{unit}; it was set to {clamped:g}",
    )
    return clamped


class FloatControl(_Control, w.FloatSlider):
    """A float slider for one parameter: NaN refused, values outside its range clamped."""

    value = _Number(0.0).tag(sync=True)

    @validate("value")
    def _validate_value(self, proposal: Any) -> float:
        return _clamped(self, proposal["value"])


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


def _float(label: str, unit: str, low: float, high: float, step: float, **extra: Any) -> dict:
    return {
        "kind": FloatControl,
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
    "bridge_damping": _float("bridge damping", "", 0, 0.1, 0.0025, readout_format=".2%"),
    "truck_weight_kip": _float("truck weight [kip]", "kip", 5, 160, 0.5),
    "truck_frequency_hz": _float("truck frequency [Hz]", "Hz", 0.5, 15, 0.05),
    "truck_damping": _float("truck damping", "", 0, 0.5, 0.01, readout_format=".0%"),
    "vehicle_type": _choice("truck model", [(label, key) for key, label in VEHICLE_TYPES.items()]),
    # the soft range of RANGES["vehicle_frequency"] tops out at 50 Hz; trucks hop at 8-15 Hz
    "axle_hop_hz": _float("axle hop [Hz]", "Hz", 2, 50, 0.5),
    "unsprung_fraction": _float(
        "unsprung share of weight", "", 0.02, MAX_UNSPRUNG_FRACTION, 0.01, readout_format=".0%"
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


def make_controls(keys: Iterable[str], values: dict[str, Any] | None = None) -> dict[str, Any]:
    """The controls for ``keys`` (parameters of :data:`SPECS`), at the given start values.

    Start values default to :class:`Scenario`'s and :data:`SWEEP_DEFAULTS`; a start value
    outside a control's range is refused like any other (:class:`ControlValueError`).

    Raises
    ------
    ValueError
        A key that is not a parameter of :data:`SPECS`.
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
        control = kind(key, unit, value=start, layout=w.Layout(width="27em"), **spec)
        controls[key] = control
    if values:
        raise ValueError(f"{sorted(values)} are not controls of this explorer; use {list(keys)}")
    return controls
