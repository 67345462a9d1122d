"""A report's results as data: ``NAME.json`` with ``{"results": [...]}`` and ``NAME.csv`` beside.

One row per speed, place, effect (and face, for the shear at a support) and direction, in SI
(m, N m, N, m/s), with the keys of :data:`vbi_lib.reports.analysis.ROW_KEYS`:

``speed_m_s``, ``section_m``
    The speed and the station from the first support.
``effect``, ``direction``, ``face``, ``place``
    ``displacement`` (positive up), ``moment`` (sagging positive) or ``shear``
    (``dM/dx``, ``x`` from the first support); ``forward`` or ``backward``; ``left`` or
    ``right`` for the shear at a support (else empty); the place's name.
``daf``, ``static``, ``dynamic``, ``sense``
    The DAF, and the static and dynamic extremes it divides, in the sense (``max`` or
    ``min``) in which the static extreme is the larger (``null`` where it is zero).
``lost_contact``, ``flight_fraction``, ``valid``
    Whether a bilateral contact became tensile (then ``valid`` is false: outside the model's
    validity), and the fraction of the time a tyre was off the road.
``rear_axle_spacing_m``
    The design truck's rear axle spacing of the row (its governing one), else ``null``.

Beside the rows the JSON holds ``units``, ``signs``, the vbi version, the model, the vehicle,
the notes and warnings, and the flights of the tyres.  Both files are written beside their
final names and renamed, so a reader never sees half a file.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from ..vehicles import as_system
from .analysis import ROW_KEYS, ReportAnalysis

__all__ = ["UNITS", "results_document", "write_results"]

#: The unit of every number in the rows.
UNITS = {
    "speed_m_s": "m/s",
    "section_m": "m",
    "rear_axle_spacing_m": "m",
    "displacement": "m",
    "moment": "N m",
    "shear": "N",
    "flight_fraction": "fraction of the time on the bridge",
}
SIGNS = {
    "displacement": "positive up (a deflection is negative)",
    "moment": "sagging positive",
    "shear": "dM/dx, x from the first support; at a support, the face named in 'face'",
}


def _plain(value: Any) -> Any:
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if value is None or isinstance(value, bool | int | float | str):
        return value
    return str(value)


def results_document(analysis: ReportAnalysis) -> dict[str, Any]:
    """The JSON document of a report's results (plain types; NaN as ``None``)."""
    import vbi_lib

    inputs = analysis.inputs
    flights = analysis.flights.table.to_dict(orient="records")
    return _plain({
        "results": analysis.results(),
        "units": UNITS,
        "signs": SIGNS,
        "columns": list(ROW_KEYS),
        "vbi_version": vbi_lib.__version__,
        "title": inputs.parameters.title,
        "model": inputs.model,
        "modes": inputs.modes,
        "vehicle": as_system(inputs.vehicle).name,
        "spans_m": list(inputs.bridge.spans),
        "flights": flights,
        "notes": list(inputs.notes) + list(analysis.notes),
        "warnings": list(inputs.warnings),
        "parameters": inputs.parameters.raw,
    })  # fmt: skip


def _write(path: Path, text: str) -> None:
    handle, partial = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as out:
            out.write(text)
        os.chmod(partial, 0o644)
        os.replace(partial, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(partial)
        raise


def write_results(analysis: ReportAnalysis, path: str | Path) -> tuple[Path, Path]:
    """Write ``path`` (``NAME.json``) and ``NAME.csv`` beside it; return both paths."""
    path = Path(path)
    if path.suffix.lower() != ".json":
        path = path.with_suffix(".json")
    document = results_document(analysis)
    _write(path, json.dumps(document, indent=1, allow_nan=False) + "\n")
    table = analysis.sections.rows[list(ROW_KEYS)]
    csv = path.with_suffix(".csv")
    _write(csv, table.to_csv(index=False, float_format="%.10g"))
    return path, csv
