r"""The line members of a deck: its girders, the beams along its edges, its diaphragms.

A deck (:class:`~vbi_lib.decks.deck.Deck`) is a slab with lines of extra stiffness and mass:
girders and edge beams (barriers, parapets) along it, diaphragms across it.  These classes
describe them; :mod:`vbi_lib.decks.ritz` adds their energies to the slab's.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .. import _validation as check
from ..ranges import check_range
from .sections import GirderSection

__all__ = ["Diaphragms", "EdgeBeam", "Girders", "LineMember"]


def _check_fields(member: object, **keys: str) -> None:
    """Each named field of a frozen member checked against ``RANGES[key]`` and stored."""
    for name, key in keys.items():
        object.__setattr__(member, name, check_range(key, getattr(member, name), name))


def _one_or_each(name: str, value: object, count: int, key: str) -> tuple[float, ...]:
    """A number, or one number per girder, checked against ``RANGES[key]``."""
    if isinstance(value, str | bytes) or not isinstance(value, Sequence | np.ndarray):
        return (check_range(key, value, name),) * count
    values = tuple(value)
    if len(values) != count:
        raise ValueError(f"{name}={value!r} must be one number or one per girder ({count} of them)")
    return tuple(check_range(key, v, f"{name}[{i}]") for i, v in enumerate(values))


@dataclass(frozen=True)
class Girders:
    """The girders under a deck: how many, how far apart, and how stiff and heavy each is.

    Give either ``EI`` and ``mass_per_length`` (one value for all, or one per girder) or a
    ``section``, from which the deck computes each girder's composite rigidity with its
    tributary slab (interior girders: one spacing; exterior ones: half a spacing and the
    overhang) and its mass.

    Parameters
    ----------
    count
        Number of girders, 1 to 100; girder 1 is the one nearest the edge ``y = 0``.
    spacing
        Distance between neighbouring girders [m] (ignored for one girder).
    EI
        Composite flexural rigidity of a girder and its tributary slab [N m^2], as an
        engineer computes it (transformed section).  The slab's own rigidity over the
        tributary width is carried by the plate and is subtracted in the model.
    mass_per_length
        The girder's own mass per length, slab excluded [kg/m].
    GJ
        Torsional rigidity of a girder [N m^2] (default none).
    section
        A :class:`~vbi_lib.decks.sections.GirderSection` instead of ``EI``,
        ``mass_per_length`` and ``GJ``.

    Raises
    ------
    TypeError, ValueError
        A value of the wrong type or outside its range (``girder_count``,
        ``girder_spacing``, ``EI``, ``line_mass``, ``torsional_rigidity``), a list of the
        wrong length, both or neither of ``EI`` and ``section``.
    """

    count: int
    spacing: float = 0.0
    EI: float | tuple[float, ...] | None = None
    mass_per_length: float | tuple[float, ...] | None = None
    GJ: float | tuple[float, ...] = 0.0
    section: GirderSection | None = None

    def __post_init__(self) -> None:
        count = check.integer("count", self.count, low=1)
        check_range("girder_count", count, "count", warn=False)
        object.__setattr__(self, "count", count)
        if count > 1:
            object.__setattr__(self, "spacing", check_range("girder_spacing", self.spacing,
                                                            "spacing"))  # fmt: skip
        else:
            object.__setattr__(self, "spacing", check.non_negative("spacing", self.spacing))
        if self.section is not None:
            check.instance("section", self.section, GirderSection, "a GirderSection")
            if self.EI is not None or self.mass_per_length is not None or self.GJ != 0.0:
                raise ValueError(
                    "girders take either a section or EI, mass_per_length and GJ, not both; "
                    "drop EI, mass_per_length and GJ (the section gives them)"
                )
            return
        if self.EI is None or self.mass_per_length is None:
            raise ValueError(
                f"EI={self.EI!r} and mass_per_length={self.mass_per_length!r} must both be "
                "given (or a section instead)"
            )
        object.__setattr__(self, "EI", _one_or_each("EI", self.EI, count, "EI"))
        object.__setattr__(
            self,
            "mass_per_length",
            _one_or_each("mass_per_length", self.mass_per_length, count, "line_mass"),
        )
        object.__setattr__(self, "GJ", _one_or_each("GJ", self.GJ, count, "torsional_rigidity"))


@dataclass(frozen=True)
class EdgeBeam:
    """A line member along one side of a deck: a barrier, a parapet, an edge beam.

    Parameters
    ----------
    EI
        Flexural rigidity it adds to the deck [N m^2] (0: mass only).
    mass_per_length
        Its mass per length [kg/m].
    GJ
        Torsional rigidity [N m^2].
    offset
        Distance from the deck's edge to its axis [m].
    """

    EI: float = 0.0
    mass_per_length: float = 0.0
    GJ: float = 0.0
    offset: float = 0.0

    def __post_init__(self) -> None:
        _check_fields(self, EI="member_EI", mass_per_length="line_mass",
                      GJ="torsional_rigidity", offset="overhang")  # fmt: skip

    @classmethod
    def rectangle(
        cls, width: float, height: float, E: float, density: float, *, stiff: bool = True
    ) -> EdgeBeam:
        """A rectangular barrier ``width`` wide and ``height`` tall on the deck's edge.

        Its own section (``E width height^3 / 12``, no composite action with the slab)
        unless ``stiff=False`` (mass only); axis at ``width / 2`` from the edge.
        """
        width = check.positive("width", width)
        height = check.positive("height", height)
        E = check_range("youngs_modulus", E, "E")
        density = check_range("material_density", density, "density")
        rigidity = E * width * height**3 / 12.0 if stiff else 0.0
        return cls(rigidity, density * width * height, 0.0, 0.5 * width)


@dataclass(frozen=True)
class Diaphragms:
    """Diaphragms across a deck: lines parallel to the supports between the exterior girders.

    Parameters
    ----------
    EI
        Flexural rigidity of each diaphragm about its horizontal axis [N m^2].
    mass_per_length
        Its mass per length [kg/m].
    stations
        Where they stand along the girders [m from the first support line], or
        ``"midspans"`` (one at the middle of every span).  Diaphragms on the support lines
        add nothing (the supports already hold the deck there).
    """

    EI: float
    mass_per_length: float = 0.0
    stations: tuple[float, ...] | str = "midspans"

    def __post_init__(self) -> None:
        _check_fields(self, EI="member_EI", mass_per_length="line_mass")
        if isinstance(self.stations, str):
            check.choice("stations", self.stations, ("midspans",))
        else:
            stations = tuple(check.finite(f"stations[{i}]", s) for i, s in enumerate(self.stations))
            object.__setattr__(self, "stations", stations)


class LineMember(NamedTuple):
    """A line along the deck at ``y = position``, as the Ritz assembly sees it."""

    position: float
    EI: float
    GJ: float
    mass_per_length: float
