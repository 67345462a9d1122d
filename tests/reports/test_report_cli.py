"""The command line: one message and status 2 for bad input, nothing left behind, ever.

Bad input is checked in-process through ``cli.main`` (fast); the routes that need a real
process (a good run, SIGTERM and SIGINT) run ``python -m vbi_lib.reports`` with a private
``TMPDIR``, so "nothing left in /tmp" is checked on a folder only that process uses.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import psutil
import pytest

from vbi_lib.reports import cli, running
from vbi_lib.reports.running import ReportFailed, ReportJob, write_reports

GOOD = """\
title: A 30 m bridge
bridge: {span: 30 m, EI: 2e10 N*m**2, mass_per_length: 8 t/m}
vehicle: {mass: 30 t, frequency: 3 Hz}
profile: {iso_class: B, seed: 3}
speeds: [50 km/h, 80 km/h]
quick: true
"""


BLOCK = """\
bridge:
  span: 30,5 m
  EI: 2e10 N*m**2
  mass_per_length: 8 t/m
vehicle: {mass: 30 t, frequency: 3 Hz}
speeds: [50 km/h]
"""


@pytest.fixture
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A folder with a good parameter file, the working directory, with a private TMPDIR."""
    (tmp_path / "good.yaml").write_text(GOOD)
    (tmp_path / "tmp").mkdir()
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))
    monkeypatch.setattr("tempfile.tempdir", None)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def refused(argv: list[str], capsys: pytest.CaptureFixture, folder: Path) -> str:
    """Run the command line; assert status 2, one line, no traceback, nothing written."""
    status = cli.main(argv)
    out, err = capsys.readouterr()
    assert status == 2, err
    assert out == "" and err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith("vbi-report: error: ")
    assert not (folder / "out").exists()
    assert list((folder / "tmp").iterdir()) == []
    return err


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (BLOCK, "bad.yaml: bridge.span='30,5 m' has a comma in its number"),
        (GOOD.replace("30 m,", "30,5 m,"), "bridge.5 m=None is not a known key: it looks like "
         "the rest of a number cut at a comma"),
        (GOOD.replace("[50 km/h, 80 km/h]", "[50; 80 km/h]"), "speeds[0]='50; 80 km/h' holds"),
        (GOOD.replace("[50 km/h, 80 km/h]", "[nan km/h]"), "speeds[0]='nan km/h' is not a finite"),
        (GOOD.replace("quick: true", "quick: 'true'"), "quick='true' must be a YAML boolean"),
        (GOOD.replace("quick: true", "quick: yes"), "quick='yes' must be a YAML boolean"),
        (GOOD.replace("quick: true", "quick: off"), "quick='off' must be a YAML boolean"),
        (GOOD.replace("seed: 3", "seed: '3'"), "profile.seed='3' must be a whole number"),
        (GOOD.replace("vehicle:", "vehicel:"), "vehicel={'mass'"),
        (GOOD + "title: again\n", "bad.yaml, line 7, column 1: not valid YAML (key 'title' is "
         "given twice)"),
        (GOOD.replace("speeds: [", "speeds: [[["), "bad.yaml, line 6"),
        ("- just\n- a list\n", "parameters must be a mapping"),
        (GOOD.replace("{iso_class: B, seed: 3}", "{file: deck.csv, length_unit: m}"),
         "profile.file='deck.csv' is not a file that exists"),
    ],
)  # fmt: skip
def test_bad_parameter_files_exit_2_with_one_message(
    text: str, message: str, folder: Path, capsys: pytest.CaptureFixture
) -> None:
    (folder / "bad.yaml").write_text(text)
    err = refused(["bad.yaml", "--output-dir", "out"], capsys, folder)
    assert message in err


def test_a_deck_much_shorter_than_the_bridge_exits_2(folder: Path, capsys) -> None:
    (folder / "deck.csv").write_text("\n".join(f"{i * 0.025},0" for i in range(800)))  # 20 m
    text = GOOD.replace("{iso_class: B, seed: 3}", "{file: deck.csv, length_unit: m}")
    (folder / "short.yaml").write_text(text)
    err = refused(["short.yaml", "--output-dir", "out"], capsys, folder)
    assert "profile.file='deck.csv' covers 19.98 m" in err


def test_the_output_path_is_checked_before_anything_runs(folder: Path, capsys) -> None:
    (folder / "out").write_text("a file")
    err = refused_file = cli.main(["good.yaml", "--output-dir", "out"])
    assert refused_file == 2
    err = capsys.readouterr().err
    assert "--output-dir='out' is a file; give a folder" in err
    (folder / "out").unlink()
    (folder / "out" / "good.html").mkdir(parents=True)
    assert cli.main(["good.yaml", "--output-dir", "out", "--no-pdf"]) == 2
    assert "good.html is a folder" in capsys.readouterr().err
    assert list((folder / "out").iterdir()) == [folder / "out" / "good.html"]
    assert list((folder / "tmp").iterdir()) == []


def test_two_files_of_one_name_and_the_old_form_are_refused(folder: Path, capsys) -> None:
    (folder / "sub").mkdir()
    (folder / "sub" / "good.yaml").write_text(GOOD)
    err = refused(["good.yaml", "sub/good.yaml", "--output-dir", "out"], capsys, folder)
    assert "two parameter files are named 'good'" in err
    err = refused(["report.html", "span=100 ft", "--output-dir", "out"], capsys, folder)
    assert "name=value parameters are replaced by a parameter file" in err


def test_missing_chromium_is_refused_before_running(folder: Path, capsys, monkeypatch) -> None:
    monkeypatch.setattr(running, "find_chromium", lambda: None)
    err = refused(["good.yaml", "--output-dir", "out"], capsys, folder)
    assert "apt-get install -y chromium" in err and "--no-pdf" in err


def test_a_report_that_fails_while_running_leaves_nothing(folder: Path, monkeypatch) -> None:
    broken = json.loads(running.TEMPLATE.read_text())
    broken["cells"].append(
        {"cell_type": "code", "id": "boom", "metadata": {}, "execution_count": None,
         "outputs": [], "source": ["if '30 m' in (title or ''):\n    raise RuntimeError('boom')"]}
    )  # fmt: skip
    (folder / "broken.ipynb").write_text(json.dumps(broken))
    monkeypatch.setattr(running, "TEMPLATE", folder / "broken.ipynb")
    starts = []
    monkeypatch.setattr(running.Kernel, "start", _counting(running.Kernel.start, starts))
    first = {
        "title": "first",
        "bridge": {"span": "30 m", "EI": "2e10 N*m**2", "mass_per_length": "8 t/m"},
        "vehicle": {"mass": "30 t", "frequency": "3 Hz"},
        "speeds": ["50 km/h"],
        "quick": True,
    }
    job = ReportJob.from_mapping(first, name="other")
    with pytest.raises(ReportFailed, match="good.yaml: RuntimeError: boom"):
        write_reports([job, "good.yaml"], folder / "out", pdf=False)
    assert len(starts) == 1  # both reports went through one kernel; the first one ran
    assert not (folder / "out").exists()
    assert list((folder / "tmp").iterdir()) == []


def _counting(method, calls: list):  # noqa: ANN001, ANN202
    def wrapper(self):  # noqa: ANN001, ANN202
        calls.append(self)
        return method(self)

    return wrapper


# ---------------------------------------------------------------------------- real processes
def _spawn(folder: Path, *args: str) -> subprocess.Popen:
    env = dict(os.environ, TMPDIR=str(folder / "tmp"))
    return subprocess.Popen(
        [sys.executable, "-m", "vbi_lib.reports", *args],
        cwd=folder,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def test_a_good_run_writes_the_html_and_the_data_and_prints_their_paths(folder: Path) -> None:
    process = _spawn(folder, "good.yaml", "--output-dir", "out", "--no-pdf")
    out, err = process.communicate(timeout=300)
    assert process.returncode == 0, err
    assert out.splitlines() == ["out/good.html", "out/good.json", "out/good.csv"]
    assert err == ""
    assert sorted(p.name for p in (folder / "out").iterdir()) == [
        "good.csv", "good.html", "good.json",
    ]  # fmt: skip
    document = json.loads((folder / "out" / "good.json").read_text())
    rows = document["results"]
    # one row per speed, place, effect and direction: 2 speeds, midspan, 3 effects, 2 ways
    assert len(rows) == 2 * 1 * 3 * 2
    assert set(rows[0]) >= {"speed_m_s", "section_m", "effect", "direction", "daf", "static",
                            "dynamic", "lost_contact", "flight_fraction"}  # fmt: skip
    header = (folder / "out" / "good.csv").read_text().splitlines()[0].split(",")
    assert header == document["columns"] and len(document["columns"]) == len(rows[0])
    assert list((folder / "tmp").iterdir()) == []


def _children(process: subprocess.Popen, word: str, seconds: float) -> list[psutil.Process]:
    """The process's descendants whose command line holds ``word``, once there are some."""
    parent = psutil.Process(process.pid)
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline and process.poll() is None:
        found = []
        with contextlib.suppress(psutil.Error):  # the parent itself may have ended
            for child in parent.children(recursive=True):
                try:  # chromium's helper processes come and go: skip one that just ended
                    if word in " ".join(child.cmdline()):
                        found.append(child)
                except psutil.Error:
                    continue
        if found:
            return found
        time.sleep(0.02)
    return []


@pytest.mark.parametrize(
    ("signum", "status", "word", "phase"),
    [
        (signal.SIGTERM, 143, "terminated", "ipykernel"),
        (signal.SIGINT, 130, "interrupted", "ipykernel"),
        (signal.SIGHUP, 129, "hung up", "ipykernel"),
        (signal.SIGTERM, 143, "terminated", "chromium"),
        (signal.SIGHUP, 129, "hung up", "chromium"),
    ],
)
def test_a_signal_stops_everything_and_leaves_nothing(
    folder: Path, signum: int, status: int, word: str, phase: str
) -> None:
    if phase == "chromium" and running.find_chromium() is None:
        if os.environ.get("CI") == "true":
            raise RuntimeError("CI needs Debian's chromium (apt-get install -y chromium)")
        pytest.skip("chromium is missing: the signal during printing is not checked")
    args = ["good.yaml", "--output-dir", "out"] + (["--no-pdf"] if phase != "chromium" else [])
    process = _spawn(folder, *args)
    children = _children(process, phase, 180)
    if not children:
        process.kill()
        out, err = process.communicate(timeout=60)
        raise AssertionError(f"no {phase} process was seen; exit {process.returncode}: {err}")
    if phase == "ipykernel":
        time.sleep(0.5)  # inside the report
    everything = psutil.Process(process.pid).children(recursive=True)
    process.send_signal(signum)
    out, err = process.communicate(timeout=60)
    assert process.returncode == status, err
    assert err.strip().splitlines() == [
        f"vbi-report: {word} ({signal.Signals(signum).name}); nothing written"
    ]
    assert "Traceback" not in err and out == ""
    psutil.wait_procs(everything, timeout=10)
    assert not [p for p in everything if p.is_running() and p.status() != psutil.STATUS_ZOMBIE]
    assert not (folder / "out").exists()
    assert list((folder / "tmp").iterdir()) == []
    assert not _short_folders(process.pid)


def _short_folders(pid: int) -> list[Path]:
    """Chromium's short folders a run of process ``pid`` made outside TMPDIR (if any)."""
    return [p for base in ("/tmp", "/var/tmp", "/dev/shm")
            for p in Path(base).glob(f"vbi-{pid}-*")]  # fmt: skip


def test_a_long_tmpdir_prints_the_pdf_and_leaves_nothing(folder: Path) -> None:
    if running.find_chromium() is None:
        if os.environ.get("CI") == "true":
            raise RuntimeError("CI needs Debian's chromium (apt-get install -y chromium)")
        pytest.skip("chromium is missing: the PDF under a long TMPDIR is not checked")
    long = folder / ("a-rather-long-folder-name-" * 5)
    long.mkdir()
    assert len(str(long)) > 100
    env = dict(os.environ, TMPDIR=str(long))
    process = subprocess.Popen([sys.executable, "-m", "vbi_lib.reports", "good.yaml", "-o", "out"],
                               cwd=folder, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)  # fmt: skip
    _, err = process.communicate(timeout=300)
    assert process.returncode == 0, err
    pdf = folder / "out" / "good.pdf"
    assert pdf.read_bytes().startswith(b"%PDF-")
    assert list(long.iterdir()) == []
    assert not _short_folders(process.pid)  # chromium's short folder went with the run


def test_papermill_runs_the_template_on_the_same_file(folder: Path) -> None:
    env = dict(os.environ, TMPDIR=str(folder / "tmp"))
    command = [sys.executable, "-m", "papermill", str(running.TEMPLATE), "run.ipynb",
               "-f", "good.yaml", "--cwd", str(folder), "-k", "python3"]  # fmt: skip
    done = subprocess.run(command, cwd=folder, env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    notebook = json.loads((folder / "run.ipynb").read_text())
    html = "".join(
        "".join(output.get("data", {}).get("text/html", ""))
        for cell in notebook["cells"]
        for output in cell.get("outputs", [])
    )
    assert "A 30 m bridge" in html and "The vehicle stayed on the road" in html
    assert "parameters given directly" in html  # papermill does not pass the file's name
    # with results_file, papermill writes the results as data too
    command += ["-p", "results_file", str(folder / "run.json")]
    done = subprocess.run(command, cwd=folder, env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    rows = json.loads((folder / "run.json").read_text())["results"]
    assert len(rows) == 2 * 3 * 2 and (folder / "run.csv").is_file()


def test_the_flat_form_checks_its_output_file_before_running(folder: Path) -> None:
    from vbi_lib.reports import legacy

    flat = {"span": "100 ft", "k_mid": "497527 lbf/in", "first_frequency": "3.99 Hz"}
    (folder / "report.html").mkdir()
    with pytest.raises(running.OutputError, match="report.html is a folder"):
        legacy.make_report(folder / "report.html", **flat)
    with pytest.raises(running.OutputError, match="must be an .html file"):
        legacy.make_report(folder / "report", **flat)
    assert list((folder / "tmp").iterdir()) == []


def test_warnings_on_the_inputs_are_printed_after_the_paths(
    folder: Path, capsys: pytest.CaptureFixture, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = folder / "out"
    written = [running.ReportFiles(out / "deck.html", None, out / "deck.json", out / "deck.csv",
                                   ("The deck profile's elevations fit ...",))]  # fmt: skip
    monkeypatch.setattr(cli, "write_reports", lambda *args, **kwargs: written)
    assert cli.main(["good.yaml", "-o", "out", "--no-pdf"]) == 0
    captured = capsys.readouterr()
    assert captured.out.splitlines() == [str(out / f"deck{s}") for s in (".html", ".json", ".csv")]
    assert captured.err == "vbi-report: warning: deck: The deck profile's elevations fit ...\n"
