r"""A slab-on-girder deck: the bridge across its width, not reduced to one beam.

:class:`Deck` describes a deck as an engineer draws it: spans along the girders (one simple
span or several continuous ones), a slab of given width, thickness and material, girders
under it, barriers or edge beams along its sides, diaphragms across it and a skew.
:meth:`Deck.plate` is the bare slab.  Its modes (:mod:`vbi_lib.decks.modes`) come from the
Rayleigh-Ritz method of :mod:`vbi_lib.decks.ritz`.

Coordinates and the skew's hand
-------------------------------
``x`` runs along the girders and ``y`` across them, from the deck's edge on girder 1's side;
looking along increasing ``x`` (a vehicle's direction of travel by default) that edge is on
the **right**, and ``y`` grows to the left.  The supports are lines across the deck.  With a
skew :math:`\theta` they are not square to the girders:

* ``skew_hand="left"`` (left-forward): the left end of every support line lies further along
  ``x`` than its right end, the line :math:`x = x_j + y\tan\theta`;
* ``skew_hand="right"`` (right-forward): :math:`x = x_j - y\tan\theta`.

Driving the other way turns one hand into the other.  Every position on the deck is given as
``(x, y)`` with ``x`` measured **along the line** ``y = const`` **from the first support
line** (the oblique coordinate :math:`\xi`): ``x = 0`` and ``x = sum(spans)`` are the end
supports at every ``y``, and a girder's midspan is at ``x = L/2`` whatever the skew.

Supports are lines (a bearing under every point of a support line; for girder decks, the
bearings and the end diaphragms together); they hold the deck down and leave it free to
rotate about the line.  The sides are free.

What the model leaves out
-------------------------
No eccentricity: the girders and edge beams bend about the slab's mid-plane, with the
composite rigidity given to them, so no membrane forces arise (the study's plate
eccentric-beam models had them; its "Bridge Models" section).  No shear deformation of the
slab (Kirchhoff), no rotary inertia, no warping of the girders.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from functools import cached_property
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from .. import _validation as check
from ..continuous_beams import support_stations
from ..ranges import check_range
from .sections import GirderSection

if TYPE_CHECKING:
    from .modes import DeckModes
    from .paths import WheelPath

__all__ = ["DEFAULT_ALONG", "DEFAULT_ACROSS", "Deck", "Diaphragms", "EdgeBeam", "Girders"]

#: Default Ritz functions along the girders, per span (beam modes of the continuous beam).
DEFAULT_ALONG = 12
#: Default Ritz functions across the girders (Legendre polynomials).
DEFAULT_ACROSS = 30
#: End functions at each end of a skewed deck (:mod:`vbi_lib.decks.basis`).
DEFAULT_END_FUNCTIONS = 1


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
        object.__setattr__(self, "EI", check_range("member_EI", self.EI, "EI"))
        object.__setattr__(
            self,
            "mass_per_length",
            check_range("line_mass", self.mass_per_length, "mass_per_length"),  # fmt: skip
        )
        object.__setattr__(self, "GJ", check_range("torsional_rigidity", self.GJ, "GJ"))
        object.__setattr__(self, "offset", check_range("overhang", self.offset, "offset"))

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
        object.__setattr__(self, "EI", check_range("member_EI", self.EI, "EI"))
        object.__setattr__(
            self,
            "mass_per_length",
            check_range("line_mass", self.mass_per_length, "mass_per_length"),  # fmt: skip
        )
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


@dataclass(frozen=True)
class Deck:
    """A slab-on-girder deck (module docstring): spans, slab, girders, edges, diaphragms, skew.

    Parameters
    ----------
    spans
        Span lengths along the girders [m]: one number for a simple span, a list for a deck
        continuous over its interior supports.
    width
        Width of the slab across the girders, edge to edge [m].
    thickness
        Slab thickness [m].
    E, poisson, density
        The slab's Young's modulus [Pa], Poisson's ratio and density [kg/m^3].
    girders
        :class:`Girders` or ``None`` (a bare slab).
    overhang
        Distance from the edge ``y = 0`` to girder 1 [m]; ``None``: the girders centred.
    edge_beams
        An :class:`EdgeBeam` on both sides, a pair ``(at y = 0, at y = width)`` (either may
        be ``None``), or ``None``.
    diaphragms
        :class:`Diaphragms` or ``None``.
    skew
        Angle between the support lines and the normal to the girders [degrees], 0 to 60.
    skew_hand
        ``"left"`` or ``"right"`` (module docstring); required when ``skew > 0``.
    damping_ratio
        Fraction of critical damping of every mode (the study: 1 %).
    sides
        ``"free"`` (a deck) or ``"simply supported"`` (a slab held along its sides too).
    resolution
        Ritz functions ``(along per span, across)``; ``None``: ``(12, 30)``, converged
        within 0.2 % in frequency and static deflection on the study's decks
        (``tests/decks/test_convergence.py``).

    Raises
    ------
    TypeError
        A value of the wrong type (text for a number, a float for a count).
    ValueError
        A value outside its range (:data:`vbi_lib.ranges.RANGES`: ``span``, ``deck_width``,
        ``slab_thickness``, ``youngs_modulus``, ``poisson``, ``material_density``,
        ``overhang``, ``skew``, ``bridge_damping_ratio``, ``ritz_functions``), girders that
        do not fit in the width, a girder whose composite ``EI`` is less than the slab's own
        rigidity over its tributary width, a skew without its hand, a diaphragm off the deck.

    Warns
    -----
    OutsideValidityWarning
        A value outside its intended (soft) range.

    Examples
    --------
    A square slab simply supported at two ends (Leissa 1969: lambda = omega a^2
    sqrt(rho h / D) = 9.631 for its first mode, nu = 0.3):

    >>> plate = Deck.plate(10.0, 10.0, 0.2, 30e9, 0.3, 2400.0)
    >>> rho_h, D = 2400.0 * 0.2, plate.flexural_rigidity
    >>> omega = 2 * math.pi * plate.frequencies_hz(1)[0]
    >>> round(float(omega * 10.0**2 * math.sqrt(rho_h / D)), 3)
    9.631
    """

    spans: tuple[float, ...] | float
    width: float
    thickness: float
    E: float
    poisson: float
    density: float
    girders: Girders | None = None
    overhang: float | None = None
    edge_beams: EdgeBeam | tuple[EdgeBeam | None, EdgeBeam | None] | None = None
    diaphragms: Diaphragms | None = None
    skew: float = 0.0
    skew_hand: str | None = None
    damping_ratio: float = 0.01
    sides: str = "free"
    resolution: tuple[int, int] | None = None

    def __post_init__(self) -> None:
        put = object.__setattr__
        spans = self.spans
        if isinstance(spans, str | bytes) or not isinstance(spans, Sequence | np.ndarray):
            spans = (spans,)
        spans = tuple(spans)
        if not spans:
            raise ValueError("spans=() must hold one or more span lengths [m]")
        check_range("n_spans", len(spans), "len(spans)", warn=False)
        put(
            self, "spans", tuple(check_range("span", s, f"spans[{i}]") for i, s in enumerate(spans))
        )
        put(self, "width", check_range("deck_width", self.width, "width"))
        put(self, "thickness", check_range("slab_thickness", self.thickness, "thickness"))
        put(self, "E", check_range("youngs_modulus", self.E, "E"))
        put(self, "poisson", check_range("poisson", self.poisson))
        put(self, "density", check_range("material_density", self.density, "density"))
        if self.girders is not None:
            check.instance("girders", self.girders, Girders, "a Girders (or None for a slab)")
        self._check_layout()
        self._check_edges()
        if self.diaphragms is not None:
            check.instance("diaphragms", self.diaphragms, Diaphragms, "a Diaphragms or None")
            length = sum(self.spans)
            for station in self.diaphragm_stations:
                if not 0.0 <= station <= length:
                    raise ValueError(
                        f"diaphragms.stations holds {station!r}, off the deck: stations must "
                        f"lie from 0 to {length:g} m along the girders"
                    )
        put(self, "skew", check_range("skew", self.skew))
        if self.skew > 0.0:
            if self.skew_hand is None:
                raise ValueError(
                    f"skew={self.skew!r} needs its hand: skew_hand='left' (left-forward: the "
                    "left end of each support line further along x) or 'right'"
                )
            check.choice("skew_hand", self.skew_hand, ("left", "right"))
        elif self.skew_hand is not None:
            check.choice("skew_hand", self.skew_hand, ("left", "right"))
            put(self, "skew_hand", None)
        zeta = check.damping_ratio("damping_ratio", self.damping_ratio)
        put(self, "damping_ratio", check_range("bridge_damping_ratio", zeta, "damping_ratio"))
        check.choice("sides", self.sides, ("free", "simply supported"))
        if self.resolution is not None:
            if isinstance(self.resolution, str | bytes) or len(self.resolution) != 2:
                raise ValueError(
                    f"resolution={self.resolution!r} must be (functions along per span, "
                    "functions across) or None"
                )
            along, across = (check.integer(f"resolution[{i}]", v) for i, v in
                             enumerate(self.resolution))  # fmt: skip
            for i, value in enumerate((along, across)):
                check_range("ritz_functions", value, f"resolution[{i}]", warn=False)
            put(self, "resolution", (along, across))
        for g, (line, width) in enumerate(
            zip(self.girder_line_rigidities, self.tributary_widths, strict=True)
        ):
            if line < 0.0:
                raise ValueError(
                    f"girder {g + 1}'s EI={self.girder_rigidities[g]:.4g} N m^2 must exceed the "
                    f"slab's own rigidity over its tributary width, D b = "
                    f"{self.flexural_rigidity * width:.4g} N m^2: give the composite rigidity "
                    "of the girder with its share of the slab"
                )

    def _check_layout(self) -> None:
        if self.girders is None:
            if self.overhang is not None:
                raise ValueError(f"overhang={self.overhang!r} needs girders: a bare slab has none")
            return
        between = (self.girders.count - 1) * self.girders.spacing
        if between > self.width:
            raise ValueError(
                f"{self.girders.count} girders {self.girders.spacing:g} m apart span "
                f"{between:g} m, more than width={self.width:g} m; widen the deck or space "
                "them closer"
            )
        if self.overhang is None:
            object.__setattr__(self, "overhang", 0.5 * (self.width - between))
        else:
            overhang = check_range("overhang", self.overhang)
            if overhang + between > self.width * (1 + 1e-12):
                raise ValueError(
                    f"overhang={overhang:g} m puts the last girder at {overhang + between:g} m, "
                    f"beyond the width {self.width:g} m"
                )
            object.__setattr__(self, "overhang", overhang)

    def _check_edges(self) -> None:
        edges = self.edge_beams
        if edges is None:
            return
        if isinstance(edges, EdgeBeam):
            edges = (edges, edges)
        if not isinstance(edges, tuple | list) or len(edges) != 2:
            raise TypeError(
                f"edge_beams={self.edge_beams!r} must be an EdgeBeam, a pair (at y = 0, at y = "
                "width) of EdgeBeam or None, or None"
            )
        for i, edge in enumerate(edges):
            if edge is not None:
                check.instance(f"edge_beams[{i}]", edge, EdgeBeam, "an EdgeBeam or None")
                if edge.offset > self.width:
                    raise ValueError(
                        f"edge_beams[{i}].offset={edge.offset:g} m lies beyond the width "
                        f"{self.width:g} m"
                    )
        object.__setattr__(self, "edge_beams", tuple(edges))

    # ------------------------------------------------------------------ constructors
    @classmethod
    def plate(
        cls,
        length: float,
        width: float,
        thickness: float,
        E: float,
        poisson: float,
        density: float,
        **options: object,
    ) -> Deck:
        """A bare slab simply supported at both ends and free along its sides.

        ``length`` along the supported edges' normal [m], ``width`` [m], ``thickness`` [m],
        ``E`` [Pa], ``poisson``, ``density`` [kg/m^3]; ``options`` are :class:`Deck`'s
        keywords (``skew``, ``skew_hand``, ``damping_ratio``, ``sides``, ``resolution``).
        A skewed plate is a parallelogram: its free sides are ``length`` long and
        ``width`` apart.
        """
        return cls((length,), width, thickness, E, poisson, density, **options)

    def scaled(self, stiffness: float = 1.0, mass: float = 1.0) -> Deck:
        """The same deck with every rigidity times ``stiffness`` and every mass times ``mass``.

        Mode shapes keep their form (divided by ``sqrt(mass)`` to stay mass-normalised),
        frequencies are multiplied by ``sqrt(stiffness / mass)`` and static deflections
        divided by ``stiffness``: the two scalars by which the study's beam is fitted to a
        path's ``K_mid`` and first frequency (:mod:`vbi_lib.decks.statics`).
        """
        s = check.positive("stiffness", stiffness)
        m = check.positive("mass", mass)
        girders = None
        if self.girders is not None:
            girders = Girders(
                self.girders.count,
                self.girders.spacing,
                tuple(s * v for v in self.girder_rigidities),
                tuple(m * v for v in self.girder_masses),
                tuple(s * v for v in self.girder_torsion),
            )
        edges = None
        if self.edge_beams is not None:
            edges = tuple(
                None if e is None else EdgeBeam(s * e.EI, m * e.mass_per_length, s * e.GJ, e.offset)
                for e in self.edge_beams
            )
        diaphragms = None
        if self.diaphragms is not None:
            d = self.diaphragms
            diaphragms = Diaphragms(s * d.EI, m * d.mass_per_length, d.stations)
        return replace(
            self,
            E=s * self.E,
            density=m * self.density,
            girders=girders,
            edge_beams=edges,
            diaphragms=diaphragms,
        )

    # ------------------------------------------------------------------ geometry
    @property
    def n_spans(self) -> int:
        """Number of spans."""
        return len(self.spans)

    @property
    def length(self) -> float:
        """Length along the girders, end support to end support [m]."""
        return float(self.supports[-1])

    @cached_property
    def supports(self) -> tuple[float, ...]:
        """Stations of the support lines along the girders [m], ``n_spans + 1``."""
        return tuple(float(s) for s in support_stations(self.spans))

    @property
    def midspans(self) -> tuple[float, ...]:
        """Stations of the midspans along the girders [m]."""
        s = self.supports
        return tuple(0.5 * (s[j] + s[j + 1]) for j in range(self.n_spans))

    @property
    def tangent(self) -> float:
        """``t`` of the oblique coordinates: ``+tan(skew)`` left-forward, ``-tan`` right."""
        t = math.tan(math.radians(self.skew))
        return -t if self.skew_hand == "right" else t

    @property
    def girder_positions(self) -> tuple[float, ...]:
        """``y`` of each girder [m], girder 1 first."""
        if self.girders is None:
            return ()
        return tuple(self.overhang + g * self.girders.spacing for g in range(self.girders.count))

    @property
    def tributary_widths(self) -> tuple[float, ...]:
        """Width of slab nearer each girder than any other [m] (to the edges for exterior ones)."""
        y = self.girder_positions
        if not y:
            return ()
        bounds = [0.0] + [0.5 * (a + b) for a, b in zip(y[:-1], y[1:], strict=True)]
        bounds.append(self.width)
        return tuple(bounds[g + 1] - bounds[g] for g in range(len(y)))

    def girder_y(self, girder: int) -> float:
        """``y`` of girder ``girder`` (1 = nearest the edge ``y = 0``) [m]."""
        count = 0 if self.girders is None else self.girders.count
        if count == 0:
            raise ValueError("this deck has no girders; give positions as (x, y) instead")
        girder = check.integer("girder", girder, low=1, high=count)
        return self.girder_positions[girder - 1]

    # ------------------------------------------------------------------ stiffness and mass
    @property
    def flexural_rigidity(self) -> float:
        """The slab's ``D = E h^3 / (12 (1 - nu^2))`` [N m]."""
        return self.E * self.thickness**3 / (12.0 * (1.0 - self.poisson**2))

    @property
    def slab_mass_per_area(self) -> float:
        """``rho h`` [kg/m^2]."""
        return self.density * self.thickness

    @property
    def girder_rigidities(self) -> tuple[float, ...]:
        """Composite ``EI`` of each girder with its tributary slab [N m^2]."""
        g = self.girders
        if g is None:
            return ()
        if g.section is None:
            return g.EI
        return tuple(
            g.section.composite(width, self.thickness, self.E) for width in self.tributary_widths
        )

    @property
    def girder_line_rigidities(self) -> tuple[float, ...]:
        """``EI - D b`` of each girder: what the line adds to the plate [N m^2]."""
        D = self.flexural_rigidity
        return tuple(
            ei - D * b for ei, b in zip(self.girder_rigidities, self.tributary_widths, strict=True)
        )

    @property
    def girder_masses(self) -> tuple[float, ...]:
        """Each girder's own mass per length [kg/m]."""
        g = self.girders
        if g is None:
            return ()
        if g.section is None:
            return g.mass_per_length
        return (g.section.mass_per_length,) * g.count

    @property
    def girder_torsion(self) -> tuple[float, ...]:
        """Each girder's ``GJ`` [N m^2]."""
        g = self.girders
        if g is None:
            return ()
        if g.section is None:
            return g.GJ
        return (g.section.torsional_rigidity,) * g.count

    def line_members(self) -> tuple[LineMember, ...]:
        """The girders and edge beams as lines ``y = const`` (rigidity net of the slab's)."""
        lines = [
            LineMember(y, ei, gj, m)
            for y, ei, gj, m in zip(
                self.girder_positions,
                self.girder_line_rigidities,
                self.girder_torsion,
                self.girder_masses,
                strict=True,
            )
        ]
        if self.edge_beams is not None:
            right, left = self.edge_beams
            if right is not None:
                lines.append(LineMember(right.offset, right.EI, right.GJ, right.mass_per_length))
            if left is not None:
                lines.append(
                    LineMember(self.width - left.offset, left.EI, left.GJ, left.mass_per_length)
                )
        return tuple(lines)

    @property
    def diaphragm_stations(self) -> tuple[float, ...]:
        """Stations of the diaphragms along the girders [m] (none without diaphragms)."""
        if self.diaphragms is None:
            return ()
        if self.diaphragms.stations == "midspans":
            return self.midspans
        return self.diaphragms.stations

    @property
    def diaphragm_extent(self) -> tuple[float, float]:
        """``(y_first, y_last)``: the diaphragms run between the exterior girders [m]."""
        y = self.girder_positions
        return (y[0], y[-1]) if len(y) > 1 else (0.0, self.width)

    @property
    def mass_per_length(self) -> float:
        """Mass of the deck per length along the girders, diaphragms left out [kg/m]."""
        total = self.slab_mass_per_area * self.width + sum(self.girder_masses)
        if self.edge_beams is not None:
            total += sum(e.mass_per_length for e in self.edge_beams if e is not None)
        return total

    @property
    def end_functions(self) -> int:
        """End functions at each end of a skewed deck (:mod:`vbi_lib.decks.basis`); 0 if square."""
        return DEFAULT_END_FUNCTIONS if self.skew > 0.0 else 0

    @property
    def functions(self) -> tuple[int, int]:
        """The Ritz functions used, ``(along, across)`` (along: all spans together)."""
        along, across = self.resolution or (DEFAULT_ALONG, DEFAULT_ACROSS)
        return along * self.n_spans, across

    # ------------------------------------------------------------------ modes and statics
    def modes(self, n: int | None = None) -> DeckModes:
        """The deck's first ``n`` modes (all the basis holds if ``None``): :class:`DeckModes`."""
        from .modes import deck_modes

        return deck_modes(self, n)

    def frequencies_hz(self, n: int) -> np.ndarray:
        """The first ``n`` natural frequencies [Hz], increasing."""
        return self.modes(n).frequencies_hz

    def first_frequency_hz(self) -> float:
        """The lowest natural frequency [Hz]."""
        return float(self.frequencies_hz(1)[0])

    def midspan_stiffness(self, path: WheelPath | float, girder: int, span: int = 1) -> float:
        """``K_mid`` [N/m]: twin half loads on ``path`` at midspan over the girder's deflection.

        See :func:`vbi_lib.decks.statics.midspan_stiffness`.
        """
        from .statics import midspan_stiffness

        return midspan_stiffness(self, path, girder, span)

    def __repr__(self) -> str:
        spans = " + ".join(f"{s:.2f}" for s in self.spans)
        parts = [f"spans {spans} m", f"width {self.width:.2f} m", f"slab {self.thickness:.3f} m"]
        if self.girders is not None:
            g = self.girders
            parts.append(
                f"{g.count} girder{'s' if g.count > 1 else ''}"
                + (f" at {g.spacing:.3f} m" if g.count > 1 else "")
            )
        if self.edge_beams is not None:
            parts.append("edge beams")
        if self.diaphragms is not None:
            parts.append(f"{len(self.diaphragm_stations)} diaphragm lines")
        if self.skew:
            parts.append(f"skew {self.skew:g} deg {self.skew_hand}-forward")
        if self.sides != "free":
            parts.append(f"sides {self.sides}")
        return f"Deck({', '.join(parts)}, zeta = {self.damping_ratio:.1%})"
