r"""Statics of a uniform beam continuous over any spans under a point load: its influence lines.

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

**Static envelopes** of axle groups crawling over the beam, exact from these influence lines,
are in :mod:`vbi_lib.beam_statics`, which gives everything here too.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from . import _validation as check
from .closed_forms import BeamStatics
from .continuous_beams import support_stations

if TYPE_CHECKING:
    pass

__all__ = [
    "DIRECTIONS",
    "EFFECTS",
    "QUANTITY",
    "SIDES",
    "continuous_statics",
    "effect_index",
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


def _simple_span(force, s, rest, al, bl, length, EI, side):  # noqa: ANN001, ANN202, N803
    """The loaded span's own simple-span part at sections ``s`` (``rest = length - s``) under
    ``force`` at ``al`` from its left support (``bl`` from its right): moment, shear on the
    face ``side`` and deflection (downward positive)."""
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
    return m0, v0, w0


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
    m0, v0, w0 = _simple_span(force, s, rest, al, bl, length, EI, side)
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
    m0, v0, w0 = _simple_span(force, s, rest, al, bl, length, EI, side)
    return BeamStatics(
        np.where(loaded, w0, 0.0) + ends[0],
        np.where(loaded, m0, 0.0) + ends[1],
        np.where(loaded, v0, 0.0) + ends[2],
    )


def effect_index(effect: str) -> int:
    """The row of ``effect`` (``"displacement"``, ``"moment"`` or ``"shear"``) in the
    ``(3, ...)`` arrays of :data:`EFFECTS`; ``ValueError`` for another name."""
    if effect not in EFFECTS:
        raise ValueError(f"effect={effect!r} is not known; use one of {', '.join(EFFECTS)}")
    return EFFECTS.index(effect)
