r"""How a tyre sees the road: the profile averaged over the tyre's contact length.

A tyre does not follow a road feature shorter than its contact patch: it envelops it.  The
library's rule is the one the IRI uses (ASTM E1926; Sayers 1995, TRR 1501): a **moving
average** of the road over the contact length :math:`L_c`,

.. math:: \bar\Delta(x) = \frac{1}{L_c} \int_{x - L_c/2}^{x + L_c/2} \Delta(s)\, ds ,

computed exactly for the road read linearly between its samples, evaluated at the profile's
own stations and read linearly between them again (so the crossing models keep every
sample as a node and the input stays exact on each step).  Beyond the profile's ends the
road is taken level at its end elevations.

Default :data:`DEFAULT_FOOTPRINT` = 0.25 m, the IRI's base length, which lies in the range
of contact lengths of heavy-vehicle tyres at their rated load (about 0.2 to 0.3 m; Cebon,
*Handbook of Vehicle-Road Interaction*, 1999, ch. 7 on tyre enveloping).  A step of height
``h`` becomes a ramp of slope ``h / L_c``: the damper's force stays bounded and results
converge as the sampling is refined.  The study's sprung mass has no footprint (its tables
are reproduced with the raw profile).
"""

from __future__ import annotations

import numpy as np

from .. import _validation as check
from ..profiles import Profile

__all__ = ["DEFAULT_FOOTPRINT", "footprint_average", "seen_by_tyre"]

#: Default tyre contact length [m] (the IRI's 250 mm moving average).
DEFAULT_FOOTPRINT = 0.25


def _integral(x: np.ndarray, y: np.ndarray, s: np.ndarray) -> np.ndarray:
    """``int_{x[0]}^{s} y`` of the piecewise-linear road, level beyond its ends."""
    slope = np.diff(y) / np.diff(x)
    cumulative = np.concatenate(([0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(x))))
    j = np.clip(np.searchsorted(x, s, side="right") - 1, 0, x.size - 2)
    d = s - x[j]
    inside = cumulative[j] + d * y[j] + 0.5 * d * d * slope[j]
    before = (s - x[0]) * y[0]
    after = cumulative[-1] + (s - x[-1]) * y[-1]
    return np.where(s < x[0], before, np.where(s > x[-1], after, inside))


def footprint_average(x: np.ndarray, elevation: np.ndarray, length: float) -> np.ndarray:
    """The road averaged over ``length`` [m] around each station ``x`` (see the module).

    Parameters
    ----------
    x, elevation
        Stations (strictly increasing) and elevations of a road read linearly [m].
    length
        Contact length [m]; 0 returns ``elevation`` unchanged.

    Returns
    -------
    ndarray
        The averaged elevation at each station [m], same shape as ``x``.

    Raises
    ------
    ValueError
        A negative or non-finite ``length``.

    Examples
    --------
    A 10 mm step (rising between 1.000 and 1.001 m) averaged over 0.25 m is a ramp:

    >>> x = np.linspace(0.0, 2.0, 2001)
    >>> y = np.where(x > 1.0, 0.01, 0.0)
    >>> avg = footprint_average(x, y, 0.25)
    >>> [round(float(np.interp(s, x, avg)) * 1e3, 2) for s in (0.8, 1.0005, 1.2)]
    [0.0, 5.0, 10.0]
    """
    length = check.non_negative("footprint", length)
    x = np.asarray(x, dtype=float)
    elevation = np.asarray(elevation, dtype=float)
    if length == 0.0:
        return elevation.copy()
    half = 0.5 * length
    return (_integral(x, elevation, x + half) - _integral(x, elevation, x - half)) / length


def seen_by_tyre(profile: Profile, footprint: float = DEFAULT_FOOTPRINT) -> Profile:
    """The road a tyre of contact length ``footprint`` [m] rides (a new :class:`Profile`).

    The profile averaged by :func:`footprint_average` at its own stations; the crossing
    models apply it to every tyre themselves, this is for looking at it.

    Parameters
    ----------
    profile
        The road.
    footprint
        Contact length [m], >= 0 (0 returns ``profile`` itself).

    Returns
    -------
    Profile
        Same stations, averaged elevations [m].

    Raises
    ------
    TypeError
        ``profile`` is not a :class:`Profile`.
    ValueError
        A negative or non-finite ``footprint``.

    Examples
    --------
    >>> road = Profile.step(4.0, 0.0025, position=2.0, height=0.01)
    >>> smooth = seen_by_tyre(road)
    >>> round(float(np.diff(smooth.elevation).max() / 0.0025), 3)   # slope h / L_c
    0.04
    """
    if not isinstance(profile, Profile):
        raise TypeError(f"profile must be a vbi.Profile, got {type(profile).__name__}")
    footprint = check.non_negative("footprint", footprint)
    if footprint == 0.0:
        return profile
    elevation = footprint_average(profile.x, profile.elevation, footprint)
    return Profile(profile.x, elevation, name=f"{profile.name} seen by a {footprint:g} m tyre")
