"""Decks across their width: slab, girders, edge beams, diaphragms and skew (issue 26).

A beam (:class:`vbi_lib.Bridge`) lumps a bridge's width into one line.  A
:class:`~vbi_lib.decks.deck.Deck` keeps it: a Kirchhoff slab on line girders, whose modes
come from the Rayleigh-Ritz method (:mod:`~vbi_lib.decks.ritz`), with shapes, slopes and
static flexibility anywhere on the deck (:mod:`~vbi_lib.decks.modes`), the tables a modal
crossing needs along a wheel path (:mod:`~vbi_lib.decks.paths`), the statics of the study's
twin loads (:mod:`~vbi_lib.decks.statics`) and the study's own decks
(:mod:`~vbi_lib.decks.study`).
"""

from .deck import Deck
from .layout import DeckLayout
from .members import Diaphragms, EdgeBeam, Girders
from .modes import DeckModes, deck_modes, path_tables
from .paths import PathTables, WheelPath
from .sections import GirderSection, Part, composite_rigidity
from .statics import axle_deflection, fit_to_path, midspan_stiffness

__all__ = [
    "Deck",
    "DeckLayout",
    "DeckModes",
    "Diaphragms",
    "EdgeBeam",
    "GirderSection",
    "Girders",
    "Part",
    "PathTables",
    "WheelPath",
    "axle_deflection",
    "composite_rigidity",
    "deck_modes",
    "fit_to_path",
    "midspan_stiffness",
    "path_tables",
]
