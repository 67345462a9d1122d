"""Slow, independent paths for checking the one-coordinate model (and showing the study's scheme).

* :func:`reference_daf` integrates the same equations with ``scipy.integrate.solve_ivp``
  (DOP853) at tight tolerance, one profile interval at a time: a readable reference for the
  compiled RK4 kernel.
* :func:`study_explicit_euler_daf` repeats the study's own scheme, forward Euler at one step
  per profile sample, only to show how much it inflates the DAF.  Use
  :func:`vbi_lib.simulate` for results.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..bridges import Bridge
from ..profiles import Profile
from ..vehicles import Vehicle
from .base import P_SPEED, check_crossing, node_grid
from .one_coordinate import _derivative, _fill_state_matrices, _parameters, _shape, state_matrices

__all__ = ["reference_daf", "study_explicit_euler_daf"]


def reference_daf(
    bridge: Bridge,
    vehicle: Vehicle,
    profile: Profile,
    speed: float,
    bridge_start: float,
    coupled: bool = True,
    convective: bool = True,
    rtol: float = 1e-10,
) -> np.ndarray:
    """DAF of each span from ``scipy.integrate.solve_ivp`` (DOP853) at tight tolerance.

    A slow, readable path for checking the compiled kernel: the right-hand side is
    :func:`state_matrices` with the road read by linear interpolation, integrated one profile
    interval at a time (the road's slope, hence the input, jumps at every sample and the
    coefficients switch at the supports), and sampled at nine points per interval for the
    peaks (a sampling error below 2e-5 at 10 Hz and 1 in / 720 in/s intervals).

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> b = vbi.Bridge(20.0, 1, 5e9, 6000.0, damping_ratio=0.0)
    >>> t = vbi.Vehicle.from_frequency(1e4, 3.0, 0.1)
    >>> road = vbi.Profile.flat(30.0, 0.1)
    >>> d = reference_daf(b, t, road, 15.0, 5.0, coupled=False)
    >>> bool(abs(d[0] / vbi.simulate(b, t, road, 15.0, 5.0, coupled=False).daf[0] - 1) < 1e-5)
    True
    """
    from scipy.integrate import solve_ivp

    speed, bridge_start = check_crossing(bridge, vehicle, profile, speed, bridge_start)
    grid = node_grid(bridge, profile, speed, bridge_start, np.inf, bridge_start + bridge.length)
    k = math.pi / bridge.span

    def rhs(t: float, z: np.ndarray, x0: float, e0: float, slope: float, on: bool) -> np.ndarray:
        x = x0 + speed * t
        psi, dpsi = (math.sin(k * (x - bridge_start)), k * math.cos(k * (x - bridge_start)))
        if not on:
            psi = dpsi = 0.0
        A, B, f = state_matrices(bridge, vehicle, speed, psi, dpsi, coupled, convective)
        return A @ z + B @ np.array([e0 + slope * (x - x0), slope * speed]) + f

    z = np.array([grid.elevation[0], 0.0, 0.0, 0.0])
    peaks = np.full(bridge.n_spans, -np.inf)
    for i in range(grid.x.size - 1):
        x0, x1 = grid.x[i], grid.x[i + 1]
        slope = (grid.elevation[i + 1] - grid.elevation[i]) / (x1 - x0)
        span = int(grid.span_of_step[i])
        duration = (x1 - x0) / speed
        sol = solve_ivp(
            rhs,
            (0.0, duration),
            z,
            method="DOP853",
            t_eval=np.linspace(0.0, duration, 9),
            args=(x0, grid.elevation[i], slope, span > 0),
            rtol=rtol,
            atol=1e-14,
        )
        z = sol.y[:, -1]
        if span > 0:
            sign = 1.0 if span == 1 else -1.0
            peaks[span - 1] = max(peaks[span - 1], float(np.max(-sign * sol.y[2])))
    return peaks / bridge.static_deflection(vehicle.weight)


@numba.njit(cache=True)
def _euler_kernel(x, elevation, span_of_step, params, n_spans, coupled, convective, peaks):
    speed = params[P_SPEED]
    A = np.empty((4, 4))
    B = np.empty((4, 2))
    f = np.empty(4)
    rate = np.empty(4)
    z = np.zeros(4)
    z[0] = elevation[0]
    for j in range(n_spans):
        peaks[j] = -np.inf
    for k in range(x.shape[0] - 1):
        h = (x[k + 1] - x[k]) / speed
        slope = (elevation[k + 1] - elevation[k]) / (x[k + 1] - x[k])
        span = span_of_step[k]
        psi, dpsi = _shape(x[k], params, span > 0)
        _fill_state_matrices(A, B, f, psi, dpsi, params, coupled, convective)
        _derivative(rate, z, A, B, f, elevation[k], slope * speed)
        for i in range(4):
            z[i] += h * rate[i]
        if span > 0:
            sign = 1.0 if span == 1 else -1.0
            peaks[span - 1] = max(peaks[span - 1], -sign * z[2])


def study_explicit_euler_daf(
    bridge: Bridge,
    vehicle: Vehicle,
    profile: Profile,
    speed: float,
    bridge_start: float,
    coupled: bool = True,
    convective: bool = False,
) -> np.ndarray:
    """DAF by the study's own scheme: forward Euler at one step per profile sample.

    Kept only to show its error (see the model chapter); use :func:`simulate`.  Forward Euler
    multiplies the amplitude of an undamped oscillation by ``sqrt(1 + (omega dt)^2)`` every
    step, so it adds energy and inflates the DAF most on stiff (high-frequency) bridges.
    ``convective=False`` by default, as in the study's code.

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> b = vbi.Bridge(12.0, 1, 2e9, 5000.0)
    >>> t = vbi.Vehicle.from_frequency(2e4, 10.0, 0.1)
    >>> road = vbi.Profile.flat(40.0, 0.025)
    >>> euler = study_explicit_euler_daf(b, t, road, 18.0, 20.0)
    >>> bool(euler[0] > vbi.simulate(b, t, road, 18.0, 20.0, convective=False).daf[0])
    True
    """
    speed, bridge_start = check_crossing(bridge, vehicle, profile, speed, bridge_start)
    grid = node_grid(bridge, profile, speed, bridge_start, np.inf, bridge_start + bridge.length)
    peaks = np.empty(bridge.n_spans)
    _euler_kernel(
        grid.x,
        grid.elevation,
        grid.span_of_step,
        _parameters(bridge, vehicle, speed, bridge_start),
        bridge.n_spans,
        bool(coupled),
        bool(convective),
        peaks,
    )
    return peaks / bridge.static_deflection(vehicle.weight)
