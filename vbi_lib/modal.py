r"""A many-mode reference model: the truck on the bridge's first N exact Euler-Bernoulli modes.

The one-coordinate model of :mod:`vbi_lib.simulation` bends the beam in one assumed shape.
Here the beam deflects in its first ``N`` exact free-vibration modes,

.. math:: u_b(x, t) = \sum_{n=1}^{N} \phi_n(x)\, q_n(t),
    \qquad \int_0^{NL} \bar m\, \phi_m \phi_n \, dx = \delta_{mn},

each with its own frequency :math:`\omega_n` and the bridge's damping ratio
:math:`\zeta_b` (modal damping, as in a modal finite-element analysis).  The modes are

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

The sprung mass couples to the modes exactly as to the one coordinate of the study's model
(:math:`\psi z_b` becomes :math:`\sum \phi_n q_n`):

.. math::
    F &= k_v (r - u_v) + c_v (\dot r - \dot u_v), \qquad
        r = \textstyle\sum_n \phi_n(x_v) q_n + \Delta(x_v) \\
    m_v \ddot u_v &= F, \qquad
    \ddot q_n + 2 \zeta_b \omega_n \dot q_n + \omega_n^2 q_n = -\phi_n(x_v)\,(m_v g + F).

With one mode this is the study's two-degree-of-freedom model (the first mode of either beam
is its shape function, and its generalised mass is the study's :math:`m^*`).

Integration
-----------
High modes are stiff (mode 5 of a 10 Hz simple span vibrates at 250 Hz), so an explicit
scheme would need a step set by the highest mode.  The modes and the vehicle are instead
integrated together with the Newmark average-acceleration (trapezoidal) rule, which is
unconditionally stable and second-order accurate; the implicit equations of a step reduce,
because the coupling has rank one, to a single scalar equation for the suspension force, so
a step costs O(N).  The accelerations at the start of each step are recomputed from the
equations of motion (the mass matrix is diagonal), so the jumps of the road's slope at
profile samples and of the coupling where the wheel leaves the bridge are honoured exactly.
Every profile sample is a node; the default step also resolves the vehicle and the lowest
bridge modes (:func:`default_time_step`).

Static deflection and DAF
-------------------------
The static midspan deflection under the weight at station :math:`x` is the modal sum
:math:`P \sum_n \phi_n(x)\phi_n(x_{mid}) / \omega_n^2`; the model's static deflection is its
largest value over all load positions (the crawl run of a finite-element study), and the DAF
of span ``j`` divides the largest downward midspan deflection while the wheel is on span
``j`` by it.  With many modes the deflection under a midspan load tends to the exact
:math:`PL^3/48EI` (one span) and :math:`23PL^3/1536EI` (two spans); on two spans the largest
value over load positions is 0.25 % above the latter, because the peak of the midspan
influence line lies slightly off midspan.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache

import numba
import numpy as np
from scipy.optimize import brentq, minimize_scalar

from . import _validation as check
from .bridges import Bridge, reference_beam
from .profiles import Profile
from .simulation import BatchResult, _broadcast, _check_inputs, _CrossingViews, _grid
from .units import g as GRAVITY
from .vehicles import Vehicle

__all__ = [
    "BeamModes",
    "ModalCrossing",
    "agreement",
    "assessment_inputs",
    "beam_modes",
    "default_time_step",
    "propped_cantilever_roots",
    "reference_beam",
    "simulate_modal",
    "simulate_modal_many",
    "static_deflection_line",
]

#: ``omega * dt`` the default step gives the vehicle and the lowest bridge modes.
DEFAULT_OMEGA_DT = 0.1

_SINE, _PROPPED = 0, 1

# parameter vector layout of the kernel
_M_V, _K_V, _C_V, _GRAV, _SPEED, _START, _SPAN = range(7)
_N_PARAMS = 7


# ---------------------------------------------------------------------------- modes
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
def _shape_values(xi, kind, kappa, amp, span, phi, dphi, ddphi):
    """Mode shapes, slopes and curvatures at ``xi`` (from the bridge start) into the arrays."""
    for n in range(kind.shape[0]):
        k = kappa[n]
        if kind[n] == _SINE:
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
            _shape_values(
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
            kind.append(_SINE)
            kappa.append(n * math.pi / L)
            amp.append(math.sqrt(2.0 / (mbar * L)))
    else:
        lambdas = propped_cantilever_roots(modes) / L
        candidates = [(k * math.pi / L, _SINE) for k in range(1, modes + 1)]
        candidates += [(lam, _PROPPED) for lam in lambdas]
        candidates.sort()
        for k, which in candidates[:modes]:
            kind.append(which)
            kappa.append(k)
            if which == _SINE:
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
def _largest_static(bridge: Bridge, modes: int) -> tuple[float, ...]:
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


def default_time_step(bridge: Bridge, vehicle: Vehicle, modes: int) -> float:
    """Largest default step [s]: ``0.1 / omega`` of the vehicle and the first two modes.

    Higher modes respond almost statically to the truck and the average-acceleration rule
    keeps them stable at any step, so they do not set the step; the dt convergence study in
    the validation chapter shows the DAF settled at this step.

    Examples
    --------
    >>> from vbi_lib import Bridge, Vehicle
    >>> dt = default_time_step(Bridge(30.0, 1, 1e10, 5000.0), Vehicle(1e4, 4e6, 2e4), 5)
    >>> round(dt * 1e3, 3)   # ms; the vehicle at 3.18 Hz, mode 2 at 9.87 Hz
    1.612
    """
    basis = beam_modes(bridge, modes)
    omega = max(vehicle.circular_frequency, float(basis.omega[: min(2, basis.count)].max()))
    return DEFAULT_OMEGA_DT / omega


# ---------------------------------------------------------------------------- kernel
@numba.njit(cache=True)
def _hermite_min(a0, a1, d0, d1, h):
    """Smallest value inside a step of the cubic Hermite interpolant (values a, rates d)."""
    m0 = h * d0
    m1 = h * d1
    c3 = 2.0 * a0 + m0 - 2.0 * a1 + m1
    c2 = -3.0 * a0 - 2.0 * m0 + 3.0 * a1 - m1
    c1 = m0
    best = min(a0, a1)
    qa = 3.0 * c3
    qb = 2.0 * c2
    qc = c1
    if abs(qa) < 1e-300:
        if abs(qb) > 1e-300:
            t = -qc / qb
            if 0.0 < t < 1.0:
                best = min(best, ((c3 * t + c2) * t + c1) * t + a0)
        return best
    disc = qb * qb - 4.0 * qa * qc
    if disc < 0.0:
        return best
    root = math.sqrt(disc)
    for t in ((-qb - root) / (2.0 * qa), (-qb + root) / (2.0 * qa)):
        if 0.0 < t < 1.0:
            best = min(best, ((c3 * t + c2) * t + c1) * t + a0)
    return best


@numba.njit(cache=True)
def _modal_kernel(
    x,
    elevation,
    span_of_step,
    params,
    kind,
    kappa,
    amp,
    omega,
    zeta,
    phi_mid,
    coupled,
    convective,
    q_hist,
    qd_hist,
    vehicle_hist,
    contact,
    peaks,
):
    """Newmark average acceleration on the vehicle and N modes over the nodes ``x``.

    ``span_of_step[k]``: 0 off the bridge, else the span (1 or 2) of step k.  History
    arrays are filled when they have one row per node.  ``peaks``: per span the largest
    downward midspan deflection while the wheel is on it, then the largest contact force on
    the bridge and its station.
    """
    n_nodes = x.shape[0]
    n_modes = omega.shape[0]
    n_spans = phi_mid.shape[0]
    record = q_hist.shape[0] == n_nodes
    m_v = params[_M_V]
    k_v = params[_K_V]
    c_v = params[_C_V]
    weight = m_v * params[_GRAV]
    speed = params[_SPEED]
    start = params[_START]
    span = params[_SPAN]
    eps = 1.0 if convective else 0.0
    cpl = 1.0 if coupled else 0.0

    y = np.zeros(n_modes)
    v = np.zeros(n_modes)
    a = np.zeros(n_modes)
    yt = np.empty(n_modes)
    vt = np.empty(n_modes)
    r = np.empty(n_modes)
    gvec = np.empty(n_modes)
    dd = np.empty(n_modes)
    phi = np.zeros(n_modes)
    dphi = np.zeros(n_modes)
    ddphi = np.empty(n_modes)
    two_zw = 2.0 * zeta * omega
    w2 = omega * omega
    uv = elevation[0]  # at rest in static equilibrium on the profile
    vv = 0.0
    mid0 = np.zeros(n_spans)
    midv0 = np.zeros(n_spans)
    for j in range(n_spans):
        peaks[j] = -np.inf
    peaks[n_spans] = 0.0
    peaks[n_spans + 1] = np.nan
    if record:
        vehicle_hist[0, 0] = uv
        vehicle_hist[0, 1] = vv
        for n in range(n_modes):
            q_hist[0, n] = 0.0
            qd_hist[0, n] = 0.0
    force_b = 0.0
    for k in range(n_nodes - 1):
        xa = x[k]
        xb = x[k + 1]
        h = (xb - xa) / speed
        rate = (elevation[k + 1] - elevation[k]) / (xb - xa) * speed
        span_k = span_of_step[k]
        on = span_k > 0
        beta = 0.25 * h * h
        gamma = 0.5 * h
        # ---- accelerations at the start of the step (right limit), from the equations
        if on:
            _shape_values(xa - start, kind, kappa, amp, span, phi, dphi, ddphi)
        else:
            for n in range(n_modes):
                phi[n] = 0.0
                dphi[n] = 0.0
        ub = 0.0
        ubd = 0.0
        for n in range(n_modes):
            ub += phi[n] * y[n]
            ubd += phi[n] * v[n] + eps * speed * dphi[n] * y[n]
        force = k_v * (cpl * ub + elevation[k] - uv) + c_v * (cpl * ubd + rate - vv)
        av = force / m_v
        for n in range(n_modes):
            a[n] = -two_zw[n] * v[n] - w2[n] * y[n] - phi[n] * (weight + force)
        if record:
            contact[k] = weight + force
        elif on and weight + force > peaks[n_spans]:
            peaks[n_spans] = weight + force
            peaks[n_spans + 1] = xa
        # midspan displacement and rate at the start
        for j in range(n_spans):
            s0 = 0.0
            s1 = 0.0
            for n in range(n_modes):
                s0 += phi_mid[j, n] * y[n]
                s1 += phi_mid[j, n] * v[n]
            mid0[j] = s0
            midv0[j] = s1
        # ---- predictors
        for n in range(n_modes):
            yt[n] = y[n] + h * v[n] + beta * a[n]
            vt[n] = v[n] + gamma * a[n]
        uvt = uv + h * vv + beta * av
        vvt = vv + gamma * av
        # ---- the implicit equations at the end of the step reduce to one for F
        if on:
            _shape_values(xb - start, kind, kappa, amp, span, phi, dphi, ddphi)
        s_v = k_v * beta + c_v * gamma
        ub = 0.0
        ubd = 0.0
        for n in range(n_modes):
            ub += phi[n] * yt[n]
            ubd += phi[n] * vt[n] + eps * speed * dphi[n] * yt[n]
        f_tilde = k_v * (cpl * ub + elevation[k + 1] - uvt) + c_v * (cpl * ubd + rate - vvt)
        denominator = 1.0 + s_v / m_v
        numerator = f_tilde
        for n in range(n_modes):
            dd[n] = 1.0 + two_zw[n] * gamma + w2[n] * beta
            r[n] = -two_zw[n] * vt[n] - w2[n] * yt[n] - phi[n] * weight
            gvec[n] = cpl * (s_v * phi[n] + c_v * eps * speed * beta * dphi[n])
            denominator += gvec[n] * phi[n] / dd[n]
            numerator += gvec[n] * r[n] / dd[n]
        force_b = numerator / denominator
        avb = force_b / m_v
        for n in range(n_modes):
            a[n] = (r[n] - phi[n] * force_b) / dd[n]
            y[n] = yt[n] + beta * a[n]
            v[n] = vt[n] + gamma * a[n]
        uv = uvt + beta * avb
        vv = vvt + gamma * avb
        if record:
            vehicle_hist[k + 1, 0] = uv
            vehicle_hist[k + 1, 1] = vv
            for n in range(n_modes):
                q_hist[k + 1, n] = y[n]
                qd_hist[k + 1, n] = v[n]
        if on:
            j = span_k - 1
            s0 = 0.0
            s1 = 0.0
            for n in range(n_modes):
                s0 += phi_mid[j, n] * y[n]
                s1 += phi_mid[j, n] * v[n]
            if midv0[j] * s1 <= 0.0:
                low = _hermite_min(mid0[j], s0, midv0[j], s1, h)
            else:
                low = min(mid0[j], s0)
            if -low > peaks[j]:
                peaks[j] = -low
    if record:
        contact[n_nodes - 1] = weight + force_b
    elif span_of_step[n_nodes - 2] > 0 and weight + force_b > peaks[n_spans]:
        peaks[n_spans] = weight + force_b
        peaks[n_spans + 1] = x[n_nodes - 1]


@numba.njit(cache=True, parallel=True)
def _batch_kernel(
    offsets, x, elevation, span_of_step, params, mode_offsets, kind, kappa, amp, omega, zeta,
    phi_mid, coupled, convective, peaks,
):  # fmt: skip
    """Run many crossings in parallel; crossing i uses nodes ``offsets[i]:offsets[i+1]``."""
    n_jobs = offsets.shape[0] - 1
    for i in numba.prange(n_jobs):
        a = offsets[i]
        b = offsets[i + 1]
        ma = mode_offsets[i]
        mb = mode_offsets[i + 1]
        n_spans = 1 if math.isnan(phi_mid[i, 1, 0]) else 2
        dummy = np.empty((1, 1))
        _modal_kernel(
            x[a:b],
            elevation[a:b],
            span_of_step[a:b],
            params[i],
            kind[ma:mb],
            kappa[ma:mb],
            amp[ma:mb],
            omega[ma:mb],
            zeta[ma:mb],
            np.ascontiguousarray(phi_mid[i, :n_spans, : mb - ma]),
            coupled[i],
            convective[i],
            dummy,
            dummy,
            np.empty((1, 2)),
            np.empty(1),
            peaks[i],
        )


# ---------------------------------------------------------------------------- preparation
def _check_modes(modes: object) -> int:
    if isinstance(modes, bool) or not isinstance(modes, int | np.integer) or modes < 1:
        raise ValueError(f"modes={modes!r} must be a whole number of modes >= 1")
    return int(modes)


def _parameters(vehicle: Vehicle, speed: float, bridge_start: float, span: float) -> np.ndarray:
    params = np.empty(_N_PARAMS)
    params[_M_V] = vehicle.mass
    params[_K_V] = vehicle.stiffness
    params[_C_V] = vehicle.damping
    params[_GRAV] = GRAVITY
    params[_SPEED] = speed
    params[_START] = bridge_start
    params[_SPAN] = span
    return params


# ---------------------------------------------------------------------------- results
@dataclass(frozen=True, eq=False)
class ModalCrossing(_CrossingViews):
    """One crossing of the many-mode model (SI, displacements positive up).

    Attributes
    ----------
    time, position
        Time [s] and wheel station [m] at every node.
    vehicle_displacement, vehicle_velocity
        ``u_v`` [m] from the static position and its rate [m/s].
    modal_coordinates, modal_velocities
        ``q_n`` and ``dq_n/dt``, shape ``(n_time, N)`` [kg^1/2 m, kg^1/2 m/s].
    midspan_displacement
        ``(n_time, n_spans)`` [m].
    contact_force
        Force pressing on the road ``R = m_v g + F`` [N].
    daf
        Per span, the largest downward midspan deflection while the wheel is on it over the
        model's static deflection.
    static_deflection
        The largest static midspan deflection under the weight over all load positions [m],
        from the same N modes.
    frequencies_hz
        The N natural frequencies [Hz].
    dt
        Largest time step [s].
    """

    bridge: Bridge
    vehicle: Vehicle
    speed: float
    bridge_start: float
    modes: BeamModes
    time: np.ndarray
    position: np.ndarray
    vehicle_displacement: np.ndarray
    vehicle_velocity: np.ndarray
    modal_coordinates: np.ndarray
    modal_velocities: np.ndarray
    midspan_displacement: np.ndarray
    contact_force: np.ndarray
    span_of_step: np.ndarray
    daf: np.ndarray
    static_deflection: float
    dt: float
    coupled: bool = True
    convective: bool = True
    notes: tuple[str, ...] = field(default=())

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Natural frequencies of the N modes [Hz]."""
        return self.modes.frequencies_hz

    def displacement_at(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """Deflection history ``sum_n phi_n(x) q_n(t)`` [m] at stations from the bridge start.

        Returns shape ``(n_time,)`` for one station, ``(n_time, n_x)`` for several.
        """
        values = self.modal_coordinates @ self.modes.shape(x_from_bridge_start).T
        return values[:, 0] if np.ndim(x_from_bridge_start) == 0 else values

    def moment_at(self, x_from_bridge_start: float | np.ndarray) -> np.ndarray:
        """Bending moment ``EI sum_n phi_n''(x) q_n(t)`` [N m], sagging positive.

        From the curvature of the modes; it converges more slowly in N than the deflection
        (mode n contributes in proportion to ``1/n^2`` rather than ``1/n^4``).
        """
        values = self.bridge.EI * (
            self.modal_coordinates @ self.modes.curvature(x_from_bridge_start).T
        )
        return values[:, 0] if np.ndim(x_from_bridge_start) == 0 else values

    def __repr__(self) -> str:
        spans = "1 span" if self.bridge.n_spans == 1 else "2 spans"
        dafs = ", ".join(f"{d:.3f}" for d in self.daf)
        return (
            f"ModalCrossing({spans}, {self.modes.count} modes, {self.speed:.2f} m/s, "
            f"dt {self.dt * 1e3:.3f} ms: DAF {dafs})"
        )


# ---------------------------------------------------------------------------- entry points
def simulate_modal(
    bridge: Bridge,
    vehicle: Vehicle,
    profile: Profile,
    speed: float,
    bridge_start: float,
    modes: int,
    coupled: bool = True,
    convective: bool = True,
    dt: float | None = None,
    free_vibration: float = 0.0,
) -> ModalCrossing:
    """Simulate one crossing with the bridge's first ``modes`` exact beam modes.

    Same arguments and conventions as :func:`vbi_lib.simulate`, plus ``modes``.  The truck
    starts at ``profile.x[0]`` at rest, drives at ``speed`` and the run ends when it leaves
    the bridge (plus ``free_vibration`` seconds).

    Parameters
    ----------
    bridge, vehicle, profile
        The beam, the sprung mass and the road (metres).
    speed
        Vehicle speed [m/s].
    bridge_start
        Station of the first support [m].
    modes
        Number of beam modes N >= 1; ``modes=1`` is the study's model.
    coupled
        ``False``: the contact force is that of the truck on a rigid road (92)-(99).
    convective
        Keep ``v sum phi_n' q_n`` in the wheel's vertical velocity.
    dt
        Largest time step [s]; ``None`` for :func:`default_time_step` (and at least one
        step per profile sample).
    free_vibration
        Seconds to continue after the truck leaves the bridge.

    Returns
    -------
    ModalCrossing

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> from vbi_lib import units as u
    >>> from vbi_lib.modal import simulate_modal
    >>> bridge = vbi.Bridge(100 * u.ft, 2, 7.5e12 * u.lbf * u.inch**2, 4.6 * u.kip / u.ft / u.g)
    >>> truck = vbi.Vehicle.from_frequency(100 * u.slinch, 4.0, 0.10)
    >>> road = vbi.Profile.flat(550 * u.ft, 1 * u.inch)
    >>> run = simulate_modal(bridge, truck, road, 720 * u.inch / u.s, 320 * u.ft, modes=5)
    >>> run.frequencies_hz.round(2)
    array([ 3.  ,  4.68, 11.99, 15.18, 26.98])
    >>> run.daf.round(2)
    array([1.02, 1.04])
    """
    speed, bridge_start = _check_inputs(bridge, vehicle, profile, speed, bridge_start)
    modes = _check_modes(modes)
    free_vibration = check.non_negative("free_vibration", free_vibration)
    basis = beam_modes(bridge, modes)
    notes = []
    if dt is None:
        dt = default_time_step(bridge, vehicle, modes)
        notes.append(f"dt picked as {DEFAULT_OMEGA_DT} / omega = {dt * 1e3:.3f} ms")
    else:
        dt = check.positive("dt", dt)
    stop = bridge_start + bridge.length + speed * free_vibration
    grid = _grid(bridge, profile, speed, bridge_start, dt, stop)
    x, elevation, span_of_step, dt_max = grid.x, grid.elevation, grid.span_of_step, grid.dt_max
    n = x.size
    q = np.empty((n, modes))
    qd = np.empty((n, modes))
    veh = np.empty((n, 2))
    contact = np.empty(n)
    peaks = np.empty(bridge.n_spans + 2)
    phi_mid = np.ascontiguousarray(basis.shape(np.array(bridge.midspans)))
    _modal_kernel(
        x,
        elevation,
        span_of_step,
        _parameters(vehicle, speed, bridge_start, bridge.span),
        basis.kind,
        basis.wavenumber,
        basis.amplitude,
        basis.omega,
        np.full(modes, bridge.damping_ratio),
        phi_mid,
        bool(coupled),
        bool(convective),
        q,
        qd,
        veh,
        contact,
        peaks,
    )
    static = np.array(_largest_static(bridge, modes)) * vehicle.weight
    notes.append(f"{n - 1} average-acceleration steps, largest {dt_max * 1e3:.3f} ms")
    return ModalCrossing(
        bridge=bridge,
        vehicle=vehicle,
        speed=speed,
        bridge_start=bridge_start,
        modes=basis,
        time=(x - x[0]) / speed,
        position=x,
        vehicle_displacement=veh[:, 0],
        vehicle_velocity=veh[:, 1],
        modal_coordinates=q,
        modal_velocities=qd,
        midspan_displacement=q @ phi_mid.T,
        contact_force=contact,
        span_of_step=span_of_step,
        daf=peaks[: bridge.n_spans] / static.max(),
        static_deflection=float(static.max()),
        dt=dt_max,
        coupled=bool(coupled),
        convective=bool(convective),
        notes=tuple(notes),
    )


def simulate_modal_many(
    bridges: Bridge | list[Bridge],
    vehicles: Vehicle | list[Vehicle],
    profiles: Profile | list[Profile],
    speeds: float | list[float] | np.ndarray,
    bridge_starts: float | list[float] | np.ndarray,
    modes: int | list[int] | np.ndarray,
    coupled: bool | list[bool] = True,
    convective: bool | list[bool] = True,
    dt: float | None = None,
) -> BatchResult:
    """DAF of many crossings with the many-mode model, compiled and run in parallel.

    Every argument but ``dt`` is one value or a list (``modes`` too: one number of modes per
    crossing); lists share one length and single values are repeated.  Results match
    :func:`simulate_modal` crossing by crossing; the result is a
    :class:`vbi_lib.BatchResult` (``daf`` is ``(n, 2)``, NaN for a missing second span).

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> from vbi_lib.modal import simulate_modal_many
    >>> b = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    >>> t = vbi.Vehicle.from_frequency(3.0e4, 3.0, 0.1)
    >>> r = simulate_modal_many(b, t, vbi.Profile.flat(130.0, 0.05), [10.0, 20.0], 100.0, 5)
    >>> r.daf.shape
    (2, 2)
    """
    args = {
        "bridges": bridges,
        "vehicles": vehicles,
        "profiles": profiles,
        "speeds": speeds,
        "bridge_starts": bridge_starts,
        "coupled": coupled,
        "convective": convective,
        "modes": modes,
    }
    n, expanded = _broadcast(args, "simulate_modal_many")
    if dt is not None:
        dt = check.positive("dt", dt)
    counts = [_check_modes(m) for m in expanded["modes"]]
    xs, es, spans, offsets = [], [], [], [0]
    params = np.empty((n, _N_PARAMS))
    dts = np.empty(n)
    phi_mid = np.full((n, 2, max(counts)), np.nan)
    statics = np.empty(n)
    kinds, kappas, amps, omegas, zetas = [], [], [], [], []
    grids: dict = {}
    for i in range(n):
        bridge = expanded["bridges"][i]
        vehicle = expanded["vehicles"][i]
        profile = expanded["profiles"][i]
        try:
            speed, start = _check_inputs(
                bridge, vehicle, profile, expanded["speeds"][i], expanded["bridge_starts"][i]
            )
        except ValueError as exc:
            raise ValueError(f"crossing {i}: {exc}") from None
        modes = counts[i]
        basis = beam_modes(bridge, modes)
        step = default_time_step(bridge, vehicle, modes) if dt is None else dt
        key = (id(profile), bridge.span, bridge.n_spans, speed, start, step)
        if key not in grids:
            grids[key] = _grid(bridge, profile, speed, start, step, start + bridge.length)
        grid = grids[key]
        xs.append(grid.x)
        es.append(grid.elevation)
        spans.append(grid.span_of_step)  # one entry per node, like x
        offsets.append(offsets[-1] + grid.x.size)
        params[i] = _parameters(vehicle, speed, start, bridge.span)
        dts[i] = grid.dt_max
        phi_mid[i, : bridge.n_spans, :modes] = basis.shape(np.array(bridge.midspans))
        statics[i] = max(_largest_static(bridge, modes)) * vehicle.weight
        kinds.append(basis.kind)
        kappas.append(basis.wavenumber)
        amps.append(basis.amplitude)
        omegas.append(basis.omega)
        zetas.append(np.full(modes, bridge.damping_ratio))
    peaks = np.full((n, 4), np.nan)
    _batch_kernel(
        np.asarray(offsets, dtype=np.int64),
        np.concatenate(xs),
        np.concatenate(es),
        np.concatenate(spans),
        params,
        np.concatenate(([0], np.cumsum(counts))).astype(np.int64),
        np.concatenate(kinds),
        np.concatenate(kappas),
        np.concatenate(amps),
        np.concatenate(omegas),
        np.concatenate(zetas),
        phi_mid,
        np.asarray(expanded["coupled"], dtype=np.bool_),
        np.asarray(expanded["convective"], dtype=np.bool_),
        peaks,
    )
    daf = np.full((n, 2), np.nan)
    force = np.empty(n)
    where = np.empty(n)
    for i, bridge in enumerate(expanded["bridges"]):
        ns = bridge.n_spans
        daf[i, :ns] = peaks[i, :ns] / statics[i]
        force[i] = peaks[i, ns] / expanded["vehicles"][i].weight
        where[i] = peaks[i, ns + 1]
    return BatchResult(daf, force, where, dts)


# ---------------------------------------------------------------------------- assessment
def assessment_inputs(
    table: object,
    profiles: dict[str, Profile],
    beam: str = "study",
    damping_ratio: float = 0.01,
) -> tuple[list[Bridge], list[Vehicle], list[Profile]]:
    """Bridges, trucks and roads of a model-assessment table like the study's Chapter 13.

    Every parameter comes from the row: the span, number of spans, midspan stiffness of the
    path and first frequency give the beam; mass, stiffness and damping coefficient give the
    truck.  Columns (US customary, as in the study): ``span_ft``, ``n_spans``,
    ``k_mid_lbf_per_in``, ``bridge_f1_hz``, ``vehicle_mass_slinch``,
    ``vehicle_k_lbf_per_in``, ``vehicle_c_lbf_s_per_in``, ``profile`` (a key of
    ``profiles``).

    Parameters
    ----------
    table
        A ``pandas.DataFrame`` (or anything with ``itertuples``) with the columns above.
    profiles
        Roads by name, stations and elevations in metres.
    beam
        ``"study"``: :meth:`Bridge.from_midspan_stiffness`, the one-coordinate model's rule
        (82)-(84); ``"exact"``: :func:`reference_beam`, the beam whose exact midspan
        stiffness is ``K_mid`` (the consistent choice for the many-mode model).
    damping_ratio
        Bridge damping ratio (the study: 1 %).

    Examples
    --------
    >>> import pandas as pd
    >>> row = dict(span_ft=40, n_spans=2, k_mid_lbf_per_in=721006, bridge_f1_hz=9.98,
    ...            vehicle_mass_slinch=200, vehicle_k_lbf_per_in=879290.0,
    ...            vehicle_c_lbf_s_per_in=2652.23, profile="flat")
    >>> road = Profile.flat(200.0, 0.0254)
    >>> b, v, p = assessment_inputs(pd.DataFrame([row]), {"flat": road}, beam="exact")
    >>> round(b[0].first_frequency_hz, 2), round(v[0].frequency_hz, 2)
    (9.98, 10.55)
    """
    from . import units as u

    if beam not in ("study", "exact"):
        raise ValueError(f"beam={beam!r} must be 'study' or 'exact'")
    make = Bridge.from_midspan_stiffness if beam == "study" else reference_beam
    bridges, vehicles, roads = [], [], []
    for i, row in enumerate(table.itertuples()):
        if row.profile not in profiles:
            raise ValueError(f"row {i}: profile {row.profile!r} is not among the roads given")
        bridges.append(
            make(
                row.span_ft * u.ft,
                int(row.n_spans),
                row.k_mid_lbf_per_in * u.lbf / u.inch,
                row.bridge_f1_hz,
                damping_ratio,
            )
        )
        vehicles.append(
            Vehicle(
                row.vehicle_mass_slinch * u.slinch,
                row.vehicle_k_lbf_per_in * u.lbf / u.inch,
                row.vehicle_c_lbf_s_per_in * u.lbf * u.s / u.inch,
            )
        )
        roads.append(profiles[row.profile])
    return bridges, vehicles, roads


def agreement(predicted: object, reference: object) -> dict[str, float]:
    """How well a model's DAFs match reference DAFs (for example a finite-element model's).

    Returns ``n``; ``r2``, the squared correlation coefficient; ``bias``, the mean relative
    error ``mean(predicted / reference - 1)``; ``mape``, the mean absolute relative error;
    and ``max_ape``, the largest absolute relative error.

    Examples
    --------
    >>> scores = agreement([1.1, 2.2, 2.7], [1.0, 2.0, 3.0])
    >>> {k: round(v, 4) for k, v in scores.items()}
    {'n': 3, 'r2': 0.9552, 'bias': 0.0333, 'mape': 0.1, 'max_ape': 0.1}
    """
    p = check.finite_array("predicted", predicted)
    f = check.finite_array("reference", reference)
    if p.shape != f.shape or p.size < 2:
        raise ValueError(
            f"predicted ({p.size}) and reference ({f.size}) need the same length, at least 2"
        )
    if (f <= 0).any():
        raise ValueError("reference DAFs must be positive")
    error = p / f - 1.0
    return {
        "n": int(p.size),
        "r2": float(np.corrcoef(p, f)[0, 1] ** 2),
        "bias": float(error.mean()),
        "mape": float(np.abs(error).mean()),
        "max_ape": float(np.abs(error).max()),
    }
