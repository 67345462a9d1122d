"""Static influence lines of a continuous beam by the three-moment equation, for the tests.

Clapeyron's equation for a beam of constant EI on pinned supports, with support moments
``M_i`` (sagging positive, so hogging supports are negative), spans ``L_i`` and a point load
``P`` at ``a`` from the left end of a span (``b = L - a`` from its right end):

    M_{i-1} L_i + 2 M_i (L_i + L_{i+1}) + M_{i+1} L_{i+1}
        = - P a (L_i^2 - a^2) / L_i          (load in span i, left of support i)
          - P b (L_{i+1}^2 - b^2) / L_{i+1}  (load in span i+1, right of it),

``M_0 = M_n = 0``.  Within a span the moment is the simply supported one plus the line
between its end moments, the shear ``V = dM/dx`` and the deflection the simply supported
point-load deflection plus those of the two end moments (Timoshenko & Young, *Theory of
Structures*).  Nothing here comes from the library; ``tests/beam_fe.py`` checks it.
"""

from __future__ import annotations

import numpy as np


class ContinuousBeam:
    """A beam on pinned supports at ``0, L_1, L_1 + L_2, ...`` with constant ``ei``."""

    def __init__(self, spans: list[float], ei: float) -> None:
        self.spans = np.asarray(spans, dtype=float)
        self.ei = float(ei)
        self.supports = np.concatenate(([0.0], np.cumsum(self.spans)))
        self.length = float(self.supports[-1])
        self.midspans = self.supports[:-1] + self.spans / 2

    def support_moments(self, a: np.ndarray) -> np.ndarray:
        """Support moments [N m per N] under a unit load at each station ``a``,
        ``(n_a, n_supports)``."""
        a = np.atleast_1d(np.asarray(a, dtype=float))
        n = self.spans.size
        moments = np.zeros((a.size, n + 1))
        if n == 1:
            return moments
        lengths = self.spans
        matrix = np.zeros((n - 1, n - 1))
        for i in range(1, n):
            matrix[i - 1, i - 1] = 2.0 * (lengths[i - 1] + lengths[i])
            if i > 1:
                matrix[i - 1, i - 2] = lengths[i - 1]
            if i < n - 1:
                matrix[i - 1, i] = lengths[i]
        span, local = self._locate(a)
        rhs = np.zeros((n - 1, a.size))
        for k in range(a.size):
            j, x = span[k], local[k]
            length = lengths[j]
            b = length - x
            if j >= 1:  # the loaded span is right of support j
                rhs[j - 1, k] -= b * (length**2 - b**2) / length
            if j <= n - 2:  # and left of support j + 1
                rhs[j, k] -= x * (length**2 - x**2) / length
        moments[:, 1:-1] = np.linalg.solve(matrix, rhs).T
        return moments

    def _locate(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Span (0-based) and distance into it of each station (a support: the span left of
        it, except the first support)."""
        span = np.clip(np.searchsorted(self.supports, x, side="left") - 1, 0, self.spans.size - 1)
        return span, x - self.supports[span]

    def influence(
        self, x: np.ndarray, a: np.ndarray, face: str = "left"
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Deflection (down positive), moment (sagging positive) and shear (dM/dx) at stations
        ``x`` under a unit load at each ``a``; each ``(n_a, n_x)``.

        At a support the shear is that of the span on its ``face`` side (``"left"`` or
        ``"right"``); a load exactly at ``x`` counts as just to the right of it (the shear
        just left of the load, as the library's ``shear_at`` and ``tests/beam_fe.py``).
        """
        x = np.atleast_1d(np.asarray(x, dtype=float))
        a = np.atleast_1d(np.asarray(a, dtype=float))
        moments = self.support_moments(a)  # (n_a, n_supports)
        span_x, xi = self._locate(x)
        if face == "right":  # a station on an interior support: the span to its right
            on_support = np.isclose(x[:, None], self.supports[None, 1:-1], atol=1e-9).any(1)
            span_x = np.where(on_support, span_x + 1, span_x)
            xi = x - self.supports[span_x]
        span_a, alpha = self._locate(a)
        lengths = self.spans[span_x][None, :]
        left = moments[:, span_x]
        right = moments[:, span_x + 1]
        xi = xi[None, :]
        same = span_a[:, None] == span_x[None, :]
        p = alpha[:, None]  # load's distance into its span
        before = xi <= p  # the section is left of the load
        # simply supported span under the unit load (only where the load is in the span)
        m0 = np.where(before, (lengths - p) * xi / lengths, p * (lengths - xi) / lengths)
        v0 = np.where(before, (lengths - p) / lengths, -p / lengths)
        v0 = np.where(p > 0.0, v0, 0.0)  # a load on the first support goes straight to it
        w0 = np.where(
            before,
            (lengths - p) * xi * (lengths**2 - (lengths - p) ** 2 - xi**2),
            p * (lengths - xi) * (lengths**2 - p**2 - (lengths - xi) ** 2),
        ) / (6.0 * lengths * self.ei)
        m0, v0, w0 = (np.where(same, q, 0.0) for q in (m0, v0, w0))
        moment = m0 + left * (1.0 - xi / lengths) + right * xi / lengths
        shear = v0 + (right - left) / lengths
        # end moments bend the span: v'' = -M / EI with v = 0 at both ends
        w_left = left * xi * (lengths - xi) * (2.0 * lengths - xi) / (6.0 * lengths * self.ei)
        w_right = right * xi * (lengths**2 - xi**2) / (6.0 * lengths * self.ei)
        return w0 + w_left + w_right, moment, shear

    def envelope(
        self,
        x: np.ndarray,
        loads: np.ndarray,
        offsets: np.ndarray,
        face: str = "left",
        step: float = 0.005,
    ) -> tuple[np.ndarray, np.ndarray]:
        """Largest and smallest deflection, moment and shear at ``x`` as the axle group
        (``loads`` [N] at ``offsets`` behind the first axle [m]) crawls across, every
        ``step`` metres of the first axle's travel and with every axle in turn on every
        section and support; each ``(3, n_x)``."""
        x = np.atleast_1d(np.asarray(x, dtype=float))
        loads, offsets = np.asarray(loads, dtype=float), np.asarray(offsets, dtype=float)
        travel = self.length + offsets.max()
        fronts = np.arange(0.0, travel + step, step)
        marks = np.concatenate((x, self.supports))
        fronts = np.unique(np.concatenate((fronts, (marks[:, None] + offsets[None, :]).ravel())))
        fronts = fronts[(fronts >= 0.0) & (fronts <= travel)]
        total = np.zeros((3, fronts.size, x.size))
        for load, offset in zip(loads, offsets, strict=True):
            where = fronts - offset
            on = (where >= 0.0) & (where <= self.length)
            values = self.influence(x, where[on], face)
            for e in range(3):
                total[e, on] += load * values[e]
        return total.max(axis=1), total.min(axis=1)
