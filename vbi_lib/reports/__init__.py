"""Reports an engineer can file: a parameter file in, an HTML report and its PDF out.

A parameter file (YAML) names the bridge, the truck, the road and the speeds, every
dimensional value as one number and one unit::

    title: I-76 span 3
    bridge: {span: 140 ft, k_mid: 222278 lbf/in, first_frequency: 2.08 Hz}
    vehicle: {mass: 200 lbf*s**2/in, frequency: 2.5 Hz, damping_ratio: 0.10}
    profile: {file: deck.csv, length_unit: inch}
    speeds: [30 mph, 70 mph]

Every route takes the same file:

* ``vbi-report PARAMS.yaml [MORE.yaml ...] --output-dir DIR`` (console script);
* ``python -m vbi_lib.reports PARAMS.yaml --output-dir DIR``;
* ``papermill vbi_lib/templates/bridge_report.ipynb out.ipynb -f PARAMS.yaml``;
* :func:`write_reports` from Python.

The package's modules, one job each: :mod:`.parameters` (checks the file, key by key),
:mod:`.inputs` (the bridge, truck and road, with the approach), :mod:`.analysis` (the
crossings), :mod:`.render` (HTML text and tables, escaped), :mod:`.running` (the kernel, the
HTML and PDF files, clean-up on failure and signals), :mod:`.cli` (the command line) and
:mod:`.legacy` (the old flat ``name=value`` parameters).
"""

from __future__ import annotations

from .analysis import ReportAnalysis, analyse
from .inputs import ReportInputs, prepare
from .legacy import DEFAULTS, make_report, read_inputs
from .parameters import (
    SCHEMA,
    ParameterError,
    ReportParameters,
    notebook_parameters,
    read_parameters,
)
from .running import (
    TEMPLATE,
    OutputError,
    ReportFailed,
    ReportFiles,
    ReportJob,
    load_job,
    write_reports,
)

__all__ = [
    "DEFAULTS",
    "SCHEMA",
    "TEMPLATE",
    "OutputError",
    "ParameterError",
    "ReportAnalysis",
    "ReportFailed",
    "ReportFiles",
    "ReportInputs",
    "ReportJob",
    "ReportParameters",
    "analyse",
    "load_job",
    "make_report",
    "notebook_parameters",
    "prepare",
    "read_inputs",
    "read_parameters",
    "write_reports",
]
