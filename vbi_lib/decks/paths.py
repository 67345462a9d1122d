r"""Wheel paths on a deck, and the tables a modal crossing reads along them.

A vehicle crosses a deck along a straight line ``y = offset`` parallel to the girders.  Each
axle has two wheels ``track`` apart (6 ft by default, the study's twin loads), one on each
side of that line, and presses on the deck with one contact force shared equally by its
wheels: for the deck the axle is a load at the **mean of its wheels' shapes**,

.. math:: \bar\phi_n(s) = \tfrac12\left[\phi_n(x_1(s), y_1) + \phi_n(x_2(s), y_2)\right],

where ``s`` is the axle's travel coordinate: the distance travelled since the path's centre
line crossed the first support line it meets (``s = 0``).  On a skewed deck the two wheels
meet a support line at different ``s`` (at :math:`s = \pm t\,\text{track}/2`), so an axle is
partly on the deck for a short while at each end.  A wheel off the deck (on the approach)
carries nothing.

:meth:`vbi_lib.decks.modes.DeckModes.path_tables` gives, for N modes, everything a modal
crossing with the mode-acceleration correction needs (the lead's kernel reads a bridge as
data):

* ``omega`` and ``damping_ratio`` of each mode;
* along the path, at stations ``s``: :math:`\bar\phi_n` and :math:`d\bar\phi_n/ds`, for
  cubic Hermite interpolation (a station where a wheel crosses a support line, where the
  slope jumps, appears twice: the slope before it, then after);
* at each response point :math:`r`: :math:`\phi_n(r)`, the full-basis static flexibility
  :math:`G(r, s)` under a unit axle load at ``s``, and the residual
  :math:`G(r, s) - \sum_n \phi_n(r)\bar\phi_n(s)/\omega_n^2`, so that the displacement at
  :math:`r` (positive down) is
  :math:`u_r = -\sum_n \phi_n(r) q_n + \sum_a F_{c,a}\,[G - \sum_n\phi_n\bar\phi_n/\omega_n^2]`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .. import _validation as check
from .. import units as u
from .layout import DeckLayout

__all__ = ["DEFAULT_TRACK", "PathTables", "WheelPath"]

#: Distance between the two wheels of an axle: the study's twin loads, 6 ft [m].
DEFAULT_TRACK = 6 * u.ft


@dataclass(frozen=True)
class WheelPath:
    """A vehicle's line of travel on a deck: where its axles' wheels run.

    Parameters
    ----------
    offset
        ``y`` of the axles' centre line, from the deck's edge ``y = 0`` [m].
    track
        Distance between an axle's two wheels [m], centred on ``offset`` (default 6 ft);
        ``0``: one wheel on the line.
    direction
        ``+1``: along increasing ``x``; ``-1``: the other way.

    Raises
    ------
    TypeError, ValueError
        A value of the wrong type, a negative offset or track, a direction other than +-1.
    """

    offset: float
    track: float = DEFAULT_TRACK
    direction: int = 1

    def __post_init__(self) -> None:
        object.__setattr__(self, "offset", check.non_negative("offset", self.offset))
        object.__setattr__(self, "track", check.non_negative("track", self.track))
        direction = check.integer("direction", self.direction)
        if direction not in (1, -1):
            raise ValueError(f"direction={direction!r} must be +1 or -1")
        object.__setattr__(self, "direction", direction)

    @classmethod
    def from_girder(
        cls,
        deck: DeckLayout,
        distance: float = 0.0,
        girder: int = 1,
        *,
        track: float = DEFAULT_TRACK,
        direction: int = 1,
    ) -> WheelPath:
        """The path ``distance`` [m] from girder ``girder`` towards larger ``y`` (0: over it).

        The study's paths: "16 ft from the exterior girder" is
        ``WheelPath.from_girder(deck, 16 * u.ft)``.
        """
        return cls(deck.girder_y(girder) + check.finite("distance", distance), track, direction)

    @property
    def wheels(self) -> tuple[float, ...]:
        """``y`` of each wheel [m]: two, or one if ``track`` is 0."""
        if self.track == 0.0:
            return (self.offset,)
        half = 0.5 * self.track
        return (self.offset - half, self.offset + half)

    def check_on(self, deck: DeckLayout) -> None:
        """Raise ``ValueError`` unless every wheel lies on the deck's width."""
        for y in self.wheels:
            if not -1e-12 <= y <= deck.width * (1 + 1e-12):
                raise ValueError(
                    f"a wheel of the path at offset={self.offset:g} m with track="
                    f"{self.track:g} m runs at y={y:g} m, off the deck (0 to {deck.width:g} m)"
                )

    def wheel_x(self, deck: DeckLayout, s: np.ndarray) -> np.ndarray:
        """``x`` (along the girders, :mod:`vbi_lib.decks.deck`) of each wheel at travel ``s``.

        Shape ``(n_s, n_wheels)``: ``s - t (y_i - offset)`` one way, ``L - s - t (y_i -
        offset)`` the other.
        """
        s = np.atleast_1d(np.asarray(s, dtype=float))
        shift = deck.tangent * (np.array(self.wheels) - self.offset)
        if self.direction == 1:
            return s[:, None] - shift[None, :]
        return deck.length - s[:, None] - shift[None, :]

    def extent(self, deck: DeckLayout) -> tuple[float, float]:
        """``(entry, exit)``: travel ``s`` where the first wheel meets the deck, the last leaves."""
        shift = deck.tangent * (np.array(self.wheels) - self.offset)
        if self.direction == 1:
            on = shift
        else:
            on = -shift
        return float(on.min()), float(on.max() + deck.length)

    def crossings(self, deck: DeckLayout) -> np.ndarray:
        """Travel ``s`` where any wheel crosses any support line, sorted (slope jumps there)."""
        shift = deck.tangent * (np.array(self.wheels) - self.offset)
        supports = np.array(deck.supports)
        if self.direction == 1:
            points = supports[:, None] + shift[None, :]
        else:
            points = deck.length - supports[:, None] - shift[None, :]
        return np.unique(points.ravel())


@dataclass(frozen=True, eq=False)
class PathTables:
    """A modal crossing's view of a deck along one wheel path (module docstring).

    Attributes
    ----------
    path
        The wheel path.
    stations
        Travel coordinate ``s`` [m], non-decreasing, from ``entry`` to ``exit``; a station
        where a wheel crosses a support line appears twice (the slope jumps there).
    shape, slope
        ``phi_bar_n(s)`` [kg^-1/2] and ``d phi_bar_n / ds`` [kg^-1/2 / m] of the axle (the mean
        of its wheels), shape ``(n_s, N)``; at a repeated station the first row holds the
        slope before it and the second the slope after.
    omega, damping_ratio
        Each mode's circular frequency [rad/s] and damping ratio, shape ``(N,)``.
    responses
        The response points ``(x, y)`` [m], shape ``(n_r, 2)``.
    response_shape
        ``phi_n`` at each response point, shape ``(n_r, N)``.
    static_flexibility
        Full-basis deflection at each response point under a unit downward axle load at
        each station [m/N], downward positive, shape ``(n_r, n_s)``.
    residual_flexibility
        ``static_flexibility`` minus its N-mode part ``sum_n phi_n(r) phi_bar_n(s) /
        omega_n^2`` [m/N], shape ``(n_r, n_s)``.
    entry, exit
        Travel ``s`` where the axle's first wheel meets the deck and its last leaves [m].
    """

    path: WheelPath
    stations: np.ndarray = field(repr=False)
    shape: np.ndarray = field(repr=False)
    slope: np.ndarray = field(repr=False)
    omega: np.ndarray = field(repr=False)
    damping_ratio: np.ndarray = field(repr=False)
    responses: np.ndarray = field(repr=False)
    response_shape: np.ndarray = field(repr=False)
    static_flexibility: np.ndarray = field(repr=False)
    residual_flexibility: np.ndarray = field(repr=False)
    entry: float = 0.0
    exit: float = 0.0

    @property
    def modal_flexibility(self) -> np.ndarray:
        """The N-mode static flexibility, ``static - residual`` [m/N], ``(n_r, n_s)``."""
        return self.static_flexibility - self.residual_flexibility

    def interpolate(self, s: object) -> tuple[np.ndarray, np.ndarray]:
        """Shape and slope at travel ``s`` by cubic Hermite interpolation of the tables.

        Returns two arrays ``(n_s, N)``; zero outside ``[entry, exit]``.  (What a kernel
        does with the tables, here to check them against the exact shapes.)
        """
        s = np.atleast_1d(check.real_array("s", s)).ravel()
        stations = self.stations
        # the last station at or before s: at a repeated station, the row after the jump
        index = np.clip(np.searchsorted(stations, s, side="right") - 1, 0, stations.size - 2)
        shape = np.zeros((s.size, self.omega.size))
        slope = np.zeros_like(shape)
        for k, (value, i) in enumerate(zip(s, index, strict=True)):
            if value < stations[0] or value > stations[-1]:
                continue
            h = stations[i + 1] - stations[i]
            tau = (value - stations[i]) / h
            h00 = 2 * tau**3 - 3 * tau**2 + 1
            h10 = tau**3 - 2 * tau**2 + tau
            h01 = -2 * tau**3 + 3 * tau**2
            h11 = tau**3 - tau**2
            p0, p1 = self.shape[i], self.shape[i + 1]
            m0, m1 = self.slope[i], self.slope[i + 1]
            shape[k] = h00 * p0 + h10 * h * m0 + h01 * p1 + h11 * h * m1
            d00 = (6 * tau**2 - 6 * tau) / h
            d10 = 3 * tau**2 - 4 * tau + 1
            d01 = (-6 * tau**2 + 6 * tau) / h
            d11 = 3 * tau**2 - 2 * tau
            slope[k] = d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1
        return shape, slope

    def __repr__(self) -> str:
        return (
            f"PathTables(offset {self.path.offset:.3f} m, track {self.path.track:.3f} m, "
            f"direction {self.path.direction:+d}: {self.omega.size} modes, "
            f"{self.stations.size} stations from {self.entry:.3f} to {self.exit:.3f} m, "
            f"{self.responses.shape[0]} response points)"
        )
