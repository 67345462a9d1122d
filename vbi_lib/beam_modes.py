r"""Exact free-vibration modes of the uniform beam of a bridge (Euler-Bernoulli).

The many-mode crossing model (:mod:`vbi_lib.models.modal`) and the static influence lines use
the bridge's first ``N`` mass-normalised modes,

.. math:: u_b(x, t) = \sum_{n=1}^{N} \phi_n(x)\, q_n(t),
    \qquad \int_0^{NL} \bar m\, \phi_m \phi_n \, dx = \delta_{mn},

* one simple span: :math:`\phi_n = \sqrt{2/(\bar m L)}\,\sin(n\pi x/L)`,
  :math:`\omega_n = (n\pi/L)^2\sqrt{EI/\bar m}`;
* two equal continuous spans: the antisymmetric family
  :math:`\phi = \sin(k\pi x/L)/\sqrt{\bar m L}` over :math:`[0, 2L]` (each span a simple span,
  :math:`\omega = (k\pi/L)^2\sqrt{EI/\bar m}`) and the symmetric family, in which each span
  is a propped cantilever (pinned at its outer end, no slope over the middle support),
  :math:`\phi(s) \propto \sin\lambda s - \sin\lambda L\,\sinh\lambda s / \sinh\lambda L`
  with :math:`s` measured from the nearer outer end and :math:`\tan\lambda L = \tanh\lambda L`
  (:math:`\lambda L = 3.9266, 7.0686, \dots`), :math:`\omega = \lambda^2\sqrt{EI/\bar m}`;
  the two families are merged in order of frequency.

The first mode of either beam is the study's shape function :math:`\psi` (33), (59).

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

__all__ = [
    "BeamModes",
    "beam_modes",
    "largest_static_deflection",
    "propped_cantilever_roots",
    "static_deflection_line",
]

SINE, PROPPED = 0, 1


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
def shape_values(xi, kind, kappa, amp, span, phi, dphi, ddphi):
    """Mode shapes, slopes and curvatures at ``xi`` (from the bridge start) into the arrays."""
    for n in range(kind.shape[0]):
        k = kappa[n]
        if kind[n] == SINE:
            s = math.sin(k * xi)
            phi[n] = amp[n] * s
            dphi[n] = amp[n] * k * math.cos(k * xi)
            ddphi[n] = -amp[n] * k * k * s
        else:
            mirrored = xi > span
            s = 2.0 * span - xi if mirrored else xi
            # sinh(k s)/sinh(k L) and cosh(k s)/sinh(k L) without overflow
            e = math.exp(k * (s - span))
            e2 = math.exp(-2.0 * k * s)
            d = 1.0 - math.exp(-2.0 * k * span)
            shr = e * (1.0 - e2) / d
            chr_ = e * (1.0 + e2) / d
            sl = math.sin(k * span)
            phi[n] = amp[n] * (math.sin(k * s) - sl * shr)
            slope = amp[n] * k * (math.cos(k * s) - sl * chr_)
            dphi[n] = -slope if mirrored else slope
            ddphi[n] = amp[n] * k * k * (-math.sin(k * s) - sl * shr)


@dataclass(frozen=True, eq=False)
class BeamModes:
    """The first N mass-normalised Euler-Bernoulli modes of a one- or two-span beam.

    Attributes
    ----------
    bridge
        The beam.
    kind
        ``0`` sine mode, ``1`` symmetric (propped-cantilever) mode of two spans.
    wavenumber
        ``n pi / L`` or ``lambda`` [1/m].
    amplitude
        Factor that normalises the mode to unit generalised mass [kg^-1/2].
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
    kind: np.ndarray
    wavenumber: np.ndarray
    amplitude: np.ndarray
    omega: np.ndarray

    @property
    def count(self) -> int:
        """Number of modes N."""
        return int(self.omega.size)

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Natural frequencies [Hz]."""
        return self.omega / (2.0 * math.pi)

    def _values(self, x_from_bridge_start: float | np.ndarray, which: int) -> np.ndarray:
        xi = np.atleast_1d(np.asarray(x_from_bridge_start, dtype=float))
        if not np.isfinite(xi).all():
            raise ValueError("x_from_bridge_start must be finite stations [m]")
        length = self.bridge.length
        if (xi < -1e-9 * length).any() or (xi > length * (1 + 1e-9)).any():
            raise ValueError(
                f"x_from_bridge_start must lie on the bridge, in [0, {length:g}] m; got values "
                f"from {xi.min():g} to {xi.max():g}"
            )
        out = np.empty((xi.size, self.count))
        phi = np.empty(self.count)
        dphi = np.empty(self.count)
        ddphi = np.empty(self.count)
        for i, value in enumerate(np.clip(xi, 0.0, length)):
            shape_values(
                value, self.kind, self.wavenumber, self.amplitude, self.bridge.span,
                phi, dphi, ddphi,
            )  # fmt: skip
            out[i] = (phi, dphi, ddphi)[which]
        return out

    def shape(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """``phi_n(x)`` [kg^-1/2], shape ``(n_x, N)``."""
        return self._values(x_from_bridge_start, 0)

    def slope(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """``phi_n'(x)`` [kg^-1/2 m^-1], shape ``(n_x, N)``."""
        return self._values(x_from_bridge_start, 1)

    def curvature(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """``phi_n''(x)`` [kg^-1/2 m^-2], shape ``(n_x, N)``."""
        return self._values(x_from_bridge_start, 2)

    def __repr__(self) -> str:
        shown = ", ".join(f"{f:.2f}" for f in self.frequencies_hz[:6])
        more = ", ..." if self.count > 6 else ""
        return f"BeamModes({self.count} modes of {self.bridge!r}: {shown}{more} Hz)"


def _normalising_amplitude(lam: float, span: float, mass_per_length: float) -> float:
    """Amplitude that gives a symmetric two-span mode unit generalised mass."""
    nodes, weights = np.polynomial.legendre.leggauss(64)
    # integrate over span in pieces short enough for the oscillation
    pieces = max(4, int(math.ceil(lam * span / math.pi)) * 4)
    edges = np.linspace(0.0, span, pieces + 1)
    total = 0.0
    sl = math.sin(lam * span)
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        s = 0.5 * (a + b) + 0.5 * (b - a) * nodes
        shr = (
            np.exp(lam * (s - span)) * (1 - np.exp(-2 * lam * s)) / (1 - math.exp(-2 * lam * span))
        )
        shape = np.sin(lam * s) - sl * shr
        total += 0.5 * (b - a) * float(np.sum(weights * shape**2))
    return 1.0 / math.sqrt(2.0 * mass_per_length * total)


@lru_cache(maxsize=256)
def beam_modes(bridge: Bridge, modes: int) -> BeamModes:
    """The bridge's first ``modes`` exact Euler-Bernoulli modes, by increasing frequency.

    Parameters
    ----------
    bridge
        A one-span or two-equal-span beam (its span, EI and mass per length).
    modes
        Number of modes N >= 1.

    Returns
    -------
    BeamModes

    Examples
    --------
    A simple span's frequencies grow as n^2:

    >>> from vbi_lib import Bridge
    >>> beam_modes(Bridge(30.0, 1, 1e10, 5000.0), 3).frequencies_hz.round(2)
    array([ 2.47,  9.87, 22.21])
    """
    if not isinstance(bridge, Bridge):
        raise TypeError(f"bridge must be a vbi.Bridge, got {type(bridge).__name__}")
    if isinstance(modes, bool) or not isinstance(modes, int | np.integer) or modes < 1:
        raise ValueError(f"modes={modes!r} must be a whole number of modes >= 1")
    modes = int(modes)
    L = bridge.span
    mbar = bridge.mass_per_length
    root = math.sqrt(bridge.EI / mbar)
    kind, kappa, amp = [], [], []
    if bridge.n_spans == 1:
        for n in range(1, modes + 1):
            kind.append(SINE)
            kappa.append(n * math.pi / L)
            amp.append(math.sqrt(2.0 / (mbar * L)))
    else:
        lambdas = propped_cantilever_roots(modes) / L
        candidates = [(k * math.pi / L, SINE) for k in range(1, modes + 1)]
        candidates += [(lam, PROPPED) for lam in lambdas]
        candidates.sort()
        for k, which in candidates[:modes]:
            kind.append(which)
            kappa.append(k)
            if which == SINE:
                amp.append(1.0 / math.sqrt(mbar * L))
            else:
                amp.append(_normalising_amplitude(k, L, mbar))
    kappa_arr = np.array(kappa)
    result = BeamModes(
        bridge=bridge,
        kind=np.array(kind, dtype=np.int64),
        wavenumber=kappa_arr,
        amplitude=np.array(amp),
        omega=kappa_arr**2 * root,
    )
    for array in (result.kind, result.wavenumber, result.amplitude, result.omega):
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
    for j in range(bridge.n_spans):
        xs = np.linspace(j * bridge.span, (j + 1) * bridge.span, 201)

        def line(x: float, j: int = j) -> float:
            return float(basis.shape(x)[0] @ weights[j])

        values = np.array([line(x) for x in xs])
        i = int(np.argmax(values))
        lo = xs[max(i - 1, 0)]
        hi = xs[min(i + 1, xs.size - 1)]
        best = minimize_scalar(lambda x, f=line: -f(x), bounds=(lo, hi), method="bounded",
                               options={"xatol": 1e-10 * bridge.span})  # fmt: skip
        results.append(max(values[i], -best.fun))
    return tuple(results)
