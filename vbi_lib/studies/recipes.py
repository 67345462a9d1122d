"""Profile recipes: small frozen descriptions of a road that a worker builds and caches.

A study may name a road by a recipe instead of a :class:`~vbi_lib.Profile`: the recipe is
cheap to send to a worker process, and the worker builds each road once
(``functools.lru_cache``) however many crossings use it.  A recipe has ``start``, ``end``,
``label`` and ``build()``.

A recipe checks its parameters when it is made, with the same checks as the
:class:`~vbi_lib.Profile` generator it names (types, ranges of validity, the number of
samples), without building the road: a recipe that exists can be built, so a study never
fails in a worker on a road it could have refused up front.
"""

from __future__ import annotations

import functools
import warnings
from dataclasses import dataclass
from typing import Any

from ..profiles import (
    Profile,
    check_harmonic,
    check_iso_rms,
    check_seed,
    check_stations,
    iso_band,
    iso_level,
)
from ..ranges import check_range
from ..validity import OutsideValidityWarning

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

    def __post_init__(self) -> None:
        check_stations(self.length, self.spacing, self.start)

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

    def __post_init__(self) -> None:
        check_harmonic(self.length, self.spacing, self.wavelength, self.amplitude, self.phase,
                       self.start)  # fmt: skip

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
    ``seed`` (a whole number >= 0) fixes the random phases, so the same recipe always builds
    the same road.  Checked as :meth:`vbi_lib.Profile.iso8608` checks (``TypeError``,
    ``ValueError``), when the recipe is made.

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
        if self.seed is None:
            raise TypeError(
                "ISOProfile seed=None: give a whole number (a study must be repeatable)"
            )
        object.__setattr__(self, "seed", check_seed(self.seed))
        level = iso_level(self.c10, self.iso_class)
        waviness = check_range("waviness", self.waviness)
        check_stations(self.length, self.spacing, self.start)
        low, high = iso_band(self.band, float(self.spacing))
        check_iso_rms(level, waviness, max(low, 1.0 / float(self.length)), high)
        object.__setattr__(self, "band", (low, high))

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
    with warnings.catch_warnings():
        # the recipe warned when it was made; its road is the same
        warnings.simplefilter("ignore", OutsideValidityWarning)
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
