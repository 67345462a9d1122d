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
converge as the sampling is refined.  The study's sprung mass has no footprint by default
(its tables are reproduced with the raw profile); ``Vehicle(..., footprint=L_c)`` gives it one.

Without a footprint (or with one shorter than the sampling), a contact whose damper stands on
the road presses on it with :math:`c\,v\,dr/dx`, and over a feature sharper than the
profile's sampling that force is set by the sampling: :func:`unresolved_road_note` is the
test a crossing makes, and says so in its notes and an
:class:`~vbi_lib.validity.UnresolvedRoadWarning`.
"""

from __future__ import annotations

import warnings
import weakref
from typing import Any

import numpy as np

from .. import _validation as check
from ..profiles import Profile
from ..ranges import _caller_level
from ..validity import UnresolvedRoadWarning
from .system import VehicleSystem, as_system

__all__ = [
    "DEFAULT_FOOTPRINT",
    "FEATURE_CONTRAST",
    "UNRESOLVED_FORCE_RATIO",
    "footprint_average",
    "seen_by_tyre",
    "unresolved_damper_force",
    "unresolved_road_note",
    "warn_unresolved_roads",
]

#: Default tyre contact length [m] (the IRI's 250 mm moving average).
DEFAULT_FOOTPRINT = 0.25

#: Share of an axle's static load from which the damper force of the part of the road's slope
#: that only the finest sampling holds makes the contact force the sampling's
#: (:func:`unresolved_road_note`).
UNRESOLVED_FORCE_RATIO = 0.1

#: How many times larger than the changes of slope just outside it the jumps of slope into and
#: out of a sample interval must be for the interval to hold a feature the sampling does not
#: resolve (:func:`unresolved_road_note`).
FEATURE_CONTRAST = 2.0


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


_EXCESS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _excess_slope(profile: Profile, footprint: float) -> tuple[np.ndarray, np.ndarray]:
    """The sample intervals holding a one-interval feature of the road seen through
    ``footprint``, and the slope ``e_k`` each adds (see :func:`unresolved_road_note`).

    Remembered per profile while it lives (only those few intervals: a batch shares its
    roads, and a smooth road has none).
    """
    cache = _EXCESS.setdefault(profile, {})
    if footprint not in cache:
        x = profile.x
        slope = np.diff(footprint_average(x, profile.elevation, footprint)) / np.diff(x)
        level = np.zeros(2)  # beyond the ends the road is level
        padded = np.concatenate((level, slope, level))
        change = np.diff(padded)  # change[j] = padded[j + 1] - padded[j]
        into, out = change[1:-2], -change[2:-1]  # s_k - s_k-1 and s_k - s_k+1
        outside = np.maximum(np.abs(change[:-3]), np.abs(change[3:]))
        jump = np.minimum(np.abs(into), np.abs(out))
        peak = into * out > 0.0  # the slope peaks (or dips) on the interval itself
        where = np.flatnonzero(peak & (jump >= FEATURE_CONTRAST * outside) & (jump > 0.0))
        cache[footprint] = (where, jump[where])
    return cache[footprint]


def unresolved_damper_force(
    system: VehicleSystem, profile: Profile, bridge_start: float, bridge_length: float
) -> tuple[float, int, int]:
    """The largest unresolved damper force per unit speed over the static load [s/m].

    ``max over axles a and sample intervals k on the bridge of c_a e_k / W_a`` (see
    :func:`unresolved_road_note`), the axle (0-based) and the interval (index into
    ``profile.x``) where it is reached; ``(0.0, -1, -1)`` when no damped contact meets an
    unresolved feature.  Multiplied by the speed it is the share of the axle's static load.
    """
    best, found = 0.0, (-1, -1)
    window = None
    for a, damping in enumerate(system.contact_damping.tolist()):
        if damping <= 0.0:
            continue
        where, excess = _excess_slope(profile, float(system.footprint[a]))
        if where.size == 0:  # a smooth road: nothing to look for (the usual case, kept fast)
            continue
        if window is None:  # the intervals under an axle on the bridge
            first = max(0, int(np.searchsorted(profile.x, bridge_start, side="right")) - 1)
            last = int(np.searchsorted(profile.x, bridge_start + bridge_length, side="left"))
            window = np.searchsorted(where, [first, last])
        lo, hi = int(window[0]), int(window[1])
        if hi <= lo:
            continue
        k = lo + int(np.argmax(excess[lo:hi]))
        value = damping * float(excess[k]) / float(system.static_loads[a])
        if value > best:
            best, found = value, (a, int(where[k]))
    return best, *found


def unresolved_road_note(
    system: VehicleSystem,
    profile: Profile,
    speed: float,
    bridge_start: float,
    bridge_length: float,
) -> str | None:
    r"""The sentence saying a crossing's contact force is set by the road's sampling, or ``None``.

    **The criterion.**  A contact whose damper :math:`c_a` stands on the road (the study's
    sprung mass, an axle without a tyre, a damped tyre) presses on it with
    :math:`c_a v\,dr/dx` besides its spring's force, :math:`r` the road it sees (the
    profile averaged over its footprint).  Read linearly between samples, :math:`dr/dx` is
    the slope :math:`s_k` of each sample interval.  Where the sampling resolves the road, the
    slope changes smoothly from one interval to the next; at a kink (a ramp's corner) it
    changes once and stays.  A feature whose rise fits within one interval (a step, a
    joint's edge) instead makes the slope jump into the interval and back out of it, by more
    than it changes anywhere near: its slope :math:`h / \Delta x` is set by the interval,
    halving the spacing doubles it, and so the damper's force.  Interval :math:`k` holds
    such a feature when the slope peaks (or dips) on it, :math:`(s_k - s_{k-1})(s_k -
    s_{k+1}) > 0`, and both jumps are at least :data:`FEATURE_CONTRAST` (2) times the
    changes of slope just outside, :math:`|s_{k-1} - s_{k-2}|` and :math:`|s_{k+2} -
    s_{k+1}|`; the slope the feature adds is the smaller jump,

    .. math:: e_k = \min(|s_k - s_{k-1}|,\ |s_k - s_{k+1}|)

    (a step of height :math:`h` within one interval of a straight road: :math:`e_k = h /
    \Delta x`).  A sine sampled :math:`N` times a wavelength, samples straddling its steepest
    point, has jumps :math:`1 - \cos\theta` and outer changes :math:`\cos\theta -
    \cos 2\theta` times its steepest slope, :math:`\theta = 2\pi/N`: a contrast of 1 at
    :math:`N = 4` and less above (at any phase, checked numerically), so a road sampled four
    times a wavelength is never taken for an unresolved feature, nor is a kink (one jump is
    0).  The crossing's contact force is the sampling's when, on an interval under an axle
    on the bridge (where the contact force is read),

    .. math:: c_a\, v\, e_k \ge \text{UNRESOLVED\_FORCE\_RATIO} \times W_a ,

    10 % of the axle's static load: the contact-force amplification then grows by 0.1 or
    more each time the sampling is halved.  The spring's force :math:`k_a (r - u)` stays
    bounded by the feature's height, and the bridge's response, driven by the force's
    impulse :math:`c_a h`, converges whatever the sampling.  A footprint averages the
    feature over the contact length; once that spans a few samples the slope is resolved.

    Parameters
    ----------
    system
        The vehicle (:class:`~vbi_lib.vehicles.VehicleSystem`).
    profile
        The road.
    speed
        Vehicle speed [m/s].
    bridge_start, bridge_length
        Station of the first support and length of the bridge [m].

    Returns
    -------
    str or None
        The sentence, naming the axle, the station, the force and ``footprint``.

    Examples
    --------
    The study's sprung mass at 20 m/s over a 10 mm step sampled every 2.5 mm:

    >>> from vbi_lib import Vehicle
    >>> truck = Vehicle.from_frequency(2e4, 3.0, 0.1)
    >>> road = Profile.step(60.0, 0.0025, position=25.0, height=0.01)
    >>> unresolved_road_note(truck.system, road, 20.0, 20.0, 20.0)[:58]
    'the contact force is set by a road feature sharper than th'
    >>> unresolved_road_note(Vehicle.from_frequency(2e4, 3.0, 0.1, footprint=0.25).system,
    ...                      road, 20.0, 20.0, 20.0) is None
    True
    """
    per_speed, axle, k = unresolved_damper_force(system, profile, bridge_start, bridge_length)
    ratio = per_speed * speed
    if not ratio >= UNRESOLVED_FORCE_RATIO:
        return None
    x = profile.x
    elevation = footprint_average(x, profile.elevation, float(system.footprint[axle]))
    rise = (elevation[k + 1] - elevation[k]) * 1e3
    spacing = (x[k + 1] - x[k]) * 1e3
    which = f"axle {axle + 1}'s" if system.n_axles > 1 else "the"
    return (
        f"the contact force is set by a road feature sharper than the profile's sampling: at "
        f"station {x[k]:.4g} m the road under {which} contact rises {rise:.3g} mm within one "
        f"sample interval of {spacing:.3g} mm, and the damper force of the slope only that "
        f"interval holds, {ratio:.3g} times the axle's static load, grows as the sampling is "
        "refined (the bridge's response converges); give the vehicle a footprint (footprint="
        f"{DEFAULT_FOOTPRINT} m, a tyre's contact length, averages the road over it) or "
        "sample the feature's true shape"
    )


def warn_unresolved_roads(batch: Any) -> None:
    """:func:`unresolved_road_note` of every crossing of a batch, in one warning.

    ``batch`` is a :class:`~vbi_lib.models.batch.Batch` (what :func:`vbi_lib.simulate_many`
    checked).  The criterion is linear in the speed, so it is evaluated once per distinct
    vehicle, road, bridge and bridge start.

    Warns
    -----
    UnresolvedRoadWarning
        Naming how many crossings have a contact force set by the road's sampling, and the
        first one's sentence.
    """
    systems = [as_system(vehicle) for vehicle in batch.vehicles]
    first, inverse = batch.groups(batch.vehicle, batch.profile, batch.bridge, batch.bridge_start)
    per_speed = np.array([
        unresolved_damper_force(systems[batch.vehicle[i]], batch.profiles[batch.profile[i]],
                                float(batch.bridge_start[i]),
                                batch.bridges[batch.bridge[i]].length)[0]
        for i in first
    ])  # fmt: skip
    flagged = np.flatnonzero(per_speed[inverse] * batch.speed >= UNRESOLVED_FORCE_RATIO)
    if flagged.size:
        i = int(flagged[0])
        note = unresolved_road_note(systems[batch.vehicle[i]], batch.profiles[batch.profile[i]],
                                    float(batch.speed[i]), float(batch.bridge_start[i]),
                                    batch.bridges[batch.bridge[i]].length)  # fmt: skip
        warnings.warn(
            f"{flagged.size} of {len(batch)} crossings have a contact force set by the road's "
            f"sampling (crossing {i}: {note})",
            UnresolvedRoadWarning,
            stacklevel=_caller_level(),
        )
