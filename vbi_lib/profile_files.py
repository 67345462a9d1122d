"""Reading measured road profiles from files: two-column text and the ERD v2 format.

Two readers turn a profiler's output into a :class:`vbi_lib.Profile` (stations and elevations
in metres):

* :func:`read_profile`: a two-column text file (station, elevation) in a unit the caller names,
  such as the study's I-76 deck profiles (inches) or a survey in metres;
* :func:`read_erd`: the ERD v2 text layout written by inertial profilers, ProVAL and the
  RoadRuf tools (UMTRI, Sayers and Karamihas), with one profile per channel (wheel path).

Both check the whole file before making a profile: a malformed file raises
:class:`ProfileFileError` (a ``ValueError``) naming the file, the line and the fault, and
nothing is half read.  Both open only regular files of at most ``max_bytes``
(:data:`vbi_lib._files.MAX_FILE_BYTES`, 100 MiB, by default), in UTF-8 or UTF-16
(:mod:`vbi_lib._files`), and say what else they were given: a directory, a device, a named
pipe, a socket, another encoding.  A profile read is checked for plausibility
(:mod:`vbi_lib.road_checks`): a road feature higher, or a slope steeper, than a road has, or
a roughness beyond ISO 8608's classes, is warned about with the likely unit slip (a deck in
millimetres read as metres), and every crossing on it says so in its ``notes``.  No
equation of the study is involved; the sampling the study asks of a profile is its equation
(32), :func:`vbi_lib.profiles.max_sample_spacing`.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import _validation as check
from ._files import MAX_FILE_BYTES, FileReadError, read_text
from .profiles import Profile
from .ranges import RANGES
from .road_checks import warn_implausible

#: Length units accepted by name by the readers [m per unit].
LENGTH_UNITS = {
    "m": 1.0,
    "mm": 1e-3,
    "cm": 1e-2,
    "km": 1e3,
    "in": 0.0254,
    "inch": 0.0254,
    "inches": 0.0254,
    "ft": 0.3048,
    "feet": 0.3048,
    "foot": 0.3048,
    "mi": 1609.344,
}


class ProfileFileError(ValueError):
    """A profile file that cannot be read; the message names the file, the line and the fault."""

    def __init__(self, path: str | Path, line: int | None, problem: str) -> None:
        shown = str(path) if str(path).isprintable() else repr(str(path))  # a zero character
        where = shown if line is None else f"{shown}, line {line}"
        super().__init__(f"{where}: {problem}")
        self.path = str(path)
        self.line = line
        self.problem = problem


def _path(path: object) -> Path:
    """``path`` as a :class:`~pathlib.Path` (text or a path-like), else ``TypeError``."""
    if not isinstance(path, str | Path) and not hasattr(path, "__fspath__"):
        raise TypeError(f"path={path!r} must be a file path (text or pathlib.Path)")
    return Path(path)


def _length_unit(name: str, unit: float | str) -> float:
    """Metres per unit from a factor (``vbi_lib.units.inch``) or a name (``"in"``)."""
    if isinstance(unit, str):
        key = unit.strip().lower()
        if key not in LENGTH_UNITS:
            raise ValueError(
                f"{name}={unit!r} is not a known length unit; use one of "
                f"{', '.join(sorted(LENGTH_UNITS))} or a factor in metres (vbi_lib.units.inch)"
            )
        return LENGTH_UNITS[key]
    return check.positive(name, unit)


_SPLIT = re.compile(r"\s*[,;\t]\s*|\s+")
#: Separators other than the comma (a file with decimal commas separates its columns so).
_SPLIT_NO_COMMA = re.compile(r"\s*[;\t]\s*|\s+")
#: A line of two whole numbers joined by one comma: ``1,5`` is 1 and 5, or one 1.5.
_COMMA_PAIR = re.compile(r"[+-]?\d+,\d+")


def _text(path: Path, max_bytes: int) -> str:
    """The file's text, through the safe reader; its refusal as a :class:`ProfileFileError`."""
    try:
        return read_text(path, "path", max_bytes)
    except FileReadError as exc:
        raise ProfileFileError(path, None, exc.problem) from None


def _decimal(lines: list[tuple[int, str]], decimal: str | None, path: Path) -> str:
    """The decimal mark of a two-column file: ``decimal`` if given, else found from the text.

    A file without a decimal point whose every line splits on semicolons, tabs or spaces
    into two cells, some with a comma, has decimal commas (``0,5;1,25``).  A file whose every
    line is two whole numbers joined by a comma (``1,5``) is ambiguous (one column of decimal
    commas, or two columns of whole numbers): it is refused, asking for ``decimal``.
    """
    if decimal is not None:
        if decimal not in (".", ","):
            raise ValueError(
                f"decimal={decimal!r} must be '.' or ',' (or None: found from the file)"
            )
        return decimal
    if len(lines) < 2 or any("." in line for _, line in lines):
        return "."
    cells = [_SPLIT_NO_COMMA.split(line) for _, line in lines]
    if all(len(c) == 2 for c in cells) and any("," in cell for c in cells for cell in c):
        return ","
    if all(_COMMA_PAIR.fullmatch(line) for _, line in lines):
        number, first = lines[0]
        raise ProfileFileError(
            path,
            number,
            f"{first!r}: every line is two whole numbers joined by a comma and the file has no "
            "decimal point, which is what one column of numbers with decimal commas looks like "
            f"({first.replace(',', '.')} written {first}); a profile needs two columns, station "
            "and elevation: write decimal points, or separate decimal-comma columns with ';', "
            "a tab or spaces (then decimal=',' reads them), or pass decimal='.' if the comma "
            "separates two columns of whole numbers",
        )
    return "."


def _number(path: Path, line: int, cell: str, what: str) -> float:
    try:
        value = float(cell)
    except ValueError:
        raise ProfileFileError(path, line, f"{what} {cell!r} is not a number") from None
    if not math.isfinite(value):
        raise ProfileFileError(path, line, f"{what} {cell!r} is not a finite number")
    return value


def read_profile(
    path: str | Path,
    unit: float | str,
    elevation_unit: float | str | None = None,
    skip_rows: int = 0,
    name: str | None = None,
    *,
    decimal: str | None = None,
    max_bytes: int = MAX_FILE_BYTES,
) -> Profile:
    """Read a measured profile from a two-column text file: station, elevation.

    Cells are separated by commas, semicolons, tabs or spaces; blank lines and lines starting
    with ``#`` are ignored.  Stations must increase strictly.  The whole file is checked
    before a :class:`Profile` is made, so a bad file raises :class:`ProfileFileError` (a
    ``ValueError``) naming the file, the line and the fault, and nothing is half read.
    Decimal commas are read when the columns are separated otherwise (``0,5;1,25``); a file
    of lines such as ``1,5`` (one column with decimal commas, or two of whole numbers) is
    refused unless ``decimal`` says which.  Only a regular file of at most ``max_bytes`` in
    UTF-8 or UTF-16 is read (:func:`vbi_lib._files.read_text`).  The profile read is checked
    for plausibility (:func:`vbi_lib.road_checks.road_notes`) and warned about, naming the
    likely unit slip.

    Parameters
    ----------
    path
        The file.
    unit
        Length unit of the stations: a factor in metres (``vbi_lib.units.inch``) or a name
        (``"in"``, ``"ft"``, ``"m"``, ``"mm"``, ...).  The study's I-76 files are in inches.
    elevation_unit
        Unit of the elevations if it differs from ``unit``.
    skip_rows
        Lines to skip at the top (a header row).
    name
        Name of the profile; the file's stem by default.
    decimal
        The decimal mark, ``"."`` or ``","``; ``None`` (default) finds it from the file.
    max_bytes
        The largest file read [bytes] (:data:`vbi_lib._files.MAX_FILE_BYTES`, 100 MiB).

    Raises
    ------
    TypeError
        ``path`` that is not a path, ``skip_rows`` or ``max_bytes`` that is not an int,
        ``unit`` that is neither a name nor a number.
    ProfileFileError
        A file that cannot be read or is malformed (a ``ValueError``): missing, a directory,
        device, named pipe or socket, larger than ``max_bytes``, not UTF-8 or UTF-16 text,
        ambiguous decimal commas, a bad line.
    ValueError
        An unknown unit name, a factor not > 0, ``skip_rows < 0``, a bad ``decimal``.

    Warns
    -----
    OutsideValidityWarning
        A profile whose unevenness, slope or roughness is outside what roads have
        (:func:`vbi_lib.road_checks.road_notes`), with the likely unit slip.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (folder / "deck.csv").write_text("0,0\\n1,0.5\\n2,0.25\\n")
    >>> p = read_profile(folder / "deck.csv", unit="in")
    >>> p.x.tolist(), p.elevation.tolist()
    ([0.0, 0.0254, 0.0508], [0.0, 0.0127, 0.00635])
    >>> _ = (folder / "bad.csv").write_text("0,0\\n1,x\\n")
    >>> read_profile(folder / "bad.csv", unit="in")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    vbi_lib.profile_files.ProfileFileError: .../bad.csv, line 2: elevation 'x' is not a number
    """
    path = _path(path)
    scale_x = _length_unit("unit", unit)
    scale_z = scale_x if elevation_unit is None else _length_unit("elevation_unit", elevation_unit)
    skip_rows = check.integer("skip_rows", skip_rows, low=0)
    if name is not None and not isinstance(name, str):
        raise TypeError(f"name={name!r} must be text or None, not {type(name).__name__}")
    text = _text(path, max_bytes)
    data = [(number, raw.strip()) for number, raw in enumerate(text.splitlines(), start=1)]
    data = [(n, line) for n, line in data if n > skip_rows and line and not line.startswith("#")]
    comma = _decimal(data, decimal, path) == ","
    stations: list[float] = []
    heights: list[float] = []
    lines: list[int] = []
    for number, line in data:
        cells = _SPLIT_NO_COMMA.split(line.replace(",", ".")) if comma else _SPLIT.split(line)
        if cells and cells[-1] == "":
            cells.pop()  # a trailing separator
        if len(cells) != 2:
            raise ProfileFileError(
                path, number, f"expected 2 columns (station, elevation), found {len(cells)}"
            )
        x = _number(path, number, cells[0], "station")
        z = _number(path, number, cells[1], "elevation")
        if stations and x <= stations[-1]:
            raise ProfileFileError(
                path,
                number,
                f"station {cells[0]} does not increase (line {lines[-1]} has {stations[-1]:g}); "
                "stations must increase strictly",
            )
        stations.append(x)
        heights.append(z)
        lines.append(number)
    if len(stations) < 2:
        raise ProfileFileError(
            path, None, f"holds {len(stations)} sample(s); a profile needs at least two"
        )
    profile = Profile(
        np.asarray(stations) * scale_x,
        np.asarray(heights) * scale_z,
        name=path.stem if name is None else name,
    )
    warn_implausible(profile, reader="read_profile")
    return profile


@dataclass(frozen=True, eq=False)
class ErdFile:
    """A profile file in the ERD v2 text format: one :class:`Profile` per channel.

    Attributes
    ----------
    channels
        One profile per channel (stations from 0, SI units), named by ``SHORTNAM``.
    header
        Every keyword line as ``{keyword: value text}`` (e.g. ``header["IRILWP"]``).
    interval
        Sample interval [m].
    path
        The file read.
    """

    channels: tuple[Profile, ...]
    header: dict[str, str]
    interval: float
    path: str

    @property
    def title(self) -> str:
        """The ``TITLE`` keyword (empty when absent)."""
        return self.header.get("TITLE", "")

    def __len__(self) -> int:
        return len(self.channels)

    def __getitem__(self, index: int) -> Profile:
        return self.channels[index]

    def __repr__(self) -> str:
        names = ", ".join(repr(c.name) for c in self.channels)
        first = self.channels[0]
        return (
            f"ErdFile({self.title!r}: {len(self.channels)} channel(s) {names}, "
            f"{first.x.size} samples every {self.interval * 1e3:.1f} mm over {first.length:.1f} m)"
        )


def read_erd(path: str | Path, *, max_bytes: int = MAX_FILE_BYTES) -> ErdFile:
    """Read a profile file in the ERD v2 text format (profilers, ProVAL, the RoadRuf tools).

    Layout: line 1 ``ERDFILEV2.00``; line 2, comma separated, the number of channels, the
    number of samples, two fields not used here, the storage code (5: text rows) and the
    sample interval (in ``XUNITS``); keyword lines (8-character keyword, then the value;
    ``UNITSNAM`` and ``SHORTNAM`` hold one 8-character field per channel) up to ``END``; then
    one row per sample with one elevation per channel.  Distance units ``XUNITS`` and
    elevation units ``UNITSNAM`` are converted to metres (m, mm, cm, in, ft).

    Anything else (another version, a binary layout, a missing ``END``, a wrong number of
    rows or columns, a non-numeric cell, an unknown unit) raises :class:`ProfileFileError`
    naming the file and the line; nothing is half read.  Only a regular file of at most
    ``max_bytes`` (:data:`vbi_lib._files.MAX_FILE_BYTES`, 100 MiB, by default) in UTF-8 or
    UTF-16 is read.  Each channel is checked for plausibility as :func:`read_profile`'s
    profile is (a warning naming the likely unit slip).

    Returns
    -------
    ErdFile
        ``channels`` (one :class:`Profile` per wheel path), ``header`` and ``interval`` [m].

    Examples
    --------
    >>> import tempfile, pathlib
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "run.erd"
    >>> _ = f.write_text(
    ...     "ERDFILEV2.00\\n1, 3, -1, 1, 5, 0.25, -1,\\nTITLE   demo\\nSHORTNAMLeft\\n"
    ...     "UNITSNAMmm\\nXUNITS  m\\nEND\\n0.0\\n1.5\\n-0.5\\n"
    ... )
    >>> erd = read_erd(f)
    >>> erd
    ErdFile('demo': 1 channel(s) 'Left', 3 samples every 250.0 mm over 0.5 m)
    >>> erd[0].elevation.tolist()
    [0.0, 0.0015, -0.0005]
    """
    path = _path(path)
    try:
        lines = read_text(path, "path", max_bytes).splitlines()
    except FileReadError as exc:
        problem = exc.problem
        if "not a text file" in exc.problem:
            problem += " (binary ERD layouts are not supported)"
        raise ProfileFileError(path, None, problem) from None
    if not lines or lines[0].strip()[:12] != "ERDFILEV2.00":
        first = lines[0].strip()[:20] if lines else ""
        raise ProfileFileError(path, 1, f"starts with {first!r}, not 'ERDFILEV2.00' (ERD v2)")
    if len(lines) < 2:
        raise ProfileFileError(path, 2, "the ERD counts line is missing")
    fields = [f for f in (c.strip() for c in lines[1].split(",")) if f]
    if len(fields) < 6:
        raise ProfileFileError(
            path, 2, f"expected at least 6 comma-separated fields, found {len(fields)}"
        )
    counts = [_number(path, 2, f, f"field {i + 1}") for i, f in enumerate(fields[:6])]
    n_channels, n_samples, storage, step = counts[0], counts[1], counts[4], counts[5]
    if n_channels != int(n_channels) or n_channels < 1:
        raise ProfileFileError(path, 2, f"number of channels {fields[0]!r} must be >= 1")
    if n_samples != int(n_samples) or n_samples < 2:
        raise ProfileFileError(path, 2, f"number of samples {fields[1]!r} must be >= 2")
    if storage != 5:
        raise ProfileFileError(
            path, 2, f"storage code {fields[4]!r} is not 5 (text rows); this layout is unknown"
        )
    if step <= 0:
        raise ProfileFileError(path, 2, f"sample interval {fields[5]!r} must be > 0")
    n_channels, n_samples = int(n_channels), int(n_samples)

    header: dict[str, str] = {}
    per_channel: dict[str, list[str]] = {}
    end = None
    for index in range(2, len(lines)):
        raw = lines[index].rstrip("\r\n")
        key = raw[:8].strip().upper()
        if key == "END":
            end = index
            break
        if not key:
            continue
        value = raw[8:]
        header[key] = value.strip()
        if key in ("UNITSNAM", "SHORTNAM"):
            # one 8-character field per channel: as many as the line holds, never the
            # declared count (a header may declare more channels than the file has)
            held = min(n_channels, math.ceil(len(value) / 8))
            fixed = [value[8 * i : 8 * i + 8].strip() for i in range(held)]
            per_channel[key] = fixed if fixed and all(fixed) else value.split()
    if end is None:
        raise ProfileFileError(path, len(lines), "no 'END' line closes the ERD header")

    def unit_of(text: str, line_key: str) -> float:
        factor = LENGTH_UNITS.get(text.strip().lower())
        if factor is None:
            raise ProfileFileError(
                path,
                _key_line(lines, line_key),
                f"{line_key} unit {text!r} is not known; use one of m, mm, cm, in, ft",
            )
        return factor

    if "XUNITS" not in header:
        raise ProfileFileError(path, end + 1, "the header has no XUNITS (distance unit)")
    scale_x = unit_of(header["XUNITS"].split()[0] if header["XUNITS"] else "", "XUNITS")
    units = per_channel.get("UNITSNAM")
    if units is None or len(units) < n_channels:
        raise ProfileFileError(
            path, end + 1, f"UNITSNAM must give an elevation unit for each of {n_channels} channels"
        )
    scales = [unit_of(units[i], "UNITSNAM") for i in range(n_channels)]
    names = per_channel.get("SHORTNAM", [])
    names = [names[i] if i < len(names) else f"channel {i + 1}" for i in range(n_channels)]
    interval = step * scale_x
    low, high = RANGES["spacing"].hard
    if not low <= interval <= high:
        raise ProfileFileError(
            path,
            2,
            f"sample interval {fields[5]} {header['XUNITS']} ({interval:.4g} m) must be "
            f"{RANGES['spacing'].hard_text()} ({RANGES['spacing'].reason})",
        )

    # rows as the file holds them: the declared count is compared, never allocated
    values: list[list[float]] = []
    row = 0
    for index in range(end + 1, len(lines)):
        line = lines[index].strip()
        if not line:
            continue
        number = index + 1
        if row == n_samples:
            raise ProfileFileError(
                path, number, f"more data rows than the {n_samples} samples the header declares"
            )
        cells = _SPLIT.split(line)
        if cells and cells[-1] == "":
            cells.pop()
        if len(cells) != n_channels:
            raise ProfileFileError(
                path, number, f"expected {n_channels} values (one per channel), found {len(cells)}"
            )
        values.append(
            [_number(path, number, cell, f"channel {j + 1} value") for j, cell in enumerate(cells)]
        )
        row += 1
    if row < n_samples:
        raise ProfileFileError(
            path, len(lines), f"only {row} data rows; the header declares {n_samples} samples"
        )
    data = np.array(values, dtype=float).reshape(n_samples, n_channels)
    x = interval * np.arange(n_samples)
    channels = tuple(Profile(x, data[:, j] * scales[j], name=names[j]) for j in range(n_channels))
    for channel in channels:
        warn_implausible(channel, reader="read_erd")
    return ErdFile(channels, header, interval, str(path))


def _key_line(lines: list[str], key: str) -> int:
    """1-based number of the header line holding ``key``."""
    for index, line in enumerate(lines):
        if line[:8].strip().upper() == key:
            return index + 1
    return 0


__all__ = ["LENGTH_UNITS", "ErdFile", "ProfileFileError", "read_erd", "read_profile"]
