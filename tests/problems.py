"""Reference problems, defined once and shared by the tests (as scipy's ``test_ivp`` does).

Every crossing model is looped over the problems in ``tests/models/test_reference_problems.py``;
model-specific tests take the cases they need from here.
"""

from __future__ import annotations

import math

import numpy as np

import vbi_lib as vbi
from vbi_lib import units as u

LB_IN = u.lbf / u.inch
LB_IN2 = u.lbf * u.inch**2

#: Every model, with the options that select it and a short id.
MODEL_CASES = {
    "one-coordinate": {},
    "modal-1": {"model": "modal", "modes": 1},
    "modal-5": {"model": "modal", "modes": 5},
}


def _vehicle_cases() -> dict[str, object]:
    """One vehicle of every type, defined here once (sizes of a heavy truck)."""
    from vbi_lib.vehicles import Axle, Convoy, IndependentAxles, RigidTruck, Tyre, hs20

    tyre = Tyre(800.0, 3.0e6, 2.0e3)
    axles = [Axle(0.0, 60e3, 1.6e6, 2.5e4), Axle(4.5, 140e3, 3.6e6, 6.0e4)]
    quarter = vbi.QuarterCar.from_frequencies(12_000.0, 900.0, 2.5, 11.0, 0.1, 0.02)
    return {
        "sprung mass": vbi.Vehicle.from_frequency(2e4, 3.0, 0.1),
        "quarter car": quarter,
        "independent axles": IndependentAxles(axles),
        "independent axles, tyres": IndependentAxles(
            [Axle(a.offset, a.load, a.stiffness, a.damping, tyre) for a in axles]
        ),
        "rigid truck": RigidTruck(axles, pitch_inertia=9e4),
        "rigid truck, tyres": RigidTruck(
            [Axle(a.offset, a.load, a.stiffness, a.damping, tyre) for a in axles],
            pitch_inertia=9e4,
        ),
        "hs20": hs20(),
        "convoy": Convoy([quarter, vbi.Vehicle.from_frequency(1.5e4, 2.5, 0.1)], [12.0]),
    }


#: Every vehicle type, by a short id (all have unilateral tyres or bilateral contacts).
VEHICLE_CASES = _vehicle_cases()

#: Biggs (1964) / Yang & Yau (1997) sprung-mass benchmark (model-equations.md).
BIGGS_BRIDGE = vbi.Bridge(25.0, 1, 2.87e9 * 2.9, 2303.0, damping_ratio=0.0)
BIGGS_TRUCK = vbi.Vehicle(5750.0, 1595e3, 0.0)
BIGGS_SPEED = 100 * u.kph


def flat(bridge: vbi.Bridge, approach: float = 0.0, spacing: float = 0.05) -> vbi.Profile:
    """A flat road covering the approach and the bridge."""
    return vbi.Profile.flat(approach + bridge.length, spacing)


def rough_profile(length: float, spacing: float, c10: float, seed: int) -> vbi.Profile:
    """An ISO-8608-like road (w = 2) made here, independent of the library's generator."""
    rng = np.random.default_rng(seed)
    x = np.arange(0.0, length + 1e-9, spacing)
    n = np.arange(0.011, 2.83, 0.5 / length)
    amplitude = np.sqrt(2 * c10 * (n / 0.1) ** -2.0 * (n[1] - n[0]))
    phase = rng.uniform(0, 2 * np.pi, n.size)
    elevation = (amplitude[:, None] * np.cos(2 * np.pi * n[:, None] * x + phase[:, None])).sum(0)
    return vbi.Profile(x, elevation - elevation[0])


#: Two of the study's assessment cases (Tables 2.13.8 and 2.13.9): span ft, spans, K_mid
#: lb/in, f1 Hz, damped truck frequency Hz.
CASES = {
    "40ft-10Hz-one-span": (40, 1, 587723, 9.95, 10.5),
    "100ft-4Hz-two-spans": (100, 2, 668815, 3.99, 4.5),
}


def build_case(name: str) -> tuple[vbi.Bridge, vbi.Vehicle, vbi.Profile, float, float]:
    """Bridge, truck, rough road, speed (720 in/s) and bridge start of a named case."""
    span_ft, n_spans, k_mid, f1, fv = CASES[name]
    bridge = vbi.Bridge.from_midspan_stiffness(span_ft * u.ft, n_spans, k_mid * LB_IN, f1)
    vehicle = vbi.Vehicle.from_frequency(200 * u.slinch, fv, 0.10, damped=True)
    approach = 20.0
    road = rough_profile(approach + bridge.length + 1.0, 1 * u.inch, 300e-6, seed=n_spans)
    return bridge, vehicle, road, 720 * u.inch, approach


def covering(bridge: vbi.Bridge, vehicle: object, approach: float, spacing: float) -> vbi.Profile:
    """A flat road from ``wheelbase`` before the approach to ``wheelbase`` past the bridge."""
    wheelbase = vbi.vehicles.as_system(vehicle).wheelbase
    length = approach + bridge.length + 2 * wheelbase
    return vbi.Profile.flat(length, spacing, start=-wheelbase)


def moving_forces_midspan(
    bridge: vbi.Bridge, loads: list[float], entry_times: list[float], speed: float, modes: int,
    t: np.ndarray,
) -> np.ndarray:  # fmt: skip
    """Midspan deflection [m, up] of an undamped simple span under constant moving forces.

    Mode n (shape sin(n pi x / L), modal mass mbar L / 2) of each force entering at its
    time: forced phase ``F/(w^2 - W^2) (sin W tau - (W/w) sin w tau)`` while the force is on
    the span (Fryba 1972), free vibration from its state at the exit afterwards; the
    forces and modes superposed.  ``loads`` downward [N].
    """
    span, mbar = bridge.span, bridge.mass_per_length
    out = np.zeros_like(t)
    for n in range(1, modes + 1):
        w = (n * math.pi / span) ** 2 * math.sqrt(bridge.EI / mbar)
        big_w = n * math.pi * speed / span
        crossing = span / speed
        for load, t0 in zip(loads, entry_times, strict=True):
            amplitude = 2 * load / (mbar * span) / (w**2 - big_w**2)
            tau = t - t0
            on = (tau >= 0) & (tau <= crossing)
            q = np.zeros_like(t)
            q[on] = amplitude * (np.sin(big_w * tau[on]) - big_w / w * np.sin(w * tau[on]))
            q1 = amplitude * (math.sin(big_w * crossing) - big_w / w * math.sin(w * crossing))
            v1 = amplitude * big_w * (math.cos(big_w * crossing) - math.cos(w * crossing))
            after = tau > crossing
            s = tau[after] - crossing
            q[after] = q1 * np.cos(w * s) + v1 / w * np.sin(w * s)
            out -= q * math.sin(n * math.pi / 2)
    return out
