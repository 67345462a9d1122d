r"""Road profiles: the elevation the wheel follows, on the approach and on the bridge.

A :class:`Profile` is a list of stations ``x`` (strictly increasing, metres along the road)
and elevations (metres, positive up).  Between samples the road is a straight line, which is
how the simulation reads it: every sample is a node of the time grid, so the wheel's vertical
velocity ``v dDelta/dx`` is exact on each segment.

The sampling rule of the study (32): to see a natural frequency ``f_max`` at the slowest
speed of interest ``v_min``, sample at least every ``S_max = v_min / (2 f_max)``.

Artificial roads follow ISO 8608 (study equation 87, :eq:`study-87` in the book): the
displacement power spectral density

.. math::
    G_d(n) = G_d(n_0) \left(\frac{n}{n_0}\right)^{-w}, \qquad n_0 = 0.1\ \text{cycle/m},

with ``G_d(n0)`` the study's "C10" [m^3] and waviness ``w``, realised as a sum of sines
:math:`\Delta(x) = \sum_i \sqrt{2 G_d(n_i)\,\Delta n} \cos(2\pi n_i x + \theta_i)` with
uniform random phases (:meth:`Profile.iso8608`).  Teaching shapes (harmonic, bump, ramp, step)
complete the module; measured profiles are read by :mod:`vbi_lib.profile_files`.

A generated road is checked through its parameters (:data:`vbi_lib.ranges.RANGES`); a road
given as data, through its samples (:mod:`vbi_lib.road_checks`: unevenness, slope, roughness
class), when it is read or first crossed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import scipy.fft

from . import _validation as check
from . import display
from ._road_marks import inherit, mark_checked
from .ranges import MAX_SAMPLES, RANGES, check_range

#: ISO 8608 road classes and the geometric mean of ``G_d(n0)`` of each [m^3].
ISO_CLASS_MEANS = {letter: 16e-6 * 4.0**i for i, letter in enumerate("ABCDEFGH")}

#: Default spatial-frequency band of :meth:`Profile.iso8608` [cycle/m] (ISO 8608's range).
ISO_BAND = (0.011, 2.83)


def max_sample_spacing(min_speed: float, max_frequency_hz: float) -> float:
    """Largest profile sample spacing ``S_max = v_min / (2 f_max)`` [m] (study equation 32).

    The book's :eq:`study-32`.

    A profile feature of wavelength ``lambda`` loads the truck at ``v / lambda`` Hz; to
    resolve loading up to ``f_max`` at the slowest speed ``v_min``, two samples per
    wavelength ``v_min / f_max`` are needed.

    Parameters
    ----------
    min_speed
        Slowest vehicle speed of interest [m/s].
    max_frequency_hz
        Highest bridge frequency that contributes to the response [Hz].

    Examples
    --------
    15 Hz and 20 mph give 11.7 in (the study rounds it to 10 in):

    >>> from vbi_lib import units as u
    >>> round(max_sample_spacing(20 * u.mph, 15.0) / u.inch, 1)
    11.7
    """
    speed = check.positive("min_speed", min_speed)
    frequency = check.positive("max_frequency_hz", max_frequency_hz)
    return speed / (2.0 * frequency)


def iso8608_class(c10: float) -> str:
    """The ISO 8608 road class (``"A"`` to ``"H"``) whose band contains ``G_d(n0) = c10``.

    The class limits are the geometric midpoints between the class means
    (A 16e-6, B 64e-6, ... H 262144e-6 m^3): class A is below 32e-6 m^3, B from 32e-6 to
    128e-6 m^3, and so on; H is everything above 131072e-6 m^3.

    Parameters
    ----------
    c10
        ``G_d(0.1 cycle/m)`` [m^3], the study's "C10".

    Examples
    --------
    The study's two roughness levels fall in classes C and D:

    >>> iso8608_class(300e-6), iso8608_class(600e-6)
    ('C', 'D')
    >>> iso8608_class(100e-6)
    'B'
    """
    c10 = check.positive("c10", c10)
    index = math.floor(math.log(c10 / 16e-6, 4.0) + 0.5)
    return "ABCDEFGH"[min(max(index, 0), 7)]


def iso_level(c10: float | None, iso_class: str | None, warn: bool = True) -> float:
    """``G_d(n0)`` [m^3] from exactly one of ``c10`` and ``iso_class``, within its range.

    Raises ``TypeError`` for a ``c10`` that is not a number or an ``iso_class`` that is not
    text, ``ValueError`` for both or neither, a ``c10`` outside its range of validity
    (:data:`vbi_lib.ranges.RANGES`) or an unknown class; warns for classes F to H and a
    ``c10`` above class E.
    """
    if (c10 is None) == (iso_class is None):
        raise ValueError(
            f"give exactly one of c10 (G_d(0.1 cycle/m) in m^3) and iso_class ('A'..'H'); "
            f"got c10={c10!r}, iso_class={iso_class!r}"
        )
    if c10 is not None:
        return check_range("c10", c10, warn=warn)
    if not isinstance(iso_class, str):
        raise TypeError(
            f"iso_class={iso_class!r} must be a letter 'A' to 'H' (text, not "
            f"{type(iso_class).__name__})"
        )
    key = iso_class.strip().upper()
    if key not in ISO_CLASS_MEANS:
        raise ValueError(f"iso_class={iso_class!r} is not an ISO 8608 class; use 'A' to 'H'")
    return check_range("c10", ISO_CLASS_MEANS[key], f"iso_class={iso_class!r}: c10", warn=warn)


def iso_band(band: object, spacing: float) -> tuple[float, float]:
    """``(low, high)`` [cycle/m] of a generated road, resolved by ``spacing`` [m]."""
    if isinstance(band, str | bytes) or not hasattr(band, "__len__") or len(band) != 2:
        raise TypeError(f"band={band!r} must be two frequencies (low, high) in cycle/m")
    low, high = (check.finite(f"band[{i}]", b) for i, b in enumerate(band))
    if not 0 < low < high:
        raise ValueError(f"band={band!r} must satisfy 0 < low < high (cycle/m)")
    if high >= 0.5 / spacing:
        raise ValueError(
            f"band={band!r} reaches {high:g} cycle/m but spacing={spacing!r} m resolves "
            f"only up to {0.5 / spacing:g} cycle/m; use a spacing below {0.5 / high:g} m "
            "or lower band[1]"
        )
    return low, high


def check_iso_rms(level: float, waviness: float, low: float, high: float) -> float:
    """The rms [m] of an ISO 8608 road over ``[low, high]`` cycle/m, refused above the hard
    limit of ``road_rms`` (:data:`vbi_lib.ranges.RANGES`).

    ``rms^2 = integral of G_d(n0) (n / n0)^-w dn`` from ``low`` to ``high``, in closed form:
    the generated road's variance before any sample is drawn.
    """
    if abs(waviness - 1.0) < 1e-12:
        variance = level * 0.1 * math.log(high / low)
    else:
        variance = level * 0.1**waviness * (high ** (1 - waviness) - low ** (1 - waviness))
        variance /= 1.0 - waviness
    rms = math.sqrt(variance)
    spec = RANGES["road_rms"]
    if rms > spec.hard[1]:
        raise ValueError(
            f"c10={level!r} m^3 with waviness={waviness!r} gives a road of rms {rms:.3g} m "
            f"over {low:.3g} to {high:.3g} cycle/m; a road's rms must be {spec.hard_text()} "
            f"({spec.reason}): lower c10 or the waviness"
        )
    return rms


def check_harmonic(
    length: object, spacing: object, wavelength: object, amplitude: object, phase: object,
    start: object,
) -> tuple[float, float, float]:  # fmt: skip
    """Check a harmonic road's inputs before anything is allocated; ``(wavelength,
    amplitude, phase)`` as floats.  A wavelength shorter than two samples would alias."""
    wavelength = check_range("feature_length", wavelength, "wavelength")
    amplitude = check_range("unevenness", check.non_negative("amplitude", amplitude),
                            "amplitude")  # fmt: skip
    phase = check.finite("phase", phase)
    check_stations(length, spacing, start)
    if wavelength < 2.0 * float(spacing):
        raise ValueError(
            f"wavelength={wavelength!r} m is shorter than two samples of spacing={spacing!r} m: "
            f"the road would alias; use a spacing below {wavelength / 2:g} m"
        )
    return wavelength, amplitude, phase


def check_seed(seed: object) -> int | None:
    """A seed of the random phases: ``None`` or a whole number >= 0."""
    if seed is None:
        return None
    return check.integer("seed", seed, low=0)


@dataclass(frozen=True, eq=False)
class Profile:
    """A road profile: stations ``x`` [m], strictly increasing, and elevations [m], up positive.

    Examples
    --------
    >>> p = Profile.harmonic(length=60.0, spacing=0.025, wavelength=9.144, amplitude=0.0127)
    >>> p
    Profile('harmonic 9.144 m', 2401 samples over 60.00 m, spacing 25.0 mm, rms 8.92 mm)
    """

    x: np.ndarray
    elevation: np.ndarray
    name: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        x = check.finite_array("profile x", self.x)
        elevation = check.finite_array("profile elevation", self.elevation)
        if x.size < 2:
            raise ValueError(f"a profile needs at least two samples; got {x.size}")
        if elevation.shape != x.shape:
            raise ValueError(
                f"profile x has {x.size} samples but elevation has {elevation.size}; "
                "give one elevation per station"
            )
        steps = np.diff(x)
        if (steps <= 0).any():
            index = int(np.flatnonzero(steps <= 0)[0])
            raise ValueError(
                f"profile x must be strictly increasing; x[{index + 1}]={x[index + 1]!r} "
                f"follows x[{index}]={x[index]!r}"
            )
        x.setflags(write=False)
        elevation.setflags(write=False)
        object.__setattr__(self, "x", x)
        object.__setattr__(self, "elevation", elevation)

    # ------------------------------------------------------------------ constructors
    @classmethod
    def flat(cls, length: float, spacing: float, start: float = 0.0) -> Profile:
        """A perfectly smooth road of ``length`` [m] sampled every ``spacing`` [m].

        >>> Profile.flat(10.0, 0.5).x.size
        21
        """
        x = _stations(length, spacing, start)
        return mark_checked(cls(x, np.zeros_like(x), name="flat"))

    @classmethod
    def harmonic(
        cls,
        length: float,
        spacing: float,
        wavelength: float,
        amplitude: float,
        phase: float = 0.0,
        start: float = 0.0,
    ) -> Profile:
        """A sinusoidal road ``amplitude * sin(2 pi x / wavelength + phase)``.

        Parameters
        ----------
        length, spacing
            Length and sample spacing [m].
        wavelength
            Wavelength [m]; the truck feels it at ``speed / wavelength`` Hz.
        amplitude
            Half the peak-to-peak height [m].
        phase
            Phase at ``x = start`` [rad].

        >>> p = Profile.harmonic(30.0, 0.01, 10.0, 0.002)
        >>> round(float(p.elevation.max()) * 1e3, 3)
        2.0
        """
        wavelength, amplitude, phase = check_harmonic(
            length, spacing, wavelength, amplitude, phase, start
        )
        x = _stations(length, spacing, start)
        elevation = amplitude * np.sin(2.0 * np.pi * (x - start) / wavelength + phase)
        return mark_checked(cls(x, elevation, name=f"harmonic {wavelength:g} m"))

    @classmethod
    def iso8608(
        cls,
        length: float,
        spacing: float,
        c10: float | None = None,
        iso_class: str | None = None,
        waviness: float = 2.0,
        seed: int | None = None,
        band: tuple[float, float] = ISO_BAND,
        start: float = 0.0,
    ) -> Profile:
        r"""A random road with the ISO 8608 spectrum ``G_d(n) = c10 (n / 0.1)^-w`` (study 87).

        The book writes the spectrum as :eq:`study-87` and the sum as :eq:`eq-roads-cosines`.
        A sum of sines :math:`\sum_i \sqrt{2 G_d(n_i) \Delta n}\cos(2\pi n_i (x - x_0) +
        \theta_i)` over the frequencies :math:`n_i = i\,\Delta n` inside ``band``, with
        phases drawn uniformly from :math:`[0, 2\pi)` by ``numpy.random.default_rng(seed)``.
        :math:`\Delta n = 1 / (N s) \le 1 / \text{length}` (``N`` samples of spacing ``s``
        on a period at least as long as the road) so the road does not repeat, and the sum is
        evaluated exactly at the stations with one inverse FFT.

        Parameters
        ----------
        length, spacing
            Length and sample spacing [m].  ``spacing`` must resolve the band:
            ``band[1] < 1 / (2 spacing)``.
        c10
            ``G_d(0.1 cycle/m)`` [m^3] (the study's "C10"); or give ``iso_class``.
        iso_class
            ``"A"`` to ``"H"``: use the class's geometric mean (A 16e-6 m^3, each class four
            times the previous one).
        waviness
            Exponent ``w`` (ISO 8608 uses 2; the study also 3 and 4).
        seed
            Seed of the random phases; the same seed gives the same road.
        band
            Lowest and highest spatial frequency [cycle/m].
        start
            First station [m].

        Raises
        ------
        TypeError
            A value of the wrong type (a seed that is not an int, a class that is not text).
        ValueError
            Both or neither of ``c10`` and ``iso_class``; ``c10``, ``waviness``, ``length``
            or ``spacing`` outside their ranges of validity (:data:`vbi_lib.ranges.RANGES`);
            a band the spacing does not resolve; more than
            :data:`~vbi_lib.ranges.MAX_SAMPLES` samples.

        Warns
        -----
        OutsideValidityWarning
            ``c10`` above class E (classes F to H) or ``waviness`` outside 1.5 to 4.

        Examples
        --------
        One of the study's roads, 650 ft at 1 in, C10 = 300e-6 m^3, w = 3, phase draw 1:

        >>> from vbi_lib import units as u
        >>> road = Profile.iso8608(650 * u.ft, 1 * u.inch, c10=300e-6, waviness=3, seed=1)
        >>> road.x.size, road.name
        (7801, 'ISO 8608 C10=300e-6 m^3 w=3 seed=1')
        """
        level = iso_level(c10, iso_class)
        waviness = check_range("waviness", waviness)
        seed = check_seed(seed)
        check_stations(length, spacing, start)
        low, high = iso_band(band, float(spacing))
        check_iso_rms(level, waviness, max(low, 1.0 / float(length)), high)
        x = _stations(length, spacing, start)
        spacing = float(spacing)
        # _stations puts every station on the grid start + j*spacing except perhaps the last
        last = (x[-1] - start) / spacing
        regular = x.size if abs(last - round(last)) < 1e-6 else x.size - 1
        count = scipy.fft.next_fast_len(x.size, real=True)
        dn = 1.0 / (count * spacing)
        k = np.arange(math.ceil(low / dn - 1e-9), math.floor(high / dn + 1e-9) + 1)
        k = k[(k > 0) & (2 * k < count)]
        if k.size == 0:
            raise ValueError(
                f"band={band!r} holds no frequency of the grid dn={dn:g} cycle/m; "
                "widen the band or lengthen the road"
            )
        n = k * dn
        amplitude = np.sqrt(2.0 * level * (n / 0.1) ** (-waviness) * dn)
        phase = np.random.default_rng(seed).uniform(0.0, 2.0 * np.pi, k.size)
        spectrum = np.zeros(count // 2 + 1, dtype=complex)
        spectrum[k] = 0.5 * count * amplitude * np.exp(1j * phase)
        elevation = np.empty_like(x)
        elevation[:regular] = scipy.fft.irfft(spectrum, count)[:regular]
        if regular < x.size:
            elevation[regular:] = amplitude @ np.cos(
                2.0 * np.pi * np.outer(n, x[regular:] - start) + phase[:, None]
            )
        name = f"ISO 8608 C10={level * 1e6:g}e-6 m^3 w={waviness:g} seed={seed}"
        return mark_checked(cls(x, elevation, name=name))

    @classmethod
    def bump(
        cls,
        length: float,
        spacing: float,
        position: float,
        height: float,
        width: float,
        start: float = 0.0,
    ) -> Profile:
        """A smooth bump (or dip, ``height < 0``) on a flat road: one raised cosine.

        ``height/2 (1 - cos(2 pi (x - position + width/2) / width))`` for
        ``|x - position| <= width/2``, zero elsewhere.

        Parameters
        ----------
        length, spacing, start
            Road length, sample spacing and first station [m].
        position
            Station of the bump's crest [m].
        height
            Crest height [m]; negative for a dip or pothole.
        width
            Base length of the bump [m].

        >>> p = Profile.bump(20.0, 0.01, position=10.0, height=0.02, width=1.0)
        >>> round(float(p.elevation_at(10.0)), 4), float(p.elevation_at(9.4))
        (0.02, 0.0)
        """
        width = check_range("feature_length", width, "width")
        height = check_range("unevenness", height, "height")
        x = _stations(length, spacing, start)
        u = (x - _finite("position", position)) / width + 0.5
        inside = (u > 0.0) & (u < 1.0)
        elevation = np.where(inside, 0.5 * height * (1.0 - np.cos(2.0 * np.pi * u)), 0.0)
        return mark_checked(cls(x, elevation, name=f"bump {height * 1e3:g} mm x {width:g} m"))

    @classmethod
    def ramp(
        cls,
        length: float,
        spacing: float,
        position: float,
        rise: float,
        run: float,
        start: float = 0.0,
    ) -> Profile:
        """A flat road that climbs ``rise`` [m] over ``run`` [m] from ``position`` and stays up.

        The corners are stations of the profile, so the road is exactly piecewise linear.
        ``position=start, run=length`` gives a straight grade of slope ``rise / length``.

        >>> p = Profile.ramp(10.0, 0.5, position=2.0, rise=0.01, run=4.0)
        >>> [round(float(p.elevation_at(s)), 4) for s in (1.0, 4.0, 6.0, 9.0)]
        [0.0, 0.005, 0.01, 0.01]
        """
        run = check_range("feature_length", run, "run")
        position, rise = _finite("position", position), _finite("rise", rise)
        check_range("grade", rise / run, f"rise/run (rise={rise!r}, run={run!r})")
        x = _with_stations(_stations(length, spacing, start), (position, position + run))
        elevation = rise * np.clip((x - position) / run, 0.0, 1.0)
        return mark_checked(cls(x, elevation, name=f"ramp {rise * 1e3:g} mm over {run:g} m"))

    @classmethod
    def step(
        cls,
        length: float,
        spacing: float,
        position: float,
        height: float,
        start: float = 0.0,
    ) -> Profile:
        """A flat road with a step of ``height`` [m] (a joint, a bridge approach) at ``position``.

        The profile is linear between samples, so the road rises over the one sample interval
        that follows ``position`` (a station is placed at ``position``): the step is as sharp
        as the sampling.

        >>> p = Profile.step(10.0, 0.1, position=5.0, height=0.01)
        >>> float(p.elevation_at(5.0)), float(p.elevation_at(6.0))
        (0.0, 0.01)
        """
        position = _finite("position", position)
        height = check_range("unevenness", height, "height")
        x = _with_stations(_stations(length, spacing, start), (position,))
        elevation = np.where(x > position, height, 0.0)
        return mark_checked(cls(x, elevation, name=f"step {height * 1e3:g} mm"))

    # ------------------------------------------------------------------ derived
    @property
    def length(self) -> float:
        """Distance from the first to the last station [m]."""
        return float(self.x[-1] - self.x[0])

    @property
    def spacing(self) -> float:
        """Median distance between samples [m]."""
        return float(np.median(np.diff(self.x)))

    @property
    def start(self) -> float:
        """First station [m]."""
        return float(self.x[0])

    @property
    def end(self) -> float:
        """Last station [m]."""
        return float(self.x[-1])

    def elevation_at(self, x: float | np.ndarray) -> np.ndarray:
        """Elevation [m] at stations ``x``, linear between samples."""
        return np.interp(x, self.x, self.elevation)

    def shifted(self, offset: float) -> Profile:
        """The same road moved ``offset`` metres along the stationing (features move forward).

        >>> Profile.flat(10.0, 1.0).shifted(5.0).start
        5.0
        """
        offset = check.finite("offset", offset)
        return inherit(self, Profile(self.x + offset, self.elevation.copy(), name=self.name))

    def segment(self, start: float, stop: float) -> Profile:
        """The part of the road between stations ``start`` and ``stop`` [m] (ends interpolated).

        >>> Profile.flat(10.0, 1.0).segment(2.5, 7.5).length
        5.0
        """
        start, stop = check.finite("start", start), check.finite("stop", stop)
        if not (self.x[0] <= start < stop <= self.x[-1]):
            raise ValueError(
                f"segment({start!r}, {stop!r}) must satisfy {self.x[0]:g} <= start < stop <= "
                f"{self.x[-1]:g} (the profile's stations)"
            )
        inside = (self.x > start) & (self.x < stop)
        x = np.concatenate(([start], self.x[inside], [stop]))
        return inherit(self, Profile(x, self.elevation_at(x), name=self.name))

    def resampled(self, spacing: float) -> Profile:
        """The road read every ``spacing`` metres from its first station (linear interpolation).

        Resampled more finely, the road is the same (it is linear between samples) but a
        crossing has more nodes, so its DAF moves by its time-step error: over random
        realistic crossings (tests/test_properties.py, ``test_resampling_the_road_converges``)
        the one-coordinate model's (RK4) by at most 4e-6, the modal model's (Newmark, second
        order) by at most 7e-4, each within its step error of the converged DAF (5e-6 and
        3e-3).  A tyre with a footprint sees the road averaged over it at the samples, which
        resampling refines too: up to 7e-4 (one-coordinate) and 2e-3 (modal) were found.

        >>> Profile.flat(10.0, 1.0).resampled(0.5).x.size
        21
        """
        x = _stations(self.length, spacing, self.start)
        return inherit(self, Profile(x, self.elevation_at(x), name=self.name))

    def __repr__(self) -> str:
        rms = float(np.sqrt(np.mean((self.elevation - self.elevation.mean()) ** 2)))
        label = f"{self.name!r}, " if self.name else ""
        return (
            f"Profile({label}{self.x.size} samples over {display.short(self.length, 'length')}, "
            f"spacing {display.short(self.spacing, 'spacing', 3)}, "
            f"rms {display.short(rms, 'elevation', 3)})"
        )


def _finite(name: str, value: float) -> float:
    """``value`` as a finite float (any sign): ``TypeError`` for text, ``ValueError`` for NaN."""
    return check.finite(name, value)


def _with_stations(x: np.ndarray, extra: tuple[float, ...]) -> np.ndarray:
    """``x`` with the stations ``extra`` that fall strictly inside it added (sorted, unique)."""
    tol = 1e-9 * max(1.0, float(x[-1] - x[0]))
    inside = [e for e in extra if x[0] < e < x[-1] and np.abs(x - e).min() > tol]
    return np.sort(np.concatenate((x, inside))) if inside else x


def check_stations(length: object, spacing: object, start: object = 0.0) -> int:
    """Check a generated road's ``length``, ``spacing`` and ``start`` and return its number of
    samples, before anything is allocated (at most :data:`~vbi_lib.ranges.MAX_SAMPLES`)."""
    length = check_range("profile_length", length, "length")
    spacing = check_range("spacing", spacing)
    check.finite("start", start)
    if spacing > length:
        raise ValueError(f"spacing={spacing!r} is longer than length={length!r}")
    samples = math.floor(length / spacing + 1e-9) + 2
    if samples > MAX_SAMPLES:
        raise ValueError(
            f"length={length!r} m every spacing={spacing!r} m asks for {samples:.3g} samples; "
            f"a generated road has at most {MAX_SAMPLES:.0e} (raise the spacing or shorten "
            "the road)"
        )
    return samples


def _stations(length: float, spacing: float, start: float = 0.0) -> np.ndarray:
    """Stations ``start, start + spacing, ...`` covering ``length`` (the last one at the end)."""
    check_stations(length, spacing, start)
    length, spacing, start = float(length), float(spacing), float(start)
    count = int(math.floor(length / spacing + 1e-9))
    x = start + spacing * np.arange(count + 1)
    if length - count * spacing > 1e-9 * length:
        x = np.append(x, start + length)
    return x
