"""Reports of real bridges, written by vbi-report's own route, against direct library calls.

The JSON a report writes is compared row by row with a crossing built here with
``vbi.simulate`` and its ``sections``, independently of the report's code: the bridge from
the parameter file's numbers (and its spans reversed for a backward crossing), the vehicle
from ``vbi.vehicles`` or its definition, the road from the deck (the generated road
regenerated from its seed, or the deck file read with numpy; reversed backward) behind a
flat approach, stations turned to the far support's frame backward, the shear's faces
swapped and its sign turned back.  Two cases, as the issue asks: a three-span continuous
bridge of unequal spans under the HS20 (the rear spacing searched), and a quarter car on
the I-76 span 3 deck.  The PDF of the first is rendered to PNG: nothing reaches the right
edge of a page, and no page ends with a heading.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import subprocess
import warnings
from pathlib import Path

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib.reports import running

FT, INCH, LBF, MPH, G = 0.3048, 0.0254, 4.4482216152605, 0.44704, 9.80665
KIP = 1000 * LBF
EFFECTS = ("displacement", "moment", "shear")

THREE_SPANS = """\
title: Three unequal spans under the HS20
bridge:
  spans: [40 ft, 55 ft, 45 ft]
  EI: 2.2e13 lbf*in**2
  mass_per_length: 6.5 kip/ft
  damping_ratio: 2 %
vehicle: {type: hs20, rear_axle_spacing: [14 ft, 30 ft]}
profile: {iso_class: B, seed: 5, approach: flat}
speeds: [40 mph, 65 mph]
quick: true
"""

QUARTER_CAR = """\
title: I-76 span 3, quarter car
bridge: {span: 140 ft, k_mid: 222278 lbf/in, first_frequency: 2.08 Hz, damping_ratio: 0.01}
vehicle: {type: quarter-car, mass: 200 lbf*s**2/in, unsprung_mass: 2 t, frequency: 2.5 Hz,
          tyre_stiffness: 7 MN/m, damping_ratio: 0.10}
profile: {file: deck.csv, length_unit: inch}
speeds: [30 mph, 70 mph]
quick: true
"""


def pdf_wanted() -> bool:
    if running.find_chromium() is not None:
        return True
    if os.environ.get("CI") == "true":
        raise RuntimeError("CI needs Debian's chromium (apt-get install -y chromium)")
    return False


@pytest.fixture(scope="module")
def reports(tmp_path_factory: pytest.TempPathFactory, shared_data: Path) -> dict:
    """Both reports, written by one call to the runner (one kernel)."""
    root = tmp_path_factory.mktemp("real")
    (root / "three-spans.yaml").write_text(THREE_SPANS)
    shutil.copyfile(shared_data / "profiles" / "i76-span3.csv", root / "deck.csv")
    (root / "quarter-car.yaml").write_text(QUARTER_CAR)
    files = running.write_reports(
        [root / "three-spans.yaml", root / "quarter-car.yaml"], root / "out", pdf=pdf_wanted()
    )
    return {"root": root, "files": files}


def modes_of(bridge: vbi.Bridge) -> int:
    """Every mode up to 2.3 times the highest simply supported span frequency."""
    limit = (
        2.3
        * (math.pi / min(bridge.spans)) ** 2
        * math.sqrt(bridge.EI / bridge.mass_per_length)
        / (2 * math.pi)
    )
    frequencies = vbi.modes.beam_modes(bridge, 30).frequencies_hz
    return max(1, int(np.sum(frequencies <= limit * (1 + 1e-12))))


def road_of(deck_x: np.ndarray, deck_z: np.ndarray, approach: float, after: float) -> vbi.Profile:
    """A flat approach, the deck, and a flat road ``after`` past its far end."""
    x = np.concatenate(([0.0], approach + deck_x))
    z = np.concatenate(([deck_z[0]], deck_z))
    if after > 0:
        x, z = np.append(x, x[-1] + after), np.append(z, z[-1])
    return vbi.Profile(x, z)


def check_rows(rows: list[dict], bridge, vehicle_of, deck_x, deck_z, approach, after, modes):  # noqa: ANN001
    """Every row equals a direct crossing of its direction, speed and vehicle."""
    length = bridge.length
    back = vbi.Bridge.continuous(list(bridge.spans[::-1]), EI=bridge.EI,
                                 mass_per_length=bridge.mass_per_length,
                                 damping_ratio=bridge.damping_ratio)  # fmt: skip
    cases = {}
    for row in rows:
        key = (row["direction"], row["speed_m_s"], row["rear_axle_spacing_m"])
        cases.setdefault(key, []).append(row)
    for (direction, speed, spacing), mine in cases.items():
        vehicle = vehicle_of(spacing)
        if direction == "forward":
            on, road = bridge, road_of(deck_x, deck_z, approach, after)
        else:
            on = back
            road = road_of(length - deck_x[::-1], deck_z[::-1], approach, after)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", vbi.VbiWarning)
            crossing = vbi.simulate(on, vehicle, road, speed, approach, model="modal",
                                    modes=modes)  # fmt: skip
        x = np.array([r["section_m"] for r in mine])
        faces = [r["face"] or "left" for r in mine]
        if direction == "backward":
            x = length - x
            faces = [{"left": "right", "right": "left"}[f] for f in faces]
        response = crossing.sections(x, side=tuple(faces))
        for i, row in enumerate(mine):
            e = EFFECTS.index(row["effect"])
            sign = -1.0 if direction == "backward" and row["effect"] == "shear" else 1.0
            up = response.governing[e, i] > 0
            static = (response.static.maximum if up else response.static.minimum)[e, i]
            dynamic = (response.maximum if up else response.minimum)[e, i]
            assert row["daf"] == pytest.approx(response.daf[e, i], rel=1e-9), row
            assert row["static"] == pytest.approx(sign * static, rel=1e-9), row
            assert row["dynamic"] == pytest.approx(sign * dynamic, rel=1e-9), row
            assert row["lost_contact"] == crossing.lost_contact
            assert row["flight_fraction"] == pytest.approx(crossing.flight_fraction, abs=1e-12)
    return cases


def test_three_unequal_spans_under_the_hs20_are_direct_crossings(reports: dict) -> None:
    report = reports["files"][0]
    document = json.loads(report.json.read_text())
    rows = document["results"]
    spans = [40 * FT, 55 * FT, 45 * FT]
    bridge = vbi.Bridge.continuous(
        spans, EI=2.2e13 * LBF * INCH**2, mass_per_length=6.5 * KIP / FT / G, damping_ratio=0.02
    )
    # the places: midspans and piers; the shear at a pier on both faces
    supports = np.cumsum([0.0, *spans])
    places = sorted({(r["section_m"], r["effect"], r["face"]) for r in rows})
    midspans = [(a + b) / 2 for a, b in zip(supports[:-1], supports[1:], strict=True)]
    expected = {(x, e, "") for x in midspans for e in EFFECTS}
    expected |= {(x, "moment", "") for x in supports[1:-1]}
    expected |= {(x, "shear", f) for x in supports[1:-1] for f in ("left", "right")}
    assert {(round(x, 9), e, f) for x, e, f in places} == {
        (round(x, 9), e, f) for x, e, f in expected
    }
    assert len(rows) == len(expected) * 2 * 2  # two speeds, two directions
    # the rear spacing of each row is the one whose static extreme is the largest
    stations, faces = [r["section_m"] for r in rows], [r["face"] or "both" for r in rows]
    search = vbi.vehicles.governing_rear_spacing(spans, bridge.EI, stations, side=faces)
    for i, row in enumerate(rows):
        assert row["rear_axle_spacing_m"] == pytest.approx(
            search.governing[EFFECTS.index(row["effect"]), i]
        )
    assert len({r["rear_axle_spacing_m"] for r in rows}) > 1  # not every place wants 14 ft
    # the deck: the generated class B road, seed 5, behind a flat approach of the longest
    # truck's wheelbase (30 ft rear spacing) and 10 m, a flat road of it and 1 m past the end
    wheelbase = 44 * FT
    approach = wheelbase + 10.0
    generated = vbi.Profile.iso8608(approach + bridge.length, 0.025, iso_class="B", seed=5)
    deck = generated.segment(approach, approach + bridge.length)
    check_rows(rows, bridge, lambda s: vbi.vehicles.hs20(rear_spacing=s), deck.x - approach,
               deck.elevation, approach, wheelbase + 1.0, modes_of(bridge))  # fmt: skip
    assert document["model"] == "modal" and document["modes"] == modes_of(bridge)
    csv = report.csv.read_text().splitlines()
    assert len(csv) == len(rows) + 1


def test_a_quarter_car_on_the_i76_deck_is_a_direct_crossing(reports: dict) -> None:
    report = reports["files"][1]
    document = json.loads(report.json.read_text())
    rows = document["results"]
    assert {r["effect"] for r in rows} == set(EFFECTS) and len(rows) == 3 * 2 * 2
    raw = np.loadtxt(reports["root"] / "deck.csv", delimiter=",")
    span = 140 * FT
    x = (raw[:, 0] - raw[0, 0]) * INCH
    deck_x, deck_z = np.append(x, span), np.append(raw[:, 1], raw[-1, 1]) * INCH
    bridge = vbi.Bridge.from_midspan_stiffness(span, 1, 222278 * LBF / INCH, 2.08, 0.01)
    mass, unsprung, omega = 200 * LBF / INCH, 2000.0, 2 * math.pi * 2.5
    car = vbi.QuarterCar(mass, unsprung, mass * omega**2, 2 * 0.10 * mass * omega, 7e6)
    check_rows(rows, bridge, lambda s: car, deck_x, deck_z, 10.0, 0.0, 1)
    # the flights the report lists are the crossings' own
    flights = document["flights"]
    assert all(f["duration_s"] is None or f["duration_s"] > 0 for f in flights)
    assert {r["flight_fraction"] > 0 for r in rows} >= {any(f["on_bridge"] for f in flights)}


def _pages(pdf: Path, folder: Path) -> list[np.ndarray]:
    from PIL import Image

    for old in folder.glob("page-*.png"):
        old.unlink()
    subprocess.run(["pdftoppm", "-r", "60", "-png", str(pdf), str(folder / "page")], check=True)
    return [np.asarray(Image.open(p).convert("L")) for p in sorted(folder.glob("page-*.png"))]


def test_the_pdf_keeps_everything_within_the_page(reports: dict) -> None:
    report = reports["files"][0]
    if report.pdf is None:
        pytest.skip("chromium is missing: the PDF is not checked")
    if shutil.which("pdftoppm") is None:
        if os.environ.get("CI") == "true":
            raise RuntimeError("CI needs poppler-utils (apt-get install -y poppler-utils)")
        pytest.skip("pdftoppm (poppler-utils) is missing: the PDF's pages are not rendered")
    pages = _pages(report.pdf, reports["root"])
    assert len(pages) > 4
    for k, page in enumerate(pages):
        height, width = page.shape
        dpmm = width / 215.9  # letter: 215.9 mm wide (the report is in US units)
        # the right margin is 12 mm: nothing may print in its outer 9 mm (a figure or table
        # cut at the page's edge, or a scrollbar, would)
        edge = page[:, int(width - 9 * dpmm) :]
        assert (edge > 235).all(), f"page {k + 1} has content at its right edge"
    # no page ends with a heading (its content on the next)
    headings = {"Summary", "Inputs", "The road", "DAF of each effect at each place",
                "DAF against speed", "Envelopes along the bridge", "The worst requested crossing",
                "The tyres", "Sensitivity to the profile's position", "The model's limits",
                "Provenance", "Design codes"}  # fmt: skip
    for k in range(1, len(pages) + 1):
        text = subprocess.run(["pdftotext", "-f", str(k), "-l", str(k), "-layout",
                               str(report.pdf), "-"], capture_output=True, text=True,
                              check=True).stdout  # fmt: skip
        lines = [line.strip() for line in text.splitlines() if line.strip()]
        assert lines and lines[-1] not in headings, f"page {k} ends with its heading {lines[-1]!r}"
