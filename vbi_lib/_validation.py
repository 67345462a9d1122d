"""Small checks that turn bad input into a sentence naming the parameter and what is allowed.

One policy everywhere: a value of the wrong *type* (text for a number, a number for a flag,
a float for a count, a string for a profile) raises ``TypeError``; a value of the right type
that is not allowed (NaN, negative, outside its range) raises ``ValueError``; every message
starts ``name=value must ...``.  Physical ranges are in :mod:`vbi_lib.ranges`.
"""

from __future__ import annotations

import math
import numbers

import numpy as np


def number(name: str, value: object) -> float:
    """``value`` as a float if it is a real number (not text, not a bool), else ``TypeError``."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}={value!r} must be a number, not {type(value).__name__}")
    return float(value)


def finite(name: str, value: object) -> float:
    """``value`` as a float if it is a finite real number (any sign)."""
    number_ = number(name, value)
    if not math.isfinite(number_):
        raise ValueError(f"{name}={value!r} must be a finite number")
    return number_


def integer(name: str, value: object, low: int | None = None, high: int | None = None) -> int:
    """``value`` as an int if it is a whole number (an ``int``, not a float, text or bool)
    within ``[low, high]``; ``TypeError`` for another type, ``ValueError`` outside."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, numbers.Integral):
        raise TypeError(
            f"{name}={value!r} must be a whole number (an int), not {type(value).__name__}"
        )
    result = int(value)
    if (low is not None and result < low) or (high is not None and result > high):
        if high is None:
            allowed = f">= {low}"
        elif low is None:
            allowed = f"<= {high}"
        else:
            allowed = f"from {low} to {high}"
        raise ValueError(f"{name}={value!r} must be a whole number {allowed}")
    return result


def choice(name: str, value: object, options: tuple[str, ...]) -> str:
    """``value`` if it is one of the strings ``options``; ``TypeError`` if it is not text."""
    if not isinstance(value, str):
        raise TypeError(
            f"{name}={value!r} must be one of {', '.join(map(repr, options))} (text, not "
            f"{type(value).__name__})"
        )
    if value not in options:
        raise ValueError(f"{name}={value!r} must be one of {', '.join(map(repr, options))}")
    return value


def instance(name: str, value: object, kind: type | tuple[type, ...], what: str) -> object:
    """``value`` if it is an instance of ``kind``, else ``TypeError`` saying ``what`` it must be."""
    if not isinstance(value, kind):
        raise TypeError(f"{name} must be {what}, got {type(value).__name__} {_short(value)}")
    return value


def _short(value: object) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def positive(name: str, value: float) -> float:
    """Return ``value`` as a float if it is finite and > 0, else raise ``ValueError``."""
    number_ = number(name, value)
    if not math.isfinite(number_) or number_ <= 0:
        raise ValueError(f"{name}={value!r} must be a finite number greater than zero")
    return number_


def non_negative(name: str, value: float) -> float:
    """Return ``value`` as a float if it is finite and >= 0, else raise ``ValueError``."""
    number_ = number(name, value)
    if not math.isfinite(number_) or number_ < 0:
        raise ValueError(f"{name}={value!r} must be a finite number >= 0")
    return number_


def damping_ratio(name: str, value: float) -> float:
    """A damping ratio in [0, 1)."""
    number_ = number(name, value)
    if not (math.isfinite(number_) and 0.0 <= number_ < 1.0):
        raise ValueError(
            f"{name}={value!r} is outside [0, 1): give the fraction of critical damping "
            "(0.01 for 1 %)"
        )
    return number_


def n_spans(value: int) -> int:
    """The number of equal spans of the study's beam and formulas: 1 or 2."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, numbers.Integral):
        raise TypeError(
            f"n_spans={value!r} must be a whole number (1 or 2), not {type(value).__name__}"
        )
    if value not in (1, 2):
        raise ValueError(
            f"n_spans={value!r} is not supported; use 1 (simple span) or 2 "
            "(two equal continuous spans), or build other layouts with "
            "Bridge.continuous(spans, EI=..., mass_per_length=...) and run them with "
            "model='modal'"
        )
    return int(value)


def finite_array(name: str, values: object) -> np.ndarray:
    """A 1-D float array of real numbers with no NaN or infinity.

    Text (even ``"1.5"``), bools, ``None`` and other objects raise ``TypeError`` naming the
    first offending entry; a wrong shape or a non-finite entry ``ValueError``.
    """
    if isinstance(values, str | bytes) or values is None:
        raise TypeError(f"{name}={values!r} must be a sequence of numbers")
    try:
        raw = np.asarray(values)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a one-dimensional sequence of numbers") from None
    if raw.dtype.kind not in "iuf":
        flat = raw.ravel() if raw.ndim else raw.reshape(1)
        for index, item in enumerate(flat):
            if isinstance(item, bool | np.bool_) or not isinstance(item, numbers.Real):
                shown = item.item() if isinstance(item, np.generic) else item
                raise TypeError(
                    f"{name}[{index}]={shown!r} must be a number, not {type(shown).__name__}"
                )
    array = raw.astype(float)
    if array.ndim != 1:
        raise ValueError(f"{name} must be one-dimensional, got shape {array.shape}")
    bad = ~np.isfinite(array)
    if bad.any():
        index = int(np.flatnonzero(bad)[0])
        raise ValueError(f"{name}[{index}]={float(array[index])!r} is not a finite number")
    return array


def real_array(name: str, values: object) -> np.ndarray:
    """A float array of any shape from numbers (a scalar, a list, an array); text, bools,
    ``None`` and other objects raise ``TypeError`` naming ``name``."""
    if isinstance(values, str | bytes) or values is None:
        raise TypeError(f"{name}={values!r} must be a number or an array of numbers")
    try:
        raw = np.asarray(values)
    except (TypeError, ValueError):
        raise ValueError(f"{name}={values!r} must be a rectangular array of numbers") from None
    if raw.dtype.kind not in "iuf":
        for item in raw.ravel():
            if isinstance(item, bool | np.bool_) or not isinstance(item, numbers.Real):
                raise TypeError(f"{name}={values!r} must be a number or an array of numbers")
    return raw.astype(float)


def flag(name: str, value: object) -> bool:
    """A boolean switch: ``True`` or ``False`` only (text such as ``'False'`` is refused)."""
    if isinstance(value, bool | np.bool_):
        return bool(value)
    raise TypeError(f"{name}={value!r} must be True or False (a bool, not {type(value).__name__})")
