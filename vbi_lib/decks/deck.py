r"""A slab-on-girder deck with its modes and statics: :class:`Deck`, exported as ``vbi.Deck``.

The description (what a deck is, its coordinates and the skew's hand) is
:class:`~vbi_lib.decks.layout.DeckLayout`; :class:`Deck` adds what is computed from it.
"""

from __future__ import annotations

import numpy as np

from .layout import DeckLayout
from .modes import DeckModes, deck_modes
from .paths import WheelPath
from .statics import midspan_stiffness

__all__ = ["Deck"]


class Deck(DeckLayout):
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
        :class:`~vbi_lib.decks.members.Girders` or ``None`` (a bare slab).
    overhang
        Distance from the edge ``y = 0`` to girder 1 [m]; ``None``: the girders centred.
    edge_beams
        An :class:`~vbi_lib.decks.members.EdgeBeam` on both sides, a pair ``(at y = 0, at
        y = width)`` (either may be ``None``), or ``None``.
    diaphragms
        :class:`~vbi_lib.decks.members.Diaphragms` or ``None``.
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

    >>> import math
    >>> plate = Deck.plate(10.0, 10.0, 0.2, 30e9, 0.3, 2400.0)
    >>> rho_h, D = 2400.0 * 0.2, plate.flexural_rigidity
    >>> omega = 2 * math.pi * plate.frequencies_hz(1)[0]
    >>> round(float(omega * 10.0**2 * math.sqrt(rho_h / D)), 3)
    9.631
    """

    def modes(self, n: int | None = None) -> DeckModes:
        """The deck's first ``n`` modes: :func:`vbi_lib.decks.modes.deck_modes`."""
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
        return midspan_stiffness(self, path, girder, span)
