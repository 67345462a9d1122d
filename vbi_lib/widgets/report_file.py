"""From an explorer to a report: the current setting as a parameter file ``vbi-report`` accepts.

:func:`report_files` writes what an explorer shows as today's report keys
(:data:`vbi_lib.reports.parameters.SCHEMA`): the bridge from its span, weight per length and
first frequency (the report's third route, study equation 84), the truck as the study's sprung
mass, and the road:

* an ISO 8608 class (not shifted) becomes the report's generated road, same class, seed and
  spacing, with the explorer's approach; the report draws it over the approach and the bridge
  only, so it is the same kind of road, not the same samples;
* any other road (flat, harmonic, a bump, a C10 and waviness, a shifted or a measured road)
  becomes ``profile.file``: the deck the explorer drives, from the first support to the far
  one, written beside the parameter file as ``NAME-deck.csv`` (metres), behind the report's
  flat approach.

The report runs the one-coordinate model, coupled (and decoupled as a bound), at the explorer's
speed (a sweep's: its lowest, shown and highest); a setting the report cannot take (a quarter
car, a speed above 150 km/h) is refused with the control to change.  A suspension damped above
the intended range (overdamped from 100 %) is written as it is: the report takes it and warns.
The static book's explorers write the same text (``vbi-model.js``, ``reportParameters``).

>>> from vbi_lib.widgets import Scenario
>>> files = report_files(Scenario().__dict__, [41.0])
>>> [f.name for f in files.files]
['vbi-explorer.yaml']
>>> [line.strip() for line in files.files[0].text.splitlines() if line.startswith("  ")][:4]
['span: 100 ft', 'n_spans: 1', 'mass_per_length: 4.6 kip/ft', 'first_frequency: 3 Hz']
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .. import units as u
from ..reports.parameters import SCHEMA
from ..reports.values import MAX_SPEEDS
from .scenario import Scenario

__all__ = ["ReportFile", "ReportFiles", "report_files", "write_report_files"]

#: The report's ``profile.approach_length`` must be above this [m] (0: any approach); the
#: sprung mass has no wheelbase that would need a longer one.
_MIN_APPROACH = SCHEMA["profile"]["approach_length"].bounds[0]
#: Above this suspension damping ratio the report warns (vehicle.damping_ratio).
_DAMPING_WARNED = SCHEMA["vehicle"]["damping_ratio"].bounds[1]


@dataclass(frozen=True)
class ReportFile:
    """One file to write: its name and its text."""

    name: str
    text: str


@dataclass(frozen=True)
class ReportFiles:
    """The parameter file (first) and the deck profile it names, if any, and a note on them."""

    files: tuple[ReportFile, ...]
    note: str


def num(value: float) -> str:
    """A number as the file writes it (Python's ``:.10g``; the page writes the same)."""
    return f"{value:.10g}"


def coordinate(value: float) -> str:
    """A profile coordinate in full (17 significant digits, exponent of two digits or more)."""
    return f"{0.0 if value == 0 else value:.16e}"


def _refuse(name: str, shown: str, rule: str) -> ValueError:
    return ValueError(f"{name}={shown} {rule}; the report parameter file was not written")


def report_files(
    values: dict[str, Any], speeds_mph: list[float], road: Any = None, name: str = "vbi-explorer"
) -> ReportFiles:
    """The report parameter file of an explorer's setting (and its deck profile if needed).

    Parameters
    ----------
    values
        The explorer's values by parameter (fields of :class:`~vbi_lib.widgets.Scenario`).
    speeds_mph
        The speeds the report runs [mph], at most 20.
    road
        ``(profile, bridge_start)``: the road the explorer drives and the station of its
        first support [m], for a road written as a file; built from ``values`` if ``None``.
    name
        The parameter file's name without ``.yaml``.

    Raises
    ------
    ValueError
        A setting the report cannot take, naming the explorer's control.
    """
    v = {**Scenario().__dict__, **values}
    if v["vehicle_type"] != "sprung-mass":
        raise _refuse(
            "vehicle_type", repr(v["vehicle_type"]), "has no report keys: the report runs the "
            "study's sprung mass (choose vehicle_type='sprung-mass')"
        )  # fmt: skip
    speeds = sorted(set(float(s) for s in speeds_mph))
    if not 1 <= len(speeds) <= MAX_SPEEDS:
        raise _refuse("speeds", str(len(speeds)), f"must be 1 to {MAX_SPEEDS} speeds")
    top = SCHEMA["speeds"].bounds[1] / u.mph
    for speed in speeds:
        if not speed * u.mph <= SCHEMA["speeds"].bounds[1]:
            raise _refuse(
                "speed_mph", f"{num(speed)} mph", f"is above the report's {num(top)} mph "
                "(150 km/h): lower the speed"
            )  # fmt: skip
    scenario = Scenario(**{k: v[k] for k in Scenario.__dataclass_fields__})
    generated = v["road"] == "iso-class" and v["road_shift_ft"] == 0
    approach = v["approach_ft"] * u.ft
    lines = [
        "# Report parameters written by a vbi explorer from its current setting:",
        f"#   vbi-report {name}.yaml --output-dir reports/out",
        "# The report runs the study's one-coordinate model, coupled (and decoupled as a",
        "# bound), with the study's sprung mass; the explorer ran "
        + ("the one-coordinate model" if v["modes"] == 1 else f"{v['modes']} beam modes")
        + (", coupled." if v["coupled"] else ", decoupled."),
    ]
    if generated:
        lines.append(
            f"# The report draws its own ISO 8608 class {v['iso_class']} road (seed {v['seed']}) "
            "over the approach and the bridge: the same kind of road as the explorer's, not "
            "the same samples."
        )
    else:
        lines.append(
            f"# The deck the explorer drives ({scenario.road_text()}) is {name}-deck.csv beside "
            "this file; the report puts its own flat approach before it."
        )
    if v["truck_damping"] > _DAMPING_WARNED:
        lines.append(
            f"# The suspension is damped {num(v['truck_damping'] * 100)} % of critical, above "
            f"the intended {num(_DAMPING_WARNED * 100)} % (from 100 % it is overdamped): the "
            "report takes it and warns of it."
        )
    if approach <= _MIN_APPROACH:
        lines.append(
            f"# The explorer's approach of {num(v['approach_ft'])} ft is none, so the report's "
            "own rule sets the approach."
        )
    bridge_text = f"{num(v['span_ft'])} ft span" + (" x 2" if v["n_spans"] == 2 else "")
    lines += [
        f'title: "vbi explorer: {bridge_text}, {num(speeds[0])} mph"',
        "bridge:",
        f"  span: {num(v['span_ft'])} ft",
        f"  n_spans: {v['n_spans']}",
        f"  mass_per_length: {num(v['bridge_weight_kip_per_ft'])} kip/ft",
        f"  first_frequency: {num(v['bridge_frequency_hz'])} Hz",
        f"  damping_ratio: {num(v['bridge_damping'] * 100)} %",
        "vehicle:",
        f"  mass: {num(v['truck_weight_kip'])} kip",
        f"  frequency: {num(v['truck_frequency_hz'])} Hz",
        f"  damping_ratio: {num(v['truck_damping'] * 100)} %",
        "profile:",
    ]
    files = []
    if generated:
        lines += [f"  iso_class: {v['iso_class']}", f"  seed: {v['seed']}", "  spacing: 1 in"]
    else:
        lines += [f"  file: {name}-deck.csv", "  length_unit: m"]
        files.append(ReportFile(f"{name}-deck.csv", _deck_text(scenario, road)))
    if approach > _MIN_APPROACH:
        lines.append(f"  approach_length: {num(v['approach_ft'])} ft")
    lines.append("speeds: [" + ", ".join(f"{num(s)} mph" for s in speeds) + "]")
    parameters = ReportFile(f"{name}.yaml", "\n".join(lines) + "\n")
    beside = f" and {files[0].name} beside it" if files else ""
    note = (
        f"Report parameters: {parameters.name}{beside}; run vbi-report {parameters.name} "
        "--output-dir reports/out."
    )
    return ReportFiles((parameters, *files), note)


def _deck_text(scenario: Scenario, road: Any) -> str:
    """The deck the explorer drives: stations from the first support [m] and elevations [m]."""
    profile, start = road if road is not None else (None, None)
    if profile is None:
        profile = scenario.profile()
        start = scenario.bridge_start(profile)
    length = scenario.bridge().length
    tolerance = 1e-9 * max(1.0, length)
    x = profile.x
    inside = (x > start + tolerance) & (x < start + length - tolerance)
    stations = np.concatenate(([start], x[inside], [start + length]))
    elevation = profile.elevation_at(stations)
    lines = [
        "# deck profile written by a vbi explorer: station from the first support [m], "
        "elevation [m]"
    ]
    lines += [
        f"{coordinate(s - start)},{coordinate(e)}" for s, e in zip(stations, elevation, strict=True)
    ]
    return "\n".join(lines) + "\n"


def write_report_files(files: ReportFiles, folder: str | Path) -> list[Path]:
    """Write the files into ``folder`` (made if needed); returns their paths."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for item in files.files:
        path = folder / item.name
        path.write_text(item.text, encoding="utf-8")
        paths.append(path)
    return paths
