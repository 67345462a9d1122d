"""Records that hold no event, and calls that lack what their method needs, raise a
ValueError naming the problem: never a negative, huge or silent DAF."""

from __future__ import annotations

import numpy as np
import pytest

from vbi_lib import monitoring as mon
from vbi_lib.closed_forms import point_load_statics

FS = 200.0
T = np.arange(0.0, 8.0, 1 / FS)
NOISE = np.random.default_rng(3).standard_normal(T.size)

#: Every way of asking: filter with a cut-off, filter choosing it (f1 given), and the
#: influence-line fit with the speed given or searched.
CALLS = {
    "filter, cut-off given": {"cutoff_hz": 2.0},
    "filter, f1 given": {"speed": 25.0, "span": 30.0, "first_frequency_hz": 4.0},
    "influence line": {"speed": 25.0, "span": 30.0, "response": "strain"},
    "influence line, speed searched": {"span": 30.0, "response": "strain"},
}


def strain_event() -> np.ndarray:
    at = 25.0 * (T - 1.0)
    on = (at >= 0) & (at <= 30.0)
    record = np.zeros_like(T)
    record[on] = point_load_statics(15.0, at[on], 30.0, 1.0).moment
    return record


@pytest.mark.parametrize("call", sorted(CALLS))
@pytest.mark.parametrize("level", [1.0, 0.0, -3e-6])
def test_a_constant_record_is_refused(call: str, level: float) -> None:
    """The issue: a constant record gave DAF -8.7."""
    with pytest.raises(ValueError, match="signal is constant"):
        mon.daf_from_record(np.full(T.size, level), FS, **CALLS[call])


@pytest.mark.parametrize("call", sorted(CALLS))
@pytest.mark.parametrize(
    "record",
    ["white noise", "noise on a drifting zero", "ambient vibration in noise"],
)
def test_a_record_without_an_event_is_refused(call: str, record: str) -> None:
    """The issue: pure noise gave DAF 5.1."""
    signals = {
        "white noise": NOISE,
        "noise on a drifting zero": NOISE + 3.0 * T / T[-1] + 2.0,
        "ambient vibration in noise": np.sin(2 * np.pi * 4.0 * T) + NOISE,
    }
    with pytest.raises(ValueError, match="no event that stands out of the noise"):
        mon.daf_from_record(signals[record], FS, **CALLS[call])


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("call", sorted(CALLS))
def test_gaps_are_refused_with_their_place(call: str, bad: float) -> None:
    record = strain_event()
    record[123] = bad
    with pytest.raises(ValueError, match=r"signal\[123\]=.* is not a finite number"):
        mon.daf_from_record(record, FS, **CALLS[call])


def test_an_event_in_strong_noise_is_refused_but_a_clear_one_is_measured() -> None:
    event = strain_event()
    peak = event.max()
    with pytest.raises(ValueError, match="stands out of the noise"):
        mon.daf_from_record(event + peak * NOISE, FS, **CALLS["influence line"])
    clear = mon.daf_from_record(event + 0.01 * peak * NOISE, FS, **CALLS["influence line"])
    assert clear.item().daf == pytest.approx(1.0, abs=0.04)  # 3 x 1 % noise at most


def test_each_method_says_what_it_needs() -> None:
    record = strain_event()
    with pytest.raises(ValueError, match="method='influence-line' needs span and response"):
        mon.daf_from_record(record, FS, speed=25.0, method="influence-line")
    with pytest.raises(ValueError, match="method='crawl' needs crawl"):
        mon.daf_from_record(record, FS, method="crawl")
    with pytest.raises(ValueError, match="crawl is used only by method='crawl'"):
        mon.daf_from_record(record, FS, crawl=record, method="filter")
    with pytest.raises(ValueError, match="cutoff_hz=2.0 is used only by method 'filter'"):
        mon.daf_from_record(record, FS, 2.0, span=30.0, response="strain")
    with pytest.raises(ValueError, match="section=10.0 is used only by method 'influence-line'"):
        mon.daf_from_record(record, FS, speed=25.0, span=30.0, section=10.0)
    with pytest.raises(ValueError, match="method='fit' must be 'auto'"):
        mon.daf_from_record(record, FS, method="fit")
    with pytest.raises(ValueError, match="response='strain gauge' must be one of"):
        mon.daf_from_record(record, FS, response="strain gauge")
    with pytest.raises(ValueError, match="section=45.0 must lie on the bridge"):
        mon.daf_from_record(record, FS, span=30.0, response="strain", section=45.0)
    with pytest.raises(ValueError, match="n_spans=3 is not supported"):
        mon.daf_from_record(record, FS, span=30.0, response="strain", n_spans=3)
    with pytest.raises(ValueError, match="shorter than the vehicle's passage"):
        mon.daf_from_record(record[200:400], FS, speed=25.0, span=30.0, response="strain")
    with pytest.raises(ValueError, match="crawl is constant"):
        mon.daf_from_record(record, FS, crawl=np.zeros(500))
    with pytest.raises(ValueError, match="speed=-25.0 must be"):
        mon.daf_from_record(record, FS, speed=-25.0, span=30.0, response="strain")


def test_drift_read_by_the_filter_is_flagged() -> None:
    """No noise to refuse it on, but no passage either: the quasi-static event is too long."""
    with pytest.warns(UserWarning, match="not one passage"):
        result = mon.daf_from_record(1e-3 * T**2, FS, **CALLS["filter, f1 given"])
    assert result.item().doubtful
