"""Measuring amplification in the field: every check against a closed form or a built-in truth."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pandas as pd
import pytest
from scipy import signal as sps

from vbi_lib import monitoring as mon

# ---------------------------------------------------------------------------- algebra


def test_first_mode_coefficients_are_the_closed_forms() -> None:
    assert mon.DISPLACEMENT_INERTIA_COEFFICIENT == pytest.approx(0.4927671, rel=1e-6)
    assert mon.STRAIN_INERTIA_COEFFICIENT == pytest.approx(0.4052847, rel=1e-6)
    assert float(mon.displacement_daf(1.0, 1.0)) == pytest.approx(1.0 + 48 / math.pi**4)
    assert float(mon.strain_daf(1.0, 1.0)) == pytest.approx(1.0 + 4 / math.pi**2)


def test_ratio_of_extra_terms_is_twelve_over_pi_squared() -> None:
    # (28): 1.216, whatever A_v and r
    assert mon.extra_amplification_ratio(1) == pytest.approx(1.2158542, rel=1e-6)
    r = np.array([0.05, 0.3, 2.0])
    extra_d = mon.displacement_daf(1.17, r) - 1.17
    extra_s = mon.strain_daf(1.17, r) - 1.17
    np.testing.assert_allclose(extra_d / extra_s, 12 / math.pi**2, rtol=1e-12)
    assert np.all(extra_d > extra_s)


@pytest.mark.parametrize("n", [1, 2, 3, 5, 7])
def test_mode_n_ratio(n: int) -> None:
    assert mon.extra_amplification_ratio(n) == pytest.approx(12 / (n**2 * math.pi**2))


def _midspan_by_superposition(n: int, span: float = 7.0) -> tuple[float, float]:
    """Midspan deflection x EI and moment of a simply supported beam under sin(n pi x / L).

    Integrates the point-load influence lines (deflection a (3L^2 - 4a^2) / 48 for a load at
    a <= L/2, moment a / 2), an independent route to the inertia terms of (20), (22).
    """

    def load(x: float) -> float:
        return math.sin(n * math.pi * x / span)

    def deflection_line(a: float) -> float:
        b = min(a, span - a)
        return b * (3 * span**2 - 4 * b**2) / 48.0

    def moment_line(a: float) -> float:
        return min(a, span - a) / 2.0

    # Gauss-Legendre on each half (smooth there): exact to rounding for these integrands
    nodes, weights = np.polynomial.legendre.leggauss(40)
    w = m = 0.0
    for lo, hi in ((0.0, span / 2), (span / 2, span)):
        for a, c in zip(lo + (hi - lo) * (nodes + 1) / 2, weights * (hi - lo) / 2, strict=True):
            w += c * load(a) * deflection_line(a)
            m += c * load(a) * moment_line(a)
    return w, m


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_inertia_terms_match_beam_statics(n: int) -> None:
    span, beam_mass, acceleration, force = 7.0, 1.0, 1.0, 1.0
    w_unit, m_unit = _midspan_by_superposition(n, span)
    q = beam_mass * acceleration / span  # load amplitude (24)
    w_point = force * span**3 / 48.0  # (19) times EI
    m_point = force * span / 4.0  # (21) over c / I
    r = mon.inertia_ratio(beam_mass, acceleration, force)
    assert float(mon.displacement_daf(0.0, r, modes=n)) == pytest.approx(
        q * w_unit / w_point, rel=1e-9, abs=1e-12
    )
    assert float(mon.strain_daf(0.0, r, modes=n)) == pytest.approx(
        q * m_unit / m_point, rel=1e-9, abs=1e-12
    )


def test_several_modes_sum_term_by_term() -> None:
    r = np.array([[0.4, 0.3, -0.2], [0.1, 0.0, 0.5]])
    modes = [1, 2, 3]
    d = 1.05 + 48 / math.pi**4 * (r[:, 0] - r[:, 2] / 81)
    s = 1.05 + 4 / math.pi**2 * (r[:, 0] - r[:, 2] / 9)
    np.testing.assert_allclose(mon.displacement_daf(1.05, r, modes), d, rtol=1e-12)
    np.testing.assert_allclose(mon.strain_daf(1.05, r, modes), s, rtol=1e-12)


def test_algebra_rejects_bad_input() -> None:
    with pytest.raises(ValueError, match="one ratio per mode"):
        mon.displacement_daf(1.0, [0.1, 0.2], modes=[1, 2, 3])
    with pytest.raises(ValueError, match="modes"):
        mon.strain_daf(1.0, 0.1, modes=0)
    with pytest.raises(ValueError, match="beam_mass"):
        mon.inertia_ratio(-1.0, 0.1, 1.0)
    with pytest.raises(ValueError, match="inertia_ratio"):
        mon.strain_daf(1.0, float("nan"))


# ---------------------------------------------------------------------------- records
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
    assert result.daf == pytest.approx(truth, rel=0.01)
    assert np.sign(result.peak) == sign and np.sign(result.quasi_static_peak) == sign
    assert result.loading_frequency_hz == pytest.approx(1.0)
    if ring > 0:
        assert result.first_frequency_hz == pytest.approx(6.0, rel=0.01)
        assert "Welch" in result.how_chosen


def test_given_first_frequency_is_used() -> None:
    record, truth = _event(ring=0.0, frequency=6.0)
    result = mon.daf_from_record(record, FS, speed=25.0, span=25.0, first_frequency_hz=6.0)
    assert result.cutoff_hz == pytest.approx(math.sqrt(6.0))
    assert result.daf == pytest.approx(truth, rel=0.01)
    assert "given" in result.how_chosen


def test_noise_and_drifting_baseline() -> None:
    record, truth = _event(ring=0.3)
    rng = np.random.default_rng(1)
    drift = 0.3 + 0.02 * np.arange(record.size) / FS
    noisy = record + drift + 0.01 * rng.standard_normal(record.size)
    result = mon.daf_from_record(noisy, FS, speed=25.0, span=25.0, noise_cutoff_hz=20.0)
    assert result.daf == pytest.approx(truth, rel=0.02)


def test_loading_faster_than_the_first_frequency_inflates_the_daf() -> None:
    # a 0.25 s pulse (loading 4 Hz) on a 2 Hz bridge: the filter eats the static part
    record, truth = _event(ring=0.1, duration=0.25, frequency=2.0, tail=10.0)
    with pytest.warns(UserWarning, match="inflates the DAF"):
        result = mon.daf_from_record(record, FS, speed=40.0, span=10.0)
    assert result.cutoff_hz == pytest.approx(result.first_frequency_hz / 2)
    assert result.daf > 1.5 * truth


def test_filter_is_zero_phase() -> None:
    t = np.arange(0.0, 20.0, 1.0 / FS)
    slow = np.sin(2 * np.pi * 0.3 * t)
    filtered = mon.lowpass(slow + 0.5 * np.sin(2 * np.pi * 15 * t), FS, 2.0)
    middle = slice(int(3 * FS), int(17 * FS))
    np.testing.assert_allclose(filtered[middle], slow[middle], atol=2e-3)
    # a symmetric pulse keeps its peak time; a one-way filter would delay it
    pulse = np.exp(-0.5 * ((t - 10.0) / 0.3) ** 2)
    assert t[np.argmax(mon.lowpass(pulse, FS, 1.0))] == pytest.approx(10.0, abs=0.5 / FS)
    one_way = sps.sosfilt(sps.butter(4, 1.0, fs=FS, output="sos"), pulse)
    assert t[np.argmax(one_way)] > 10.1


def test_several_events_give_a_table() -> None:
    rings = [0.0, 0.15, 0.3]
    events = np.array([_event(ring=a)[0] for a in rings])
    table = mon.daf_from_record(
        events, FS, speed=[25.0, 25.0, 25.0], span=25.0, first_frequency_hz=6.0
    )
    assert isinstance(table, pd.DataFrame) and len(table) == 3
    np.testing.assert_allclose(table["daf"], [1.0 + a for a in rings], rtol=0.01)
    as_list = mon.daf_from_record(list(events[1:]), FS, speed=25.0, span=25.0)
    assert len(as_list) == 2
    assert list(as_list.columns) == list(table.columns)


def test_a_plain_list_is_one_record() -> None:
    record, truth = _event(ring=0.2)
    result = mon.daf_from_record(list(record), FS, speed=25.0, span=25.0)
    assert isinstance(result, mon.RecordDAF)
    assert result.daf == pytest.approx(truth, rel=0.01)


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
    result = mon.daf_from_record(record, FS, speed=10.0, span=bridge.span)
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


def test_first_frequency_from_the_tail() -> None:
    t = np.arange(0.0, 12.0, 1.0 / FS)
    tail = np.exp(-0.25 * t) * np.sin(2 * np.pi * 3.7 * t + 0.4)
    record = np.concatenate([np.zeros(400), tail])
    assert mon.estimate_first_frequency(record, FS, tail_fraction=0.5) == pytest.approx(
        3.7, rel=0.005
    )


def test_record_from_crossing_resamples_and_adds_drift_and_noise() -> None:
    from types import SimpleNamespace

    t = np.linspace(0.0, 10.0, 5001)
    speed, start = 5.0, 20.0  # the wheel reaches the bridge at t = 4 s
    fake = SimpleNamespace(
        time=t,
        position=speed * t,
        bridge_start=start,
        midspan_displacement=np.sin(0.7 * t)[:, None],
    )
    clock, record = mon.record_from_crossing(fake, 50.0, lead_s=1.0)
    assert clock[0] == 0.0 and clock[1] == pytest.approx(0.02)
    np.testing.assert_allclose(record, np.sin(0.7 * (clock + 3.0)), atol=1e-5)
    _, drifted = mon.record_from_crossing(fake, 50.0, lead_s=1.0, drift=0.5)
    assert drifted[-1] - record[-1] == pytest.approx(0.5)
    assert drifted[0] == pytest.approx(record[0])
    _, noisy = mon.record_from_crossing(fake, 50.0, lead_s=1.0, noise_std=0.1, seed=4)
    assert np.std(noisy - record) == pytest.approx(0.1, rel=0.1)
    with pytest.raises(ValueError, match="response has 3 values"):
        mon.record_from_crossing(fake, 50.0, response=[1.0, 2.0, 3.0])


# ---------------------------------------------------------------------------- load tests
def _influence(n: int = 201) -> np.ndarray:
    return np.sin(np.pi * np.linspace(0.0, 1.0, n))


def test_load_test_per_gauge_and_speed() -> None:
    line = _influence()
    wobble = np.sin(np.pi * np.linspace(0.0, 1.0, line.size))
    static_runs = {
        "strain": [120e-6 * line, 122e-6 * line],  # tension, two crawl runs: mean 121e-6
        "deflection": -3.0,  # parked truck, mm down
    }
    dynamic_runs = {
        10.0: {"strain": 121e-6 * line * (1 + 0.10 * wobble), "deflection": -3.0 * line * 1.2},
        25.0: {"strain": [121e-6 * line * (1 + 0.30 * wobble), 121e-6 * line * (1 + 0.2 * wobble)]},
    }
    table = mon.daf_from_load_test(static_runs, dynamic_runs)
    assert len(table) == 4
    got = table.set_index(["gauge", "speed", "run"])["daf"]
    assert got[("strain", 10.0, 0)] == pytest.approx(1.10, rel=1e-4)
    assert got[("deflection", 10.0, 0)] == pytest.approx(1.20, rel=1e-12)
    assert got[("strain", 25.0, 0)] == pytest.approx(1.30, rel=1e-4)
    assert got[("strain", 25.0, 1)] == pytest.approx(1.20, rel=1e-4)
    assert table.set_index(["gauge", "speed", "run"])["static"][("strain", 10.0, 0)] == (
        pytest.approx(121e-6)
    )
    worst = table.groupby(["gauge", "speed"])["daf"].max()
    assert worst[("strain", 25.0)] == pytest.approx(1.30, rel=1e-4)


def test_load_test_zeroing_and_errors() -> None:
    line = np.concatenate([np.zeros(20), _influence()]) + 0.5  # offset gauge
    table = mon.daf_from_load_test({"G": line}, {5.0: {"G": 1.1 * (line - 0.5) + 0.5}}, 20)
    assert table["daf"].iloc[0] == pytest.approx(1.1)
    with pytest.raises(ValueError, match="no static response"):
        mon.daf_from_load_test({"G": line}, {5.0: {"H": line}})
    with pytest.raises(ValueError, match="mixed sign"):
        mon.daf_from_load_test({"G": [_influence(), -_influence()]}, {5.0: {"G": line}})
    bad = _influence()
    bad[3] = np.nan
    with pytest.raises(ValueError, match="not a finite number"):
        mon.daf_from_load_test({"G": _influence()}, {5.0: {"G": bad}})
    with pytest.raises(ValueError, match="static_runs is empty"):
        mon.daf_from_load_test({}, {5.0: {"G": line}})


def test_no_warning_in_the_well_separated_case() -> None:
    record, _ = _event(ring=0.2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mon.daf_from_record(record, FS, speed=25.0, span=25.0)
