r"""Statics of a uniform beam continuous over any spans, and its static envelopes under axles.

The static counterparts of the section responses (:mod:`vbi_lib.models.sections`) and the
exact part of the mode-acceleration method come from here.

**A point load on a continuous beam.**  Supports :math:`0 = s_0 < s_1 < \dots < s_N` (pinned,
no deflection), spans :math:`L_j = s_{j} - s_{j-1}`, one :math:`EI`.  The moments over the
interior supports follow from the three-moment equation (Clapeyron; e.g. Timoshenko & Young,
*Theory of Structures*): at support :math:`i`,

.. math::
    M_{i-1} L_i + 2 M_i (L_i + L_{i+1}) + M_{i+1} L_{i+1} =
    -\frac{P a b (L_i + a)}{L_i} \ \text{(load in span } i\text{)}
    \quad\text{or}\quad -\frac{P a b (L_{i+1} + b)}{L_{i+1}} \ \text{(load in span } i+1),

with :math:`a, b` the load's distances from the left and right supports of its span and
:math:`M_0 = M_N = 0`.  Each span is then a simple span carrying its own load plus its end
moments :math:`M_l, M_r`: at :math:`s` from its left support,

.. math::
    M = M_0(s) + M_l \left(1 - \tfrac{s}{L}\right) + M_r \tfrac{s}{L}, \quad
    V = V_0(s) + \frac{M_r - M_l}{L}, \quad
    w = w_0(s) + \frac{M_l s' (L^2 - s'^2) + M_r s (L^2 - s^2)}{6 L EI},

:math:`s' = L - s`, where :math:`M_0, V_0, w_0` are the simple span's (zero outside the loaded
span).  Deflection positive down (with the load), moment positive sagging, shear
:math:`V = dM/dx`.  The shear jumps at a load and at an interior support; ``side`` picks the
face: ``"left"`` (the default) is the value just to the left of the section, ``"right"`` just
to its right.  At the bridge's ends both give the one face on the beam (just right of
:math:`x = 0`, just left of the far end).  ``side="left"`` is the convention of
:func:`vbi_lib.closed_forms.point_load_statics`, which this reproduces for one span and two
equal spans.  The support moments depend on the load's position only, so they are solved
once per load position whatever the number of sections.

**Static envelope** (:func:`static_envelope`).  A group of axles (loads :math:`P_i` at
:math:`o_i` behind the first) crawls over the bridge; at each section the largest and
smallest value of each effect over the positions :math:`p` of the group,
:math:`R(p) = \sum_i P_i\, \eta(x, p - o_i)` with :math:`\eta` the influence line, is found
exactly.  Every influence line of a uniform continuous beam is a cubic polynomial of the
load's position between its kinks (the supports and the section itself: the support moments
carry :math:`a b (L + a)`, the simple span's :math:`M_0, V_0, w_0` are at most cubic on
either side of the section), so :math:`R` is a cubic between the positions where an axle is
over a support or over the section.  Each of those pieces is fitted exactly from four
interior values, and its extremes are its end limits and the roots of its derivative: no
search, no grid, and the supremum at a jump of the shear (an axle just passing the section)
is its one-sided limit.  ``direction="backward"`` runs the group the other way (the vehicle
turned round: loads in reverse order); ``"both"`` keeps the larger of the two.
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
from .closed_forms import BeamStatics
from .continuous_beams import support_stations

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "DIRECTIONS",
    "EFFECTS",
    "SIDES",
    "StaticEnvelope",
    "continuous_statics",
    "envelope",
    "field_envelope",
    "static_envelope",
    "support_face",
]

#: The effects at a section, in the order of every ``(3, ...)`` array.
EFFECTS = ("displacement", "moment", "shear")
#: The display quantity of each effect.
QUANTITY = {"displacement": "deflection", "moment": "moment", "shear": "force"}
#: Faces of a section for the shear, which jumps at a load and at an interior support.
SIDES = ("left", "right")
#: Directions a vehicle crosses in: from the first support, from the last, or both.
DIRECTIONS = ("forward", "backward", "both")
#: Interior points of a piece [0, 1] where a cubic is sampled (Chebyshev points of the 2nd
#: kind of degree 4 less the ends, well conditioned), and the inverse of their Vandermonde
#: matrix: values there -> coefficients of 1, t, t^2, t^3.
_NODES = 0.5 - 0.5 * np.cos(np.pi * (np.arange(4) + 0.5) / 4)
_FIT = np.linalg.inv(np.vander(_NODES, 4, increasing=True))


def _span_lengths(spans: object) -> np.ndarray:
    array = np.atleast_1d(check.real_array("spans", spans))
    if array.ndim != 1 or array.size < 1 or not np.isfinite(array).all() or (array <= 0).any():
        raise ValueError(f"spans={spans!r} must be one or more finite span lengths > 0 [m]")
    return array


def _stations(name: str, values: object, length: float) -> np.ndarray:
    array = check.real_array(name, values)
    if not np.isfinite(array).all():
        raise ValueError(f"{name}={values!r} must be finite stations [m]")
    if ((array < 0) | (array > length)).any():
        raise ValueError(
            f"{name}={values!r} must lie on the beam, 0 to {length:g} m from the first support"
        )
    return array


def _side(side: object) -> str:
    if side not in SIDES:
        raise ValueError(f"side={side!r} must be one of {', '.join(map(repr, SIDES))}")
    return str(side)


def support_face(x: float, supports: Sequence[float], side: str) -> str:
    """The face a shear at station ``x`` is on: ``"left"`` or ``"right"`` at a support, ``""``
    inside a span (where the shear has one value); at the bridge's ends the face on the beam.

    >>> support_face(20.0, [0.0, 20.0, 50.0], "right"), support_face(0.0, [0.0, 20.0], "left")
    ('right', 'right')
    """
    supports = np.asarray(supports, dtype=float)
    tolerance = 1e-9 * supports[-1]
    if abs(x - supports[0]) <= tolerance:
        return "right"
    if abs(x - supports[-1]) <= tolerance:
        return "left"
    if (np.abs(supports[1:-1] - x) <= tolerance).any():
        return _side(side)
    return ""


def _support_moments(a: np.ndarray, lengths: np.ndarray, supports: np.ndarray, force: float):  # noqa: ANN202
    """Moments over every support ``(n + 1, n_a)`` for a load at each station ``a`` ``(n_a,)``,
    and the load's span, its distances from that span's supports and the span's length."""
    n = lengths.size
    # the load's span (an interior support belongs to the span on its right: no bending)
    k = np.clip(np.searchsorted(supports, a, side="right") - 1, 0, n - 1)
    al = a - supports[k]
    big = lengths[k]
    bl = big - al
    moments = np.zeros((n + 1, a.size))
    if n > 1:
        matrix = np.zeros((n - 1, n - 1))
        rhs = np.zeros((n - 1, a.size))
        for i in range(1, n):  # support i: right end of span i-1, left end of span i
            left, right = lengths[i - 1], lengths[i]
            matrix[i - 1, i - 1] = 2.0 * (left + right)
            if i > 1:
                matrix[i - 1, i - 2] = left
            if i < n - 1:
                matrix[i - 1, i] = right
            rhs[i - 1] -= np.where(k == i - 1, force * al * bl * (big + al) / big, 0.0)
            rhs[i - 1] -= np.where(k == i, force * al * bl * (big + bl) / big, 0.0)
        moments[1:n] = np.linalg.solve(matrix, rhs)
    return moments, k, al, bl, big


def continuous_statics(
    x: float | np.ndarray,
    load_position: float | np.ndarray,
    spans: Sequence[float],
    EI: float,
    force: float = 1.0,
    *,
    side: str = "left",
) -> BeamStatics:
    """Exact statics of a uniform continuous beam under a point load (three-moment equation).

    Parameters
    ----------
    x
        Sections from the first support [m], in ``[0, sum(spans)]``.
    load_position
        Position of the load from the first support [m], same range; broadcast with ``x``
        (an influence line: fix ``x``, vary ``load_position``).
    spans
        Span lengths [m], any number, any lengths; pinned supports at every span end.
    EI
        Flexural rigidity [N m^2].
    force
        The load ``P`` [N], positive down.
    side
        Face of the shear where it jumps (at the load, at an interior support):
        ``"left"`` (default), the value just left of ``x``; ``"right"``, just right.  At the
        bridge's ends both give the face on the beam.

    Returns
    -------
    BeamStatics
        ``deflection`` [m] (down positive), ``moment`` [N m] (sagging positive) and ``shear``
        [N] (``dM/dx`` on the face ``side``), broadcast over ``x`` and ``load_position``.

    Raises
    ------
    ValueError
        A section or load off the beam, a span or EI that is not a positive number, an
        unknown ``side``.

    Examples
    --------
    Three equal spans, a unit load at the middle of the first: the three-moment equations
    ``4 M_1 + M_2 = -3/8`` and ``M_1 + 4 M_2 = 0`` give ``M_1 = -0.1 P L`` over the first
    interior support and ``M_2 = 0.025 P L`` over the second:

    >>> statics = continuous_statics([1.0, 2.0], 0.5, [1.0, 1.0, 1.0], 1.0)
    >>> statics.moment.round(6).tolist()
    [-0.1, 0.025]

    The shear on either face of the first interior support: the support's reaction
    ``0.6 + 0.125 = 0.725`` is the jump between them.

    >>> left = continuous_statics(1.0, 0.5, [1.0, 1.0, 1.0], 1.0).shear
    >>> right = continuous_statics(1.0, 0.5, [1.0, 1.0, 1.0], 1.0, side="right").shear
    >>> round(float(left), 6), round(float(right), 6)
    (-0.6, 0.125)
    """
    lengths = _span_lengths(spans)
    EI = check.positive("EI", EI)
    force = check.number("force", force)
    if not math.isfinite(force):
        raise ValueError(f"force={force!r} must be a finite number [N]")
    side = _side(side)
    supports = support_stations(lengths)
    total = float(supports[-1])
    x = _stations("x", x, total)
    a = _stations("load_position", load_position, total)
    shape = np.broadcast_shapes(x.shape, a.shape)
    n = lengths.size
    if x.ndim == 2 and a.ndim == 2 and x.shape[0] == 1 and a.shape[1] == 1:
        return _influence_matrix(x[0], a[:, 0], lengths, supports, EI, force, side)
    # everything of the load alone is computed once per load position, then broadcast
    moments, k, al, bl, big = _support_moments(a.ravel(), lengths, supports, force)
    aligned = (1,) * (len(shape) - a.ndim) + a.shape  # a's axes, right-aligned with shape
    moments = np.broadcast_to(moments.reshape((n + 1, *aligned)), (n + 1, *shape))
    k, al, bl, big = (np.broadcast_to(v.reshape(a.shape), shape) for v in (k, al, bl, big))
    x = np.broadcast_to(x, shape)
    # the section's span: an interior support belongs to the span on the side of its face
    found = np.searchsorted(supports, x, side="left" if side == "left" else "right")
    j = np.clip(found - 1, 0, n - 1)
    s = x - supports[j]
    length = lengths[j]
    rest = length - s
    m_left = np.take_along_axis(moments, j[None], axis=0)[0]
    m_right = np.take_along_axis(moments, (j + 1)[None], axis=0)[0]
    loaded = k == j
    before = s <= al  # the section is left of (or under) the load
    m0 = np.where(before, force * bl * s / length, force * al * rest / length)
    # whether the load is behind the section's face (then it is not in the shear from the
    # left); a load on a support shears no span
    at = s == al
    if side == "left":
        passed = (s > al) | (at & (al == 0.0))
    else:
        passed = (s > al) | (at & (al < length))
    v0 = force * bl / length - np.where(passed, force, 0.0)
    w0 = np.where(
        before,
        force * bl * s * (length**2 - bl**2 - s**2),
        force * al * rest * (length**2 - al**2 - rest**2),
    ) / (6.0 * length * EI)
    moment = np.where(loaded, m0, 0.0) + m_left * rest / length + m_right * s / length
    shear = np.where(loaded, v0, 0.0) + (m_right - m_left) / length
    end_moments = m_left * rest * (length**2 - rest**2) + m_right * s * (length**2 - s**2)
    deflection = np.where(loaded, w0, 0.0) + end_moments / (6.0 * length * EI)
    return BeamStatics(deflection, moment, shear)


def _influence_matrix(
    x: np.ndarray,
    a: np.ndarray,
    lengths: np.ndarray,
    supports: np.ndarray,
    EI: float,
    force: float,
    side: str,
) -> BeamStatics:
    """:func:`continuous_statics` of sections ``x`` ``(n_s,)`` under loads ``a`` ``(n_a,)``,
    ``(n_a, n_s)``: the support moments' part as one matrix product (the same formulas)."""
    n = lengths.size
    moments, k, al, bl, big = _support_moments(a, lengths, supports, force)  # (n + 1, n_a)
    found = np.searchsorted(supports, x, side="left" if side == "left" else "right")
    j = np.clip(found - 1, 0, n - 1)
    s = x - supports[j]
    length = lengths[j]
    rest = length - s
    columns = np.arange(x.size)
    # each section's share of the moments over its span's two supports
    weights = np.zeros((3, n + 1, x.size))
    weights[0, j, columns] = rest * (length**2 - rest**2) / (6.0 * length * EI)
    weights[0, j + 1, columns] = s * (length**2 - s**2) / (6.0 * length * EI)
    weights[1, j, columns] = rest / length
    weights[1, j + 1, columns] = s / length
    weights[2, j, columns] = -1.0 / length
    weights[2, j + 1, columns] = 1.0 / length
    ends = moments.T @ weights  # (3, n_a, n_s)
    # the loaded span's own simple-span part, where the load is in the section's span
    loaded = k[:, None] == j[None, :]
    al, bl = al[:, None], bl[:, None]
    before = s <= al
    m0 = np.where(before, force * bl * s / length, force * al * rest / length)
    at = s == al
    if side == "left":
        passed = (s > al) | (at & (al == 0.0))
    else:
        passed = (s > al) | (at & (al < length))
    v0 = force * bl / length - np.where(passed, force, 0.0)
    w0 = np.where(
        before,
        force * bl * s * (length**2 - bl**2 - s**2),
        force * al * rest * (length**2 - al**2 - rest**2),
    ) / (6.0 * length * EI)
    return BeamStatics(
        np.where(loaded, w0, 0.0) + ends[0],
        np.where(loaded, m0, 0.0) + ends[1],
        np.where(loaded, v0, 0.0) + ends[2],
    )


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


def effect_index(effect: str) -> int:
    """The row of ``effect`` (``"displacement"``, ``"moment"`` or ``"shear"``) in the
    ``(3, ...)`` arrays of :data:`EFFECTS`; ``ValueError`` for another name."""
    if effect not in EFFECTS:
        raise ValueError(f"effect={effect!r} is not known; use one of {', '.join(EFFECTS)}")
    return EFFECTS.index(effect)


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
