"""Influence lines of axle groups and their least-squares fit to a record.

References: the simple span's moment influence line written out by hand, and the exact beam
statics of ``closed_forms.point_load_statics`` summed over the axles in the test.
"""

from __future__ import annotations

import numpy as np
import pytest

from vbi_lib import monitoring as mon
from vbi_lib.closed_forms import point_load_statics
from vbi_lib.monitoring.influence import axle_shape, fit_shape


def test_axles_hold_offsets_and_shares() -> None:
    truck = mon.Axles(spacings=(4.0, 1.5), loads=(2.0, 4.0, 4.0))
    np.testing.assert_allclose(truck.offsets, [0.0, 4.0, 5.5])
    np.testing.assert_allclose(truck.weights, [0.2, 0.4, 0.4])
    assert truck.length == pytest.approx(5.5) and truck.n_axles == 3
    assert mon.Axles().n_axles == 1 and mon.Axles((3.0,)).loads == (1.0, 1.0)
    with pytest.raises(ValueError, match="2 values for 3 axles"):
        mon.Axles(spacings=(4.0, 1.5), loads=(1.0, 2.0))
    with pytest.raises(ValueError, match="spacings"):
        mon.Axles(spacings=(4.0, -1.0))
    with pytest.raises(ValueError, match="loads"):
        mon.Axles(spacings=(4.0,), loads=(1.0, np.nan))


def test_simple_span_moment_line_is_the_hand_formula() -> None:
    """M at x for a unit load at a: a (L - x) / L left of x, x (L - a) / L right of it."""
    span, x = 20.0, 7.0
    a = np.linspace(-3.0, 25.0, 281)
    hand = np.where(a <= x, a * (span - x) / span, x * (span - a) / span)
    hand[(a < 0) | (a > span)] = 0.0
    got = mon.influence_line(a, x, span, response="strain")
    np.testing.assert_allclose(got, hand, atol=1e-12)


def test_axle_group_is_the_weighted_sum_of_shifted_lines() -> None:
    span, x = 15.0, 12.0  # gauge in span 1 of two continuous spans
    truck = mon.Axles(spacings=(3.5, 1.2), loads=(5.0, 9.0, 9.0))
    position = np.linspace(-2.0, 40.0, 421)
    expected = np.zeros_like(position)
    for offset, load in zip((0.0, 3.5, 4.7), (5.0, 9.0, 9.0), strict=True):
        at = position - offset
        on = (at >= 0) & (at <= 2 * span)
        expected[on] += load / 23.0 * point_load_statics(x, at[on], span, 3e9, 2).deflection
    got = mon.influence_line(
        position, x, span, n_spans=2, response="deflection", axles=truck, EI=3e9
    )
    np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-18)
    with pytest.raises(ValueError, match="section=31.0 must lie on the bridge"):
        mon.influence_line(position, 31.0, span, n_spans=2)
    with pytest.raises(ValueError, match="response='shear'"):
        mon.influence_line(position, 5.0, span, response="shear")


@pytest.mark.parametrize("speed_known", [True, False])
def test_fit_recovers_arrival_speed_scale_and_baseline(speed_known: bool) -> None:
    fs, span, speed, arrival, scale = 100.0, 25.0, 19.0, 2.137, -3.5e-4
    truck = mon.Axles(spacings=(4.0,), loads=(1.0, 2.0))
    t = np.arange(0.0, 8.0, 1 / fs)
    line = np.zeros_like(t)
    for offset, share in ((0.0, 1 / 3), (4.0, 2 / 3)):
        at = speed * (t - arrival) - offset
        on = (at >= 0) & (at <= span)
        line[on] += share * point_load_statics(10.0, at[on], span, 1.0).moment
    record = scale * line + 2e-5 - 1e-6 * t  # offset and drift
    shape = axle_shape(10.0, span, 1, "moment", truck)
    fit = fit_shape(record, fs, shape, rate=speed if speed_known else None)
    assert fit.arrival_s == pytest.approx(arrival, abs=1e-4)
    assert fit.rate == pytest.approx(speed, rel=1e-4)
    assert fit.rate_fitted is not speed_known and not fit.rate_at_bound
    assert fit.scale == pytest.approx(scale, rel=1e-4)
    np.testing.assert_allclose(fit.baseline, 2e-5 - 1e-6 * t, atol=1e-9)
    np.testing.assert_allclose(fit.model, scale * line, atol=1e-4 * abs(scale))


def test_fit_refuses_a_record_shorter_than_the_passage() -> None:
    shape = axle_shape(15.0, 30.0, 1, "moment", None)
    with pytest.raises(ValueError, match="shorter than the vehicle's passage"):
        fit_shape(np.sin(np.linspace(0, 3, 100)), 100.0, shape, rate=20.0)  # 1 s < 1.5 s
