"""An independent reference crossing: the study's sprung mass on a bridge's modes, by solve_ivp.

Written for the tests and the deck preview of issue 26; nothing here comes from the library's
crossing code (vbi_lib.models).  A bridge enters as data, the form the deck's
``PathTables`` give and a beam's exact modes can give too:

* ``omega``, ``zeta`` (N modes), the axle's shape and slope along its travel coordinate ``s``
  at ``stations`` (cubic Hermite between them; a repeated station carries the slope before
  and after a jump),
* at each response point: the mode shapes and the residual static flexibility along the
  stations (full static minus the N-mode static), and the full static flexibility.

Equations (the study's 46-58 with N modes, the sprung mass bonded to the road: the study's FE
runs allowed no loss of contact, Chapter 13):

    r  = phi(s) . q + D(x),          D the road's elevation (linear between samples)
    F  = k (r - u) + c (r' - u'),    R = m g + F (the contact force, downward on the deck)
    m u'' = F,                       q_n'' + 2 zeta_n omega_n q_n' + omega_n^2 q_n = -phi_n(s) R

with ``s = v t - bridge_start``.  The approach (bridge at rest, the truck on the rigid road)
is solved exactly, interval by interval of the road (the 2-state system under a linear input,
by the matrix exponential).  On the bridge each interval between road samples is integrated
by ``scipy.integrate.solve_ivp`` (DOP853, rtol 1e-9): the right-hand side is smooth inside
an interval and jumps (the road's slope) only at its ends.  The response at a point
(downward positive) is the mode-acceleration one, ``-phi(r) . q + R * residual(r, s)``; its
peak is searched on each interval's dense output.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp
from scipy.linalg import expm

G = 9.80665


@dataclass(frozen=True)
class BridgeData:
    """What the reference crossing reads of a bridge (module docstring)."""

    stations: np.ndarray  # (n_s,)
    shape: np.ndarray  # (n_s, N)
    slope: np.ndarray  # (n_s, N)
    omega: np.ndarray  # (N,)
    zeta: np.ndarray  # (N,)
    response_shape: np.ndarray  # (n_r, N)
    static: np.ndarray  # (n_r, n_s) full static flexibility [m/N]
    residual: np.ndarray  # (n_r, n_s)
    entry: float
    exit: float

    @classmethod
    def from_tables(cls, tables: object) -> BridgeData:
        return cls(
            np.asarray(tables.stations),
            np.asarray(tables.shape),
            np.asarray(tables.slope),
            np.asarray(tables.omega),
            np.asarray(tables.damping_ratio),
            np.asarray(tables.response_shape),
            np.asarray(tables.static_flexibility),
            np.asarray(tables.residual_flexibility),
            float(tables.entry),
            float(tables.exit),
        )

    def __post_init__(self) -> None:
        # cubic Hermite of each station interval as powers of tau: value and slope
        st = self.stations
        h = np.diff(st)
        h[h == 0.0] = 1.0  # a repeated station: an interval of no length, never used
        p0, p1 = self.shape[:-1], self.shape[1:]
        m0, m1 = self.slope[:-1] * h[:, None], self.slope[1:] * h[:, None]
        powers = np.stack([p0, m0, 3 * (p1 - p0) - 2 * m0 - m1, 2 * (p0 - p1) + m0 + m1], axis=1)
        object.__setattr__(self, "_powers", powers)  # (n_int, 4, N)
        object.__setattr__(self, "_h", h)
        object.__setattr__(self, "_list", st.tolist())

    def at(self, s: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Shape, slope (Hermite) and residual row (linear) at travel ``s``; zero off the bridge."""
        st = self._list
        if s <= st[0] or s >= st[-1]:
            zero = np.zeros(self.omega.size)
            return zero, zero, np.zeros(self.response_shape.shape[0])
        i = min(bisect.bisect_right(st, s) - 1, len(st) - 2)
        h = self._h[i]
        tau = (s - st[i]) / h
        block = self._powers[i]
        shape = block.T @ np.array([1.0, tau, tau * tau, tau**3])
        slope = block.T @ np.array([0.0, 1.0, 2.0 * tau, 3.0 * tau * tau]) / h
        residual = (1 - tau) * self.residual[:, i] + tau * self.residual[:, i + 1]
        return shape, slope, residual


def _approach(m: float, k: float, c: float, x: np.ndarray, z: np.ndarray, speed: float,
              upto: float) -> tuple[float, float, int]:  # fmt: skip
    """The truck's state (u, u') on the rigid road at ``upto``: exact, interval by interval."""
    a = np.array(
        [
            [0.0, 1.0, 0.0, 0.0],
            [-k / m, -c / m, k / m, c / m],
            [0.0, 0.0, 0.0, 1.0],
            [0.0, 0.0, 0.0, 0.0],
        ]
    )
    state = np.array([z[0], 0.0])
    cache: dict[float, np.ndarray] = {}
    i = 0
    while x[i + 1] <= upto:
        dt = (x[i + 1] - x[i]) / speed
        key = round(dt, 15)
        if key not in cache:
            cache[key] = expm(a * dt)
        rate = (z[i + 1] - z[i]) / dt
        full = cache[key] @ np.array([state[0], state[1], z[i], rate])
        state = full[:2]
        i += 1
    return float(state[0]), float(state[1]), i


def crossing(
    bridge: BridgeData,
    vehicle: tuple[float, float, float],
    road: tuple[np.ndarray, np.ndarray],
    speed: float,
    bridge_start: float,
    *,
    refine: int = 4,
    rtol: float = 1e-9,
) -> dict[str, np.ndarray]:
    """One crossing; returns the DAF at each response point and its parts.

    Parameters
    ----------
    bridge
        The bridge as data.
    vehicle
        ``(m, k, c)`` of the sprung mass [kg, N/m, N s/m].
    road
        ``(x, z)``: stations from the truck's start [m] and elevations [m].
    speed, bridge_start
        [m/s], [m] (where ``s = 0``).
    refine
        Dense-output points inside each interval searched for the peak.

    Returns
    -------
    dict
        ``daf`` (n_r,), ``peak`` (n_r,) dynamic peak [m], ``static`` (n_r,) largest static
        deflection under the truck's weight [m], ``min_contact`` (smallest R / m g).
    """
    m, k, c = vehicle
    x, z = road
    n = bridge.omega.size
    omega, zeta = bridge.omega, bridge.zeta
    weight = m * G
    first = bridge_start + bridge.entry
    last = bridge_start + bridge.exit
    if last > x[-1]:
        raise ValueError("the road ends before the truck leaves the bridge")
    u, du, i = _approach(m, k, c, x, z, speed, first)

    def rhs(t: float, y: np.ndarray, z0: float, x0: float, rate: float) -> np.ndarray:
        xs = speed * t
        s = xs - bridge_start
        phi, dphi, _ = bridge.at(s)
        q, dq = y[:n], y[n : 2 * n]
        road_z = z0 + rate * (xs - x0)
        r = phi @ q + road_z
        dr = phi @ dq + speed * (dphi @ q) + rate * speed
        force = k * (r - y[2 * n]) + c * (dr - y[2 * n + 1])
        out = np.empty_like(y)
        out[:n] = dq
        out[n : 2 * n] = -2 * zeta * omega * dq - omega**2 * q - phi * (weight + force)
        out[2 * n] = y[2 * n + 1]
        out[2 * n + 1] = force / m
        return out

    def response(
        t: float, y: np.ndarray, z0: float, x0: float, rate: float
    ) -> tuple[np.ndarray, float]:
        xs = speed * t
        phi, dphi, residual = bridge.at(xs - bridge_start)
        q, dq = y[:n], y[n : 2 * n]
        r = phi @ q + z0 + rate * (xs - x0)
        dr = phi @ dq + speed * (dphi @ q) + rate * speed
        contact = weight + k * (r - y[2 * n]) + c * (dr - y[2 * n + 1])
        return -bridge.response_shape @ q + contact * residual, contact

    # from the station where the first wheel meets the bridge to the sample after it
    y = np.zeros(2 * n + 2)
    # the truck's state at 'first': advance exactly from sample x[i] to 'first' on the road
    x_now = x[i]
    y[2 * n], y[2 * n + 1] = u, du
    peak = np.full(bridge.response_shape.shape[0], -np.inf)
    least = np.inf
    edges = np.concatenate([[x_now], x[(x > x_now) & (x < last)], [last]])
    breaks = bridge_start + bridge.stations[np.r_[False, np.diff(bridge.stations) == 0]]
    edges = np.unique(np.concatenate([edges, breaks[(breaks > x_now) & (breaks < last)]]))
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        j = min(int(np.searchsorted(x, a, side="right")) - 1, x.size - 2)
        rate = (z[j + 1] - z[j]) / (x[j + 1] - x[j])
        args = (z[j], x[j], rate)
        span = (b / speed - a / speed) * (1 - 1e-12)
        sol = solve_ivp(rhs, (a / speed, b / speed), y, method="DOP853", rtol=rtol,
                        atol=1e-14, args=args, dense_output=True, first_step=span)  # fmt: skip
        if not sol.success:
            raise RuntimeError(sol.message)
        for tt in np.linspace(a / speed, b / speed, refine + 2)[1:]:
            value, contact = response(tt, sol.sol(tt), *args)
            peak = np.maximum(peak, value)
            least = min(least, contact / weight)
        y = sol.y[:, -1]
    static = static_peak(bridge, weight)
    return {"daf": peak / static, "peak": peak, "static": static, "min_contact": least}


def static_peak(bridge: BridgeData, weight: float) -> np.ndarray:
    """Largest static deflection at each response under ``weight`` over the stations [m].

    The stations' largest value refined by a parabola through it and its neighbours.
    """
    static = bridge.static * weight
    out = np.empty(static.shape[0])
    for r, line in enumerate(static):
        i = int(np.argmax(line))
        best = line[i]
        if 0 < i < line.size - 1:
            s0, s1, s2 = bridge.stations[i - 1 : i + 2]
            f0, f1, f2 = line[i - 1 : i + 2]
            if s0 < s1 < s2:
                coef = np.polyfit([s0, s1, s2], [f0, f1, f2], 2)
                if coef[0] < 0:
                    best = max(best, float(np.polyval(coef, -coef[1] / (2 * coef[0]))))
        out[r] = best
    return out


def beam_data(bridge: object, modes: int, responses: list[float], spacing: float = 0.05,
              full_modes: int = 200) -> BridgeData:  # fmt: skip
    """A beam (vbi_lib.Bridge) as data: its exact modes, full static from ``full_modes`` modes."""
    from vbi_lib.modes import beam_modes

    length = bridge.length
    stations = np.linspace(0.0, length, int(round(length / spacing)) + 1)
    supports = np.array(bridge.supports[1:-1])
    stations = np.sort(np.concatenate([stations[~np.isin(stations, supports)], supports, supports]))
    basis = beam_modes(bridge, modes)
    shape = basis.shape(stations)
    slope = basis.slope(stations)
    full = beam_modes(bridge, full_modes)
    at_r = full.shape(np.array(responses))
    static = (at_r / full.omega**2) @ full.shape(stations).T
    resp = basis.shape(np.array(responses))
    modal = (resp / basis.omega**2) @ shape.T
    zeta = np.full(modes, bridge.damping_ratio)
    return BridgeData(stations, shape, slope, basis.omega, zeta, resp, static, static - modal,
                      0.0, length)  # fmt: skip
