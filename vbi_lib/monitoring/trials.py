r"""Field methods tried on simulated crossings, whose true DAF is known.

A field test never knows the true DAF of a passing truck; a simulation does (divide the
crossing's peak by a crawl run of the same truck).  The trials below run a method on many
simulated crossings and set its estimate beside the truth, one row per crossing:

* :func:`crawl_static`: the true static response, the largest midspan deflection of the
  same vehicle crawling over a flat road (the denominator of the true DAF, study
  equation 17);
* :func:`gauge_trial`: the DAF a displacement gauge and a strain gauge (the midspan moment)
  read on the same crossings, with one beam mode or many (equations 25-31 of the study say
  the displacement reads more while the first mode dominates);
* :func:`filter_trial`: the low-pass estimate of :func:`~vbi_lib.monitoring.daf_from_record`
  on clean records and on records with gauge noise and drift, against the true DAF;
* :func:`strain_trial`: the same on strain (midspan moment) records, by the filter and by
  the influence-line fit;
* :func:`load_test_trial`: a load test simulated gauge by gauge, a crawl run and passes at
  speed along several wheel paths, read by :func:`~vbi_lib.monitoring.daf_from_load_test`.

Every row keeps ``lost contact``: a crossing whose tyre would have pulled the road down is
outside the model's validity as a picture of a real bridge, though a method is still judged
fairly against the true DAF of the same simulated record.
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence

import numpy as np
import pandas as pd

from .. import _validation as check
from ..bridges import Bridge
from ..models import simulate
from ..profiles import Profile
from ..validity import ContactLossWarning
from .load_tests import daf_from_load_test
from .records import daf_from_record
from .synthetic import record_from_crossing

__all__ = [
    "CRAWL_SPEED",
    "GAUGE_EFFECTS",
    "crawl_static",
    "filter_trial",
    "gauge_trial",
    "load_test_trial",
    "strain_trial",
]

#: Speed of a crawl run [m/s]: walking pace, far too slow to excite any bridge.
CRAWL_SPEED = 0.5
#: What a gauge of :func:`load_test_trial` can read, and the display quantity of its unit.
GAUGE_EFFECTS = {"deflection": "deflection", "moment": "moment"}


def _speeds(speeds: float | Sequence[float]) -> np.ndarray:
    values = np.atleast_1d(np.asarray(speeds, dtype=float))
    if values.ndim != 1 or values.size == 0:
        raise ValueError(f"speeds={speeds!r} must be one speed or a list of speeds [m/s]")
    for v in values:
        check.positive("speed", v)
    return values


def _runs(bridge: Bridge, vehicle: object, road: Profile, speeds: np.ndarray,
          bridge_start: float, **options: object) -> list:  # fmt: skip
    """One crossing per speed; contact loss is reported in the rows, not warned of."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ContactLossWarning)
        return [simulate(bridge, vehicle, road, v, bridge_start, **options) for v in speeds]


def crawl_static(bridge: Bridge, vehicle: object, **options: object) -> float:
    """Largest static deflection at midspan of span 1 [m, a magnitude], by a crawl run.

    The vehicle crawls at :data:`CRAWL_SPEED` over a flat road that starts 1 m before the
    bridge and ends 1 m after it: the static response a load test measures.

    Parameters
    ----------
    bridge, vehicle
        As :func:`vbi_lib.simulate`.
    options
        Keyword options of :func:`vbi_lib.simulate` (e.g. ``model="modal", modes=20``).

    Examples
    --------
    >>> import vbi_lib as vbi
    >>> bridge = vbi.Bridge(20.0, 1, 4e9, 6000.0)
    >>> truck = vbi.Vehicle.from_frequency(2e4, 4.0, 0.1)
    >>> static = crawl_static(bridge, truck)
    >>> round(static / bridge.static_deflection(truck.weight), 3)  # the model's P / k*
    1.0
    """
    road = Profile.flat(bridge.length + 2.0 + 0.05, 0.05)
    run = _runs(bridge, vehicle, road, np.array([CRAWL_SPEED]), 1.0, **options)[0]
    return float(-run.midspan_displacement[:, 0].min())


def gauge_trial(
    bridge: Bridge,
    vehicle: object,
    road: Profile,
    speeds: float | Sequence[float],
    bridge_start: float,
    *,
    modes: Sequence[int] = (1, 20),
) -> pd.DataFrame:
    """The midspan DAF of a displacement gauge and of a strain gauge, by number of modes.

    Each crossing runs with the many-mode model (``model="modal"``) and each number of
    ``modes``; :meth:`vbi_lib.Crossing.sections` at midspan of span 1, with the
    mode-displacement method (the modes' deflections and curvatures summed, as in the
    study's equations 29-30), gives the DAF of the deflection and of the moment, each over
    its own static extreme.

    Returns
    -------
    pandas.DataFrame
        One row per number of modes and speed: ``modes``, ``speed`` [m/s],
        ``displacement`` and ``moment`` (their DAFs) and ``lost contact``.
    """
    speeds = _speeds(speeds)
    rows = []
    for n in modes:
        runs = _runs(bridge, vehicle, road, speeds, bridge_start, model="modal", modes=int(n))
        for v, run in zip(speeds, runs, strict=True):
            daf = run.sections(bridge.span / 2, method="mode-displacement").daf[:2, 0]
            rows.append({"modes": int(n), "speed": v, "displacement": daf[0],
                         "moment": daf[1], "lost contact": run.lost_contact})  # fmt: skip
    return pd.DataFrame(rows)


def filter_trial(
    bridge: Bridge,
    vehicle: object,
    road: Profile,
    speeds: float | Sequence[float],
    bridge_start: float,
    *,
    sample_rate_hz: float,
    noise: float = 0.02,
    drift: float = 0.10,
    seed: int = 2,
    free_vibration: float = 6.0,
    smoothing: float = 3.0,
) -> pd.DataFrame:
    """The filter's DAF estimate of deflection records against the true DAF.

    Each crossing (the one-coordinate model, with ``free_vibration`` seconds of free
    vibration for the first-frequency estimate) becomes a record of the midspan deflection
    of span 1 at ``sample_rate_hz`` (:func:`~vbi_lib.monitoring.record_from_crossing`),
    clean and with white noise of ``noise`` times the static deflection and a drift of
    ``drift`` times it.  :func:`~vbi_lib.monitoring.daf_from_record` estimates the DAF of
    the clean records from the speed and span alone (it finds the first frequency in the
    record's tail), and of the noisy records with the bridge's first frequency given, raw
    and smoothed above ``smoothing`` times it (``noise_cutoff_hz``).  The estimates' doubts
    are kept in the rows (``doubtful``) instead of warnings.

    Returns
    -------
    pandas.DataFrame
        One row per speed: ``speed`` [m/s], ``f_load / f1`` (loading over first
        frequency), ``true DAF`` (the record's peak over :func:`crawl_static`), the
        estimates ``clean record``, ``noisy record`` and ``noisy, smoothed``, ``f1
        estimated`` [Hz] (from the clean record), ``filtered peak / static`` (the clean
        record's low-passed peak over the true static deflection), ``doubtful`` (the
        clean estimate flagged) and ``lost contact``.
    """
    speeds = _speeds(speeds)
    fs = check.positive("sample_rate_hz", sample_rate_hz)
    static = crawl_static(bridge, vehicle)
    runs = _runs(bridge, vehicle, road, speeds, bridge_start, free_vibration=free_vibration)
    clean = [record_from_crossing(r, fs)[1] for r in runs]
    gauge = {"noise_std": noise * static, "drift": drift * static, "seed": seed}
    noisy = [record_from_crossing(r, fs, **gauge)[1] for r in runs]
    known = {"speed": speeds, "span": bridge.span}
    f1 = bridge.first_frequency_hz
    with warnings.catch_warnings():  # the doubts are in the rows (doubtful), not warnings
        warnings.simplefilter("ignore", UserWarning)
        estimate = daf_from_record(clean, fs, **known)
        raw = daf_from_record(noisy, fs, **known, first_frequency_hz=f1)
        smooth = daf_from_record(noisy, fs, **known, first_frequency_hz=f1,
                                 noise_cutoff_hz=smoothing * f1)  # fmt: skip
    rows = zip(speeds, runs, clean, estimate.events, raw.events, smooth.events, strict=True)
    return pd.DataFrame(
        [
            {
                "speed": v,
                "f_load / f1": v / bridge.span / f1,
                "true DAF": -c.min() / static,
                "clean record": e.daf,
                "noisy record": n.daf,
                "noisy, smoothed": s.daf,
                "f1 estimated": e.first_frequency_hz,
                "filtered peak / static": -e.quasi_static_peak / static,
                "doubtful": e.doubtful,
                "lost contact": r.lost_contact,
            }
            for v, r, c, e, n, s in rows
        ]
    )


def strain_trial(
    bridge: Bridge,
    vehicle: object,
    road: Profile,
    speeds: float | Sequence[float],
    bridge_start: float,
    *,
    sample_rate_hz: float,
    modes: int = 100,
    free_vibration: float = 6.0,
) -> pd.DataFrame:
    """The DAF of strain (midspan moment) records by the filter and by the influence-line fit.

    The many-mode model with ``modes`` modes gives the midspan moment of span 1 (its
    curvature); the true DAF divides the record's peak by the moment of a crawl run.  Both
    estimates know the speed and the span (``response="strain"``).

    Returns
    -------
    pandas.DataFrame
        One row per speed: ``speed`` [m/s], ``true DAF``, ``filter``, ``influence-line
        fit`` and ``lost contact``.
    """
    speeds = _speeds(speeds)
    fs = check.positive("sample_rate_hz", sample_rate_hz)
    modal = {"model": "modal", "modes": int(modes)}
    midspan = bridge.span / 2
    crawl_road = Profile.flat(bridge.length + 2.0 + 0.05, 0.05)
    crawl = _runs(bridge, vehicle, crawl_road, np.array([CRAWL_SPEED]), 1.0, **modal)[0]
    static = crawl.moment_at(midspan).max()
    runs = _runs(bridge, vehicle, road, speeds, bridge_start, free_vibration=free_vibration,
                 **modal)  # fmt: skip
    moments = [record_from_crossing(r, fs, response=r.moment_at(midspan))[1] for r in runs]
    known = {"speed": speeds, "span": bridge.span, "response": "strain"}
    with warnings.catch_warnings():  # the filter's bias on a kink is the point of the trial
        warnings.simplefilter("ignore", UserWarning)
        filtered = daf_from_record(moments, fs, method="filter", **known).daf
        fitted = daf_from_record(moments, fs, **known).daf
    return pd.DataFrame(
        {
            "speed": speeds,
            "true DAF": [m.max() / static for m in moments],
            "filter": filtered,
            "influence-line fit": fitted,
            "lost contact": [r.lost_contact for r in runs],
        }
    )


def load_test_trial(
    bridge: Bridge,
    vehicle: object,
    paths: Sequence[Profile],
    speeds: float | Sequence[float],
    bridge_start: float,
    gauges: dict[str, tuple[str, float]],
    **options: object,
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """A load test simulated: crawl and passes at speed, each gauge read as a test would.

    The vehicle crawls at :data:`CRAWL_SPEED` along the first path, then passes once along
    every path at every speed.  Each gauge records the displacement or the bending moment
    at its section, in display units (:mod:`vbi_lib.display`), and
    :func:`~vbi_lib.monitoring.daf_from_load_test` divides each pass by the crawl.

    Parameters
    ----------
    bridge, vehicle, bridge_start, options
        As :func:`vbi_lib.simulate` (e.g. ``model="modal", modes=20``); every path is a road
        with the same approach.
    paths
        The wheel paths, one road each.
    speeds
        Speeds of the passes [m/s].
    gauges
        ``{name: (effect, section)}``: the effect (a key of :data:`GAUGE_EFFECTS`) and
        its section [m from the start of the bridge].

    Returns
    -------
    table, passes
        ``table``: :func:`~vbi_lib.monitoring.daf_from_load_test`'s rows (gauge, speed, run,
        static, dynamic peak, DAF); ``passes``: one row per pass, ``speed``, ``run`` (the
        path's index) and ``lost contact``.

    Raises
    ------
    ValueError
        No path, or a gauge whose effect is not known.
    """
    speeds = _speeds(speeds)
    if not paths:
        raise ValueError("paths is empty: give at least one road (a wheel path)")
    for name, (effect, _) in gauges.items():
        if effect not in GAUGE_EFFECTS:
            raise ValueError(
                f"gauges[{name!r}] reads effect={effect!r}; use one of {', '.join(GAUGE_EFFECTS)}"
            )
    from .. import display

    def records(run: object) -> dict[str, np.ndarray]:
        out = {}
        for name, (effect, x) in gauges.items():
            history = run.moment_at(x) if effect == "moment" else run.displacement_at(x)
            out[name] = display.value(history, GAUGE_EFFECTS[effect])
        return out

    crawl_start = max(bridge_start - 1.0, float(paths[0].x[0]))
    crawl_road = paths[0].segment(crawl_start, paths[0].end)
    crawl = _runs(bridge, vehicle, crawl_road, np.array([CRAWL_SPEED]), bridge_start,
                  **options)[0]  # fmt: skip
    dynamic, passes = {}, []
    for v in speeds:
        runs = [_runs(bridge, vehicle, path, np.array([v]), bridge_start, **options)[0]
                for path in paths]  # fmt: skip
        read = [records(r) for r in runs]
        dynamic[float(v)] = {g: [one[g] for one in read] for g in gauges}
        passes += [{"speed": float(v), "run": j, "lost contact": r.lost_contact}
                   for j, r in enumerate(runs)]  # fmt: skip
    return daf_from_load_test(records(crawl), dynamic), pd.DataFrame(passes)
