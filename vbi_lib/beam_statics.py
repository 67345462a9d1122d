r"""Statics of a uniform continuous beam: point loads and the static envelopes of axle groups.

The point-load statics (the three-moment equation, both faces of the shear) are
:mod:`vbi_lib.beam_influence`'s and are given here too: :func:`continuous_statics`,
:func:`support_face`, :func:`effect_index`, :data:`EFFECTS`, :data:`SIDES`,
:data:`DIRECTIONS`.

**Static envelope** (:func:`static_envelope`).  A group of axles (loads :math:`P_i` at
:math:`o_i` behind the first) crawls over the bridge; at each section the largest and
smallest value of each effect over the positions :math:`p` of the group,
:math:`Q(p) = \sum_i P_i\, \eta(x, p - o_i)` with :math:`\eta` the influence line, is found
exactly.  Every influence line of a uniform continuous beam is a cubic polynomial of the
load's position between its kinks (the supports and the section itself: the support moments
carry :math:`a b (L + a)`, the simple span's :math:`M_0, V_0, w_0` are at most cubic on
either side of the section), so :math:`Q` is a cubic between the positions where an axle is
over a support or over the section.  Each of those pieces is fitted exactly from four
interior values, and its extremes are its end limits and the roots of its derivative: no
search, no grid, and the supremum at a jump of the shear (an axle just passing the section)
is its one-sided limit.  ``direction="backward"`` runs the group the other way (the vehicle
turned round: loads in reverse order); ``"both"`` keeps the larger of the two.

The envelopes' stations are stations from the bridge start; displacement positive up (as the
crossing results), moment sagging positive, shear ``dM/dx`` on a named face at supports.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd
from scipy.optimize import minimize_scalar

from . import _validation as check
from . import display
from .beam_influence import (
    DIRECTIONS,
    EFFECTS,
    QUANTITY,
    SIDES,
    _side,
    _span_lengths,
    _stations,
    continuous_statics,
    effect_index,
    support_face,
)
from .continuous_beams import support_stations

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "DIRECTIONS",
    "EFFECTS",
    "QUANTITY",
    "SIDES",
    "StaticEnvelope",
    "continuous_statics",
    "effect_index",
    "envelope",
    "field_envelope",
    "static_envelope",
    "support_face",
]

#: Interior points of a piece [0, 1] where a cubic is sampled (Chebyshev points of the 2nd
#: kind of degree 4 less the ends, well conditioned), and the inverse of their Vandermonde
#: matrix: values there -> coefficients of 1, t, t^2, t^3.
_NODES = 0.5 - 0.5 * np.cos(np.pi * (np.arange(4) + 0.5) / 4)
_FIT = np.linalg.inv(np.vander(_NODES, 4, increasing=True))


# ---------------------------------------------------------------------------- envelopes
@dataclass(frozen=True, eq=False)
class StaticEnvelope:
    """Largest and smallest static effects at sections as a group of axles crawls across.

    Attributes
    ----------
    sections
        Stations from the bridge start [m], shape ``(n_s,)``.
    maximum, minimum
        Largest and smallest value of each effect, shape ``(3, n_s)`` in the order of
        :data:`EFFECTS`: displacement [m] (positive **up**, as the crossing results),
        moment [N m] (sagging positive), shear [N].
    maximum_at, minimum_at
        Where each occurs: the station of the vehicle's front axle from the bridge start
        [m], ``(3, n_s)`` (for a backward crossing too; at a jump of the shear, where its
        one-sided limit is reached).
    faces
        Face of the shear at each section (:func:`support_face`): ``"left"`` or ``"right"``
        at a support, ``""`` inside a span; empty when not recorded.
    direction
        ``"forward"`` (the vehicle from the first support), ``"backward"`` or ``"both"``.
    maximum_direction, minimum_direction
        With ``direction="both"``: ``"forward"`` or ``"backward"``, the direction of each
        extreme, ``(3, n_s)``; else ``None``.
    """

    sections: np.ndarray
    maximum: np.ndarray
    minimum: np.ndarray
    maximum_at: np.ndarray
    minimum_at: np.ndarray
    faces: tuple[str, ...] = ()
    direction: str = "forward"
    maximum_direction: np.ndarray | None = field(default=None, repr=False)
    minimum_direction: np.ndarray | None = field(default=None, repr=False)

    def to_dataframe(self) -> pd.DataFrame:
        """One row per section and effect: the extremes (display units) and where they occur.

        Columns: section, effect, face (of the shear at a support, else empty), unit,
        maximum, minimum, the front axle's station at each, and with ``direction="both"``
        the direction of each.
        """
        rows = []
        faces = self.faces or ("",) * self.sections.size
        for e, effect in enumerate(EFFECTS):
            quantity = QUANTITY[effect]
            for i, x in enumerate(self.sections):
                row = {
                    display.label("section", "length"): display.value(x, "length"),
                    "effect": effect,
                    "face": faces[i] if effect == "shear" else "",
                    "unit": display.symbol(quantity),
                    "maximum": display.value(self.maximum[e, i], quantity),
                    "minimum": display.value(self.minimum[e, i], quantity),
                    display.label("front axle at maximum", "length"): display.value(
                        self.maximum_at[e, i], "length"
                    ),
                    display.label("front axle at minimum", "length"): display.value(
                        self.minimum_at[e, i], "length"
                    ),
                }
                if self.maximum_direction is not None:
                    row["direction of maximum"] = self.maximum_direction[e, i]
                    row["direction of minimum"] = self.minimum_direction[e, i]
                rows.append(row)
        return pd.DataFrame(rows)

    def plot(self, ax: Axes | None = None, effect: str = "moment") -> Axes:
        """Plot the envelope of one effect against the section (display units).

        A station given twice (both faces of a support, :func:`field_envelope`) draws the
        jump of the shear there.
        """
        import matplotlib.pyplot as plt

        e = effect_index(effect)
        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        x = display.value(self.sections, "length")
        quantity = QUANTITY[effect]
        marker = "-" if self.sections.size > 40 else "o-"
        ax.plot(x, display.value(self.maximum[e], quantity), marker, ms=3, label="maximum")
        ax.plot(x, display.value(self.minimum[e], quantity), marker, ms=3, label="minimum")
        ax.axhline(0.0, color="k", lw=0.8)
        ax.set_xlabel(display.label("section from the start of the bridge", "length"))
        ax.set_ylabel(display.label(f"static {effect}", quantity))
        ax.legend(loc="best")
        return ax


def _axles(loads: object, offsets: object) -> tuple[np.ndarray, np.ndarray]:
    p = np.atleast_1d(np.asarray(loads, dtype=float))
    o = np.atleast_1d(np.asarray(offsets, dtype=float))
    if p.ndim != 1 or p.size < 1 or not np.isfinite(p).all() or (p < 0).any():
        raise ValueError(f"axle_loads={loads!r} must be one or more finite loads >= 0 [N]")
    if o.shape != p.shape or not np.isfinite(o).all() or (o < 0).any():
        raise ValueError(
            f"axle_offsets={offsets!r} must give one distance >= 0 behind the first axle [m] "
            f"for each of the {p.size} axle loads"
        )
    return p, o


def envelope(
    influence: Callable[[np.ndarray], np.ndarray],
    supports: np.ndarray,
    sections: np.ndarray,
    axle_loads: np.ndarray,
    axle_offsets: np.ndarray,
) -> StaticEnvelope:
    """Extremes over the positions of an axle group of any (smooth) influence lines.

    ``influence(a)`` gives the effects of a unit downward load at stations ``a`` (``(n_a,)``
    on the bridge) at the sections, shape ``(3, n_a, n_s)``.  Positions of the first axle
    run from the bridge start until the last axle leaves; a fine grid holds every kink (an
    axle over a section or a support, from either side), and the best point of each extreme
    is refined with a bounded scalar search.  For the exact beam, :func:`static_envelope`
    is exact and much faster; this serves influence lines of another form (the N-mode ones
    of :mod:`vbi_lib.models.sections`).
    """
    length = float(supports[-1])
    tiny = 1e-9 * length
    spacing = float(np.diff(supports).min()) / 200.0
    end = length + float(axle_offsets.max())
    kinks = np.concatenate([np.asarray(sections, dtype=float), supports])
    points = [np.linspace(0.0, end, int(math.ceil(end / spacing)) + 1)]
    for offset in axle_offsets:
        points += [kinks + offset, kinks + offset - tiny, kinks + offset + tiny]
    grid = np.unique(np.clip(np.concatenate(points), 0.0, end))

    def total(first: np.ndarray) -> np.ndarray:
        out = np.zeros((3, first.size, sections.size))
        for load, offset in zip(axle_loads, axle_offsets, strict=True):
            at = first - offset
            on = (at >= 0.0) & (at <= length)
            if on.any():
                out[:, on] += load * influence(at[on])
        return out

    values = total(grid)
    result = {}
    for sense, pick in (("maximum", np.argmax), ("minimum", np.argmin)):
        best = np.empty((3, sections.size))
        where = np.empty((3, sections.size))
        sign = 1.0 if sense == "maximum" else -1.0
        for e in range(3):
            for i in range(sections.size):
                k = int(pick(values[e, :, i]))
                best[e, i], where[e, i] = values[e, k, i], grid[k]
                lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
                if hi - lo <= 2.0 * tiny:
                    continue
                found = minimize_scalar(
                    lambda p, e=e, i=i, sign=sign: -sign * float(total(np.array([p]))[e, 0, i]),
                    bounds=(lo, hi),
                    method="bounded",
                    options={"xatol": 1e-10 * length},
                )
                if -found.fun > sign * best[e, i]:  # found.fun = -sign * f(x)
                    best[e, i], where[e, i] = -found.fun * sign, float(found.x)
        result[sense] = (best, where)
    return StaticEnvelope(
        sections=np.array(sections, dtype=float),
        maximum=result["maximum"][0],
        minimum=result["minimum"][0],
        maximum_at=result["maximum"][1],
        minimum_at=result["minimum"][1],
    )


def _cubic_extremes(lo: np.ndarray, width: np.ndarray, samples: np.ndarray):  # noqa: ANN202
    """Largest and smallest value of cubics given by their values at :data:`_NODES`.

    ``lo``, ``width``: ``(n_s, n_p)`` pieces; ``samples``: ``(3, n_s, n_p, 4)``.  Returns
    the extremes and their positions, each ``(3, n_s)``; pieces of no width are skipped.
    """
    c = samples @ _FIT.T  # (3, n_s, n_p, 4): coefficients of 1, t, t^2, t^3
    qa, qb, qc = 3.0 * c[..., 3], 2.0 * c[..., 2], c[..., 1]  # the derivative's
    with np.errstate(divide="ignore", invalid="ignore"):
        disc = qb * qb - 4.0 * qa * qc
        root = np.sqrt(np.where(disc >= 0.0, disc, np.nan))
        q = -0.5 * (qb + np.copysign(root, qb))
        scale = np.abs(c).max(axis=-1)
        quadratic = np.abs(qa) > 1e-12 * scale
        r1 = np.where(quadratic, q / qa, -qc / qb)
        r2 = np.where(quadratic, qc / q, np.nan)
    t = np.stack([np.zeros_like(r1), np.ones_like(r1), r1, r2], axis=-1)
    t = np.where((t >= 0.0) & (t <= 1.0), t, np.nan)
    t[..., :2] = [0.0, 1.0]
    value = c[..., :1] + t * (c[..., 1:2] + t * (c[..., 2:3] + t * c[..., 3:4]))
    empty = np.broadcast_to((width <= 0.0)[None, :, :, None], value.shape)
    out = []
    for fill, pick in ((-np.inf, np.nanargmax), (np.inf, np.nanargmin)):
        v = np.where(empty | np.isnan(value), fill, value)
        flat = v.reshape(*v.shape[:2], -1)
        k = pick(flat, axis=-1)
        best = np.take_along_axis(flat, k[..., None], axis=-1)[..., 0]
        piece, candidate = np.divmod(k, 4)
        tt = np.take_along_axis(t.reshape(*t.shape[:2], -1), k[..., None], axis=-1)[..., 0]
        start = np.take_along_axis(lo[None], piece[..., None], axis=-1)[..., 0]
        size = np.take_along_axis(width[None], piece[..., None], axis=-1)[..., 0]
        del candidate
        out.append((best, start + tt * size))
    return out


def _exact_envelope(
    lengths: np.ndarray,
    supports: np.ndarray,
    EI: float,
    x: np.ndarray,
    side: str,
    loads: np.ndarray,
    offsets: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Exact extremes of every effect at ``x`` over the positions of the first axle, with the
    positions: ``(maximum, minimum, maximum_at, minimum_at)``, each ``(3, n_s)``."""
    total = float(supports[-1])
    end = total + float(offsets.max())
    knots = np.concatenate([np.broadcast_to(supports, (x.size, supports.size)), x[:, None]], 1)
    breaks = (knots[:, None, :] + offsets[None, :, None]).reshape(x.size, -1)
    ends = np.broadcast_to([0.0, end], (x.size, 2))
    breaks = np.sort(np.clip(np.concatenate([breaks, ends], axis=1), 0.0, end), axis=1)
    lo = breaks[:, :-1]
    width = breaks[:, 1:] - lo
    width = np.where(width > 1e-12 * end, width, 0.0)
    first = lo[..., None] + width[..., None] * _NODES  # (n_s, n_p, 4)
    samples = np.zeros((3, *first.shape))
    for load, offset in zip(loads, offsets, strict=True):
        a = first - offset
        on = (a > 0.0) & (a < total)  # a piece lies wholly on or off the bridge
        if not on.any() or load == 0.0:
            continue
        statics = continuous_statics(
            x[:, None, None], np.clip(a, 0.0, total), lengths, EI, side=side
        )
        for e, values in enumerate((-statics.deflection, statics.moment, statics.shear)):
            samples[e] += load * np.where(on, values, 0.0)
    (maximum, maximum_at), (minimum, minimum_at) = _cubic_extremes(lo, width, samples)
    return maximum, minimum, maximum_at, minimum_at


def _sides(side: object, n: int) -> list[str]:
    if isinstance(side, str):
        return [_side(side)] * n
    sides = [_side(s) for s in side]
    if len(sides) != n:
        raise ValueError(f"side={side!r} must be one face, or one for each of the {n} sections")
    return sides


def static_envelope(
    spans: Sequence[float],
    EI: float,
    sections: float | Sequence[float] | np.ndarray,
    axle_loads: float | Sequence[float] = 1.0,
    axle_offsets: float | Sequence[float] = 0.0,
    *,
    side: str | Sequence[str] = "left",
    direction: str = "forward",
) -> StaticEnvelope:
    """Exact static envelope at sections of a continuous beam under a crawling axle group.

    Exact to rounding, from the piecewise-cubic influence lines (module docstring); about a
    millisecond for a few sections, some 50 ms for 300 sections of three spans under three
    axles.

    Parameters
    ----------
    spans
        Span lengths [m] (``bridge.spans``).
    EI
        Flexural rigidity [N m^2].
    sections
        Stations from the bridge start [m].
    axle_loads
        Load of each axle [N], downward (one sprung mass: its weight), front axle first.
    axle_offsets
        Distance of each axle behind the first [m] (0 for the first).
    side
        Face of the shear at a support (``"left"`` or ``"right"``), one for all sections or
        one per section; it matters only at interior supports.
    direction
        ``"forward"``: the vehicle enters at the first support; ``"backward"``: at the last
        (front axle first, so the axles pass in reverse order); ``"both"``: the larger
        extreme of the two, with ``maximum_direction`` saying which.

    Returns
    -------
    StaticEnvelope
        Displacement positive up (a deflection is negative), as the crossing results.

    Raises
    ------
    ValueError
        A section off the beam; loads and offsets of different lengths or negative; an
        unknown side or direction.

    Examples
    --------
    One span of 10 m under 100 kN: ``P L / 4`` at midspan, shear ``+-P/2`` there.

    >>> env = static_envelope([10.0], 1e9, [5.0], 1e5)
    >>> [round(float(v)) for v in (env.maximum[1, 0], env.maximum[2, 0], env.minimum[2, 0])]
    [250000, 50000, -50000]

    Both faces of the interior support of two 10 m spans: the shear just left of it tends
    to ``-P`` as the load comes up to the support, just right of it to ``+P`` as it leaves.

    >>> faces = [static_envelope([10, 10], 1e9, 10.0, 1e5, side=s) for s in ("left", "right")]
    >>> [(round(float(f.minimum[2, 0])), round(float(f.maximum[2, 0]))) for f in faces]
    [(-100000, 0), (0, 100000)]
    """
    lengths = _span_lengths(spans)
    EI = check.positive("EI", EI)
    if direction not in DIRECTIONS:
        raise ValueError(
            f"direction={direction!r} must be one of {', '.join(map(repr, DIRECTIONS))}"
        )
    supports = support_stations(lengths)
    x = np.atleast_1d(_stations("sections", sections, float(supports[-1]))).astype(float).ravel()
    loads, offsets = _axles(axle_loads, axle_offsets)
    sides = _sides(side, x.size)
    faces = tuple(support_face(float(v), supports, s) for v, s in zip(x, sides, strict=True))
    runs = []
    for way in ("forward", "backward") if direction == "both" else (direction,):
        if way == "forward":
            group = (loads, offsets)
        else:  # turned round: seen from the first support the rear axle comes first
            wheelbase = float(offsets.max())
            group = (loads[::-1], wheelbase - offsets[::-1])
        out = [np.empty((3, x.size)) for _ in range(4)]
        for face in set(sides):
            take = np.array([s == face for s in sides])
            part = _exact_envelope(lengths, supports, EI, x[take], face, *group)
            for whole, piece in zip(out, part, strict=True):
                whole[:, take] = piece
        if way == "backward":  # the front axle is the last of the turned group
            out[2] -= float(offsets.max())
            out[3] -= float(offsets.max())
        runs.append(out)
    if direction != "both":
        maximum, minimum, maximum_at, minimum_at = runs[0]
        return StaticEnvelope(x, maximum, minimum, maximum_at, minimum_at, faces, direction)
    (fmax, fmin, fmax_at, fmin_at), (bmax, bmin, bmax_at, bmin_at) = runs
    back_max, back_min = bmax > fmax, bmin < fmin
    return StaticEnvelope(
        sections=x,
        maximum=np.where(back_max, bmax, fmax),
        minimum=np.where(back_min, bmin, fmin),
        maximum_at=np.where(back_max, bmax_at, fmax_at),
        minimum_at=np.where(back_min, bmin_at, fmin_at),
        faces=faces,
        direction="both",
        maximum_direction=np.where(back_max, "backward", "forward"),
        minimum_direction=np.where(back_min, "backward", "forward"),
    )


def field_envelope(
    spans: Sequence[float],
    EI: float,
    axle_loads: float | Sequence[float] = 1.0,
    axle_offsets: float | Sequence[float] = 0.0,
    *,
    count: int = 301,
    direction: str = "both",
) -> StaticEnvelope:
    """The static envelope over the whole bridge: ``count`` even stations, every support
    among them, each interior support twice (its left face, then its right).

    Parameters and result as :func:`static_envelope`; ``faces`` names the face of each
    support station.

    Examples
    --------
    >>> env = field_envelope([20.0, 30.0, 20.0], 2e10, [36e3, 142e3, 142e3], [0, 4.27, 8.53],
    ...                      count=71)
    >>> env.sections.size, env.faces[20:22]
    (73, ('left', 'right'))
    """
    lengths = _span_lengths(spans)
    count = check.integer("count", count, low=2, high=100_000)
    supports = support_stations(lengths)
    x = np.unique(np.concatenate([np.linspace(0.0, supports[-1], count), supports]))
    inner = supports[1:-1]
    near = np.abs(x[:, None] - inner[None, :]).min(axis=1) if inner.size else np.full(x.size, 1.0)
    keep = (near > 1e-9 * supports[-1]) | np.isin(x, inner)
    x = x[keep]
    stations, sides = [], []
    for v in x:
        if inner.size and np.isin(v, inner):
            stations += [v, v]
            sides += ["left", "right"]
        else:
            stations.append(v)
            sides.append("left")
    return static_envelope(
        lengths, EI, np.array(stations), axle_loads, axle_offsets, side=sides,
        direction=direction,
    )  # fmt: skip
