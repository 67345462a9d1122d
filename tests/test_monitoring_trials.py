"""The trials of chapter 2 (vbi_lib.monitoring.trials) against independent references.

- A crawl run's static deflection is the model's own static deflection: P / k* for the
  one-coordinate model, the exact beam's P L^3 / 48 EI for many modes (a closed form).
- With one mode, the displacement and the moment of a beam are the same function of time, so
  a displacement gauge and a strain gauge read the same DAF; with many they do not.
- The true DAF of a filter trial is the crossing's own peak over the crawl run, computed here
  without the trial; at a low speed on a good road the filter's estimate is close to it.
- On a flat road at low speed the influence-line fit of a strain record is within a few per
  cent of the truth, while the filter reads it high (the kink of the moment's influence line).
"""

from __future__ import annotations

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import monitoring as mon

BRIDGE = vbi.Bridge(20.0, 1, 4e9, 6000.0)  # 20 m, f1 about 4.6 Hz
TRUCK = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)


def test_the_crawl_gives_each_model_its_own_static_deflection() -> None:
    weight = TRUCK.weight
    assert mon.crawl_static(BRIDGE, TRUCK) == pytest.approx(
        2 * weight * BRIDGE.span**3 / (np.pi**4 * BRIDGE.EI), rel=2e-3
    )
    exact = weight * BRIDGE.span**3 / (48 * BRIDGE.EI)
    many = mon.crawl_static(BRIDGE, TRUCK, model="modal", modes=15)
    assert many == pytest.approx(exact, rel=2e-3)


def test_one_mode_cannot_tell_a_strain_gauge_from_a_displacement_gauge() -> None:
    road = vbi.Profile.harmonic(80.0, 0.05, 5.0, 0.003)
    trial = mon.gauge_trial(BRIDGE, TRUCK, road, [12.0, 20.0], 40.0, modes=(1, 10))
    one, ten = trial[trial.modes == 1], trial[trial.modes == 10]
    np.testing.assert_allclose(one.displacement, one.moment, rtol=1e-9)
    assert not np.allclose(ten.displacement, ten.moment, rtol=1e-3)
    assert list(trial.columns) == ["modes", "speed", "displacement", "moment", "lost contact"]


def test_the_truth_of_a_filter_trial_is_the_peak_over_the_crawl() -> None:
    road = vbi.Profile.iso8608(70.0, 0.05, iso_class="A", seed=4)
    speeds = [10.0, 25.0]
    trial = mon.filter_trial(BRIDGE, TRUCK, road, speeds, 40.0, sample_rate_hz=200.0)
    static = mon.crawl_static(BRIDGE, TRUCK)
    for v, truth in zip(speeds, trial["true DAF"], strict=True):
        run = vbi.simulate(BRIDGE, TRUCK, road, v, 40.0, free_vibration=6.0)
        # the record is the history resampled at 200 Hz: its peak is within a sample's reach
        assert truth == pytest.approx(-run.midspan_displacement[:, 0].min() / static, rel=2e-3)
    assert trial["f_load / f1"].tolist() == pytest.approx(
        [v / BRIDGE.span / BRIDGE.first_frequency_hz for v in speeds]
    )
    # a good road, a long span's worth of margin between v/L and f1: the estimate is close
    slow = trial.iloc[0]
    assert slow["clean record"] == pytest.approx(slow["true DAF"], rel=0.05)


def test_the_fit_keeps_the_kink_the_filter_rounds_off() -> None:
    flat = vbi.Profile.flat(70.0, 0.05)
    trial = mon.strain_trial(BRIDGE, TRUCK, flat, [3.0], 40.0, sample_rate_hz=200.0, modes=40)
    row = trial.iloc[0]
    assert row["true DAF"] == pytest.approx(1.0, abs=0.03)
    assert row["influence-line fit"] == pytest.approx(row["true DAF"], rel=0.03)
    assert row["filter"] > row["true DAF"]


def test_speeds_are_checked() -> None:
    flat = vbi.Profile.flat(70.0, 0.05)
    with pytest.raises(ValueError, match="speed"):
        mon.gauge_trial(BRIDGE, TRUCK, flat, [-1.0], 40.0)
    with pytest.raises(ValueError, match="speeds="):
        mon.gauge_trial(BRIDGE, TRUCK, flat, [], 40.0)


def test_a_simulated_load_test_divides_each_pass_by_the_crawl() -> None:
    paths = [vbi.Profile.iso8608(70.0, 0.05, iso_class="A", seed=s) for s in (1, 2)]
    gauges = {"mid": ("deflection", BRIDGE.span / 2), "quarter": ("deflection", BRIDGE.span / 4)}
    table, passes = mon.load_test_trial(BRIDGE, TRUCK, paths, [15.0], 40.0, gauges)
    assert len(table) == 4 and len(passes) == 2  # two gauges, two paths, one speed
    # an independent reading of one pass: its midspan peak over the crawl's (same model)
    crawl = vbi.simulate(BRIDGE, TRUCK, paths[0].segment(39.0, paths[0].end), 0.5, 40.0)
    run = vbi.simulate(BRIDGE, TRUCK, paths[1], 15.0, 40.0)
    expected = run.displacement_at(10.0).min() / crawl.displacement_at(10.0).min()
    mid = table[(table.gauge == "mid") & (table.run == 1)].daf.item()
    assert mid == pytest.approx(expected, rel=1e-9)
    with pytest.raises(ValueError, match="effect='shear'"):
        mon.load_test_trial(BRIDGE, TRUCK, paths, [15.0], 40.0, {"g": ("shear", 5.0)})
