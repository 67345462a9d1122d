r"""Exact free vibration of a uniform beam continuous over pinned supports (any spans).

The beam has spans :math:`L_1, \dots, L_N` of one flexural rigidity :math:`EI` and one mass
per length :math:`\bar m`, a support under every span end (no deflection there) and pinned
ends (no moment).  Within span :math:`j`, with :math:`s \in [0, L_j]` measured from its left
support, a mode of wavenumber :math:`k` (:math:`\omega = k^2 \sqrt{EI/\bar m}`) is

.. math:: \phi_j(s) = a_j \sin ks + b_j \cos ks + c_j e^{-ks} + d_j e^{-k(L_j - s)},

the usual :math:`\sin, \cos, \sinh, \cosh` solution written with decaying exponentials, so
that no term grows with :math:`kL` and high modes are computed without loss of precision.
The :math:`4N` coefficients satisfy :math:`4N` conditions: zero deflection at both ends of
every span, zero moment at the two ends of the beam, and continuous slope and moment over
every interior support.  The natural wavenumbers are the zeros of the determinant of those
conditions.

Finding every root
------------------
Two close roots can hide from a scan of the determinant, so the roots are *counted* first,
with the Wittrick-Williams algorithm (Wittrick & Williams 1971, *Q. J. Mech. Appl. Math.*
24, 263-284): the number of natural frequencies below :math:`\omega` is

.. math:: J(\omega) = \sum_j J_0^{(j)}(\omega) + s\{K(\omega)\},

where :math:`K` is the dynamic stiffness matrix relating the moments to the rotations at the
supports (each span contributes :math:`\tfrac{EI}{L}\begin{bmatrix}F & G\\ G & F\end{bmatrix}`
with :math:`\nu = kL`, :math:`F = \nu(\cosh\nu\sin\nu - \sinh\nu\cos\nu)/(1 - \cos\nu\cosh\nu)`
and :math:`G = \nu(\sinh\nu - \sin\nu)/(1 - \cos\nu\cosh\nu)`, which tend to the static 4 and
2), :math:`s\{K\}` is the number of its negative eigenvalues (counted from the pivots of its
:math:`LDL^T` factorisation) and :math:`J_0^{(j)}` the number of natural frequencies of span
:math:`j` clamped at both ends below :math:`\omega`.  Bisection on :math:`J` isolates each root
in an interval holding it alone; Brent's method on the determinant then refines it to
machine precision.  Every root is found, in order, and none twice.

Mass normalisation, :math:`\int_0^{\sum L_j} \bar m \phi^2 dx = 1`, is by Gauss-Legendre
quadrature in pieces shorter than a quarter wavelength (exact to rounding).  The sign of each
mode makes its slope at the start of the beam positive.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from scipy.optimize import brentq

from . import _validation as check

__all__ = [
    "clamped_count",
    "count_below",
    "mode_coefficients",
    "natural_wavenumbers",
    "shape_derivatives",
    "support_stations",
]


def _spans_array(spans: object) -> np.ndarray:
    array = np.asarray(spans, dtype=float)
    if array.ndim != 1 or array.size < 1 or not np.isfinite(array).all() or (array <= 0).any():
        raise ValueError(f"spans={spans!r} must be one or more finite span lengths > 0 [m]")
    return array


def support_stations(spans: object) -> np.ndarray:
    """Stations of the supports from the start [m]: ``0, L_1, L_1 + L_2, ...``.

    Equal spans give ``j L`` exactly; others the correctly rounded partial sums.

    >>> support_stations([20.0, 30.0, 25.0]).tolist()
    [0.0, 20.0, 50.0, 75.0]
    """
    spans = _spans_array(spans)
    if (spans == spans[0]).all():
        return spans[0] * np.arange(spans.size + 1)
    return np.array([0.0] + [math.fsum(spans[: j + 1]) for j in range(spans.size)])


# ---------------------------------------------------------------------------- conditions
def _basis(k: float, s: float, length: float, order: int) -> np.ndarray:
    """``d^order/ds^order`` of the four basis functions at ``s``, divided by ``k^order``."""
    sn, cs = math.sin(k * s), math.cos(k * s)
    e0, e1 = math.exp(-k * s), math.exp(-k * (length - s))
    table = (
        (sn, cs, e0, e1),
        (cs, -sn, -e0, e1),
        (-sn, -cs, e0, e1),
        (-cs, sn, -e0, e1),
    )
    return np.array(table[order])


def boundary_matrix(k: float, spans: np.ndarray) -> np.ndarray:
    """The ``4N x 4N`` matrix of the support conditions at wavenumber ``k`` (rows scaled by k).

    Columns ``4j .. 4j + 3`` hold span ``j``'s ``(a, b, c, d)``.
    """
    n = spans.size
    matrix = np.zeros((4 * n, 4 * n))
    row = 0
    matrix[row, 0:4] = _basis(k, 0.0, spans[0], 2)  # no moment at the start
    row += 1
    for j, length in enumerate(spans):
        columns = slice(4 * j, 4 * j + 4)
        matrix[row, columns] = _basis(k, 0.0, length, 0)  # no deflection at the left support
        matrix[row + 1, columns] = _basis(k, length, length, 0)  # ... and at the right one
        row += 2
        if j + 1 < n:
            following = slice(4 * j + 4, 4 * j + 8)
            for order in (1, 2):  # slope and moment continuous over the support
                matrix[row, columns] = _basis(k, length, length, order)
                matrix[row, following] = -_basis(k, 0.0, spans[j + 1], order)
                row += 1
    matrix[row, 4 * n - 4 :] = _basis(k, spans[-1], spans[-1], 2)  # no moment at the end
    return matrix


def _determinant(k: float, spans: np.ndarray) -> float:
    return float(np.linalg.det(boundary_matrix(k, spans)))


# ---------------------------------------------------------------------------- counting
def clamped_count(nu: float) -> int:
    """Natural frequencies of a span clamped at both ends below ``nu = k L`` (``J_0``).

    ``i - (1 - (-1)^i sgn(1 - cos nu cosh nu)) / 2`` with ``i = floor(nu / pi)``; the roots
    of ``cos nu cosh nu = 1`` are 4.7300, 7.8532, 10.9956, ...

    >>> [clamped_count(nu) for nu in (4.72, 4.74, 7.86, 11.0)]
    [0, 1, 2, 3]
    """
    i = int(math.floor(nu / math.pi))
    # sgn(1 - cos nu cosh nu) = sgn(sech nu - cos nu), without overflow
    sign = 1.0 if _sech(nu) - math.cos(nu) > 0 else -1.0
    return int(i - (1 - (-1) ** i * sign) // 2)


def _sech(nu: float) -> float:
    e = math.exp(-nu)
    return 2.0 * e / (1.0 + e * e)


def _rotation_stiffness(nu: float) -> tuple[float, float]:
    """``F`` and ``G`` of a span with fixed ends (rotations free), times ``L / EI``."""
    if nu < 0.05:  # near the static limit: series to O(nu^4), no cancellation
        return 4.0 - nu**4 / 105.0, 2.0 + nu**4 / 140.0
    sech, tanh = _sech(nu), math.tanh(nu)
    denominator = sech - math.cos(nu)  # (1 - cos nu cosh nu) / cosh nu
    f = nu * (math.sin(nu) - tanh * math.cos(nu)) / denominator
    g = nu * (tanh - math.sin(nu) * sech) / denominator
    return f, g


def count_below(k: float, spans: object) -> int:
    """Number of natural wavenumbers of the continuous beam below ``k`` (Wittrick-Williams).

    Parameters
    ----------
    k
        Wavenumber [1/m], ``omega = k^2 sqrt(EI / mbar)``.
    spans
        Span lengths [m].

    Examples
    --------
    A simple span's wavenumbers are ``n pi / L``:

    >>> count_below(3.5 * math.pi / 10.0, [10.0])
    3
    """
    spans = _spans_array(spans)
    n = spans.size
    diagonal = np.zeros(n + 1)
    off = np.zeros(n)
    total = 0
    for j, length in enumerate(spans):
        nu = k * length
        f, g = _rotation_stiffness(nu)
        diagonal[j] += f / length
        diagonal[j + 1] += f / length
        off[j] = g / length
        total += clamped_count(nu)
    # negative pivots of the LDL^T factorisation of the tridiagonal K (Sturm count)
    pivot = diagonal[0]
    negative = int(pivot < 0)
    for i in range(1, n + 1):
        if pivot == 0.0:
            pivot = 1e-300
        pivot = diagonal[i] - off[i - 1] ** 2 / pivot
        negative += int(pivot < 0)
    return total + negative


# ---------------------------------------------------------------------------- roots
@lru_cache(maxsize=256)
def _wavenumbers(spans: tuple[float, ...], count: int) -> tuple[float, ...]:
    array = np.array(spans)
    longest = float(array.max())
    # upper bound: about sum(k L_j / pi) roots lie below k
    high = math.pi * (count + 1) / float(array.sum()) + math.pi / longest
    while count_below(high, array) < count:
        high *= 1.5
    roots: list[float] = []
    low = 0.0
    for n in range(1, count + 1):
        lo, hi = low, high
        below_lo, below_hi = count_below(lo, array) if lo > 0 else 0, count_below(hi, array)
        while not (below_lo == n - 1 and below_hi == n):
            if hi - lo <= 1e-14 * hi:  # a repeated root: both copies lie here
                break
            mid = 0.5 * (lo + hi)
            c = count_below(mid, array)
            if c >= n:
                hi, below_hi = mid, c
            else:
                lo, below_lo = mid, c
        f_lo, f_hi = _determinant(lo, array), _determinant(hi, array)
        if below_lo == n - 1 and below_hi == n and f_lo * f_hi < 0:
            root = brentq(_determinant, lo, hi, args=(array,), xtol=1e-15 * hi, rtol=1e-15)
        else:  # no sign change to follow: bisect on the count to rounding
            while hi - lo > 4e-16 * hi:
                mid = 0.5 * (lo + hi)
                if count_below(mid, array) >= n:
                    hi = mid
                else:
                    lo = mid
            root = 0.5 * (lo + hi)
        roots.append(root)
        low = hi if below_hi == n else root
    return tuple(roots)


def natural_wavenumbers(spans: object, count: int) -> np.ndarray:
    """The first ``count`` natural wavenumbers ``k_n`` [1/m] of the continuous beam, increasing.

    ``omega_n = k_n^2 sqrt(EI / mbar)``.  Roots are counted (Wittrick-Williams) and refined
    with Brent's method on the determinant of the support conditions.

    Examples
    --------
    Three equal spans: 1, 1.2815, 1.8713 and 4 times the simple span's first frequency
    (Blevins, *Formulas for Natural Frequency and Mode Shape*, continuous beams):

    >>> k = natural_wavenumbers([1.0, 1.0, 1.0], 4)
    >>> ((k / math.pi) ** 2).round(4)
    array([1.    , 1.2815, 1.8713, 4.    ])
    """
    spans = _spans_array(spans)
    count = check.integer("count", count, low=1)
    return np.array(_wavenumbers(tuple(float(s) for s in spans), int(count)))


# ---------------------------------------------------------------------------- shapes
def mode_coefficients(spans: object, k: float, mass_per_length: float) -> np.ndarray:
    """Coefficients ``(N, 4)`` of the mass-normalised mode of wavenumber ``k`` (a root).

    The null vector of the support conditions (smallest singular vector), scaled so that
    ``int mbar phi^2 dx = 1`` and signed so that the slope at the start is positive.
    """
    spans = _spans_array(spans)
    _, _, vt = np.linalg.svd(boundary_matrix(k, spans))
    coef = vt[-1].reshape(spans.size, 4)
    total = sum(_square_integral(k, length, coef[j]) for j, length in enumerate(spans))
    coef = coef / math.sqrt(mass_per_length * total)
    slope = float(_basis(k, 0.0, spans[0], 1) @ coef[0])
    scale = float(np.abs(coef).max())
    sign = np.sign(slope) if abs(slope) > 1e-9 * scale else np.sign(coef.flat[np.argmax(abs(coef))])
    return coef * sign


def _square_integral(k: float, length: float, coef: np.ndarray) -> float:
    """``int_0^L phi^2 ds`` of one span by Gauss-Legendre quadrature in short pieces."""
    nodes, weights = np.polynomial.legendre.leggauss(32)
    pieces = max(4, 4 * int(math.ceil(k * length / math.pi)))
    edges = np.linspace(0.0, length, pieces + 1)
    half = 0.5 * np.diff(edges)
    s = (0.5 * (edges[:-1] + edges[1:]))[:, None] + half[:, None] * nodes[None, :]
    phi = (
        coef[0] * np.sin(k * s)
        + coef[1] * np.cos(k * s)
        + coef[2] * np.exp(-k * s)
        + coef[3] * np.exp(-k * (length - s))
    )
    return float(np.sum(half[:, None] * weights[None, :] * phi**2))


def shape_derivatives(
    x: np.ndarray,
    supports: np.ndarray,
    wavenumbers: np.ndarray,
    coefficients: np.ndarray,
    order: int,
) -> np.ndarray:
    """``d^order phi_n / dx^order`` at stations ``x`` from the beam's start, shape ``(n_x, N)``.

    A station on an interior support belongs to the span on its left (and ``x = 0`` to the
    first span): the third derivative (the shear) jumps there, and this gives its value just
    to the left, the convention of :mod:`vbi_lib.closed_forms`.
    """
    x = np.asarray(x, dtype=float)
    n_spans = supports.size - 1
    span = np.clip(np.searchsorted(supports, x, side="left") - 1, 0, n_spans - 1)
    s = (x - supports[span])[:, None]
    length = np.diff(supports)[span][:, None]
    k = wavenumbers[None, :]
    c = coefficients[:, span, :].transpose(1, 0, 2)  # (n_x, N, 4)
    sn, cs = np.sin(k * s), np.cos(k * s)
    e0, e1 = np.exp(-k * s), np.exp(-k * (length - s))
    terms = ((sn, cs, e0, e1), (cs, -sn, -e0, e1), (-sn, -cs, e0, e1), (-cs, sn, -e0, e1))[order]
    value = sum(c[..., i] * terms[i] for i in range(4))
    return value * k**order
