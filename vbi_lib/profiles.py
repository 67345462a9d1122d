r"""Road profiles: the elevation the wheel follows, on the approach and on the bridge.

A :class:`Profile` is a list of stations ``x`` (strictly increasing, metres along the road)
and elevations (metres, positive up).  Between samples the road is a straight line, which is
how the simulation reads it: every sample is a node of the time grid, so the wheel's vertical
velocity ``v dDelta/dx`` is exact on each segment.

The sampling rule of the study (32): to see a natural frequency ``f_max`` at the slowest
speed of interest ``v_min``, sample at least every ``S_max = v_min / (2 f_max)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import _validation as check


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
