"""Every bad input is refused at the edge: one row per member of each class of issue 17.

Each row calls the library (or the report writer) with one bad input and asserts

* the exception's exact type (``TypeError`` for a wrong type, ``ValueError`` for a wrong
  value, or the library's subclass of one of them),
* that the message names the parameter and the value given (the strings in ``says``),
* that no file was written: the test runs in an empty working folder and compares every
  file under it (the inputs a row reads are written before) before and after the call.

The classes are those of the issue: implausible values (outside the hard limits of
:data:`vbi_lib.ranges.RANGES`), huge allocations, flags and types, silent NaN or garbage,
studies, widgets and reports.  Soft limits (warnings) and the results that used to be
garbage are checked after the table.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import vbi_lib as vbi
from vbi_lib import monitoring as mon
from vbi_lib import reports, studies, widgets
from vbi_lib._files import FileReadError
from vbi_lib.profile_files import ProfileFileError
from vbi_lib.ranges import MAX_NODES, RANGES, ranges_markdown
from vbi_lib.vehicles import Axle, Convoy, QuarterCar, Tyre, VehicleSystem, hs20

#: The book's page that shows the table of ranges (it was the README's until issue 24).
RANGES_PAGE = Path(__file__).resolve().parents[1] / "book" / "ranges.md"


# ---------------------------------------------------------------------------- inputs
def bridge() -> vbi.Bridge:
    return vbi.Bridge(30.0, 1, 2e10, 8000.0)


def truck() -> vbi.Vehicle:
    return vbi.Vehicle.from_frequency(3e4, 3.0, 0.1)


def road() -> vbi.Profile:
    return vbi.Profile.flat(130.0, 0.05)


def crossing(**changes: object) -> dict:
    """The five inputs of a valid crossing, some replaced."""
    inputs = {"bridge": bridge(), "vehicle": truck(), "profile": road(), "speed": 20.0,
              "bridge_start": 50.0}  # fmt: skip
    inputs.update(changes)
    return inputs


def simulate(options: dict | None = None, **changes: object) -> object:
    i = crossing(**changes)
    return vbi.simulate(i["bridge"], i["vehicle"], i["profile"], i["speed"], i["bridge_start"],
                        **(options or {}))  # fmt: skip


def simulate_many(options: dict | None = None, **changes: object) -> object:
    i = crossing(**changes)
    return vbi.simulate_many(i["bridge"], i["vehicle"], i["profile"], i["speed"],
                             i["bridge_start"], **(options or {}))  # fmt: skip


def erd(channels: str, samples: str, interval: str = "0.25", units: str = "mm") -> str:
    """An ERD v2 file whose header declares ``channels`` and ``samples``; three data rows."""
    return (
        f"ERDFILEV2.00\n{channels}, {samples}, -1, 1, 5, {interval}, -1,\nTITLE   demo\n"
        f"SHORTNAMLeft\nUNITSNAM{units}\nXUNITS  m\nEND\n0.0\n1.5\n-0.5\n"
    )


@dataclass(frozen=True)
class UnbuildableRecipe:
    """A recipe of the user's own whose road cannot be built (its spacing is negative)."""

    start: float = 0.0
    end: float = 200.0
    label: str = "own recipe"

    def build(self) -> vbi.Profile:
        return vbi.Profile.flat(self.end - self.start, -0.05, self.start)


def table(first: dict | None = None, **changes: object) -> pd.DataFrame:
    """A valid two-row scenario table, its second row changed (and its first by ``first``)."""
    rows = [
        {"bridge": bridge(), "vehicle": truck(), "profile": studies.FlatProfile(200.0, 0.05),
         "speed": 20.0, "bridge_start": 50.0},
        {"bridge": bridge(), "vehicle": truck(), "profile": studies.FlatProfile(200.0, 0.05),
         "speed": 25.0, "bridge_start": 50.0},
    ]  # fmt: skip
    rows[0].update(first or {})
    rows[1].update(changes)
    return pd.DataFrame(rows)


def explorer_control(name: str, value: object) -> None:
    widgets.CrossingExplorer(road="flat").controls[name].value = value


def fifo(folder: Path) -> Path:
    """A named pipe no one writes to: reading it would wait for ever."""
    import os

    path = folder / "pipe.csv"
    os.mkfifo(path)
    return path


def unix_socket(folder: Path) -> Path:
    """A Unix socket bound in ``folder`` (kept open while the test runs)."""
    import socket

    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    server.bind(str(folder / "sock.csv"))
    _OPEN.append(server)
    return folder / "sock.csv"


_OPEN: list = []


def assessment_pipe(folder: Path) -> Path:
    """A data-set folder whose scenario table is a named pipe."""
    import os

    os.mkfifo(folder / "scenarios-239.csv")
    return folder


def link_to(folder: Path, target: str) -> Path:
    """A symbolic link in ``folder`` to ``target``: the reader must judge what it names."""
    link = folder / "link.csv"
    link.symlink_to(target)
    return link


# ---------------------------------------------------------------------------- the table
@dataclass(frozen=True)
class Row:
    """One bad input: the call, the exception it must raise and what its message names."""

    name: str
    call: Callable[[Path], object]
    error: type[BaseException]
    says: tuple[str, ...]
    files: dict[str, str] = field(default_factory=dict)


def row(name: str, call: Callable, error: type, *says: str, files: dict | None = None) -> Row:
    return Row(name, call, error, says, files or {})


ROWS = [
    # ---- implausible values: physically meaningless, refused by name
    row("span of 1 mm", lambda _: vbi.Bridge(0.001, 1, 2e10, 8000.0), ValueError, "span=0.001"),
    row("span of 10 km", lambda _: vbi.Bridge(1e4, 1, 2e10, 8000.0), ValueError, "span=10000.0"),
    row("one span of 10 km among others",
        lambda _: vbi.Bridge.continuous([20.0, 1e4], EI=1e10, mass_per_length=5e3),
        ValueError, "spans[1]=10000.0"),
    row("60 continuous spans",
        lambda _: vbi.Bridge.continuous([20.0] * 60, EI=1e10, mass_per_length=5e3),
        ValueError, "len(spans)=60"),
    row("EI of a thread", lambda _: vbi.Bridge(30.0, 1, 1.0, 8000.0), ValueError, "EI=1.0"),
    row("mass per length of a dam", lambda _: vbi.Bridge(30.0, 1, 2e10, 1e8), ValueError,
        "mass_per_length=100000000.0"),
    row("EI and mass that vibrate at 50 kHz", lambda _: vbi.Bridge(30.0, 1, 1e18, 1.0),
        ValueError, "first_frequency_hz=", "EI=1e+18"),
    row("k_mid of 1e15 N/m",
        lambda _: vbi.Bridge.from_midspan_stiffness(30.0, 1, 1e15, 3.0), ValueError,
        "k_mid=1000000000000000.0"),
    row("a 5 kHz bridge", lambda _: vbi.Bridge.from_frequency(30.0, 1, 8000.0, 5000.0),
        ValueError, "first_frequency_hz=5000.0"),
    row("bridge damping of 150 %", lambda _: vbi.Bridge(30.0, 1, 2e10, 8000.0, 1.5), ValueError,
        "damping_ratio=1.5"),
    row("a 100 000 t truck", lambda _: vbi.Vehicle(1e8, 4e6, 0.0), ValueError,
        "mass=100000000.0"),
    row("a suspension of 1e15 N/m", lambda _: vbi.Vehicle(1e4, 1e15, 0.0), ValueError,
        "frequency_hz (from mass and stiffness)="),
    row("a 2 kHz body bounce", lambda _: vbi.Vehicle.from_frequency(1e4, 2000.0), ValueError,
        "frequency_hz=2000.0"),
    row("a 1 g wheel", lambda _: QuarterCar(4e3, 1e-3, 2e5, 5e3, 2e6), ValueError,
        "unsprung_mass=0.001"),
    row("a 5 kHz axle hop",
        lambda _: QuarterCar.from_frequencies(4e3, 500.0, 1.5, 5000.0), ValueError,
        "axle_hop_hz=5000.0"),
    row("a 5 m tyre footprint", lambda _: Tyre(500.0, 1e6, footprint=5.0), ValueError,
        "footprint=5.0"),
    row("an axle 500 m behind the first", lambda _: Axle(500.0, 1e5, 1e6), ValueError,
        "offset=500.0"),
    row("a headway of 5 km", lambda _: Convoy([truck(), truck()], [5000.0]), ValueError,
        "headways[0]=5000.0"),
    row("10^6 m/s", lambda _: simulate(speed=1e6), ValueError, "speed=1000000.0"),
    row("10^6 m/s in a batch", lambda _: simulate_many(speed=[20.0, 1e6]), ValueError,
        "crossing 1: speed=1000000.0"),
    row("1000 beam modes", lambda _: simulate({"model": "modal", "modes": 1000}), ValueError,
        "modes=1000"),
    row("RK4 stepping 0.5 s", lambda _: simulate(
        {"dt": 0.5}, profile=vbi.Profile.harmonic(130.0, 5.0, 40.0, 0.01)), ValueError, "dt=0.5"),
    row("c10 = 1e3 m^3", lambda _: vbi.Profile.iso8608(100.0, 0.05, c10=1e3, seed=1),
        ValueError, "c10=1000.0"),
    row("a recipe with c10 = 1e3 m^3", lambda _: studies.ISOProfile(100.0, 0.05, c10=1e3),
        ValueError, "c10=1000.0"),
    row("waviness 10", lambda _: vbi.Profile.iso8608(100.0, 0.05, c10=1e-4, waviness=10.0),
        ValueError, "waviness=10.0"),
    row("a road 10 000 km long", lambda _: vbi.Profile.flat(1e7, 1.0), ValueError,
        "length=10000000.0"),
    row("a spacing of 1 micrometre", lambda _: vbi.Profile.flat(100.0, 1e-6), ValueError,
        "spacing=1e-06"),
    row("a 5 m harmonic amplitude", lambda _: vbi.Profile.harmonic(100.0, 0.05, 10.0, 5.0),
        ValueError, "amplitude=5.0"),
    row("a 3 m bump", lambda _: vbi.Profile.bump(100.0, 0.05, 50.0, 3.0, 1.0), ValueError,
        "height=3.0"),
    row("a -2 m step", lambda _: vbi.Profile.step(100.0, 0.05, 50.0, -2.0), ValueError,
        "height=-2.0"),
    row("a ramp of grade 2", lambda _: vbi.Profile.ramp(100.0, 0.05, 10.0, 20.0, 10.0),
        ValueError, "rise=20.0", "run=10.0"),
    row("a wavelength the spacing aliases", lambda _: vbi.Profile.harmonic(10.0, 0.05, 0.06, 0.01),
        ValueError, "wavelength=0.06", "spacing=0.05"),
    row("Monte Carlo speeds up to 500 m/s",
        lambda _: studies.monte_carlo(bridge(), truck(), 4, speed_range=(10.0, 500.0),
                                      c10_range=(1e-5, 1e-4)),
        ValueError, "speed_range[1]=500.0"),
    row("Monte Carlo roughness up to 10 m^3",
        lambda _: studies.monte_carlo(bridge(), truck(), 4, speed_range=(10.0, 30.0),
                                      c10_range=(1e-5, 10.0)),
        ValueError, "c10_range[1]=10.0"),
    # ---- huge allocations: counted before anything is allocated
    row("dt = 1e-12 s (47 TiB)", lambda _: simulate({"dt": 1e-12}), ValueError, "dt=1e-12",
        f"at most {MAX_NODES:.0e}"),
    row("dt = 1e-12 s in a batch", lambda _: simulate_many({"dt": 1e-12}), ValueError,
        "crossing 0: dt=1e-12"),
    row("a crawl at 1 mm/s over a long free vibration",
        lambda _: simulate({"free_vibration": 1e6}, speed=1e-3), ValueError, "speed=0.001"),
    row("10^9 samples", lambda _: vbi.Profile.flat(1e5, 1e-4), ValueError, "length=100000.0",
        "spacing=0.0001"),
    row("a recipe of 10^9 samples", lambda _: studies.FlatProfile(1e5, 1e-4), ValueError,
        "length=100000.0"),
    row("an ERD header declaring 10^12 samples", lambda d: vbi.read_erd(d / "big.erd"),
        ProfileFileError, "big.erd", "1000000000000 samples",
        files={"big.erd": erd("1", "1000000000000")}),
    row("an ERD header declaring 2x10^8 channels", lambda d: vbi.read_erd(d / "wide.erd"),
        ProfileFileError, "wide.erd", "200000000 channels",
        files={"wide.erd": erd("200000000", "3")}),
    row("an ERD sample interval of 1 km", lambda d: vbi.read_erd(d / "coarse.erd"),
        ProfileFileError, "coarse.erd", "sample interval 1000",
        files={"coarse.erd": erd("1", "3", interval="1000")}),
    # ---- files: only regular files, of bounded size, in UTF-8 or UTF-16 (issue 23)
    row("read_profile of /dev/zero", lambda _: vbi.read_profile("/dev/zero", "m"),
        ProfileFileError, "/dev/zero", "is a character device", "not a regular file"),
    row("read_erd of /dev/zero", lambda _: vbi.read_erd("/dev/zero"), ProfileFileError,
        "/dev/zero", "is a character device"),
    row("the explorers' profile path at /dev/zero",
        lambda _: widgets.scenario._measured("/dev/zero", "in"), ProfileFileError,
        "/dev/zero", "character device"),
    row("read_profile of a named pipe", lambda d: vbi.read_profile(fifo(d), "m"),
        ProfileFileError, "pipe.csv", "named pipe (FIFO"),
    row("read_erd of a named pipe", lambda d: vbi.read_erd(fifo(d)), ProfileFileError,
        "pipe.csv", "named pipe"),
    row("read_profile of a socket", lambda d: vbi.read_profile(unix_socket(d), "m"),
        ProfileFileError, "sock.csv", "is a socket"),
    row("read_profile of a folder", lambda d: vbi.read_profile(d, "m"), ProfileFileError,
        "is a directory"),
    row("read_profile of a link to /dev/zero",
        lambda d: vbi.read_profile(link_to(d, "/dev/zero"), "m"), ProfileFileError,
        "link.csv", "character device"),
    row("read_erd of a dangling link", lambda d: vbi.read_erd(link_to(d, str(d / "gone"))),
        ProfileFileError, "link.csv", "cannot be read"),
    row("a profile file larger than max_bytes",
        lambda d: vbi.read_profile(d / "deck.csv", "in", max_bytes=10), ProfileFileError,
        "deck.csv", "more than max_bytes=10", files={"deck.csv": "0,0\n1,0.5\n2,0.25\n"}),
    row("an ERD file larger than max_bytes",
        lambda d: vbi.read_erd(d / "run.erd", max_bytes=100), ProfileFileError, "run.erd",
        "max_bytes=100", files={"run.erd": erd("1", "3")}),
    row("max_bytes='1'", lambda d: vbi.read_profile(d / "deck.csv", "in", max_bytes="1"),
        TypeError, "max_bytes='1'", files={"deck.csv": "0,0\n1,0.5\n"}),
    row("max_bytes=0", lambda d: vbi.read_profile(d / "deck.csv", "in", max_bytes=0),
        ValueError, "max_bytes=0", files={"deck.csv": "0,0\n1,0.5\n"}),
    row("a profile file in UTF-32", lambda d: vbi.read_profile(d / "u32.csv", "in"),
        ProfileFileError, "u32.csv", "UTF-32", files={"u32.csv": "0,0\n1,0.5\n".encode("utf-32")}),
    row("a profile file in Latin-1", lambda d: vbi.read_profile(d / "l1.csv", "in"),
        ProfileFileError, "l1.csv", "not UTF-8", "Latin-1", "line 1",
        files={"l1.csv": "# d\xe9part\n0,0\n1,0.5\n".encode("latin-1")}),
    row("a binary file as a profile", lambda d: vbi.read_profile(d / "b.csv", "in"),
        ProfileFileError, "b.csv", "not a text file", "zero bytes",
        files={"b.csv": b"0,0\n\x00\x01\x02\x03"}),
    row("an ERD file in Latin-1", lambda d: vbi.read_erd(d / "l1.erd"), ProfileFileError,
        "l1.erd", "Latin-1", files={"l1.erd": erd("1", "3").replace("demo", "d\xe9mo")
                                    .encode("latin-1")}),
    row("one column of decimal commas",
        lambda d: vbi.read_profile(d / "comma.csv", "m"), ProfileFileError, "comma.csv",
        "decimal commas", "decimal=", files={"comma.csv": "1,5\n2,5\n3,5\n4,5\n"}),
    row("one column of decimal commas, some with leading zeros",
        lambda d: vbi.read_profile(d / "comma.csv", "m"), ProfileFileError, "decimal commas",
        files={"comma.csv": "0,05\n0,10\n0,25\n"}),
    row("decimal=';'", lambda d: vbi.read_profile(d / "deck.csv", "m", decimal=";"),
        ValueError, "decimal=';'", files={"deck.csv": "0,0\n1,0.5\n"}),
    row("a path given as bytes", lambda _: vbi.read_profile(b"/dev/zero", "m"), TypeError,
        "path=b'/dev/zero'"),
    row("a zero character in a path", lambda _: vbi.read_profile("a\x00b.csv", "m"),
        ProfileFileError, "'a\\x00b.csv'", "zero character"),
    row("save into a missing folder",
        lambda d: studies.save(pd.DataFrame({"daf": [1.0]}), d / "nowhere" / "s.csv"),
        FileNotFoundError, "path=", "nowhere", "does not exist"),
    row("load a study from /dev/zero", lambda _: studies.load("/dev/zero.csv"), FileReadError,
        "path='/dev/zero.csv'", "cannot be read"),
    row("load a study from a named pipe", lambda d: studies.load(fifo(d)), FileReadError,
        "pipe.csv", "named pipe"),
    row("load a study larger than max_bytes",
        lambda d: studies.load(d / "s.csv", max_bytes=4), FileReadError, "max_bytes=4",
        files={"s.csv": "daf\n1.0\n"}),
    row("an assessment table that is a named pipe",
        lambda d: vbi.study_data.read_assessment_set(assessment_pipe(d)), FileReadError,
        "scenarios-239.csv", "named pipe"),
    row("save onto a folder",
        lambda d: studies.save(pd.DataFrame({"daf": [1.0]}), mkdir(d / "s.csv")),
        IsADirectoryError, "s.csv", "is a folder"),
    # ---- flags and types: a bool is a bool, a number a number, everywhere alike
    row("coupled='False'", lambda _: simulate({"coupled": "False"}), TypeError,
        "coupled='False'"),
    row("coupled='False' in a batch", lambda _: simulate_many({"coupled": "False"}), TypeError,
        "coupled='False'"),
    row("convective=1", lambda _: simulate({"convective": 1}), TypeError, "convective=1"),
    row("dt=-1 in a batch", lambda _: simulate_many({"dt": -1}), ValueError, "dt=-1"),
    row("dt=0 in a batch", lambda _: simulate_many({"dt": 0}), ValueError, "dt=0"),
    row("dt='0.01'", lambda _: simulate({"dt": "0.01"}), TypeError, "dt='0.01'"),
    row("speed='20'", lambda _: simulate(speed="20"), TypeError, "speed='20'"),
    row("bridge_start='abc'", lambda _: simulate(bridge_start="abc"), TypeError,
        "bridge_start='abc'"),
    row("modes=2.5", lambda _: simulate({"model": "modal", "modes": 2.5}), TypeError,
        "modes=2.5"),
    row("model=3", lambda _: simulate({"model": 3}), TypeError, "model=3"),
    row("a bridge that is text", lambda _: simulate(bridge="30 m bridge"), TypeError,
        "bridge must be a vbi.Bridge", "'30 m bridge'"),
    row("a vehicle that is a dict", lambda _: simulate(vehicle={"mass": 1e4}), TypeError,
        "vehicle must be a vbi vehicle", "{'mass': 10000.0}"),
    row("a profile that is an array", lambda _: simulate(profile=np.zeros(3)), TypeError,
        "profile must be a vbi.Profile", "array("),
    row("seed='abc'", lambda _: vbi.Profile.iso8608(100.0, 0.05, c10=1e-4, seed="abc"),
        TypeError, "seed='abc'"),
    row("a recipe seed of 1.5", lambda _: studies.ISOProfile(100.0, 0.05, c10=1e-4, seed=1.5),
        TypeError, "seed=1.5"),
    row("iso_class=3", lambda _: vbi.Profile.iso8608(100.0, 0.05, iso_class=3), TypeError,
        "iso_class=3"),
    row("skip_rows='a'", lambda d: vbi.read_profile(d / "deck.csv", "in", skip_rows="a"),
        TypeError, "skip_rows='a'", files={"deck.csv": "0,0\n1,0.5\n"}),
    row("skip_rows=-1", lambda d: vbi.read_profile(d / "deck.csv", "in", skip_rows=-1),
        ValueError, "skip_rows=-1", files={"deck.csv": "0,0\n1,0.5\n"}),
    row("Profile(['a', 'b'], ...)", lambda _: vbi.Profile(["a", "b"], [0.0, 0.0]), TypeError,
        "profile x[0]='a'"),
    row("elevations given as text", lambda _: vbi.Profile([0.0, 1.0], ["1", "2"]), TypeError,
        "profile elevation[0]='1'"),
    row("n_spans='1'", lambda _: vbi.Bridge(30.0, "1", 2e10, 8000.0), TypeError, "n_spans='1'"),
    row("span='30 m'", lambda _: vbi.Bridge("30 m", 1, 2e10, 8000.0), TypeError, "span='30 m'"),
    row("a sprung mass of None", lambda _: QuarterCar(None, 500.0, 2e5, 5e3, 2e6), TypeError,
        "sprung_mass=None"),
    row("damped='yes'", lambda _: vbi.Vehicle.from_frequency(1e4, 3.0, 0.1, damped="yes"),
        TypeError, "damped='yes'"),
    row("unilateral='yes'", lambda _: Tyre(500.0, 1e6, unilateral="yes"), TypeError,
        "unilateral='yes'"),
    row("body=1", lambda _: hs20(body=1), TypeError, "body=1"),
    row("a mass matrix of text",
        lambda _: VehicleSystem([["a"]], [[0.0]], [[0.0]], [[1.0]], [0.0], [1e4], [1e6], [0.0],
                                [False], [0.0]),
        TypeError, "mass[0]='a'"),
    row("n=2.5 crossings",
        lambda _: studies.monte_carlo(bridge(), truck(), 2.5, speed_range=(10.0, 30.0),
                                      c10_range=(1e-5, 1e-4)),
        TypeError, "n=2.5"),
    row("iri of a text", lambda _: vbi.iri("road"), TypeError, "profile must be", "'road'"),
    row("a band that is text", lambda _: vbi.fit_iso8608(road(), band="abc"), TypeError,
        "band='abc'"),
    row("beam modes='3'", lambda _: vbi.beam_modes(bridge(), "3"), TypeError, "modes='3'"),
    row("a closed form with 2.5 modes",
        lambda _: vbi.closed_forms.moving_force_response(0.5, 0.5, modes=2.5), TypeError,
        "modes=2.5"),
    row("statics at a station given as text",
        lambda _: vbi.beam_statics.continuous_statics("mid", 1.0, [10.0], 1e9), TypeError,
        "x='mid'"),
    row("a record given as text", lambda _: mon.daf_from_record(["a", "b"], 200.0, 2.0),
        TypeError, "signal=['a', 'b']"),
    row("baseline_fraction='a'",
        lambda _: mon.daf_from_record(np.sin(np.linspace(0, 3, 1600)), 200.0, 2.0,
                                      baseline_fraction="a"),
        TypeError, "baseline_fraction='a'"),
    # ---- silent NaN or garbage: now refused with the reason
    row("IRI segments shorter than the 250 mm base",
        lambda _: vbi.iri(vbi.Profile.flat(100.0, 0.05), segment_length=0.1), ValueError,
        "segment_length=0.1"),
    row("ISO 8608 fit of a straight grade",
        lambda _: vbi.fit_iso8608(vbi.Profile.ramp(200.0, 0.05, 0.0, 2.0, 200.0)), ValueError,
        "profile=Profile('ramp", "fitted c10="),
    row("DAF of a constant record", lambda _: mon.daf_from_record(np.full(1600, 2.0), 200.0, 2.0),
        ValueError, "signal is constant"),
    row("DAF of pure noise",
        lambda _: mon.daf_from_record(np.random.default_rng(3).standard_normal(1600), 200.0, 2.0),
        ValueError, "no event that stands out of the noise"),
    # ---- studies: every row and every road checked before any work
    row("a recipe that cannot be built", lambda _: studies.run(table(
        profile=UnbuildableRecipe()), "serial"), ValueError, "row 1", "spacing=-0.05"),
    row("a recipe whose band the spacing cannot hold",
        lambda _: studies.ISOProfile(100.0, 0.5, c10=1e-4), ValueError, "band=", "spacing=0.5"),
    row("a study row at 500 m/s", lambda _: studies.run(table(speed=500.0), "serial"),
        ValueError, "row 1", "speed must be"),
    row("a study row of 1000 modes", lambda _: studies.run(table(
        {"model": "modal", "modes": 5}, model="modal", modes=1000), "serial"), ValueError,
        "row 1", "modes must be a whole number from 1 to 200"),
    row("the one-coordinate model on three spans", lambda _: studies.run(table(
        bridge=vbi.Bridge.continuous([20.0, 20.0, 20.0], EI=2e10, mass_per_length=8e3)),
        "serial"), ValueError, "row 1", "one-coordinate model bends one span or two"),
    # ---- widgets: refused in the explorer, by name
    row("a NaN typed into a slider", lambda _: explorer_control("span_ft", float("nan")),
        widgets.ControlValueError, "span_ft=nan"),
    row("a road kind not offered", lambda _: explorer_control("road", "gravel"),
        widgets.ControlValueError, "road='gravel'"),
    row("three spans chosen", lambda _: explorer_control("n_spans", 3),
        widgets.ControlValueError, "n_spans=3"),
    row("2.5 modes typed", lambda _: explorer_control("modes", 2.5),
        widgets.ControlValueError, "modes=2.5"),
    # ---- reports: the parameter file refused before any output exists
    row("a report for a 1 mm span",
        lambda d: reports.write_reports([d / "bad.yaml"], d / "out", pdf=False),
        reports.ParameterError, "bridge.span", "1 mm",
        files={"bad.yaml": "bridge: {span: 1 mm, k_mid: 497527 lbf/in, first_frequency: 3.99 Hz}\n"
               "vehicle: {mass: 77.2 kip, frequency: 4.5 Hz}\nprofile: {iso_class: A}\n"
               "speeds: [50 mph]\n"}),
    row("a report at 10^6 mph",
        lambda d: reports.write_reports([d / "fast.yaml"], d / "out", pdf=False),
        reports.ParameterError, "speeds", "1000000 mph",
        files={"fast.yaml": "bridge: {span: 30 m, k_mid: 497527 lbf/in, first_frequency: 3.99 Hz}"
               "\nvehicle: {mass: 77.2 kip, frequency: 4.5 Hz}\nprofile: {iso_class: A}\n"
               "speeds: [1000000 mph]\n"}),
]  # fmt: skip


def mkdir(path: Path) -> Path:
    path.mkdir()
    return path


def _files(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in folder.rglob("*") if p.is_file()}


def test_the_table_covers_every_class_with_at_least_60_rows() -> None:
    assert len(ROWS) >= 60
    assert len({r.name for r in ROWS}) == len(ROWS), "two rows share a name"


@pytest.mark.parametrize("case", ROWS, ids=[r.name for r in ROWS])
def test_a_bad_input_is_refused_by_name_and_writes_nothing(
    case: Row, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    for name, text in case.files.items():
        if isinstance(text, bytes):
            (tmp_path / name).write_bytes(text)
        else:
            (tmp_path / name).write_text(text)
    before = _files(tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.VbiWarning)  # a refusal is what is asserted
        with pytest.raises(BaseException) as caught:  # noqa: PT011 - the type is checked below
            case.call(tmp_path)
    assert type(caught.value) is case.error, f"{type(caught.value).__name__}: {caught.value}"
    message = str(caught.value)
    for part in case.says:
        assert part in message, f"{part!r} not in: {message}"
    assert _files(tmp_path) == before, "a file was written"


# ---------------------------------------------------------------------------- the ranges
def test_the_book_s_table_of_ranges_is_the_library_s() -> None:
    text = RANGES_PAGE.read_text()
    start = text.index("<!-- ranges:start -->\n") + len("<!-- ranges:start -->\n")
    stop = text.index("<!-- ranges:end -->")
    assert text[start:stop] == ranges_markdown(), (
        "book/ranges.md's table of ranges differs from vbi_lib.ranges.RANGES; regenerate it with "
        "python -c 'import vbi_lib.ranges as r; print(r.ranges_markdown())'"
    )


def test_every_range_is_ordered_and_soft_limits_lie_inside_hard_ones() -> None:
    for key, spec in RANGES.items():
        low, high = spec.hard
        assert low < high, key
        if spec.soft is not None:
            assert low <= spec.soft[0] < spec.soft[1] <= high, key
        assert spec.quantity and spec.unit and spec.used_by, key


def _inside(key: str) -> float:
    spec = RANGES[key]
    low, high = spec.soft or spec.hard
    return 0.5 * (low + high)


FINITE = [k for k, s in RANGES.items() if math.isfinite(s.hard[1])]


@pytest.mark.parametrize("key", FINITE)
def test_inside_is_accepted_quietly_and_beyond_the_hard_limit_refused(key: str) -> None:
    spec = RANGES[key]
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.OutsideValidityWarning)
        assert vbi.ranges.check_range(key, _inside(key)) == _inside(key)
    with pytest.raises(ValueError, match=f"^{key}="):
        vbi.ranges.check_range(key, spec.hard[1] * 1.001 + 1e-9)
    with pytest.raises(TypeError, match=f"^{key}='1'"):
        vbi.ranges.check_range(key, "1")


def test_closed_limits_are_inside_and_open_ones_outside() -> None:
    check = vbi.ranges.check_range
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.OutsideValidityWarning)
        assert check("span", 1.0) == 1.0 and check("span", 2000.0) == 2000.0
        assert check("speed", 100.0) == 100.0
    with pytest.raises(ValueError, match="above 0"):
        check("speed", 0.0)
    with pytest.raises(ValueError, match="below 1"):
        check("bridge_damping_ratio", 1.0)


# ---------------------------------------------------------------------------- soft limits
SOFT = [
    ("a 500 m span", lambda: vbi.Bridge(500.0, 1, 1e14, 8000.0), "span=500"),
    ("a 60 Hz bridge", lambda: vbi.Bridge.from_frequency(30.0, 1, 8000.0, 60.0),
     "first_frequency_hz=60"),
    ("a class F road", lambda: vbi.Profile.iso8608(100.0, 0.05, iso_class="F", seed=1),
     "iso_class='F'"),
    ("waviness 4.8", lambda: vbi.Profile.iso8608(100.0, 0.05, c10=1e-4, waviness=4.8, seed=1),
     "waviness=4.8"),
    ("a 0.3 m step", lambda: vbi.Profile.step(20.0, 0.05, 10.0, 0.3), "height=0.3"),
    ("200 km/h", lambda: simulate(speed=200 / 3.6), "speed=55.5556"),
    ("a road sampled too coarsely for the bridge",
     lambda: simulate(profile=vbi.Profile.harmonic(130.0, 2.0, 40.0, 0.01), speed=5.0),
     "profile spacing 2 m"),
    ("steps of omega dt = 1.5", lambda: simulate(
        {"model": "modal", "modes": 1, "dt": 0.08},
        profile=vbi.Profile.harmonic(130.0, 5.0, 40.0, 0.001)), "omega_max dt (dt=0.08 s)"),
    ("the IRI of a 5 m road", lambda: vbi.iri(vbi.Profile.harmonic(5.0, 0.025, 2.0, 0.001)),
     "profile length=5 m"),
    ("the IRI of a road sampled every 1 m",
     lambda: vbi.iri(vbi.Profile.harmonic(500.0, 1.0, 20.0, 0.01)), "profile spacing=1 m"),
    ("a 60 Hz axle hop", lambda: QuarterCar.from_frequencies(4e3, 500.0, 1.5, 60.0).system,
     "frequency 2 of quarter car=60"),
    ("an ISO fit of waviness 4.8",
     lambda: vbi.fit_iso8608(vbi.Profile.iso8608(2000.0, 0.05, c10=1e-4, waviness=4.8, seed=2)),
     "fitted waviness="),
]  # fmt: skip


@pytest.mark.parametrize(("name", "call", "says"), SOFT, ids=[s[0] for s in SOFT])
def test_outside_the_intended_range_warns_by_name(name: str, call: Callable, says: str) -> None:
    with pytest.warns(vbi.OutsideValidityWarning) as caught:
        result = call()
    messages = " | ".join(str(w.message) for w in caught)
    assert says in messages and "outside the intended range" in messages, messages
    notes = getattr(result, "notes", None)
    if notes is not None and "dt=" not in says:  # a crossing also says so in its notes
        assert any(says.split("=")[0] in n for n in notes), notes


# ---------------------------------------------------------------------------- garbage, fixed
def test_a_span_never_pushed_down_has_no_daf_and_says_why() -> None:
    """Reference: the bridge's own midspan history over the whole run.  On a flexible
    two-span bridge (0.8 Hz) at 30 m/s, the one-coordinate beam's span 2 (``-z_b``) only
    rises: the first span's swing lifts it (the contact force stays compressive), and its
    DAF, once printed negative, is NaN with a note.  The modal beam's symmetric mode dips
    span 2 a little while the truck is on span 1: its DAF is that dip over its static,
    small and positive, never negative."""
    bridge = vbi.Bridge.from_frequency(10.0, 2, 5000.0, 0.8)
    vehicle = vbi.Vehicle.from_frequency(5000.0, 3.0, 0.2)
    road = vbi.Profile.flat(100.0, 0.05)
    for options in ({}, {"model": "modal", "modes": 4}):
        with warnings.catch_warnings():
            warnings.simplefilter("error", vbi.ContactLossWarning)
            run = vbi.simulate(bridge, vehicle, road, 30.0, 30.0, **options)
            batch = vbi.simulate_many(bridge, vehicle, road, [30.0, 10.0], 30.0, **options)
        assert np.isfinite(run.daf[0]) and run.daf[0] > 0
        dip = -run.midspan_displacement[:, 1].min()  # the largest downward value, if any
        if options:
            static = run.static_deflection  # two equal spans: both midspans' statics alike
            assert 0 < dip < 0.1 * static
            assert run.daf[1] == pytest.approx(dip / static, rel=1e-2)  # refined in a step
            assert batch.daf[0, 1] == pytest.approx(run.daf[1], rel=1e-9)
        else:
            assert dip <= 0  # it only rose
            assert np.isnan(run.daf[1])
            assert any("span 2 was never pushed down" in n for n in run.notes)
            assert np.isnan(batch.daf[0, 1])
        assert np.isfinite(batch.daf[1]).all()
        assert not (batch.daf < 0).any()


def test_iri_segments_are_never_nan() -> None:
    """The issue: a 100.1 m road in 10 m segments gave NaN for the last 0.1 m."""
    road = vbi.Profile.harmonic(100.1, 0.05, 10.0, 0.001)
    result = vbi.iri(road, segment_length=10.0)
    assert len(result) == 10 and np.isfinite(result.segment_iri).all()
    assert result.stop[-1] == pytest.approx(100.1)


def test_a_failing_row_keeps_the_others_and_names_itself() -> None:
    """A row that passes the checks but fails when run (too many time steps for its dt)
    keeps NaN results and its reason; the other rows equal a run without it."""
    scenarios = pd.concat([table(), table(speed=0.3)], ignore_index=True)  # rows 0..3
    with pytest.warns(vbi.validity.FailedRowsWarning, match=r"1 of 4 crossings failed.*row 3"):
        result = studies.run(scenarios, "serial", dt=1e-5, chunk_size=2)
    assert result["error"].isna().tolist() == [True, True, True, False]
    assert "at most" in result["error"][3] and "dt=1e-05" in result["error"][3]
    assert np.isnan(result["daf"][3]) and np.isfinite(result["daf"][:3]).all()
    alone = studies.run(scenarios.iloc[:3], "serial", dt=1e-5)
    pd.testing.assert_series_equal(result["daf"][:3], alone["daf"])


def test_a_declared_count_is_never_allocated(tmp_path: Path) -> None:
    """A header declaring 10^12 samples and 2x10^8 channels: the error names what the file
    holds, and nothing the size of the declaration was made (tracemalloc's peak)."""
    import tracemalloc

    path = tmp_path / "huge.erd"
    path.write_text(erd("200000000", "1000000000000"))
    tracemalloc.start()
    try:
        with pytest.raises(ProfileFileError):
            vbi.read_erd(path)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 10e6


# ---------------------------------------------------------------------------- dead workers
@dataclass(frozen=True)
class WorkerKiller:
    """A road recipe whose worker process dies when it builds it: ``kill -9`` of itself, as
    the out-of-memory killer does (in the test's own process it builds a flat road, so that
    ``studies.validate`` can try it)."""

    start: float = 0.0
    end: float = 200.0
    label: str = "kills its worker"

    def build(self) -> vbi.Profile:
        import multiprocessing
        import os
        import signal

        if multiprocessing.parent_process() is not None:
            os.kill(os.getpid(), signal.SIGKILL)
        return vbi.Profile.flat(self.end - self.start, 0.05, self.start)


@dataclass(frozen=True)
class MarkedRoad:
    """A flat road recipe that, built in a worker, leaves a file behind and takes a while
    (so that a test knows when the workers are busy)."""

    folder: str
    key: int
    start: float = 0.0
    end: float = 200.0
    label: str = "marked"

    def build(self) -> vbi.Profile:
        import multiprocessing
        import time

        if multiprocessing.parent_process() is not None:
            (Path(self.folder) / f"built-{self.key}").touch()
            time.sleep(0.3)
        return vbi.Profile.flat(self.end - self.start, 0.05, self.start)


def _spawn_pool(workers: int = 2) -> object:
    import concurrent.futures as cf
    import multiprocessing

    return cf.ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("spawn"))


def _marked_study(folder: Path, count: int) -> pd.DataFrame:
    roads = [MarkedRoad(str(folder), k) for k in range(count)]
    return pd.DataFrame([
        {"bridge": bridge(), "vehicle": truck(), "profile": r, "speed": 20.0, "bridge_start": 50.0}
        for r in roads
    ])  # fmt: skip


def _kill_when_busy(pids: Callable[[], list[int]], folder: Path, built: int) -> object:
    """A thread that kills one worker with SIGKILL once ``built`` roads were built."""
    import os
    import signal
    import threading
    import time

    def kill() -> None:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            if len(list(folder.glob("built-*"))) >= built and pids():
                os.kill(pids()[0], signal.SIGKILL)
                return
            time.sleep(0.05)

    thread = threading.Thread(target=kill, daemon=True)
    thread.start()
    return thread


def test_a_worker_killed_once_loses_no_row(tmp_path: Path) -> None:
    """kill -9 of one pool worker while it holds chunks (takes about 20 s: three pools
    start).  Reference: the same study run serially; every row is kept and equal."""
    table = _marked_study(tmp_path, 16)
    pool = _spawn_pool()
    try:
        thread = _kill_when_busy(lambda: list(pool._processes), tmp_path, 3)
        with pytest.warns(vbi.validity.WorkerLostWarning) as caught:
            result = studies.run(table, pool, chunk_size=2)
        thread.join(1)
    finally:
        pool.shutdown(cancel_futures=True)
    message = " | ".join(str(w.message) for w in caught)
    assert "worker" in message and "killed by signal 9" in message, message
    assert "perhaps out of memory" in message and "__main__" not in message, message
    assert "error" not in result.columns
    serial = studies.run(table, "serial")
    pd.testing.assert_frame_equal(result, serial)


def test_a_chunk_whose_worker_dies_twice_keeps_nan_and_the_reason() -> None:
    """A row whose road kills its worker each time: run again once, alone, then NaN with the
    reason; the other rows finish (about 20 s)."""
    rows = [{"profile": studies.FlatProfile(200.0, 0.05), "speed": s} for s in (15.0, 20.0)]
    table = pd.DataFrame([
        {"bridge": bridge(), "vehicle": truck(), "bridge_start": 50.0, **r}
        for r in (rows[0], {"profile": WorkerKiller(), "speed": 18.0}, rows[1])
    ])  # fmt: skip
    pool = _spawn_pool()
    try:
        with (
            pytest.warns(vbi.validity.WorkerLostWarning, match="perhaps out of memory"),
            pytest.warns(vbi.validity.FailedRowsWarning, match="1 of 3 crossings failed"),
        ):
            result = studies.run(table, pool, chunk_size=1)
    finally:
        pool.shutdown(cancel_futures=True)
    assert result["error"].isna().tolist() == [True, False, True]
    reason = result["error"][1]
    assert "again when it ran alone" in reason and "killed by signal 9" in reason, reason
    assert "perhaps out of memory" in reason and "__main__" not in reason
    assert np.isnan(result["daf"][1]) and np.isfinite(result["daf"][[0, 2]]).all()
    alone = studies.run(table.iloc[[0, 2]], "serial")
    np.testing.assert_array_equal(result["daf"][[0, 2]], alone["daf"])


def test_a_dask_worker_killed_is_rescheduled(tmp_path: Path) -> None:
    """kill -9 of a worker of a Dask LocalCluster: the cluster reruns its tasks; a row that
    kills every worker that runs it gets the reason once the cluster gives up."""
    distributed = pytest.importorskip("dask.distributed")
    import dask

    table = _marked_study(tmp_path, 12)
    with (
        dask.config.set({"distributed.scheduler.allowed-failures": 1}),
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        thread = _kill_when_busy(lambda: list(client.run(__import__("os").getpid).values()),
                                 tmp_path, 3)  # fmt: skip
        result = studies.run(table, client.get_executor(), chunk_size=2)
        thread.join(1)
        assert not thread.is_alive()
        assert "error" not in result.columns
        pd.testing.assert_frame_equal(result, studies.run(table, "serial"))
        killer = pd.concat([table.iloc[:1], table.iloc[:1].assign(profile=[WorkerKiller()])],
                           ignore_index=True)  # fmt: skip
        with pytest.warns(vbi.validity.FailedRowsWarning):
            lost = studies.run(killer, client.get_executor(), chunk_size=1)
    assert lost["error"].isna().tolist() == [True, False]
    assert "workers died" in lost["error"][1] and "perhaps out of memory" in lost["error"][1]


# ---------------------------------------------------------------------------- files read
@pytest.mark.parametrize(
    ("data", "name"),
    [
        ("0,0\n10,0.5\n".encode("utf-16"), "UTF-16 with a byte-order mark"),
        (b"\xfe\xff" + "0,0\n10,0.5\n".encode("utf-16-be"), "UTF-16 big-endian"),
        ("0,0\n10,0.5\n".encode("utf-16-le"), "UTF-16 without a byte-order mark"),
        (b"\xef\xbb\xbf0,0\r\n10,0.5\r\n", "UTF-8 with a byte-order mark"),
        (b"0;0\n10;0,5\n", "decimal commas, columns split by semicolons"),
        (b"0\t0\n10\t0,5\n", "decimal commas, columns split by a tab"),
        (b"# station elevation\n0 0\n10 0,5\n", "decimal commas, columns split by spaces"),
    ],
    ids=lambda v: v if isinstance(v, str) else "",
)
def test_utf16_and_decimal_commas_are_read(tmp_path: Path, data: bytes, name: str) -> None:
    path = tmp_path / "p.csv"
    path.write_bytes(data)
    road = vbi.read_profile(path, unit="m")
    np.testing.assert_array_equal(road.x, [0.0, 10.0])
    np.testing.assert_array_equal(road.elevation, [0.0, 0.5])


def test_decimal_says_which_mark_an_ambiguous_file_uses(tmp_path: Path) -> None:
    """``1,5`` lines: one column of decimal commas, or two columns of whole numbers."""
    path = tmp_path / "p.csv"
    path.write_text("10,5\n20,5\n30,7\n")
    with pytest.warns(vbi.OutsideValidityWarning, match="unevenness 0.667 m"):
        pairs = vbi.read_profile(path, unit="m", decimal=".")  # a 2 m step: no road
    np.testing.assert_array_equal(pairs.x, [10.0, 20.0, 30.0])
    np.testing.assert_array_equal(pairs.elevation, [5.0, 5.0, 7.0])
    path.write_text("1,5 0,25\n12,5 0,5\n")
    commas = vbi.read_profile(path, unit="m", decimal=",")
    np.testing.assert_array_equal(commas.x, [1.5, 12.5])
    np.testing.assert_array_equal(commas.elevation, [0.25, 0.5])


def test_a_utf16_erd_file_reads_as_its_utf8_twin(tmp_path: Path) -> None:
    text = erd("1", "3")
    (tmp_path / "a.erd").write_text(text)
    (tmp_path / "b.erd").write_text(text, encoding="utf-16")
    a, b = vbi.read_erd(tmp_path / "a.erd"), vbi.read_erd(tmp_path / "b.erd")
    np.testing.assert_array_equal(a[0].elevation, b[0].elevation)
    assert a.header == b.header


def test_the_size_cap_is_stated_and_can_be_raised(tmp_path: Path) -> None:
    from vbi_lib._files import MAX_FILE_BYTES, read_text

    assert MAX_FILE_BYTES == 100 * 2**20
    path = tmp_path / "p.csv"
    path.write_text("0,0\n9,0.5\n")
    with pytest.raises(ProfileFileError, match="holds 10 bytes, more than max_bytes=9"):
        vbi.read_profile(path, unit="m", max_bytes=9)
    assert vbi.read_profile(path, unit="m", max_bytes=10).x.size == 2
    assert read_text(path, "profile.file", 10) == "0,0\n9,0.5\n"  # the helper for reports
    with pytest.raises(ValueError, match="^profile.file='.*' is a directory"):
        read_text(tmp_path, "profile.file")


# ---------------------------------------------------------------------------- given roads
def _deck(unit: str, tmp_path: Path) -> vbi.Profile:
    """A 40 m deck sampled every 25 mm with a 25 mm joint at 20 m, written in millimetres,
    read with ``unit``."""
    lines = [f"{25 * i},{0 if i < 800 else 25}" for i in range(1601)]
    (tmp_path / "deck.csv").write_text("\n".join(lines) + "\n")
    return vbi.read_profile(tmp_path / "deck.csv", unit=unit, decimal=".")  # whole numbers


def _crossings(road: vbi.Profile) -> dict[str, object]:
    """A crossing of each vehicle model over a 10 m span that starts 20 m down ``road``
    (a 16 m approach holds the HS20 wholly)."""
    bridge = vbi.Bridge(10.0, 1, 2e9, 5e3)
    cars = {"sprung mass": truck(), "quarter car": QuarterCar.from_frequencies(
        4e3, 500.0, 1.5, 12.0), "HS20": hs20(14 * vbi.units.ft)}  # fmt: skip
    out = {}
    for name, car in cars.items():
        for model in ("one-coordinate", "modal"):
            out[f"{name}, {model}"] = vbi.simulate(
                bridge, car, road, 10.0, 16.0, model=model, modes=3 if model == "modal" else None
            )
    return out


def test_a_deck_in_mm_read_as_metres_is_named_and_every_crossing_says_so(tmp_path: Path) -> None:
    """The issue's case: the 25 mm joint becomes a 25 m wall.  Reference: the same file read
    in millimetres, a plausible deck that warns of nothing."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.OutsideValidityWarning)
        _deck("mm", tmp_path)  # plausible: no warning
    with pytest.warns(vbi.OutsideValidityWarning) as caught:
        wall = _deck("m", tmp_path)
    message = " | ".join(str(w.message) for w in caught)
    assert "read_profile: profile 'deck' is not a plausible road" in message
    assert "beyond the largest 1 m (a 1 m obstacle is a wall" in message
    assert "millimetres read as metres" in message
    assert "unit slip of both columns" in message and "unit='mm'" in message, message
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.VbiWarning)  # the 25 m sampling is warned of too
        warnings.filterwarnings("error", ".*plausible road", vbi.OutsideValidityWarning)
        runs = _crossings(wall)  # warned once, when read
    for name, run in runs.items():
        assert any("'deck' is not a plausible road" in n for n in run.notes), name


@pytest.mark.filterwarnings("ignore::vbi_lib.ContactLossWarning")  # the truck flies off the kerb
def test_a_profile_built_from_arrays_is_warned_of_by_its_first_crossing() -> None:
    x = np.arange(0.0, 60.0, 0.025)
    road = vbi.Profile(x, np.where((x > 25.0) & (x < 25.3), 0.8, 0.0), name="kerb in m")
    with pytest.warns(vbi.OutsideValidityWarning, match="'kerb in m' is outside the intended"):
        first = vbi.simulate(vbi.Bridge(10.0, 1, 2e9, 5e3), truck(), road, 10.0, 20.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.OutsideValidityWarning)  # not twice
        # a point contact on a 0.8 m kerb sampled at 25 mm: its damper force is set by the
        # sampling, which every crossing says (h20's UnresolvedRoadWarning); not asserted here
        warnings.simplefilter("ignore", vbi.validity.UnresolvedRoadWarning)
        batch = vbi.simulate_many(vbi.Bridge(10.0, 1, 2e9, 5e3), truck(), road, [10.0], 20.0)
    assert any("unevenness 0.7" in n for n in first.notes), first.notes
    assert np.isfinite(batch.daf[0, 0])


def test_the_study_s_data_profiles_are_plausible(shared_data: Path) -> None:
    """Reference: the files' stated units (../shared/data READMEs); none may be warned of."""
    from vbi_lib.road_checks import road_notes

    folder = shared_data / "profiles"
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.OutsideValidityWarning)
        roads = [vbi.read_profile(folder / f"i76-span{k}.csv", "in") for k in range(2, 7)]
        roads.append(vbi.read_profile(folder / "sorel-profile-1.txt", "m"))
        roads += list(vbi.read_erd(folder / "basic-2channel.erd"))
        for path in sorted((shared_data / "seed-study" / "profiles").glob("*.csv")):
            roads.append(vbi.read_profile(path, "in"))
    assert len(roads) == 23 and not any(road_notes(r) for r in roads)


def test_a_deck_with_elevations_in_inches_read_as_metres_is_named(shared_data: Path) -> None:
    """The I-76 deck with its elevations (inches) read in metres: 39 times too large, outside
    every intended range at once."""
    with pytest.warns(vbi.OutsideValidityWarning) as caught:
        vbi.read_profile(shared_data / "profiles" / "i76-span2.csv", "in", elevation_unit="m")
    message = " | ".join(str(w.message) for w in caught)
    assert "unit slip of the elevations" in message, message
    assert "inches read as metres (39.37 times too large: elevation_unit='in')" in message


# ---------------------------------------------------------------------------- vehicle notes
VEHICLE_NOTES = [
    ("a 0.6 m footprint", lambda: QuarterCar.from_frequencies(4e3, 500.0, 1.5, 12.0,
                                                              footprint=0.6), "footprint=0.6"),
    ("an 8 kg wheel", lambda: QuarterCar.from_frequencies(300.0, 8.0, 1.5, 12.0),
     "unsprung_mass=8"),
    ("an axle 40 m behind the first", lambda: vbi.vehicles.IndependentAxles(
        [Axle(0.0, 1e5, 4e6, 2e4), Axle(40.0, 1e5, 4e6, 2e4)]), "axle 2: offset=40"),
    ("a tyre of 8 kg on a truck", lambda: vbi.vehicles.RigidTruck(
        [Axle(0.0, 6e4, 3e5, 1e4), Axle(5.0, 1.4e5, 7e5, 2e4, Tyre(8.0, 1e6))], 1.2e5),
     "axle 2: unsprung_mass=8"),
    ("an HS20 damped at 60 %", lambda: hs20(suspension_damping_ratio=0.6),
     "suspension_damping_ratio=0.6"),
    ("a sprung mass of 50 kg", lambda: vbi.Vehicle.from_frequency(50.0, 3.0, 0.1), "mass=50"),
    ("a convoy with a heavy second truck", lambda: Convoy(
        [truck(), vbi.Vehicle.from_frequency(3e5, 3.0, 0.1)], [30.0]), "vehicle 2: mass=300000"),
]  # fmt: skip


@pytest.mark.parametrize(("name", "make", "says"), VEHICLE_NOTES, ids=[v[0] for v in VEHICLE_NOTES])
def test_what_a_vehicle_warned_of_is_in_every_result(name: str, make: Callable, says: str) -> None:
    """Whatever a vehicle's constructors warn of is a note of every crossing (both models)
    and a column of every study (with sections or not)."""
    with pytest.warns(vbi.OutsideValidityWarning) as caught:
        vehicle = make()
        vbi.vehicles.as_system(vehicle)
    warned = " | ".join(str(w.message) for w in caught)
    assert says.split(": ")[-1] in warned, warned
    road = vbi.Profile.flat(200.0, 0.05)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.VbiWarning)
        for model in ("one-coordinate", "modal"):
            run = vbi.simulate(bridge(), vehicle, road, 20.0, 60.0, model=model,
                               modes=3 if model == "modal" else None)  # fmt: skip
            assert any(says in n for n in run.notes), (model, run.notes)
        table = studies.grid(bridge(), vehicle, road, [20.0, 25.0], 60.0)
        for sections in (None, [15.0]):
            result = studies.run(table, "serial", sections=sections)
            assert result["vehicle_notes"].str.contains(says, regex=False).all(), sections


def test_a_vehicle_inside_every_range_has_no_notes() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.OutsideValidityWarning)
        for vehicle in (truck(), hs20(), QuarterCar.from_frequencies(4e3, 500.0, 1.5, 12.0)):
            assert vbi.vehicles.as_system(vehicle).notes == ()
        run = vbi.simulate(bridge(), hs20(), vbi.Profile.flat(200.0, 0.05), 20.0, 60.0)
    assert not any("outside the intended" in n for n in run.notes)


# ---------------------------------------------------------------------------- smaller ones
def test_free_vibration_past_the_end_of_the_road_is_noted() -> None:
    road = vbi.Profile.harmonic(90.0, 0.05, 10.0, 0.005)
    inside = simulate({"free_vibration": 0.2}, profile=road, bridge_start=50.0)
    assert not any("past the end of the road" in n for n in inside.notes)
    past = simulate({"free_vibration": 2.0}, profile=road, bridge_start=50.0)
    note = next(n for n in past.notes if "past the end of the road" in n)
    assert "went 30 m past" in note and "free_vibration=2 s" in note, note
    assert past.position[-1] == pytest.approx(120.0)


def test_a_bridge_at_exactly_the_frequency_limit_is_accepted() -> None:
    """1000 Hz is allowed; the EI computed from it lands an ulp above and was refused,
    blaming the units.  Just beyond the limit the message asks for another EI or mass."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.OutsideValidityWarning)
        for span in (1.0, 7.3, 30.0, 100.0):
            beam = vbi.Bridge.from_frequency(span, 1, 8000.0, 1000.0)
            assert beam.first_frequency_hz == pytest.approx(1000.0, rel=1e-12)
        for span in (7.3, 30.0, 100.0):
            low = vbi.Bridge.from_frequency(span, 1, 8000.0, 0.05)
            assert low.first_frequency_hz == pytest.approx(0.05, rel=1e-12)
        with pytest.raises(ValueError, match="first_frequency_hz=1000.5") as near:
            vbi.Bridge(30.0, 1, 8000.0 * (2 * math.pi * 1000.5) ** 2 * 30.0**4 / math.pi**4,
                       8000.0)  # fmt: skip
        assert "units" not in str(near.value) and "adjust EI" in str(near.value)
        with pytest.raises(ValueError, match="check their units"):
            vbi.Bridge(30.0, 1, 1e18, 1.0)


def test_a_long_mode_search_or_crossing_is_announced(monkeypatch: pytest.MonkeyPatch) -> None:
    """The estimate warns before the work: a mode search whose timed pieces (a count, a
    determinant, an SVD with its quadrature) take 50 ms each (monkeypatched: on the shared
    machine they take 1 to 300 ms with its load), and a modal crossing of 2e6 steps with 200
    modes (estimated 100 s: nothing runs past the warning, which the test makes an error)."""
    from vbi_lib import costs

    monkeypatch.setattr(costs, "_slowest", lambda work: 0.05)  # each piece of work: 50 ms
    spans = [20.0 + i % 3 for i in range(50)]
    with pytest.warns(vbi.validity.CostWarning, match=r"50 spans, 200 of them.*about 4 min"):
        costs.warn_mode_search(spans, 200)  # 200 x (1 + 12 + 9) x 50 ms = 220 s
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.validity.CostWarning)
        costs.warn_mode_search(spans[:2], 200)  # two spans: seconds, not timed
        with pytest.raises(vbi.validity.CostWarning, match=r"2,000,001 time steps, 200 modes"):
            simulate({"model": "modal", "modes": 200, "dt": 2e-6})
        with pytest.raises(vbi.validity.CostWarning, match="finding the exact modes of 50"):
            vbi.modes.beam_modes(vbi.Bridge.continuous(spans, EI=1e10, mass_per_length=5e3), 199)
