r"""A slab-on-girder deck: the bridge across its width, not reduced to one beam.

:class:`~vbi_lib.decks.deck.Deck` describes a deck as an engineer draws it: spans along the
girders (one simple span or several continuous ones), a slab of given width, thickness and
material, girders under it, barriers or edge beams along its sides, diaphragms across it and
a skew.  :meth:`~vbi_lib.decks.layout.DeckLayout.plate` is the bare slab.  Its modes
(:mod:`vbi_lib.decks.modes`) come from the Rayleigh-Ritz method of
:mod:`vbi_lib.decks.ritz`.

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

import numpy as np

from .. import _validation as check
from ..continuous_beams import support_stations
from ..ranges import check_range
from .members import Diaphragms, EdgeBeam, Girders, LineMember

__all__ = ["DEFAULT_ACROSS", "DEFAULT_ALONG", "DEFAULT_END_FUNCTIONS", "DeckLayout"]

#: Default Ritz functions along the girders, per span (beam modes of the continuous beam).
DEFAULT_ALONG = 12
#: Default Ritz functions across the girders (Legendre polynomials).
DEFAULT_ACROSS = 30
#: End functions at each end of a skewed deck (:mod:`vbi_lib.decks.basis`).
DEFAULT_END_FUNCTIONS = 1


@dataclass(frozen=True)
class DeckLayout:
    """What a deck is (spans, slab, girders, edges, diaphragms, skew), checked on creation.

    :class:`~vbi_lib.decks.deck.Deck` is this description with its modes and statics; its
    docstring gives the parameters.  The computing modules (:mod:`~vbi_lib.decks.ritz`,
    :mod:`~vbi_lib.decks.modes`, :mod:`~vbi_lib.decks.paths`, :mod:`~vbi_lib.decks.statics`)
    read a deck through this class, so that none of them imports the other way.
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
    ) -> DeckLayout:
        """A bare slab simply supported at both ends and free along its sides.

        ``length`` along the supported edges' normal [m], ``width`` [m], ``thickness`` [m],
        ``E`` [Pa], ``poisson``, ``density`` [kg/m^3]; ``options`` are the deck's keywords
        (``skew``, ``skew_hand``, ``damping_ratio``, ``sides``, ``resolution``;
        :class:`~vbi_lib.decks.deck.Deck`).
        A skewed plate is a parallelogram: its free sides are ``length`` long and
        ``width`` apart.
        """
        return cls((length,), width, thickness, E, poisson, density, **options)

    def scaled(self, stiffness: float = 1.0, mass: float = 1.0) -> DeckLayout:
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
        scaled = replace(
            self,
            E=s * self.E,
            density=m * self.density,
            girders=girders,
            edge_beams=edges,
            diaphragms=diaphragms,
        )
        # its modes follow from this deck's exactly (vbi_lib.decks.modes): no new eigenproblem
        object.__setattr__(scaled, "_scaled_from", (self, s, m))
        return scaled

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
