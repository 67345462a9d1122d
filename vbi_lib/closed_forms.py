r"""Textbook solutions used as references: a moving force, beam statics, a base-excited mass.

Each closed form is written here once; the tests and the book compare the models with it.

**A constant force crossing a simply supported beam** (Frýba 1972, *Vibration of Solids
and Structures under Moving Loads*, ch. 1; Biggs 1964, *Introduction to Structural
Dynamics*, ch. 8).  An undamped uniform beam of span :math:`L`, at rest, is crossed by a
force :math:`P` entering at :math:`t = 0` at speed :math:`v`.  In its modes
:math:`\sin(n\pi x/L)`, with :math:`\omega_n = n^2 \omega_1` and the force at
:math:`\tau = vt/L \in [0, 1]`,

.. math::
    \frac{w(x, t)}{w_0} = \sum_{n=1}^{N} \frac{\sin(n\pi x/L)}{n^4}\,
    \frac{\sin(n\pi\tau) - \frac{\alpha}{n}\sin\!\left(\frac{n^2\pi\tau}{\alpha}\right)}
         {1 - \alpha^2/n^2},
    \qquad \alpha = \frac{v}{2 f_1 L}, \qquad w_0 = \frac{2 P L^3}{\pi^4 EI},

:math:`w` positive in the direction of the force.  :math:`w_0` is the one-mode static
midspan deflection, :math:`\omega = \pi v / L` the forcing frequency of mode 1 and
:math:`\alpha = \omega/\omega_1`.  With :math:`N = 1` at midspan this is the study's one-
coordinate model under a constant force (the decoupled model on a smooth road); its peak while
the force is on the span is 1.7685 :math:`w_0` at :math:`\alpha = 0.617` (1.743 of
:math:`PL^3/48EI`); the converged series peaks at 1.732 of :math:`PL^3/48EI` near
:math:`\alpha = 0.62`.  Where :math:`\alpha/n \to 1` (resonance of mode :math:`n`) the
term tends to :math:`(\sin\theta - \theta\cos\theta)/2`, :math:`\theta = n\pi\tau`; the
code evaluates an algebraically equal form without the :math:`0/0`, exact at and near
resonance.  Damping is left out: the published values are for the undamped beam, and 1 %
damping changes the peak of one crossing only slightly.

**Statics of a uniform beam under a point load** :math:`P` at :math:`a` (deflection positive
down with the load, sagging moment positive, shear :math:`V = dM/dx`).  One simple span,
:math:`b = L - a`:

.. math::
    w = \frac{P b x (L^2 - b^2 - x^2)}{6 L EI}, \quad M = \frac{P b x}{L}, \quad
    V = \frac{P b}{L} \qquad (x \le a),

and the mirror image for :math:`x \ge a`: midspan :math:`PL^3/48EI` (the study's 38) and
:math:`PL/4`.  Two equal continuous spans: the three-moment equation gives the moment over
the middle support for a load in span 1, :math:`M_B = -P a (L^2 - a^2) / (4 L^2)`
(:math:`-3PL/32` at midspan), and each span is a simple span carrying its own load plus the
end moment :math:`M_B`, which adds :math:`M_B\, s (L^2 - s^2)/(6 L EI)` to the deflection,
:math:`M_B s / L` to the moment and :math:`\pm M_B / L` to the shear (:math:`s` the distance
from the span's outer support).  Midspan of the loaded span: :math:`23PL^3/1536EI` (64).

**A sprung mass on a harmonic road** (steady state of base excitation; e.g. Chopra,
*Dynamics of Structures*, §3.6).  With frequency ratio :math:`r = \omega/\omega_n` and damping
ratio :math:`\zeta`, the mass moves :math:`T_d` times the road amplitude and the dynamic
contact force is :math:`r^2 T_d` times :math:`k Y`:

.. math::
    T_d = \sqrt{\frac{1 + (2\zeta r)^2}{(1 - r^2)^2 + (2\zeta r)^2}}, \qquad
    T_F = r^2 T_d = \frac{m \omega^2 |U|}{k Y}.

Everything is vectorised (NumPy broadcasting: arrays in, arrays out) and in SI units.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from scipy.optimize import minimize_scalar

from . import _validation as check

__all__ = [
    "BeamStatics",
    "contact_force_transmissibility",
    "displacement_transmissibility",
    "moving_force_daf",
    "moving_force_deflection",
    "moving_force_peak",
    "moving_force_response",
    "point_load_statics",
    "speed_parameter",
]

#: Modes :func:`moving_force_daf` sums by default: the midspan series is then converged to
#: about 1e-6 (the odd terms fall as ``1/n^4``).
CONVERGED_MODES = 51


# ---------------------------------------------------------------------------- moving force
def speed_parameter(
    speed: float | np.ndarray, span: float | np.ndarray, first_frequency_hz: float | np.ndarray
) -> np.ndarray:
    """Frýba's speed parameter ``alpha = v / (2 f_1 L)`` [-]: forcing over first frequency.

    Parameters
    ----------
    speed
        Speed of the force [m/s].
    span
        Span length [m].
    first_frequency_hz
        First natural frequency of the simply supported beam [Hz].

    Examples
    --------
    >>> float(speed_parameter(24.68, 10.0, 2.0))
    0.617
    """
    v = _positive_array("speed", speed)
    length = _positive_array("span", span)
    frequency = _positive_array("first_frequency_hz", first_frequency_hz)
    return v / (2.0 * frequency * length)


def moving_force_response(
    alpha: float | np.ndarray,
    tau: float | np.ndarray,
    section: float | np.ndarray = 0.5,
    modes: int = 1,
) -> np.ndarray:
    r"""Deflection over :math:`w_0 = 2PL^3/(\pi^4 EI)` under a force crossing the span (Frýba).

    The series of the module docstring, modes ``n = 1..modes``, undamped, the beam at rest
    when the force enters.

    Parameters
    ----------
    alpha
        Speed parameter ``v / (2 f_1 L)`` (> 0), :func:`speed_parameter`.
    tau
        Position of the force as a fraction of the span, ``v t / L``, in ``[0, 1]`` (the
        force on the span; afterwards the beam vibrates freely, which this does not give).
    section
        Section ``x / L`` where the deflection is read, in ``[0, 1]``; default midspan.
    modes
        Number of modes summed (1: the study's one-coordinate model).

    Returns
    -------
    ndarray
        ``w / w0``, positive in the direction of the force, broadcast over ``alpha``,
        ``tau`` and ``section``.

    Raises
    ------
    ValueError
        ``alpha <= 0``, ``tau`` or ``section`` outside ``[0, 1]``, ``modes < 1``.

    Examples
    --------
    One mode at ``alpha = 0.617``: the largest midspan value, near ``tau = 0.77``, is 1.7685.

    >>> import numpy as np
    >>> w = moving_force_response(0.617, np.linspace(0.0, 1.0, 100001))
    >>> round(float(w.max()), 4)
    1.7685

    At resonance (``alpha = 1``) the closed form is ``(sin pi tau - pi tau cos pi tau) / 2``:

    >>> round(float(moving_force_response(1.0, 1.0)), 6), round(float(np.pi / 2), 6)
    (1.570796, 1.570796)
    """
    alpha = _positive_array("alpha", alpha)
    tau = _unit_interval("tau", tau, "the force's position v t / L while it is on the span")
    section = _unit_interval("section", section, "the section x / L")
    n = _mode_range(modes)
    alpha, tau, section = np.broadcast_arrays(alpha, tau, section)
    a, t, s = alpha[..., None], tau[..., None], section[..., None]
    beta = a / n  # forcing over natural frequency of mode n
    theta = n * np.pi * t
    phi = theta / beta  # n^2 pi tau / alpha: mode n's own phase
    # (sin theta - beta sin phi) / (1 - beta^2), rewritten with sin A - sin B so that
    # beta -> 1 is no 0/0: -2 cos((theta+phi)/2) sin((theta-phi)/2) / (1-beta) is
    # -(theta/beta) cos((theta+phi)/2) sinc(theta (1-beta) / (2 pi beta))
    delta = 1.0 - beta
    transient = (
        -(theta / beta)
        * np.cos(0.5 * (theta + phi))
        * np.sinc(theta * delta / (2.0 * np.pi * beta))
    )
    term = (transient + np.sin(phi)) / (1.0 + beta)
    return np.sum(np.sin(n * np.pi * s) / n**4 * term, axis=-1)


def moving_force_deflection(
    x: float | np.ndarray,
    t: float | np.ndarray,
    force: float,
    speed: float,
    span: float,
    EI: float,
    mass_per_length: float,
    modes: int = 1,
) -> np.ndarray:
    """Deflection [m] of a simply supported beam crossed by a constant force (Frýba), SI.

    ``w0 * moving_force_response(alpha, v t / L, x / L, modes)`` with
    ``w0 = 2 P L^3 / (pi^4 EI)`` and ``alpha = v / (2 f_1 L)``,
    ``f_1 = (pi / 2 L^2) sqrt(EI / mbar)``.

    Parameters
    ----------
    x
        Section from the support where the force enters [m], in ``[0, span]``.
    t
        Time since the force entered [s], in ``[0, span / speed]``.
    force
        The force ``P`` [N] (its sign carries to the deflection).
    speed
        Speed [m/s].
    span, EI, mass_per_length
        Span [m], flexural rigidity [N m^2] and mass per length [kg/m] of the beam.
    modes
        Number of modes summed.

    Returns
    -------
    ndarray
        Deflection [m], in the direction of the force, broadcast over ``x`` and ``t``.

    Examples
    --------
    A slow crossing reads the static deflection: the force at midspan, 51 modes,
    ``P L^3 / 48 EI`` = 1 mm here.

    >>> L, EI, P = 10.0, 1e9, 48e3   # P L^3 / (48 EI) = 1e-3 m
    >>> w = moving_force_deflection(5.0, 5.0 / 0.01, P, 0.01, L, EI, 1000.0, modes=51)
    >>> round(float(w) * 1e3, 4)
    1.0
    """
    span = check.positive("span", span)
    EI = check.positive("EI", EI)
    mass_per_length = check.positive("mass_per_length", mass_per_length)
    speed = check.positive("speed", speed)
    force = _finite("force", force)
    first = math.pi / (2.0 * span**2) * math.sqrt(EI / mass_per_length)
    alpha = speed / (2.0 * first * span)
    tau = np.asarray(t, dtype=float) * speed / span
    tau = np.where(np.abs(tau - 1.0) < 1e-12, 1.0, tau)  # the last instant, despite rounding
    w0 = 2.0 * force * span**3 / (math.pi**4 * EI)
    return w0 * moving_force_response(alpha, tau, np.asarray(x, dtype=float) / span, modes)


def moving_force_peak(
    alpha: float | np.ndarray, modes: int = 1, section: float = 0.5
) -> np.ndarray:
    """Largest ``w / w0`` at a section while the force is on the span (``0 <= tau <= 1``).

    The response is sampled finely enough to resolve the vibration of the first three modes,
    and the best sample is refined with a bounded scalar search (to ``1e-12`` in ``tau``).

    Parameters
    ----------
    alpha
        Speed parameter(s) ``v / (2 f_1 L)``, each > 0.
    modes
        Number of modes summed.
    section
        Section ``x / L``; default midspan.

    Returns
    -------
    ndarray
        Peak ``w / w0``, one per ``alpha``.

    Examples
    --------
    >>> [round(float(p), 4) for p in moving_force_peak([0.617, 1.0])]
    [1.7685, 1.5708]
    """
    alpha = _positive_array("alpha", alpha)
    _unit_interval("section", section, "the section x / L")
    _mode_range(modes)
    peaks = np.empty(alpha.shape)
    for index, a in np.ndenumerate(alpha):
        peaks[index] = _peak_over_crossing(float(a), modes, float(section))
    return peaks


def moving_force_daf(alpha: float | np.ndarray, modes: int = CONVERGED_MODES) -> np.ndarray:
    """DAF of the midspan deflection: peak over the crossing / exact static ``P L^3 / 48 EI``.

    ``moving_force_peak(alpha, modes) * w0 / (P L^3 / 48 EI)`` with
    ``w0 / (P L^3 / 48 EI) = 96 / pi^4``.  With the default 51 modes this is the beam's
    converged DAF (peak 1.732 near ``alpha = 0.62``); with ``modes=1`` the one-mode response
    over the exact static deflection (1.743 at ``alpha = 0.617``).

    Examples
    --------
    >>> round(float(moving_force_daf(0.617, modes=1)), 3)
    1.743
    >>> round(float(moving_force_daf(0.62)), 3)
    1.732
    """
    return moving_force_peak(alpha, modes) * (96.0 / math.pi**4)


def _peak_over_crossing(alpha: float, modes: int, section: float) -> float:
    """Largest ``moving_force_response`` over ``tau in [0, 1]`` for one ``alpha``."""
    # resolve the free vibration of modes 1-3 (n^2 / (2 alpha) cycles each) with 40 points
    # a cycle; higher modes carry at most alpha / n^5 of w0 and are left to the refinement
    cycles = min(modes, 3) ** 2 / (2.0 * alpha)
    count = int(min(2_000_001, max(4001, 40.0 * cycles)))
    tau = np.linspace(0.0, 1.0, count)
    values = _response_1d(alpha, tau, modes, section)
    best = int(np.argmax(values))
    low, high = tau[max(best - 1, 0)], tau[min(best + 1, count - 1)]
    found = minimize_scalar(
        lambda s: -float(_response_1d(alpha, np.array([s]), modes, section)[0]),
        bounds=(low, high),
        method="bounded",
        options={"xatol": 1e-12},
    )
    return float(max(values[best], -found.fun))


def _response_1d(alpha: float, tau: np.ndarray, modes: int, section: float) -> np.ndarray:
    """``moving_force_response`` for one ``alpha`` over many ``tau``, in chunks (memory)."""
    out = np.empty(tau.size)
    step = max(1, 2_000_000 // modes)
    for start in range(0, tau.size, step):
        out[start : start + step] = moving_force_response(
            alpha, tau[start : start + step], section, modes
        )
    return out


# ---------------------------------------------------------------------------- statics
class BeamStatics(NamedTuple):
    """Deflection [m], bending moment [N m] and shear [N] at the sections asked.

    Deflection positive in the direction of the load (down), moment positive sagging,
    shear ``V = dM/dx`` (at the load itself, the value just to its left).
    """

    deflection: np.ndarray
    moment: np.ndarray
    shear: np.ndarray


def point_load_statics(
    x: float | np.ndarray,
    load_position: float | np.ndarray,
    span: float,
    EI: float,
    n_spans: int = 1,
    force: float = 1.0,
) -> BeamStatics:
    """Exact statics of a uniform beam under a point load: one simple span or two equal spans.

    Euler-Bernoulli beam, pinned supports at ``0, L`` (and ``2L``), load ``force`` at
    ``load_position``; the formulas are in the module docstring.  The support reactions come
    from the three-moment equation (two spans, load ``P`` at ``a`` in span 1:
    ``M_B = -P a (L^2 - a^2) / (4 L^2)``, ``R_A = (P (L - a) + M_B) / L``, ``R_C = M_B / L``,
    ``R_B = P - R_A - R_C``; mirrored for a load in span 2); moment and shear follow by
    statics, ``M(x) = sum R_s (x - s) - P (x - a)`` over the supports and load left of ``x``.

    Parameters
    ----------
    x
        Sections from the first support [m], in ``[0, n_spans * span]``.
    load_position
        Position of the load from the first support [m], same range; broadcast with ``x``
        (an influence line: fix ``x``, vary ``load_position``).
    span
        Length of each span ``L`` [m].
    EI
        Flexural rigidity [N m^2].
    n_spans
        1 (simple span) or 2 (two equal continuous spans).
    force
        The load ``P`` [N], positive down.

    Returns
    -------
    BeamStatics
        ``deflection`` [m] (down positive), ``moment`` [N m] (sagging positive), ``shear`` [N]
        (``dM/dx``; at a section holding the load or a support, the value just to its left,
        and at ``x = 0`` just to its right), broadcast over ``x`` and ``load_position``.

    Raises
    ------
    ValueError
        A section or load off the beam, ``n_spans`` other than 1 or 2, a non-positive span
        or EI.

    Examples
    --------
    The study's (38) and (64), and the simple span's ``P L / 4`` and ``P / 2``:

    >>> one = point_load_statics(5.0, 5.0, span=10.0, EI=1.0)
    >>> float(one.deflection * 48 / 10.0**3), float(one.moment), float(one.shear)
    (1.0, 2.5, 0.5)
    >>> two = point_load_statics(5.0, 5.0, span=10.0, EI=1.0, n_spans=2)
    >>> round(float(two.deflection * 1536 / (23 * 10.0**3)), 12)
    1.0
    >>> float(point_load_statics(10.0, 5.0, span=10.0, EI=1.0, n_spans=2).moment)  # -3PL/32
    -0.9375
    """
    span = check.positive("span", span)
    EI = check.positive("EI", EI)
    n_spans = check.n_spans(n_spans)
    force = _finite("force", force)
    length = n_spans * span
    x = _on_beam("x", x, length)
    a = _on_beam("load_position", load_position, length)
    x, a = np.broadcast_arrays(x, a)
    if n_spans == 1:
        deflection = _simple_span_deflection(x, a, span, EI, force)
        reactions = [force * (span - a) / span]
    else:
        # a load in span 2 is the mirror image of one in span 1
        second = a > span
        near = np.where(second, length - a, a)  # the load's distance from its outer support
        deflection = _two_span_deflection(np.where(second, length - x, x), near, span, EI, force)
        support = -force * near * (span**2 - near**2) / (4.0 * span**2)  # M_B
        outer = (force * (span - near) + support) / span  # reaction of the loaded span's end
        far = support / span  # reaction of the other end (downward: negative)
        first = np.where(second, far, outer)
        reactions = [first, force - outer - far]
    # statics from the left: the reactions at supports s = 0, L (left of x) and the load
    moment = np.zeros(x.shape)
    shear = np.zeros(x.shape)
    for j, reaction in enumerate(reactions):
        left = (x > j * span) | (j == 0)
        moment = moment + np.where(left, reaction * (x - j * span), 0.0)
        shear = shear + np.where(left, reaction, 0.0)
    passed = (x > a) | ((x == 0.0) & (a == 0.0))
    moment = moment - np.where(passed, force * (x - a), 0.0)
    shear = shear - np.where(passed, force, 0.0)
    return BeamStatics(deflection, moment, shear)


def _simple_span_deflection(
    x: np.ndarray, a: np.ndarray, L: float, EI: float, P: float
) -> np.ndarray:
    """Deflection of a simple span ``[0, L]`` under ``P`` at ``a``, down positive."""
    b = L - a
    r = L - x  # distance from the far support
    w = np.where(x <= a, P * b * x * (L**2 - b**2 - x**2), P * a * r * (L**2 - a**2 - r**2))
    return w / (6.0 * L * EI)


def _two_span_deflection(x: np.ndarray, a: np.ndarray, L: float, EI: float, P: float) -> np.ndarray:
    """Two equal spans ``[0, L], [L, 2L]``, load ``P`` at ``a <= L``: each span a simple span
    with the middle-support moment ``M_B`` adding ``M_B s (L^2 - s^2) / (6 L EI)``."""
    support = -P * a * (L**2 - a**2) / (4.0 * L**2)  # M_B, three-moment equation
    first = x <= L
    s = np.where(first, x, 2.0 * L - x)  # distance from the span's outer support
    end_moment = support * s * (L**2 - s**2) / (6.0 * L * EI)
    loaded = _simple_span_deflection(np.minimum(x, L), a, L, EI, P)
    return np.where(first, loaded, 0.0) + end_moment


# ---------------------------------------------------------------------------- base excitation
def displacement_transmissibility(
    frequency_ratio: float | np.ndarray, damping_ratio: float | np.ndarray
) -> np.ndarray:
    """Steady-state ``|U / Y|`` of a sprung mass on a harmonic road (base excitation).

    ``T_d = sqrt((1 + (2 zeta r)^2) / ((1 - r^2)^2 + (2 zeta r)^2))`` with
    ``r = omega / omega_n``; 1 at ``r = 0`` and at ``r = sqrt(2)`` for any damping,
    ``sqrt(1 + 4 zeta^2) / (2 zeta)`` at ``r = 1``; infinite at ``r = 1`` without damping.

    Parameters
    ----------
    frequency_ratio
        ``r``: excitation frequency (``speed / wavelength``) over the sprung mass's undamped
        natural frequency, >= 0.
    damping_ratio
        ``zeta``, >= 0.

    Examples
    --------
    >>> [round(float(displacement_transmissibility(r, 0.1)), 4) for r in (0.0, 1.0, 2**0.5)]
    [1.0, 5.099, 1.0]
    """
    r, zeta = _ratios(frequency_ratio, damping_ratio)
    numerator = 1.0 + (2.0 * zeta * r) ** 2
    denominator = (1.0 - r**2) ** 2 + (2.0 * zeta * r) ** 2
    with np.errstate(divide="ignore"):
        return np.sqrt(numerator / denominator)


def contact_force_transmissibility(
    frequency_ratio: float | np.ndarray, damping_ratio: float | np.ndarray
) -> np.ndarray:
    """Steady-state dynamic contact force of a sprung mass on a harmonic road, over ``k Y``.

    ``T_F = r^2 T_d``: the force the road feels beyond the weight has amplitude
    ``m omega^2 |U| = k Y r^2 T_d`` (the mass's inertia); 0 at ``r = 0``, equal to
    ``r^2`` at ``r = sqrt(2)``.  Divide by the weight to get the amplitude of the contact-force
    amplification: ``k Y T_F / (m g)``.

    Parameters
    ----------
    frequency_ratio, damping_ratio
        As :func:`displacement_transmissibility`.

    Examples
    --------
    >>> round(float(contact_force_transmissibility(2**0.5, 0.2)), 6)
    2.0
    """
    r, _ = _ratios(frequency_ratio, damping_ratio)
    return r**2 * displacement_transmissibility(frequency_ratio, damping_ratio)


# ---------------------------------------------------------------------------- input checks
def _finite(name: str, value: float) -> float:
    return check.finite(name, value)


def _as_array(name: str, values: object) -> np.ndarray:
    array = check.real_array(name, values)
    if not np.isfinite(array).all():
        raise ValueError(f"{name}={values!r} must be finite (no NaN or infinity)")
    return array


def _positive_array(name: str, values: object) -> np.ndarray:
    array = _as_array(name, values)
    if (array <= 0).any():
        raise ValueError(f"{name}={values!r} must be greater than zero")
    return array


def _unit_interval(name: str, values: object, meaning: str) -> np.ndarray:
    array = _as_array(name, values)
    if ((array < 0) | (array > 1)).any():
        raise ValueError(f"{name}={values!r} must lie in [0, 1]: it is {meaning}")
    return array


def _on_beam(name: str, values: object, length: float) -> np.ndarray:
    array = _as_array(name, values)
    if ((array < 0) | (array > length)).any():
        raise ValueError(
            f"{name}={values!r} must lie on the beam, 0 to {length:g} m from the first support"
        )
    return array


def _mode_range(modes: int) -> np.ndarray:
    return np.arange(1, check.integer("modes", modes, low=1, high=100_000) + 1, dtype=float)


def _ratios(frequency_ratio: object, damping_ratio: object) -> tuple[np.ndarray, np.ndarray]:
    r = _as_array("frequency_ratio", frequency_ratio)
    zeta = _as_array("damping_ratio", damping_ratio)
    if (r < 0).any():
        raise ValueError(f"frequency_ratio={frequency_ratio!r} must be >= 0")
    if (zeta < 0).any():
        raise ValueError(f"damping_ratio={damping_ratio!r} must be >= 0")
    return r, zeta
