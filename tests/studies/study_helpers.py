"""Helpers of the study tests: an executor that counts tasks and a small mixed study."""

from __future__ import annotations

import concurrent.futures as cf

import pandas as pd

import vbi_lib as vbi
from vbi_lib import studies
from vbi_lib import units as u


class CountingExecutor(cf.Executor):
    """Runs tasks in this process and counts them (to prove no work started)."""

    def __init__(self) -> None:
        self.submitted = 0

    def submit(self, fn, /, *args, **kwargs):  # noqa: ANN001, ANN201
        self.submitted += 1
        future: cf.Future = cf.Future()
        future.set_result(fn(*args, **kwargs))
        return future


def small_study() -> pd.DataFrame:
    """Mixed grid: one- and two-span bridges, two trucks, harmonic and ISO roads, offsets."""
    bridges = {
        "one span": vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * u.lbf / u.inch, 3.99),
        "two spans": vbi.Bridge.from_midspan_stiffness(
            100 * u.ft, 2, 668815 * u.lbf / u.inch, 3.99
        ),
    }
    trucks = studies.parametric_trucks((2.5, 4.0))
    length = 200 * u.ft + 200 * u.ft + 10 * u.ft
    profiles = {
        "harmonic": studies.HarmonicProfile(length, 1 * u.inch, 30 * u.ft, 0.25 * u.inch),
        "iso": studies.ISOProfile(length, 1 * u.inch, c10=300e-6, seed=7),
    }
    return studies.grid(
        bridges,
        trucks,
        profiles,
        [15.0, 25.0],
        200 * u.ft,
        profile_offsets=[0.0, 10 * u.ft],
        coupled=[True, False],
    )
