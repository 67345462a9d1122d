"""Parameterised HTML reports: an engineer's bridge, truck and road in, a DAF report out.

A report is the notebook ``vbi_lib/templates/bridge_report.ipynb`` executed by papermill with
the engineer's values, then converted to HTML without its code.  Every value is text with
its unit (``"100 ft"``, ``"4.5 Hz"``, ``"77.2 kip"``) read by :func:`vbi_lib.units.parse`
(pint); :func:`read_inputs` checks them all before anything runs, and the HTML is written
only when the whole report has run (to a temporary file, then renamed).

>>> inputs = read_inputs(span="100 ft", k_mid="497527 lbf/in", first_frequency="3.99 Hz",
...                      vehicle_mass="200 slinch", vehicle_frequency="4.5 Hz")
>>> round(inputs.bridge.first_frequency_hz, 2), inputs.speeds_mph
(3.99, (30.0, 45.0, 60.0))

From the command line (parameters as ``name=value`` pairs)::

    python -m vbi_lib.reports report.html span="100 ft" k_mid="497527 lbf/in" ...
"""

from __future__ import annotations

import os
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from . import units as u
from .bridges import Bridge
from .profile_files import read_profile
from .profiles import Profile
from .vehicles import Vehicle

TEMPLATE = Path(__file__).resolve().parent / "templates" / "bridge_report.ipynb"

#: Report parameters and their defaults (text values carry their units).
DEFAULTS: dict[str, Any] = {
    "title": "Dynamic amplification of a bridge under one truck",
    "span": "100 ft",
    "n_spans": 1,
    "k_mid": "",
    "EI": "",
    "mass_per_length": "",
    "first_frequency": "",
    "bridge_damping": 0.01,
    "vehicle_mass": "200 slinch",
    "vehicle_frequency": "4.5 Hz",
    "vehicle_damping": 0.10,
    "profile_path": "",
    "profile_unit": "inch",
    "iso_class": "C",
    "approach": "320 ft",
    "speeds": "30 mph, 45 mph, 60 mph",
    "seed": 1,
    "quick": False,
}


@dataclass(frozen=True)
class ReportInputs:
    """What a report runs on, in SI: the model objects and the speeds."""

    bridge: Bridge
    vehicle: Vehicle
    profile: Profile
    bridge_start: float
    speeds: tuple[float, ...]
    profile_source: str

    @property
    def speeds_mph(self) -> tuple[float, ...]:
        return tuple(round(s / u.mph, 6) for s in self.speeds)


def _mass_or_weight(text: str, name: str, per_length: bool) -> float:
    """A mass (``"200 slinch"``, ``"0.99 slinch/inch"``) or a weight (``"77.2 kip"``,
    ``"4.6 kip/ft"``) divided by g, in kg or kg/m."""
    mass_kind, force_kind = (
        ("mass_per_length", "force_per_length") if per_length else ("mass", "force")
    )
    for kind, factor in ((mass_kind, 1.0), (force_kind, 1.0 / u.g)):
        try:
            return u.parse(text, kind, name=name) * factor
        except ValueError:
            continue
    examples = "'0.99 slinch/inch' or '4.6 kip/ft'" if per_length else "'200 slinch' or '77.2 kip'"
    what = "a mass or a weight per length" if per_length else "a mass or a weight"
    raise ValueError(f"{name}={text!r} must be {what} (e.g. {examples})")


def read_inputs(**parameters: Any) -> ReportInputs:
    """Check and convert report parameters (see :data:`DEFAULTS`) to model objects.

    The bridge comes from ``k_mid`` and ``first_frequency`` (study equations 82-84), or from
    ``EI`` and ``mass_per_length``, or from ``mass_per_length`` and ``first_frequency``.  The
    road is the file ``profile_path`` (two columns, stations and elevations in
    ``profile_unit``) with the bridge starting ``approach`` after its first station, or, if no
    file is given, an ISO 8608 road of class ``iso_class``.

    Raises
    ------
    ValueError
        Naming the parameter, its value and what is allowed.
    """
    unknown = sorted(set(parameters) - set(DEFAULTS))
    if unknown:
        raise ValueError(f"unknown report parameter(s) {unknown}; allowed: {sorted(DEFAULTS)}")
    p = {**DEFAULTS, **parameters}
    span = u.parse(p["span"], "length", name="span")
    n_spans = p["n_spans"]
    if isinstance(n_spans, str) and n_spans.strip().isdigit():
        n_spans = int(n_spans)
    damping = float(p["bridge_damping"])
    given = {k for k in ("k_mid", "EI", "mass_per_length", "first_frequency") if str(p[k]).strip()}
    if {"k_mid", "first_frequency"} <= given:
        bridge = Bridge.from_midspan_stiffness(
            span,
            n_spans,
            u.parse(p["k_mid"], "stiffness", name="k_mid"),
            u.parse(p["first_frequency"], "frequency", name="first_frequency"),
            damping,
        )
    elif {"EI", "mass_per_length"} <= given:
        bridge = Bridge(
            span,
            n_spans,
            u.parse(p["EI"], "flexural_rigidity", name="EI"),
            _mass_or_weight(p["mass_per_length"], "mass_per_length", per_length=True),
            damping,
        )
    elif {"mass_per_length", "first_frequency"} <= given:
        bridge = Bridge.from_frequency(
            span,
            n_spans,
            _mass_or_weight(p["mass_per_length"], "mass_per_length", per_length=True),
            u.parse(p["first_frequency"], "frequency", name="first_frequency"),
            damping,
        )
    else:
        raise ValueError(
            f"the bridge needs k_mid and first_frequency, or EI and mass_per_length, or "
            f"mass_per_length and first_frequency; got {sorted(given) or 'none of them'}"
        )
    vehicle = Vehicle.from_frequency(
        _mass_or_weight(p["vehicle_mass"], "vehicle_mass", per_length=False),
        u.parse(p["vehicle_frequency"], "frequency", name="vehicle_frequency"),
        float(p["vehicle_damping"]),
    )
    speeds = tuple(
        u.parse(text.strip(), "speed", name="speeds")
        for text in str(p["speeds"]).split(",")
        if text.strip()
    )
    if not speeds or min(speeds) <= 0:
        raise ValueError(f"speeds={p['speeds']!r} must list positive speeds, e.g. '30 mph, 45 mph'")
    approach = u.parse(p["approach"], "length", name="approach")
    if approach < 0:
        raise ValueError(f"approach={p['approach']!r} must be a length >= 0")
    if str(p["profile_path"]).strip():
        road = read_profile(p["profile_path"], unit=p["profile_unit"])
        source = f"measured profile {Path(p['profile_path']).name}"
    else:
        length = approach + bridge.length + 1.0
        road = Profile.iso8608(length, 1 * u.inch, iso_class=str(p["iso_class"]), seed=p["seed"])
        source = f"generated ISO 8608 class {p['iso_class']} road (seed {p['seed']})"
    start = road.start + approach
    if start + bridge.length > road.end:
        raise ValueError(
            f"profile_path={p['profile_path']!r} covers {road.length:.1f} m but the approach "
            f"({approach:.1f} m) and the bridge ({bridge.length:.1f} m) need "
            f"{approach + bridge.length:.1f} m"
        )
    return ReportInputs(bridge, vehicle, road, start, speeds, source)


def make_report(
    output: str | Path, *, timeout: float = 900, keep_notebook: bool = False, **parameters: Any
) -> Path:
    """Run the report for ``parameters`` and write it as HTML to ``output``.

    Parameters are checked first (:func:`read_inputs`); the notebook runs with papermill (a
    cell that fails stops the report with its error); the HTML (code hidden) is written to a
    temporary file beside ``output`` and renamed, so a failed run leaves nothing behind.

    Parameters
    ----------
    output
        Path of the HTML file.
    timeout
        Seconds allowed for any one cell.
    keep_notebook
        Also keep the executed notebook next to the HTML (``.ipynb``).
    **parameters
        Report parameters (:data:`DEFAULTS`).

    Returns
    -------
    Path
        The HTML file.
    """
    import nbformat
    import papermill
    from nbconvert import HTMLExporter

    read_inputs(**parameters)  # fail before anything runs
    output = Path(output)
    if output.suffix.lower() != ".html":
        raise ValueError(f"output={str(output)!r} must be an .html file")
    output.parent.mkdir(parents=True, exist_ok=True)
    values = {**DEFAULTS, **parameters}
    if values["profile_path"]:
        values["profile_path"] = str(Path(values["profile_path"]).resolve())
    with tempfile.TemporaryDirectory() as work:
        executed = Path(work) / "report.ipynb"
        papermill.execute_notebook(
            str(TEMPLATE),
            str(executed),
            parameters=values,
            kernel_name="python3",
            execution_timeout=timeout,
            progress_bar=False,
            cwd=work,
        )
        notebook = nbformat.read(executed, as_version=4)
        exporter = HTMLExporter(exclude_input=True, exclude_input_prompt=True)
        exporter.exclude_output_prompt = True
        html, _ = exporter.from_notebook_node(
            notebook, resources={"metadata": {"name": values["title"]}}
        )
        handle, temporary = tempfile.mkstemp(suffix=".html", dir=output.parent)
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(html)
        os.chmod(temporary, 0o644)
        os.replace(temporary, output)
        if keep_notebook:
            nbformat.write(notebook, output.with_suffix(".ipynb"))
    return output


def _main(argv: list[str]) -> int:
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        print("parameters and defaults:")
        for name, value in DEFAULTS.items():
            print(f"  {name} = {value!r}")
        return 0
    output, pairs = argv[0], argv[1:]
    parameters: dict[str, Any] = {}
    for pair in pairs:
        if "=" not in pair:
            raise SystemExit(f"expected name=value, got {pair!r}")
        name, value = pair.split("=", 1)
        parameters[name] = value
    for name in ("n_spans", "seed"):
        if name in parameters:
            parameters[name] = int(parameters[name])
    for name in ("bridge_damping", "vehicle_damping"):
        if name in parameters:
            parameters[name] = float(parameters[name])
    if "quick" in parameters:
        parameters["quick"] = parameters["quick"].lower() in ("1", "true", "yes")
    print(make_report(output, **parameters))
    return 0


if __name__ == "__main__":
    sys.exit(_main(sys.argv[1:]))
