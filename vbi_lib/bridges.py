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

Continuous bridges
------------------
:meth:`Bridge.continuous` builds a uniform beam continuous over any number of spans of any
lengths (pinned supports, no deflection at any of them).  Its exact modes come from
:func:`vbi_lib.modes` and its statics from :mod:`vbi_lib.beam_statics`; it runs with
``model="modal"``.  The one-coordinate model and the study's formulas (the generalised
properties, (82)-(84), (90)-(91)) hold for one span and two equal spans only, and refuse
other layouts with a message saying what to use instead.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property, lru_cache

from . import _validation as check
from . import display
from .continuous_beams import natural_wavenumbers, support_stations
from .ranges import RANGES, check_range, within_rounding


@dataclass(frozen=True)
class Bridge:
    """A uniform beam over one or more spans: the bridge along the truck's path.

    ``Bridge(span, n_spans, EI, mass_per_length)`` is the study's beam, one span or two equal
    continuous spans; :meth:`continuous` builds any other layout (``span_lengths``).  Every
    bridge gives its layout as :attr:`spans`, :attr:`supports` and :attr:`midspans`.

    Parameters
    ----------
    span
        Length of each span ``L`` [m] (for unequal spans, the longest).
    n_spans
        1 (simple span) or 2 (two equal continuous spans); any number with ``span_lengths``.
    EI
        Flexural rigidity [N m^2].
    mass_per_length
        Mass per unit length ``mbar`` [kg/m].
    damping_ratio
        Fraction of critical damping of every mode, in [0, 1).
    span_lengths
        The span lengths from the start of the bridge [m], for layouts other than the
        study's (set by :meth:`continuous`); ``None`` for ``n_spans`` equal spans of
        ``span``, and so for one span or two equal spans whichever way they are given (so
        that ``dataclasses.replace(bridge, span=...)`` works on the study's bridges).

    Raises
    ------
    TypeError
        A value that is not a number (text, a bool), ``n_spans`` that is not an int.
    ValueError
        A value outside its range of validity (:data:`vbi_lib.ranges.RANGES`: ``span``,
        ``EI``, ``mass_per_length``, ``bridge_damping_ratio`` and the first frequency they
        give, ``bridge_frequency``), named in the message; ``n_spans`` other than 1 or 2
        without ``span_lengths``; ``span`` and ``n_spans`` that disagree with them.

    Warns
    -----
    OutsideValidityWarning
        A span, mass, damping ratio or first frequency outside the intended (soft) range.

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
    span_lengths: tuple[float, ...] | None = None

    def __post_init__(self) -> None:
        given = self.span_lengths is not None
        object.__setattr__(self, "span", check_range("span", self.span, warn=not given))
        if not given:
            object.__setattr__(self, "n_spans", check.n_spans(self.n_spans))
        else:
            lengths = _span_lengths(self.span_lengths)
            if self.n_spans != len(lengths) or self.span != max(lengths):
                raise ValueError(
                    f"span={self.span!r} and n_spans={self.n_spans!r} must be the longest span "
                    f"and the number of spans of span_lengths={self.span_lengths!r}; build "
                    "continuous bridges with Bridge.continuous(spans, EI=..., mass_per_length=...)"
                )
            study = len(lengths) <= 2 and all(length == lengths[0] for length in lengths)
            object.__setattr__(self, "span_lengths", None if study else lengths)
        object.__setattr__(self, "EI", check_range("EI", self.EI))
        object.__setattr__(
            self, "mass_per_length", check_range("mass_per_length", self.mass_per_length)
        )
        zeta = check.damping_ratio("damping_ratio", self.damping_ratio)
        object.__setattr__(
            self, "damping_ratio", check_range("bridge_damping_ratio", zeta, "damping_ratio")
        )
        frequency = within_rounding("bridge_frequency", self.first_frequency_hz)
        try:
            check_range("bridge_frequency", frequency, "first_frequency_hz")
        except ValueError as exc:
            low, high = RANGES["bridge_frequency"].hard
            far = not low / 10 <= frequency <= 10 * high  # a unit slip, not a near miss
            hint = "check their units" if far else "adjust EI or the mass per length"
            raise ValueError(
                f"{exc}: EI={self.EI:.4g} N m^2 and mass_per_length={self.mass_per_length:.4g} "
                f"kg/m over spans {self.spans} m give no beam a vehicle crosses; {hint}"
            ) from None

    @classmethod
    def continuous(
        cls,
        spans: Sequence[float],
        *,
        EI: float,
        mass_per_length: float,
        damping_ratio: float = 0.01,
    ) -> Bridge:
        """A uniform beam continuous over ``spans`` (any number, any lengths), pinned supports.

        One span, or two equal spans, give the same bridge as ``Bridge(span, n_spans, ...)``
        (equal and with the same hash, so the same modes and results).  Run it with
        ``model="modal"``; its modes are exact (:func:`vbi_lib.modes`).

        Parameters
        ----------
        spans
            Span lengths from the start of the bridge [m], each > 0.
        EI
            Flexural rigidity [N m^2].
        mass_per_length
            Mass per unit length [kg/m].
        damping_ratio
            Fraction of critical damping of every mode, in [0, 1).

        Raises
        ------
        TypeError
            ``spans`` that is not a list of numbers.
        ValueError
            No spans, more than 50, a span outside 1 to 2000 m, or a bad EI, mass or damping
            (see :class:`Bridge`).

        Examples
        --------
        Three equal spans vibrate first at the simple span's frequency:

        >>> b = Bridge.continuous([20.0, 20.0, 20.0], EI=1e10, mass_per_length=5000.0)
        >>> b.supports, round(b.first_frequency_hz, 4) == round(Bridge(20.0, 1, 1e10, 5000.0)
        ...                                                      .first_frequency_hz, 4)
        ((0.0, 20.0, 40.0, 60.0), True)
        """
        lengths = _span_lengths(spans, warn=False)  # the bridge warns once, below
        return cls(max(lengths), len(lengths), EI, mass_per_length, damping_ratio, lengths)

    @property
    def spans(self) -> tuple[float, ...]:
        """The span lengths from the start of the bridge [m], ``n_spans`` of them."""
        if self.span_lengths is None:
            return (self.span,) * self.n_spans
        return self.span_lengths

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

        The book's :eq:`study-82` to :eq:`study-84`.

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
        span = check_range("span", span, warn=False)
        n_spans = check.n_spans(n_spans)
        k_mid = check_range("k_mid", k_mid)
        frequency = check_range("bridge_frequency", first_frequency_hz, "first_frequency_hz",
                                warn=False)  # fmt: skip
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
        span = check_range("span", span, warn=False)
        mass_per_length = check_range("mass_per_length", mass_per_length, warn=False)
        frequency = check_range("bridge_frequency", first_frequency_hz, "first_frequency_hz",
                                warn=False)  # fmt: skip
        omega = 2.0 * math.pi * frequency
        EI = omega**2 * mass_per_length * span**4 / math.pi**4
        return cls(span, n_spans, EI, mass_per_length, damping_ratio)

    # ------------------------------------------------------------------ layout
    @cached_property
    def equal_spans(self) -> bool:
        """Whether every span has the same length (computed once per bridge)."""
        return all(length == self.span for length in self.spans)

    @cached_property
    def study_layout(self) -> bool:
        """True for the study's beams, one span or two equal spans, where its formulas hold."""
        return self.n_spans <= 2 and self.equal_spans

    @property
    def length(self) -> float:
        """Total length ``sum L_j`` [m] (``N L`` for equal spans)."""
        return self.supports[-1]

    @cached_property
    def supports(self) -> tuple[float, ...]:
        """Stations of the supports from the start of the bridge [m], ``n_spans + 1`` of them.

        Computed once per bridge (a frozen object): every crossing and batch asks for them.
        """
        return tuple(float(s) for s in support_stations(self.spans))

    @property
    def midspans(self) -> tuple[float, ...]:
        """Positions of the midspans measured from the start of the bridge [m]."""
        if self.equal_spans:
            return tuple((j + 0.5) * self.span for j in range(self.n_spans))
        supports = self.supports
        return tuple(0.5 * (supports[j] + supports[j + 1]) for j in range(self.n_spans))

    @property
    def mass_per_span(self) -> float:
        """Mass of one span ``mbar L`` [kg] (equal spans only)."""
        if not self.equal_spans:
            raise ValueError(
                f"the spans {self.spans} differ, so there is no one mass per span; use "
                "mass_per_length * spans[j]"
            )
        return self.mass_per_length * self.span

    # ------------------------------------------------------------------ frequency
    @property
    def first_frequency_hz(self) -> float:
        """First natural frequency [Hz], ``(pi / 2 L^2) sqrt(EI / mbar)`` for equal spans (37).

        For unequal spans, the exact first frequency of the continuous beam
        (:func:`vbi_lib.continuous_beams.natural_wavenumbers`).
        """
        return self.circular_frequency / (2.0 * math.pi)

    @property
    def circular_frequency(self) -> float:
        """``omega_b = pi^2 sqrt(EI / (mbar L^4))`` [rad/s] for equal spans; exact for any layout.

        Over any number of equal spans the first mode is the simple span's (each span a half
        sine), so the formula holds; for unequal spans ``k_1^2 sqrt(EI / mbar)`` with the
        first root ``k_1`` of the continuous beam.
        """
        if self.equal_spans:
            return math.pi**2 * math.sqrt(self.EI / (self.mass_per_length * self.span**4))
        return _first_wavenumber(self.spans) ** 2 * math.sqrt(self.EI / self.mass_per_length)

    # ------------------------------------------------------------------ the study's model
    def _study_only(self, what: str) -> None:
        if not self.study_layout:
            raise NotImplementedError(
                f"{what} is the study's formula for one span or two equal spans; this bridge "
                f"has spans {self.spans} m.  Use model='modal' (exact modes of any layout) "
                "and vbi.beam_statics for the beam's statics"
            )

    @property
    def generalized_mass(self) -> float:
        """``m* = N mbar L / 2`` [kg] (36), (62); one span or two equal spans.

        The book's :eq:`study-36` and :eq:`study-62`.
        """
        self._study_only("generalized_mass")
        return self.n_spans * self.mass_per_length * self.span / 2.0

    @property
    def generalized_stiffness(self) -> float:
        """``k* = N pi^4 EI / (2 L^3)`` [N/m] (37), (63); one span or two equal spans.

        The book's :eq:`study-37` and :eq:`study-63`.
        """
        self._study_only("generalized_stiffness")
        return self.n_spans * math.pi**4 * self.EI / (2.0 * self.span**3)

    @property
    def generalized_damping(self) -> float:
        """``c* = 2 zeta omega_b m*`` [N s/m], mass-proportional damping (40)-(43), (66).

        The book's :eq:`study-43` and :eq:`study-66`.
        """
        return 2.0 * self.damping_ratio * self.circular_frequency * self.generalized_mass

    def static_deflection(self, force: float) -> float:
        """The model's own midspan deflection under ``force`` at midspan [m] (90), (91).

        The book's :eq:`study-90` and :eq:`study-91`.

        ``2 P L^3 / (pi^4 EI)`` for one span, ``P L^3 / (pi^4 EI)`` for two: in both cases
        ``P / k*``.  Positive number (magnitude of the downward deflection).

        Raises
        ------
        NotImplementedError
            For layouts other than one span or two equal spans.

        Examples
        --------
        >>> b = Bridge(10.0, 1, 1e9, 1000.0)
        >>> round(b.static_deflection(1e5) * 1e3, 4)   # mm
        2.0532
        """
        return float(force) / self.generalized_stiffness

    def exact_static_deflection(self, force: float) -> float:
        """Exact beam midspan deflection under ``force`` at midspan [m] (38), (64).

        The book's :eq:`study-38` and :eq:`study-64`.

        ``P L^3 / (48 EI)`` for one span; ``23 P L^3 / 1536 EI`` for two equal continuous
        spans with the load at midspan of one span.  Other layouts:
        :func:`vbi_lib.beam_statics.continuous_statics`.
        """
        self._study_only("exact_static_deflection")
        factor = 1.0 / 48.0 if self.n_spans == 1 else 23.0 / 1536.0
        return factor * float(force) * self.span**3 / self.EI

    def __repr__(self) -> str:
        # in the display units of the session (vbi_lib.display.set_units), SI by default
        if self.equal_spans:
            layout = "1 span" if self.n_spans == 1 else f"{self.n_spans} spans"
            layout += f" x {display.short(self.span, 'length')}"
        else:
            lengths = (f"{display.value(length, 'length'):.2f}" for length in self.spans)
            layout = "spans " + " + ".join(lengths) + f" {display.symbol('length')}"
        return (
            f"Bridge({layout}, f1 = {self.first_frequency_hz:.2f} Hz, "
            f"EI = {display.short(self.EI, 'flexural_rigidity')}, "
            f"mbar = {display.short(self.mass_per_length, 'mass_per_length')}, "
            f"zeta = {self.damping_ratio:.1%})"
        )


def _span_lengths(spans: object, warn: bool = True) -> tuple[float, ...]:
    """Span lengths as a tuple of floats, each within the range of ``span``."""
    if isinstance(spans, str | bytes) or not hasattr(spans, "__len__"):
        raise TypeError(f"spans={spans!r} must be a list of one or more span lengths [m]")
    if len(spans) < 1:
        raise ValueError(f"spans={spans!r} must be a list of one or more span lengths [m]")
    check_range("n_spans", len(spans), "len(spans)", warn=False)
    return tuple(
        check_range("span", length, f"spans[{j}]", warn=warn) for j, length in enumerate(spans)
    )


@lru_cache(maxsize=256)
def _first_wavenumber(spans: tuple[float, ...]) -> float:
    return float(natural_wavenumbers(spans, 1)[0])


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
    span = check_range("span", span, warn=False)
    n_spans = check.n_spans(n_spans)
    k_mid = check_range("k_mid", k_mid)
    frequency = check_range("bridge_frequency", first_frequency_hz, "first_frequency_hz",
                            warn=False)  # fmt: skip
    EI = k_mid * span**3 * (1.0 / 48.0 if n_spans == 1 else 23.0 / 1536.0)
    return Bridge(span, n_spans, EI, mass_per_length_for(EI, span, frequency), damping_ratio)


def shape_function_error(n_spans: int) -> float:
    """Error of the sine shape function in the midspan deflection under a midspan load (39), (65).

    The book's :eq:`study-39` and :eq:`study-65`.

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
