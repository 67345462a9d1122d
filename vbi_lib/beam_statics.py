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
:math:`V = dM/dx`; at a section holding the load or an interior support the shear is the
value just to its left, and at :math:`x = 0` just to its right
(the convention of :func:`vbi_lib.closed_forms.point_load_statics`, which this reproduces
for one span and two equal spans).

**Static envelope.**  A group of axles (loads :math:`P_i` at :math:`o_i` behind the first)
crawls over the bridge; at each section the largest and smallest value of each effect over
the positions of the group, :math:`\max_p \sum_i P_i\, \eta(x, p - o_i)` with :math:`\eta` the
influence line, is found on a fine grid of positions that includes every kink (an axle over
the section or over a support), then refined with a bounded scalar search.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
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

__all__ = ["EFFECTS", "StaticEnvelope", "continuous_statics", "envelope", "static_envelope"]

#: The effects at a section, in the order of every ``(3, ...)`` array.
EFFECTS = ("displacement", "moment", "shear")
#: The display quantity of each effect.
QUANTITY = {"displacement": "deflection", "moment": "moment", "shear": "force"}


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


def continuous_statics(
    x: float | np.ndarray,
    load_position: float | np.ndarray,
    spans: Sequence[float],
    EI: float,
    force: float = 1.0,
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

    Returns
    -------
    BeamStatics
        ``deflection`` [m] (down positive), ``moment`` [N m] (sagging positive) and ``shear``
        [N] (``dM/dx``, the value just left of a load or interior support, just right at
        ``x = 0``), broadcast over ``x`` and ``load_position``.

    Raises
    ------
    ValueError
        A section or load off the beam, a span or EI that is not a positive number.

    Examples
    --------
    Three equal spans, a unit load at the middle of the first: the three-moment equations
    ``4 M_1 + M_2 = -3/8`` and ``M_1 + 4 M_2 = 0`` give ``M_1 = -0.1 P L`` over the first
    interior support and ``M_2 = 0.025 P L`` over the second:

    >>> statics = continuous_statics([1.0, 2.0], 0.5, [1.0, 1.0, 1.0], 1.0)
    >>> statics.moment.round(6).tolist()
    [-0.1, 0.025]
    """
    lengths = _span_lengths(spans)
    EI = check.positive("EI", EI)
    force = check.number("force", force)
    if not math.isfinite(force):
        raise ValueError(f"force={force!r} must be a finite number [N]")
    supports = support_stations(lengths)
    total = float(supports[-1])
    x, a = np.broadcast_arrays(
        _stations("x", x, total), _stations("load_position", load_position, total)
    )
    shape = x.shape
    x, a = x.ravel(), a.ravel()
    n = lengths.size
    # the load's span (an interior support belongs to the span on its right: no bending)
    k = np.clip(np.searchsorted(supports, a, side="right") - 1, 0, n - 1)
    al = a - supports[k]
    big = lengths[k]
    bl = big - al
    moments = np.zeros((n + 1, a.size))  # at the supports
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
    # the section's span (an interior support belongs to the span on its left)
    j = np.clip(np.searchsorted(supports, x, side="left") - 1, 0, n - 1)
    s = x - supports[j]
    length = lengths[j]
    rest = length - s
    columns = np.arange(a.size)
    m_left, m_right = moments[j, columns], moments[j + 1, columns]
    loaded = k == j
    before = s <= al  # the section is left of (or under) the load
    m0 = np.where(before, force * bl * s / length, force * al * rest / length)
    passed = (s > al) | ((s == 0.0) & (al == 0.0))
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
    return BeamStatics(deflection.reshape(shape), moment.reshape(shape), shear.reshape(shape))


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
        Position of the first axle from the bridge start where each occurs [m], ``(3, n_s)``.
    """

    sections: np.ndarray
    maximum: np.ndarray
    minimum: np.ndarray
    maximum_at: np.ndarray
    minimum_at: np.ndarray

    def to_dataframe(self) -> pd.DataFrame:
        """One row per section and effect: the extremes (display units) and where they occur."""
        rows = []
        for e, effect in enumerate(EFFECTS):
            quantity = QUANTITY[effect]
            for i, x in enumerate(self.sections):
                rows.append(
                    {
                        display.label("section", "length"): display.value(x, "length"),
                        "effect": effect,
                        "unit": display.symbol(quantity),
                        "maximum": display.value(self.maximum[e, i], quantity),
                        "minimum": display.value(self.minimum[e, i], quantity),
                        display.label("first axle at maximum", "length"): display.value(
                            self.maximum_at[e, i], "length"
                        ),
                        display.label("first axle at minimum", "length"): display.value(
                            self.minimum_at[e, i], "length"
                        ),
                    }
                )
        return pd.DataFrame(rows)

    def plot(self, ax: Axes | None = None, effect: str = "moment") -> Axes:
        """Plot the envelope of one effect against the section (display units)."""
        import matplotlib.pyplot as plt

        e = effect_index(effect)
        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        x = display.value(self.sections, "length")
        quantity = QUANTITY[effect]
        ax.plot(x, display.value(self.maximum[e], quantity), "o-", ms=3, label="maximum")
        ax.plot(x, display.value(self.minimum[e], quantity), "o-", ms=3, label="minimum")
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
    """Extremes over the positions of an axle group of any influence lines.

    ``influence(a)`` gives the effects of a unit downward load at stations ``a`` (``(n_a,)``
    on the bridge) at the sections, shape ``(3, n_a, n_s)``.  Positions of the first axle
    run from the bridge start until the last axle leaves; the grid holds every kink (an
    axle over a section or a support, from either side), and the best point of each
    extreme is refined with a bounded scalar search.
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


def static_envelope(
    spans: Sequence[float],
    EI: float,
    sections: float | Sequence[float] | np.ndarray,
    axle_loads: float | Sequence[float] = 1.0,
    axle_offsets: float | Sequence[float] = 0.0,
) -> StaticEnvelope:
    """Exact static envelope at sections of a continuous beam under a crawling axle group.

    Parameters
    ----------
    spans
        Span lengths [m] (``bridge.spans``).
    EI
        Flexural rigidity [N m^2].
    sections
        Stations from the bridge start [m].
    axle_loads
        Load of each axle [N], downward (one sprung mass: its weight).
    axle_offsets
        Distance of each axle behind the first [m] (0 for the first).

    Returns
    -------
    StaticEnvelope
        Displacement positive up (a deflection is negative), as the crossing results.

    Raises
    ------
    ValueError
        A section off the beam; loads and offsets of different lengths or negative.

    Examples
    --------
    One span of 10 m under 100 kN: ``P L / 4`` at midspan, shear ``+-P/2`` there.

    >>> env = static_envelope([10.0], 1e9, [5.0], 1e5)
    >>> float(env.maximum[1, 0]), float(env.maximum[2, 0]), round(float(env.minimum[2, 0]))
    (250000.0, 50000.0, -50000)
    """
    lengths = _span_lengths(spans)
    EI = check.positive("EI", EI)
    supports = support_stations(lengths)
    x = np.atleast_1d(_stations("sections", sections, float(supports[-1]))).ravel()
    loads, offsets = _axles(axle_loads, axle_offsets)

    def influence(a: np.ndarray) -> np.ndarray:
        statics = continuous_statics(x[None, :], a[:, None], lengths, EI)
        return np.stack([-statics.deflection, statics.moment, statics.shear])

    return envelope(influence, supports, x, loads, offsets)
