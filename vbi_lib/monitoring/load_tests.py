"""DAF from a load test: runs at speed divided by crawl runs or a parked truck (study eq. 17).

With the bridge closed to traffic, a truck of known weight crawls across (or parks at the
critical position) to give each gauge's static response :math:`Q_{sta}`, then crosses at
speed to give dynamic peaks :math:`Q_{dyn}`; ``DAF = Q_dyn / Q_sta`` (17) per gauge, speed and
run.  The loading direction of each gauge (tension up, deflection down) is the sign of its
static response, and the dynamic peak is taken in that direction.

Limits: each record is assumed to hold one truck's crossing and the same gauge zero as the
static runs (or the first ``zero_samples`` before the truck arrives define it).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
import pandas as pd

from .filtering import _record


def _runs(name: str, value: object) -> list[np.ndarray]:
    """A record, a list of records, or a single number (a parked-truck reading)."""
    if isinstance(value, list | tuple):
        runs = list(value)
    elif np.ndim(value) == 2:
        runs = list(np.asarray(value, dtype=float))
    else:
        runs = [value]
    if not runs:
        raise ValueError(f"{name} holds no runs")
    out = []
    for j, run in enumerate(runs):
        label = f"{name}[{j}]" if len(runs) > 1 else name
        array = np.atleast_1d(np.asarray(run, dtype=float))
        out.append(_record(label, array))
    return out


def daf_from_load_test(
    static_runs: Mapping[str, object],
    dynamic_runs: Mapping[float, Mapping[str, object]],
    zero_samples: int = 0,
) -> pd.DataFrame:
    """DAF per gauge, speed and run from a load test with the bridge closed to traffic.

    The static response of each gauge is the mean, over its crawl runs, of each run's
    extreme (or a parked-truck reading given as a number); its sign sets the gauge's loading
    direction.  Each run at speed gives ``DAF = dynamic peak / static response``, the peak
    taken in the same direction.

    Parameters
    ----------
    static_runs
        ``{gauge: record, list of records, or a number}`` from crawl runs or a parked truck.
    dynamic_runs
        ``{speed: {gauge: record or list of records}}`` from runs at speed; speed in m/s
        (any label works, it is copied to the table).
    zero_samples
        If > 0, each record is zeroed by the mean of its first ``zero_samples`` samples
        (taken before the truck arrives); parked-truck numbers are used as given.

    Returns
    -------
    pandas.DataFrame
        Columns ``gauge, speed, run, static, dynamic_peak, daf``; use
        ``.groupby(["gauge", "speed"]).daf.max()`` for the largest per gauge and speed.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> crawl = -2.0 * np.sin(np.pi * t)                  # deflection, mm, downward
    >>> fast = crawl * (1 + 0.25 * np.sin(np.pi * t))     # crests 25 % higher at midspan
    >>> table = daf_from_load_test({"G1": crawl}, {20.0: {"G1": fast}})
    >>> table[["gauge", "speed", "static", "dynamic_peak", "daf"]].to_dict("records")
    [{'gauge': 'G1', 'speed': 20.0, 'static': -2.0, 'dynamic_peak': -2.5, 'daf': 1.25}]
    """
    zero_samples = int(zero_samples)
    if zero_samples < 0:
        raise ValueError(f"zero_samples={zero_samples!r} must be >= 0")
    if not static_runs:
        raise ValueError("static_runs is empty: give at least one gauge's crawl run or reading")

    def zeroed(run: np.ndarray, label: str) -> np.ndarray:
        if zero_samples == 0 or run.size == 1:
            return run
        if run.size <= zero_samples:
            raise ValueError(
                f"{label} has {run.size} samples, not more than zero_samples={zero_samples}"
            )
        return run - run[:zero_samples].mean()

    static = {}
    for gauge, value in static_runs.items():
        peaks = []
        for j, run in enumerate(_runs(f"static_runs[{gauge!r}]", value)):
            run = zeroed(run, f"static_runs[{gauge!r}][{j}]")
            peaks.append(run[np.argmax(np.abs(run))])
        response = float(np.mean(peaks))
        if response == 0 or np.any(np.sign(peaks) != np.sign(response)):
            raise ValueError(
                f"static_runs[{gauge!r}] gives static peaks {peaks} that are zero or of mixed "
                "sign; check the gauge's zero and sign"
            )
        static[gauge] = response
    rows = []
    for speed, gauges in dynamic_runs.items():
        for gauge, value in gauges.items():
            if gauge not in static:
                raise ValueError(
                    f"dynamic_runs[{speed!r}] has gauge {gauge!r} with no static response; "
                    f"static_runs has {sorted(static)}"
                )
            direction = math.copysign(1.0, static[gauge])
            for j, run in enumerate(_runs(f"dynamic_runs[{speed!r}][{gauge!r}]", value)):
                run = zeroed(run, f"dynamic_runs[{speed!r}][{gauge!r}][{j}]")
                peak = direction * float(np.max(direction * run))
                rows.append(
                    {
                        "gauge": gauge,
                        "speed": speed,
                        "run": j,
                        "static": static[gauge],
                        "dynamic_peak": peak,
                        "daf": peak / static[gauge],
                    }
                )
    if not rows:
        raise ValueError("dynamic_runs holds no runs at speed")
    return pd.DataFrame(rows)


__all__ = ["daf_from_load_test"]
