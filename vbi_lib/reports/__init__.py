"""Reports an engineer can file: a parameter file in; an HTML report, its PDF and the results as
data (JSON and CSV) out.

A parameter file (YAML) names the bridge, the vehicle, the road, the speeds and what to
report, every dimensional value as one number and one unit::

    title: Three spans under the HS20
    bridge: {spans: [90 ft, 120 ft, 90 ft], EI: 5.3e11 kip*in**2, mass_per_length: 11 kip/ft}
    vehicle: {type: hs20, rear_axle_spacing: [14 ft, 30 ft]}
    profile: {iso_class: B, seed: 7}
    speeds: [35 mph, 55 mph, 70 mph]

The study's own case (one sprung mass on one span or two equal spans, ``bridge: {span: ...,
k_mid: ..., first_frequency: ...}``, ``vehicle: {mass: ..., frequency: ...}``) runs on its
one-coordinate model; every other on the modal model.  The report gives the DAF of each
effect (displacement, moment, shear on both faces of a support) at each place (by default
the midspans and the interior supports), in each direction, against the design codes.

Every route takes the same file:

* ``vbi-report PARAMS.yaml [MORE.yaml ...] --output-dir DIR`` (console script);
* ``python -m vbi_lib.reports PARAMS.yaml --output-dir DIR``;
* ``papermill vbi_lib/templates/bridge_report.ipynb out.ipynb -f PARAMS.yaml``;
* :func:`write_reports` from Python.

The package's modules, one job each: :mod:`.parameter_file` (reads a parameter file under
caps), :mod:`.values` and :mod:`.parameters` (check it, value by value and key by key),
:mod:`.inputs` (the bridge, vehicle and road, with the approaches and the places) and
:mod:`.deck` (a measured deck, checked for unit slips), :mod:`.analysis` (the crossings, the
DAF of each place and effect, the sweep) with :mod:`.along` (envelopes, flights),
:mod:`.road` (roughness, positions, the study's span DAF) and :mod:`.codes` (the design
codes), :mod:`.results_file` (the results as JSON and CSV), :mod:`.render`,
:mod:`.figures` and :mod:`.appendix` (the HTML, escaped), :mod:`.running` (the kernel, the
files, clean-up on failure and signals), :mod:`.kernel` and :mod:`.printing` (the kernel and
chromium), :mod:`.cli` (the command line) and :mod:`.legacy` (the old flat ``name=value``
parameters).
"""

from __future__ import annotations

from .analysis import ReportAnalysis, analyse
from .inputs import ReportInputs, prepare
from .legacy import DEFAULTS, make_report, read_inputs
from .parameter_file import read_parameter_file
from .parameters import (
    SCHEMA,
    ParameterError,
    ReportParameters,
    notebook_parameters,
    read_parameters,
)
from .results_file import results_document, write_results
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
    "read_parameter_file",
    "read_parameters",
    "results_document",
    "write_reports",
    "write_results",
]
