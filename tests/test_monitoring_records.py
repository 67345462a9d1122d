"""DAF of recorded events by filtering: synthetic events whose true DAF is built in, and a
simulated crossing against its own crawl run."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pandas as pd
import pytest

from vbi_lib import monitoring as mon

FS = 200.0


def _event(
    height: float = 1.0,
    ring: float = 0.2,
    duration: float = 1.0,
    frequency: float = 6.0,
    sign: float = 1.0,
    lead: float = 2.0,
    tail: float = 6.0,
    decay: float = 0.3,
) -> tuple[np.ndarray, float]:
    """A half-sine quasi-static pulse plus a vibration that crests with it; true DAF known.

    Both parts peak at mid-pulse and nowhere exceed their amplitudes, so the record's peak is
    exactly height + ring and the true DAF (height + ring) / height.
    """
    t = np.arange(-lead, duration + tail, 1.0 / FS)
    mid = duration / 2.0
    pulse = np.where((t > 0) & (t < duration), np.sin(np.pi * t / duration), 0.0)
    vibration = np.exp(-decay * np.abs(t - mid)) * np.cos(2 * np.pi * frequency * (t - mid))
    return sign * (height * pulse + ring * vibration), (height + ring) / height


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("ring", [0.0, 0.1, 0.4])
def test_daf_of_a_synthetic_record_matches_the_truth(sign: float, ring: float) -> None:
    record, truth = _event(ring=ring, sign=sign)
    first = 6.0 if ring == 0 else None  # no vibration: nothing to estimate f1 from
    result = mon.daf_from_record(record, FS, speed=25.0, span=25.0, first_frequency_hz=first)
    result = result.item()
    assert result.daf == pytest.approx(truth, rel=0.01)
    assert not result.doubtful
    assert np.sign(result.peak) == sign and np.sign(result.quasi_static_peak) == sign
    assert result.loading_frequency_hz == pytest.approx(1.0)
    if ring > 0:
        assert result.first_frequency_hz == pytest.approx(6.0, rel=0.01)
        assert "Welch" in result.how_chosen


def test_given_first_frequency_is_used() -> None:
    record, truth = _event(ring=0.0, frequency=6.0)
    result = mon.daf_from_record(record, FS, speed=25.0, span=25.0, first_frequency_hz=6.0)[0]
    assert result.cutoff_hz == pytest.approx(math.sqrt(6.0))
    assert result.daf == pytest.approx(truth, rel=0.01)
    assert "given" in result.how_chosen


def test_noise_and_drifting_baseline() -> None:
    record, truth = _event(ring=0.3)
    rng = np.random.default_rng(1)
    drift = 0.3 + 0.02 * np.arange(record.size) / FS
    noisy = record + drift + 0.01 * rng.standard_normal(record.size)
    result = mon.daf_from_record(noisy, FS, speed=25.0, span=25.0, noise_cutoff_hz=20.0)
    assert result.item().daf == pytest.approx(truth, rel=0.02)


def test_loading_faster_than_the_first_frequency_inflates_the_daf() -> None:
    # a 0.25 s pulse (loading 4 Hz) on a 2 Hz bridge: the filter eats the static part
    record, truth = _event(ring=0.1, duration=0.25, frequency=2.0, tail=10.0)
    with pytest.warns(UserWarning, match="inflates the DAF"):
        result = mon.daf_from_record(record, FS, speed=40.0, span=10.0).item()
    assert result.doubtful and "inflates the DAF" in result.how_chosen
    assert result.cutoff_hz == pytest.approx(result.first_frequency_hz / 2)
    assert result.daf > 1.5 * truth


def test_several_events_one_entry_each() -> None:
    rings = [0.0, 0.15, 0.3]
    events = np.array([_event(ring=a)[0] for a in rings])
    result = mon.daf_from_record(
        events, FS, speed=[25.0, 25.0, 25.0], span=25.0, first_frequency_hz=6.0
    )
    assert isinstance(result, mon.RecordDAFs) and len(result) == 3
    np.testing.assert_allclose(result.daf, [1.0 + a for a in rings], rtol=0.01)
    np.testing.assert_allclose([event.daf for event in result], result.daf)
    table = result.to_dataframe()
    assert isinstance(table, pd.DataFrame) and len(table) == 3
    assert table.index.name == "event"
    np.testing.assert_allclose(table["daf"], [1.0 + a for a in rings], rtol=0.01)
    as_list = mon.daf_from_record(list(events[1:]), FS, speed=25.0, span=25.0)
    assert len(as_list) == 2
    assert list(as_list.to_dataframe().columns) == list(table.columns)
    assert "response" not in table.columns  # the signals stay out of the table
    with pytest.raises(ValueError, match="holds 3 events; item"):
        result.item()
    assert repr(result).startswith("RecordDAFs(3 events: DAF 1.0")


def test_one_record_gives_the_same_type_as_many() -> None:
    record, truth = _event(ring=0.2)
    one = mon.daf_from_record(record, FS, speed=25.0, span=25.0)
    many = mon.daf_from_record([record, record], FS, speed=25.0, span=25.0)
    assert type(one) is type(many) is mon.RecordDAFs
    assert len(one) == 1 and one.item() is one[0]
    assert one.item().daf == pytest.approx(truth, rel=0.01)
    assert one.daf.shape == (1,) and many.daf[1] == one.daf[0]
    assert list(one.to_dataframe().columns) == list(many.to_dataframe().columns)
    assert "RecordDAFs(1 event: RecordDAF(DAF" in repr(one)


def test_events_of_different_lengths_in_a_list() -> None:
    """Records of events at different speeds differ in length: a list of them is several
    events, each estimated on its own (as if given one at a time)."""
    short, truth_short = _event(ring=0.1, tail=4.0)
    long, truth_long = _event(ring=0.3, tail=7.0)
    assert short.size != long.size
    both = mon.daf_from_record([short, long], FS, speed=[25.0, 25.0], span=25.0)
    assert len(both) == 2
    np.testing.assert_allclose(both.daf, [truth_short, truth_long], rtol=0.01)
    alone = mon.daf_from_record(long, FS, speed=25.0, span=25.0).item()
    assert both[1].daf == alone.daf


def test_a_plain_list_is_one_record() -> None:
    record, truth = _event(ring=0.2)
    result = mon.daf_from_record(list(record), FS, speed=25.0, span=25.0)
    assert len(result) == 1
    assert isinstance(result.item(), mon.RecordDAF)
    assert result.item().daf == pytest.approx(truth, rel=0.01)


def test_the_result_keeps_the_signals_it_measured() -> None:
    """The kept signals are the record and its low-pass: their peaks are the reported ones."""
    record, _ = _event(ring=0.3, sign=-1.0)
    event = mon.daf_from_record(record, FS, speed=25.0, span=25.0, baseline_fraction=0.0).item()
    np.testing.assert_array_equal(event.response, record)
    assert event.response is not record and not event.response.flags.writeable
    expected = mon.lowpass(record, FS, event.cutoff_hz)
    np.testing.assert_allclose(event.quasi_static, expected, rtol=1e-12, atol=1e-15)
    assert event.peak == record.min() and event.quasi_static_peak == expected.min()
    assert event.daf == pytest.approx(record.min() / expected.min(), rel=1e-12)


def test_filter_estimate_of_a_simulated_crossing_against_its_crawl_run() -> None:
    """A long span at moderate speed (v/L = f1/12): the filter DAF is close to the truth."""
    import vbi_lib as vbi
    from vbi_lib import units as u

    bridge = vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * u.lbf / u.inch, 3.99)
    truck = vbi.Vehicle.from_frequency(200 * u.slinch, 4.5, 0.10, damped=True)
    road = vbi.Profile.iso8608(100.0 + bridge.length + 5, 0.05, iso_class="A", seed=7)
    flat = vbi.Profile.flat(100.0 + bridge.length + 5, 0.05)
    crawl = vbi.simulate(bridge, truck, flat.segment(99.0, flat.end), 0.5, 100.0)
    static = -crawl.midspan_displacement[:, 0].min()
    run = vbi.simulate(bridge, truck, road, 10.0, 100.0, free_vibration=6.0)
    _, record = mon.record_from_crossing(run, FS)
    truth = -record.min() / static
    assert truth > 1.1  # the bridge does vibrate
    result = mon.daf_from_record(record, FS, speed=10.0, span=bridge.span).item()
    assert result.first_frequency_hz == pytest.approx(bridge.first_frequency_hz, rel=0.01)
    assert result.daf == pytest.approx(truth, rel=0.02)


def test_record_errors_are_clear() -> None:
    record, _ = _event(ring=0.2)
    with_nan = record.copy()
    with_nan[300] = np.nan
    with pytest.raises(ValueError, match=r"signal\[300\]=nan"):
        mon.daf_from_record(with_nan, FS, speed=25.0, span=25.0)
    with pytest.raises(ValueError, match="needs at least"):
        mon.daf_from_record(record[:200], FS, cutoff_hz=0.5)
    with pytest.raises(ValueError, match="too low for a first frequency"):
        mon.daf_from_record(record[::4], FS / 4, speed=25.0, span=25.0, first_frequency_hz=6.0)
    with pytest.raises(ValueError, match="too low for a first frequency"):
        mon.daf_from_record(record[::4], FS / 4, speed=25.0, span=25.0)  # estimated 6 Hz
    with pytest.raises(ValueError, match="Nyquist"):
        mon.daf_from_record(record, FS, cutoff_hz=100.0)
    with pytest.raises(ValueError, match="Nyquist"):
        mon.daf_from_record(record, FS, cutoff_hz=150.0)
    with pytest.raises(ValueError, match="3 values for 2 events"):
        mon.daf_from_record([record, record], FS, speed=[1.0, 2.0, 3.0], span=25.0)
    with pytest.raises(ValueError, match="sample_rate_hz"):
        mon.daf_from_record(record, 0.0)
    # a pulse with only white noise after it: no frequency to find
    noise_only = _event(ring=0.0)[0] + 1e-3 * np.random.default_rng(2).standard_normal(record.size)
    with pytest.raises(ValueError, match="no clear natural frequency"):
        mon.daf_from_record(noise_only, FS, speed=25.0, span=25.0)


def test_no_warning_in_the_well_separated_case() -> None:
    record, _ = _event(ring=0.2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mon.daf_from_record(record, FS, speed=25.0, span=25.0)


def test_the_result_plots_one_event_or_the_dafs_of_many() -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    record, _ = _event(ring=0.3)
    one = mon.daf_from_record(record, FS, speed=25.0, span=25.0)
    ax = one.plot(scale=1e3, unit="mm")
    lines = ax.get_lines()
    np.testing.assert_allclose(lines[0].get_ydata(), 1e3 * one.item().response)
    np.testing.assert_allclose(lines[1].get_ydata(), 1e3 * one.item().quasi_static)
    assert ax.get_ylabel() == "record [mm]"
    many = mon.daf_from_record([record, record], FS, speed=25.0, span=25.0)
    ax = many.plot()
    np.testing.assert_allclose(ax.get_lines()[0].get_ydata(), many.daf)
    plt.close("all")
