r"""The Ritz functions of a deck: beam modes along its girders times polynomials across them.

The deck's deflection is sought as

.. math:: w(\xi, \eta) = \sum_{m=1}^{M} \sum_{q=0}^{Q-1} c_{mq}\, X_m(\xi)\, Y_q(\eta),

in **oblique coordinates** (Leissa, *Vibration of Plates*, 1969, ch. 6; the usual frame for
skew plates): :math:`\eta = y` across the deck, perpendicular to its girders, and
:math:`\xi = x - t\,y` along them, measured from the first support line, with
:math:`t = \pm\tan\theta` for a skew :math:`\theta`.  Every support line, skewed or not, is a
line :math:`\xi = \text{const}`, and the deck is the rectangle
:math:`0 \le \xi \le \sum L_j`, :math:`0 \le \eta \le B` in these coordinates.

* Along: :math:`X_m` are the exact free-vibration modes of a uniform beam continuous over the
  deck's spans (unit rigidity and mass; :mod:`vbi_lib.continuous_beams`).  Each vanishes on
  every support line, so the supports hold exactly; no moment is imposed there (a natural
  condition).  On one span they are :math:`\sqrt{2/L}\sin(m\pi\xi/L)`.
  Every beam mode has :math:`X'' = 0` at the end supports.  A square deck's slab has that
  too (no moment about the support line), but a skewed one does not: its moment vanishes
  about the *skewed* line, so :math:`w_{,\xi\xi} \ne 0` there.  Beam modes alone then
  converge slowly, so a skewed deck adds ``end_functions`` polynomials at each end,
  :math:`g_k = \sigma(1-\sigma)^2 P_k(2\sigma - 1)` in the first span
  (:math:`\sigma = \xi / L_1`) and their mirror images in the last, which vanish on every
  support, are C1 at the first interior one and have :math:`g_k'' \ne 0` at the end.
* Across: :math:`Y_q` are Legendre polynomials, orthonormal on :math:`[0, B]`: the sides
  are free (nothing is imposed).  With ``sides="simply supported"`` they are multiplied by
  :math:`(1 - u^2)`, :math:`u = 2\eta/B - 1`, and vanish on both sides.

Derivatives in the deck's Cartesian frame (:math:`x` along the girders, :math:`y` across)
follow from the chain rule: :math:`\partial_x = \partial_\xi` and
:math:`\partial_y = \partial_\eta - t\,\partial_\xi`.  The area element is
:math:`dx\,dy = d\xi\,d\eta`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property, lru_cache

import numpy as np
from numpy.polynomial import legendre

from ..continuous_beams import (
    mode_coefficients,
    natural_wavenumbers,
    shape_derivatives,
    support_stations,
)

__all__ = ["RitzBasis", "ritz_basis"]

_GAUSS_ALONG = np.polynomial.legendre.leggauss(12)


@dataclass(frozen=True, eq=False)
class RitzBasis:
    """The ``M x Q`` Ritz functions of a deck (module docstring); function ``m Q + q``.

    Attributes
    ----------
    spans
        Span lengths along the girders [m].
    width
        Width across the girders ``B`` [m].
    tangent
        ``t`` of the oblique coordinates, signed (``xi = x - t y``).
    along, across
        ``M`` (functions along: beam modes, then end functions) and ``Q`` (polynomials
        across).
    modes_along, end_functions
        How many of the ``M`` are beam modes, and how many end functions at each end.
    sides
        ``"free"`` or ``"simply supported"``.
    supports
        Support stations along the girders [m], ``(n_spans + 1,)``.
    wavenumber, coefficients
        The beam modes along (:func:`vbi_lib.continuous_beams.mode_coefficients`, unit
        mass per length).
    """

    spans: tuple[float, ...]
    width: float
    tangent: float
    along: int
    across: int
    sides: str
    modes_along: int
    end_functions: int
    supports: np.ndarray = field(repr=False)
    wavenumber: np.ndarray = field(repr=False)
    coefficients: np.ndarray = field(repr=False)
    legendre_coefficients: np.ndarray = field(repr=False)
    _grams: dict = field(default_factory=dict, repr=False)

    @property
    def size(self) -> int:
        """Number of Ritz functions ``M Q``."""
        return self.along * self.across

    @property
    def length(self) -> float:
        """Length of the deck along its girders ``sum L_j`` [m]."""
        return float(self.supports[-1])

    # ------------------------------------------------------------------ one direction
    def along_values(self, xi: np.ndarray, order: int = 0) -> np.ndarray:
        """``d^order X_m / dxi^order`` at ``xi`` [m], shape ``(n, M)``; zero off the deck."""
        xi = np.atleast_1d(np.asarray(xi, dtype=float))
        length = self.length
        on = (xi >= -1e-12 * length) & (xi <= length * (1.0 + 1e-12))
        out = np.zeros((xi.size, self.along))
        if on.any():
            x = np.clip(xi[on], 0.0, length)
            out[on, : self.modes_along] = shape_derivatives(
                x, self.supports, self.wavenumber, self.coefficients, order
            )
            if self.end_functions:
                out[on, self.modes_along :] = self._end_values(x, order)
        return out

    def _end_values(self, x: np.ndarray, order: int) -> np.ndarray:
        """The end functions (module docstring) and their derivatives at ``x`` on the deck."""
        first, last = float(self.supports[1]), float(self.supports[-2])
        span_1, span_n = first, self.length - last
        count = self.end_functions
        out = np.zeros((x.size, 2 * count))
        for end, (span, sigma, sign) in enumerate(
            ((span_1, x / span_1, 1.0), (span_n, (self.length - x) / span_n, -1.0))
        ):
            inside = (sigma >= 0.0) & (sigma <= 1.0)
            for k in range(count):
                # sigma (1 - sigma)^2 P_k(2 sigma - 1) as a power series in sigma
                legendre_k = np.polynomial.Polynomial(legendre.leg2poly(np.eye(k + 1)[k]))
                poly = np.polynomial.Polynomial([0.0, 1.0, -2.0, 1.0]) * legendre_k(
                    np.polynomial.Polynomial([-1.0, 2.0])
                )
                derived = poly.deriv(order) if order else poly
                value = derived(sigma[inside]) * (sign / span) ** order
                out[inside, end * count + k] = value
        return out

    def across_values(self, eta: np.ndarray, order: int = 0) -> np.ndarray:
        """``d^order Y_q / deta^order`` at ``eta`` [m], shape ``(n, Q)``."""
        eta = np.atleast_1d(np.asarray(eta, dtype=float))
        u = 2.0 * eta / self.width - 1.0
        coef = self.legendre_coefficients
        if order:
            coef = legendre.legder(coef, order, scl=2.0 / self.width, axis=0)
        return legendre.legvander(u, coef.shape[0] - 1) @ coef

    # ------------------------------------------------------------------ both
    def values(self, x: np.ndarray, y: np.ndarray, along: int = 0, across: int = 0) -> np.ndarray:
        """``d^along/dx^along d^across/dy^across`` of every function, shape ``(n, M Q)``.

        ``x`` is the oblique ``xi`` (along the girders from the first support line) and
        ``y`` is ``eta`` (across from the edge ``y = 0``); the derivatives are Cartesian:
        ``d/dx`` along a line ``y = const`` and ``d/dy`` at fixed Cartesian ``x``
        (``d/deta - t d/dxi``).  ``along + across <= 3``.
        """
        x = np.atleast_1d(np.asarray(x, dtype=float))
        y = np.atleast_1d(np.asarray(y, dtype=float))
        x, y = np.broadcast_arrays(x, y)
        x, y = x.ravel(), y.ravel()
        total = np.zeros((x.size, self.along, self.across))
        for j in range(across + 1):
            weight = math.comb(across, j) * (-self.tangent) ** j
            if weight == 0.0:
                continue
            xs = self.along_values(x, along + j)
            ys = self.across_values(y, across - j)
            total += weight * xs[:, :, None] * ys[:, None, :]
        return total.reshape(x.size, self.size)

    # ------------------------------------------------------------------ integrals
    @cached_property
    def _along_quadrature(self) -> tuple[np.ndarray, np.ndarray]:
        nodes, weights = _GAUSS_ALONG
        points, factors = [], []
        k_max = float(self.wavenumber.max())
        for a, b in zip(self.supports[:-1], self.supports[1:], strict=True):
            pieces = 2 * int(math.ceil(k_max * (b - a) / math.pi)) + 2
            edges = np.linspace(a, b, pieces + 1)
            half = 0.5 * np.diff(edges)
            middle = 0.5 * (edges[:-1] + edges[1:])
            points.append((middle[:, None] + half[:, None] * nodes[None, :]).ravel())
            factors.append((half[:, None] * weights[None, :]).ravel())
        return np.concatenate(points), np.concatenate(factors)

    def along_gram(self, a: int, c: int) -> np.ndarray:
        """``int X^(a) X^(c)^T dxi`` over the deck, ``(M, M)`` (computed once)."""
        if (a, c) not in self._grams:
            xi, weight = self._along_quadrature
            left = self.along_values(xi, a)
            right = left if a == c else self.along_values(xi, c)
            gram = (left * weight[:, None]).T @ right
            gram.setflags(write=False)
            self._grams[(a, c)] = gram
        return self._grams[(a, c)]

    def across_gram(
        self, b: int, d: int, low: float = 0.0, high: float | None = None
    ) -> np.ndarray:
        """``int Y^(b) Y^(d)^T deta`` over ``[low, high]`` (default the width), ``(Q, Q)``."""
        high = self.width if high is None else high
        degree = self.legendre_coefficients.shape[0]
        nodes, weights = np.polynomial.legendre.leggauss(degree + 2)
        eta = low + 0.5 * (high - low) * (nodes + 1.0)
        weight = 0.5 * (high - low) * weights
        left = self.across_values(eta, b)
        right = left if b == d else self.across_values(eta, d)
        return (left * weight[:, None]).T @ right


def _legendre_columns(across: int, width: float, sides: str) -> np.ndarray:
    """Legendre-series coefficients (in ``u = 2 eta / B - 1``) of each ``Y_q``, columns."""
    extra = 2 if sides == "simply supported" else 0
    coef = np.zeros((across + extra, across))
    for q in range(across):
        if sides == "simply supported":
            # (1 - u^2) P_q(u), normalised below by its own norm on [-1, 1]
            series = legendre.legmul([2.0 / 3.0, 0.0, -2.0 / 3.0], np.eye(q + 1)[q])
            coef[: series.size, q] = series
        else:
            coef[q, q] = 1.0
    # orthonormal on [0, B] for free sides: int P_q^2 du = 2 / (2q + 1), deta = B/2 du
    nodes, weights = np.polynomial.legendre.leggauss(across + extra + 2)
    values = legendre.legvander(nodes, coef.shape[0] - 1) @ coef
    norms = np.sqrt(0.5 * width * (weights[:, None] * values**2).sum(axis=0))
    return coef / norms[None, :]


@lru_cache(maxsize=64)
def ritz_basis(
    spans: tuple[float, ...],
    width: float,
    tangent: float,
    along: int,
    across: int,
    sides: str,
    end_functions: int = 0,
) -> RitzBasis:
    """The deck's Ritz functions (module docstring), cached by their description.

    ``along`` beam modes of the continuous beam over ``spans`` (all spans together),
    ``end_functions`` end functions at each end, and ``across`` polynomials over ``width``.
    """
    spans_array = np.asarray(spans, dtype=float)
    wavenumber = natural_wavenumbers(spans_array, along)
    coefficients = np.array([mode_coefficients(spans_array, k, 1.0) for k in wavenumber])
    basis = RitzBasis(
        spans=tuple(spans),
        width=float(width),
        tangent=float(tangent),
        along=int(along) + 2 * int(end_functions),
        across=int(across),
        sides=sides,
        modes_along=int(along),
        end_functions=int(end_functions),
        supports=support_stations(spans_array),
        wavenumber=wavenumber,
        coefficients=np.ascontiguousarray(coefficients),
        legendre_coefficients=_legendre_columns(across, width, sides),
    )
    for array in (
        basis.supports,
        basis.wavenumber,
        basis.coefficients,
        basis.legendre_coefficients,
    ):
        array.setflags(write=False)
    return basis
