"""The first report API's flat ``name=value`` parameters, kept for existing callers.

``read_inputs(span="100 ft", k_mid=..., speeds="30 mph, 45 mph")`` and
``make_report("report.html", **flat)`` map the flat names onto the nested parameters of
:mod:`vbi_lib.reports.parameters` (:func:`nested`) and go through the same strict checks: a
typo is refused, not read.  ``speeds`` may be a comma-separated text here (each item is then
one number and one unit).  New code should write a parameter file (YAML) or a nested mapping.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from .inputs import ReportInputs, prepare
from .parameters import DEFAULT_TITLE, ParameterError, read_parameters

__all__ = ["DEFAULTS", "make_report", "nested", "read_inputs"]

#: The flat parameters and their defaults ("" means not given).
DEFAULTS: dict[str, Any] = {
    "title": DEFAULT_TITLE,
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

#: Flat name -> (section, nested key).
_MAP = {
    "span": ("bridge", "span"),
    "n_spans": ("bridge", "n_spans"),
    "k_mid": ("bridge", "k_mid"),
    "EI": ("bridge", "EI"),
    "mass_per_length": ("bridge", "mass_per_length"),
    "first_frequency": ("bridge", "first_frequency"),
    "bridge_damping": ("bridge", "damping_ratio"),
    "vehicle_mass": ("vehicle", "mass"),
    "vehicle_frequency": ("vehicle", "frequency"),
    "vehicle_damping": ("vehicle", "damping_ratio"),
    "seed": ("profile", "seed"),
}


def nested(**flat: Any) -> dict[str, Any]:
    """The nested parameters of flat ``name=value`` ones (defaults from :data:`DEFAULTS`).

    With ``profile_path``, ``approach`` is the file's station of the first support
    (``profile.bridge_start``); without it, the length of the generated approach.

    >>> nested(span="40 m", k_mid="1e8 N/m", first_frequency="5 Hz")["bridge"]["span"]
    '40 m'
    """
    unknown = sorted(set(flat) - set(DEFAULTS))
    if unknown:
        from .parameters import _suggest

        raise ParameterError(unknown[0], flat[unknown[0]], _suggest(unknown[0], list(DEFAULTS)))
    p = {**DEFAULTS, **flat}
    values: dict[str, Any] = {"title": p["title"], "bridge": {}, "vehicle": {}, "profile": {}}
    for name, (section, key) in _MAP.items():
        if p[name] is None or (isinstance(p[name], str) and not p[name].strip()):
            continue
        values[section][key] = p[name]
    path = p["profile_path"]
    if not (isinstance(path, str) and not path.strip()):  # None is refused, not "not given"
        values["profile"].update(
            file=path, length_unit=p["profile_unit"], bridge_start=p["approach"]
        )
    else:
        values["profile"].update(iso_class=p["iso_class"], approach_length=p["approach"])
    speeds = p["speeds"]
    if isinstance(speeds, str):
        speeds = [item.strip() for item in speeds.split(",")]
    values["speeds"] = speeds
    values["quick"] = p["quick"]
    return values


def read_inputs(**flat: Any) -> ReportInputs:
    """Check flat parameters (:data:`DEFAULTS`) and build what a report runs on.

    Raises
    ------
    ParameterError
        Naming the nested key, its value and what is allowed.

    Examples
    --------
    >>> inputs = read_inputs(span="100 ft", k_mid="497527 lbf/in", first_frequency="3.99 Hz")
    >>> round(inputs.bridge.first_frequency_hz, 2), len(inputs.speeds)
    (3.99, 3)
    """
    return prepare(read_parameters(nested(**flat)))


def make_report(output: str | Path, *, timeout: float = 600.0, **flat: Any) -> Path:
    """Write the HTML report of flat parameters to ``output`` (an ``.html`` file; no PDF).

    Returns
    -------
    Path
        The HTML file.

    Raises
    ------
    ParameterError, OutputError, ReportFailed
        See :func:`vbi_lib.reports.running.write_reports`.
    """
    from .running import OutputError, ReportJob, write_reports

    output = Path(output)
    if output.suffix.lower() != ".html":
        raise OutputError(f"output={str(output)!r} must be an .html file")
    job = ReportJob.from_mapping(nested(**flat), name=output.stem)
    return write_reports([job], output.parent, pdf=False, timeout=timeout)[0].html
