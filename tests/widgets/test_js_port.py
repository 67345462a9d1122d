"""The book's JavaScript crossing models against vbi_lib, in Node (issue 25).

``book/_static/vbi-explorers/vbi-model.js`` is the port the static book's explorers run in the
reader's browser.  ``js/port_check.js`` runs it in Node on random explorer settings drawn here
within the intended ranges (one and two spans, both models, flat, harmonic, bump and ISO 8608
roads, coupled and decoupled); the same settings run through vbi_lib
(:class:`vbi_lib.widgets.Scenario`, :func:`vbi_lib.simulate`) and the two are compared:

* the SI setting, the road (stations exactly, elevations to rounding), the node grid and the
  step (the time-step rule);
* the histories that do not depend on how the DAF is defined: the midspan displacement, the
  contact force and the truck's displacement at every node, to 1e-9 of their size;
* the contact checks, the peaks and the DAF to 1e-9 relative.  The DAF is that of the issue 20
  definitions (DAF-DEFINITION.md: whole run, each span over its own static), which the core is
  moving to; until it lands the reference is computed here from the library's histories:
  the one-coordinate model's midspan peaks over W / k* (90)-(91), and for the modal model the
  mode-acceleration displacement from ``modal_coordinates``, ``axle_contact_force`` and the
  exact influence line of :func:`vbi_lib.beam_statics.continuous_statics`, over the exact
  static of :func:`vbi_lib.beam_statics.static_envelope`.  On one span the old and the new
  windows agree, and the library's own DAF is compared too.

The test is skipped only where ``node`` is missing, and never on CI.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import subprocess
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import scipy.fft
from conftest import ROOT

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.beam_statics import continuous_statics, static_envelope
from vbi_lib.profiles import ISO_BAND, ISO_CLASS_MEANS
from vbi_lib.ranges import RANGES
from vbi_lib.reports.parameters import SCHEMA
from vbi_lib.reports.values import MAX_SPEEDS
from vbi_lib.widgets import Scenario
from vbi_lib.widgets.report_file import report_files
from vbi_lib.widgets.scenario import MAX_ROAD_SHIFT_FT, ROAD_SPACING

SCRIPT = Path(__file__).parent / "js" / "port_check.js"
CASES = 240
RTOL = 1e-9
#: The test's own seed for the random settings (any seed must pass).
SEED = 20260425


def _node() -> str:
    node = shutil.which("node")
    if node is None:
        if os.environ.get("CI") == "true":
            pytest.fail(
                "CI runs the JavaScript port's test: node is missing (apt-get install nodejs)"
            )
        pytest.skip("node is not installed: the JavaScript port is not checked here")
    return node


def random_settings(count: int, seed: int = SEED) -> list[dict[str, Any]]:
    """Explorer settings inside the intended ranges (and one in ten with an overdamped
    suspension, outside them), every model, span count and road in turn."""
    rng = np.random.default_rng(seed)
    roads = ["flat", "harmonic", "bump", "iso-class", "iso-c10"]
    out = []
    for i in range(count):
        modal = i % 2 == 1
        values: dict[str, Any] = {
            "span_ft": float(rng.uniform(20, 250)),
            "n_spans": int(1 + (i // 2) % 2),
            "bridge_frequency_hz": float(rng.uniform(0.5, 15)),
            "bridge_weight_kip_per_ft": float(rng.uniform(0.5, 20)),
            "bridge_damping": float(rng.uniform(0, 0.1)),
            "truck_weight_kip": float(rng.uniform(5, 160)),
            "truck_frequency_hz": float(rng.uniform(0.5, 15)),
            "truck_damping": float(rng.uniform(0, 0.5)),
            "speed_mph": float(rng.uniform(5, 93)),
            "road": roads[(i // 4) % len(roads)],
            "iso_class": "ABCDE"[int(rng.integers(0, 5))],
            "c10_e6": float(rng.uniform(1, 5000)),
            "waviness": float(rng.uniform(1.5, 4)),
            "seed": int(rng.integers(0, 100)),
            "wavelength_ft": float(rng.uniform(2, 200)),
            "amplitude_in": float(rng.uniform(0, 2)),
            "bump_height_in": float(rng.uniform(-3, 3)),
            "bump_width_ft": float(rng.uniform(0.5, 30)),
            "bump_position_ft": float(rng.uniform(-100, 500)),
            "road_shift_ft": float(rng.choice([0.0, rng.uniform(0, 200)])),
            "approach_ft": float(rng.uniform(0, 400)),
            "modes": int(rng.integers(2, 11)) if modal else 1,
            "coupled": bool(rng.random() > 0.15),
        }
        if i % 10 == 7:  # an overdamped suspension (h20): taken, noted, crossed alike
            values["truck_damping"] = float(rng.uniform(1.0, 2.5))
        # the explorers' sliders step in whole units for some controls
        for name in ("span_ft", "approach_ft", "road_shift_ft", "speed_mph"):
            if rng.random() < 0.5:
                values[name] = float(round(values[name]))
        out.append(values)
    return out


def library_crossing(values: dict[str, Any]) -> vbi.Crossing:
    scenario = Scenario(**values)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.OutsideValidityWarning)
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        profile = scenario.profile()
        start = scenario.bridge_start(profile)
        options = scenario.simulate_options()
        return vbi.simulate(scenario.bridge(), scenario.vehicle(), profile, scenario.speed, start,
                            **options)  # fmt: skip


# ---------------------------------------------------------------------------- references
def hermite_peak(m0: np.ndarray, m1: np.ndarray, v0: np.ndarray, v1: np.ndarray,
                 h: np.ndarray) -> float:  # fmt: skip
    """Largest downward value (displacements up) over steps of the cubic Hermite interpolant
    of the values ``m`` and rates ``v`` at each step's ends: the ends, and the stationary
    points inside a step where the rate changes sign (written here with numpy)."""
    best = np.maximum(-m0, -m1)
    turn = v0 * v1 <= 0.0
    a0, a1, d0, d1 = m0[turn], m1[turn], v0[turn] * h[turn], v1[turn] * h[turn]
    rise = a1 - a0
    c3 = d0 + d1 - 2.0 * rise
    c2 = 3.0 * rise - 2.0 * d0 - d1
    inside = np.maximum(-a0, -a1)
    # stationary points: roots of 3 c3 t^2 + 2 c2 t + d0, in the form that avoids cancellation
    qa, qb, qc = 3.0 * c3, 2.0 * c2, d0
    disc = qb * qb - 4.0 * qa * qc
    real = disc >= 0.0
    q = -0.5 * (qb + np.where(qb >= 0.0, 1.0, -1.0) * np.sqrt(np.where(real, disc, 0.0)))
    with np.errstate(divide="ignore", invalid="ignore"):
        for t in (q / qa, qc / q):
            ok = real & np.isfinite(t) & (t > 0.0) & (t < 1.0)
            value = a0 + ((c3 * t + c2) * t + d0) * t
            inside = np.where(ok, np.maximum(inside, -value), inside)
    best[turn] = inside
    return float(best.max())


def reference_spans(crossing: vbi.Crossing) -> dict[str, list[float]]:
    """Peaks, statics and DAFs of each span by the issue 20 definitions, from the histories."""
    bridge = crossing.bridge
    x = crossing.position
    h = np.diff(x) / crossing.speed
    weight = crossing.vehicle.weight
    out: dict[str, list[float]] = {"peak": [], "static": [], "daf": [], "series_peak": []}
    if crossing.model == "one-coordinate":
        for j in range(bridge.n_spans):
            sign = 1.0 if j == 0 else -1.0
            z = sign * crossing.bridge_coordinate
            rate = sign * crossing.bridge_velocity
            peak = hermite_peak(z[:-1], z[1:], rate[:-1], rate[1:], h)
            static = weight / bridge.generalized_stiffness
            out["peak"].append(peak)
            out["static"].append(static)
            out["daf"].append(peak / static if peak > 0 else math.nan)
        return out
    modes = crossing.modes
    q, qd = crossing.modal_coordinates, crossing.modal_velocities
    xi = x - crossing.bridge_start
    on = (xi >= 0.0) & (xi <= bridge.length)
    contact = crossing.axle_contact_force[:, 0]
    phi_mid = modes.shape(np.array(bridge.midspans))
    statics = static_envelope(bridge.spans, bridge.EI, list(bridge.midspans), weight)
    phi_x = modes.shape(xi[on])
    for j, mid in enumerate(bridge.midspans):
        series = q @ phi_mid[j]
        rate = qd @ phi_mid[j]
        eta = continuous_statics(mid, xi[on], bridge.spans, bridge.EI).deflection
        correction = np.zeros_like(series)
        correction[on] = contact[on] * ((phi_x / modes.omega**2) @ phi_mid[j] - eta)
        u_j = series + correction
        secant = np.diff(correction) / h
        peak = hermite_peak(u_j[:-1], u_j[1:], rate[:-1] + secant, rate[1:] + secant, h)
        static = -float(statics.minimum[0, j])  # displacement positive up
        out["peak"].append(peak)
        out["static"].append(static)
        out["daf"].append(peak / static if peak > 0 else math.nan)
        out["series_peak"].append(hermite_peak(series[:-1], series[1:], rate[:-1], rate[1:], h))
    return out


def _number(value: object) -> float:
    return float(value) if isinstance(value, str) else value


def _close(a: object, b: object, rtol: float = RTOL) -> bool:
    a, b = _number(a), _number(b)
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= rtol * max(abs(a), abs(b))


# ---------------------------------------------------------------------------- the run
@pytest.fixture(scope="module")
def port_run(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    node = _node()
    folder = tmp_path_factory.mktemp("js-port")
    cases = random_settings(CASES)
    probes = {
        "uniform": [[0, 5], [1, 1000], [7, 17], [99, 2500], [2**32 + 5, 40], [2**40 + 3, 3]],
        "next_fast_len": [1, 5, 7, 11, 13, 97, 1000, 1001, 7441, 13201, 13501, 39999],
    }
    reports = [[values, [values["speed_mph"]], f"case-{i}"] for i, values in enumerate(cases[:20])]
    reports.append([{**cases[0], "truck_damping": 2.09}, [40.0], "overdamped"])
    reports.append([{**cases[2], "approach_ft": 0.0}, [40.0], "no-approach"])
    reports.append([{**cases[1], "truck_damping": 0.2}, [40.0, 95.0], "too-fast"])
    text = json.dumps({"cases": cases, "probes": probes, "report_cases": reports})
    (folder / "cases.json").write_text(text)
    subprocess.run([node, str(SCRIPT), str(folder / "cases.json"), str(folder / "out")],
                   check=True, timeout=900, cwd=ROOT)  # fmt: skip
    data = json.loads((folder / "out" / "results.json").read_text())
    arrays = np.fromfile(folder / "out" / "arrays.f64", dtype="<f8")
    return {"cases": cases, "probes": probes, "reports": reports, "data": data, "arrays": arrays}


def _array(run: dict[str, Any], where: list[int]) -> np.ndarray:
    start, size = where
    return run["arrays"][start : start + size]


def test_the_port_draws_numpys_random_phases_and_scipys_fft_length(port_run: dict) -> None:
    probes, probed = port_run["probes"], port_run["data"]["probed"]
    for (seed, count), got in zip(probes["uniform"], probed["uniform"], strict=True):
        expected = np.random.default_rng(seed).uniform(0.0, 2.0 * np.pi, count)
        assert np.array_equal(np.array(got), expected), f"seed {seed}"
    for n, got in zip(probes["next_fast_len"], probed["next_fast_len"], strict=True):
        assert got == scipy.fft.next_fast_len(n, real=True), n


def test_the_page_writes_the_report_parameter_files_the_live_explorers_write(
    port_run: dict,
) -> None:
    """The static explorers' report files are the live ones': the parameter file byte for byte
    (or both refuse with the same message), the deck's stations exactly and its elevations to
    rounding (the browser's sines are not numpy's to the last bit);
    tests/widgets/test_report_file.py checks that vbi-report takes them."""
    for (values, speeds, name), got in zip(port_run["reports"], port_run["data"]["reports"],
                                           strict=True):  # fmt: skip
        try:
            files = report_files(values, speeds, name=name)
        except ValueError as error:
            assert got.get("error") == str(error), name
            continue
        assert "error" not in got, f"{name}: the page refused: {got['error']}"
        assert [f["name"] for f in got["files"]] == [f.name for f in files.files], name
        assert got["files"][0]["text"] == files.files[0].text, f"{name}: the YAML differs"
        for mine, theirs in zip(got["files"][1:], files.files[1:], strict=True):
            a = np.loadtxt(mine["text"].splitlines(), delimiter=",")
            b = np.loadtxt(theirs.text.splitlines(), delimiter=",")
            assert np.array_equal(a[:, 0], b[:, 0]), f"{name}: deck stations differ"
            scale = max(float(np.abs(b[:, 1]).max()), 1e-12)
            np.testing.assert_allclose(a[:, 1], b[:, 1], rtol=0, atol=1e-12 * scale, err_msg=name)
        assert got["note"] == files.note


def test_the_ports_constants_are_the_librarys(port_run: dict) -> None:
    data = port_run["data"]
    for name in ("inch", "ft", "lbf", "kip", "mile", "mph", "kph", "g"):
        assert data["units"][name] == getattr(u, name), name
    for key in ("speed", "sample_spacing", "c10", "vehicle_damping_ratio"):
        js = data["ranges"][key]
        assert [_number(v) for v in js["hard"]] == list(RANGES[key].hard), key
        assert [_number(v) for v in js["soft"]] == list(RANGES[key].soft), key
    assert data["iso_class_means"] == ISO_CLASS_MEANS
    assert tuple(data["iso_band"]) == ISO_BAND
    assert data["max_road_shift_ft"] == MAX_ROAD_SHIFT_FT
    assert data["road_spacing"] == ROAD_SPACING
    # what the page's report writer takes from the report's keys (report_file's, from SCHEMA)
    report = {k: _number(v) for k, v in data["report"].items()}
    assert report == {
        "dampingWarned": SCHEMA["vehicle"]["damping_ratio"].bounds[1],
        "maxSpeed": pytest.approx(SCHEMA["speeds"].bounds[1], rel=1e-15),
        "maxSpeeds": MAX_SPEEDS,
        "minApproach": SCHEMA["profile"]["approach_length"].bounds[0],
    }


def test_the_port_crosses_as_the_library_does(port_run: dict) -> None:
    problems: list[str] = []
    kinds: set[tuple] = set()
    compared = overdamped = 0
    lost = 0
    for i, (values, got) in enumerate(
        zip(port_run["cases"], port_run["data"]["results"], strict=True)
    ):
        label = f"case {i} ({values['road']}, {values['n_spans']} span(s), modes={values['modes']})"
        try:
            crossing = library_crossing(values)
        except ValueError as error:
            if "error" not in got:
                problems.append(f"{label}: the library refuses ({error}) but the port ran")
            continue
        if "error" in got:
            problems.append(f"{label}: the port refused ({got['error']}) but the library ran")
            continue
        compared += 1
        overdamped += values["truck_damping"] >= 1.0
        lost += crossing.lost_contact
        kinds.add((values["road"], values["n_spans"], crossing.model))
        problems += _compare(label, crossing, got, port_run)
    assert not problems, "\n".join(problems[:40])
    assert compared >= 200, f"only {compared} settings compared"
    assert overdamped >= 15, f"only {overdamped} overdamped suspensions compared"
    assert len(kinds) == 5 * 2 * 2, f"not every road, span count and model was drawn: {kinds}"
    assert 0 < lost < compared, f"{lost} of {compared} crossings lost contact: draw both kinds"


def _compare(label: str, crossing: vbi.Crossing, got: dict, run: dict) -> list[str]:
    out: list[str] = []
    bridge, vehicle = crossing.bridge, crossing.vehicle
    s = got["setting"]
    expected = {
        "EI": bridge.EI,
        "mass_per_length": bridge.mass_per_length,
        "damping_ratio": bridge.damping_ratio,
        "mass": vehicle.mass,
        "stiffness": vehicle.stiffness,
        "damping": vehicle.damping,
        "speed": crossing.speed,
        "bridge_start": crossing.bridge_start,
    }
    for name, value in expected.items():
        if not _close(s[name], value, 1e-14):
            out.append(f"{label}: setting {name} {s[name]!r} != {value!r}")
    if s["spans"] != list(bridge.spans) or s["model"] != crossing.model:
        out.append(f"{label}: spans {s['spans']} / model {s['model']} differ")
    # the road and the grid
    road = Scenario(**run["cases"][int(label.split()[1])]).profile()
    x_js, e_js = _array(run, got["road_x"]), _array(run, got["road_elevation"])
    if not np.array_equal(x_js, road.x):
        out.append(f"{label}: road stations differ")
    scale = max(float(np.abs(road.elevation).max()), 1e-12)
    if not np.allclose(e_js, road.elevation, rtol=0, atol=1e-12 * scale):
        out.append(
            f"{label}: road elevations differ by {np.abs(e_js - road.elevation).max():.3g} m"
        )
    if got["nodes"] != crossing.position.size:
        return [*out, f"{label}: {got['nodes']} nodes, the library {crossing.position.size}"]
    if not np.array_equal(_array(run, got["position"]), crossing.position):
        out.append(f"{label}: node stations differ")
    if not _close(got["dt"], crossing.dt, 1e-12):
        out.append(f"{label}: largest step {got['dt']} s, the library {crossing.dt} s")
    # histories that do not depend on the DAF's definition
    weight = vehicle.weight
    histories = [
        ("contact force", _array(run, got["contact_force"]), crossing.contact_force, weight),
        ("truck displacement", _array(run, got["vehicle_displacement"]),
         crossing.vehicle_displacement, None),
    ]  # fmt: skip
    for j, where in enumerate(got["midspan"]):  # the headline: what the span DAFs read
        histories.append(
            (f"midspan {j + 1}", _array(run, where), crossing.midspan_displacement[:, j], None)
        )
    if crossing.model == "modal":  # and the modes' series
        for j, where in enumerate(got["series_midspan"]):
            series = crossing.series_midspan_displacement[:, j]
            histories.append((f"series midspan {j + 1}", _array(run, where), series, None))
    for name, mine, theirs, size in histories:
        size = size or max(float(np.abs(theirs).max()), 1e-300)
        error = float(np.abs(mine - theirs).max())
        if error > RTOL * size:
            out.append(f"{label}: {name} history differs by {error / size:.2e} of its size")
    # contact checks
    for name in ("contact_force_amplification", "min_contact_force_ratio"):
        if not _close(got[name], getattr(crossing, name)):
            out.append(f"{label}: {name} {got[name]} != {getattr(crossing, name)}")
    if abs(got["tension_fraction"] - crossing.tension_fraction) > 1e-9:
        out.append(
            f"{label}: tension_fraction {got['tension_fraction']} != {crossing.tension_fraction}"
        )
    if got["lost_contact"] != crossing.lost_contact:
        out.append(f"{label}: lost_contact {got['lost_contact']} != {crossing.lost_contact}")
    # peaks and DAF (issue 20's definitions, from the library's histories)
    ref = reference_spans(crossing)
    for j in range(bridge.n_spans):
        for name in ("peak", "static", "daf"):
            if not _close(got[name][j], ref[name][j]):
                out.append(f"{label}: span {j + 1} {name} {got[name][j]} != {ref[name][j]}")
    if crossing.model == "modal":
        for j in range(bridge.n_spans):
            if not _close(got["series"]["peak"][j], ref["series_peak"][j]):
                out.append(f"{label}: span {j + 1} series peak differs")
    # and the library's own DAFs, which follow the same definition
    for j in range(bridge.n_spans):
        if not _close(got["daf"][j], float(crossing.daf[j])):
            out.append(f"{label}: span {j + 1} DAF {got['daf'][j]} != {crossing.daf[j]}")
        if crossing.model == "modal" and not _close(got["series"]["daf"][j],
                                                    float(crossing.series_daf[j])):  # fmt: skip
            out.append(f"{label}: span {j + 1} series DAF differs from the library's")
    return out
