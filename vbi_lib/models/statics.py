r"""The static deflection every span DAF divides by: one definition for every model and vehicle.

The DAF of span ``j`` is the largest downward midspan deflection of span ``j`` over the whole
run, divided by the largest downward static midspan deflection of span ``j`` under the same
vehicle: all its axles, with their static loads :math:`P_a`, in every position of the group
along the bridge, by the same model's statics (the study's definition for reference models,
the crawl run, 88-91):

.. math:: \delta_j = \max_p \sum_a P_a\, \eta_j(p - o_a),

with :math:`\eta_j(s)` the model's downward midspan deflection of span ``j`` under a unit
load at ``s`` (zero off the bridge):

* ``"one-shape"`` (the one-coordinate model): :math:`\eta_j(s) = \psi(m_j) \psi(s) / k^*`;
  one axle gives :math:`P / k^*` on every span, the study's (90)-(91);
* ``"exact"`` (the modal model's mode-acceleration headline): the beam's exact influence
  line, three-moment equation (:func:`vbi_lib.beam_statics.continuous_statics`);
* ``"modal"`` (the modal model's N-mode series): :math:`\sum_n \phi_n(s)\phi_n(m_j)/\omega_n^2`.

The largest value over the positions is found on a grid that holds every kink (an axle over
a support or a midspan, from either side), then refined by a bounded scalar search.  The
exact influence line is also given as cubic pieces (:func:`influence_pieces`), exact to
rounding, for the integrators' mode-acceleration correction.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from scipy.optimize import minimize_scalar

from ..beam_statics import continuous_statics
from ..bridges import Bridge
from ..modes import beam_modes
from ..vehicles import VehicleSystem

__all__ = ["KINDS", "influence", "influence_pieces", "span_statics"]

#: The statics a span DAF can divide by.
KINDS = ("one-shape", "exact", "modal")


def influence(bridge: Bridge, kind: str, s: np.ndarray, modes: int = 0) -> np.ndarray:
    """Downward midspan deflection of each span under a unit load at ``s`` [m/N].

    ``s`` are stations from the bridge start, on the bridge; returns ``(n_s, n_spans)``.
    """
    s = np.asarray(s, dtype=float)
    mids = np.array(bridge.midspans)
    if kind == "one-shape":
        wave = math.pi / bridge.span
        return (
            np.sin(wave * s)[:, None]
            * np.sin(wave * mids)[None, :]
            / (bridge.generalized_stiffness)
        )
    if kind == "exact":
        statics = continuous_statics(mids[None, :], s[:, None], bridge.spans, bridge.EI)
        return statics.deflection
    if kind == "modal":
        basis = beam_modes(bridge, modes)
        return (basis.shape(s) / basis.omega**2) @ basis.shape(mids).T
    raise ValueError(f"kind={kind!r} must be one of {KINDS}")


@lru_cache(maxsize=1024)
def _span_statics(bridge: Bridge, kind: str, modes: int, offsets: tuple, loads: tuple) -> tuple:
    length = bridge.length
    supports = np.array(bridge.supports)
    mids = np.array(bridge.midspans)
    offs = np.array(offsets)
    w = np.array(loads)
    end = length + float(offs.max())
    tiny = 1e-9 * length
    spacing = float(np.diff(supports).min()) / 400.0
    kinks = np.concatenate((supports, mids))
    points = [np.linspace(0.0, end, int(math.ceil(end / spacing)) + 1)]
    for offset in offs:
        points += [kinks + offset, kinks + offset - tiny, kinks + offset + tiny]
    grid = np.unique(np.clip(np.concatenate(points), 0.0, end))

    def total(first: np.ndarray) -> np.ndarray:
        out = np.zeros((first.size, bridge.n_spans))
        for load, offset in zip(w, offs, strict=True):
            at = first - offset
            on = (at >= 0.0) & (at <= length)
            if on.any():
                out[on] += load * influence(bridge, kind, np.clip(at[on], 0.0, length), modes)
        return out

    values = total(grid)
    best = []
    for j in range(bridge.n_spans):
        k = int(np.argmax(values[:, j]))
        value = float(values[k, j])
        lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
        if hi - lo > 2.0 * tiny:
            found = minimize_scalar(
                lambda p, j=j: -float(total(np.array([p]))[0, j]),
                bounds=(lo, hi),
                method="bounded",
                options={"xatol": 1e-10 * length},
            )
            value = max(value, -float(found.fun))
        best.append(value)
    return tuple(best)


def span_statics(bridge: Bridge, system: VehicleSystem, kind: str, modes: int = 0) -> np.ndarray:
    """The static deflection each span's DAF divides by [m], ``(n_spans,)`` (module docstring).

    Parameters
    ----------
    bridge, system
        The beam and the vehicle (its axles' static loads and offsets).
    kind
        ``"one-shape"``, ``"exact"`` or ``"modal"`` (:data:`KINDS`).
    modes
        Number of modes, for ``"modal"``.

    Examples
    --------
    One axle on a simple span: the exact static deflection is ``P L^3 / 48 EI``; the one
    shape gives ``P / k* = 2 P L^3 / (pi^4 EI)``, 1.45 % less (39):

    >>> import vbi_lib as vbi
    >>> b = vbi.Bridge(20.0, 1, 1e10, 5000.0)
    >>> s = vbi.Vehicle(1e4, 4e6, 2e4).system
    >>> exact, shape = span_statics(b, s, "exact"), span_statics(b, s, "one-shape")
    >>> round(float(exact[0] / (s.weight * 20.0**3 / 48e10)), 9)
    1.0
    >>> round(float(shape[0] / exact[0]), 4)
    0.9855
    """
    if kind not in KINDS:
        raise ValueError(f"kind={kind!r} must be one of {KINDS}")
    if kind == "one-shape" and system.n_axles == 1:
        # one axle: P / k* on every span (90)-(91), in the study's own form
        return np.full(bridge.n_spans, bridge.static_deflection(system.weight))
    if system.n_axles == 1 and kind == "exact":  # the cubic pieces' largest value
        return system.weight * _unit_peaks(bridge)
    if system.n_axles == 1:  # the unit load's, once per bridge, times the weight
        return system.weight * np.array(_span_statics(bridge, kind, int(modes), (0.0,), (1.0,)))
    key = (tuple(float(o) for o in system.offsets), tuple(float(w) for w in system.static_loads))
    return np.array(_span_statics(bridge, kind, int(modes), *key))


@lru_cache(maxsize=256)
def _unit_peaks(bridge: Bridge) -> np.ndarray:
    """The largest exact downward deflection of each midspan under a unit load anywhere
    [m/N], ``(n_spans,)``: the extremes of :func:`influence_pieces`' cubics (their ends and
    the roots of their derivatives)."""
    _, coef = influence_pieces(bridge)
    out = np.empty(bridge.n_spans)
    for j in range(bridge.n_spans):
        best = 0.0
        for c0, c1, c2, c3 in coef[j]:
            candidates = [0.0, 1.0]
            roots = np.roots([3.0 * c3, 2.0 * c2, c1]) if abs(c3) + abs(c2) > 0 else []
            candidates += [r.real for r in np.atleast_1d(roots) if abs(r.imag) < 1e-12
                           and 0.0 < r.real < 1.0]  # fmt: skip
            for u in candidates:
                best = max(best, ((c3 * u + c2) * u + c1) * u + c0)
        out[j] = best
    out.setflags(write=False)
    return out


@lru_cache(maxsize=256)
def influence_pieces(bridge: Bridge) -> tuple[np.ndarray, np.ndarray]:
    """The exact midspan influence lines as cubic pieces, for the integrators.

    Returns ``breaks`` ``(n_spans, n_spans + 2)``: for midspan ``j``, the supports with
    ``m_j`` inserted (so ``eta_j`` is one cubic between consecutive breaks), and ``coef``
    ``(n_spans, n_spans + 1, 4)``: ``eta_j(s) = c0 + c1 u + c2 u^2 + c3 u^3`` with ``u = (s -
    b_k) / (b_{k+1} - b_k)`` on piece ``k`` between breaks ``b_k`` and ``b_{k+1}`` [m/N,
    downward positive].  Each piece is fitted through four of its points, which a cubic
    passes through exactly.
    """
    supports = np.array(bridge.supports)
    n = bridge.n_spans
    breaks = np.empty((n, n + 2))
    coef = np.empty((n, n + 1, 4))
    for j, mid in enumerate(bridge.midspans):
        breaks[j] = np.sort(np.concatenate((supports, [mid])))
        for k in range(n + 1):
            a, b = breaks[j, k], breaks[j, k + 1]
            u = np.linspace(0.0, 1.0, 4)
            at = np.clip(a + u * (b - a), 0.0, bridge.length)
            values = continuous_statics(mid, at, bridge.spans, bridge.EI).deflection
            coef[j, k] = np.linalg.solve(np.vander(u, 4, increasing=True), values)
    breaks.setflags(write=False)
    coef.setflags(write=False)
    return breaks, coef
