r"""Cross-sections of a deck's line members, and their composite action with the slab.

A girder under a concrete slab bends with it about one neutral axis: the composite section.
By the transformed-section method (any text on composite beams; AASHTO LRFD 4.6.2.6 for the
effective width) every part :math:`i` of modulus :math:`E_i`, area :math:`A_i`, own second
moment :math:`I_i` and centroid at height :math:`z_i` contributes

.. math::
    z_0 = \frac{\sum_i E_i A_i z_i}{\sum_i E_i A_i}, \qquad
    (EI)_{comp} = \sum_i E_i \left[ I_i + A_i (z_i - z_0)^2 \right].

:class:`GirderSection` describes a girder (a rolled shape or a precast beam) by its area,
second moment, depth, modulus and density; :func:`composite_rigidity` gives the rigidity of
any set of :class:`Part`\ s.  The deck (:class:`~vbi_lib.decks.deck.Deck`) uses them to turn a
girder's section into its composite :math:`EI` over its tributary width of slab.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from .. import _validation as check
from ..ranges import check_range

__all__ = ["GirderSection", "Part", "composite_rigidity"]


@dataclass(frozen=True)
class Part:
    """One part of a composite section: modulus, area, own second moment, centroid height.

    Parameters
    ----------
    E
        Young's modulus [Pa].
    area
        Area [m^2].
    inertia
        Second moment of area about its own horizontal centroidal axis [m^4].
    height
        Height of its centroid above any one datum shared by the parts [m].
    """

    E: float
    area: float
    inertia: float
    height: float

    @classmethod
    def rectangle(cls, E: float, width: float, depth: float, bottom: float) -> Part:
        """A ``width x depth`` rectangle whose bottom lies at height ``bottom`` [m]."""
        return cls(E, width * depth, width * depth**3 / 12.0, bottom + 0.5 * depth)


def composite_rigidity(parts: Iterable[Part]) -> tuple[float, float]:
    """Flexural rigidity [N m^2] of parts bending together, and their neutral axis height [m].

    Raises
    ------
    ValueError
        No parts, or parts with no axial stiffness at all.

    Examples
    --------
    Two equal rectangles stacked act as one of twice the depth (``b (2d)^3 / 12``):

    >>> top, bottom = Part.rectangle(1.0, 1.0, 1.0, 1.0), Part.rectangle(1.0, 1.0, 1.0, 0.0)
    >>> rigidity, axis = composite_rigidity([top, bottom])
    >>> round(rigidity * 12 / 8, 12), axis
    (1.0, 1.0)
    """
    parts = list(parts)
    axial = sum(p.E * p.area for p in parts)
    if not parts or axial <= 0.0:
        raise ValueError(f"parts={parts!r} must hold at least one part with E * area > 0")
    axis = sum(p.E * p.area * p.height for p in parts) / axial
    rigidity = sum(p.E * (p.inertia + p.area * (p.height - axis) ** 2) for p in parts)
    return rigidity, axis


@dataclass(frozen=True)
class GirderSection:
    """A girder's own cross-section: what a deck needs to make it composite with the slab.

    Parameters
    ----------
    area
        Area [m^2].
    inertia
        Second moment of area about its own horizontal centroidal axis [m^4].
    depth
        Overall depth [m]; the slab sits on top of it (after ``haunch``).
    E
        Young's modulus [Pa].
    density
        Density [kg/m^3]: the girder's mass per length is ``density * area``.
    centroid
        Height of its centroid above its bottom [m]; ``None``: mid-depth (a doubly
        symmetric shape).
    torsion_constant
        Saint-Venant torsion constant J [m^4] (AISC tables for rolled shapes).
    shear_modulus
        Shear modulus G [Pa]; ``None``: ``E / 2.6`` (Poisson's ratio 0.3).
    haunch
        Gap between the top of the girder and the underside of the slab [m].

    Raises
    ------
    TypeError, ValueError
        A value that is not a number, or not positive (area, inertia, depth), or outside
        its range (``E``: ``youngs_modulus``; ``density``: ``material_density``).

    Examples
    --------
    A W30x108 (AISC: 31.7 in^2, 4470 in^4, 29.8 in deep, J = 4.99 in^4):

    >>> from vbi_lib import units as u
    >>> w30 = GirderSection(31.7 * u.inch**2, 4470 * u.inch**4, 29.8 * u.inch,
    ...                     29000e3 * u.psi, 7850.0, torsion_constant=4.99 * u.inch**4)
    >>> round(w30.mass_per_length / (u.lbf / u.ft / u.g), 1)   # lb/ft
    107.9
    """

    area: float
    inertia: float
    depth: float
    E: float
    density: float
    centroid: float | None = None
    torsion_constant: float = 0.0
    shear_modulus: float | None = None
    haunch: float = 0.0

    def __post_init__(self) -> None:
        for name in ("area", "inertia", "depth"):
            object.__setattr__(self, name, check.positive(name, getattr(self, name)))
        object.__setattr__(self, "E", check_range("youngs_modulus", self.E, "E"))
        object.__setattr__(
            self, "density", check_range("material_density", self.density, "density")
        )
        if self.centroid is not None:
            centroid = check.positive("centroid", self.centroid)
            if centroid >= self.depth:
                raise ValueError(
                    f"centroid={centroid!r} must lie within the depth {self.depth!r} m"
                )
            object.__setattr__(self, "centroid", centroid)
        object.__setattr__(
            self,
            "torsion_constant",
            check_range("torsional_rigidity", self.torsion_constant, "torsion_constant"),
        )
        if self.shear_modulus is not None:
            object.__setattr__(
                self,
                "shear_modulus",
                check_range("youngs_modulus", self.shear_modulus, "shear_modulus"),  # fmt: skip
            )
        object.__setattr__(self, "haunch", check.non_negative("haunch", self.haunch))

    @property
    def mass_per_length(self) -> float:
        """The girder's own mass per length, ``density * area`` [kg/m]."""
        return self.density * self.area

    @property
    def torsional_rigidity(self) -> float:
        """``G J`` [N m^2]."""
        shear = self.shear_modulus if self.shear_modulus is not None else self.E / 2.6
        return shear * self.torsion_constant

    def part(self) -> Part:
        """The girder as a :class:`Part`, its bottom at height 0."""
        centroid = self.centroid if self.centroid is not None else 0.5 * self.depth
        return Part(self.E, self.area, self.inertia, centroid)

    def composite(self, slab_width: float, slab_thickness: float, slab_E: float) -> float:
        """Rigidity [N m^2] of the girder and ``slab_width`` of slab on it, bending as one."""
        slab = Part.rectangle(slab_E, slab_width, slab_thickness, self.depth + self.haunch)
        return composite_rigidity([self.part(), slab])[0]
