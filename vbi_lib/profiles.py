r"""Road profiles: the elevation the wheel follows, on the approach and on the bridge.

A :class:`Profile` is a list of stations ``x`` (strictly increasing, metres along the road)
and elevations (metres, positive up).  Between samples the road is a straight line, which is
how the simulation reads it: every sample is a node of the time grid, so the wheel's vertical
velocity ``v dDelta/dx`` is exact on each segment.

The sampling rule of the study (32): to see a natural frequency ``f_max`` at the slowest
speed of interest ``v_min``, sample at least every ``S_max = v_min / (2 f_max)``.

Artificial roads follow ISO 8608 (study equation 87): the displacement power spectral density

.. math::
    G_d(n) = G_d(n_0) \left(\frac{n}{n_0}\right)^{-w}, \qquad n_0 = 0.1\ \text{cycle/m},

with ``G_d(n0)`` the study's "C10" [m^3] and waviness ``w``, realised as a sum of sines
:math:`\Delta(x) = \sum_i \sqrt{2 G_d(n_i)\,\Delta n} \cos(2\pi n_i x + \varphi_i)` with
uniform random phases (:meth:`Profile.iso8608`).  Teaching shapes (harmonic, bump, ramp, step)
and readers for measured profiles (:func:`read_profile` for two-column text,
:func:`read_erd` for the ERD v2 format of profilers) complete the module.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import scipy.fft

from . import _validation as check

#: ISO 8608 road classes and the geometric mean of ``G_d(n0)`` of each [m^3].
ISO_CLASS_MEANS = {letter: 16e-6 * 4.0**i for i, letter in enumerate("ABCDEFGH")}

#: Default spatial-frequency band of :meth:`Profile.iso8608` [cycle/m] (ISO 8608's range).
ISO_BAND = (0.011, 2.83)

#: Length units accepted by name by the readers [m per unit].
LENGTH_UNITS = {
    "m": 1.0,
    "mm": 1e-3,
    "cm": 1e-2,
    "km": 1e3,
    "in": 0.0254,
    "inch": 0.0254,
    "inches": 0.0254,
    "ft": 0.3048,
    "feet": 0.3048,
    "foot": 0.3048,
    "mi": 1609.344,
}


def max_sample_spacing(min_speed: float, max_frequency_hz: float) -> float:
    """Largest profile sample spacing ``S_max = v_min / (2 f_max)`` [m] (study equation 32).

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


def _iso_level(c10: float | None, iso_class: str | None) -> float:
    """``G_d(n0)`` [m^3] from exactly one of ``c10`` and ``iso_class``."""
    if (c10 is None) == (iso_class is None):
        raise ValueError(
            f"give exactly one of c10 (G_d(0.1 cycle/m) in m^3) and iso_class ('A'..'H'); "
            f"got c10={c10!r}, iso_class={iso_class!r}"
        )
    if c10 is not None:
        return check.positive("c10", c10)
    key = str(iso_class).strip().upper()
    if key not in ISO_CLASS_MEANS:
        raise ValueError(f"iso_class={iso_class!r} is not an ISO 8608 class; use 'A' to 'H'")
    return ISO_CLASS_MEANS[key]


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
        return cls(x, np.zeros_like(x), name="flat")

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
        wavelength = check.positive("wavelength", wavelength)
        amplitude = check.non_negative("amplitude", amplitude)
        x = _stations(length, spacing, start)
        elevation = amplitude * np.sin(2.0 * np.pi * (x - start) / wavelength + phase)
        return cls(x, elevation, name=f"harmonic {wavelength:g} m")

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

        A sum of sines :math:`\sum_i \sqrt{2 G_d(n_i) \Delta n}\cos(2\pi n_i (x - x_0) +
        \varphi_i)` over the frequencies :math:`n_i = i\,\Delta n` inside ``band``, with
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

        Examples
        --------
        One of the study's roads, 650 ft at 1 in, C10 = 300e-6 m^3, w = 3, phase draw 1:

        >>> from vbi_lib import units as u
        >>> road = Profile.iso8608(650 * u.ft, 1 * u.inch, c10=300e-6, waviness=3, seed=1)
        >>> road.x.size, road.name
        (7801, 'ISO 8608 C10=300e-6 m^3 w=3 seed=1')
        """
        level = _iso_level(c10, iso_class)
        waviness = check.positive("waviness", waviness)
        try:
            low, high = (float(b) for b in band)
        except (TypeError, ValueError):
            raise ValueError(
                f"band={band!r} must be two frequencies (low, high) in cycle/m"
            ) from None
        if not (0 < low < high and math.isfinite(high)):
            raise ValueError(f"band={band!r} must satisfy 0 < low < high (cycle/m)")
        x = _stations(length, spacing, start)
        spacing = float(spacing)
        if high >= 0.5 / spacing:
            raise ValueError(
                f"band={band!r} reaches {high:g} cycle/m but spacing={spacing!r} m resolves "
                f"only up to {0.5 / spacing:g} cycle/m; use a spacing below {0.5 / high:g} m "
                "or lower band[1]"
            )
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
        return cls(x, elevation, name=name)

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
        width = check.positive("width", width)
        height = _finite("height", height)
        x = _stations(length, spacing, start)
        u = (x - _finite("position", position)) / width + 0.5
        inside = (u > 0.0) & (u < 1.0)
        elevation = np.where(inside, 0.5 * height * (1.0 - np.cos(2.0 * np.pi * u)), 0.0)
        return cls(x, elevation, name=f"bump {height * 1e3:g} mm x {width:g} m")

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
        run = check.positive("run", run)
        position, rise = _finite("position", position), _finite("rise", rise)
        x = _with_stations(_stations(length, spacing, start), (position, position + run))
        elevation = rise * np.clip((x - position) / run, 0.0, 1.0)
        return cls(x, elevation, name=f"ramp {rise * 1e3:g} mm over {run:g} m")

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
        position, height = _finite("position", position), _finite("height", height)
        x = _with_stations(_stations(length, spacing, start), (position,))
        elevation = np.where(x > position, height, 0.0)
        return cls(x, elevation, name=f"step {height * 1e3:g} mm")

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
        return Profile(self.x + float(offset), self.elevation.copy(), name=self.name)

    def segment(self, start: float, stop: float) -> Profile:
        """The part of the road between stations ``start`` and ``stop`` [m] (ends interpolated).

        >>> Profile.flat(10.0, 1.0).segment(2.5, 7.5).length
        5.0
        """
        if not (self.x[0] <= start < stop <= self.x[-1]):
            raise ValueError(
                f"segment({start!r}, {stop!r}) must satisfy {self.x[0]:g} <= start < stop <= "
                f"{self.x[-1]:g} (the profile's stations)"
            )
        inside = (self.x > start) & (self.x < stop)
        x = np.concatenate(([start], self.x[inside], [stop]))
        return Profile(x, self.elevation_at(x), name=self.name)

    def resampled(self, spacing: float) -> Profile:
        """The road read every ``spacing`` metres from its first station (linear interpolation).

        >>> Profile.flat(10.0, 1.0).resampled(0.5).x.size
        21
        """
        x = _stations(self.length, spacing, self.start)
        return Profile(x, self.elevation_at(x), name=self.name)

    def __repr__(self) -> str:
        rms = float(np.sqrt(np.mean((self.elevation - self.elevation.mean()) ** 2)))
        label = f"{self.name!r}, " if self.name else ""
        return (
            f"Profile({label}{self.x.size} samples over {self.length:.2f} m, "
            f"spacing {self.spacing * 1e3:.1f} mm, rms {rms * 1e3:.2f} mm)"
        )


def _finite(name: str, value: float) -> float:
    """``value`` as a finite float (any sign), else ``ValueError`` naming ``name``."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name}={value!r} must be a number") from None
    if not math.isfinite(number):
        raise ValueError(f"{name}={value!r} must be a finite number")
    return number


def _with_stations(x: np.ndarray, extra: tuple[float, ...]) -> np.ndarray:
    """``x`` with the stations ``extra`` that fall strictly inside it added (sorted, unique)."""
    tol = 1e-9 * max(1.0, float(x[-1] - x[0]))
    inside = [e for e in extra if x[0] < e < x[-1] and np.abs(x - e).min() > tol]
    return np.sort(np.concatenate((x, inside))) if inside else x


def _stations(length: float, spacing: float, start: float = 0.0) -> np.ndarray:
    """Stations ``start, start + spacing, ...`` covering ``length`` (the last one at the end)."""
    length = check.positive("length", length)
    spacing = check.positive("spacing", spacing)
    if spacing > length:
        raise ValueError(f"spacing={spacing!r} is longer than length={length!r}")
    count = int(math.floor(length / spacing + 1e-9))
    x = start + spacing * np.arange(count + 1)
    if length - count * spacing > 1e-9 * length:
        x = np.append(x, start + length)
    return x


# ---------------------------------------------------------------------------- reading files
class ProfileFileError(ValueError):
    """A profile file that cannot be read; the message names the file, the line and the fault."""

    def __init__(self, path: str | Path, line: int | None, problem: str) -> None:
        where = f"{path}" if line is None else f"{path}, line {line}"
        super().__init__(f"{where}: {problem}")
        self.path = str(path)
        self.line = line
        self.problem = problem


def _length_unit(name: str, unit: float | str) -> float:
    """Metres per unit from a factor (``vbi_lib.units.inch``) or a name (``"in"``)."""
    if isinstance(unit, str):
        key = unit.strip().lower()
        if key not in LENGTH_UNITS:
            raise ValueError(
                f"{name}={unit!r} is not a known length unit; use one of "
                f"{', '.join(sorted(LENGTH_UNITS))} or a factor in metres (vbi_lib.units.inch)"
            )
        return LENGTH_UNITS[key]
    return check.positive(name, unit)


_SPLIT = re.compile(r"\s*[,;\t]\s*|\s+")


def _number(path: Path, line: int, cell: str, what: str) -> float:
    try:
        value = float(cell)
    except ValueError:
        raise ProfileFileError(path, line, f"{what} {cell!r} is not a number") from None
    if not math.isfinite(value):
        raise ProfileFileError(path, line, f"{what} {cell!r} is not a finite number")
    return value


def read_profile(
    path: str | Path,
    unit: float | str,
    elevation_unit: float | str | None = None,
    skip_rows: int = 0,
    name: str | None = None,
) -> Profile:
    """Read a measured profile from a two-column text file: station, elevation.

    Cells are separated by commas, semicolons, tabs or spaces; blank lines and lines starting
    with ``#`` are ignored.  Stations must increase strictly.  The whole file is checked
    before a :class:`Profile` is made, so a bad file raises :class:`ProfileFileError` (a
    ``ValueError``) naming the file, the line and the fault, and nothing is half read.

    Parameters
    ----------
    path
        The file.
    unit
        Length unit of the stations: a factor in metres (``vbi_lib.units.inch``) or a name
        (``"in"``, ``"ft"``, ``"m"``, ``"mm"``, ...).  The study's I-76 files are in inches.
    elevation_unit
        Unit of the elevations if it differs from ``unit``.
    skip_rows
        Lines to skip at the top (a header row).
    name
        Name of the profile; the file's stem by default.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (folder / "deck.csv").write_text("0,0\\n1,0.5\\n2,0.25\\n")
    >>> p = read_profile(folder / "deck.csv", unit="in")
    >>> p.x.tolist(), p.elevation.tolist()
    ([0.0, 0.0254, 0.0508], [0.0, 0.0127, 0.00635])
    >>> _ = (folder / "bad.csv").write_text("0,0\\n1,x\\n")
    >>> read_profile(folder / "bad.csv", unit="in")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vbi_lib.profiles.ProfileFileError: .../bad.csv, line 2: elevation 'x' is not a number
    """
    path = Path(path)
    scale_x = _length_unit("unit", unit)
    scale_z = scale_x if elevation_unit is None else _length_unit("elevation_unit", elevation_unit)
    if int(skip_rows) != skip_rows or skip_rows < 0:
        raise ValueError(f"skip_rows={skip_rows!r} must be a whole number >= 0")
    try:
        text = path.read_text(encoding="utf-8-sig")  # tolerate a byte-order mark
    except OSError as exc:
        raise ProfileFileError(path, None, f"cannot be read ({exc.strerror or exc})") from None
    except UnicodeDecodeError:
        raise ProfileFileError(path, None, "is not a text file") from None
    stations: list[float] = []
    heights: list[float] = []
    lines: list[int] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if number <= skip_rows or not line or line.startswith("#"):
            continue
        cells = _SPLIT.split(line)
        if cells and cells[-1] == "":
            cells.pop()  # a trailing separator
        if len(cells) != 2:
            raise ProfileFileError(
                path, number, f"expected 2 columns (station, elevation), found {len(cells)}"
            )
        x = _number(path, number, cells[0], "station")
        z = _number(path, number, cells[1], "elevation")
        if stations and x <= stations[-1]:
            raise ProfileFileError(
                path,
                number,
                f"station {cells[0]} does not increase (line {lines[-1]} has {stations[-1]:g}); "
                "stations must increase strictly",
            )
        stations.append(x)
        heights.append(z)
        lines.append(number)
    if len(stations) < 2:
        raise ProfileFileError(
            path, None, f"holds {len(stations)} sample(s); a profile needs at least two"
        )
    return Profile(
        np.asarray(stations) * scale_x,
        np.asarray(heights) * scale_z,
        name=path.stem if name is None else name,
    )


@dataclass(frozen=True, eq=False)
class ErdFile:
    """A profile file in the ERD v2 text format: one :class:`Profile` per channel.

    Attributes
    ----------
    channels
        One profile per channel (stations from 0, SI units), named by ``SHORTNAM``.
    header
        Every keyword line as ``{keyword: value text}`` (e.g. ``header["IRILWP"]``).
    interval
        Sample interval [m].
    path
        The file read.
    """

    channels: tuple[Profile, ...]
    header: dict[str, str]
    interval: float
    path: str

    @property
    def title(self) -> str:
        """The ``TITLE`` keyword (empty when absent)."""
        return self.header.get("TITLE", "")

    def __len__(self) -> int:
        return len(self.channels)

    def __getitem__(self, index: int) -> Profile:
        return self.channels[index]

    def __repr__(self) -> str:
        names = ", ".join(repr(c.name) for c in self.channels)
        first = self.channels[0]
        return (
            f"ErdFile({self.title!r}: {len(self.channels)} channel(s) {names}, "
            f"{first.x.size} samples every {self.interval * 1e3:.1f} mm over {first.length:.1f} m)"
        )


def read_erd(path: str | Path) -> ErdFile:
    """Read a profile file in the ERD v2 text format (profilers, ProVAL, the RoadRuf tools).

    Layout: line 1 ``ERDFILEV2.00``; line 2, comma separated, the number of channels, the
    number of samples, two fields not used here, the storage code (5: text rows) and the
    sample interval (in ``XUNITS``); keyword lines (8-character keyword, then the value;
    ``UNITSNAM`` and ``SHORTNAM`` hold one 8-character field per channel) up to ``END``; then
    one row per sample with one elevation per channel.  Distance units ``XUNITS`` and
    elevation units ``UNITSNAM`` are converted to metres (m, mm, cm, in, ft).

    Anything else (another version, a binary layout, a missing ``END``, a wrong number of
    rows or columns, a non-numeric cell, an unknown unit) raises :class:`ProfileFileError`
    naming the file and the line; nothing is half read.

    Returns
    -------
    ErdFile
        ``channels`` (one :class:`Profile` per wheel path), ``header`` and ``interval`` [m].

    Examples
    --------
    >>> import tempfile, pathlib
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "run.erd"
    >>> _ = f.write_text(
    ...     "ERDFILEV2.00\\n1, 3, -1, 1, 5, 0.25, -1,\\nTITLE   demo\\nSHORTNAMLeft\\n"
    ...     "UNITSNAMmm\\nXUNITS  m\\nEND\\n0.0\\n1.5\\n-0.5\\n"
    ... )
    >>> erd = read_erd(f)
    >>> erd
    ErdFile('demo': 1 channel(s) 'Left', 3 samples every 250.0 mm over 0.5 m)
    >>> erd[0].elevation.tolist()
    [0.0, 0.0015, -0.0005]
    """
    path = Path(path)
    try:
        lines = path.read_text(encoding="utf-8-sig").splitlines()
    except OSError as exc:
        raise ProfileFileError(path, None, f"cannot be read ({exc.strerror or exc})") from None
    except UnicodeDecodeError:
        raise ProfileFileError(
            path, None, "is not a text file (binary ERD layouts are not supported)"
        ) from None
    if not lines or lines[0].strip()[:12] != "ERDFILEV2.00":
        first = lines[0].strip()[:20] if lines else ""
        raise ProfileFileError(path, 1, f"starts with {first!r}, not 'ERDFILEV2.00' (ERD v2)")
    if len(lines) < 2:
        raise ProfileFileError(path, 2, "the ERD counts line is missing")
    fields = [f for f in (c.strip() for c in lines[1].split(",")) if f]
    if len(fields) < 6:
        raise ProfileFileError(
            path, 2, f"expected at least 6 comma-separated fields, found {len(fields)}"
        )
    counts = [_number(path, 2, f, f"field {i + 1}") for i, f in enumerate(fields[:6])]
    n_channels, n_samples, storage, step = counts[0], counts[1], counts[4], counts[5]
    if n_channels != int(n_channels) or n_channels < 1:
        raise ProfileFileError(path, 2, f"number of channels {fields[0]!r} must be >= 1")
    if n_samples != int(n_samples) or n_samples < 2:
        raise ProfileFileError(path, 2, f"number of samples {fields[1]!r} must be >= 2")
    if storage != 5:
        raise ProfileFileError(
            path, 2, f"storage code {fields[4]!r} is not 5 (text rows); this layout is unknown"
        )
    if step <= 0:
        raise ProfileFileError(path, 2, f"sample interval {fields[5]!r} must be > 0")
    n_channels, n_samples = int(n_channels), int(n_samples)

    header: dict[str, str] = {}
    per_channel: dict[str, list[str]] = {}
    end = None
    for index in range(2, len(lines)):
        raw = lines[index].rstrip("\r\n")
        key = raw[:8].strip().upper()
        if key == "END":
            end = index
            break
        if not key:
            continue
        value = raw[8:]
        header[key] = value.strip()
        if key in ("UNITSNAM", "SHORTNAM"):
            fixed = [value[8 * i : 8 * i + 8].strip() for i in range(n_channels)]
            per_channel[key] = fixed if all(fixed) else value.split()
    if end is None:
        raise ProfileFileError(path, len(lines), "no 'END' line closes the ERD header")

    def unit_of(text: str, line_key: str) -> float:
        factor = LENGTH_UNITS.get(text.strip().lower())
        if factor is None:
            raise ProfileFileError(
                path,
                _key_line(lines, line_key),
                f"{line_key} unit {text!r} is not known; use one of m, mm, cm, in, ft",
            )
        return factor

    if "XUNITS" not in header:
        raise ProfileFileError(path, end + 1, "the header has no XUNITS (distance unit)")
    scale_x = unit_of(header["XUNITS"].split()[0] if header["XUNITS"] else "", "XUNITS")
    units = per_channel.get("UNITSNAM")
    if units is None or len(units) < n_channels:
        raise ProfileFileError(
            path, end + 1, f"UNITSNAM must give an elevation unit for each of {n_channels} channels"
        )
    scales = [unit_of(units[i], "UNITSNAM") for i in range(n_channels)]
    names = per_channel.get("SHORTNAM", [])
    names = [names[i] if i < len(names) else f"channel {i + 1}" for i in range(n_channels)]

    data = np.empty((n_samples, n_channels))
    row = 0
    for index in range(end + 1, len(lines)):
        line = lines[index].strip()
        if not line:
            continue
        number = index + 1
        if row == n_samples:
            raise ProfileFileError(
                path, number, f"more data rows than the {n_samples} samples the header declares"
            )
        cells = _SPLIT.split(line)
        if cells and cells[-1] == "":
            cells.pop()
        if len(cells) != n_channels:
            raise ProfileFileError(
                path, number, f"expected {n_channels} values (one per channel), found {len(cells)}"
            )
        for j, cell in enumerate(cells):
            data[row, j] = _number(path, number, cell, f"channel {j + 1} value")
        row += 1
    if row < n_samples:
        raise ProfileFileError(
            path, len(lines), f"only {row} data rows; the header declares {n_samples} samples"
        )
    interval = step * scale_x
    x = interval * np.arange(n_samples)
    channels = tuple(Profile(x, data[:, j] * scales[j], name=names[j]) for j in range(n_channels))
    return ErdFile(channels, header, interval, str(path))


def _key_line(lines: list[str], key: str) -> int:
    """1-based number of the header line holding ``key``."""
    for index, line in enumerate(lines):
        if line[:8].strip().upper() == key:
            return index + 1
    return 0
