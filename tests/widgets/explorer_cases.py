"""What the explorers' controls mean, written out again with the library's primitives.

``direct_inputs`` turns control values into a bridge, a truck, a road, a speed, a bridge start
and the model's options without going through :mod:`vbi_lib.widgets`, following the rules the
explorers document (US customary controls; generated roads sampled every inch from station 0,
200 ft longer than the approach and the bridge; a shift slides the road back; the first
support ``approach_ft`` after the road's first station; one mode = the study's model; the
quarter car from its uncoupled frequencies, weight split by ``unsprung_fraction``, undamped
tyre of the library's default 0.25 m footprint).
``CHANGES`` gives each control a new value and the settings under which it matters.
"""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any

import numpy as np

import vbi_lib as vbi
from vbi_lib import units as u

#: Generated roads are this much longer than the approach and the bridge [ft] (documented).
EXTRA_ROAD_FT = 200.0

#: A new value for every control, and the settings that make it matter.
CHANGES: dict[str, tuple[dict[str, Any], Any]] = {
    "span_ft": ({}, 80.0),
    "n_spans": ({}, 2),
    "bridge_frequency_hz": ({}, 4.2),
    "bridge_weight_kip_per_ft": ({}, 8.0),
    "bridge_damping": ({}, 0.03),
    "truck_weight_kip": ({}, 50.0),
    "truck_frequency_hz": ({}, 2.4),
    "truck_damping": ({}, 0.25),
    # the frequency map runs bodies up to 2 x 3 Hz: an axle hop of 20 Hz keeps every tyre
    # stiffness positive at unsprung fractions from 0.1 (the lowest hop is 18 Hz)
    "vehicle_type": ({"axle_hop_hz": 20.0}, "quarter-car"),
    "axle_hop_hz": ({"vehicle_type": "quarter-car", "axle_hop_hz": 20.0}, 26.0),
    "unsprung_fraction": ({"vehicle_type": "quarter-car", "axle_hop_hz": 20.0}, 0.14),
    "speed_mph": ({}, 55.0),
    "road": ({"road": "iso-class"}, "bump"),
    "iso_class": ({"road": "iso-class"}, "C"),
    "c10_e6": ({"road": "iso-c10"}, 600.0),
    "waviness": ({"road": "iso-c10"}, 3.0),
    "seed": ({"road": "iso-class"}, 7),
    "wavelength_ft": ({"road": "harmonic"}, 20.0),
    "amplitude_in": ({"road": "harmonic"}, 0.1),
    "bump_height_in": ({"road": "bump"}, -1.5),
    "bump_width_ft": ({"road": "bump"}, 8.0),
    "bump_position_ft": ({"road": "bump"}, 30.0),
    "profile_path": ({"road": "measured", "profile_path": "A"}, "B"),
    "profile_unit": ({"road": "measured", "profile_path": "A"}, "ft"),
    "road_shift_ft": ({"road": "iso-class"}, 37.0),
    "approach_ft": ({}, 150.0),
    "modes": ({}, 4),
    "coupled": ({}, False),
    "speed_range_mph": ({}, (30.0, 50.0)),
    "n_speeds": ({}, 4),
    "ratio_range": ({}, (0.8, 1.6)),
    "n_ratios": ({}, 4),
}


def write_profiles(folder: Path) -> dict[str, str]:
    """Two measured-profile files (stations and elevations in inches), by name A and B."""
    x = np.arange(0.0, 7200.0 + 1e-9, 2.0)  # 600 ft every 2 in
    files = {}
    for name, wavelength in (("A", 360.0), ("B", 290.0)):
        path = folder / f"deck-{name}.csv"
        elevation = 0.1 * np.sin(2 * np.pi * x / wavelength)
        np.savetxt(path, np.column_stack([x, elevation]), delimiter=",", fmt="%.6f")
        files[name] = str(path)
    return files


def resolve(values: dict[str, Any], files: dict[str, str]) -> dict[str, Any]:
    """Replace the file names "A" and "B" by the files' paths."""
    out = dict(values)
    if out.get("profile_path") in files:
        out["profile_path"] = files[out["profile_path"]]
    return out


def road_of(v: dict[str, Any]) -> vbi.Profile:
    """The road the truck drives on, built here from the controls' values."""
    spacing = 1 * u.inch
    length = (v["approach_ft"] + v["n_spans"] * v["span_ft"] + EXTRA_ROAD_FT) * u.ft
    kind = v["road"]
    if kind == "flat":
        road = vbi.Profile.flat(length, spacing)
    elif kind == "harmonic":
        road = vbi.Profile.harmonic(
            length, spacing, v["wavelength_ft"] * u.ft, v["amplitude_in"] * u.inch
        )
    elif kind == "bump":
        road = vbi.Profile.bump(
            length,
            spacing,
            position=(v["approach_ft"] + v["bump_position_ft"]) * u.ft,
            height=v["bump_height_in"] * u.inch,
            width=v["bump_width_ft"] * u.ft,
        )
    elif kind == "iso-class":
        road = vbi.Profile.iso8608(length, spacing, iso_class=v["iso_class"], seed=v["seed"])
    elif kind == "iso-c10":
        road = vbi.Profile.iso8608(
            length, spacing, c10=v["c10_e6"] * 1e-6, waviness=v["waviness"], seed=v["seed"]
        )
    else:
        road = vbi.read_profile(v["profile_path"], unit=v["profile_unit"])
    shift = v["road_shift_ft"] * u.ft
    if shift:
        keep = road.x >= road.x[0] + shift - 1e-9
        road = vbi.Profile(road.x[keep] - shift, road.elevation[keep])
    return road


def quarter_car(v: dict[str, Any]) -> vbi.QuarterCar:
    """The quarter car of the controls, from its own formulas (not ``from_frequencies``).

    Body on its suspension alone at ``truck_frequency_hz``: ``k_s = m_s (2 pi f_body)^2``;
    axle between suspension and tyre at ``axle_hop_hz``: ``k_t = m_u (2 pi f_hop)^2 - k_s``;
    suspension damping ratio ``truck_damping`` of the body's oscillator; no tyre damping.
    """
    mass = v["truck_weight_kip"] * u.kip / u.g
    m_u = v["unsprung_fraction"] * mass
    m_s = mass - m_u
    w_body = 2 * np.pi * v["truck_frequency_hz"]
    w_hop = 2 * np.pi * v["axle_hop_hz"]
    k_s = m_s * w_body**2
    k_t = m_u * w_hop**2 - k_s
    c_s = 2 * v["truck_damping"] * m_s * w_body
    return vbi.QuarterCar(m_s, m_u, k_s, c_s, k_t, 0.0, footprint=0.25, unilateral=True)


def direct_inputs(
    v: dict[str, Any],
) -> tuple[vbi.Bridge, object, vbi.Profile, float, float, dict[str, Any]]:
    """Bridge, truck, road, speed [m/s], bridge start [m] and options of the controls."""
    bridge = vbi.Bridge.from_frequency(
        v["span_ft"] * u.ft,
        v["n_spans"],
        v["bridge_weight_kip_per_ft"] * u.kip / u.ft / u.g,
        v["bridge_frequency_hz"],
        v["bridge_damping"],
    )
    if v.get("vehicle_type", "sprung-mass") == "quarter-car":
        truck = quarter_car(v)
    else:
        truck = vbi.Vehicle.from_frequency(
            v["truck_weight_kip"] * u.kip / u.g, v["truck_frequency_hz"], v["truck_damping"]
        )
    road = road_of(v)
    options: dict[str, Any] = {"coupled": v["coupled"]}
    if v["modes"] > 1:
        options.update(model="modal", modes=v["modes"])
    return bridge, truck, road, v["speed_mph"] * u.mph, road.x[0] + v["approach_ft"] * u.ft, options


def direct_crossing(v: dict[str, Any]) -> vbi.Crossing:
    """``vbi.simulate`` of the controls' values."""
    bridge, truck, road, speed, start, options = direct_inputs(v)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        return vbi.simulate(bridge, truck, road, speed, start, **options)
