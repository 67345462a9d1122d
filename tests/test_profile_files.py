"""Reading measured profiles: two-column text files and ERD v2 files.

References: the layout and sample counts stated in ../shared/data/profiles/README.md, the
header of the published ERD file, and small files written in each test whose content is known.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.profile_files import ProfileFileError


# ---------------------------------------------------------------------------- reading text
def test_reads_the_i76_deck_profiles_in_inches(shared_data: Path) -> None:
    for k in range(2, 7):
        road = vbi.read_profile(shared_data / "profiles" / f"i76-span{k}.csv", unit="in")
        assert road.x.size == 1707  # README: 1707 points at 0.98425 in
        # stations are printed to 5 significant digits, so steps vary by +-0.005 in
        assert road.length / 1706 == pytest.approx(0.98425 * u.inch, rel=1e-4)
        assert road.name == f"i76-span{k}"


def test_reads_the_sorel_profile_in_metres(shared_data: Path) -> None:
    road = vbi.read_profile(shared_data / "profiles" / "sorel-profile-1.txt", unit="m")
    assert road.spacing == pytest.approx(0.25)
    assert road.length == pytest.approx(544.0)
    assert 500 < road.elevation.mean() < 700  # absolute elevations, ~583 m


def test_units_by_name_or_factor_and_separate_elevation_unit(tmp_path: Path) -> None:
    path = tmp_path / "p.txt"
    path.write_text("# station elevation\n0\t1\n\n10 ; 2\n20 3\n")
    feet = vbi.read_profile(path, unit="ft", elevation_unit=u.mm)
    np.testing.assert_allclose(feet.x, [0, 10 * u.ft, 20 * u.ft])
    np.testing.assert_allclose(feet.elevation, [1e-3, 2e-3, 3e-3])
    same = vbi.read_profile(path, unit=u.ft, elevation_unit="mm")
    np.testing.assert_allclose(same.x, feet.x)
    header = tmp_path / "h.csv"
    header.write_text("distance,elevation\n0,0\n1,0.01,\n")
    assert vbi.read_profile(header, unit="m", skip_rows=1).x.size == 2
    bom = tmp_path / "bom.csv"
    bom.write_bytes(b"\xef\xbb\xbf0,0\r\n10,0.2\r\n")
    np.testing.assert_allclose(vbi.read_profile(bom, unit="m").elevation, [0.0, 0.2])
    with pytest.raises(ValueError, match="unit='furlong'"):
        vbi.read_profile(path, unit="furlong")


@pytest.mark.parametrize(
    ("text", "line", "problem"),
    [
        ("0,0\n1\n2,0\n", 2, "expected 2 columns"),
        ("0,0\n1,0,5\n", 2, "found 3"),
        ("0,0\n1,abc\n", 2, "elevation 'abc' is not a number"),
        ("0,0\nx,1\n", 2, "station 'x' is not a number"),
        ("0,0\n1,0\n0.5,0\n", 3, "does not increase"),
        ("0,0\n1,0.5\n1,0\n", 3, "does not increase"),
        ("0,0\n1,nan\n", 2, "not a finite number"),
        ("0,0\n1,,0\n", 2, "expected 2 columns"),
    ],
)
def test_bad_text_files_name_the_file_line_and_fault(
    tmp_path: Path, text: str, line: int, problem: str
) -> None:
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ProfileFileError, match=problem) as info:
        vbi.read_profile(path, unit="in")
    assert f"bad.csv, line {line}:" in str(info.value)
    assert info.value.line == line


@pytest.mark.parametrize("text", ["", "# only a comment\n", "0,0\n"])
def test_too_few_samples(tmp_path: Path, text: str) -> None:
    path = tmp_path / "short.csv"
    path.write_text(text)
    with pytest.raises(ProfileFileError, match="short.csv: holds .* a profile needs at least two"):
        vbi.read_profile(path, unit="m")


def test_missing_file_is_named(tmp_path: Path) -> None:
    with pytest.raises(ProfileFileError, match="nothere.csv: cannot be read"):
        vbi.read_profile(tmp_path / "nothere.csv", unit="m")


# ---------------------------------------------------------------------------- reading ERD
def test_reads_the_two_channel_erd_file(shared_data: Path) -> None:
    erd = vbi.read_erd(shared_data / "profiles" / "basic-2channel.erd")
    assert len(erd) == 2
    assert erd.interval == pytest.approx(0.2069167 * u.ft)
    assert erd.header["IRILWP"] == "183" and erd.header["IRIRWP"] == "163"
    assert erd.title == "Track Run E1"
    for channel in erd.channels:
        assert channel.x.size == 25544
        assert channel.length == pytest.approx(25543 * 0.2069167 * u.ft)
    assert [c.name for c in erd] == ["LElev.", "RElev."]
    # first data row "-0.000037 -0.000050" in feet
    assert erd[0].elevation[0] == pytest.approx(-0.000037 * u.ft)
    assert erd[1].elevation[0] == pytest.approx(-0.000050 * u.ft)


def _erd(counts: str = "2, 3, -1, 1, 5, 0.25, -1,", header: str = None, rows: str = None) -> str:
    header = (
        "TITLE   t\nSHORTNAML       R       \nUNITSNAMmm      mm      \nXUNITS  m\nEND\n"
        if header is None
        else header
    )
    rows = "0 0\n1 2\n3 4\n" if rows is None else rows
    return f"ERDFILEV2.00\n{counts}\n{header}{rows}"


def test_a_small_erd_file_reads_exactly(tmp_path: Path) -> None:
    path = tmp_path / "ok.erd"
    path.write_text(_erd())
    erd = vbi.read_erd(path)
    np.testing.assert_allclose(erd[0].x, [0, 0.25, 0.5])
    np.testing.assert_allclose(erd[1].elevation, [0, 2e-3, 4e-3])
    assert [c.name for c in erd] == ["L", "R"]


@pytest.mark.parametrize(
    ("text", "line", "problem"),
    [
        ("ERDFILEV1.00\n2, 3\n", 1, "not 'ERDFILEV2.00'"),
        (_erd(counts="2, 3, -1"), 2, "at least 6 comma-separated fields"),
        (_erd(counts="2, 3, -1, 1, 3, 0.25,"), 2, "storage code '3' is not 5"),
        (_erd(counts="2, 3, -1, 1, 5, 0,"), 2, "sample interval '0' must be > 0"),
        (_erd(counts="2, 1, -1, 1, 5, 0.25,"), 2, "number of samples '1' must be >= 2"),
        (_erd(header="TITLE   t\nUNITSNAMmm      mm\nXUNITS  m\n", rows=""), 5, "no 'END'"),
        (_erd(rows="0 0\n1 2\n"), 9, "only 2 data rows; the header declares 3"),
        (_erd(rows="0 0\n1 2\n3 4\n5 6\n"), 11, "more data rows than the 3"),
        (_erd(rows="0 0\n1\n3 4\n"), 9, "expected 2 values"),
        (_erd(rows="0 0\n1 q\n3 4\n"), 9, "channel 2 value 'q' is not a number"),
        (
            _erd(header="SHORTNAML       R\nUNITSNAMmm      yd\nXUNITS  m\nEND\n"),
            4,
            "UNITSNAM unit 'yd' is not known",
        ),
        (_erd(header="UNITSNAMmm      mm\nEND\n"), 4, "no XUNITS"),
    ],
)
def test_bad_erd_files_name_the_file_line_and_fault(
    tmp_path: Path, text: str, line: int, problem: str
) -> None:
    path = tmp_path / "bad.erd"
    path.write_text(text)
    with pytest.raises(ProfileFileError, match=problem) as info:
        vbi.read_erd(path)
    assert f"bad.erd, line {line}:" in str(info.value)
