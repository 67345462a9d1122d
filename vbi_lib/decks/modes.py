r"""A deck's modes and its static flexibility, from the Rayleigh-Ritz method.

The modes solve :math:`K c_n = \omega_n^2 M c_n` (:mod:`vbi_lib.decks.ritz`), normalised
:math:`c_m^T M c_n = \delta_{mn}`, so that the deck's deflection (positive up) is

.. math:: w(x, y, t) = \sum_n \phi_n(x, y)\, q_n(t), \qquad
    \int \mu\, \phi_m \phi_n \, dA + \sum_{lines}\int m\,\phi_m\phi_n\,dx = \delta_{mn},

with :math:`\phi_n = \sum_i c_{in}\Phi_i` [kg^-1/2], exactly as the beam's modes of
:mod:`vbi_lib.modes`.  By the Rayleigh-Ritz method each frequency is an upper bound of the
deck's, and falls as functions are added (``tests/decks/test_convergence.py``).

Static flexibility
------------------
The deflection (positive down) at a point :math:`r` under a unit downward load at :math:`a`
is, in the full basis, :math:`G(r, a) = \Phi(r)^T K^{-1} \Phi(a)`: the deck's own static
answer within its Ritz functions, every function included (Maxwell: :math:`G(r,a) = G(a,r)`).
With :math:`N` modes it is :math:`\sum_{n \le N} \phi_n(r)\phi_n(a)/\omega_n^2`; the
difference, the **residual flexibility**, is what the mode-acceleration method adds to an
:math:`N`-mode response (:mod:`vbi_lib.decks.paths`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np
import scipy.linalg

from .. import _validation as check
from ..ranges import RANGES
from .basis import RitzBasis, ritz_basis
from .layout import DeckLayout
from .paths import PathTables, WheelPath
from .ritz import stiffness_and_mass

__all__ = ["DEFAULT_MODE_RANGE", "DeckModes", "axle_shape", "deck_modes", "path_tables"]

#: ``deck.modes()`` without a count keeps every mode below this multiple of the first.
DEFAULT_MODE_RANGE = 4.0


@dataclass(frozen=True, eq=False)
class DeckModes:
    """The first N mass-normalised modes of a :class:`~vbi_lib.decks.deck.Deck`.

    Positions are ``(x, y)``: ``x`` along the girders from the first support line (along
    the line ``y = const``, so skew or not, a girder's midspan is ``x = L/2``) and ``y``
    across from the edge ``y = 0`` [m] (:mod:`vbi_lib.decks.deck`).  Off the deck along
    ``x`` (a wheel on the approach) every shape is 0.

    Attributes
    ----------
    deck
        The deck.
    basis
        Its Ritz functions (:class:`~vbi_lib.decks.basis.RitzBasis`).
    omega
        Circular frequencies [rad/s], increasing, shape ``(N,)``.
    vectors
        Ritz coefficients of each mode, shape ``(M Q, N)``.

    Examples
    --------
    >>> from vbi_lib.decks import Deck
    >>> modes = Deck.plate(10.0, 10.0, 0.2, 30e9, 0.3, 2400.0).modes(3)
    >>> (modes.frequencies_hz / modes.frequencies_hz[0]).round(3)
    array([1.   , 1.675, 3.813])
    """

    deck: DeckLayout
    basis: RitzBasis = field(repr=False)
    omega: np.ndarray
    vectors: np.ndarray = field(repr=False)
    _factor: Any = field(repr=False)

    @property
    def count(self) -> int:
        """Number of modes N."""
        return int(self.omega.size)

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Natural frequencies [Hz], shape ``(N,)``."""
        return self.omega / (2.0 * math.pi)

    @property
    def damping_ratios(self) -> np.ndarray:
        """Damping ratio of each mode (the deck's, the same for all), shape ``(N,)``."""
        return np.full(self.count, self.deck.damping_ratio)

    # ------------------------------------------------------------------ shapes
    def derivative(self, x: object, y: object, along: int = 0, across: int = 0) -> np.ndarray:
        """``d^along/dx^along d^across/dy^across phi_n`` at points, shape ``(n_points, N)``.

        ``d/dx`` is along the girders at fixed ``y`` (the direction of travel), ``d/dy``
        across them at fixed Cartesian ``x`` (square to the girders).  Units
        [kg^-1/2 m^-(along + across)].  ``along + across`` at most 2 (3 along alone).

        Raises
        ------
        ValueError
            Orders out of that range, a point not finite or off the deck across (``y``
            outside 0 to the width).
        """
        along = check.integer("along", along, low=0, high=3)
        across = check.integer("across", across, low=0, high=2)
        if along + across > 3 or (across and along + across > 2):
            raise ValueError(
                f"along={along} and across={across}: give at most second derivatives "
                "(third along alone)"
            )
        xs, ys = self._coordinates(x, y)
        return self.basis.values(xs, ys, along, across) @ self.vectors

    def shape(self, x: object, y: object) -> np.ndarray:
        """``phi_n(x, y)`` [kg^-1/2], shape ``(n_points, N)``."""
        return self.derivative(x, y)

    def slope(self, x: object, y: object) -> np.ndarray:
        """``d phi_n / dx`` along the girders [kg^-1/2 / m], shape ``(n_points, N)``."""
        return self.derivative(x, y, along=1)

    def curvature(self, x: object, y: object) -> np.ndarray:
        """``d^2 phi_n / dx^2`` along the girders [kg^-1/2 / m^2], shape ``(n_points, N)``."""
        return self.derivative(x, y, along=2)

    def _coordinates(self, x: object, y: object) -> tuple[np.ndarray, np.ndarray]:
        xs = np.atleast_1d(check.real_array("x", x))
        ys = np.atleast_1d(check.real_array("y", y))
        try:
            xs, ys = np.broadcast_arrays(xs, ys)
        except ValueError:
            raise ValueError(
                f"x (shape {xs.shape}) and y (shape {ys.shape}) must have the same shape or "
                "broadcast together"
            ) from None
        xs, ys = xs.ravel(), ys.ravel()
        if not (np.isfinite(xs).all() and np.isfinite(ys).all()):
            raise ValueError("x and y must be finite positions [m]")
        width = self.deck.width
        if (ys < -1e-9 * width).any() or (ys > width * (1 + 1e-9)).any():
            raise ValueError(
                f"y must lie on the deck, from 0 to its width {width:g} m; got {ys.min():g} "
                f"to {ys.max():g} m"
            )
        return xs, np.clip(ys, 0.0, width)

    # ------------------------------------------------------------------ statics
    def _basis_at(self, points: object, name: str) -> np.ndarray:
        array = check.real_array(name, points)
        if array.ndim == 1 and array.size == 2:
            array = array[None, :]
        if array.ndim != 2 or array.shape[1] != 2:
            raise ValueError(f"{name} must be (x, y) points, shape (n, 2); got {array.shape}")
        xs, ys = self._coordinates(array[:, 0], array[:, 1])
        return self.basis.values(xs, ys)

    def static_flexibility(self, loads: object, responses: object) -> np.ndarray:
        """Full-basis static deflection at each response under a unit load at each load [m/N].

        ``G[r, a] = Phi(r)^T K^-1 Phi(a)``, downward positive under a downward load: the
        deck's own exact static answer within its Ritz functions.  ``loads`` and
        ``responses`` are ``(x, y)`` points, shape ``(n, 2)``; a load off the deck along
        ``x`` gives 0.  Returns shape ``(n_responses, n_loads)``.
        """
        at_loads = self._basis_at(loads, "loads")
        at_responses = self._basis_at(responses, "responses")
        if at_responses.shape[0] <= at_loads.shape[0]:
            solved = scipy.linalg.cho_solve(self._factor, at_responses.T)
            return (at_loads @ solved).T
        solved = scipy.linalg.cho_solve(self._factor, at_loads.T)
        return at_responses @ solved

    def modal_flexibility(self, loads: object, responses: object) -> np.ndarray:
        """``sum_n phi_n(r) phi_n(a) / omega_n^2`` over these N modes [m/N], ``(n_r, n_a)``."""
        at_loads = self._basis_at(loads, "loads") @ self.vectors
        at_responses = self._basis_at(responses, "responses") @ self.vectors
        return (at_responses / self.omega**2) @ at_loads.T

    def residual_flexibility(self, loads: object, responses: object) -> np.ndarray:
        """Full-basis minus N-mode static flexibility [m/N], ``(n_responses, n_loads)``."""
        return self.static_flexibility(loads, responses) - self.modal_flexibility(loads, responses)

    def static_fraction(self, loads: object, responses: object) -> np.ndarray:
        """Share of the full static flexibility carried by each mode, ``(n_r, n_a, N)``."""
        at_loads = self._basis_at(loads, "loads") @ self.vectors
        at_responses = self._basis_at(responses, "responses") @ self.vectors
        full = self.static_flexibility(loads, responses)
        each = at_responses[:, None, :] * at_loads[None, :, :] / self.omega**2
        return each / full[:, :, None]

    # ------------------------------------------------------------------ paths
    def path_tables(
        self, path: WheelPath, responses: object, spacing: float | None = None
    ) -> PathTables:
        """What a modal crossing needs along ``path`` (:func:`vbi_lib.decks.modes.path_tables`)."""
        return path_tables(self, path, responses, spacing)

    # ------------------------------------------------------------------ output
    def plot(self, modes: int = 4, *, axes: object = None, resolution: int = 41) -> object:
        """Contours of the first ``modes`` mode shapes on the deck's plan; returns the axes.

        ``axes``: a sequence of ``modes`` matplotlib axes (a new figure if ``None``).
        Lengths in the display units (:mod:`vbi_lib.display`); girders dashed, supports
        solid.
        """
        import matplotlib.pyplot as plt

        from .. import display

        count = check.integer("modes", modes, low=1, high=self.count)
        if axes is None:
            _, axes = plt.subplots(1, count, figsize=(3.2 * count, 3.0), squeeze=False)
            axes = axes[0]
        axes = list(np.atleast_1d(axes))
        if len(axes) < count:
            raise ValueError(f"axes holds {len(axes)} axes; modes={count} needs as many")
        deck = self.deck
        xi = np.linspace(0.0, deck.length, resolution)
        eta = np.linspace(0.0, deck.width, resolution)
        grid_x, grid_y = np.meshgrid(xi, eta)
        values = self.shape(grid_x.ravel(), grid_y.ravel())
        t = deck.tangent
        plan_x = display.value(grid_x + t * grid_y, "length")
        plan_y = display.value(grid_y, "length")
        for n, ax in enumerate(axes[:count]):
            shape = values[:, n].reshape(grid_x.shape)
            level = np.abs(shape).max() or 1.0
            ax.contourf(plan_x, plan_y, shape / level, levels=np.linspace(-1, 1, 21), cmap="RdBu_r")
            for y in deck.girder_positions:
                xs = display.value(np.array([t * y, deck.length + t * y]), "length")
                ax.plot(xs, display.value(np.array([y, y]), "length"), "k--", lw=0.6)
            for s in deck.supports:
                xs = display.value(np.array([s, s + t * deck.width]), "length")
                ax.plot(xs, display.value(np.array([0.0, deck.width]), "length"), "k-", lw=1.2)
            ax.set_title(f"mode {n + 1}: {self.frequencies_hz[n]:.2f} Hz")
            ax.set_xlabel(display.label("x", "length"))
            ax.set_aspect("equal")
        axes[0].set_ylabel(display.label("y", "length"))
        return axes[:count]

    def __repr__(self) -> str:
        shown = ", ".join(f"{f:.2f}" for f in self.frequencies_hz[:6])
        more = ", ..." if self.count > 6 else ""
        along, across = self.basis.along, self.basis.across
        return (
            f"DeckModes({self.count} modes of {self.deck!r}: {shown}{more} Hz; Ritz "
            f"{along} x {across} functions)"
        )


@lru_cache(maxsize=16)
def _solve(deck: DeckLayout) -> tuple[RitzBasis, np.ndarray, np.ndarray, Any]:
    """Every mode the deck's basis holds (up to the ``modes`` limit), and K's Cholesky factor.

    A deck scaled from another (:meth:`~vbi_lib.decks.layout.DeckLayout.scaled`: rigidities
    times ``s``, masses times ``m``) has the other's modes exactly: ``omega sqrt(s / m)``,
    vectors over ``sqrt(m)``, ``K``'s factor times ``sqrt(s)``.
    """
    origin = getattr(deck, "_scaled_from", None)
    if origin is not None:
        base, s, m = origin
        basis, omega, vectors, (factor, lower) = _solve(base)
        omega, vectors = omega * math.sqrt(s / m), vectors / math.sqrt(m)
        for array in (omega, vectors):
            array.setflags(write=False)
        return basis, omega, vectors, (factor * math.sqrt(s), lower)
    along, across = deck.functions
    ends = deck.end_functions
    basis = ritz_basis(deck.spans, deck.width, deck.tangent, along, across, deck.sides, ends)
    stiffness, mass = stiffness_and_mass(deck, basis)
    keep = min(basis.size, int(RANGES["modes"].hard[1]))
    eigenvalues, vectors = scipy.linalg.eigh(stiffness, mass, subset_by_index=[0, keep - 1])
    if eigenvalues[0] <= 0.0:
        raise ValueError(
            f"{deck!r} has a mode of no stiffness (omega^2 = {eigenvalues[0]:.3g}); give it "
            "supports that hold it"
        )
    # sign: the largest value of each mode over a grid of the deck is positive
    grid = np.linspace(0.0, 1.0, 7)
    gx, gy = np.meshgrid(grid * deck.length, grid * deck.width)
    sample = basis.values(gx.ravel(), gy.ravel()) @ vectors
    pick = np.abs(sample).argmax(axis=0)
    vectors = vectors * np.sign(sample[pick, np.arange(vectors.shape[1])])
    factor = scipy.linalg.cho_factor(stiffness)
    omega = np.sqrt(eigenvalues)
    for array in (omega, vectors):
        array.setflags(write=False)
    return basis, omega, vectors, factor


def deck_modes(deck: DeckLayout, n: int | None = None) -> DeckModes:
    """The deck's first ``n`` modes by the Rayleigh-Ritz method (module docstring).

    Parameters
    ----------
    deck
        The deck.
    n
        Number of modes, 1 to 200 and at most the number of Ritz functions; ``None``: every
        mode below :data:`DEFAULT_MODE_RANGE` (4) times the first frequency.

    Returns
    -------
    DeckModes

    Raises
    ------
    TypeError, ValueError
        ``deck`` is not a :class:`~vbi_lib.decks.deck.Deck`; ``n`` not a whole number in range.
    """
    check.instance("deck", deck, DeckLayout, "a vbi.Deck")
    basis, omega, vectors, factor = _solve(deck)
    if n is None:
        count = max(1, int(np.count_nonzero(omega < DEFAULT_MODE_RANGE * omega[0])))
    else:
        count = check.integer("n", n, low=1, high=omega.size)
    return DeckModes(deck, basis, omega[:count], vectors[:, :count], factor)


def axle_shape(modes: DeckModes, path: WheelPath, s: object, order: int = 0) -> np.ndarray:
    """Mean of the wheels' ``d^order phi_n / ds^order`` at travel ``s``, shape ``(n_s, N)``.

    ``order`` 0 (shape [kg^-1/2]) or 1 (slope along travel [kg^-1/2 / m]).  At a station
    where a wheel crosses a support line the slope is the one on the far side (the support's
    own span convention, :mod:`vbi_lib.continuous_beams`).
    """
    order = check.integer("order", order, low=0, high=1)
    s = np.atleast_1d(check.real_array("s", s)).ravel()
    xs = path.wheel_x(modes.deck, s)
    total = np.zeros((s.size, modes.count))
    for i, y in enumerate(path.wheels):
        total += modes.derivative(xs[:, i], np.full(s.size, y), along=order)
    sign = float(path.direction) ** order
    return sign * total / len(path.wheels)


def path_tables(
    modes: DeckModes, path: WheelPath, responses: object, spacing: float | None = None
) -> PathTables:
    """:class:`~vbi_lib.decks.paths.PathTables` for ``path`` and ``responses`` on a deck's modes.

    Parameters
    ----------
    modes
        The deck's N modes (:meth:`vbi_lib.Deck.modes`).
    path
        The wheel path; every wheel must lie on the deck's width.
    responses
        Response points ``(x, y)`` [m], shape ``(n_r, 2)`` (a girder's midspan is
        ``(L/2, y_girder)``).
    spacing
        Largest distance between stations [m]; default an eighth of the shortest half
        wavelength of the Ritz functions along (cubic Hermite interpolation then errs by
        under 1e-4 of a shape's amplitude).

    Raises
    ------
    ValueError
        A wheel off the deck's width, a response point off the deck, a spacing <= 0.
    """
    deck = modes.deck
    check.instance("path", path, WheelPath, "a WheelPath")
    path.check_on(deck)
    if spacing is None:
        spacing = np.pi / float(modes.basis.wavenumber.max()) / 8.0
    spacing = check.positive("spacing", spacing)
    entry, exit_ = path.extent(deck)
    count = max(2, int(np.ceil((exit_ - entry) / spacing)) + 1)
    grid = np.linspace(entry, exit_, count)
    breaks = path.crossings(deck)
    breaks = breaks[(breaks > entry) & (breaks < exit_)]
    plain = np.setdiff1d(grid, breaks)
    stations = np.sort(np.concatenate([plain, breaks, breaks]))
    shape = axle_shape(modes, path, stations, 0)
    slope = axle_shape(modes, path, stations, 1)
    # one-sided slopes at each repeated station: before it, then after it
    nudge = 1e-9 * max(deck.length, 1.0)
    for b in breaks:
        first = int(np.searchsorted(stations, b, side="left"))
        slope[first] = axle_shape(modes, path, [b - nudge], 1)[0]
        slope[first + 1] = axle_shape(modes, path, [b + nudge], 1)[0]
    points = check.real_array("responses", responses)
    if points.ndim == 1 and points.size == 2:
        points = points[None, :]
    if points.ndim != 2 or points.shape[1] != 2:
        raise ValueError(f"responses must be (x, y) points, shape (n, 2); got {points.shape}")
    if (points[:, 0] < 0).any() or (points[:, 0] > deck.length * (1 + 1e-12)).any():
        raise ValueError(
            f"responses must lie on the deck: x from 0 to {deck.length:g} m; got "
            f"{points[:, 0].min():g} to {points[:, 0].max():g} m"
        )
    response_shape = modes.shape(points[:, 0], points[:, 1])
    xs = path.wheel_x(deck, stations)
    static = np.zeros((points.shape[0], stations.size))
    for i, y in enumerate(path.wheels):
        loads = np.column_stack([xs[:, i], np.full(stations.size, y)])
        static += modes.static_flexibility(loads, points)
    static /= len(path.wheels)
    modal = (response_shape / modes.omega**2) @ shape.T
    tables = PathTables(
        path=path,
        stations=stations,
        shape=shape,
        slope=slope,
        omega=np.array(modes.omega),
        damping_ratio=modes.damping_ratios,
        responses=points,
        response_shape=response_shape,
        static_flexibility=static,
        residual_flexibility=static - modal,
        entry=entry,
        exit=exit_,
    )
    for array in (tables.stations, tables.shape, tables.slope, tables.omega,
                  tables.damping_ratio, tables.responses, tables.response_shape,
                  tables.static_flexibility, tables.residual_flexibility):  # fmt: skip
        array.setflags(write=False)
    return tables
