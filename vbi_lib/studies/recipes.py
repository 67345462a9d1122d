"""Profile recipes: small frozen descriptions of a road that a worker builds and caches.

A study may name a road by a recipe instead of a :class:`~vbi_lib.Profile`: the recipe is
cheap to send to a worker process, and the worker builds each road once
(``functools.lru_cache``) however many crossings use it.  A recipe has ``start``, ``end``,
``label`` and ``build()``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..profiles import Profile

__all__ = ["FlatProfile", "HarmonicProfile", "ISOProfile", "extent", "is_recipe", "profile_label"]


@dataclass(frozen=True)
class FlatProfile:
    """Recipe for a smooth road: ``Profile.flat(length, spacing, start)`` built in the worker.

    >>> FlatProfile(100.0, 0.025).build().x.size
    4001
    """

    length: float
    spacing: float
    start: float = 0.0

    @property
    def end(self) -> float:
        """Last station [m]."""
        return self.start + self.length

    @property
    def label(self) -> str:
        """Short name used in result tables."""
        return "flat"

    def build(self) -> Profile:
        """The :class:`~vbi_lib.Profile` (cached per process)."""
        return _build(self)

    def _make(self) -> Profile:
        return Profile.flat(self.length, self.spacing, self.start)


@dataclass(frozen=True)
class HarmonicProfile:
    """Recipe for ``Profile.harmonic(length, spacing, wavelength, amplitude, phase, start)``.

    >>> round(float(HarmonicProfile(30.0, 0.01, 10.0, 0.002).build().elevation.max()) * 1e3, 3)
    2.0
    """

    length: float
    spacing: float
    wavelength: float
    amplitude: float
    phase: float = 0.0
    start: float = 0.0

    @property
    def end(self) -> float:
        """Last station [m]."""
        return self.start + self.length

    @property
    def label(self) -> str:
        """Short name used in result tables."""
        return f"harmonic {self.wavelength:g} m"

    def build(self) -> Profile:
        """The :class:`~vbi_lib.Profile` (cached per process)."""
        return _build(self)

    def _make(self) -> Profile:
        return Profile.harmonic(
            self.length, self.spacing, self.wavelength, self.amplitude, self.phase, self.start
        )


@dataclass(frozen=True)
class ISOProfile:
    """Recipe for an ISO 8608 random road, ``Profile.iso8608(...)`` built in the worker (87).

    The book writes the spectrum as :eq:`study-87`.
    Give either ``c10`` (``G_d(n0)`` at ``n0 = 0.1`` cycle/m [m^3]) or ``iso_class`` (A-H).
    ``seed`` fixes the random phases, so the same recipe always builds the same road.

    Examples
    --------
    >>> ISOProfile(200.0, 0.025, c10=300e-6, seed=1).label
    'ISO C10=300e-6 w=2 seed 1'
    """

    length: float
    spacing: float
    c10: float | None = None
    iso_class: str | None = None
    waviness: float = 2.0
    seed: int = 0
    band: tuple[float, float] = (0.011, 2.83)
    start: float = 0.0

    def __post_init__(self) -> None:
        if (self.c10 is None) == (self.iso_class is None):
            raise ValueError(
                f"ISOProfile needs exactly one of c10 and iso_class; got c10={self.c10!r}, "
                f"iso_class={self.iso_class!r}"
            )
        if not isinstance(self.seed, int | np.integer) or isinstance(self.seed, bool):
            raise ValueError(
                f"ISOProfile seed={self.seed!r} must be an integer (a study must be repeatable)"
            )
        object.__setattr__(self, "seed", int(self.seed))
        object.__setattr__(self, "band", tuple(float(b) for b in self.band))

    @property
    def end(self) -> float:
        """Last station [m]."""
        return self.start + self.length

    @property
    def label(self) -> str:
        """Short name used in result tables."""
        rough = (
            f"C10={self.c10 * 1e6:.4g}e-6" if self.c10 is not None else f"class {self.iso_class}"
        )
        return f"ISO {rough} w={self.waviness:g} seed {self.seed}"

    def build(self) -> Profile:
        """The :class:`~vbi_lib.Profile` (cached per process)."""
        return _build(self)

    def _make(self) -> Profile:
        return Profile.iso8608(
            self.length,
            self.spacing,
            c10=self.c10,
            iso_class=self.iso_class,
            waviness=self.waviness,
            seed=self.seed,
            band=self.band,
            start=self.start,
        )


_RECIPES = (FlatProfile, HarmonicProfile, ISOProfile)


@functools.lru_cache(maxsize=64)
def _build(recipe: Any) -> Profile:
    return recipe._make()


def is_recipe(value: object) -> bool:
    """Whether ``value`` is a profile recipe (it has ``build()`` and ``end``)."""
    return callable(getattr(value, "build", None)) and hasattr(value, "end")


def extent(profile: Any) -> tuple[float, float]:
    """First and last station of a profile or recipe without building it."""
    if isinstance(profile, Profile):
        return profile.start, profile.end
    return float(profile.start), float(profile.end)


def profile_label(profile: Any) -> str:
    """A short name for a profile or a recipe, for result tables."""
    if isinstance(profile, Profile):
        return profile.name or "profile"
    return str(getattr(profile, "label", type(profile).__name__))
