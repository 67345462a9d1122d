r"""The study's decks (Chapter 13, "Bridge Models"), drawn from its geometry, and their paths.

The study's finite-element decks were plate eccentric-beam models of real bridges.  What it
says of them, and what is taken here where it says nothing (marked *assumed*):

**40 ft** (Maryland structure 70042010): seven W30x108 rolled steel girders at 84 in, an
8.5 in slab, concrete barriers "modeled with a rectangular section (32"x19")", channel
diaphragms (15C33.9), a 15 degree skew raised to 16 in the models; first frequency 9.95 Hz
(one span) and 9.98 Hz (two).  Path 1 runs over the first interior girder (girder 2), path 2
16 ft from the exterior girder (girder 3 named, Table 2.13.7).

**100 ft** (Maryland structure 80053010): five AASHTO Type IV girders at 99 in, a 9.5 in
slab, cast-in-place diaphragms "modeled with a rectangular section (37"x9")" at the ends and
the middle of each span, "4' tall by 2' wide concrete barriers ... placed along either
side", no skew stated; first frequency 3.99 Hz.  Paths 4, 10.5 and 16.5 ft from the
exterior girder, on the girders Table 2.13.6 names: 1, 2, 3 (one span) and 2, 3, 3 (two
spans; the two-span table names girders 2 and 3 for the paths at 4 and 10.5 ft, not the
nearest ones, and it is followed as printed).

**140 ft**: "based on the geometry of the bridge presented in Part 1", which the seed does
not give: it has no deck here (:func:`study_deck` refuses it; the assessment keeps the
exact beam for it).

*Assumed* (the seed is silent): an overhang of half a girder spacing (so the exterior
girder's tributary width is an interior one's); slab concrete f'c = 4 ksi
(E = 57 000 sqrt(f'c) psi = 3605 ksi, ACI 318-19 19.2.2.1), Poisson's ratio 0.2, 150 pcf;
Type IV girders f'c = 5 ksi (4031 ksi), their torsion constant 1/3 sum b t^3 of the nominal
flanges and web; steel 29 000 ksi, 490 pcf, J of the W30x108 from AISC; the 40 ft deck's
diaphragms at its midspans (one line per span, its steel channel's own section); the
40 ft barriers acting with the exterior girder as one composite section, as the eccentric
beams of the study's model do (their share of that section's rigidity on the edge line);
the 100 ft barriers with their own section only (the seed gives their size, not that they
were modelled as members; ``barriers=`` changes either); no haunches.  Every girder is
composite with its tributary slab (:class:`~vbi_lib.decks.sections.GirderSection`).  These
fix the deck's *shape*; its rigidity and mass are then scaled to each row's ``K_mid`` and
``f1`` (:func:`~vbi_lib.decks.statics.fit_to_path`), and "f1" is the deck's lowest mode:
on the drawn 100 ft deck a torsional mode, 1.5 % below the first bending one.

Drawn, before any scaling, the 40 ft deck has K_mid 0.93 (path 1) and 0.96 (path 2) of
Table 2.13.7's and a first frequency of 10.38 Hz against 9.95; the 100 ft deck is softer,
K_mid 0.42-0.49 of Table 2.13.6's and 2.73 Hz against 3.99, and its exterior girder carries
path 1 with 0.65 of path 3's stiffness against the table's 0.75.  What the seed's decks had
that these lack is not known (composite barriers would raise the 100 ft deck to 3.48 Hz but
make its exterior girder the stiffest).

The default 40 ft deck is not skewed: the seed gives the angle (16 degrees) but not the hand,
which way the skew runs relative to the direction of travel.  ``skew_hand="left"`` or
``"right"`` draws it skewed.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

from .. import _validation as check
from .. import units as u
from ..bridges import Bridge, reference_beam
from .deck import Deck
from .members import Diaphragms, EdgeBeam, Girders
from .paths import WheelPath
from .sections import GirderSection, Part, composite_rigidity
from .statics import fit_to_path

__all__ = [
    "DEFAULT_BARRIERS",
    "STUDY_PATHS",
    "STUDY_SKEW",
    "StudyDeck",
    "StudyPath",
    "assessment_site",
    "study_deck",
    "study_site",
]

KSI = 1000 * u.psi
PCF = u.lbf / u.ft**3 / u.g  # lb/ft^3 of weight as a density [kg/m^3]

#: Skew of the study's 40 ft models (the bridge's 15 degrees "increased to 16 ... for ease of
#: modeling"); its hand is not given.
STUDY_SKEW = 16.0

_SLAB_E = 57000 * 4000**0.5 * u.psi  # 3605 ksi
_GIRDER_CONCRETE_E = 57000 * 5000**0.5 * u.psi  # 4031 ksi
_STEEL_E = 29000 * KSI
_STEEL = 490 * PCF
_CONCRETE = 150 * PCF
_POISSON = 0.2


@dataclass(frozen=True)
class StudyPath:
    """One of the study's paths: its distance from girder 1 and the girder Table 2.13.x names."""

    distance: float
    girder: int


#: (span ft, spans, path) -> the path: distance from the exterior girder [m], named girder.
STUDY_PATHS: dict[tuple[int, int, int], StudyPath] = {
    (40, 1, 1): StudyPath(84 * u.inch, 2),
    (40, 1, 2): StudyPath(16 * u.ft, 3),
    (40, 2, 1): StudyPath(84 * u.inch, 2),
    (40, 2, 2): StudyPath(16 * u.ft, 3),
    (100, 1, 1): StudyPath(4 * u.ft, 1),
    (100, 1, 2): StudyPath(10.5 * u.ft, 2),
    (100, 1, 3): StudyPath(16.5 * u.ft, 3),
    (100, 2, 1): StudyPath(4 * u.ft, 2),
    (100, 2, 2): StudyPath(10.5 * u.ft, 3),
    (100, 2, 3): StudyPath(16.5 * u.ft, 3),
}


def _w30x108() -> GirderSection:
    """AISC W30x108: 31.7 in^2, Ix 4470 in^4, d 29.8 in, J 4.99 in^4."""
    return GirderSection(
        31.7 * u.inch**2,
        4470 * u.inch**4,
        29.8 * u.inch,
        _STEEL_E,
        _STEEL,
        torsion_constant=4.99 * u.inch**4,
        shear_modulus=11200 * KSI,
    )


def _type_iv() -> GirderSection:
    """AASHTO Type IV: 789 in^2, 260 741 in^4, 54 in deep, centroid 24.73 in above the bottom."""
    flanges_and_web = (20 * 8**3 + 26 * 8**3 + 38 * 8**3) / 3.0  # 1/3 sum b t^3 [in^4]
    return GirderSection(
        789 * u.inch**2,
        260741 * u.inch**4,
        54 * u.inch,
        _GIRDER_CONCRETE_E,
        _CONCRETE,
        centroid=24.73 * u.inch,
        torsion_constant=flanges_and_web * u.inch**4,
        shear_modulus=_GIRDER_CONCRETE_E / (2 * (1 + _POISSON)),
    )


def _check_span(span_ft: object, n_spans: object) -> tuple[int, int]:
    n_spans = check.integer("n_spans", n_spans, low=1, high=2)
    span = check.number("span_ft", span_ft)
    if span == 140:
        raise ValueError(
            "span_ft=140: the seed does not give the 140 ft deck's geometry (only its K_mid "
            "and f1, Table 2.13.5); it stays a beam (vbi.reference_beam)"
        )
    if span not in (40, 100):
        raise ValueError(f"span_ft={span_ft!r} must be 40 or 100 (the study's decks)")
    return int(span), n_spans


#: How each deck's barriers act when ``barriers`` is not given (module docstring).
DEFAULT_BARRIERS = {40: "composite", 100: "own"}


@lru_cache(maxsize=16)
def study_deck(
    span_ft: int,
    n_spans: int,
    skew_hand: str | None = None,
    damping_ratio: float = 0.01,
    barriers: str | None = None,
) -> Deck:
    """The study's 40 ft or 100 ft deck as drawn (module docstring), one span or two.

    Parameters
    ----------
    span_ft
        40 or 100 (140 ft is refused: its geometry is not in the seed).
    n_spans
        1 or 2 equal continuous spans.
    skew_hand
        40 ft only: ``None`` (not skewed, the default), ``"left"`` or ``"right"`` (16 degrees
        with that hand, :mod:`vbi_lib.decks.deck`).
    damping_ratio
        Of every mode (the study: 1 %).
    barriers
        How the barriers act, which the seed does not say: ``"composite"`` (one section
        with the exterior girder and its slab, as the eccentric beams of the study's model),
        ``"own"`` (their own rectangle only) or ``None``: :data:`DEFAULT_BARRIERS`
        (composite on the 40 ft deck, whose barriers the seed says were "modeled with a
        rectangular section"; their own section on the 100 ft one).

    Examples
    --------
    >>> deck = study_deck(40, 1)
    >>> deck.girders.count, round(deck.width / u.ft, 2), round(deck.first_frequency_hz(), 2)
    (7, 49.0, 10.38)
    """
    span, n_spans = _check_span(span_ft, n_spans)
    if barriers is None:
        barriers = DEFAULT_BARRIERS[span]
    check.choice("barriers", barriers, ("composite", "own"))
    if span == 40:
        return _deck_40(n_spans, skew_hand, damping_ratio, barriers)
    if skew_hand is not None:
        raise ValueError(
            f"skew_hand={skew_hand!r}: the seed gives the 100 ft deck no skew; use None"
        )
    return _deck_100(n_spans, damping_ratio, barriers)


def _girders_and_barriers(
    section: GirderSection,
    count: int,
    spacing: float,
    slab: float,
    barrier: tuple[float, float],
    barriers: str,
) -> tuple[Girders, EdgeBeam]:
    """Composite girders (tributary slab) and the barriers on the edges, acting as asked."""
    overhang = 0.5 * spacing
    interior = section.composite(spacing, slab, _SLAB_E)
    exterior_width = 0.5 * spacing + overhang
    width, height = barrier
    if barriers == "composite":
        # exterior girder, its slab and the barrier bend as one section (eccentric beams)
        part = Part.rectangle(_SLAB_E, width, height, section.depth + section.haunch + slab)
        slab_part = Part.rectangle(_SLAB_E, exterior_width, slab, section.depth + section.haunch)
        whole, axis = composite_rigidity([section.part(), slab_part, part])
        share = part.E * (part.inertia + part.area * (part.height - axis) ** 2)
        exterior = whole - share
        edge = EdgeBeam(share, _CONCRETE * width * height, 0.0, 0.5 * width)
    else:
        exterior = section.composite(exterior_width, slab, _SLAB_E)
        edge = EdgeBeam.rectangle(width, height, _SLAB_E, _CONCRETE)
    rigidities = (exterior,) + (interior,) * (count - 2) + (exterior,)
    girders = Girders(count, spacing, rigidities, section.mass_per_length,
                      section.torsional_rigidity)  # fmt: skip
    return girders, edge


def _deck_40(n_spans: int, skew_hand: str | None, damping_ratio: float, barriers: str) -> Deck:
    spacing, count, slab = 84 * u.inch, 7, 8.5 * u.inch
    girders, edge = _girders_and_barriers(_w30x108(), count, spacing, slab,
                                          (19 * u.inch, 32 * u.inch), barriers)  # fmt: skip
    channel = Diaphragms(_STEEL_E * 315 * u.inch**4, 33.9 * u.lbf / u.ft / u.g)
    return _seed_deck(40 * u.ft, n_spans, count, spacing, slab, girders, edge, channel,
                      skew_hand, damping_ratio)  # fmt: skip


def _deck_100(n_spans: int, damping_ratio: float, barriers: str) -> Deck:
    spacing, count, slab = 99 * u.inch, 5, 9.5 * u.inch
    girders, edge = _girders_and_barriers(_type_iv(), count, spacing, slab,
                                          (24 * u.inch, 48 * u.inch), barriers)  # fmt: skip
    thick, deep = 9 * u.inch, 37 * u.inch
    diaphragms = Diaphragms(_SLAB_E * thick * deep**3 / 12.0, _CONCRETE * thick * deep)
    return _seed_deck(100 * u.ft, n_spans, count, spacing, slab, girders, edge, diaphragms,
                      None, damping_ratio)  # fmt: skip


def _seed_deck(span: float, n_spans: int, count: int, spacing: float, slab: float,
               girders: Girders, edge: EdgeBeam, diaphragms: Diaphragms,
               skew_hand: str | None, damping_ratio: float) -> Deck:  # fmt: skip
    """A deck of the seed: the overhang half a spacing, the slab's concrete, the skew if any."""
    overhang = 0.5 * spacing
    return Deck(
        (span,) * n_spans,
        (count - 1) * spacing + 2 * overhang,
        slab,
        _SLAB_E,
        _POISSON,
        _CONCRETE,
        girders=girders,
        overhang=overhang,
        edge_beams=edge,
        diaphragms=diaphragms,
        skew=STUDY_SKEW if skew_hand is not None else 0.0,
        skew_hand=skew_hand,
        damping_ratio=damping_ratio,
    )


@dataclass(frozen=True)
class StudyDeck:
    """One assessment row's bridge across its width: the fitted deck, its path and girder.

    Attributes
    ----------
    deck
        The study's deck fitted to the row's ``K_mid`` and ``f1``
        (:func:`~vbi_lib.decks.statics.fit_to_path`), or ``None`` where the seed gives no
        geometry (140 ft).
    path
        The row's wheel path (two wheels 6 ft apart on the path's line), or ``None``.
    girder
        The girder whose midspan deflection the study measured (Tables 2.13.5-2.13.7).
    beam
        The exact beam (:func:`vbi_lib.reference_beam`) where there is no deck, else ``None``.
    notes
        What the reader must know about this row's bridge.
    """

    deck: Deck | None
    path: WheelPath | None
    girder: int
    beam: Bridge | None = None
    notes: tuple[str, ...] = field(default=())

    @property
    def responses(self) -> tuple[tuple[float, float], ...]:
        """``(x, y)`` of the named girder's midspan on every span (none without a deck)."""
        if self.deck is None:
            return ()
        y = self.deck.girder_y(self.girder)
        return tuple((x, y) for x in self.deck.midspans)


def study_site(
    span_ft: float,
    n_spans: int,
    path: int,
    k_mid: float,
    first_frequency_hz: float,
    *,
    skew_hand: str | None = None,
    damping_ratio: float = 0.01,
    barriers: str | None = None,
) -> StudyDeck:
    """One assessment row's deck, path and girder: the drawn deck fitted to ``K_mid`` and ``f1``.

    Parameters
    ----------
    span_ft, n_spans, path
        The row's bridge and path (Table 2.13.8).
    k_mid
        The path's midspan stiffness [N/m].
    first_frequency_hz
        The deck's first frequency [Hz].
    skew_hand
        For the 40 ft deck: ``None`` (not skewed), ``"left"`` or ``"right"`` (16 degrees).
    damping_ratio
        Of every mode.
    barriers
        How the barriers act (:func:`study_deck`); ``None``: :data:`DEFAULT_BARRIERS`.

    Returns
    -------
    StudyDeck
        For 140 ft, no deck: the exact beam, and a note saying why.

    Raises
    ------
    ValueError
        A bridge or path the study does not have; ``K_mid`` or ``f1`` outside their ranges.
    """
    number = check.integer("path", path, low=1)
    span = check.number("span_ft", span_ft)
    n_spans = check.integer("n_spans", n_spans, low=1, high=2)
    if span == 140:
        if number != 1:
            raise ValueError(f"path={path!r}: the 140 ft bridges have one path, 1")
        beam = reference_beam(span * u.ft, n_spans, k_mid, first_frequency_hz, damping_ratio)
        note = (
            "the seed does not give the 140 ft deck's geometry (only K_mid and f1, Table "
            "2.13.5): this row stays the exact beam (vbi.reference_beam)"
        )
        return StudyDeck(None, None, 2, beam, (note,))
    span_int, n_spans = _check_span(span, n_spans)
    key = (span_int, n_spans, number)
    if key not in STUDY_PATHS:
        raise ValueError(
            f"path={path!r} is not a path of the study's {span_int} ft, {n_spans}-span deck; "
            f"it has paths {sorted(p for s, n, p in STUDY_PATHS if (s, n) == key[:2])}"
        )
    where = STUDY_PATHS[key]
    drawn = study_deck(span_int, n_spans, skew_hand, damping_ratio, barriers)
    wheel_path = WheelPath.from_girder(drawn, where.distance)
    fitted = fit_to_path(drawn, k_mid, first_frequency_hz, wheel_path, where.girder)
    notes = []
    if span_int == 40 and skew_hand is None:
        notes.append(
            "the 40 ft deck is drawn square: the study's models were skewed 16 degrees, but "
            "the seed does not say which way (skew_hand='left' or 'right' draws it skewed)"
        )
    return StudyDeck(fitted, wheel_path, where.girder, None, tuple(notes))


def assessment_site(row: object, skew_hand: str | None = None, damping_ratio: float = 0.01,
                    barriers: str | None = None) -> StudyDeck:  # fmt: skip
    """:func:`study_site` of a row of the study's assessment table (US customary columns).

    Reads ``span_ft``, ``n_spans``, ``path``, ``k_mid_lbf_per_in`` and ``bridge_f1_hz``;
    ``skew_hand`` applies to the 40 ft decks only (the others have no skew).
    """
    span = check.number("span_ft", row.span_ft)
    return study_site(
        span,
        int(row.n_spans),
        int(row.path),
        row.k_mid_lbf_per_in * u.lbf / u.inch,
        row.bridge_f1_hz,
        skew_hand=skew_hand if span == 40 else None,
        damping_ratio=damping_ratio,
        barriers=barriers,
    )
