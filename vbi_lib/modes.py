r"""Exact free-vibration modes of the uniform beam of a bridge (Euler-Bernoulli).

The many-mode crossing model (:mod:`vbi_lib.models.modal`), the section responses
(:mod:`vbi_lib.models.sections`) and the static influence lines use the bridge's first ``N``
mass-normalised modes,

.. math:: u_b(x, t) = \sum_{n=1}^{N} \phi_n(x)\, q_n(t),
    \qquad \int_0^{\ell} \bar m\, \phi_m \phi_n \, dx = \delta_{mn},

for a beam continuous over any spans (:meth:`vbi_lib.Bridge.continuous`), computed exactly
by :mod:`vbi_lib.continuous_beams`.  Two layouts have textbook forms, which the general
solution reproduces to rounding (``tests/test_modes.py``):

* one simple span: :math:`\phi_n = \sqrt{2/(\bar m L)}\,\sin(n\pi x/L)`,
  :math:`\omega_n = (n\pi/L)^2\sqrt{EI/\bar m}`;
* two equal continuous spans: the antisymmetric family
  :math:`\phi = \sin(k\pi x/L)/\sqrt{\bar m L}` over :math:`[0, 2L]` (each span a simple span,
  :math:`\omega = (k\pi/L)^2\sqrt{EI/\bar m}`) and the symmetric family, in which each span
  is a propped cantilever (pinned at its outer end, no slope over the middle support),
  :math:`\phi(s) \propto \sin\lambda s - \sin\lambda L\,\sinh\lambda s / \sinh\lambda L`
  with :math:`s` measured from the nearer outer end and :math:`\tan\lambda L = \tanh\lambda L`
  (:math:`\lambda L = 3.9266, 7.0686, \dots`), :math:`\omega = \lambda^2\sqrt{EI/\bar m}`.

The first mode of either is the study's shape function :math:`\psi` (33), (59).  Over any
number of *equal* spans the first frequency is the simple span's; three equal spans have
1, 1.2815, 1.8713 and 4 times it (Blevins, *Formulas for Natural Frequency and Mode Shape*).

Static deflection
-----------------
The static midspan deflection under a load :math:`P` at station :math:`x` is the modal sum
:math:`P \sum_n \phi_n(x)\phi_n(x_{mid}) / \omega_n^2` (the influence line of the midspan
deflection).  With many modes it tends to the exact :math:`PL^3/48EI` (one span, load at
midspan) and :math:`23PL^3/1536EI` (two spans); on two spans the largest value over load
positions is 0.25 % above the latter, because the peak of the midspan influence line lies
slightly off midspan.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numba
import numpy as np
from scipy.optimize import brentq, minimize_scalar

from . import _validation as check
from .bridges import Bridge
from .continuous_beams import mode_coefficients, natural_wavenumbers, shape_derivatives
from .costs import warn_mode_search
from .ranges import RANGES

__all__ = [
    "BeamModes",
    "beam_modes",
    "largest_static_deflection",
    "propped_cantilever_roots",
    "static_deflection_line",
]


def propped_cantilever_roots(count: int) -> np.ndarray:
    r"""The first ``count`` positive roots of :math:`\tan z = \tanh z` (``z = lambda L``).

    They give the symmetric modes of two equal continuous spans (each span a propped
    cantilever): :math:`\omega = (z/L)^2 \sqrt{EI/\bar m}`.  Root ``n`` lies in
    :math:`(n\pi, n\pi + \pi/2)` and tends to :math:`(n + 1/4)\pi`.

    Examples
    --------
    >>> propped_cantilever_roots(3).round(4)
    array([ 3.9266,  7.0686, 10.2102])
    """
    count = int(count)
    if count < 0:
        raise ValueError(f"count={count!r} must be >= 0")

    def residual(z: float) -> float:  # sin z - cos z tanh z, no poles
        return math.sin(z) - math.cos(z) * math.tanh(z)

    roots = [
        brentq(residual, n * math.pi + 1e-9, n * math.pi + 0.5 * math.pi - 1e-12, xtol=1e-14)
        for n in range(1, count + 1)
    ]
    return np.array(roots, dtype=float)


@numba.njit(cache=True)
def shape_values(xi, supports, kappa, coef, phi, dphi, ddphi):
    """Mode shapes, slopes and curvatures at ``xi`` (from the bridge start) into the arrays.

    ``supports`` (n_spans + 1) are the support stations from the bridge start, ``kappa``
    (N) the wavenumbers and ``coef`` (N, n_spans, 4) the coefficients ``(a, b, c, d)`` of
    ``a sin ks + b cos ks + c exp(-ks) + d exp(-k (L_j - s))`` in each span.
    """
    n_spans = supports.shape[0] - 1
    j = 0
    while j < n_spans - 1 and xi > supports[j + 1]:
        j += 1
    s = xi - supports[j]
    rest = supports[j + 1] - xi
    for n in range(kappa.shape[0]):
        k = kappa[n]
        a = coef[n, j, 0]
        b = coef[n, j, 1]
        c = coef[n, j, 2]
        d = coef[n, j, 3]
        sn = math.sin(k * s)
        cs = math.cos(k * s)
        e0 = math.exp(-k * s)
        e1 = math.exp(-k * rest)
        phi[n] = a * sn + b * cs + c * e0 + d * e1
        dphi[n] = k * (a * cs - b * sn - c * e0 + d * e1)
        ddphi[n] = k * k * (-a * sn - b * cs + c * e0 + d * e1)


@dataclass(frozen=True, eq=False)
class BeamModes:
    """The first N mass-normalised Euler-Bernoulli modes of a bridge's continuous beam.

    In span ``j`` (local ``s`` from its left support) mode ``n`` is
    ``a sin ks + b cos ks + c exp(-ks) + d exp(-k (L_j - s))``
    (:mod:`vbi_lib.continuous_beams`).

    Attributes
    ----------
    bridge
        The beam.
    supports
        Support stations from the bridge start [m], shape ``(n_spans + 1,)``.
    wavenumber
        ``k_n`` [1/m], shape ``(N,)``; ``omega_n = k_n^2 sqrt(EI / mbar)``.
    coefficients
        ``(a, b, c, d)`` of every mode in every span [kg^-1/2], shape ``(N, n_spans, 4)``.
    omega
        Circular frequencies [rad/s], increasing.

    Examples
    --------
    >>> from vbi_lib import Bridge
    >>> modes = beam_modes(Bridge(30.0, 2, 1e10, 5000.0), 3)
    >>> (modes.frequencies_hz / modes.frequencies_hz[0]).round(3)
    array([1.   , 1.562, 4.   ])
    """

    bridge: Bridge
    supports: np.ndarray
    wavenumber: np.ndarray
    coefficients: np.ndarray
    omega: np.ndarray

    @property
    def count(self) -> int:
        """Number of modes N."""
        return int(self.omega.size)

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Natural frequencies [Hz]."""
        return self.omega / (2.0 * math.pi)

    def derivative(self, x_from_bridge_start: float | np.ndarray, order: int) -> np.ndarray:
        """``d^order phi_n / dx^order`` at stations from the bridge start, shape ``(n_x, N)``.

        ``order`` 0 to 3 [kg^-1/2 m^-order].  At an interior support the third derivative
        (shear) is the value just to the left of it.

        Raises
        ------
        ValueError
            A station off the bridge or not finite, an order outside 0-3.
        """
        if order not in (0, 1, 2, 3):
            raise ValueError(f"order={order!r} must be 0, 1, 2 or 3")
        xi = np.atleast_1d(np.asarray(x_from_bridge_start, dtype=float)).ravel()
        if not np.isfinite(xi).all():
            raise ValueError("x_from_bridge_start must be finite stations [m]")
        length = self.bridge.length
        if (xi < -1e-9 * length).any() or (xi > length * (1 + 1e-9)).any():
            raise ValueError(
                f"x_from_bridge_start must lie on the bridge, in [0, {length:g}] m; got values "
                f"from {xi.min():g} to {xi.max():g}"
            )
        return shape_derivatives(
            np.clip(xi, 0.0, length), self.supports, self.wavenumber, self.coefficients, order
        )

    def shape(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """``phi_n(x)`` [kg^-1/2], shape ``(n_x, N)``."""
        return self.derivative(x_from_bridge_start, 0)

    def slope(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """``phi_n'(x)`` [kg^-1/2 m^-1], shape ``(n_x, N)``."""
        return self.derivative(x_from_bridge_start, 1)

    def curvature(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """``phi_n''(x)`` [kg^-1/2 m^-2], shape ``(n_x, N)``."""
        return self.derivative(x_from_bridge_start, 2)

    def __repr__(self) -> str:
        shown = ", ".join(f"{f:.2f}" for f in self.frequencies_hz[:6])
        more = ", ..." if self.count > 6 else ""
        return f"BeamModes({self.count} modes of {self.bridge!r}: {shown}{more} Hz)"


@lru_cache(maxsize=256)
def beam_modes(bridge: Bridge, modes: int) -> BeamModes:
    """The bridge's first ``modes`` exact Euler-Bernoulli modes, by increasing frequency.

    Any layout of spans (:meth:`vbi_lib.Bridge.continuous`): the roots are counted with the
    Wittrick-Williams algorithm so none is missed (:mod:`vbi_lib.continuous_beams`).  For one
    span these are ``sqrt(2 / (mbar L)) sin(n pi x / L)``; for two equal spans the sine and
    propped-cantilever families of the module docstring.

    Parameters
    ----------
    bridge
        The beam (its spans, EI and mass per length).
    modes
        Number of modes N >= 1.

    Returns
    -------
    BeamModes

    Raises
    ------
    TypeError, ValueError
        ``bridge`` is not a :class:`~vbi_lib.Bridge`; ``modes`` is not a whole number >= 1.

    Examples
    --------
    A simple span's frequencies grow as n^2:

    >>> from vbi_lib import Bridge
    >>> beam_modes(Bridge(30.0, 1, 1e10, 5000.0), 3).frequencies_hz.round(2)
    array([ 2.47,  9.87, 22.21])
    """
    if not isinstance(bridge, Bridge):
        raise TypeError(f"bridge must be a vbi.Bridge, got {type(bridge).__name__}")
    modes = check.integer("modes", modes, low=1, high=int(RANGES["modes"].hard[1]))
    warn_mode_search(bridge.spans, modes)  # h23: a long search is announced (costs.py)
    spans = np.array(bridge.spans)
    kappa = natural_wavenumbers(spans, int(modes))
    coef = np.array([mode_coefficients(spans, k, bridge.mass_per_length) for k in kappa])
    result = BeamModes(
        bridge=bridge,
        supports=np.array(bridge.supports),
        wavenumber=kappa,
        coefficients=np.ascontiguousarray(coef),
        omega=kappa**2 * math.sqrt(bridge.EI / bridge.mass_per_length),
    )
    for array in (result.supports, result.wavenumber, result.coefficients, result.omega):
        array.setflags(write=False)
    return result


def static_deflection_line(
    bridge: Bridge, force: float, modes: int, load_positions: np.ndarray
) -> np.ndarray:
    """Static midspan deflections under ``force`` at each load position, from N modes.

    ``force * sum_n phi_n(x) phi_n(mid_j) / omega_n^2`` for each span ``j``: the influence
    line of each midspan deflection, positive down.

    Parameters
    ----------
    bridge, modes
        The beam and the number of modes.
    force
        Load [N], positive down.
    load_positions
        Load stations from the bridge start [m].

    Returns
    -------
    ndarray ``(n_positions, n_spans)`` [m], downward positive.

    Raises
    ------
    ValueError
        A negative force, a load position off the bridge.

    Examples
    --------
    Fifty modes give the exact midspan deflection of a simple span, ``P L^3 / 48 EI``:

    >>> from vbi_lib import Bridge
    >>> b = Bridge(10.0, 1, 1e9, 1000.0)
    >>> d = static_deflection_line(b, 1e5, 50, [5.0])[0, 0]
    >>> round(float(d / (1e5 * 10.0**3 / (48 * 1e9))), 5)
    1.0
    """
    force = check.non_negative("force", force)
    basis = beam_modes(bridge, modes)
    at_load = basis.shape(load_positions)
    at_mid = basis.shape(np.array(bridge.midspans))
    return force * (at_load / basis.omega**2) @ at_mid.T


@lru_cache(maxsize=512)
def largest_static_deflection(bridge: Bridge, modes: int) -> tuple[float, ...]:
    """Largest midspan deflection of each span under a unit load over all positions [m/N]."""
    basis = beam_modes(bridge, modes)
    at_mid = basis.shape(np.array(bridge.midspans))
    weights = at_mid / basis.omega**2
    results = []
    supports = bridge.supports
    for j in range(bridge.n_spans):
        length = supports[j + 1] - supports[j]
        xs = np.linspace(supports[j], supports[j + 1], 201)

        def line(x: float, j: int = j) -> float:
            return float(basis.shape(x)[0] @ weights[j])

        values = np.array([line(x) for x in xs])
        i = int(np.argmax(values))
        lo = xs[max(i - 1, 0)]
        hi = xs[min(i + 1, xs.size - 1)]
        best = minimize_scalar(lambda x, f=line: -f(x), bounds=(lo, hi), method="bounded",
                               options={"xatol": 1e-10 * length})  # fmt: skip
        results.append(max(values[i], -best.fun))
    return tuple(results)
