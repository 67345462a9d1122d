"""Reference problems, defined once and shared by the tests (as scipy's ``test_ivp`` does).

Every crossing model is looped over the problems in ``tests/models/test_reference_problems.py``;
model-specific tests take the cases they need from here.
"""

from __future__ import annotations

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
