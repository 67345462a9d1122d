"""Small checks that turn bad input into a sentence naming the parameter and what is allowed."""

from __future__ import annotations

import math
import numbers

import numpy as np


def number(name: str, value: object) -> float:
    """``value`` as a float if it is a real number (not text, not a bool), else ``TypeError``."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}={value!r} must be a number, not {type(value).__name__}")
    return float(value)


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
    if value not in (1, 2) or isinstance(value, bool):
        raise ValueError(
            f"n_spans={value!r} is not supported; use 1 (simple span) or 2 "
            "(two equal continuous spans), or build other layouts with "
            "Bridge.continuous(spans, EI=..., mass_per_length=...) and run them with "
            "model='modal'"
        )
    return int(value)


def finite_array(name: str, values: object) -> np.ndarray:
    """A 1-D float array with no NaN or infinity."""
    array = np.asarray(values, dtype=float)
    if array.ndim != 1:
        raise ValueError(f"{name} must be one-dimensional, got shape {array.shape}")
    bad = ~np.isfinite(array)
    if bad.any():
        index = int(np.flatnonzero(bad)[0])
        raise ValueError(f"{name}[{index}]={float(array[index])!r} is not a finite number")
    return array


def flag(name: str, value: object) -> bool:
    """A boolean switch: ``True`` or ``False`` only (text such as ``'False'`` is refused)."""
    if isinstance(value, bool | np.bool_):
        return bool(value)
    raise TypeError(f"{name}={value!r} must be True or False (a bool, not {type(value).__name__})")
