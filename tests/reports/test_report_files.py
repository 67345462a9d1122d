"""Reading a parameter file: only a small regular file, its aliases expanded under a cap.

Each refusal goes through the command line (``cli.main``): status 2, one line naming the
file, nothing written, nothing left in the temporary folder, and within a second.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest
from test_report_cli import GOOD, refused

from vbi_lib.reports import cli
from vbi_lib.reports.parameter_file import MAX_BYTES, MAX_VALUES, read_parameter_file

#: The "billion laughs": nine levels of ten aliases, 10^9 strings, in some 700 bytes.
BOMB = "\n".join(
    ['a0: &a0 "lol"']
    + [f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 10)}]" for i in range(1, 10)]
    + ["bridge: *a9"]
)


@pytest.fixture
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    (tmp_path / "tmp").mkdir()
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))
    monkeypatch.setattr("tempfile.tempdir", None)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def quickly_refused(argv: list[str], capsys: pytest.CaptureFixture, folder: Path) -> str:
    start = time.perf_counter()
    err = refused(argv, capsys, folder)
    assert time.perf_counter() - start < 1.0, "the refusal took more than a second"
    return err


def test_an_alias_bomb_is_refused_within_a_second(folder: Path, capsys) -> None:
    (folder / "bomb.yaml").write_text(BOMB)
    assert len(BOMB) < 1000
    err = quickly_refused(["bomb.yaml", "-o", "out"], capsys, folder)
    assert f"bomb.yaml: expands to more than {MAX_VALUES:,} values through its aliases" in err


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("a: &x [1, *x]\n", "refers to itself through an alias"),
        ("a: " + "[" * 30 + "]" * 30 + "\n", "nests lists and mappings more than 20 deep"),
        ("a: " + "[" * 3000 + "]" * 3000 + "\n", "nests lists and mappings more than 20 deep"),
        ("[1, 2]: x\n", "a key must be a name, not a list or mapping"),
    ],
)
def test_self_reference_and_depth_are_refused(
    folder: Path, capsys, text: str, message: str
) -> None:
    (folder / "odd.yaml").write_text(text)
    assert message in quickly_refused(["odd.yaml", "-o", "out"], capsys, folder)


def test_a_large_file_is_refused_before_it_is_parsed(folder: Path, capsys) -> None:
    (folder / "big.yaml").write_text(GOOD + "# " + "x" * (MAX_BYTES + 10) + "\n")
    err = quickly_refused(["big.yaml", "-o", "out"], capsys, folder)
    assert "big.yaml: is " in err and "bytes, more than the 256 KiB a parameter file" in err


def test_special_files_are_refused_by_name(folder: Path, capsys) -> None:
    # the words are the library's safe reader's (vbi_lib._files), after the file's name
    err = quickly_refused(["/dev/zero", "-o", "out"], capsys, folder)
    assert "/dev/zero: is a character device (" in err and "not a regular file" in err
    os.mkfifo(folder / "pipe.yaml")  # nobody writes to it: reading would block forever
    err = quickly_refused(["pipe.yaml", "-o", "out"], capsys, folder)
    assert "pipe.yaml: is a named pipe (FIFO" in err and "not a regular file" in err
    (folder / "dir.yaml").mkdir()
    err = quickly_refused(["dir.yaml", "-o", "out"], capsys, folder)
    assert "dir.yaml: is a directory, not a regular file" in err
    err = quickly_refused(["missing.yaml", "-o", "out"], capsys, folder)
    assert "missing.yaml: cannot be read (No such file or directory)" in err


def test_small_aliases_and_an_empty_file_are_read(tmp_path: Path) -> None:
    (tmp_path / "ok.yaml").write_text("a: &x [1 ft, 2 ft]\nb: *x\nc: yes\nd: true\n")
    values, data = read_parameter_file(tmp_path / "ok.yaml")
    assert values == {"a": ["1 ft", "2 ft"], "b": ["1 ft", "2 ft"], "c": "yes", "d": True}
    assert data.startswith(b"a: &x")
    (tmp_path / "empty.yaml").write_text("")
    assert read_parameter_file(tmp_path / "empty.yaml")[0] == {}
    empty = str(tmp_path / "empty.yaml")
    assert cli.main([empty, "-o", str(tmp_path / "out")]) == 2  # nothing in it: refused
