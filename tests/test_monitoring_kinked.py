"""An unbiased DAF for kinked (strain, moment) records: influence-line fit and crawl run.

Independent references: records built in the test from the exact beam statics of
``closed_forms.point_load_statics`` (no dynamics: true DAF 1), the same plus a vibration of
known amplitude (true DAF known), and simulated crossings divided by their own crawl runs.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from vbi_lib import monitoring as mon
from vbi_lib.closed_forms import point_load_statics

FS = 200.0


def static_record(
    span: float,
    speed: float,
    section: float,
    n_spans: int = 1,
    offsets: tuple[float, ...] = (0.0,),
    loads: tuple[float, ...] = (1.0,),
    arrival: float = 1.2345,
    tail: float = 6.0,
    kind: str = "moment",
) -> tuple[np.ndarray, np.ndarray]:
    """Time [s] and the static response at the gauge, axle by axle, sampled at FS."""
    t = np.arange(0.0, arrival + (n_spans * span + offsets[-1]) / speed + tail, 1 / FS)
    record = np.zeros_like(t)
    for offset, load in zip(offsets, loads, strict=True):
        at = speed * (t - arrival) - offset
        on = (at >= 0) & (at <= n_spans * span)
        statics = point_load_statics(section, at[on], span, 4e9, n_spans, force=load * 1e5)
        record[on] += getattr(statics, kind)
    return t, record


KINKED = {  # span, speed, section, n_spans, axle offsets, loads: a strain gauge, no dynamics
    "one axle, 30 m": (30.0, 25.0, 15.0, 1, (0.0,), (1.0,)),
    "one axle, 12 m": (12.0, 20.0, 6.0, 1, (0.0,), (1.0,)),
    "one axle, two 30 m spans": (30.0, 25.0, 15.0, 2, (0.0,), (1.0,)),
    "three axles, 20 m, off-centre": (20.0, 22.3, 8.0, 1, (0.0, 4.2, 5.5), (0.3, 1.0, 1.0)),
    "five axles, two 35 m spans": (
        35.0,
        27.1,
        14.0,
        2,
        (0.0, 3.6, 4.9, 10.9, 12.2),
        (0.6, 1.0, 1.0, 0.9, 0.9),
    ),
}


@pytest.mark.parametrize("speed_known", [True, False])
@pytest.mark.parametrize("case", sorted(KINKED))
def test_kinked_record_without_dynamics_gives_daf_one(case: str, speed_known: bool) -> None:
    span, speed, section, n_spans, offsets, loads = KINKED[case]
    _, record = static_record(span, speed, section, n_spans, offsets, loads)
    spacings = tuple(np.diff(offsets))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a clean fit must not warn
        result = mon.daf_from_record(
            1e-9 * record,  # a strain-like magnitude
            FS,
            speed=speed if speed_known else None,
            span=span,
            n_spans=n_spans,
            section=section,
            axles=mon.Axles(spacings, loads),
            response="strain",
        ).item()
    assert result.method == "influence-line" and "auto" in result.how_chosen
    assert result.daf == pytest.approx(1.0, abs=0.005)
    assert not result.doubtful and result.fit_residual < 1e-3
    assert result.speed == pytest.approx(speed, rel=1e-3)
    assert result.arrival_s == pytest.approx(1.2345, abs=1e-3)


@pytest.mark.parametrize("case", ["one axle, 30 m", "one axle, 12 m", "one axle, two 30 m spans"])
def test_the_plain_filter_reads_a_kinked_record_high_and_says_so(case: str) -> None:
    """The issue's measurement: the low-pass rounds the kink off, DAF 1.06-1.11 from 1."""
    span, speed, section, n_spans, offsets, loads = KINKED[case]
    _, record = static_record(span, speed, section, n_spans, offsets, loads)
    f1 = 8.0 * speed / span  # a stiff bridge: a cut-off with plenty of room either side
    with pytest.warns(UserWarning, match="rounds off the kink"):
        result = mon.daf_from_record(
            record,
            FS,
            speed=speed,
            span=span,
            first_frequency_hz=f1,
            response="moment",
            method="filter",
        ).item()
    assert result.method == "filter" and result.doubtful
    assert result.daf > 1.03
    # the same record read as a deflection is smooth: the filter is fine there
    _, smooth = static_record(span, speed, section, n_spans, offsets, loads, kind="deflection")
    deflection = mon.daf_from_record(
        smooth, FS, speed=speed, span=span, first_frequency_hz=f1, response="deflection"
    ).item()
    assert deflection.method == "filter" and not deflection.doubtful
    assert deflection.daf == pytest.approx(1.0, abs=0.01)


@pytest.mark.parametrize(
    ("amplitude", "f1", "damping"),
    [(0.1, 4.0, 0.02), (0.3, 4.0, 0.02), (0.3, 2.5, 0.02), (0.2, 6.0, 0.05)],
)
def test_known_vibration_on_a_kinked_record_gives_the_known_daf(
    amplitude: float, f1: float, damping: float
) -> None:
    """Static line plus a decaying vibration cresting with it: true DAF = peak / static peak."""
    span, speed = 30.0, 25.0
    t, static = static_record(span, speed, 15.0)
    crest = 1.2345 + 15.0 / speed  # the axle is over the gauge
    omega = 2 * np.pi * f1
    ring = np.exp(-damping * omega * np.abs(t - crest)) * np.cos(omega * (t - crest))
    record = static + amplitude * static.max() * ring
    truth = record.max() / static.max()
    overlap = f1 < 4 * speed / span  # flagged, yet still close, when f1 < 4 v / L
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = mon.daf_from_record(record, FS, speed=speed, span=span, response="strain")
        unknown_speed = mon.daf_from_record(record, FS, span=span, response="strain").item()
    result = result.item()
    assert result.daf == pytest.approx(truth, rel=0.005)
    assert result.first_frequency_hz == pytest.approx(f1, rel=0.02)  # from the tail
    assert result.doubtful == overlap and unknown_speed.doubtful == overlap
    assert len(caught) == (2 if overlap else 0)
    assert all("quasi-static and the dynamic response overlap" in str(w.message) for w in caught)
    assert unknown_speed.speed == pytest.approx(speed, rel=0.01)
    assert unknown_speed.daf == pytest.approx(truth, rel=0.005)


def test_noise_and_drift_on_a_kinked_record() -> None:
    span, speed = 30.0, 25.0
    t, static = static_record(span, speed, 15.0)
    rng = np.random.default_rng(5)
    peak = static.max()
    record = static + 0.3 * peak + 0.1 * peak * (t / t[-1]) ** 2
    noisy = record + 0.02 * peak * rng.standard_normal(t.size)
    with pytest.warns(UserWarning, match="pass noise_cutoff_hz"):
        raw = mon.daf_from_record(noisy, FS, speed=speed, span=span, response="strain").item()
    assert raw.doubtful
    smoothed = mon.daf_from_record(
        noisy, FS, speed=speed, span=span, response="strain", noise_cutoff_hz=12.0
    ).item()
    # 2 % noise keeps sqrt(2 x 12 / 200) of itself below 12 Hz: 0.7 % of the peak
    assert smoothed.daf == pytest.approx(1.0, abs=0.015)
    assert not smoothed.doubtful and "noise removed above 12 Hz" in smoothed.how_chosen
    drift_only = mon.daf_from_record(record, FS, speed=speed, span=span, response="strain")
    assert drift_only.item().daf == pytest.approx(1.0, abs=0.005)  # parabola: fits a line


@pytest.mark.parametrize(
    ("wrong", "value"),
    [("section", 7.5), ("span", 20.0), ("n_spans", 2)],
)
def test_a_shape_that_does_not_match_is_flagged(wrong: str, value: float) -> None:
    _, record = static_record(30.0, 25.0, 15.0)
    known = {"speed": 25.0, "span": 30.0, "section": 15.0, "n_spans": 1}
    known[wrong] = value
    if wrong == "span":
        known["section"] = value / 2
    if wrong == "n_spans":
        known["span"], known["section"] = 15.0, 7.5
    with pytest.warns(UserWarning, match="does not match"):
        result = mon.daf_from_record(record, FS, response="strain", **known).item()
    assert result.doubtful and result.fit_residual > mon.MAX_FIT_RESIDUAL


def test_two_vehicles_in_one_record_are_flagged() -> None:
    t, first = static_record(30.0, 25.0, 15.0, arrival=1.0)
    _, second = static_record(30.0, 25.0, 15.0, arrival=1.6)
    record = first + 0.7 * second[: first.size]
    for speed in (25.0, None):
        with pytest.warns(UserWarning, match="does not match"):
            result = mon.daf_from_record(record, FS, speed=speed, span=30.0, response="strain")
        assert result.item().doubtful


def test_crawl_run_of_the_same_vehicle_gives_daf_one() -> None:
    """A crawl at 0.5 m/s sampled at 50 Hz, and the same vehicle at 25 m/s sampled at 200 Hz."""
    span, speed = 30.0, 25.0
    _, fast = static_record(span, speed, 15.0)
    crawl_t = np.arange(0.0, 80.0, 1 / 50.0)
    crawl = np.zeros_like(crawl_t)
    at = 0.5 * (crawl_t - 5.0)
    on = (at >= 0) & (at <= span)
    crawl[on] = point_load_statics(15.0, at[on], span, 4e9, force=1e5).moment
    for crawl_speed in (0.5, None):
        result = mon.daf_from_record(
            fast + 3.0,  # the gauge's zero moved between the runs
            FS,
            speed=speed,
            crawl=crawl,
            crawl_speed=crawl_speed,
            crawl_sample_rate_hz=50.0,
        ).item()
        assert result.method == "crawl" and "crawl run given" in result.how_chosen
        assert result.daf == pytest.approx(1.0, abs=0.005)
        assert result.fit_residual < 1e-3 and not result.doubtful


def test_simulated_crossing_against_its_crawl_run() -> None:
    """Midspan moment of a modal crossing: fit and crawl near the truth, filter high.

    100 modes keep the modal moment within 0.4 % of the exact static value under the
    load; the rest of the fit's shortfall is the forced response's own amplification
    ``1 / (1 - alpha^2)``, 0.2 % at this speed.
    """
    import vbi_lib as vbi
    from vbi_lib import units as u

    bridge = vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * u.lbf / u.inch, 3.99)
    truck = vbi.Vehicle.from_frequency(200 * u.slinch, 4.5, 0.10, damped=True)
    mid = bridge.span / 2
    length = 100.0 + bridge.length + 5
    road = vbi.Profile.iso8608(length, 0.05, iso_class="A", seed=7)
    flat = vbi.Profile.flat(length, 0.05).segment(90.0, length)
    modal = {"model": "modal", "modes": 100}
    crawl = vbi.simulate(bridge, truck, flat, 0.5, 100.0, free_vibration=10.0, **modal)
    crawl_moment = crawl.moment_at(mid)
    _, crawl_record = mon.record_from_crossing(crawl, 50.0, response=crawl_moment, lead_s=10.0)
    run = vbi.simulate(bridge, truck, road, 10.0, 100.0, free_vibration=6.0, **modal)
    _, record = mon.record_from_crossing(run, FS, response=run.moment_at(mid))
    truth = record.max() / crawl_moment.max()
    assert truth > 1.2  # the bridge does vibrate
    known = {"span": bridge.span, "response": "strain"}
    fit = mon.daf_from_record(record, FS, speed=10.0, **known).item()
    assert fit.method == "influence-line" and not fit.doubtful
    assert fit.daf == pytest.approx(truth, rel=0.01)
    searched = mon.daf_from_record(record, FS, **known).item()
    assert searched.speed == pytest.approx(10.0, rel=0.01)
    assert searched.daf == pytest.approx(truth, rel=0.015)
    by_crawl = mon.daf_from_record(
        record, FS, speed=10.0, crawl=crawl_record, crawl_speed=0.5, crawl_sample_rate_hz=50.0
    ).item()
    assert by_crawl.daf == pytest.approx(truth, rel=0.003)
    with pytest.warns(UserWarning, match="rounds off the kink"):
        low = mon.daf_from_record(record, FS, speed=10.0, method="filter", **known).item()
    assert low.daf > 1.03 * truth


def test_a_truck_bouncing_through_a_short_span() -> None:
    """12 m span, 2.5 Hz truck at 20 m/s: its force changes within the 0.6 s passage.

    No fixed scale of the influence line is the quasi-static response then: the fit is
    flagged (with the speed given or searched) while the crawl run, the static response
    itself, stays within 0.3 % of the truth and is not flagged.
    """
    import vbi_lib as vbi
    from vbi_lib import units as u

    bridge = vbi.Bridge.from_midspan_stiffness(40 * u.ft, 1, 587723 * u.lbf / u.inch, 9.95)
    truck = vbi.Vehicle.from_frequency(200 * u.slinch, 2.5, 0.10, damped=True)
    mid, length = bridge.span / 2, 100.0 + bridge.length + 5
    road = vbi.Profile.iso8608(length, 0.05, iso_class="A", seed=7)
    flat = vbi.Profile.flat(length, 0.05).segment(90.0, length)
    modal = {"model": "modal", "modes": 100}
    crawl = vbi.simulate(bridge, truck, flat, 0.5, 100.0, free_vibration=10.0, **modal)
    _, crawl_record = mon.record_from_crossing(
        crawl, 50.0, response=crawl.moment_at(mid), lead_s=10.0
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.validity.ContactLossWarning)
        run = vbi.simulate(bridge, truck, road, 20.0, 100.0, free_vibration=6.0, **modal)
    _, record = mon.record_from_crossing(run, FS, response=run.moment_at(mid))
    truth = record.max() / crawl.moment_at(mid).max()
    known = {"span": bridge.span, "response": "strain"}
    for speed in (20.0, None):
        with pytest.warns(UserWarning, match="bouncing through a short span"):
            fit = mon.daf_from_record(record, FS, speed=speed, **known).item()
        assert fit.doubtful
    by_crawl = mon.daf_from_record(
        record, FS, speed=20.0, crawl=crawl_record, crawl_speed=0.5, crawl_sample_rate_hz=50.0
    ).item()
    assert by_crawl.daf == pytest.approx(truth, rel=0.003) and not by_crawl.doubtful


def test_the_method_is_chosen_and_reported() -> None:
    span, speed = 30.0, 25.0
    _, record = static_record(span, speed, 15.0)
    auto = mon.daf_from_record(record, FS, speed=speed, span=span, response="moment").item()
    assert auto.method == "influence-line" and auto.cutoff_hz is None
    asked = mon.daf_from_record(
        record, FS, speed=speed, span=span, response="moment", method="influence-line"
    ).item()
    assert "asked" in asked.how_chosen and asked.daf == pytest.approx(auto.daf)
    with pytest.warns(UserWarning, match="give span"):
        no_span = mon.daf_from_record(
            record, FS, response="strain", first_frequency_hz=4.0, cutoff_hz=2.0
        ).item()
    assert no_span.method == "filter" and no_span.doubtful
    result = mon.daf_from_record([record, record], FS, speed=speed, span=span, response="strain")
    assert list(result.method) == ["influence-line"] * 2
    table = result.to_dataframe()
    assert {"method", "speed", "arrival_s", "fit_residual"} <= set(table.columns)
    assert table["cutoff_hz"].isna().all()
    assert repr(result[0]).startswith("RecordDAF(DAF 1.000 by influence-line: peak")


def test_each_event_can_have_its_own_axles_and_speed() -> None:
    """Two trucks, two records: each fitted with its own axle layout and speed."""
    span = 25.0
    layouts = [((0.0,), (1.0,)), ((0.0, 3.6, 4.9), (0.4, 1.0, 1.0))]
    speeds = [18.0, 27.0]
    records = [
        static_record(span, v, 12.5, 1, offsets, loads, tail=4.0)[1][:1200]
        for (offsets, loads), v in zip(layouts, speeds, strict=True)
    ]
    axles = [mon.Axles(tuple(np.diff(offsets)), loads) for offsets, loads in layouts]
    result = mon.daf_from_record(
        np.array(records), FS, speed=speeds, span=span, axles=axles, response="stress"
    )
    np.testing.assert_allclose(result.daf, 1.0, atol=0.005)
    assert "3 axles" in result[1].how_chosen and "one axle" in result[0].how_chosen
    with pytest.raises(ValueError, match="axles has 1 values for 2 events"):
        mon.daf_from_record(records, FS, span=span, axles=axles[:1], response="stress")


def test_an_influence_line_result_plots_its_fit() -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    _, record = static_record(30.0, 25.0, 15.0)
    event = mon.daf_from_record(record, FS, speed=25.0, span=30.0, response="strain").item()
    ax = event.plot(scale=1e-3, unit="kN m")
    lines = ax.get_lines()
    np.testing.assert_allclose(lines[1].get_ydata(), 1e-3 * event.quasi_static)
    assert lines[1].get_label() == "influence-line fit"
    assert "by influence-line" in ax.get_title()
    plt.close("all")
