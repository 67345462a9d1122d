"""Displacement, moment and shear at sections against Frýba's moving force and FE statics.

References: Frýba's closed-form modal solution of a force crossing a simple span (summed
here with its quasi-static part written as the exact statics, so that moment and shear
converge); the beam finite-element model of ``tests/beam_fe.py`` for the static envelopes
of a crawl; the textbook ``P L / 4`` and ``P / 2``.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

import vbi_lib as vbi
from vbi_lib import units as u
from vbi_lib.closed_forms import point_load_statics

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from beam_fe import Beam  # noqa: E402

EI, MBAR = 3e9, 4000.0


def fryba_moment_and_shear(
    x: np.ndarray, tau: np.ndarray, alpha: float, force: float, span: float, terms: int = 2000
) -> tuple[np.ndarray, np.ndarray]:
    """Moment and shear of an undamped simple span under a force crossing it (Frýba).

    ``w / w0 = sum sin(n pi x / L) T_n(tau) / n^4`` with
    ``T_n = (sin n pi tau - (alpha / n) sin(n^2 pi tau / alpha)) / (1 - alpha^2 / n^2)``.
    ``T_n = sin n pi tau + D_n``: the ``sin`` part sums to the exact statics of the force at
    ``tau L``; the rest, ``D_n``, falls as ``1/n`` and its moment and shear series converge.
    """
    n = np.arange(1, terms + 1)[None, None, :]
    t = tau[:, None, None]
    s = x[None, :, None] / span
    ratio = alpha / n
    dynamic = (ratio**2 * np.sin(n * math.pi * t) - ratio * np.sin(n**2 * math.pi * t / alpha)) / (
        1 - ratio**2
    )
    statics = point_load_statics(x[None, :], tau[:, None] * span, span, 1.0, 1, force)
    moment = statics.moment + (2 * force * span / math.pi**2) * np.sum(
        np.sin(n * math.pi * s) * dynamic / n**2, axis=-1
    )
    shear = statics.shear + (2 * force / math.pi) * np.sum(
        np.cos(n * math.pi * s) * dynamic / n, axis=-1
    )
    return moment, shear


def moving_force_run(alpha: float, modes: int) -> tuple[vbi.Crossing, float]:
    """Decoupled crossing of a flat road (the contact force is the weight), every third
    node on the bridge kept for the comparisons."""
    bridge = vbi.Bridge(20.0, 1, EI, MBAR, damping_ratio=0.0)
    truck = vbi.Vehicle(1e4, 1e6, 0.0)
    speed = alpha * 2 * bridge.first_frequency_hz * bridge.span
    road = vbi.Profile.flat(25.0, 0.02)
    run = vbi.simulate(bridge, truck, road, speed, 5.0, model="modal", modes=modes,
                       coupled=False, dt=5e-5)  # fmt: skip
    return run, truck.weight


def on_bridge(run: vbi.Crossing) -> np.ndarray:
    """Every third node on the bridge (the reference sums 2000 terms per instant)."""
    return np.flatnonzero(run.on_bridge)[::3]


@pytest.mark.parametrize(("alpha", "shear_tolerance"), [(0.2, 0.01), (0.5, 0.02)])
def test_moment_and_shear_of_a_moving_force_match_fryba(
    alpha: float, shear_tolerance: float
) -> None:
    """Mode acceleration with 8 modes: moment to 0.2 % of its peak, shear to 1-2 %.

    The shear's dynamic part (the high modes' free vibration set off as the force enters)
    falls only as about ``(2 / pi) alpha / N`` of the force, hence the looser bound at the
    fast ``alpha = 0.5``; the mode-displacement series with the same modes is 4-5 % off in
    the moment and 30-60 % in the shear (Gibbs' overshoot at the force).
    """
    sections = np.array([5.0, 10.0, 14.3])
    run, weight = moving_force_run(alpha, 8)
    on = on_bridge(run)
    tau = (run.position[on] - run.bridge_start) / run.bridge.span
    moment, shear = fryba_moment_and_shear(sections, tau, alpha, weight, run.bridge.span)
    peak_m, peak_v = np.abs(moment).max(), np.abs(shear).max()
    assert np.abs(run.moment_at(sections)[on] - moment).max() < 2e-3 * peak_m
    assert np.abs(run.shear_at(sections)[on] - shear).max() < shear_tolerance * peak_v
    plain_m = run.moment_at(sections, method="mode-displacement")[on]
    plain_v = run.shear_at(sections, method="mode-displacement")[on]
    assert np.abs(plain_m - moment).max() > 0.03 * peak_m
    assert np.abs(plain_v - shear).max() > 0.25 * peak_v
    # the dynamic extremes at the sections, as the section result reports them
    result = run.sections(sections)
    assert result.maximum[1] == pytest.approx(moment.max(axis=0), rel=2e-3)
    assert result.minimum[2] == pytest.approx(shear.min(axis=0), abs=shear_tolerance * peak_v)


def test_mode_acceleration_converges_with_few_modes() -> None:
    """Error of the moment and shear at three sections against Frýba, alpha = 0.2."""
    sections = np.array([5.0, 10.0, 14.3])
    errors = []
    for modes in (1, 3, 9):
        run, weight = moving_force_run(0.2, modes)
        on = on_bridge(run)
        tau = (run.position[on] - run.bridge_start) / run.bridge.span
        moment, shear = fryba_moment_and_shear(sections, tau, 0.2, weight, run.bridge.span)
        errors.append(
            (
                np.abs(run.moment_at(sections)[on] - moment).max() / np.abs(moment).max(),
                np.abs(run.shear_at(sections)[on] - shear).max() / np.abs(shear).max(),
            )
        )
    errors = np.array(errors)  # measured: moment 2.7 %, 0.33 %, 0.05 %; shear 5 %, 1.8 %, 0.6 %
    assert np.all(np.diff(errors, axis=0) < 0)
    assert errors[-1, 0] < 1e-3 and errors[-1, 1] < 1e-2


def fe_envelope(spans, sections, loads, offsets, step):  # noqa: ANN001, ANN201
    """Static envelope by brute force: every first-axle position on a grid of ``step``."""
    length = float(np.sum(spans))
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    positions = step * np.arange(int(round(length / step)) + 1)
    beam = Beam(supports, np.concatenate([positions, sections]), EI, element=0.5)
    _, moment, _ = beam.influence(positions, sections)
    first = np.arange(positions.size + int(round(max(offsets) / step)))
    total = np.zeros((first.size, sections.size))
    for load, offset in zip(loads, offsets, strict=True):
        at = first - int(round(offset / step))
        on = (at >= 0) & (at < positions.size)
        total[on] += load * moment[at[on]]
    return total.max(axis=0), total.min(axis=0)


def test_a_crawl_gives_the_static_moment_envelope_of_a_three_span_beam() -> None:
    """One sprung mass, decoupled, crawling (alpha ~ 0.003) over three unequal spans."""
    spans = [18 * u.ft * 2, 30 * u.ft * 2, 24 * u.ft * 2]
    bridge = vbi.Bridge.continuous(spans, EI=EI, mass_per_length=MBAR, damping_ratio=0.05)
    truck = vbi.Vehicle(2e4, 2e6, 0.0)
    sections = np.round(np.array([0.4 * spans[0], spans[0], spans[0] + 0.5 * spans[1]]) / 0.0254)
    sections *= 0.0254
    road = vbi.Profile.flat(5.0 + bridge.length, 0.0254)
    run = vbi.simulate(bridge, truck, road, 0.2, 5.0, model="modal", modes=6, coupled=False,
                       dt=0.0254 / 0.2)  # fmt: skip
    result = run.sections(sections)
    high, low = fe_envelope(spans, sections, [truck.weight], [0.0], 0.0254)
    scale = np.abs(np.concatenate([high, low])).max()
    np.testing.assert_allclose(result.maximum[1], high, rtol=0.01, atol=1e-3 * scale)
    np.testing.assert_allclose(result.minimum[1], low, rtol=0.01, atol=1e-3 * scale)
    # and the DAF of each section's governing moment is one
    assert result.daf[1] == pytest.approx(np.ones(3), abs=0.01)


@pytest.mark.parametrize("rear_spacing_ft", [14, 30])
def test_hs20_crawl_gives_the_static_moment_envelope(rear_spacing_ft: float) -> None:
    """The HS20 design truck (8, 32, 32 kip) crawling over three unequal spans.

    Its largest and smallest moments at the sections equal the static envelope of its axle
    loads, computed by the beam finite-element model of ``tests/beam_fe.py`` (a brute-force
    crawl in 1 in steps), to 1 %.
    """
    spans = [60 * u.ft, 80 * u.ft, 70 * u.ft]
    bridge = vbi.Bridge.continuous(spans, EI=EI, mass_per_length=MBAR, damping_ratio=0.05)
    truck = vbi.vehicles.hs20(rear_spacing=rear_spacing_ft * u.ft)
    system = vbi.vehicles.as_system(truck)
    loads, offsets = system.static_loads, system.offsets
    np.testing.assert_allclose(loads / u.kip, [8, 32, 32], rtol=1e-12)
    sections = np.array([24 * u.ft, 60 * u.ft, 100 * u.ft, 140 * u.ft, 175 * u.ft])
    approach = 10 * u.ft
    road = vbi.Profile.flat(approach + bridge.length + 2 * system.wheelbase, 1 * u.inch,
                            start=-system.wheelbase)  # fmt: skip
    run = vbi.simulate(bridge, truck, road, 0.3, approach, model="modal", modes=8)
    moments = run.moment_at(sections)
    high, low = fe_envelope(spans, sections, loads, offsets, 1 * u.inch)
    scale = np.abs(np.concatenate([high, low])).max()
    np.testing.assert_allclose(moments.max(axis=0), high, rtol=0.01, atol=1e-3 * scale)
    np.testing.assert_allclose(moments.min(axis=0), low, rtol=0.01, atol=1e-3 * scale)
    result = run.sections(sections)
    assert result.daf[1] == pytest.approx(np.ones(sections.size), abs=0.01)


def force_method_shear(spans, loads, positions, x, side):  # noqa: ANN001, ANN201
    """Static shear at ``x`` on face ``side`` of a continuous beam under point loads, by the
    force method (written here, independent of the library): the beam over its end
    supports is a simple span, the interior reactions its redundants, found from zero
    deflection at those supports with the simple span's closed-form deflection.

    ``loads`` ``(n_a,)`` [N] at ``positions`` ``(n_t, n_a)`` [m]; returns ``(n_t,)``.
    """
    supports = np.concatenate([[0.0], np.cumsum(spans)])
    length = supports[-1]
    inner = supports[1:-1]

    def deflection(at, a):  # simple span, unit load at a, deflection at at (down)
        b = length - a
        near = np.where(at <= a, at, length - at)
        far = np.where(at <= a, b, a)
        return far * near * (length**2 - far**2 - near**2) / (6 * length)

    flexibility = deflection(inner[:, None], inner[None, :])
    on = (positions >= 0) & (positions <= length)
    load = np.where(on, loads[None, :], 0.0)
    a = np.clip(positions, 0.0, length)
    rhs = (load[:, None, :] * deflection(inner[None, :, None], a[:, None, :])).sum(axis=-1)
    redundants = np.linalg.solve(flexibility, rhs.T).T  # (n_t, n_inner): upward
    left_end = (load * (length - a)).sum(axis=1) / length - redundants @ (length - inner) / length
    behind = (a < x) if side == "left" else (a <= x)
    shear = left_end - (load * behind).sum(axis=1)
    passed = (inner < x) if side == "left" else (inner <= x)
    return shear + redundants @ passed.astype(float)


@pytest.mark.parametrize("side", ["left", "right"])
def test_hs20_shear_on_both_faces_of_the_supports_is_the_static_shear(side: str) -> None:
    """The HS20 crawling over three unequal spans: the shear history just left and just
    right of each interior support is the static shear of its axle loads at their positions,
    by the force method written in the test; and the two faces differ."""
    spans = [60 * u.ft, 80 * u.ft, 70 * u.ft]
    bridge = vbi.Bridge.continuous(spans, EI=EI, mass_per_length=MBAR, damping_ratio=0.05)
    truck = vbi.vehicles.hs20(rear_spacing=20 * u.ft, tyres=False)
    system = vbi.vehicles.as_system(truck)
    approach = 10 * u.ft
    road = vbi.Profile.flat(approach + bridge.length + 2 * system.wheelbase, 1 * u.inch,
                            start=-system.wheelbase)  # fmt: skip
    run = vbi.simulate(bridge, truck, road, 0.5, approach, model="modal", modes=8)
    supports = np.array(bridge.supports[1:-1])
    shear = run.shear_at(supports, side=side)
    positions = run.axle_position - approach
    for i, x in enumerate(supports):
        static = force_method_shear(spans, system.static_loads, positions, x, side)
        scale = np.abs(static).max()
        assert np.abs(shear[:, i] - static).max() < 5e-3 * scale
    other = run.shear_at(supports, side="right" if side == "left" else "left")
    assert np.abs(other - shear).max() > 0.3 * np.abs(shear).max()  # the reaction between


def test_sections_give_the_governing_face_of_a_support_and_name_it() -> None:
    spans = [20.0, 32.0, 20.0]
    bridge = vbi.Bridge.continuous(spans, EI=EI, mass_per_length=MBAR, damping_ratio=0.05)
    truck = vbi.vehicles.hs20(rear_spacing=30 * u.ft, tyres=False)
    system = vbi.vehicles.as_system(truck)
    road = vbi.Profile.flat(12.0 + bridge.length + 2 * system.wheelbase, 0.05,
                            start=-system.wheelbase)  # fmt: skip
    run = vbi.simulate(bridge, truck, road, 0.5, 12.0, model="modal", modes=8)
    stations = np.array([10.0, 20.0, 52.0])
    result = run.sections(stations)
    positions = run.axle_position - 12.0
    e = 2
    for i, x in enumerate(stations):
        sizes = {}
        for side in ("left", "right"):
            static = force_method_shear(spans, system.static_loads, positions, x, side)
            sizes[side] = np.abs(static).max()
            alone = run.sections([x], side=side)
            # each face's static extreme is the crawl's, and at a crawl its DAF is one
            assert max(abs(alone.static.maximum[e, 0]), abs(alone.static.minimum[e, 0])) == (
                pytest.approx(sizes[side], rel=1e-3)
            )
            assert alone.daf[e, 0] == pytest.approx(1.0, abs=0.01)
        expected = "" if i == 0 else max(sizes, key=sizes.get)
        assert result.faces[i] == expected
        governing = result.static.maximum[e, i], result.static.minimum[e, i]
        assert max(map(abs, governing)) == pytest.approx(max(sizes.values()), rel=1e-3)
    table = result.to_dataframe()
    shear_rows = table[table.effect == "shear"]
    assert set(shear_rows.face) == set(result.faces) == {"", "left", "right"}
    assert set(table[table.effect == "moment"].face) == {""}
    # the history is the governing face's
    alone = run.shear_at(20.0, side=result.faces[1])
    np.testing.assert_allclose(result.shear[:, 1], alone, rtol=0, atol=1e-9 * np.abs(alone).max())
    with pytest.raises(ValueError, match="side='top' is not known; use one of governing"):
        run.sections([20.0], side="top")
    with pytest.raises(ValueError, match="side='governing' is not known; use one of left"):
        run.shear_at(20.0, side="governing")


def test_one_coordinate_sections_are_one_mode_of_the_modal_model() -> None:
    bridge = vbi.Bridge(20.0, 2, EI, MBAR)
    truck = vbi.Vehicle.from_frequency(1e4, 4.0, 0.1)
    road = vbi.Profile.harmonic(70.0, 0.02, 4.0, 0.002)
    sections = [5.0, 10.0, 20.0, 33.0]
    one = vbi.simulate(bridge, truck, road, 20.0, 25.0, dt=2e-4).sections(sections)
    modal = vbi.simulate(bridge, truck, road, 20.0, 25.0, model="modal", modes=1, dt=2e-4)
    other = modal.sections(sections)
    for effect in ("displacement", "moment", "shear"):
        a, b = one.history(effect), other.history(effect)
        assert np.abs(a - b).max() < 2e-4 * np.abs(b).max()
    np.testing.assert_allclose(one.static.maximum, other.static.maximum, rtol=1e-12)


def test_crawl_on_a_simple_span_gives_pl_over_4_and_the_coincident_shear() -> None:
    bridge = vbi.Bridge(10.0, 1, 1e9, 1000.0, damping_ratio=0.05)
    truck = vbi.Vehicle(1e3, 1e6, 0.0)
    run = vbi.simulate(bridge, truck, vbi.Profile.flat(10.0, 0.05), 0.05, 0.0, model="modal",
                       modes=3, coupled=False, dt=1.0)  # fmt: skip
    result = run.sections([5.0, 2.5])
    weight = truck.weight
    assert result.maximum[1, 0] == pytest.approx(weight * 10.0 / 4, rel=1e-3)
    assert result.static.maximum[1, 0] == pytest.approx(weight * 10.0 / 4, rel=1e-12)
    # the largest midspan moment occurs with the load over midspan: shear +P/2 (left value)
    assert result.coincident("moment", "max", "shear")[0] == pytest.approx(weight / 2, rel=1e-3)
    assert result.position[result.extreme_index("moment", "max")[0]] == pytest.approx(5.0)
    assert result.daf[1] == pytest.approx([1.0, 1.0], abs=2e-3)
    assert np.isnan(result.daf_maximum[0, 0])  # a simple span never deflects up statically
    table = result.to_dataframe()
    assert len(table) == 2 * 3 * 2
    row = table[(table.effect == "moment") & (table.sense == "max")].iloc[0]
    assert bool(row.governs) and row.daf == pytest.approx(1.0, abs=2e-3)


def test_midspan_section_daf_is_the_span_daf() -> None:
    bridge = vbi.Bridge.continuous([20.0, 26.0, 20.0], EI=EI, mass_per_length=MBAR)
    truck = vbi.Vehicle.from_frequency(2e4, 3.0, 0.1)
    road = vbi.Profile.harmonic(100.0, 0.05, 6.0, 0.004)
    run = vbi.simulate(bridge, truck, road, 22.0, 30.0, model="modal", modes=12)
    result = run.sections(bridge.midspans)
    np.testing.assert_allclose(result.daf[0], run.daf, rtol=5e-3)


def test_lost_contact_is_carried_to_the_sections() -> None:
    bridge = vbi.Bridge(20.0, 1, EI, MBAR)
    truck = vbi.Vehicle.from_frequency(1e4, 3.0, 0.05)
    road = vbi.Profile.harmonic(60.0, 0.02, 2.0, 0.03)
    with pytest.warns(vbi.ContactLossWarning):
        run = vbi.simulate(bridge, truck, road, 15.0, 30.0, model="modal", modes=4)
    result = run.sections([10.0])
    assert result.lost_contact and "CONTACT LOST" in repr(result)
    assert result.to_dataframe()["lost contact"].all()
    assert any("contact" in note for note in result.notes)


def test_bad_section_input_is_refused_with_a_sentence() -> None:
    bridge = vbi.Bridge.continuous([10.0, 12.0], EI=EI, mass_per_length=MBAR)
    truck = vbi.Vehicle(1e4, 1e6, 0.0)
    run = vbi.simulate(bridge, truck, vbi.Profile.flat(30.0, 0.05), 10.0, 5.0, model="modal",
                       modes=3)  # fmt: skip
    with pytest.raises(ValueError, match=r"on the bridge, in \[0, 22\] m"):
        run.moment_at(23.0)
    with pytest.raises(ValueError, match="method='modal' is not known"):
        run.shear_at(3.0, method="modal")
    with pytest.raises(ValueError, match="effect='torque'"):
        run.sections([3.0]).plot(effect="torque")
    with pytest.raises(ValueError, match="sense='top'"):
        run.sections([3.0]).extreme_index("moment", "top")


def test_sections_must_be_stations() -> None:
    bridge = vbi.Bridge(10.0, 1, EI, MBAR)
    run = vbi.simulate(bridge, vbi.Vehicle(1e4, 1e6, 0.0), vbi.Profile.flat(12.0, 0.05), 10.0,
                       1.0, model="modal", modes=2)  # fmt: skip
    with pytest.raises(ValueError, match=r"x=\[\] must give one or more stations"):
        run.sections([])
    with pytest.raises(TypeError, match="x='mid' must be stations"):
        run.moment_at("mid")
    # the static counterpart is shared by crossings of the same bridge and vehicle
    again = vbi.simulate(bridge, vbi.Vehicle(1e4, 1e6, 0.0), vbi.Profile.flat(12.0, 0.05),
                         12.0, 1.0, model="modal", modes=2)  # fmt: skip
    assert run.sections([5.0]).static is again.sections([5.0]).static
