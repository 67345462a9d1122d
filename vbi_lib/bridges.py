r"""Bridges reduced to a beam with one generalised coordinate (study equations 33-45, 59-68, 82-84).

The deck along the truck's path is a uniform Euler-Bernoulli beam of ``n_spans`` equal spans
(one simple span, or two equal continuous spans).  Its deflection is
:math:`u_b(x, t) = \psi(x) z_b(t)` with the shape function

.. math:: \psi(x) = \sin(\pi x / L), \qquad 0 \le x \le N L,

a half sine on one span and a full (antisymmetric) sine over two spans.  The generalised
properties are (36)-(37), (62)-(63), (40)-(43):

.. math::
    m^* = \frac{N \bar m L}{2}, \qquad k^* = \frac{N \pi^4 EI}{2 L^3}, \qquad
    \omega_b = \sqrt{k^*/m^*} = \pi^2 \sqrt{\frac{EI}{\bar m L^4}}, \qquad
    c^* = 2 \zeta_b \omega_b m^* .

The first frequency of the one-coordinate model is the exact first frequency of the simple
span, and of the two-span beam (whose first mode is the antisymmetric one).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from . import _validation as check


@dataclass(frozen=True)
class Bridge:
    """A one- or two-span uniform beam, the bridge of the one-coordinate model.

    Parameters
    ----------
    span
        Length of each span ``L`` [m].
    n_spans
        1 (simple span) or 2 (two equal continuous spans).
    EI
        Flexural rigidity [N m^2].
    mass_per_length
        Mass per unit length ``mbar`` [kg/m].
    damping_ratio
        Fraction of critical damping of the first mode (mass-proportional), in [0, 1).

    Examples
    --------
    The study's validation beam (Table 2.13.1): 100 ft, 4.6 kip/ft, EI = 7.5e12 lb in^2.

    >>> from vbi_lib import units as u
    >>> b = Bridge(100 * u.ft, 1, 7.5e12 * u.lbf * u.inch**2, 4.6 * u.kip / u.ft / u.g)
    >>> round(b.first_frequency_hz, 2)
    3.0
    """

    span: float
    n_spans: int
    EI: float
    mass_per_length: float
    damping_ratio: float = 0.01

    def __post_init__(self) -> None:
        object.__setattr__(self, "span", check.positive("span", self.span))
        object.__setattr__(self, "n_spans", check.n_spans(self.n_spans))
        object.__setattr__(self, "EI", check.positive("EI", self.EI))
        object.__setattr__(
            self, "mass_per_length", check.positive("mass_per_length", self.mass_per_length)
        )
        object.__setattr__(
            self, "damping_ratio", check.damping_ratio("damping_ratio", self.damping_ratio)
        )

    # ------------------------------------------------------------------ constructors
    @classmethod
    def from_midspan_stiffness(
        cls,
        span: float,
        n_spans: int,
        k_mid: float,
        first_frequency_hz: float,
        damping_ratio: float = 0.01,
    ) -> Bridge:
        """The study's beam from a path's midspan stiffness and the first frequency (82)-(84).

        ``EI = K_mid L^3 / 48`` for one span (82) and ``EI = K_mid L^3 / pi^4`` for two (83);
        the mass per span ``pi^4 EI / ((2 pi f_1)^2 L^3)`` (84) then gives the frequency.

        Parameters
        ----------
        span
            Span length [m].
        n_spans
            1 or 2.
        k_mid
            Midspan stiffness of the path, load / deflection [N/m].
        first_frequency_hz
            First natural frequency of the bridge [Hz].
        damping_ratio
            Bridge damping ratio, default 1 %.

        Examples
        --------
        Table 2.13.8, row 1 (40 ft, one span, 9.95 Hz, K_mid = 587723 lb/in):

        >>> from vbi_lib import units as u
        >>> b = Bridge.from_midspan_stiffness(40 * u.ft, 1, 587723 * u.lbf / u.inch, 9.95)
        >>> f"{b.EI / (u.lbf * u.inch**2):.3e}", round(b.mass_per_span / u.slinch, 2)
        ('1.354e+12', 305.16)
        """
        span = check.positive("span", span)
        n_spans = check.n_spans(n_spans)
        k_mid = check.positive("k_mid", k_mid)
        frequency = check.positive("first_frequency_hz", first_frequency_hz)
        EI = k_mid * span**3 / (48.0 if n_spans == 1 else math.pi**4)
        return cls(span, n_spans, EI, mass_per_length_for(EI, span, frequency), damping_ratio)

    @classmethod
    def from_frequency(
        cls,
        span: float,
        n_spans: int,
        mass_per_length: float,
        first_frequency_hz: float,
        damping_ratio: float = 0.01,
    ) -> Bridge:
        """A beam of given mass whose EI gives the first frequency: ``EI = w^2 mbar L^4 / pi^4``.

        Examples
        --------
        Table 2.15.3, bridge 1 (100 ft, 2000 slinch in all, 2 Hz):

        >>> from vbi_lib import units as u
        >>> b = Bridge.from_frequency(100 * u.ft, 1, 2000 * u.slinch / (100 * u.ft), 2.0)
        >>> f"{b.EI / (u.lbf * u.inch**2):.3e}"
        '5.603e+12'
        """
        span = check.positive("span", span)
        mass_per_length = check.positive("mass_per_length", mass_per_length)
        omega = 2.0 * math.pi * check.positive("first_frequency_hz", first_frequency_hz)
        EI = omega**2 * mass_per_length * span**4 / math.pi**4
        return cls(span, n_spans, EI, mass_per_length, damping_ratio)

    # ------------------------------------------------------------------ derived
    @property
    def length(self) -> float:
        """Total length ``N L`` [m]."""
        return self.n_spans * self.span

    @property
    def mass_per_span(self) -> float:
        """Mass of one span ``mbar L`` [kg]."""
        return self.mass_per_length * self.span

    @property
    def first_frequency_hz(self) -> float:
        """First natural frequency ``(pi / 2 L^2) sqrt(EI / mbar)`` [Hz] (37), (63)."""
        return self.circular_frequency / (2.0 * math.pi)

    @property
    def circular_frequency(self) -> float:
        """``omega_b = pi^2 sqrt(EI / (mbar L^4))`` [rad/s]."""
        return math.pi**2 * math.sqrt(self.EI / (self.mass_per_length * self.span**4))

    @property
    def generalized_mass(self) -> float:
        """``m* = N mbar L / 2`` [kg] (36), (62)."""
        return self.n_spans * self.mass_per_length * self.span / 2.0

    @property
    def generalized_stiffness(self) -> float:
        """``k* = N pi^4 EI / (2 L^3)`` [N/m] (37), (63)."""
        return self.n_spans * math.pi**4 * self.EI / (2.0 * self.span**3)

    @property
    def generalized_damping(self) -> float:
        """``c* = 2 zeta omega_b m*`` [N s/m], mass-proportional damping (40)-(43), (66)."""
        return 2.0 * self.damping_ratio * self.circular_frequency * self.generalized_mass

    @property
    def midspans(self) -> tuple[float, ...]:
        """Positions of the midspans measured from the start of the bridge [m]."""
        return tuple((j + 0.5) * self.span for j in range(self.n_spans))

    def static_deflection(self, force: float) -> float:
        """The model's own midspan deflection under ``force`` at midspan [m] (90), (91).

        ``2 P L^3 / (pi^4 EI)`` for one span, ``P L^3 / (pi^4 EI)`` for two: in both cases
        ``P / k*``.  Positive number (magnitude of the downward deflection).

        Examples
        --------
        >>> b = Bridge(10.0, 1, 1e9, 1000.0)
        >>> round(b.static_deflection(1e5) * 1e3, 4)   # mm
        2.0532
        """
        return float(force) / self.generalized_stiffness

    def exact_static_deflection(self, force: float) -> float:
        """Exact beam midspan deflection under ``force`` at midspan [m] (38), (64).

        ``P L^3 / (48 EI)`` for one span; ``23 P L^3 / (1536 EI)`` for two equal continuous
        spans with the load at midspan of one span.
        """
        factor = 1.0 / 48.0 if self.n_spans == 1 else 23.0 / 1536.0
        return factor * float(force) * self.span**3 / self.EI

    def __repr__(self) -> str:
        spans = "1 span" if self.n_spans == 1 else "2 spans"
        return (
            f"Bridge({spans} x {self.span:.2f} m, f1 = {self.first_frequency_hz:.2f} Hz, "
            f"EI = {self.EI:.3e} N m^2, mbar = {self.mass_per_length:.0f} kg/m, "
            f"zeta = {self.damping_ratio:.1%})"
        )


def mass_per_length_for(EI: float, span: float, first_frequency_hz: float) -> float:
    """Mass per length [kg/m] that gives a beam of ``EI`` the first frequency (84).

    ``mbar = pi^4 EI / ((2 pi f_1)^2 L^4)``: the mass per span of (84) divided by ``L``.

    >>> round(mass_per_length_for(1e10, 20.0, 5.0), 3)
    6168.503
    """
    omega = 2.0 * math.pi * first_frequency_hz
    return math.pi**4 * EI / (omega**2 * span**4)


def reference_beam(
    span: float,
    n_spans: int,
    k_mid: float,
    first_frequency_hz: float,
    damping_ratio: float = 0.01,
) -> Bridge:
    """The uniform beam whose exact midspan stiffness and first frequency are the bridge's.

    The study's rule (82)-(83) makes the *one-coordinate* model's midspan stiffness equal
    ``K_mid``; for two spans that beam is 31 % too flexible as a real beam (65).  For the
    many-mode model the exact beam formulas are the consistent choice:
    ``EI = K_mid L^3 / 48`` for one span (38) and ``EI = 23 K_mid L^3 / 1536`` for two (64),
    and the mass per length ``pi^4 EI / ((2 pi f_1)^2 L^4)`` keeps the first frequency (84).
    For one span this is the study's beam.

    Parameters
    ----------
    span
        Span length [m].
    n_spans
        1 or 2.
    k_mid
        Midspan stiffness of the path, load / deflection with the load at midspan [N/m].
    first_frequency_hz
        First natural frequency [Hz].
    damping_ratio
        Modal damping ratio, default 1 %.

    Examples
    --------
    Table 2.13.8, row 3 (40 ft, two spans, 9.98 Hz): EI 1.459 times the study's 8.186e11.

    >>> from vbi_lib import units as u
    >>> b = reference_beam(40 * u.ft, 2, 721006 * u.lbf / u.inch, 9.98)
    >>> f"{b.EI / (u.lbf * u.inch**2):.4e}"
    '1.1940e+12'
    """
    span = check.positive("span", span)
    n_spans = check.n_spans(n_spans)
    k_mid = check.positive("k_mid", k_mid)
    frequency = check.positive("first_frequency_hz", first_frequency_hz)
    EI = k_mid * span**3 * (1.0 / 48.0 if n_spans == 1 else 23.0 / 1536.0)
    return Bridge(span, n_spans, EI, mass_per_length_for(EI, span, frequency), damping_ratio)


def shape_function_error(n_spans: int) -> float:
    """Error of the sine shape function in the midspan deflection under a midspan load (39), (65).

    The model's deflection ``P / k*`` against the exact beam value: one span
    ``1 - 96 / pi^4`` (1.45 %), two spans ``1 - 1536 / (23 pi^4)`` (31.4 %).

    Examples
    --------
    >>> round(shape_function_error(1), 4), round(shape_function_error(2), 3)
    (0.0145, 0.314)
    """
    n_spans = check.n_spans(n_spans)
    model = 2.0 / math.pi**4 if n_spans == 1 else 1.0 / math.pi**4
    exact = 1.0 / 48.0 if n_spans == 1 else 23.0 / 1536.0
    return 1.0 - model / exact
