r"""Roughness of a road profile: ISO 8608 parameters and the IRI.

Two ways to put a number on a profile, each weighed in the study's chapter 14 as a
predictor of dynamic amplification (the third, a vehicle-only contact-force metric, is in
:mod:`vbi_lib.vehicle_metrics`):

**ISO 8608 parameters** (:func:`fit_iso8608`, :func:`profile_spectrum`).  The displacement
PSD of the road is modelled as :math:`G_d(n) = C_{10} (n / n_0)^{-w}`, :math:`n_0 = 0.1`
cycle/m (study equation 87, :eq:`study-87` in the book).  The one-sided PSD is estimated
with Welch's method (Hann window, 50 % overlap, each segment detrended with a straight
line), averaged over 1/3-octave bands centred on :math:`0.1 \cdot 2^{k/3}` cycle/m, and a
straight line is fitted to :math:`\log G_d` against :math:`\log (n / n_0)` (each band
weighted by the square root of its number of Welch bins), giving :math:`C_{10}` and
:math:`w`.

**International Roughness Index** (:func:`iri`).  The golden quarter car (per unit sprung
mass: tyre :math:`k_1 = 653\ s^{-2}`, suspension :math:`k_2 = 63.3\ s^{-2}`, damper
:math:`c = 6.0\ s^{-1}`, unsprung mass ratio :math:`\mu = 0.15`) drives at 80 km/h over the
profile smoothed by a 250 mm moving average.  With states
:math:`z = (z_s, \dot z_s, z_u, \dot z_u)`

.. math::
    \dot z = A z + B\, y', \quad
    A = \begin{pmatrix} 0 & 1 & 0 & 0 \\ -k_2 & -c & k_2 & c \\ 0 & 0 & 0 & 1 \\
        k_2/\mu & c/\mu & -(k_1 + k_2)/\mu & -c/\mu \end{pmatrix}, \quad
    B = (0, 0, 0, k_1/\mu)^T

written for slopes (Sayers 1995, TRR 1501; ASTM E1926): the input is the slope of the
smoothed profile, constant over each sample interval, so one step is exactly
:math:`z_{i+1} = e^{A \Delta t} z_i + A^{-1}(e^{A \Delta t} - I) B\, y'_i` with
:math:`\Delta t = \Delta x / V`.  The car starts at steady state on the mean slope of the
first 11 m; the IRI is the mean of :math:`|z_1 - z_3|` (suspension stroke rate over speed),
reported in m/km (1 m/km = 63.36 in/mi).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

import numba
import numpy as np
import scipy.linalg
import scipy.signal

from . import _validation as check
from . import display
from .profiles import ISO_BAND, Profile
from .ranges import RANGES, outside_note, warn_outside

if TYPE_CHECKING:
    import pandas as pd
    from matplotlib.axes import Axes

#: Golden quarter car, per unit sprung mass: k1 [1/s^2], k2 [1/s^2], c [1/s], mu [-].
GOLDEN_CAR = {"k1": 653.0, "k2": 63.3, "c": 6.0, "mu": 0.15}
#: IRI reference speed [m/s] (80 km/h).
IRI_SPEED = 80.0 / 3.6
#: IRI moving-average base length [m].
IRI_BASE = 0.25
#: Length over which the initial slope is taken [m].
IRI_LEAD = 11.0
#: in/mi per m/km.
IN_PER_MI = 63.36


# ---------------------------------------------------------------------------- ISO 8608
class Iso8608Fit(NamedTuple):
    """``G_d(0.1 cycle/m)`` [m^3] and the waviness ``w`` of a profile."""

    c10: float
    waviness: float


@dataclass(frozen=True, eq=False)
class ProfileSpectrum:
    """Welch PSD of a profile, its 1/3-octave band averages and the ISO 8608 line through them.

    Attributes
    ----------
    frequency, psd
        Welch bins [cycle/m] and the one-sided displacement PSD ``G_d`` [m^3].
    band_frequency, band_psd
        Centres of the 1/3-octave bands used in the fit [cycle/m] and their mean PSD [m^3].
    c10, waviness
        The fitted ``G_d(0.1)`` [m^3] and ``w``.
    segment_length
        Length of the Welch segments [m].
    """

    frequency: np.ndarray
    psd: np.ndarray
    band_frequency: np.ndarray
    band_psd: np.ndarray
    c10: float
    waviness: float
    segment_length: float

    @property
    def iso_class(self) -> str:
        """ISO 8608 class of the fitted ``c10``."""
        from .profiles import iso8608_class

        return iso8608_class(self.c10)

    def fitted(self, frequency: np.ndarray) -> np.ndarray:
        """The fitted spectrum ``c10 (n / 0.1)^-w`` [m^3] at ``frequency`` [cycle/m]."""
        return self.c10 * (np.asarray(frequency) / 0.1) ** (-self.waviness)

    def plot(self, ax: Axes | None = None, label: str | None = None) -> Axes:
        """Log-log plot of the PSD, the band averages and the fitted line."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6, 4))
        keep = self.frequency > 0
        (line,) = ax.loglog(
            self.frequency[keep], self.psd[keep], lw=0.6, alpha=0.5, label=label or "Welch PSD"
        )
        ax.loglog(self.band_frequency, self.band_psd, "o", ms=4, color=line.get_color())
        ax.loglog(
            self.band_frequency,
            self.fitted(self.band_frequency),
            "--",
            color=line.get_color(),
            label=f"fit C10 = {self.c10 * 1e6:.0f}e-6 m$^3$, w = {self.waviness:.2f}",
        )
        ax.set_xlabel("spatial frequency n [cycle/m]")
        ax.set_ylabel("displacement PSD $G_d$ [m$^3$]")
        ax.legend(loc="best", fontsize="small")
        return ax

    def __repr__(self) -> str:
        return (
            f"ProfileSpectrum(C10 {self.c10 * 1e6:.1f}e-6 m^3, w {self.waviness:.2f}, "
            f"class {self.iso_class}; {self.band_frequency.size} bands "
            f"{self.band_frequency[0]:.3g}-{self.band_frequency[-1]:.3g} cycle/m)"
        )


def profile_spectrum(
    profile: Profile,
    band: tuple[float, float] = ISO_BAND,
    segment_length: float | None = None,
) -> ProfileSpectrum:
    """Welch PSD of a profile and the ISO 8608 line fitted to its 1/3-octave averages.

    Parameters
    ----------
    profile
        The road; read at its mean spacing if the samples are uneven.
    band
        Frequencies to fit [cycle/m]; bands below ``4 / segment_length`` (fewer than four
        cycles per segment) are left out.
    segment_length
        Welch segment length [m]; default a quarter of the profile, at most 250 m.

    Raises
    ------
    TypeError
        ``profile`` that is not a :class:`~vbi_lib.Profile`, a band that is not two numbers.
    ValueError
        A profile too short for two 1/3-octave bands, or one with no roughness to fit (a
        straight line or grade: the fitted ``c10`` would be below the range of validity of
        ``c10``, :data:`vbi_lib.ranges.RANGES`), or so rough that no road is (check the
        elevation unit).

    Warns
    -----
    OutsideValidityWarning
        A fitted ``c10`` or waviness outside the intended range: not a road of ISO 8608
        classes A to E, or a spectrum whose slope is unlike a road's.

    Examples
    --------
    >>> road = Profile.iso8608(2000.0, 0.05, c10=300e-6, waviness=2.0, seed=7)
    >>> spectrum = profile_spectrum(road)
    >>> round(spectrum.c10 * 1e6, -1), round(spectrum.waviness, 1), spectrum.iso_class
    (300.0, 2.0, 'C')
    """
    profile = _uniform(profile)
    spacing = profile.spacing
    if segment_length is None:
        segment_length = min(profile.length / 4.0, 250.0)
    segment_length = check.positive("segment_length", segment_length)
    if isinstance(band, str | bytes) or not hasattr(band, "__len__") or len(band) != 2:
        raise TypeError(f"band={band!r} must be two frequencies (low, high) in cycle/m")
    low, high = (check.finite(f"band[{i}]", b) for i, b in enumerate(band))
    if not 0 < low < high:
        raise ValueError(f"band={band!r} must satisfy 0 < low < high (cycle/m)")
    per_segment = min(profile.x.size, max(8, int(round(segment_length / spacing))))
    frequency, psd = scipy.signal.welch(
        profile.elevation,
        fs=1.0 / spacing,
        window="hann",
        nperseg=per_segment,
        noverlap=per_segment // 2,
        detrend="linear",
    )
    low = max(low, 4.0 / (per_segment * spacing))
    high = min(high, 0.5 / spacing)
    k = np.arange(math.ceil(3 * math.log2(low / 0.1)), math.floor(3 * math.log2(high / 0.1)) + 1)
    centres = 0.1 * 2.0 ** (k / 3.0)
    band_f, band_g, weight = [], [], []
    for centre in centres:
        inside = (frequency >= centre * 2 ** (-1 / 6)) & (frequency < centre * 2 ** (1 / 6))
        if inside.any() and psd[inside].mean() > 0:
            band_f.append(centre)
            band_g.append(psd[inside].mean())
            weight.append(math.sqrt(inside.sum()))
    if len(band_f) < 2:
        raise ValueError(
            f"profile {profile.name!r} ({profile.length:.1f} m every {spacing * 1e3:.1f} mm) has "
            f"fewer than two 1/3-octave bands in {band!r} cycle/m with Welch segments of "
            f"{per_segment * spacing:.1f} m; use a longer profile or a wider band"
        )
    band_f, band_g, weight = np.array(band_f), np.array(band_g), np.array(weight)
    design = np.column_stack((np.ones_like(band_f), np.log10(band_f / 0.1)))
    solution = np.linalg.lstsq(design * weight[:, None], np.log10(band_g) * weight, rcond=None)[0]
    c10, waviness = float(10.0 ** solution[0]), float(-solution[1])
    _check_fit(profile, c10, waviness)
    return ProfileSpectrum(
        frequency=frequency,
        psd=psd,
        band_frequency=band_f,
        band_psd=band_g,
        c10=c10,
        waviness=waviness,
        segment_length=per_segment * spacing,
    )


def _check_fit(profile: Profile, c10: float, waviness: float) -> None:
    """Refuse a fit of a road with no roughness (or an absurd one); warn outside intended use."""
    low, high = RANGES["c10"].hard
    if not low <= c10 <= high:
        why = (
            "it has no roughness the fit can measure: it is a straight line or grade to "
            "rounding error (rms under 1 micrometre)"
            if c10 < low
            else "no road is this rough: are the elevations in metres?"
        )
        raise ValueError(
            f"profile={profile!r}: the fitted c10={c10:.3g} m^3 lies outside the range of "
            f"validity of c10 ({RANGES['c10'].hard_text()}); {why}"
        )
    notes = [outside_note("c10", c10, "fitted c10"), outside_note("waviness", waviness,
                                                                   "fitted waviness")]  # fmt: skip
    for note in notes:
        if note:
            warn_outside(f"profile {profile.name!r}: {note}")


def fit_iso8608(
    profile: Profile,
    band: tuple[float, float] = ISO_BAND,
    segment_length: float | None = None,
) -> Iso8608Fit:
    """ISO 8608 parameters ``(c10, waviness)`` of a profile (see :func:`profile_spectrum`).

    Examples
    --------
    >>> road = Profile.iso8608(4000.0, 0.1, c10=600e-6, waviness=3.0, seed=2)
    >>> c10, w = fit_iso8608(road)
    >>> bool(abs(c10 / 600e-6 - 1) < 0.05), bool(abs(w - 3.0) < 0.05)
    (True, True)
    """
    spectrum = profile_spectrum(profile, band, segment_length)
    return Iso8608Fit(spectrum.c10, spectrum.waviness)


# ---------------------------------------------------------------------------- IRI
def golden_car_matrices() -> tuple[np.ndarray, np.ndarray]:
    """``A`` (4x4) and ``B`` (4,) of the golden quarter car, states ``(zs, zs', zu, zu')``."""
    k1, k2, c, mu = (GOLDEN_CAR[k] for k in ("k1", "k2", "c", "mu"))
    a = np.array(
        [
            [0.0, 1.0, 0.0, 0.0],
            [-k2, -c, k2, c],
            [0.0, 0.0, 0.0, 1.0],
            [k2 / mu, c / mu, -(k1 + k2) / mu, -c / mu],
        ]
    )
    b = np.array([0.0, 0.0, 0.0, k1 / mu])
    return a, b


@numba.njit(cache=True)
def _iri_kernel(slope, st, pr, state, stroke):
    """Step the golden car over ``slope``; ``stroke[i] = |zs - zu|`` after step ``i``."""
    z0, z1, z2, z3 = state[0], state[1], state[2], state[3]
    for i in range(slope.size):
        s = slope[i]
        n0 = st[0, 0] * z0 + st[0, 1] * z1 + st[0, 2] * z2 + st[0, 3] * z3 + pr[0] * s
        n1 = st[1, 0] * z0 + st[1, 1] * z1 + st[1, 2] * z2 + st[1, 3] * z3 + pr[1] * s
        n2 = st[2, 0] * z0 + st[2, 1] * z1 + st[2, 2] * z2 + st[2, 3] * z3 + pr[2] * s
        n3 = st[3, 0] * z0 + st[3, 1] * z1 + st[3, 2] * z2 + st[3, 3] * z3 + pr[3] * s
        z0, z1, z2, z3 = n0, n1, n2, n3
        stroke[i] = abs(z0 - z2)


@dataclass(frozen=True, eq=False)
class IriResult:
    """The IRI of a profile: the whole road and consecutive segments of it (m/km).

    Whatever :func:`iri` is asked, it returns this: ``result.iri`` is the whole-road IRI
    [m/km] (the one number to quote), and the segments hold the IRI of each consecutive piece
    of ``segment_length`` metres (one segment covering the road when no length was asked).

    Attributes
    ----------
    iri
        IRI of the whole profile [m/km] (multiply by :data:`IN_PER_MI` for in/mi).
    start, stop
        Stations bounding each segment [m], shape ``(n_segments,)``; the last segment may be
        shorter than ``segment_length``.
    segment_iri
        IRI of each segment [m/km], shape ``(n_segments,)``; always finite (a last piece of
        road too short to hold a slope step joins the segment before it).
    segment_length
        Length asked for [m], or ``None`` (one segment: the whole road).
    name
        Name of the profile.

    Examples
    --------
    >>> road = Profile.harmonic(1000.0, 0.025, wavelength=10.0, amplitude=0.001, phase=0.3)
    >>> result = iri(road, segment_length=400.0)
    >>> result
    IriResult('harmonic 10 m', 1000 m: IRI 0.50 m/km; 3 segments of 400 m: 0.50, 0.50, 0.50)
    >>> round(result.iri, 3), len(result)
    (0.503, 3)
    >>> result.to_dataframe().round(2)  # doctest: +NORMALIZE_WHITESPACE
             start_m  stop_m  iri_m_per_km
    segment
    0            0.0   400.0           0.5
    1          400.0   800.0           0.5
    2          800.0  1000.0           0.5
    """

    iri: float
    start: np.ndarray
    stop: np.ndarray
    segment_iri: np.ndarray
    segment_length: float | None = None
    name: str = ""

    @property
    def valid(self) -> np.ndarray:
        """``True`` for each segment with at least one slope step (a finite IRI)."""
        return np.isfinite(self.segment_iri)

    def __len__(self) -> int:
        return int(self.segment_iri.size)

    def to_dataframe(self) -> pd.DataFrame:
        """One row per segment: ``start_m``, ``stop_m``, ``iri_m_per_km`` (index ``segment``)."""
        import pandas as pd

        table = pd.DataFrame(
            {"start_m": self.start, "stop_m": self.stop, "iri_m_per_km": self.segment_iri}
        )
        return table.rename_axis("segment")

    def plot(self, ax: Axes | None = None, label: str | None = None) -> Axes:
        """Segment IRI as steps along the road, with the whole-road value dashed."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6, 3))
        edges = np.append(self.start, self.stop[-1])
        values = np.append(self.segment_iri, self.segment_iri[-1])
        (line,) = ax.step(edges, values, where="post", label=label or self.name or "segments")
        ax.axhline(
            self.iri, color=line.get_color(), ls="--", lw=1, label=f"whole {self.iri:.2f} m/km"
        )
        ax.set_xlabel("station [m]")
        ax.set_ylabel("IRI [m/km]")
        ax.legend(loc="best", fontsize="small")
        return ax

    def __repr__(self) -> str:
        label = f"{self.name!r}, " if self.name else ""
        length = self.stop[-1] - self.start[0]
        head = f"IriResult({label}{display.short(length, 'length', 3)}: IRI {self.iri:.2f} m/km"
        if self.segment_length is None:
            return head + ")"
        shown = ", ".join(f"{v:.2f}" for v in self.segment_iri[:6])
        more = ", ..." if self.segment_iri.size > 6 else ""
        return (
            f"{head}; {self.segment_iri.size} segments of "
            f"{display.short(self.segment_length, 'length', 3)}: {shown}{more})"
        )


def iri(profile: Profile, segment_length: float | None = None) -> IriResult:
    """International Roughness Index of a profile [m/km] (Sayers 1995, ASTM E1926).

    The golden quarter car at 80 km/h over the profile smoothed by a 250 mm moving average,
    starting in steady state on the mean slope of the first 11 m, stepped exactly (see the
    module docstring).  Profiles with uneven spacing are read at their mean spacing
    (linear interpolation).

    Parameters
    ----------
    profile
        The road (stations and elevations in metres); sample at 250 mm or finer.
    segment_length
        ``None`` for one segment covering the whole profile; otherwise consecutive segments
        of this length [m] from the first station (one run, the car's state carried from
        segment to segment; each slope step is assigned to the segment holding the middle of
        its 250 mm base).  A last piece of road that holds no slope step (shorter than the
        moving average or a sample interval) joins the segment before it, so the last
        segment may be up to that much longer than ``segment_length``.

    Returns
    -------
    IriResult
        ``result.iri`` the whole-road IRI [m/km] (multiply by 63.36 for in/mi);
        ``result.segment_iri`` the IRI of each segment.

    Raises
    ------
    TypeError
        ``profile`` that is not a :class:`~vbi_lib.Profile`, ``segment_length`` that is not
        a number.
    ValueError
        A profile shorter than the 250 mm moving average, or ``segment_length`` not positive
        or shorter than the 250 mm moving average or the profile's sample interval.

    Warns
    -----
    OutsideValidityWarning
        A profile shorter than 11 m (the IRI's start-up: the result is that of the start) or
        sampled more coarsely than every 250 mm (the IRI reads low); see ``iri_length`` and
        ``iri_spacing`` in :data:`vbi_lib.ranges.RANGES`.

    Examples
    --------
    A 1 mm sine of wavelength 10 m (the steady-state value is 0.503 m/km):

    >>> road = Profile.harmonic(2000.0, 0.025, wavelength=10.0, amplitude=0.001)
    >>> round(iri(road).iri, 3)
    0.503
    >>> iri(road, segment_length=800.0)
    IriResult('harmonic 10 m', 2000 m: IRI 0.50 m/km; 3 segments of 800 m: 0.50, 0.50, 0.50)
    >>> iri(road)
    IriResult('harmonic 10 m', 2000 m: IRI 0.50 m/km)
    """
    profile = _uniform(profile)
    dx = profile.spacing
    if segment_length is not None:
        segment_length = check.positive("segment_length", segment_length)
        shortest = max(dx, IRI_BASE)
        if segment_length < shortest:
            raise ValueError(
                f"segment_length={segment_length!r} m is shorter than the IRI's 250 mm moving "
                f"average or the profile's sample interval ({dx:g} m): segments would hold no "
                f"slope step; give at least {shortest:g} m"
            )
    y = profile.elevation
    base = max(1, int(round(IRI_BASE / dx)))
    if y.size <= base:
        raise ValueError(
            f"profile {profile.name!r} ({profile.length:.3f} m) is shorter than the IRI's "
            f"250 mm moving average; give at least {base + 1} samples"
        )
    for key, value, name in (
        ("iri_length", profile.length, "profile length"),
        ("iri_spacing", dx, "profile spacing"),
    ):
        note = outside_note(key, value, name)
        if note:
            warn_outside(f"profile {profile.name!r}: {note}")
    lead = min(int(round(IRI_LEAD / dx)), y.size - 1)
    initial = (y[lead] - y[0]) / (lead * dx)
    slope = (y[base:] - y[:-base]) / (base * dx)
    st, pr = _golden_transition(dx / IRI_SPEED)
    stroke = np.empty(slope.size)
    _iri_kernel(slope, st, pr, np.array([initial, 0.0, initial, 0.0]), stroke)
    whole = float(stroke.mean() * 1000.0)
    if segment_length is None:  # one segment: the whole road
        start, stop, values = np.array([profile.start]), np.array([profile.end]), np.array([whole])
        return IriResult(whole, start, stop, values, None, profile.name)
    centre = profile.x[: slope.size] + 0.5 * base * dx
    count = max(1, math.ceil(profile.length / segment_length - 1e-9))
    # the last segment holding a slope step takes the rest of the road
    count = min(count, int((centre[-1] - profile.start) // segment_length) + 1)
    index = np.minimum(((centre - profile.start) // segment_length).astype(np.int64), count - 1)
    sums = np.bincount(index, weights=stroke, minlength=count)
    steps = np.bincount(index, minlength=count)
    values = sums / steps * 1000.0
    start = profile.start + segment_length * np.arange(count)
    stop = np.minimum(start + segment_length, profile.end)
    stop[-1] = profile.end
    return IriResult(whole, start, stop, values, segment_length, profile.name)


def _golden_transition(dt: float) -> tuple[np.ndarray, np.ndarray]:
    """``ST = exp(A dt)`` and ``PR = A^-1 (ST - I) B`` of the golden car."""
    a, b = golden_car_matrices()
    st = scipy.linalg.expm(a * dt)
    pr = np.linalg.solve(a, (st - np.eye(4)) @ b)
    return st, pr


def _uniform(profile: Profile) -> Profile:
    """The profile itself when evenly sampled, else read at its mean spacing."""
    check.instance("profile", profile, Profile, "a vbi_lib.Profile")
    steps = np.diff(profile.x)
    spacing = profile.length / steps.size
    if np.abs(steps - spacing).max() <= 1e-6 * spacing:
        return profile
    return profile.resampled(spacing)


__all__ = [
    "GOLDEN_CAR",
    "IN_PER_MI",
    "Iso8608Fit",
    "IriResult",
    "ProfileSpectrum",
    "fit_iso8608",
    "golden_car_matrices",
    "iri",
    "profile_spectrum",
]
