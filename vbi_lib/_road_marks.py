"""A road's verdict, kept on the road itself: whether :mod:`vbi_lib.road_checks` found it
plausible, and whether it has warned of it.

Kept apart from the checks so that :mod:`vbi_lib.profiles` can mark the roads it generates (and
pass a verdict on to a road's segments and copies) without importing the checks, which
measure roads with :mod:`vbi_lib.profiles` and :mod:`vbi_lib.roughness`: no import cycle.
"""

from __future__ import annotations

from typing import Any

__all__ = ["inherit", "mark_checked"]

_NOTES = "_road_notes"
_WARNED = "_road_warned"


def _store(profile: Any, key: str, value: Any) -> None:
    object.__setattr__(profile, key, value)  # a frozen Profile: not a field, it pickles along


def mark_checked(profile: Any, notes: tuple[str, ...] = ()) -> Any:
    """Record ``profile``'s verdict (``()``: plausible; a generator's road); returns it."""
    _store(profile, _NOTES, tuple(notes))
    return profile


def inherit(source: Any, derived: Any) -> Any:
    """Give ``derived`` (a segment, a shifted or resampled copy) ``source``'s verdict, if it
    has one (a road cut from a plausible road is plausible); returns ``derived``."""
    notes = source.__dict__.get(_NOTES)
    if notes is not None:
        _store(derived, _NOTES, notes)
        if source.__dict__.get(_WARNED):
            _store(derived, _WARNED, True)
    return derived
