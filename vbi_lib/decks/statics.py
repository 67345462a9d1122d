r"""A deck's statics under the study's twin loads, and a deck fitted to a path's K_mid and f1.

The study measured each path's stiffness on its finite-element decks as "the midspan
displacements of the girder closest to each path due to twin point loads totaling 1 lb.,
spaced 6' apart at midspan on the vehicle path" (Tables 2.13.5-2.13.7):

.. math:: K_{mid} = 1 \big/ \tfrac12\left[G(r, a_1) + G(r, a_2)\right],

with :math:`a_{1,2}` the two loads, 3 ft either side of the path at its midspan, :math:`r`
the named girder's midspan and :math:`G` the deck's full-basis static flexibility
(:meth:`vbi_lib.decks.modes.DeckModes.static_flexibility`).

The study then fitted its beam to each path with two numbers, :math:`EI` from
:math:`K_{mid}` and the mass from :math:`f_1` (equations 82-84).  :func:`fit_to_path`
fits a deck the same way with two scalars: every rigidity times :math:`s_k` and every mass
times :math:`s_m`, so that the deck's own :math:`K_{mid}` and first frequency are the row's,

.. math:: s_k = K_{mid} / K^{(0)}_{mid}, \qquad s_m = s_k \left(f^{(0)}_1 / f_1\right)^2,

where :math:`K^{(0)}_{mid}` and :math:`f^{(0)}_1` are the deck's as drawn.  The shapes of its
modes, and so its transverse distribution, are the drawn deck's: nothing else is fitted.
"""

from __future__ import annotations

import numpy as np

from .. import _validation as check
from ..ranges import check_range
from .layout import DeckLayout
from .modes import deck_modes
from .paths import WheelPath

__all__ = ["axle_deflection", "fit_to_path", "midspan_stiffness"]


def _path(deck: DeckLayout, path: WheelPath | float) -> WheelPath:
    if not isinstance(path, WheelPath):
        path = WheelPath(check.finite("path", path))
    path.check_on(deck)
    return path


def axle_deflection(
    deck: DeckLayout, path: WheelPath | float, station: float, responses: object
) -> np.ndarray:
    """Static deflection [m/N] at ``responses`` under a unit axle load at travel ``station``.

    The load is shared equally by the path's wheels (two, ``track`` apart: the study's
    twin loads).  ``path`` is a :class:`~vbi_lib.decks.paths.WheelPath` or its offset
    ``y`` [m] (then with the default 6 ft track).  Downward positive; shape ``(n_r,)``.
    """
    path = _path(deck, path)
    station = check.finite("station", station)
    modes = deck_modes(deck, 1)
    xs = path.wheel_x(deck, [station])[0]
    loads = np.column_stack([xs, path.wheels])
    return modes.static_flexibility(loads, responses).mean(axis=1)


def midspan_stiffness(
    deck: DeckLayout, path: WheelPath | float, girder: int, span: int = 1
) -> float:
    """The study's ``K_mid`` [N/m]: twin loads at midspan of ``span`` on ``path``, at ``girder``.

    Load (1 N in all, halved between the wheels) over the deflection of girder ``girder``
    at the midspan of span ``span`` (both counted from 1), the loads at the midspan of the
    same span on the path.

    Raises
    ------
    ValueError
        A girder or span that does not exist, a wheel off the deck.

    Examples
    --------
    One girder under a thin slab is nearly a beam: ``48 EI / L^3`` with the load at
    midspan (``track=0``: one load on the girder):

    >>> from vbi_lib.decks import Deck, Girders, WheelPath
    >>> deck = Deck(20.0, 2.0, 0.1, 1e9, 0.3, 300.0, girders=Girders(1, EI=1e10,
    ...             mass_per_length=5000.0))
    >>> k = midspan_stiffness(deck, WheelPath(1.0, track=0.0), girder=1)
    >>> round(k / (48 * 1e10 / 20.0**3), 3)
    1.0
    """
    span = check.integer("span", span, low=1, high=deck.n_spans)
    path = _path(deck, path)
    station = deck.midspans[span - 1]
    if path.direction == -1:
        station = deck.length - station
    response = [(deck.midspans[span - 1], deck.girder_y(girder))]
    return 1.0 / float(axle_deflection(deck, path, station, response)[0])


def fit_to_path(
    deck: DeckLayout,
    k_mid: float,
    first_frequency_hz: float,
    path: WheelPath | float,
    girder: int,
    span: int = 1,
) -> DeckLayout:
    """The deck with every rigidity and mass scaled so that its ``K_mid`` and f1 are these.

    Two scalars (module docstring), as the study's beam is fitted (82)-(84).

    Parameters
    ----------
    deck
        The deck as drawn (geometry and materials).
    k_mid
        The path's midspan stiffness [N/m] (:func:`midspan_stiffness`'s definition).
    first_frequency_hz
        The deck's first natural frequency [Hz].
    path, girder, span
        Where ``k_mid`` was measured.

    Returns
    -------
    Deck
        :meth:`~vbi_lib.decks.layout.DeckLayout.scaled` by ``s_k`` and ``s_m``.

    Raises
    ------
    ValueError
        ``k_mid`` or ``first_frequency_hz`` outside their ranges (``k_mid``,
        ``bridge_frequency``), or a path, girder or span that does not exist.
    """
    k_mid = check_range("k_mid", k_mid)
    frequency = check_range("bridge_frequency", first_frequency_hz, "first_frequency_hz")
    drawn = midspan_stiffness(deck, path, girder, span)
    stiffness = k_mid / drawn
    mass = stiffness * (deck_modes(deck, 1).frequencies_hz[0] / frequency) ** 2
    return deck.scaled(stiffness, mass)
