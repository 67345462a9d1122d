"""Small checks that turn bad input into a sentence naming the parameter and what is allowed."""

from __future__ import annotations

import math

import numpy as np


def positive(name: str, value: float) -> float:
    """Return ``value`` as a float if it is finite and > 0, else raise ``ValueError``."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name}={value!r} must be a positive number") from None
    if not math.isfinite(number) or number <= 0:
        raise ValueError(f"{name}={value!r} must be a finite number greater than zero")
    return number


def non_negative(name: str, value: float) -> float:
    """Return ``value`` as a float if it is finite and >= 0, else raise ``ValueError``."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name}={value!r} must be a number >= 0") from None
    if not math.isfinite(number) or number < 0:
        raise ValueError(f"{name}={value!r} must be a finite number >= 0")
    return number


def damping_ratio(name: str, value: float) -> float:
    """A damping ratio in [0, 1)."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name}={value!r} must be a number in [0, 1)") from None
    if not (math.isfinite(number) and 0.0 <= number < 1.0):
        raise ValueError(
            f"{name}={value!r} is outside [0, 1): give the fraction of critical damping "
            "(0.01 for 1 %)"
        )
    return number


def n_spans(value: int) -> int:
    """The number of equal spans the one-coordinate model supports: 1 or 2."""
    if value not in (1, 2) or isinstance(value, bool):
        raise ValueError(
            f"n_spans={value!r} is not supported; use 1 (simple span) or 2 "
            "(two equal continuous spans)"
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
