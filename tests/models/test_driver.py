"""The driver's contract: one simulate for every model, keyword-only options, one result family."""

from __future__ import annotations

import math
import warnings

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from problems import MODEL_CASES, build_case, flat  # noqa: E402

import vbi_lib as vbi  # noqa: E402
from vbi_lib import display  # noqa: E402

MODELS = pytest.mark.parametrize("options", MODEL_CASES.values(), ids=MODEL_CASES.keys())


def small() -> tuple[vbi.Bridge, vbi.Vehicle, vbi.Profile, float, float]:
    bridge = vbi.Bridge(20.0, 2, 8e9, 6000.0)
    return bridge, vbi.Vehicle.from_frequency(2e4, 3.0, 0.1), flat(bridge, 5.0), 20.0, 5.0


def test_options_after_the_five_inputs_are_keyword_only() -> None:
    """``simulate(b, t, r, v, s, 5)`` once meant ``coupled=5``: now it is refused."""
    with pytest.raises(TypeError, match="positional"):
        vbi.simulate(*small(), False)
    with pytest.raises(TypeError, match="positional"):
        vbi.simulate_many(*small(), False)


@MODELS
def test_every_model_returns_a_crossing_that_names_it(options: dict) -> None:
    crossing = vbi.simulate(*small(), **options)
    assert isinstance(crossing, vbi.Crossing)
    assert crossing.model == options.get("model", "one-coordinate")
    assert isinstance(crossing, vbi.MODELS[crossing.model].result_type)
    batch = vbi.simulate_many(*small(), **options)
    assert isinstance(batch, vbi.BatchResult) and batch.model == crossing.model
    assert crossing.midspan_displacement.shape == (crossing.time.size, 2)


def test_models_are_looked_up_by_name() -> None:
    with pytest.raises(ValueError, match="model='Modal' is not a crossing model"):
        vbi.simulate(*small(), model="Modal", modes=3)
    with pytest.raises(ValueError, match="modes=5 applies to model='modal'"):
        vbi.simulate(*small(), modes=5)


def test_the_default_modes_reach_2_3_times_the_highest_simply_supported_span_frequency() -> None:
    """Reference: the frequencies of 40 modes, counted in the test against 2.3 f_ss of the
    shortest span, f_ss = (pi / 2 L^2) sqrt(EI / mbar)."""
    bridge = small()[0]
    crossing = vbi.simulate(*small(), model="modal")
    f_ss = math.pi / (2 * min(bridge.spans) ** 2) * math.sqrt(bridge.EI / bridge.mass_per_length)
    expected = int((vbi.beam_modes(bridge, 40).frequencies_hz <= 2.3 * f_ss).sum())
    assert crossing.modes.count == max(1, expected)
    for spans in ([10.0, 200.0], [12.0, 16.0, 10.0]):
        b = vbi.Bridge.continuous(spans, EI=bridge.EI, mass_per_length=bridge.mass_per_length)
        f_ss = math.pi / (2 * min(spans) ** 2) * math.sqrt(b.EI / b.mass_per_length)
        expected = int((vbi.beam_modes(b, 60).frequencies_hz <= 2.3 * f_ss).sum())
        assert vbi.models.modal.default_modes(b) == expected


@pytest.mark.parametrize("name", ["coupled", "convective"])
@pytest.mark.parametrize("value", ["False", 0, 1.0, None])
def test_flags_must_be_booleans(name: str, value: object) -> None:
    with pytest.raises(TypeError, match=f"{name}={value!r} must be True or False"):
        vbi.simulate(*small(), **{name: value})
    with pytest.raises(TypeError, match=f"crossing 1: {name}={value!r}"):
        vbi.simulate_many(*small(), **{name: [True, value]})


@pytest.mark.parametrize(
    ("dt", "error"),
    [(0.0, ValueError), (-1.0, ValueError), (float("nan"), ValueError), ("0.01", TypeError)],
)
def test_a_bad_step_is_refused_in_both_entry_points(dt: object, error: type) -> None:
    with pytest.raises(error, match="dt="):
        vbi.simulate(*small(), dt=dt)
    with pytest.raises(error, match="dt="):
        vbi.simulate_many(*small(), dt=dt)


@MODELS
def test_results_export_their_histories(options: dict) -> None:
    display.set_units("US")
    try:
        crossing = vbi.simulate(*small(), **options)
        table = crossing.to_dataframe()
        assert len(table) == crossing.time.size
        position = table["position from bridge start [ft]"].to_numpy()
        np.testing.assert_allclose(position * 0.3048, crossing.position - crossing.bridge_start)
        deflection = table["midspan displacement, span 2 [in]"].to_numpy()
        np.testing.assert_allclose(deflection * 0.0254, crossing.midspan_displacement[:, 1])
        batch = vbi.simulate_many(*small()[:3], [10.0, 20.0], 5.0, **options).to_dataframe()
        np.testing.assert_allclose(batch["speed [mph]"] * 0.44704, [10.0, 20.0])
        assert not batch["lost contact"].any()
    finally:
        display.set_units("SI")


@pytest.mark.parametrize("kind", ["displacement", "deflection", "contact", "vehicle"])
def test_results_plot_themselves_with_units(kind: str) -> None:
    import matplotlib.pyplot as plt

    crossing = vbi.simulate(*small())
    ax = crossing.plot(kind=kind)
    assert ax.get_xlabel() == "wheel position from the start of the bridge [m]"
    assert ax.get_ylabel().endswith("]") and ax.lines
    plt.close("all")
    with pytest.raises(ValueError, match="kind='moment'"):
        crossing.plot(kind="moment")


def test_batch_plot_marks_crossings_that_lost_contact() -> None:
    import matplotlib.pyplot as plt

    bridge, vehicle, road, speed, start = build_case("40ft-10Hz-one-span")
    rough = vbi.Profile(road.x, 8 * road.elevation)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vbi.ContactLossWarning)
        batch = vbi.simulate_many(bridge, vehicle, [rough, flat(bridge, start)], speed, start)
    assert batch.lost_contact.tolist() == [True, False]
    ax = batch.plot()
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "contact lost (outside validity)" in labels
    assert "CONTACT LOST in 1" in repr(batch)
    plt.close("all")


def test_simulate_many_warns_once_for_all_crossings() -> None:
    bridge, vehicle, road, speed, start = build_case("40ft-10Hz-one-span")
    rough = vbi.Profile(road.x, 8 * road.elevation)
    with pytest.warns(vbi.ContactLossWarning) as caught:
        vbi.simulate_many(bridge, vehicle, rough, [speed, 0.9 * speed], start)
    caught = [w for w in caught if w.category is vbi.ContactLossWarning]  # h23: the road x 8
    assert len(caught) == 1 and "2 of 2 crossings lost contact" in str(caught[0].message)


def test_a_multi_axle_crossing_exports_and_plots_each_axle() -> None:
    import matplotlib.pyplot as plt

    truck = vbi.vehicles.hs20(body="rigid")
    bridge = vbi.Bridge(20.0, 1, 8e9, 6000.0)
    road = vbi.Profile.iso8608(60.0, 0.05, c10=64e-6, seed=1)
    crossing = vbi.simulate(bridge, truck, road, 20.0, 15.0)
    n = crossing.time.size
    assert crossing.axle_contact_force.shape == (n, 3)
    assert crossing.dof_displacement.shape == (n, 5)  # bounce, pitch, three axles
    np.testing.assert_allclose(crossing.contact_force, crossing.axle_contact_force.sum(axis=1))
    np.testing.assert_allclose(crossing.vehicle_displacement, crossing.dof_displacement[:, 0])
    expected = crossing.position - 28 * 0.3048
    np.testing.assert_allclose(crossing.axle_position[:, 2], expected, atol=1e-12)
    table = crossing.to_dataframe()
    assert {"pitch displacement [rad]", "axle 3 contact force / load [-]"} <= set(table.columns)
    np.testing.assert_allclose(
        table["axle 2 contact force / load [-]"], crossing.axle_contact_force_ratio[:, 1]
    )
    labels = [t.get_text() for t in crossing.plot(kind="contact").get_legend().get_texts()]
    assert labels == ["axle 1", "axle 2", "axle 3"]
    labels = [t.get_text() for t in crossing.plot(kind="vehicle").get_legend().get_texts()]
    assert "pitch" not in labels and "bounce" in labels
    plt.close("all")


def test_batch_plot_marks_tyres_that_left_the_road() -> None:
    import matplotlib.pyplot as plt

    car = vbi.QuarterCar.from_frequencies(4000.0, 500.0, 1.5, 12.0, 0.1, 0.02)
    bridge = vbi.Bridge(30.0, 1, 1e10, 5e3)
    road = vbi.Profile.step(60.0, 0.01, position=15.0, height=0.06)
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.VbiWarning)
        batch = vbi.simulate_many(bridge, car, [road, flat(bridge, 10.0)], 20.0, 10.0)
    assert batch.lost_contact.tolist() == [True, False]
    assert not batch.outside_validity.any() and batch.flight_fraction[0] > 0
    labels = [t.get_text() for t in batch.plot().get_legend().get_texts()]
    assert "a tyre left the road" in labels and "contact lost (outside validity)" not in labels
    assert "a tyre left the road in 1" in repr(batch)
    assert batch.to_dataframe()["flight fraction"].iloc[0] == batch.flight_fraction[0]
    plt.close("all")


@pytest.mark.parametrize(
    ("change", "error", "message"),
    [
        ({"speeds": [10.0, -1.0, 12.0]}, ValueError, "crossing 1: speed=-1.0 must be"),
        ({"speeds": [10.0, 11.0, "12"]}, TypeError, "crossing 2: speed='12' must be a number"),
        ({"speeds": [10.0, True, 12.0]}, TypeError, "crossing 1: speed=True must be a number"),
        ({"bridge_starts": [5.0, float("nan"), 5.0]}, ValueError, "crossing 1: bridge_start"),
        ({"bridge_starts": [5.0, 5.0, 30.0]}, ValueError, "crossing 2: the profile"),
        ({"bridges": [None, None, None]}, TypeError, "crossing 0: bridge must be a vbi.Bridge"),
        ({"profiles": "road"}, TypeError, "crossing 0: profile must be a vbi.Profile"),
        ({"modes": [None, 3, None]}, ValueError, "crossing 1: modes=3 applies to model='modal'"),
    ],
)
def test_batch_inputs_are_checked_and_the_crossing_named(
    change: dict, error: type, message: str
) -> None:
    bridge, vehicle, road, _, start = small()
    args = {"bridges": bridge, "vehicles": vehicle, "profiles": road,
            "speeds": [10.0, 11.0, 12.0], "bridge_starts": start} | change  # fmt: skip
    modes = args.pop("modes", None)
    with pytest.raises(error, match=message):
        vbi.simulate_many(*args.values(), modes=modes)


def test_a_bridge_start_given_as_text_is_refused_as_simulate_refuses_it() -> None:
    """The type policy (issue 17): text is no number, in a batch as in one crossing."""
    bridge, vehicle, road, speed, start = small()
    with pytest.raises(TypeError, match="bridge_start='5.0' must be a number") as single:
        vbi.simulate(bridge, vehicle, road, speed, str(start))
    with pytest.raises(TypeError, match="crossing 1: ") as batch:
        vbi.simulate_many(bridge, vehicle, road, [speed, speed], [start, str(start)])
    assert str(batch.value) == f"crossing 1: {single.value}"


def test_a_batch_checks_steps_and_ranges_as_simulate_does() -> None:
    """Reference: :func:`vbi.simulate` of each crossing.  A batch finds the crossings that
    need a check on their grid with array bounds; the verdicts must be simulate's: the same
    refusal of an unstable RK4 step, no warning for a long ``dt`` that the road's samples cut
    short, and one warning counting the crossings simulate warns of."""
    bridge, vehicle, _, speed, start = small()
    road = vbi.Profile.flat(45.0, 2.5)  # samples far apart: the default step sets the steps
    default = vbi.simulate(bridge, vehicle, road, speed, start).dt  # 0.1 / omega_max, or less
    fine = vbi.Profile(road.x, np.where(road.x > 20.0, 1e-3, 0.0))  # a step: not a line
    fine = fine.resampled(0.002)  # samples every 2 mm: steps of 0.1 ms at 20 m/s
    long = 60.0 * default  # the samples cut it to 125 ms, omega_max dt 3.8: RK4 refuses it
    with pytest.raises(ValueError, match="omega_max dt of at most 2") as single:
        vbi.simulate(bridge, vehicle, road, speed, start, dt=long)
    with pytest.raises(ValueError) as batch:
        vbi.simulate_many(bridge, vehicle, [fine, road], speed, start, dt=long)
    assert str(batch.value) == f"crossing 1: {single.value}"
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.OutsideValidityWarning)
        alone = vbi.simulate(bridge, vehicle, fine, speed, start, dt=long)
        many = vbi.simulate_many(bridge, vehicle, [fine, fine], speed, start, dt=long)
    assert alone.dt < default  # the samples set the step, not dt
    np.testing.assert_allclose(many.daf[0], alone.daf, rtol=1e-10)
    coarse = fine.resampled(0.5)  # fine enough at 20 m/s, not at 1 m/s (rule 32)
    speeds = [speed, 50.0, speed, 1.0]  # 50 m/s is above 150 km/h; 1 m/s samples coarsely
    with pytest.warns(vbi.OutsideValidityWarning) as caught:
        vbi.simulate_many(bridge, vehicle, coarse, speeds, start)
    expected = []
    for i, v in enumerate(speeds):
        with warnings.catch_warnings(record=True) as seen:
            warnings.simplefilter("always", vbi.OutsideValidityWarning)
            vbi.simulate(bridge, vehicle, coarse, v, start)
        if any(issubclass(w.category, vbi.OutsideValidityWarning) for w in seen):
            expected.append(i)
    messages = [str(w.message) for w in caught if "crossings have inputs" in str(w.message)]
    assert len(messages) == 1, messages
    assert messages[0].startswith(f"{len(expected)} of 4 crossings have inputs outside")
    assert f"(crossing {expected[0]}: " in messages[0]


def test_a_batch_takes_a_pandas_series_and_refuses_unordered_iterables() -> None:
    import pandas as pd

    bridge = vbi.Bridge(30.0, 1, 2e10, 8000.0)
    truck = vbi.Vehicle.from_frequency(3e4, 3.0, 0.1)
    road = vbi.Profile.flat(200.0, 0.05)
    batch = vbi.simulate_many(bridge, truck, road, pd.Series([20.0, 30.0]), 50.0)
    for i, speed in enumerate((20.0, 30.0)):  # the reference: one crossing at a time
        single = vbi.simulate(bridge, truck, road, speed, 50.0).daf[0]
        assert batch.daf[i, 0] == pytest.approx(single, rel=1e-10)
    for bad in ({20.0, 30.0}, (s for s in (20.0, 30.0))):
        with pytest.raises(TypeError, match=r"speeds must be one value or a list"):
            vbi.simulate_many(bridge, truck, road, bad, 50.0)
